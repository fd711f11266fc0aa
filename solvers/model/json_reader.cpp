#include "json_reader.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <limits>
#include <set>
#include <vector>

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

std::string range_message(const std::string& key, double value, const Range& range, const std::string& unit) {
  return fmt::format("{} = {}: allowed range is {}{}", key, format_value(value), range.describe(),
                     unit.empty() ? "" : " " + unit);
}

namespace {

/// Why a value was not kept: the subtype of the binary value (which JSON text never yields)
/// that stands in its place.
enum class Unread : std::uint8_t { too_many_values = 1, too_deep = 2 };

/// "more than 1000000 values", as a message shows the placeholder in place of a value.
std::string unread_label(Unread why) {
  if (why == Unread::too_deep) return fmt::format("nested deeper than {} levels", max_json_depth);
  return fmt::format("more than {} values", max_json_values);
}

/// The error of a value not read.
std::string unread_text(Unread why) {
  if (why == Unread::too_deep) return unread_label(why);
  return unread_label(why) + " in one file, the most gearbench reads (a case holds a few hundred)";
}

template <class Json>
std::optional<Unread> unread_reason(const Json& value) {
  if (!value.is_binary()) return std::nullopt;
  return static_cast<Unread>(value.get_binary().subtype());
}

/// Builds the document from the parser's events (nlohmann's SAX interface), knowing the key
/// path it is at so that an error inside the text can name its key. Refuses a key given
/// twice in one object. Nesting deeper than max_json_depth or more than max_json_values
/// values are not read: the innermost value under a key that holds the excess is skipped to
/// its end and kept as an Unread placeholder, so that ObjectReader refuses an unknown key as
/// unknown, and names the cap for a known one; with no key to hold it, the cap is the error.
template <class Json>
class DocumentBuilder {
 public:
  using number_integer_t = typename Json::number_integer_t;
  using number_unsigned_t = typename Json::number_unsigned_t;
  using number_float_t = typename Json::number_float_t;
  using string_t = typename Json::string_t;
  using binary_t = typename Json::binary_t;

  bool null() { return value(nullptr); }
  bool boolean(bool v) { return value(v); }
  bool number_integer(number_integer_t v) { return value(v); }
  bool number_unsigned(number_unsigned_t v) { return value(v); }
  bool number_float(number_float_t v, const string_t& /*text*/) { return value(v); }
  bool string(string_t& v) { return value(std::move(v)); }
  bool binary(binary_t& v) { return value(std::move(v)); }  // never called: JSON text has no binary values
  bool start_object(std::size_t /*size*/) { return open(false); }
  bool start_array(std::size_t /*size*/) { return open(true); }
  bool end_object() { return close(); }
  bool end_array() { return close(); }

  bool key(string_t& k) {
    if (skipping()) return true;
    auto& frame = frames_.back();
    frame.key = k;
    if (!frame.keys.insert(k).second)
      throw InputError(fmt::format("{}: duplicate key; give each key once", where()));
    return true;
  }

  template <class Exception>
  bool parse_error(std::size_t /*position*/, const std::string& /*token*/, const Exception& e) {
    throw e;
  }

  Json& document() { return root_; }

  /// "gear_pair.teeth[1]"; "" at the top.
  [[nodiscard]] std::string where() const {
    std::string path;
    for (const auto& f : frames_) {
      if (f.array)
        path += fmt::format("[{}]", f.index);
      else if (!f.keys.empty())
        path += (path.empty() ? "" : ".") + shown_text(f.key);
    }
    return path;
  }

 private:
  struct Frame {
    Json* value;               ///< the container, in the document
    bool array;
    std::size_t values_before; ///< values_ when it opened
    std::string key = {};      ///< the key being read (objects)
    std::size_t index = 0;     ///< the element being read (arrays)
    std::set<std::string> keys = {};
  };
  static constexpr std::size_t none = std::numeric_limits<std::size_t>::max();

