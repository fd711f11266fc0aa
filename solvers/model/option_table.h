#pragma once
// One table per solver's Options (issue 21): each case key is declared once, with the member
// it sets, its unit, its allowed range and its description. The case reader, validate(), the
// record of the options used and `gearbench schema` are all made from the table, so a key's
// range or unit cannot be written twice and drift. The default is not written in the table:
// it is the member's initialiser, read from a default-constructed Options, so the schema and
// the code cannot disagree on it either.
#include <array>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "json_reader.h"

namespace gearbench::model {

/// How a key is shown and converted; SI value = case value × scale / divisor + offset (integers:
/// + offset).
struct KeySpec {
  std::string description;
  std::string unit;            ///< as the key's name spells it ("mm", "Pa"); "" for none
  double scale = 1.0;
  double offset = 0.0;
  bool required = false;
  /// A default that depends on other keys, in words; the schema then gives none.
  std::string default_text = {};
  /// The member's value (SI) that means "not given, the solver chooses" (EHL grid.nodes 0:
  /// sized by the error target): valid beside the range, left out of the record, and no
  /// schema default where the holder leaves it so.
  std::optional<double> unset = {};
  /// A unit given by its reciprocal, converted by division as the readers did (1/GPa: / 1e9).
  double divisor = 1.0;
};

enum class KeyType { number, integer, boolean, choice, text, section, external };

/// The part of a key that documentation and the schema see.
/// One value, [gear 1, gear 2], or a list of any length.
enum class Shape { scalar, pair, list };

struct KeyInfo {
  std::string key;
  KeyType type = KeyType::number;
  Shape shape = Shape::scalar;
  std::optional<Range> range;      ///< numbers and integers (case units)
  std::vector<std::string> choices;
  KeySpec spec;
  nlohmann::json schema;           ///< section / external: the value's own schema
};

/// The JSON Schema (draft 2020-12) property of one key; `default_value` null for none.
nlohmann::json key_schema(const KeyInfo& info, const nlohmann::json& default_value);

/// Merges object schemas (their properties and required keys) into one object schema that
/// refuses any other key, as ObjectReader::finish() does.
nlohmann::json merge_object_schemas(const std::vector<nlohmann::json>& parts, const std::string& description = "");

namespace detail {
template <class T> struct is_optional : std::false_type {};
template <class T> struct is_optional<std::optional<T>> : std::true_type {};
template <class T> struct is_pair : std::false_type {};
template <class T> struct is_pair<std::array<T, 2>> : std::true_type {};
template <class T> struct is_list : std::false_type {};
template <class T> struct is_list<std::vector<T>> : std::true_type {};
template <class T> T strip_optional(const std::optional<T>&);
template <class T> T strip_optional(const T&);
}  // namespace detail

template <class O>
class OptionTable {
 public:
  /// An accessor returns a reference to the member: a member pointer or a lambda taking `auto&`.
  template <class Access>
  OptionTable& number(std::string key, Access access, Range range, KeySpec spec) {
    using M = member_t<Access>;
    using V = decltype(detail::strip_optional(std::declval<M>()));
    constexpr bool pair = detail::is_pair<V>::value;
    constexpr bool list = detail::is_list<V>::value;
    KeyInfo info{std::move(key), KeyType::number, pair ? Shape::pair : list ? Shape::list : Shape::scalar, range, {},
                 std::move(spec), {}};
    const double scale = info.spec.scale, offset = info.spec.offset, divisor = info.spec.divisor;
    const auto to_case = [scale, offset, divisor](double si) { return (si - offset) * divisor / scale; };
    const auto to_si = [scale, offset, divisor](double v) { return v * scale / divisor + offset; };
    Entry e{info};
    e.get = [access, to_case, unset = info.spec.unset](const O& o) -> nlohmann::json {
      const M& m = std::invoke(access, o);
      if constexpr (detail::is_optional<M>::value) {
        if (!m) return nullptr;
        return value_json(*m, to_case);
      } else {
        if constexpr (std::is_same_v<M, double>)
          if (unset && m == *unset) return nullptr;
        return value_json(m, to_case);
      }
    };
    e.read = [access, to_si, info](ObjectReader& r, O& o) {
      if constexpr (pair) {
        const auto v = r.number_pair(info.key, *info.range, info.spec.unit);
        std::invoke(access, o) = V{to_si(v[0]), to_si(v[1])};
      } else if constexpr (list) {
        auto v = r.number_list(info.key, *info.range, info.spec.unit);
        for (auto& x : v) x = to_si(x);
        std::invoke(access, o) = std::move(v);
      } else {
        std::invoke(access, o) = to_si(r.number(info.key, *info.range, info.spec.unit));
      }
    };
    e.validate = [access, info, to_si](const O& o, const std::string& prefix) {
      const M& m = std::invoke(access, o);
      if constexpr (detail::is_optional<M>::value) {
        if (m) check_range(*m, prefix + info.key, info, to_si);
      } else {
        if constexpr (std::is_same_v<M, double>)
          if (info.spec.unset && m == *info.spec.unset) return;
        check_range(m, prefix + info.key, info, to_si);
      }
    };
    entries_.push_back(std::move(e));
    return *this;
  }

