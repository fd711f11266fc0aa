#pragma once
// Validating reader over a JSON object: every access names the key by its full path
// ("gear_pair.teeth[1]"), checks type and range, and remembers which keys it was asked
// about, so that finish() can reject unknown keys with the nearest known one suggested.
#include <array>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace gearbench::model {

/// Allowed interval of a number; open or closed at either end.
struct Range {
  double lo;
  double hi;
  bool lo_open = false;
  bool hi_open = false;

  static Range positive(double hi = 1e300) { return {0.0, hi, true, false}; }
  static Range closed(double lo, double hi) { return {lo, hi, false, false}; }
  [[nodiscard]] bool contains(double v) const;
  [[nodiscard]] std::string describe() const;
};

/// Formats a number the way an error message shows it (shortest round-trip form).
std::string format_value(double v);

/// "key = value: allowed range is R unit": the one wording of a range error, for the reader
/// and for every Options table's validate() (option_table.h).
std::string range_message(const std::string& key, double value, const Range& range, const std::string& unit);

/// Limits on what gearbench reads: deeper nesting or a larger file is refused as bad input
/// before it can exhaust the stack or the memory.
inline constexpr std::size_t max_json_depth = 64;
inline constexpr std::size_t max_file_bytes = std::size_t{64} << 20;
/// Values (numbers, strings, arrays, objects…) in one file: a case holds a few hundred, a
/// sweep a few thousand. The cap stops a long array, under a key the kinds would refuse, from
/// being read into memory before the refusal (issue 20: 7.6 GB for 1e8 elements; at most a
/// few tens of MB now).
inline constexpr std::size_t max_json_values = 1'000'000;

/// Parses JSON text; malformed input becomes an InputError that gives the line number, and
/// a number beyond double range or a duplicate key one that names the key path.
/// Nesting deeper than max_json_depth or more than max_json_values values is not read: the
/// innermost value under a key that holds the excess is skipped to its end and left in the
/// document as a placeholder (see unread), so that the key is refused as unknown when it is
/// (ObjectReader::finish), and by the cap when a reader asks for it. With no key to hold the
/// excess (a long or deep array at the top), the cap is the InputError.
nlohmann::json parse_json(const std::string& text, const std::string& source_name);
/// The same, keeping the keys in the order written.
nlohmann::ordered_json parse_ordered_json(const std::string& text, const std::string& source_name);

/// The content of a regular file (or a device/pipe) of at most max_file_bytes; InputError
/// if it is missing, a directory or too large. `what` names the file in messages.
std::string read_text_file(const std::string& path, const std::string& what = "case file");

/// Reads a file and parses it (InputError if missing, too large or malformed).
nlohmann::json read_json_file(const std::string& path);

/// For the placeholder of a value that parse_json did not read, why ("nested deeper than 64
/// levels", "more than 1000000 values in one file, …"); nullopt for any other value.
std::optional<std::string> unread(const nlohmann::json& value);
std::optional<std::string> unread(const nlohmann::ordered_json& value);

/// Text from the input as a message shows it: control characters escaped (a NUL or a line
/// break cannot cut or forge the one-line message), at most a few dozen characters.
std::string shown_text(const std::string& text);
/// A JSON value as a message shows it: compact, escaped, cut short, never dumped whole.
std::string shown_value(const nlohmann::json& value);

class ObjectReader {
 public:
  /// `path` is the key path of this object ("" for the root). Keeps a reference to `object`,
  /// which must outlive the reader.
  ObjectReader(const nlohmann::json& object, std::string path);

  [[nodiscard]] bool has(const std::string& key);

  double number(const std::string& key, const Range& range, const std::string& unit = "");
  std::optional<double> optional_number(const std::string& key, const Range& range,
                                        const std::string& unit = "");
  int integer(const std::string& key, int lo, int hi);
  std::optional<int> optional_integer(const std::string& key, int lo, int hi);
  bool boolean(const std::string& key);
  std::string string(const std::string& key, const std::vector<std::string>& allowed = {});
  std::optional<std::string> optional_string(const std::string& key,
                                             const std::vector<std::string>& allowed = {});

  /// A two-element array [gear 1, gear 2] of numbers / integers.
  std::array<double, 2> number_pair(const std::string& key, const Range& range,
                                    const std::string& unit = "");
  std::optional<std::array<double, 2>> optional_number_pair(const std::string& key,
                                                            const Range& range,
                                                            const std::string& unit = "");
  std::array<int, 2> integer_pair(const std::string& key, int lo, int hi);
  /// An array of numbers of any length (a sweep's values).
  std::vector<double> number_list(const std::string& key, const Range& range, const std::string& unit = "");

  /// A nested object, read by its own reader.
  ObjectReader object(const std::string& key);
  /// A nested object or an array of objects: `object_or_pair` accepts one object
  /// (meaning the same for both gears) or an array of exactly two.
  struct ObjectPair {
    std::array<nlohmann::json, 2> objects;
    std::array<std::string, 2> paths;  ///< key paths for error messages
  };
  ObjectPair object_or_pair(const std::string& key);

  /// Declares a key as known without reading it (read elsewhere).
  void accept(const std::string& key);

  /// Throws InputError for the first key that was never asked about.
  void finish() const;

  [[nodiscard]] std::string key_path(const std::string& key) const;
  [[nodiscard]] const std::string& path() const { return path_; }

 private:
  const nlohmann::json& require(const std::string& key);
  double checked_number(const nlohmann::json& value, const std::string& full_key,
                        const Range& range, const std::string& unit) const;
  int checked_integer(const nlohmann::json& value, const std::string& full_key, int lo, int hi) const;

  const nlohmann::json& object_;
  std::string path_;
  std::set<std::string> known_;
};

/// Levenshtein distance, used to suggest the nearest known key.
std::size_t edit_distance(const std::string& a, const std::string& b);

}  // namespace gearbench::model
