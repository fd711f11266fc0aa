#pragma once
// Figure-by-figure comparison of two reports (`gearbench report compare A B`).
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace gearbench::reports {

struct Comparison {
  std::vector<std::string> changed;      ///< checks whose value changed
  std::vector<std::string> regressions;  ///< checks that went from pass to fail
  std::vector<std::string> fixed;        ///< fail to pass
  std::vector<std::string> slower;       ///< > 20 % slower (same machine fingerprint only)
  std::vector<std::string> added;
  std::vector<std::string> removed;
  bool same_machine = false;

  [[nodiscard]] std::string text() const;
};

/// Timing ratio above which a check is flagged slower (same machine only).
constexpr double slower_threshold = 1.20;
/// Timings below this are noise and never flagged [s].
constexpr double timing_floor_seconds = 0.05;

Comparison compare_reports(const nlohmann::json& before, const nlohmann::json& after);

/// Loads report.json from a report folder or a direct path (InputError if unreadable).
nlohmann::json load_report(const std::string& path);

}  // namespace gearbench::reports
