// `gearbench report compare|perf|pdf`.
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <iostream>

#include "build_info.h"
#include "commands.h"
#include "compare.h"
#include "interrupt.h"
#include "model/errors.h"
#include "model/json_reader.h"
#include "perf_history.h"

namespace gearbench::app {

namespace fs = std::filesystem;

std::string default_perf_dir() { return std::string(build::source_dir()) + "/reports/perf"; }

namespace {
/// A report that compare_reports can read: it looks up these keys without checking them, so a
/// report.json of another structure is refused here, naming the first key that is amiss.
nlohmann::json comparable_report(const std::string& path) {
  auto report = reports::load_report(path);
  const auto refuse = [&path](const std::string& key, const std::string& what) {
    throw InputError(fmt::format("{}: {}: {}; not a gearbench report", model::shown_text(path), key, what));
  };
  const auto machine = report.find("machine");
  if (machine == report.end() || !machine->is_object() || !machine->contains("fingerprint"))
    refuse("machine.fingerprint", "missing");
  const auto& checks = report["checks"];
  if (!checks.is_array()) refuse("checks", "must be an array");
  for (std::size_t i = 0; i < checks.size(); ++i) {
    const auto key = fmt::format("checks[{}]", i);
    const auto& check = checks[i];
    if (!check.is_object()) refuse(key, "must be an object");
    for (const char* text : {"id", "status"})
      if (!check.contains(text) || !check[text].is_string()) refuse(key + "." + text, "must be a string");
    for (const char* number : {"value", "seconds"})
      if (!check.contains(number) || !(check[number].is_number() || check[number].is_null()))
        refuse(key + "." + number, "must be a number or null");
  }
  return report;
}
}  // namespace

int report_compare_command(const std::string& before, const std::string& after) {
  const auto comparison = reports::compare_reports(comparable_report(before), comparable_report(after));
  std::cout << comparison.text();
  return comparison.regressions.empty() ? exit_ok : exit_failed;
}

namespace {
void write_text(const fs::path& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
  out.flush();
  if (!out) throw std::runtime_error("cannot write " + path.string());
}
}  // namespace

int report_perf_command(const PerfReportRequest& request) {
  const reports::PerfOptions options{.alpha = request.alpha, .threshold = request.threshold,
                                     .clock = reports::parse_perf_clock(request.clock)};
  options.validate();
  auto runs = reports::load_perf_records(request.dir, options.clock);
  if (runs.empty()) throw InputError(fmt::format("--dir {}: no benchmark records (*.json) in it", request.dir));
  const auto history = reports::analyse_perf_history(std::move(runs), options);
  const fs::path out(request.out_dir);
  const DeferInterrupts defer;  // perf.md, perf.json and the figures are written as one
  fs::create_directories(out / "figures");
  write_text(out / "perf.json", history.to_json(options).dump(2) + "\n");
  write_text(out / "perf.md", history.markdown(options));
  for (const auto& f : history.figures) reports::write_figure(f, (out / "figures" / f.id).string(), request.pdf);
  const auto latest = history.latest_regressions();
  std::cerr << fmt::format("{} records, {} comparisons, {} regression(s) at the newest runs\n",
                           history.runs.size(), history.changes.size(), latest.size());
  for (const auto* c : latest)
    std::cerr << fmt::format("  REGRESSION {} {}: {:+.1f} % (p = {:.3g})\n", c->ratio ? "ratio" : "time", c->name,
                             100.0 * c->change, c->p_value);
  std::cout << (out / "perf.md").string() << "\n";
  return latest.empty() ? exit_ok : exit_failed;
}

int report_pdf_command(const std::string& report_dir) {
  const auto report = reports::load_report(report_dir);
  const fs::path folder = fs::is_directory(report_dir) ? fs::path(report_dir) : fs::path(report_dir).parent_path();
  const DeferInterrupts defer;  // no half-drawn PDF is left behind
  fs::create_directories(folder / "figures");
  int drawn = 0, failed = 0;
  for (const auto& f : report["figures"]) {
    const auto figure = reports::figure_from_json(f);
    const bool ok = reports::render_pdf(figure, (folder / "figures" / (figure.id + ".pdf")).string());
    (ok ? drawn : failed) += 1;
  }
  std::cerr << fmt::format("{} PDF figures written{}\n", drawn,
                           failed ? fmt::format(", {} failed (is gnuplot with the cairo terminals installed?)", failed) : "");
  std::cout << (folder / "figures").string() << "\n";
  return failed == 0 ? exit_ok : exit_failed;
}

}  // namespace gearbench::app
