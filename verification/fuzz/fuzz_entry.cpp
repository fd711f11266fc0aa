#include "fuzz_entry.h"

#include <nlohmann/json.hpp>

#include "kind_registry.h"
#include "model/case_reader.h"
#include "model/errors.h"

namespace gearbench::fuzz {
namespace {

/// The input as JSON; malformed text is the parser's business, not a finding.
nlohmann::json parse(const std::uint8_t* data, std::size_t size) {
  return nlohmann::json::parse(data, data + size, nullptr, /*allow_exceptions=*/false);
}

}  // namespace

void read_case_bytes(const std::uint8_t* data, std::size_t size) {
  const auto j = parse(data, size);
  if (j.is_discarded() || !j.is_object()) return;
  try {
    model::ObjectReader root(j, "");
    (void)model::read_gear_case(root);
  } catch (const InputError&) {
  }
}

void run_case_bytes(const std::uint8_t* data, std::size_t size) {
  const auto j = parse(data, size);
  if (j.is_discarded()) return;
  try {
    (void)app::run_case(j);
  } catch (const InputError&) {
  } catch (const ConvergenceError&) {
  }
}

}  // namespace gearbench::fuzz
