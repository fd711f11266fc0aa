#pragma once
// Case kinds: each solver registers the `"kind"` it answers and a runner from the case
// JSON to the result JSON, so main() never grows a switch.
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace gearbench::app {

struct KindSpec {
  std::string name;
  std::string summary;
  /// Validates the case (InputError on bad input) and returns the result as JSON.
  std::function<nlohmann::json(const nlohmann::json& case_json)> run;
  /// The object schemas of the case's keys beside "kind" and "description", made from the
  /// tables its reader reads (case_schema.h); every kind has them.
  std::function<std::vector<nlohmann::json>()> schema_parts = {};
  /// A kind whose other keys depend on one key's value (the dynamics kind's "model"): that
  /// key (declared in schema_parts) and, per value, the parts its reader then reads.
  struct SchemaVariant {
    std::string value;
    std::function<std::vector<nlohmann::json>()> parts;
  };
  std::string variant_key = {};
  std::vector<SchemaVariant> schema_variants = {};
};

class KindRegistry {
 public:
  static KindRegistry& instance();
  void add(KindSpec kind);
  [[nodiscard]] const KindSpec& find(const std::string& name) const;  // InputError if unknown
  [[nodiscard]] const std::map<std::string, KindSpec>& kinds() const { return kinds_; }

 private:
  std::map<std::string, KindSpec> kinds_;
};

struct RegisterKind {
  explicit RegisterKind(KindSpec kind) { KindRegistry::instance().add(std::move(kind)); }
};

/// Runs a case: reads "kind", dispatches, and checks the result has no NaN/Inf.
nlohmann::json run_case(const nlohmann::json& case_json);

/// Throws std::logic_error naming the first non-finite number in `j`.
void ensure_finite(const nlohmann::json& j, const std::string& path = "result");

}  // namespace gearbench::app
