// `gearbench bench --commits A..B`: the performance history of past commits (issue 25), as
// asv's `asv run A..B` makes it. Each commit is built apart from the user's checkout, in a
// git worktree under --workdir, by a build script (scripts/build-commit: Release, only the
// benchmark target, ccache; `SCRIPT SHA WORKDIR` prints the executable, `SCRIPT --clean
// WORKDIR` removes what the builds left); the chosen benchmarks run with their repetitions
// interleaved across the commits, and each commit gets one record in reports/perf. A commit
// that does not build or whose benchmarks fail is recorded so and the range goes on, but the
// command then names each such commit with the end of its log and exits 1.
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <iostream>
#include <sstream>

#include "bench_support.h"
#include "commands.h"
#include "model/errors.h"
#include "model/json_reader.h"
#include "perf_range.h"
#include "report.h"

namespace gearbench::app {

namespace fs = std::filesystem;
using nlohmann::json;

void BenchRangeRequest::validate() const {
  if (commits.empty()) throw InputError("--commits: name a range A..B or commits");
  if (every < 1) throw InputError(fmt::format("--every {}: must be ≥ 1", every));
  if (repetitions < 1 || repetitions > 1000)
    throw InputError(fmt::format("--repetitions = {}: must lie in [1, 1000]", repetitions));
  if (!(min_time > 0.0)) throw InputError(fmt::format("--min-time = {}: must be > 0 s", min_time));
  if (filter.empty()) reports::benchmark_set_filter(set);  // throws for an unknown set
  if (!fs::exists(build_script)) throw InputError(fmt::format("--build-script {}: no such file", build_script));
}

namespace {

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) out.push_back(line);
  return out;
}

std::string git(const std::string& repo, const std::string& args) {
  const auto r = capture(fmt::format("git -C {} {} 2>/dev/null", shell_quoted(repo), args));
  return r.exit_code == 0 ? r.out : std::string();
}

/// The full shas of one --commits spec, oldest first: a range along its first-parent
/// history thinned to every K-th commit, or one commit.
std::vector<std::string> resolve_spec(const std::string& repo, const std::string& spec, int every) {
  if (spec.find("..") != std::string::npos) {
    const auto shas = lines_of(git(repo, "rev-list --reverse --first-parent " + shell_quoted(spec)));
    if (shas.empty()) throw InputError(fmt::format("--commits {}: no commits in this range of {}", spec, repo));
    return reports::every_kth(shas, every);
  }
  const auto sha = lines_of(git(repo, "rev-parse --verify " + shell_quoted(spec + "^{commit}")));
  if (sha.empty()) throw InputError(fmt::format("--commits {}: not a commit of {}", spec, repo));
  return sha;
}

/// Every commit the request names, once, in commit order.
std::vector<reports::CommitOutcome> resolve_commits(const BenchRangeRequest& request) {
  std::vector<reports::CommitOutcome> out;
  for (const auto& spec : request.commits)
    for (const auto& sha : resolve_spec(request.repo, spec, request.every))
      if (std::none_of(out.begin(), out.end(), [&](const auto& o) { return o.sha == sha; }))
        out.push_back({.sha = sha, .commit_time_utc = commit_time_utc(request.repo, sha)});
  std::stable_sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.commit_time_utc < b.commit_time_utc; });
  return out;
}

std::string tail(const std::string& text, std::size_t lines) {
  auto all = lines_of(text);
  if (all.size() > lines) all.erase(all.begin(), all.end() - static_cast<long>(lines));
  std::string out;
  for (const auto& l : all) out += l + "\n";
  return out;
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), {}};
}

/// Builds one commit; the path of its benchmark executable, or "" with the outcome marked.
std::string build(const BenchRangeRequest& request, reports::CommitOutcome& outcome) {
  const auto log = fs::path(request.workdir) / (outcome.sha.substr(0, 12) + ".runner.log");
  std::cerr << fmt::format("building {} ({})\n", outcome.sha.substr(0, 10), outcome.commit_time_utc);
  const auto r = capture(fmt::format("{} {} {} 2>{}", shell_quoted(request.build_script), outcome.sha,
                                     shell_quoted(request.workdir), shell_quoted(log.string())));
  const auto out = lines_of(r.out);
  if (r.exit_code == 0 && !out.empty() && fs::exists(out.back())) return out.back();
  outcome.status = "build_failed";
  outcome.log_tail = tail(read_text(log), 20) +
                     (r.exit_code != 0 ? fmt::format("{} exited with code {}\n", request.build_script, r.exit_code)
                                       : fmt::format("{} printed no executable that exists (last line: \"{}\")\n",
                                                     request.build_script, out.empty() ? "" : out.back()));
  std::cerr << fmt::format("  {} does not build; recorded as such\n", outcome.sha.substr(0, 10));
  return "";
}