  template <class Access>
  OptionTable& integer(std::string key, Access access, int lo, int hi, KeySpec spec) {
    using M = member_t<Access>;
    static_assert(std::is_same_v<M, int> || std::is_same_v<M, std::array<int, 2>>);
    constexpr bool pair = detail::is_pair<M>::value;
    KeyInfo info{std::move(key), KeyType::integer, pair ? Shape::pair : Shape::scalar, Range::closed(lo, hi), {},
                 std::move(spec), {}};
    const int offset = static_cast<int>(info.spec.offset);
    Entry e{info};
    e.get = [access, offset, unset = info.spec.unset](const O& o) -> nlohmann::json {
      const M& m = std::invoke(access, o);
      if constexpr (pair) return nlohmann::json::array({m[0] - offset, m[1] - offset});
      else if (unset && m == *unset) return nullptr;
      else return m - offset;
    };
    e.read = [access, offset, lo, hi, key = info.key](ObjectReader& r, O& o) {
      if constexpr (pair) {
        const auto v = r.integer_pair(key, lo, hi);
        std::invoke(access, o) = M{v[0] + offset, v[1] + offset};
      } else {
        std::invoke(access, o) = r.integer(key, lo, hi) + offset;
      }
    };
    e.validate = [access, info, offset](const O& o, const std::string& prefix) {
      const M& m = std::invoke(access, o);
      const auto to_si = [offset](double v) { return v + offset; };
      if constexpr (pair) check_range(std::array<double, 2>{double(m[0]), double(m[1])}, prefix + info.key, info, to_si);
      else if (!(info.spec.unset && m == *info.spec.unset)) check_range(double(m), prefix + info.key, info, to_si);
    };
    entries_.push_back(std::move(e));
    return *this;
  }

  /// A string key with a fixed set of values, each naming a value of the member (an enum,
  /// a bool, or the string itself). `api_only` are values the C++ API may set and the record
  /// names, but a case may not (methods kept for a study only): neither read nor in the schema.
  template <class Access, class V>
  OptionTable& choice(std::string key, Access access, std::vector<std::pair<std::string, V>> names, KeySpec spec,
                      std::vector<std::pair<std::string, V>> api_only = {}) {
    KeyInfo info{std::move(key), KeyType::choice, Shape::scalar, std::nullopt, {}, std::move(spec), {}};
    for (const auto& n : names) info.choices.push_back(n.first);
    Entry e{info};
    e.get = [access, all = concat(names, api_only)](const O& o) -> nlohmann::json {
      for (const auto& [name, value] : all)
        if (std::invoke(access, o) == value) return name;
      return nullptr;
    };
    e.read = [access, names, info](ObjectReader& r, O& o) {
      const auto s = r.string(info.key, info.choices);
      for (const auto& [name, value] : names)
        if (name == s) std::invoke(access, o) = value;
    };
    e.validate = [get = e.get, info](const O& o, const std::string& prefix) {
      if (get(o).is_null()) throw_not_a_choice(prefix + info.key, info);
    };
    entries_.push_back(std::move(e));
    return *this;
  }
  template <class Access>
  OptionTable& choice(std::string key, Access access, const std::vector<std::string>& names, KeySpec spec) {
    std::vector<std::pair<std::string, std::string>> same;
    for (const auto& n : names) same.emplace_back(n, n);
    return choice(std::move(key), access, std::move(same), std::move(spec));
  }

  template <class Access>
  OptionTable& boolean(std::string key, Access access, KeySpec spec) {
    KeyInfo info{std::move(key), KeyType::boolean, Shape::scalar, std::nullopt, {}, std::move(spec), {}};
    Entry e{info};
    e.get = [access](const O& o) -> nlohmann::json { return bool(std::invoke(access, o)); };
    e.read = [access, key = info.key](ObjectReader& r, O& o) { std::invoke(access, o) = r.boolean(key); };
    entries_.push_back(std::move(e));
    return *this;
  }

