#include "json_reader.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <fstream>
#include <sstream>

#include "errors.h"

namespace gearbench::model {

using nlohmann::json;

bool Range::contains(double v) const {
  const bool above = lo_open ? v > lo : v >= lo;
  const bool below = hi_open ? v < hi : v <= hi;
  return above && below;
}

std::string Range::describe() const {
  if (hi >= 1e299) return fmt::format("{} {}", lo_open ? ">" : ">=", format_value(lo));
  return fmt::format("{}{}, {}{}", lo_open ? "(" : "[", format_value(lo), format_value(hi),
                     hi_open ? ")" : "]");
}

std::string format_value(double v) { return fmt::format("{}", v); }

json parse_json(const std::string& text, const std::string& source_name) {
  try {
    return json::parse(text);
  } catch (const json::parse_error& e) {
    // Count lines up to the failing byte: nlohmann reports a byte offset (1-based).
    const std::size_t upto = std::min<std::size_t>(e.byte, text.size());
    const auto line = 1 + std::count(text.begin(), text.begin() + static_cast<long>(upto == 0 ? 0 : upto - 1), '\n');
    std::string what = e.what();
    const auto colon = what.rfind(": ");
    throw InputError(fmt::format("{}: malformed JSON at line {}: {}", source_name, line,
                                 colon == std::string::npos ? what : what.substr(colon + 2)));
  }
}

json read_json_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(fmt::format("{}: cannot open the case file", path));
  std::stringstream buffer;
  buffer << in.rdbuf();
  return parse_json(buffer.str(), path);
}

namespace {
std::string type_name(const json& v) {
  if (v.is_number_integer()) return "an integer";
  if (v.is_number()) return "a number";
  if (v.is_string()) return "a string";
  if (v.is_boolean()) return "a boolean";
  if (v.is_array()) return "an array";
  if (v.is_object()) return "an object";
  return "null";
}
std::string shown(const json& v) {
  std::string s = v.dump();
  return s.size() > 40 ? s.substr(0, 37) + "..." : s;
}
}  // namespace

ObjectReader::ObjectReader(const json& object, std::string path)
    : object_(object), path_(std::move(path)) {
  if (!object_.is_object())
    throw InputError(fmt::format("{} = {}: must be an object, got {}",
                                 path_.empty() ? "case" : path_, shown(object_),
                                 type_name(object_)));
}

std::string ObjectReader::key_path(const std::string& key) const {
  return path_.empty() ? key : path_ + "." + key;
}

bool ObjectReader::has(const std::string& key) {
  known_.insert(key);
  return object_.contains(key);
}

const json& ObjectReader::require(const std::string& key) {
  known_.insert(key);
  const auto it = object_.find(key);
  if (it == object_.end())
    throw InputError(fmt::format("{}: missing required key", key_path(key)));
  return *it;
}

double ObjectReader::checked_number(const json& value, const std::string& full_key,
                                    const Range& range, const std::string& unit) const {
  if (!value.is_number())
    throw InputError(fmt::format("{} = {}: must be a number, got {}", full_key, shown(value),
                                 type_name(value)));
  const double v = value.get<double>();
  if (!std::isfinite(v))
    throw InputError(fmt::format("{} = {}: must be finite", full_key, format_value(v)));
  if (!range.contains(v))
    throw InputError(fmt::format("{} = {}: allowed range is {}{}", full_key, format_value(v),
                                 range.describe(), unit.empty() ? "" : " " + unit));
  return v;
}

double ObjectReader::number(const std::string& key, const Range& range,
                            const std::string& unit) {
  return checked_number(require(key), key_path(key), range, unit);
}

std::optional<double> ObjectReader::optional_number(const std::string& key,
                                                    const Range& range,
                                                    const std::string& unit) {
  if (!has(key)) return std::nullopt;
  return number(key, range, unit);
}

int ObjectReader::integer(const std::string& key, int lo, int hi) {
  const json& value = require(key);
  if (!value.is_number_integer())
    throw InputError(fmt::format("{} = {}: must be an integer, got {}", key_path(key),
                                 shown(value), type_name(value)));
  const auto v = value.get<long long>();
  if (v < lo || v > hi)
    throw InputError(
        fmt::format("{} = {}: allowed range is [{}, {}]", key_path(key), v, lo, hi));
  return static_cast<int>(v);
}

