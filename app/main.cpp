// gearbench: command-line front end. Parses, dispatches, prints; no physics.
#include <CLI/CLI.hpp>
#include <cerrno>
#include <cstring>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <iostream>

#include "build_info.h"
#include "commands.h"
#include "interrupt.h"
#include "model/errors.h"
#include "model/json_reader.h"
#include "model/plugin.h"

namespace {

std::string version_string() {
  return fmt::format("gearbench {} (git {}{})", gearbench::build::version(),
                     gearbench::build::git_sha(), gearbench::build::git_dirty() ? "-dirty" : "");
}

/// Flushes stdout; OutputError if anything written to it was lost (`run > /dev/full`).
void check_stdout() {
  std::cout.flush();
  if (!std::cout) throw gearbench::app::OutputError(fmt::format("writing to stdout failed: {}", std::strerror(errno)));
}

/// A usage error as the one `error:` line of the CLI contract (CLI11 prints two lines, and
/// no prefix); help and version go out as CLI11 prints them.
int usage_error(const CLI::App& cli, const CLI::ParseError& e) {
  using namespace gearbench::app;
  if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) {
    cli.exit(e);
    return exit_ok;
  }
  std::string message = e.what();
  if (const auto extras = cli.remaining(); !extras.empty())
    message += fmt::format("; not understood: {}", fmt::join(extras, " "));
  std::cerr << "error: " << gearbench::model::shown_text(message) << " (see gearbench --help)\n";
  return exit_bad_input;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace gearbench::app;
  CLI::App cli{"gearbench: gear tribology and dynamics solvers, verified against independent references"};
  cli.set_version_flag("--version", version_string());
  cli.require_subcommand(1);

  std::string case_path, output_path;
  auto* run = cli.add_subcommand("run", "solve one case file; JSON result on stdout (or -o)");
  run->add_option("case", case_path, "case file (JSON); its \"kind\" picks the solver")->required();
  run->add_option("-o,--output", output_path, "write the JSON result here instead of stdout");

  std::string tier = "fast", out_dir = default_output_dir(), cases_dir = default_cases_dir();
  auto* verify = cli.add_subcommand("verify", "run the verification matrix and write a versioned report");
  verify->add_option("--tier", tier, "fast or full")->check(CLI::IsMember({"fast", "full"}));
  verify->add_option("--out", out_dir, "parent folder of the report")->capture_default_str();
  verify->add_option("--cases", cases_dir, "folder of the built-in cases")->capture_default_str();
  std::string bench_record;
  verify->add_option("--bench", bench_record, "a `gearbench bench` record to include as the Benchmarks section");
  std::string only;
  verify->add_option("--only", only, "regular expression: run only the checks and sections whose id matches");

  auto* report = cli.add_subcommand("report", "work with reports");
  report->require_subcommand(1);
  std::string before, after;
  auto* compare = report->add_subcommand("compare", "show what changed between two reports");
  compare->add_option("A", before, "earlier report folder or report.json")->required();
  compare->add_option("B", after, "later report folder or report.json")->required();

  auto* perf = report->add_subcommand("perf", "performance history over commits from `bench --record` records");
  PerfReportRequest perf_request{.dir = default_perf_dir(), .out_dir = default_output_dir() + "/perf"};
  perf->add_option("--dir", perf_request.dir, "folder of the benchmark records")->capture_default_str();
  perf->add_option("--out", perf_request.out_dir, "folder for perf.md, perf.json and figures/")->capture_default_str();
  perf->add_option("--alpha", perf_request.alpha, "significance level of the U test")->capture_default_str();
  perf->add_option("--threshold", perf_request.threshold,
                   "relative change of the median below which nothing is flagged")->capture_default_str();
  perf->add_option("--clock", perf_request.clock, "compare CPU time (default) or real (wall-clock) time")
      ->check(CLI::IsMember({"cpu", "real"}))->capture_default_str();
  perf->add_flag("--pdf", perf_request.pdf, "also draw the figures as PDF");
  std::string pdf_report;
  auto* pdf = report->add_subcommand("pdf", "draw a report's figures as PDF (for publications)");
  pdf->add_option("REPORT", pdf_report, "report folder or report.json")->required();

