#include <filesystem>
#include <fmt/format.h>
#include <iostream>

#include "bench_section.h"
#include "build_info.h"
#include "model/json_reader.h"
#include "check_registry.h"
#include "commands.h"
#include "interrupt.h"
#include "model/errors.h"
#include "outcome.h"

namespace gearbench::app {

std::string default_output_dir() { return std::string(build::source_dir()) + "/reports/out"; }
std::string default_cases_dir() { return std::string(build::source_dir()) + "/cases"; }

namespace {
/// The report's Performance section: the --bench record, else this commit's newest record in
/// reports/perf, against the previous record of this machine there.
reports::Note performance_note(const std::string& bench_record) {
  const auto dir = default_perf_dir();
  const auto history = std::filesystem::is_directory(dir) ? reports::load_perf_records(dir) : std::vector<reports::PerfRun>{};
  std::optional<reports::PerfRun> current;
  if (!bench_record.empty()) current = reports::parse_perf_record(model::read_json_file(bench_record), bench_record);
  return reports::performance_note(history, current,
                                   {.sha = build::git_sha(), .fingerprint = reports::hardware_fingerprint(),
                                    .build_type = build::build_type()});
}
}  // namespace

int verify_command(const std::string& tier, const std::string& out_dir, const std::string& cases_dir,
                   const std::string& bench_record, const std::string& only) {
  const auto parsed = verification::parse_tier(tier);
  if (!std::filesystem::is_directory(cases_dir))
    throw InputError(fmt::format("--cases {}: not a directory", cases_dir));
  const verification::CheckContext context{cases_dir};
  auto report = verification::run_verification(
      parsed, context, [](const std::string& line) { std::cerr << line << std::endl; }, only);
  if (!bench_record.empty()) {
    const auto record = model::read_json_file(bench_record);
    report.notes.push_back(reports::benchmark_note(record));
    for (auto& figure : reports::work_precision_figures(record)) report.figures.push_back(std::move(figure));
  }
  report.notes.push_back(performance_note(bench_record));
  // The report folder appears whole and its path is printed, or neither: a Ctrl-C before this
  // point leaves nothing; one after it comes when the work is done, and the run finishes.
  hold_interrupts_to_the_end();
  std::cerr << "writing the report..." << std::endl;
  const std::string folder = reports::write_report(report, out_dir);
  const auto counts = report.counts();
  std::cerr << reports::headline(counts) << "\n";
  for (const auto& f : report.section_failures) std::cerr << fmt::format("section {} FAILED: {}\n", f.id, f.error);
  std::cout << folder << "/report.md" << std::endl;
  return verification::gate_passes(counts) ? exit_ok : exit_failed;
}

}  // namespace gearbench::app