std::optional<int> ObjectReader::optional_integer(const std::string& key, int lo, int hi) {
  if (!has(key)) return std::nullopt;
  return integer(key, lo, hi);
}

std::string ObjectReader::string(const std::string& key,
                                 const std::vector<std::string>& allowed) {
  const json& value = require(key);
  if (!value.is_string())
    throw InputError(fmt::format("{} = {}: must be a string, got {}", key_path(key),
                                 shown(value), type_name(value)));
  auto s = value.get<std::string>();
  if (!allowed.empty() && std::find(allowed.begin(), allowed.end(), s) == allowed.end())
    throw InputError(fmt::format("{} = \"{}\": allowed values are {}", key_path(key), s,
                                 fmt::join(allowed, ", ")));
  return s;
}

std::optional<std::string> ObjectReader::optional_string(
    const std::string& key, const std::vector<std::string>& allowed) {
  if (!has(key)) return std::nullopt;
  return string(key, allowed);
}

namespace {
const json& pair_value(const json& value, const std::string& full_key) {
  if (!value.is_array() || value.size() != 2)
    throw InputError(fmt::format("{} = {}: must be an array of two values [gear 1, gear 2]",
                                 full_key, shown(value)));
  return value;
}
}  // namespace

std::array<double, 2> ObjectReader::number_pair(const std::string& key, const Range& range,
                                                const std::string& unit) {
  const json& value = pair_value(require(key), key_path(key));
  std::array<double, 2> out{};
  for (std::size_t i = 0; i < 2; ++i)
    out[i] = checked_number(value[i], fmt::format("{}[{}]", key_path(key), i), range, unit);
  return out;
}

std::optional<std::array<double, 2>> ObjectReader::optional_number_pair(
    const std::string& key, const Range& range, const std::string& unit) {
  if (!has(key)) return std::nullopt;
  return number_pair(key, range, unit);
}

std::array<int, 2> ObjectReader::integer_pair(const std::string& key, int lo, int hi) {
  const json& value = pair_value(require(key), key_path(key));
  std::array<int, 2> out{};
  for (std::size_t i = 0; i < 2; ++i) {
    const auto item_key = fmt::format("{}[{}]", key_path(key), i);
    if (!value[i].is_number_integer())
      throw InputError(fmt::format("{} = {}: must be an integer, got {}", item_key,
                                   shown(value[i]), type_name(value[i])));
    const auto v = value[i].get<long long>();
    if (v < lo || v > hi)
      throw InputError(fmt::format("{} = {}: allowed range is [{}, {}]", item_key, v, lo, hi));
    out[i] = static_cast<int>(v);
  }
  return out;
}

ObjectReader ObjectReader::object(const std::string& key) {
  return ObjectReader(require(key), key_path(key));
}

ObjectReader::ObjectPair ObjectReader::object_or_pair(const std::string& key) {
  const json& value = require(key);
  const std::string base = key_path(key);
  if (value.is_object()) return {{value, value}, {base, base}};
  if (value.is_array() && value.size() == 2 && value[0].is_object() && value[1].is_object())
    return {{value[0], value[1]}, {base + "[0]", base + "[1]"}};
  throw InputError(fmt::format(
      "{} = {}: must be one object (both gears) or an array of two objects", key_path(key),
      shown(value)));
}

void ObjectReader::accept(const std::string& key) { known_.insert(key); }

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
      diagonal = above;
    }
  }
  return row[b.size()];
}

void ObjectReader::finish() const {
  for (const auto& item : object_.items()) {
    if (known_.count(item.key())) continue;
    std::string best;
    std::size_t best_distance = std::string::npos;
    for (const auto& k : known_) {
      const auto d = edit_distance(item.key(), k);
      if (d < best_distance) {
        best_distance = d;
        best = k;
      }
    }
    const bool close = !best.empty() && best_distance <= std::max<std::size_t>(3, best.size() / 3);
    throw InputError(fmt::format("{}: unknown key{}", key_path(item.key()),
                                 close ? fmt::format(" (did you mean '{}'?)", best)
                                       : fmt::format(" (known keys: {})", fmt::join(known_, ", "))));
  }
}

}  // namespace gearbench::model