  std::string bench_out = default_output_dir() + "/bench", filter;
  double min_time = 0.2;
  auto* bench = cli.add_subcommand("bench", "run the benchmarks and record them with their context");
  bench->add_option("--out", bench_out, "folder for the benchmark record")->capture_default_str();
  bench->add_option("--filter", filter, "regular expression selecting benchmarks");
  bench->add_option("--min-time", min_time, "minimum seconds per benchmark")->capture_default_str();
  bool record_run = false;
  int repetitions = 0;
  bench->add_flag("--record", record_run,
                  "a performance-history record: repetitions, into reports/perf/<date>_<sha>.json");
  auto* repetitions_option = bench->add_option("--repetitions", repetitions,
                                               "repetitions of every benchmark (default 10 with --record, 5 with "
                                               "--commits, else 1)");
  BenchRangeRequest range{.repo = gearbench::build::source_dir(),
                          .workdir = std::string(gearbench::build::source_dir()) + "/build/perf-worktrees",
                          .build_script = std::string(gearbench::build::source_dir()) + "/scripts/build-commit"};
  auto* commits_option = bench->add_option("--commits", range.commits,
                                           "benchmark past commits: a range A..B and/or single commits, each "
                                           "built in its own worktree, one record each in reports/perf");
  bench->add_option("--every", range.every, "with --commits: every K-th commit of a range (its newest always)")
      ->capture_default_str();
  bench->add_option("--set", range.set, "with --commits: benchmark set short (< 2 min) or full, unless --filter")
      ->check(CLI::IsMember({"short", "full"}))->capture_default_str();
  bench->add_option("--repo", range.repo, "with --commits: the git checkout whose commits are built")
      ->capture_default_str();
  bench->add_option("--workdir", range.workdir, "with --commits: folder of the worktrees and their builds")
      ->capture_default_str();
  bench->add_option("--build-script", range.build_script,
                    "with --commits: `SCRIPT SHA WORKDIR` builds SHA and prints its benchmark executable")
      ->capture_default_str();
  bench->add_flag("--keep-worktrees", range.keep_worktrees, "with --commits: keep the worktrees and builds");

  std::string sweep_path, sweep_out;
  bool sweep_pdf = false;
  auto* sweep = cli.add_subcommand("sweep", "run a grid of cases (over MPI ranks under mpirun) into a table and figures");
  sweep->add_option("SWEEP", sweep_path, "sweep file (JSON): base, vary, outputs")->required();
  sweep->add_option("--out", sweep_out, "output folder (default reports/out/sweep/<sweep name>)");
  sweep->add_flag("--pdf", sweep_pdf, "also draw the figures as PDF");

  std::string oil_name;
  double oil_temperature_C = 0.0;
  auto* lubricants = cli.add_subcommand("lubricants", "list the lubricant catalogue, or resolve one oil at a temperature");
  lubricants->add_option("NAME", oil_name, "oil name, e.g. \"ISO VG 320 mineral\"");
  auto* oil_temperature = lubricants->add_option("--temperature-C", oil_temperature_C, "temperature [degC]");

  std::string schema_kind;
  auto* schema = cli.add_subcommand("schema", "print the JSON Schema of a kind's case files (all kinds without KIND)");
  schema->add_option("KIND", schema_kind, "case kind, e.g. stiffness");

  install_interrupt_handler();
  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return usage_error(cli, e);
  }

  const auto dispatch = [&]() -> int {
    if (*run) return run_command(case_path, output_path);
    if (*verify) return verify_command(tier, out_dir, cases_dir, bench_record, only);
    if (*compare) return report_compare_command(before, after);
    if (*perf) return report_perf_command(perf_request);
    if (*pdf) return report_pdf_command(pdf_report);
    if (*sweep) return sweep_command(sweep_path, sweep_out, sweep_pdf);
    if (*bench && commits_option->count()) {
      range.out_dir = bench->count("--out") ? bench_out : default_perf_dir();
      range.filter = filter;
      range.min_time = min_time;
      if (repetitions_option->count()) range.repetitions = repetitions;
      return bench_range_command(range);
    }
    if (*schema) return schema_command(schema_kind);
    if (*lubricants)
      return lubricants_command(oil_name, oil_temperature->count() ? std::optional(oil_temperature_C) : std::nullopt);
    if (*bench) {
      const bool out_given = bench->count("--out") > 0;
      return bench_command({.out_dir = record_run && !out_given ? default_perf_dir() : bench_out,
                            .filter = filter, .min_time = min_time,
                            .repetitions = repetitions_option->count() ? repetitions : (record_run ? 10 : 1),
                            .record = record_run});
    }
    return exit_failed;
  };
  try {
    const int code = dispatch();
    check_stdout();
    return code;
  } catch (const gearbench::InputError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return exit_bad_input;
  } catch (const gearbench::ConvergenceError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return exit_not_converged;
  } catch (const OutputError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return exit_failed;
  } catch (const gearbench::PluginError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return exit_failed;
  } catch (const std::exception& e) {
    std::cerr << "error: internal: " << e.what() << "\n";
    return exit_failed;
  }
}