  /// Free text (a name shown in the output).
  template <class Access>
  OptionTable& text(std::string key, Access access, KeySpec spec) {
    KeyInfo info{std::move(key), KeyType::text, Shape::scalar, std::nullopt, {}, std::move(spec), {}};
    Entry e{info};
    e.get = [access](const O& o) -> nlohmann::json { return std::invoke(access, o); };
    e.read = [access, key = info.key](ObjectReader& r, O& o) { std::invoke(access, o) = r.string(key); };
    entries_.push_back(std::move(e));
    return *this;
  }

  /// A nested object read by its own table into the member `access` returns (a struct, or
  /// an optional one that the section's presence sets).
  /// `schema_of` widens the section's schema where the section has another form (an oil
  /// named from the catalogue, resolved before the table reads it).
  template <class Access, class S>
  OptionTable& section(std::string key, Access access, const OptionTable<S>& table, KeySpec spec,
                       const std::function<nlohmann::json(nlohmann::json)>& schema_of = {}) {
    using M = member_t<Access>;
    KeyInfo info{std::move(key), KeyType::section, Shape::scalar, std::nullopt, {}, std::move(spec), {}};
    info.schema = table.schema(info.spec.description, holder_default<S>(access));
    if (schema_of) info.schema = schema_of(std::move(info.schema));
    Entry e{info};
    e.get = [access, &table](const O& o) -> nlohmann::json {
      const M& m = std::invoke(access, o);
      if constexpr (detail::is_optional<M>::value) return m ? table.to_json(*m) : nlohmann::json(nullptr);
      else return table.to_json(m);
    };
    e.read = [access, &table, key = info.key](ObjectReader& r, O& o) {
      auto sub = r.object(key);
      M& m = std::invoke(access, o);
      if constexpr (detail::is_optional<M>::value) table.read(sub, m.emplace());
      else table.read(sub, m);
      sub.finish();
    };
    e.validate = [access, &table, key = info.key](const O& o, const std::string& prefix) {
      const M& m = std::invoke(access, o);
      if constexpr (detail::is_optional<M>::value) {
        if (m) table.validate(*m, prefix + key + ".");
      } else {
        table.validate(m, prefix + key + ".");
      }
    };
    entries_.push_back(std::move(e));
    return *this;
  }

  /// The keys of another struct's table at this level, in the member `access` returns (the
  /// part of a case section that one solver input holds), with its reading rules.
  template <class Access, class S>
  OptionTable& include(Access access, const OptionTable<S>& table) {
    for (const auto& se : table.entries_) {
      Entry e{se.info};
      if (se.get) e.get = [access, g = se.get](const O& o) { return g(std::invoke(access, o)); };
      if (se.read) e.read = [access, r = se.read](ObjectReader& rd, O& o) { r(rd, std::invoke(access, o)); };
      if (se.validate)
        e.validate = [access, v = se.validate](const O& o, const std::string& p) { v(std::invoke(access, o), p); };
      entries_.push_back(std::move(e));
    }
    for (const auto& f : table.after_read_)
      after_read_.push_back([access, f](ObjectReader& r, O& o) { f(r, std::invoke(access, o)); });
    for (const auto& f : table.rules_)
      rules_.push_back([access, f](const O& o, const std::string& p) { f(std::invoke(access, o), p); });
    return *this;
  }

  /// A key that after_read() reads by hand (a section with a reader of its own); `schema`
  /// is its value's schema, or an object schema that says what it does not check.
  OptionTable& external(std::string key, nlohmann::json schema, KeySpec spec) {
    KeyInfo info{std::move(key), KeyType::external, Shape::scalar, std::nullopt, {}, std::move(spec), std::move(schema)};
    entries_.push_back(Entry{info});
    return *this;
  }

  /// Reading that the keys alone cannot say (one key derived from others); runs after the
  /// declared keys are read, before the caller's finish().
  OptionTable& after_read(std::function<void(ObjectReader&, O&)> f) {
    after_read_.push_back(std::move(f));
    return *this;
  }
  /// A rule between keys, checked by validate() after the ranges.
  OptionTable& rule(std::function<void(const O&, const std::string& prefix)> f) {
    rules_.push_back(std::move(f));
    return *this;
  }

  /// Reads every declared key present (required ones must be) into `o`; leaves finish() to
  /// the caller, who may read other keys of the same object.
  void read(ObjectReader& r, O& o) const {
    for (const auto& e : entries_) {
      if (e.info.type == KeyType::external) continue;
      if (e.info.spec.required || r.has(e.info.key)) e.read(r, o);
    }
    for (const auto& f : after_read_) f(r, o);
  }

  /// InputError naming the key (prefix + key), the value and the allowed range.
  void validate(const O& o, const std::string& prefix = "") const {
    for (const auto& e : entries_)
      if (e.validate) e.validate(o, prefix);
    for (const auto& rule : rules_) rule(o, prefix);
  }