/// One repetition of the chosen benchmarks of one commit, in its own process; the outcome
/// is marked run_failed when the executable fails.
void run_once(const BenchRangeRequest& request, const std::string& exe, const std::string& filter, int repetition,
              reports::CommitOutcome& outcome) {
  const auto out = fs::path(request.workdir) / (outcome.sha.substr(0, 12) + ".bench.json");
  const auto log = fs::path(request.workdir) / (outcome.sha.substr(0, 12) + ".bench.log");
  fs::remove(out);
  const auto r = capture(fmt::format(
      "{} --benchmark_out={} --benchmark_out_format=json --benchmark_min_time={} --benchmark_repetitions=1 {} "
      ">{} 2>&1",
      shell_quoted(exe), shell_quoted(out.string()), request.min_time,
      filter.empty() ? "" : "--benchmark_filter=" + shell_quoted(filter), shell_quoted(log.string())));
  if (r.exit_code != 0) {
    outcome.status = "run_failed";
    outcome.log_tail = tail(read_text(log), 20) +
                       fmt::format("{} exited with code {} at repetition {}\n", exe, r.exit_code, repetition + 1);
    return;
  }
  // A commit none of whose benchmarks match writes no output: it ran nothing.
  outcome.outputs.push_back(fs::exists(out) ? model::read_json_file(out.string()) : json::object());
  fs::remove(out);
}

/// Which commit failed, how, where its record is, and the end of the log that says why.
std::string failure_text(const reports::CommitOutcome& outcome, const fs::path& record) {
  std::string text = fmt::format("  {} ({}) {}; record {}:\n", outcome.sha.substr(0, 10), outcome.commit_time_utc,
                                 outcome.status == "build_failed" ? "does not build" : "its benchmarks failed",
                                 record.string());
  for (const auto& line : lines_of(outcome.log_tail)) text += "    | " + line + "\n";
  return text;
}

}  // namespace

int bench_range_command(const BenchRangeRequest& request) {
  request.validate();
  auto outcomes = resolve_commits(request);
  const std::string filter = request.filter.empty() ? reports::benchmark_set_filter(request.set) : request.filter;
  fs::create_directories(request.workdir);
  fs::create_directories(request.out_dir);
  const auto start = std::chrono::steady_clock::now();
  std::vector<std::string> exes;
  for (auto& o : outcomes) exes.push_back(build(request, o));
  for (const auto& [r, k] : reports::interleaved_schedule(outcomes.size(), request.repetitions)) {
    if (outcomes[k].status != "ok") continue;
    std::cerr << fmt::format("repetition {}/{}: {}\n", r + 1, request.repetitions, outcomes[k].sha.substr(0, 10));
    run_once(request, exes[k], filter, r, outcomes[k]);
  }
  reports::RangeContext range{.set = request.filter.empty() ? request.set : "custom", .filter = filter,
                              .repetitions = request.repetitions};
  for (const auto& o : outcomes) range.commits.push_back(o.sha);
  const auto missing = reports::missing_benchmarks(outcomes);
  const auto provenance = reports::provenance();
  std::string failures;
  int failed = 0;
  for (std::size_t k = 0; k < outcomes.size(); ++k) {
    // Named by commit date, so that the folder lists the history in commit order.
    const auto stem = outcomes[k].commit_time_utc.substr(0, 10) + "_" + outcomes[k].sha.substr(0, 10);
    const auto target = free_path(request.out_dir, stem);
    write_record(target, reports::range_record(outcomes[k], range, missing[k], provenance));
    if (outcomes[k].status != "ok") {
      ++failed;
      failures += failure_text(outcomes[k], target);
    }
    std::cout << target.string() << "\n";
  }
  if (!request.keep_worktrees)
    capture(fmt::format("{} --clean {} >&2", shell_quoted(request.build_script), shell_quoted(request.workdir)));
  const double minutes = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / 60.0;
  std::cerr << fmt::format("{} commits, {} not built or not run, {:.1f} min\n", outcomes.size(), failed, minutes);
  if (failed == 0) return exit_ok;
  // Like a sweep with a failed case: every record is written, but the range is not whole.
  std::cerr << fmt::format("error: {} of {} commits failed (recorded so; the range went on):\n{}", failed,
                           outcomes.size(), failures);
  return exit_failed;
}

}  // namespace gearbench::app
