#include "fuzz_entry.h"

#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "kind_registry.h"
#include "model/case_reader.h"
#include "model/errors.h"
#include "model/json_reader.h"

namespace gearbench::fuzz {
namespace {

/// The input as JSON through the parser `gearbench run` uses (nesting, number range and
/// duplicate keys bounded there); what it refuses is bad input, not a finding.
nlohmann::json parse(const std::uint8_t* data, std::size_t size) {
  try {
    return model::parse_json(std::string(reinterpret_cast<const char*>(data), size), "fuzz input");
  } catch (const InputError&) {
    return nlohmann::json(nlohmann::json::value_t::discarded);
  }
}

/// The message of a refused input is one printable line: a control character taken from
/// the input could cut it or forge a second `error:` line. Anything else is a finding.
void check_one_line(const std::exception& e) {
  for (const char c : std::string(e.what()))
    if (static_cast<unsigned char>(c) < 0x20)
      throw std::logic_error(std::string("a control character in the message: ") + e.what());
}

/// Legitimate work that a per-input timeout would take for a hang: the FE reference with
/// elements of degree 3 or more takes a minute and more under ASan (a degree-4 tooth stopped
/// run_fuzzer at its 60 s limit, 2026-11-25). Its input handling is the same code at any degree.
bool too_slow_to_fuzz(const nlohmann::json& j) {
  if (!j.is_object()) return false;
  const auto kind = j.find("kind");
  if (kind == j.end() || !kind->is_string() || kind->get<std::string>() != "fe_stiffness") return false;
  const auto fe = j.find("fe");
  if (fe == j.end() || !fe->is_object()) return false;
  const auto degree = fe->find("degree");
  return degree != fe->end() && degree->is_number() && degree->get<double>() > 2.0;
}

}  // namespace

void read_case_bytes(const std::uint8_t* data, std::size_t size) {
  const auto j = parse(data, size);
  if (j.is_discarded() || !j.is_object()) return;
  try {
    model::ObjectReader root(j, "");
    (void)model::read_gear_case(root);
  } catch (const InputError& e) {
    check_one_line(e);
  }
}

void run_case_bytes(const std::uint8_t* data, std::size_t size) {
  const auto j = parse(data, size);
  if (j.is_discarded() || too_slow_to_fuzz(j)) return;
  try {
    (void)app::run_case(j);
  } catch (const InputError& e) {
    check_one_line(e);
  } catch (const ConvergenceError& e) {
    check_one_line(e);
  }
}

}  // namespace gearbench::fuzz
