#include "perf_range.h"

#include <algorithm>
#include <fmt/format.h>
#include <set>

#include "bench_ratios.h"
#include "model/errors.h"

namespace gearbench::reports {

using nlohmann::json;

std::string benchmark_set_filter(const std::string& set) {
  // The short set: one fast benchmark of each solver that has had the same name since the
  // first commits, each with its baseline where it has one (so the ratios show too). The
  // EHL sizes are given as alternatives because the oldest commits ran BM_EhlSteadySolve
  // and BM_EhlDeformation on other grids: a size a commit lacks is recorded as missing.
  if (set == "short")
    return "^BM_(GeometryProfile|GeometryProfile_baseline|StiffnessSpurCycle|StiffnessSpurCycle_baseline|"
           "EfficiencySpur|EfficiencySpur_baseline|ContactFriction|ContactFriction_baseline)(/[0-9]+)?$|"
           "^BM_EhlSteadySolve(_baseline)?/257$|^BM_EhlSteadySolve/(513|1025)$|"
           "^BM_EhlDeformation(_baseline)?/1025$";
  if (set == "full") return "";
  throw InputError(fmt::format("--set {}: expected short or full", set));
}

std::vector<std::string> every_kth(const std::vector<std::string>& commits, int every) {
  if (every < 1) throw InputError(fmt::format("--every {}: must be ≥ 1", every));
  std::vector<std::string> out;
  for (std::size_t back = 0; back < commits.size(); back += static_cast<std::size_t>(every))
    out.push_back(commits[commits.size() - 1 - back]);
  std::reverse(out.begin(), out.end());
  return out;
}

std::vector<std::pair<int, std::size_t>> interleaved_schedule(std::size_t commits, int repetitions) {
  std::vector<std::pair<int, std::size_t>> out;
  for (int r = 0; r < repetitions; ++r)
    for (std::size_t k = 0; k < commits; ++k) out.emplace_back(r, r % 2 == 0 ? k : commits - 1 - k);
  return out;
}

std::string interleaving_note(std::size_t commits, int repetitions) {
  return fmt::format(
      "{} repetitions of each of {} commits, interleaved: repetition r of every commit ran before "
      "repetition r + 1 of any (alternating direction), each in its own process, so that a drift "
      "of the shared machine falls on all commits alike",
      repetitions, commits);
}

json join_repetitions(const std::vector<json>& outputs) {
  json joined{{"benchmarks", json::array()}};
  if (outputs.empty()) return joined;
  joined["context"] = outputs.front().value("context", json::object());
  const int repetitions = static_cast<int>(outputs.size());
  for (int r = 0; r < repetitions; ++r)
    for (json run : outputs[static_cast<std::size_t>(r)].value("benchmarks", json::array())) {
      if (run.value("run_type", "iteration") != "iteration") continue;  // aggregates are recomputed
      run["repetition_index"] = r;
      run["repetitions"] = repetitions;
      joined["benchmarks"].push_back(std::move(run));
    }
  return joined;
}

std::vector<std::string> run_names(const json& joined) {
  std::set<std::string> names;
  for (const auto& run : joined.value("benchmarks", json::array()))
    if (run.value("run_type", "iteration") == "iteration") names.insert(run.at("run_name").get<std::string>());
  return {names.begin(), names.end()};
}

std::vector<std::vector<std::string>> missing_benchmarks(const std::vector<CommitOutcome>& outcomes) {
  std::vector<std::vector<std::string>> ran;
  std::set<std::string> all;
  for (const auto& o : outcomes) {
    ran.push_back(run_names(join_repetitions(o.outputs)));
    all.insert(ran.back().begin(), ran.back().end());
  }
  std::vector<std::vector<std::string>> missing;
  for (const auto& names : ran) {
    missing.emplace_back();
    std::set_difference(all.begin(), all.end(), names.begin(), names.end(), std::back_inserter(missing.back()));
  }
  return missing;
}

json range_record(const CommitOutcome& outcome, const RangeContext& range, const std::vector<std::string>& missing,
                  const json& provenance) {
  json record = join_repetitions(outcome.outputs);
  record["gearbench"] = provenance;
  json& g = record["gearbench"];
  // The runner's own commit stays on record: it joined, timed and wrote this record.
  g["runner_code"] = g.value("code", json::object());
  // The short sha, as `bench --record` and the report folders name a commit.
  g["code"] = {{"git_sha", outcome.sha.substr(0, 10)}, {"git_sha_full", outcome.sha}, {"dirty", false},
               {"commit_time_utc", outcome.commit_time_utc}};
  g["repetitions"] = range.repetitions;
  g["status"] = outcome.status;
  if (!outcome.log_tail.empty()) g["log_tail"] = outcome.log_tail;
  g["missing"] = missing;
  g["range"] = {{"set", range.set}, {"filter", range.filter}, {"commits", range.commits},
                {"interleaving", interleaving_note(range.commits.size(), range.repetitions)}};
  record["ratios"] = side_by_side_ratios(record["benchmarks"]);
  record["scaling"] = scaling_exponents(record["benchmarks"]);
  return record;
}

}  // namespace gearbench::reports
