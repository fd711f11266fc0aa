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

int verify_command(const std::string& tier, const std::string& out_dir, const std::string& cases_dir,
                   const std::string& bench_record, const std::string& only) {
  const auto parsed = verification::parse_tier(tier);
  if (!std::filesystem::is_directory(cases_dir))
    throw InputError(fmt::format("--cases {}: not a directory", cases_dir));
  const verification::CheckContext context{cases_dir};
  auto report = verification::run_verification(
      parsed, context, [](const std::string& line) { std::cerr << line << std::endl; }, only);
  if (!bench_record.empty()) report.notes.push_back(reports::benchmark_note(model::read_json_file(bench_record)));
  const std::string folder = [&] {
    const DeferInterrupts defer;  // the report folder appears whole or not at all
    return reports::write_report(report, out_dir);
  }();
  const auto counts = report.counts();
  std::cerr << reports::headline(counts) << "\n";
  for (const auto& f : report.section_failures) std::cerr << fmt::format("section {} FAILED: {}\n", f.id, f.error);
  std::cout << folder << "/report.md\n";
  return verification::gate_passes(counts) ? exit_ok : exit_failed;
}

}  // namespace gearbench::app