  [[nodiscard]] bool skipping() const { return skipped_ != none; }

  bool value(Json v) {
    if (skipping()) return true;
    if (++values_ > max_json_values) {
      skip(Unread::too_many_values);
      return true;
    }
    insert(std::move(v));
    element_done();
    return true;
  }

  bool open(bool array) {
    if (skipping()) {
      ++skipped_depth_;
      return true;
    }
    if (frames_.size() >= max_json_depth) {
      skip(Unread::too_deep);
      ++skipped_depth_;
      return true;
    }
    const std::size_t before = values_++;
    frames_.push_back({insert(array ? Json::array() : Json::object()), array, before});
    if (values_ > max_json_values) skip(Unread::too_many_values);
    return true;
  }

  bool close() {
    if (skipped_depth_ > 0) {
      --skipped_depth_;
      return true;
    }
    Json* const closed = frames_.back().value;
    const std::size_t values_before = frames_.back().values_before;
    frames_.pop_back();
    if (frames_.size() == skipped_) {
      *closed = Json::binary({}, static_cast<std::uint8_t>(why_));
      values_ = values_before + 1;
      skipped_ = none;
    }
    if (!skipping()) element_done();
    return true;
  }

  /// Adds `v` where the parser is; returns it in the document.
  Json* insert(Json v) {
    if (frames_.empty()) {
      root_ = std::move(v);
      return &root_;
    }
    auto& top = frames_.back();
    if (top.array) {
      top.value->push_back(std::move(v));
      return &top.value->back();
    }
    return &((*top.value)[top.key] = std::move(v));
  }

  /// Skips the innermost open container under a key to its end; the cap is the error
  /// when there is none.
  void skip(Unread why) {
    for (std::size_t i = frames_.size(); i-- > 1;)
      if (!frames_[i - 1].array) {
        skipped_ = i;
        why_ = why;
        return;
      }
    throw InputError(fmt::format("{}: {}", where(), unread_text(why)));
  }

  void element_done() {
    if (!frames_.empty() && frames_.back().array) ++frames_.back().index;
  }

  Json root_;
  std::vector<Frame> frames_;
  std::size_t values_ = 0;
  std::size_t skipped_ = none;    ///< index in frames_ of the container being skipped
  std::size_t skipped_depth_ = 0; ///< containers opened inside it (not in frames_)
  Unread why_ = Unread::too_many_values;
};

/// The part of a parser message after its "[json.exception...] ... at line 1, column 2: ".
std::string parser_reason(const std::string& what) {
  const auto colon = what.rfind(": ");
  return colon == std::string::npos ? what : what.substr(colon + 2);
}

template <class Json>
Json parse_tracked(const std::string& text, const std::string& source_name) {
  DocumentBuilder<Json> builder;
  try {
    Json::sax_parse(text, &builder);
    return std::move(builder.document());
  } catch (const typename Json::parse_error& e) {
    // Count lines up to the failing byte: nlohmann reports a byte offset (1-based).
    const std::size_t upto = std::min<std::size_t>(e.byte, text.size());
    const auto line = 1 + std::count(text.begin(), text.begin() + static_cast<long>(upto == 0 ? 0 : upto - 1), '\n');
    throw InputError(fmt::format("{}: malformed JSON at line {}: {}", shown_text(source_name), line,
                                 shown_text(parser_reason(e.what()))));
  } catch (const typename Json::out_of_range& e) {
    // The one range error of the parser: "number overflow parsing '1e999'".
    const std::string what = e.what();
    const auto open = what.find('\''), close = what.rfind('\'');
    const auto where = builder.where();
    throw InputError(fmt::format("{} = {}: beyond the range of a double (about ±1.8e308)",
                                 where.empty() ? shown_text(source_name) : where,
                                 shown_text(what.substr(open + 1, close - open - 1))));
  }
}

}  // namespace

json parse_json(const std::string& text, const std::string& source_name) {
  return parse_tracked<json>(text, source_name);
}

