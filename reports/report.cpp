#include "report.h"

#include <chrono>
#include <cstdint>
#include <cmath>
#include <ctime>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <map>
#include <thread>
#include <unistd.h>

#include "build_info.h"

namespace gearbench::reports {

namespace fs = std::filesystem;
using nlohmann::json;

double CheckRecord::abs_error() const { return std::abs(value - reference_value); }

double CheckRecord::rel_error() const {
  return reference_value != 0.0 ? abs_error() / std::abs(reference_value) : abs_error();
}

std::string outcome_name(Outcome outcome) {
  switch (outcome) {
    case Outcome::pass: return "pass";
    case Outcome::reproduced: return "reproduced";
    case Outcome::missed: return "missed";
    case Outcome::fail: break;
  }
  return "fail";
}

OutcomeCounts Report::counts() const {
  OutcomeCounts n;
  n.checks = static_cast<int>(checks.size());
  for (const auto& c : checks) {
    switch (c.outcome) {
      case Outcome::pass: ++n.pass; break;
      case Outcome::reproduced: ++n.reproduced; break;
      case Outcome::missed: ++n.missed; break;
      case Outcome::fail: ++n.failed; break;
    }
  }
  n.sections_failed = static_cast<int>(section_failures.size());
  return n;
}

std::string headline(const OutcomeCounts& n) {
  std::string line = fmt::format("{} checks: {} pass, {} reproduced, {} missed, {} failed", n.checks, n.pass,
                                 n.reproduced, n.missed, n.failed);
  if (n.sections_failed > 0) line += fmt::format("; {} report section(s) could not be built", n.sections_failed);
  return line;
}

namespace {

/// JSON has no NaN: a non-finite number is written as null, never as a number.
json number(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("model name", 0) == 0) {
      const auto colon = line.find(':');
      return colon == std::string::npos ? line : line.substr(colon + 2);
    }
  return "unknown";
}

/// Installed memory rounded to whole GiB (MemTotal moves by a few MiB between kernels).
long memory_gib() {
  std::ifstream in("/proc/meminfo");
  std::string key;
  long kib = 0;
  while (in >> key) {
    if (key == "MemTotal:") {
      in >> kib;
      break;
    }
    std::getline(in, key);
  }
  return std::lround(static_cast<double>(kib) / (1024.0 * 1024.0));
}

json dependency_versions() {
  json deps = json::object();
  std::string list = build::dependency_versions();
  std::size_t start = 0;
  while (start < list.size()) {
    auto end = list.find(';', start);
    if (end == std::string::npos) end = list.size();
    const auto item = list.substr(start, end - start);
    const auto eq = item.find('=');
    if (eq != std::string::npos) deps[item.substr(0, eq)] = item.substr(eq + 1);
    start = end + 1;
  }
  return deps;
}

std::string utc_now(const char* format) {
  const auto now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  gmtime_r(&now, &tm);
  char buffer[64];
  std::strftime(buffer, sizeof buffer, format, &tm);
  return buffer;
}

/// Markdown table cells may not contain '|'.
std::string cell(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '|') out.push_back('\\');
    out.push_back(c);
  }
  return out;
}

std::string format_number(const json& v) {
  if (v.is_null()) return "—";
  const double x = v.get<double>();
  if (x == 0.0) return "0";
  if (std::abs(x) >= 1e-3 && std::abs(x) < 1e6) return fmt::format("{:.6g}", x);
  return fmt::format("{:.4e}", x);
}

/// The headline and the summary table: every outcome counted on its own.
std::string headline_markdown(const OutcomeCounts& n) {
  std::string md = fmt::format("**{}.**", headline(n));
  if (n.missed > 0)
    md += " A missed seed reproduction is a finding, not a failure: the figure reached is recorded "
          "and the gap explained in its section.";
  md += fmt::format("\n\n| outcome | checks |\n|---|---|\n| pass | {} |\n| reproduced | {} |\n| missed | {} |\n"
                    "| failed | {} |\n| sections not built | {} |\n\n",
                    n.pass, n.reproduced, n.missed, n.failed, n.sections_failed);
  return md;
}

std::string section_failures_markdown(const std::vector<SectionFailure>& failures) {
  if (failures.empty()) return {};
  std::string md = "## Sections that could not be built\n\n";
  for (const auto& f : failures) md += fmt::format("- **FAIL** `{}`: {}\n", f.id, f.error);
  return md + "\n";
}

}  // namespace

/// Stable across compilers and standard libraries, unlike std::hash, so committed
/// fingerprints stay valid: offset basis 14695981039346656037, prime 1099511628211.
std::uint64_t fnv1a64(const std::string& text) {
  std::uint64_t h = 14695981039346656037ull;
  for (unsigned char c : text) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}

