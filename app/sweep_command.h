#pragma once
// `gearbench sweep SWEEP.json`: a grid over any keys of a base case, each case run through
// the kind registry as by `gearbench run`, into a CSV and JSON table plus figures.
//
//   { "base": "seed004_spur_efficiency.json",       (a path, or the case object itself)
//     "vary": { "operating.pinion_torque_Nm": [50, 100, 200],
//               "operating.pinion_speed_rpm": [500, 1000] },
//     "outputs": ["efficiency_mean", "power_loss_mean_W"] }
//
// Keys are dotted paths ("gear_pair.teeth.0" indexes an array) or JSON pointers
// ("/gear_pair/teeth/0"); the last key varies fastest. The result of a case depends only
// on its index, so the table is the same whatever the number of MPI ranks.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "report.h"

namespace gearbench::app {

struct SweepAxis {
  std::string key;                    ///< as written in the sweep file
  nlohmann::json::json_pointer where;  ///< into the case
  std::vector<nlohmann::json> values;
};

struct SweepSpec {
  std::string name;  ///< the sweep file's stem
  std::string base_source;
  nlohmann::json base;  ///< the base case
  std::vector<SweepAxis> axes;
  std::vector<std::string> outputs;
  std::string description;

  [[nodiscard]] std::size_t size() const;
  /// The grid values of case `index` (one per axis, last axis fastest).
  [[nodiscard]] std::vector<nlohmann::json> values_at(std::size_t index) const;
  /// The base case with the values of case `index` set.
  [[nodiscard]] nlohmann::json case_at(std::size_t index) const;
};

/// Parses and validates a sweep (InputError naming the key); `base` paths are resolved
/// against `sweep_dir` first, then the working directory.
SweepSpec parse_sweep_spec(const nlohmann::ordered_json& spec, const std::string& sweep_dir,
                           const std::string& name);
SweepSpec read_sweep_file(const std::string& path);

/// A dotted path or JSON pointer as a JSON pointer (InputError when malformed, naming the
/// key under `section`: "vary" or "outputs").
nlohmann::json::json_pointer key_pointer(const std::string& key, const std::string& section = "vary");

struct SweepRow {
  std::size_t index = 0;
  nlohmann::json outputs = nlohmann::json::object();  ///< output name -> value
  std::string error;       ///< empty when the case ran
  std::string error_kind;  ///< "bad_input", "not_converged", "internal"
  double seconds = 0.0;
  int rank = 0;
  [[nodiscard]] nlohmann::json to_json() const;
  static SweepRow from_json(const nlohmann::json& j);
};

/// Runs case `index`; any error is recorded in the row, never thrown.
SweepRow run_sweep_case(const SweepSpec& spec, std::size_t index);

/// The table: one line per case with the grid values, the outputs and the error. No
/// timings, so that it is identical for any number of ranks.
std::string sweep_csv(const SweepSpec& spec, const std::vector<SweepRow>& rows);
nlohmann::json sweep_json(const SweepSpec& spec, const std::vector<SweepRow>& rows, int ranks);
/// One figure per numeric output over the first axis, one series per combination of the
/// other axes.
std::vector<reports::Figure> sweep_figures(const SweepSpec& spec, const std::vector<SweepRow>& rows);

}  // namespace gearbench::app