nlohmann::ordered_json parse_ordered_json(const std::string& text, const std::string& source_name) {
  return parse_tracked<nlohmann::ordered_json>(text, source_name);
}

std::string read_text_file(const std::string& path, const std::string& what) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw InputError(fmt::format("{}: is a directory, not a {}", shown_text(path), what));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(fmt::format("{}: cannot open the {}", shown_text(path), what));
  // Read in chunks up to the cap: /dev/zero or a runaway file must not fill the memory.
  std::string text;
  std::array<char, 1 << 16> chunk{};
  while (in.read(chunk.data(), chunk.size()) || in.gcount() > 0) {
    text.append(chunk.data(), static_cast<std::size_t>(in.gcount()));
    if (text.size() > max_file_bytes)
      throw InputError(fmt::format("{}: larger than {} MiB, the most gearbench reads in a {}",
                                   shown_text(path), max_file_bytes >> 20, what));
  }
  if (in.bad()) throw InputError(fmt::format("{}: cannot read the {}", shown_text(path), what));
  return text;
}

json read_json_file(const std::string& path) { return parse_json(read_text_file(path), path); }

std::optional<std::string> unread(const json& value) {
  const auto why = unread_reason(value);
  return why ? std::optional(unread_text(*why)) : std::nullopt;
}

std::optional<std::string> unread(const nlohmann::ordered_json& value) {
  const auto why = unread_reason(value);
  return why ? std::optional(unread_text(*why)) : std::nullopt;
}

namespace {
/// At most `n` bytes of `s`, not cutting a UTF-8 sequence, with "..." when cut.
std::string cut(const std::string& s, std::size_t n) {
  if (s.size() <= n) return s;
  std::size_t end = n - 3;
  while (end > 0 && (static_cast<unsigned char>(s[end]) & 0xC0) == 0x80) --end;
  return s.substr(0, end) + "...";
}

constexpr std::size_t shown_length = 40;

/// Compact JSON of `v`, stopping once `out` is longer than shown_length.
void render(const json& v, std::string& out) {
  if (v.is_string()) {
    out += '"' + shown_text(v.get<std::string>()) + '"';
  } else if (const auto why = unread_reason(v)) {
    out += fmt::format("({})", unread_label(*why));
  } else if (v.is_array() || v.is_object()) {
    out += v.is_array() ? '[' : '{';
    bool first = true;
    for (const auto& item : v.items()) {
      if (out.size() > shown_length) break;
      if (!first) out += ',';
      first = false;
      if (v.is_object()) out += '"' + shown_text(item.key()) + "\":";
      render(item.value(), out);
    }
    out += v.is_array() ? ']' : '}';
  } else {
    out += v.dump();
  }
}
}  // namespace

std::string shown_text(const std::string& text) {
  constexpr std::size_t longest = 200;  // a file path fits; a megabyte key does not
  std::string out;
  for (const char c : text) {
    if (out.size() > longest) break;
    const auto u = static_cast<unsigned char>(c);
    if (c == '\n') out += "\\n";
    else if (c == '\r') out += "\\r";
    else if (c == '\t') out += "\\t";
    else if (u < 0x20 || u == 0x7f) out += fmt::format("\\u{:04x}", u);
    else out += c;
  }
  return cut(out, longest);
}

std::string shown_value(const json& value) {
  std::string out;
  render(value, out);
  return cut(out, shown_length);
}

namespace {
std::string type_name(const json& v) {
  if (v.is_number_integer()) return "an integer";
  if (v.is_number()) return "a number";
  if (v.is_string()) return "a string";
  if (v.is_boolean()) return "a boolean";
  if (v.is_array()) return "an array";
  if (v.is_object()) return "an object";
  if (v.is_binary()) return "a value not read";
  return "null";
}
}  // namespace