json provenance() {
  const unsigned cores = std::thread::hardware_concurrency();
  return {
      {"code", {{"version", build::version()}, {"git_sha", build::git_sha()},
                {"dirty", build::git_dirty()}}},
      {"build", {{"compiler", build::compiler()}, {"build_type", build::build_type()},
                 {"flags", build::cxx_flags()}, {"dependencies", dependency_versions()}}},
      {"machine", {{"cpu_model", cpu_model()}, {"cores", cores}, {"memory_GiB", memory_gib()},
                   {"fingerprint", machine_fingerprint()}, {"fingerprint_digest", fingerprint_digest},
                   {"hardware_fingerprint", hardware_fingerprint()}}},
      {"created_utc", utc_now("%Y-%m-%dT%H:%M:%SZ")},
  };
}

std::string machine_fingerprint() {
  const std::string key = fmt::format("{}|{}|{}|{}|{}", cpu_model(),
                                      std::thread::hardware_concurrency(), build::compiler(),
                                      build::build_type(), build::cxx_flags());
  return fmt::format("{:016x}", fnv1a64(key));
}

std::string hardware_fingerprint() {
  return fmt::format("{:016x}", fnv1a64(fmt::format("{}|{}|{}", cpu_model(), std::thread::hardware_concurrency(),
                                                  memory_gib())));
}

std::string report_folder_name() {
  return fmt::format("{}_{}", utc_now("%Y-%m-%d"), build::git_sha());
}

json to_json(const Report& report) {
  json checks = json::array();
  for (const auto& c : report.checks) {
    checks.push_back({
        {"id", c.id}, {"section", c.section}, {"solver", c.solver},
        {"reference", c.reference}, {"quantity", c.quantity}, {"unit", c.unit},
        {"value", c.error.empty() ? number(c.value) : json(nullptr)},
        {"reference_value", number(c.reference_value)},
        {"abs_error", c.error.empty() ? number(c.abs_error()) : json(nullptr)},
        {"rel_error", c.error.empty() ? number(c.rel_error()) : json(nullptr)},
        {"tolerance", {{"abs", c.tolerance.abs}, {"rel", c.tolerance.rel},
                       {"justification", c.justification}}},
        {"status", outcome_name(c.outcome)},
        {"seconds", number(c.seconds)},
        {"diagnostics", c.diagnostics},
    });
    if (!c.error.empty()) checks.back()["error"] = c.error;
    if (c.reproduction)
      checks.back()["recorded"] = {{"value", number(c.recorded)}, {"rel_tolerance", c.recorded_tolerance}};
  }
  json figures = json::array();
  for (const auto& f : report.figures) {
    json series = json::array();
    for (const auto& s : f.series) {
      json xs = json::array(), ys = json::array();
      for (double x : s.x) xs.push_back(number(x));
      for (double y : s.y) ys.push_back(number(y));
      series.push_back({{"label", s.label}, {"x", xs}, {"y", ys}});
      if (!s.z.empty()) {
        json zs = json::array();
        for (double z : s.z) zs.push_back(number(z));
        series.back()["z"] = zs;
      }
    }
    figures.push_back({{"id", f.id}, {"section", f.section}, {"title", f.title},
                       {"xlabel", f.xlabel}, {"ylabel", f.ylabel}, {"series", series},
                       {"log_x", f.log_x}, {"log_y", f.log_y}, {"impulses", f.impulses}, {"points", f.points},
                       {"colour_label", f.colour_label},
                       {"file", "figures/" + f.id + ".svg"}, {"data", "figures/" + f.id + ".csv"}});
  }
  json notes = json::array();
  for (const auto& n : report.notes) notes.push_back({{"section", n.section}, {"text", n.text}});
  json out = provenance();
  out["schema_version"] = 2;  // 2: summary by outcome, section_failures, fingerprint_digest
  out["tier"] = report.tier;
  const auto n = report.counts();
  out["summary"] = {{"checks", n.checks}, {"pass", n.pass}, {"reproduced", n.reproduced},
                    {"missed", n.missed}, {"failed", n.failed}, {"sections_failed", n.sections_failed}};
  json failures = json::array();
  for (const auto& f : report.section_failures) failures.push_back({{"section", f.id}, {"error", f.error}});
  out["section_failures"] = failures;
  out["checks"] = checks;
  out["figures"] = figures;
  out["notes"] = notes;
  return out;
}

