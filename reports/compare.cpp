#include "compare.h"

#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <map>

#include "model/errors.h"
#include "model/json_reader.h"

namespace gearbench::reports {

using nlohmann::json;

json load_report(const std::string& path) {
  std::filesystem::path p(path);
  if (std::filesystem::is_directory(p)) p /= "report.json";
  json j = model::read_json_file(p.string());
  if (!j.contains("schema_version") || !j.contains("checks"))
    throw InputError(fmt::format("{}: not a gearbench report (no schema_version/checks)", p.string()));
  return j;
}

namespace {
std::map<std::string, json> by_id(const json& report) {
  std::map<std::string, json> out;
  for (const auto& c : report["checks"]) out[c["id"].get<std::string>()] = c;
  return out;
}
std::string show(const json& v) { return v.is_null() ? "null" : fmt::format("{:.10g}", v.get<double>()); }

/// Fingerprints are compared only when both were made by the same digest. Reports of
/// schema 1 carry no `fingerprint_digest`: theirs came from std::hash, which is not stable
/// between builds, so such a report matches only another of its kind (as before), never a
/// report with an FNV-1a fingerprint: their timings are then not compared.
bool same_machine(const json& before, const json& after) {
  const auto digest = [](const json& machine) { return machine.value("fingerprint_digest", std::string("std::hash")); };
  const json& a = before["machine"];
  const json& b = after["machine"];
  return digest(a) == digest(b) && a["fingerprint"] == b["fingerprint"];
}

}  // namespace

Comparison compare_reports(const json& before, const json& after) {
  Comparison out;
  out.same_machine = same_machine(before, after);
  const auto a = by_id(before);
  const auto b = by_id(after);
  for (const auto& [id, old] : a) {
    const auto it = b.find(id);
    if (it == b.end()) {
      out.removed.push_back(id);
      continue;
    }
    const json& now = it->second;
    if (old["value"] != now["value"])
      out.changed.push_back(fmt::format("{}: {} -> {}", id, show(old["value"]), show(now["value"])));
    if (old["status"] != "fail" && now["status"] == "fail") out.regressions.push_back(id);
    if (old["status"] == "fail" && now["status"] != "fail") out.fixed.push_back(id);
    if (out.same_machine && old["seconds"].is_number() && now["seconds"].is_number()) {
      const double t0 = old["seconds"].get<double>();
      const double t1 = now["seconds"].get<double>();
      if (t1 > timing_floor_seconds && t1 > slower_threshold * t0)
        out.slower.push_back(fmt::format("{}: {:.3g} s -> {:.3g} s (x{:.2f})", id, t0, t1, t1 / t0));
    }
  }
  for (const auto& [id, now] : b)
    if (!a.count(id)) out.added.push_back(id);
  return out;
}

std::string Comparison::text() const {
  std::string s;
  auto block = [&s](const std::string& title, const std::vector<std::string>& items) {
    if (items.empty()) return;
    s += fmt::format("{} ({}):\n", title, items.size());
    for (const auto& i : items) s += "  " + i + "\n";
  };
  block("REGRESSIONS: pass -> fail", regressions);
  block("fixed: fail -> pass", fixed);
  block("changed values", changed);
  block(fmt::format("slower by more than {:.0f} %", 100 * (slower_threshold - 1)), slower);
  block("added checks", added);
  block("removed checks", removed);
  if (!same_machine) s += "timings not compared: the reports come from different machines/builds\n";
  if (s.empty()) s = "no differences\n";
  return s;
}

}  // namespace gearbench::reports