ObjectReader::ObjectReader(const json& object, std::string path)
    : object_(object), path_(std::move(path)) {
  if (!object_.is_object())
    throw InputError(fmt::format("{} = {}: must be an object, got {}",
                                 path_.empty() ? "case" : path_, shown_value(object_),
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
  if (const auto why = unread(*it)) throw InputError(fmt::format("{}: {}", key_path(key), *why));
  return *it;
}

double ObjectReader::checked_number(const json& value, const std::string& full_key,
                                    const Range& range, const std::string& unit) const {
  if (!value.is_number())
    throw InputError(fmt::format("{} = {}: must be a number, got {}", full_key, shown_value(value),
                                 type_name(value)));
  const double v = value.get<double>();
  if (!std::isfinite(v))
    throw InputError(fmt::format("{} = {}: must be finite", full_key, format_value(v)));
  if (!range.contains(v)) throw InputError(range_message(full_key, v, range, unit));
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

int ObjectReader::checked_integer(const json& value, const std::string& full_key, int lo, int hi) const {
  if (!value.is_number_integer())
    throw InputError(fmt::format("{} = {}: must be an integer, got {}", full_key, shown_value(value),
                                 type_name(value)));
  // Above the range of long long (up to 2^64 - 1) nlohmann holds an unsigned: compare it as
  // one, so that 18446744073709551615 is never read as -1.
  const bool fits = !value.is_number_unsigned() ||
                    value.get<std::uint64_t>() <= static_cast<std::uint64_t>(std::numeric_limits<long long>::max());
  const auto v = fits ? value.get<long long>() : static_cast<long long>(hi) + 1;
  if (v < lo || v > hi)
    throw InputError(fmt::format("{} = {}: allowed range is [{}, {}]", full_key, value.dump(), lo, hi));
  return static_cast<int>(v);
}

int ObjectReader::integer(const std::string& key, int lo, int hi) {
  return checked_integer(require(key), key_path(key), lo, hi);
}

std::optional<int> ObjectReader::optional_integer(const std::string& key, int lo, int hi) {
  if (!has(key)) return std::nullopt;
  return integer(key, lo, hi);
}

bool ObjectReader::boolean(const std::string& key) {
  const json& value = require(key);
  if (!value.is_boolean())
    throw InputError(fmt::format("{} = {}: must be true or false", key_path(key), shown_value(value)));
  return value.get<bool>();
}

std::string ObjectReader::string(const std::string& key,
                                 const std::vector<std::string>& allowed) {
  const json& value = require(key);
  if (!value.is_string())
    throw InputError(fmt::format("{} = {}: must be a string, got {}", key_path(key),
                                 shown_value(value), type_name(value)));
  auto s = value.get<std::string>();
  if (!allowed.empty() && std::find(allowed.begin(), allowed.end(), s) == allowed.end())
    throw InputError(fmt::format("{} = {}: allowed values are {}", key_path(key), shown_value(value),
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
                                 full_key, shown_value(value)));
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
  for (std::size_t i = 0; i < 2; ++i)
    out[i] = checked_integer(value[i], fmt::format("{}[{}]", key_path(key), i), lo, hi);
  return out;
}

std::vector<double> ObjectReader::number_list(const std::string& key, const Range& range, const std::string& unit) {
  const json& value = require(key);
  if (!value.is_array())
    throw InputError(fmt::format("{} = {}: must be a list of numbers, got {}", key_path(key), shown_value(value),
                                 type_name(value)));
  std::vector<double> out;
  for (std::size_t i = 0; i < value.size(); ++i)
    out.push_back(checked_number(value[i], fmt::format("{}[{}]", key_path(key), i), range, unit));
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
      shown_value(value)));
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
    throw InputError(fmt::format("{}: unknown key{}", key_path(shown_text(item.key())),
                                 close ? fmt::format(" (did you mean '{}'?)", best)
                                       : fmt::format(" (known keys: {})", fmt::join(known_, ", "))));
  }
}

}  // namespace gearbench::model