std::string to_markdown(const Report& report, const json& meta) {
  std::string md;
  md += fmt::format("# gearbench verification report — {} tier\n\n", report.tier);
  md += fmt::format("Commit `{}`{} · gearbench {} · {} · {} build · {} ({} cores) · {}\n\n",
                    meta["code"]["git_sha"].get<std::string>(),
                    meta["code"]["dirty"].get<bool>() ? " (dirty)" : "",
                    meta["code"]["version"].get<std::string>(),
                    meta["build"]["compiler"].get<std::string>(),
                    meta["build"]["build_type"].get<std::string>(),
                    meta["machine"]["cpu_model"].get<std::string>(),
                    meta["machine"]["cores"].get<unsigned>(),
                    meta["created_utc"].get<std::string>());
  md += headline_markdown(report.counts());
  md += section_failures_markdown(report.section_failures);

  md += "## Overview\n\n| check | solver | reference | quantity | value | reference value | "
        "deviation | tolerance | status |\n|---|---|---|---|---|---|---|---|---|\n";
  const json j = to_json(report);
  for (const auto& c : j["checks"]) {
    const auto& tol = c["tolerance"];
    std::string tol_text;
    const std::string unit =
        c["unit"] == "-" ? std::string() : fmt::format(" {}", c["unit"].get<std::string>());
    if (tol["abs"].get<double>() > 0) tol_text += fmt::format("±{:.3g}{}", tol["abs"].get<double>(), unit);
    if (tol["rel"].get<double>() > 0)
      tol_text += fmt::format("{}{:.3g} %", tol_text.empty() ? "±" : " + ", 100 * tol["rel"].get<double>());
    md += fmt::format("| `{}` | {} | {} | {} [{}] | {} | {} | {} | {} | {} |\n",
                      c["id"].get<std::string>(), cell(c["solver"].get<std::string>()),
                      cell(c["reference"].get<std::string>()),
                      cell(c["quantity"].get<std::string>()), c["unit"].get<std::string>(),
                      format_number(c["value"]), format_number(c["reference_value"]),
                      format_number(c["abs_error"]), tol_text,
                      c["status"] == "fail" ? std::string("**FAIL**") : c["status"].get<std::string>());
  }

  // Sections in order of first appearance.
  std::vector<std::string> sections;
  auto add_section = [&](const std::string& s) {
    if (std::find(sections.begin(), sections.end(), s) == sections.end()) sections.push_back(s);
  };
  for (const auto& c : report.checks) add_section(c.section);
  for (const auto& n : report.notes) add_section(n.section);
  for (const auto& f : report.figures) add_section(f.section);

  for (const auto& section : sections) {
    md += fmt::format("\n## {}\n\n", section);
    for (const auto& n : report.notes)
      if (n.section == section) md += n.text + "\n\n";
    bool header = false;
    for (const auto& c : j["checks"]) {
      if (c["section"] != section) continue;
      if (!header) {
        md += "| check | value | reference | tolerance justification | time [s] |\n|---|---|---|---|---|\n";
        header = true;
      }
      md += fmt::format("| `{}` | {} | {} | {} | {:.3g} |\n", c["id"].get<std::string>(),
                        format_number(c["value"]), format_number(c["reference_value"]),
                        cell(c["tolerance"]["justification"].get<std::string>()),
                        c["seconds"].is_null() ? 0.0 : c["seconds"].get<double>());
      if (c.contains("error")) md += fmt::format("\n> error: {}\n\n", c["error"].get<std::string>());
    }
    for (const auto& f : report.figures)
      if (f.section == section)
        md += fmt::format("\n![{}](figures/{}.svg) ([data](figures/{}.csv))\n", f.title, f.id, f.id);
  }
  md += "\n## Build\n\n| dependency | version |\n|---|---|\n";
  for (const auto& [name, version] : meta["build"]["dependencies"].items())
    md += fmt::format("| {} | {} |\n", name, version.get<std::string>());
  md += fmt::format("\nFlags: `{}`\n", meta["build"]["flags"].get<std::string>());
  return md;
}

namespace {
void write_file(const fs::path& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
  out.flush();
  if (!out) throw std::runtime_error("cannot write " + path.string());
}
}  // namespace

std::string write_report(const Report& report, const std::string& parent) {
  fs::create_directories(parent);
  const std::string name = report_folder_name();
  fs::path target = fs::path(parent) / name;
  for (int suffix = 2; fs::exists(target); ++suffix)
    target = fs::path(parent) / fmt::format("{}-{}", name, suffix);

  const fs::path temp = fs::path(parent) / fmt::format(".tmp-{}-{}", name, ::getpid());
  fs::remove_all(temp);
  fs::create_directories(temp / "figures");
  try {
    const json j = to_json(report);
    write_file(temp / "report.json", j.dump(2) + "\n");
    write_file(temp / "report.md", to_markdown(report, j));
    for (const auto& f : report.figures) write_figure(f, (temp / "figures" / f.id).string());
    fs::rename(temp, target);
  } catch (...) {
    fs::remove_all(temp);  // never leave a half-written report behind
    throw;
  }
  return target.string();
}

}  // namespace gearbench::reports