  /// The options as a case would give them (case units); absent optional keys are left out.
  [[nodiscard]] nlohmann::json to_json(const O& o) const {
    auto out = nlohmann::json::object();
    for (const auto& e : entries_) {
      if (!e.get) continue;
      if (auto v = e.get(o); !v.is_null()) out[e.info.key] = std::move(v);
    }
    return out;
  }

  /// The object schema of these keys; defaults from a default-constructed O.
  [[nodiscard]] nlohmann::json schema(const std::string& description = "") const { return schema(description, O{}); }
  /// The same with the defaults `defaults` holds: a section's are those its holder sets (one
  /// friction section, a different default μ in each model that holds it).
  [[nodiscard]] nlohmann::json schema(const std::string& description, const O& defaults) const {
    auto obj = nlohmann::json{{"type", "object"}, {"properties", nlohmann::json::object()}};
    auto required = nlohmann::json::array();
    for (const auto& e : entries_) {
      const bool has_default = e.get && !e.info.spec.required && e.info.spec.default_text.empty() &&
                               e.info.type != KeyType::section;
      obj["properties"][e.info.key] = key_schema(e.info, has_default ? e.get(defaults) : nlohmann::json(nullptr));
      if (e.info.spec.required) required.push_back(e.info.key);
    }
    if (!required.empty()) obj["required"] = required;
    return merge_object_schemas({obj}, description);
  }

  [[nodiscard]] std::vector<KeyInfo> keys() const {
    std::vector<KeyInfo> out;
    for (const auto& e : entries_) out.push_back(e.info);
    return out;
  }

 private:
  struct Entry {
    KeyInfo info;
    std::function<nlohmann::json(const O&)> get;
    std::function<void(ObjectReader&, O&)> read;
    std::function<void(const O&, const std::string&)> validate;
  };
  template <class Access>
  using member_t = std::remove_cvref_t<std::invoke_result_t<Access, O&>>;

  /// The section a default-constructed O holds (a default S where it holds none).
  template <class S, class Access>
  static S holder_default(Access access) {
    const O holder{};
    const auto& m = std::invoke(access, holder);
    if constexpr (detail::is_optional<member_t<Access>>::value) return m ? *m : S{};
    else return m;
  }

  template <class T>
  static std::vector<T> concat(std::vector<T> a, const std::vector<T>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
  }

  template <class F>
  static nlohmann::json value_json(double v, const F& to_case) { return to_case(v); }
  template <class Values, class F>
  static nlohmann::json value_json(const Values& values, const F& to_case) {
    auto out = nlohmann::json::array();
    for (const double v : values) out.push_back(to_case(v));
    return out;
  }

  /// The range is checked in SI, its bounds converted as the reader converts a value, so a
  /// value read at a bound passes exactly.
  template <class F>
  static void check_range(double si, const std::string& key, const KeyInfo& info, const F& to_si) {
    const Range& r = *info.range;
    const Range si_range{to_si(r.lo), r.hi >= 1e299 ? r.hi : to_si(r.hi), r.lo_open, r.hi_open};
    if (!si_range.contains(si))
      throw_range(key,
                  info.type == KeyType::integer ? si - info.spec.offset
                                                : (si - info.spec.offset) * info.spec.divisor / info.spec.scale,
                  info);
  }
  template <class Values, class F>
  static void check_range(const Values& si, const std::string& key, const KeyInfo& info, const F& to_si) {
    for (std::size_t i = 0; i < si.size(); ++i) check_range(si[i], key + "[" + std::to_string(i) + "]", info, to_si);
  }
  [[noreturn]] static void throw_range(const std::string& key, double value, const KeyInfo& info);
  [[noreturn]] static void throw_not_a_choice(const std::string& key, const KeyInfo& info);

  template <class>
  friend class OptionTable;
  std::vector<Entry> entries_;
  std::vector<std::function<void(ObjectReader&, O&)>> after_read_;
  std::vector<std::function<void(const O&, const std::string&)>> rules_;
};

/// A table made by `make` on first use, once (the order of static initialisation across files
/// is not ours to rely on).
template <auto make>
const auto& built_once() {
  static const auto table = make();
  return table;
}

/// Out of line so that every table throws the same InputError.
[[noreturn]] void throw_option_range(const std::string& key, double value, const KeyInfo& info);
[[noreturn]] void throw_option_choice(const std::string& key, const KeyInfo& info);

template <class O>
void OptionTable<O>::throw_range(const std::string& key, double value, const KeyInfo& info) {
  throw_option_range(key, value, info);
}
template <class O>
void OptionTable<O>::throw_not_a_choice(const std::string& key, const KeyInfo& info) {
  throw_option_choice(key, info);
}

}  // namespace gearbench::model
