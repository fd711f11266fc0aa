#include "sweep_command.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <exception>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <iostream>
#include <map>

#include "build_info.h"
#include "commands.h"
#include "interrupt.h"
#include "kind_registry.h"
#include "mpi_session.h"
#include "model/errors.h"
#include "model/json_reader.h"

namespace gearbench::app {

namespace fs = std::filesystem;
using nlohmann::json;
using nlohmann::ordered_json;

/// Cases in one sweep at most: a larger grid is almost surely a mistake in the file.
constexpr std::size_t max_sweep_cases = 100000;

json::json_pointer key_pointer(const std::string& key, const std::string& section) {
  if (key.empty())
    throw InputError(fmt::format("{}: a key is empty; expected a dotted path such as operating.speed_rpm", section));
  // A case nests no deeper than the parser allows; a longer path would build a deeper one.
  if (static_cast<std::size_t>(std::count(key.begin(), key.end(), key.front() == '/' ? '/' : '.')) >= model::max_json_depth)
    throw InputError(fmt::format("{}.\"{}\": deeper than {} levels", section, model::shown_text(key), model::max_json_depth));
  try {
    if (key.front() == '/') return json::json_pointer(key);
    std::string pointer;
    std::size_t start = 0;
    while (start <= key.size()) {
      auto end = key.find('.', start);
      if (end == std::string::npos) end = key.size();
      const std::string part = key.substr(start, end - start);
      if (part.empty())
        throw InputError(fmt::format("{}.\"{}\": empty segment in the dotted path", section, model::shown_text(key)));
      pointer += "/";
      for (char c : part) pointer += c == '~' ? std::string("~0") : c == '/' ? std::string("~1") : std::string(1, c);
      start = end + 1;
    }
    return json::json_pointer(pointer);
  } catch (const json::exception& e) {
    throw InputError(fmt::format("{}.\"{}\": not a valid JSON pointer ({})", section, model::shown_text(key), e.what()));
  }
}

std::size_t SweepSpec::size() const {
  std::size_t n = 1;
  for (const auto& a : axes) n *= a.values.size();
  return n;
}

std::vector<json> SweepSpec::values_at(std::size_t index) const {
  std::vector<json> out(axes.size());
  for (std::size_t k = axes.size(); k-- > 0;) {
    out[k] = axes[k].values[index % axes[k].values.size()];
    index /= axes[k].values.size();
  }
  return out;
}

json SweepSpec::case_at(std::size_t index) const {
  json c = base;
  const auto values = values_at(index);
  for (std::size_t k = 0; k < axes.size(); ++k) {
    try {
      c[axes[k].where] = values[k];
    } catch (const json::exception& e) {
      throw InputError(fmt::format("vary.\"{}\": cannot be set in the base case ({})", model::shown_text(axes[k].key),
                                   model::shown_text(e.what())));
    }
  }
  return c;
}

namespace {

json load_base(const ordered_json& base, const std::string& sweep_dir) {
  if (base.is_object()) return json(base);
  if (!base.is_string()) throw InputError("base: must be a case file path or a case object");
  const std::string path = base.get<std::string>();
  const fs::path beside = fs::path(sweep_dir) / path;
  return model::read_json_file(fs::exists(beside) ? beside.string() : path);
}

SweepAxis parse_axis(const std::string& key, const ordered_json& values) {
  if (const auto why = model::unread(values))
    throw InputError(fmt::format("vary.\"{}\": {}", model::shown_text(key), *why));
  if (!values.is_array() || values.empty())
    throw InputError(fmt::format("vary.\"{}\" = {}: must be a non-empty array of values", model::shown_text(key),
                                 model::shown_value(json(values))));
  SweepAxis axis{key, key_pointer(key), {}};
  for (const auto& v : values) axis.values.emplace_back(v);
  return axis;
}

/// Two axes that reach the same place (a dotted path and a JSON pointer to one key, or a key
/// and a key inside it) would overwrite each other: the table would show values never used.
void check_axes_apart(const std::vector<SweepAxis>& axes) {
  for (std::size_t i = 0; i < axes.size(); ++i)
    for (std::size_t j = i + 1; j < axes.size(); ++j) {
      const auto a = axes[i].where.to_string(), b = axes[j].where.to_string();
      const std::string& shorter = a.size() <= b.size() ? a : b;
      const std::string& longer = a.size() <= b.size() ? b : a;
      if (longer.compare(0, shorter.size(), shorter) == 0 && (longer.size() == shorter.size() || longer[shorter.size()] == '/'))
        throw InputError(fmt::format("vary.\"{}\": reaches the same key as vary.\"{}\" ({}); vary each key once",
                                     model::shown_text(axes[j].key), model::shown_text(axes[i].key),
                                     model::shown_text(shorter)));
    }
}

/// The product of the axis lengths, refused above max_sweep_cases before it can overflow
/// (64 axes of 2 values once wrapped to 0 cases).
void check_case_count(const std::vector<SweepAxis>& axes) {
  std::size_t n = 1;
  for (const auto& a : axes) {
    if (n > max_sweep_cases / a.values.size())
      throw InputError(fmt::format("vary: more than {} cases ({} axes); at most {} are allowed", max_sweep_cases,
                                   axes.size(), max_sweep_cases));
    n *= a.values.size();
  }
}

}  // namespace

SweepSpec parse_sweep_spec(const ordered_json& spec, const std::string& sweep_dir, const std::string& name) {
  if (!spec.is_object()) throw InputError("sweep: must be a JSON object with base, vary and outputs");
  for (const auto& [key, value] : spec.items())
    if (key != "base" && key != "vary" && key != "outputs" && key != "description")
      throw InputError(fmt::format("{}: unknown key; allowed keys are base, vary, outputs, description",
                                   model::shown_text(key)));
  for (const char* key : {"base", "vary", "outputs"})
    if (!spec.contains(key)) throw InputError(fmt::format("{}: missing required key", key));
  SweepSpec s;
  s.name = name;
  s.base_source = spec["base"].is_string() ? spec["base"].get<std::string>() : std::string("(inline)");
  s.base = load_base(spec["base"], sweep_dir);
  if (!s.base.is_object() || !s.base.contains("kind"))
    throw InputError(fmt::format("base = {}: not a case (no \"kind\")", model::shown_text(s.base_source)));
  if (!spec["vary"].is_object() || spec["vary"].empty())
    throw InputError("vary: must be a non-empty object of key -> array of values");
  for (const auto& [key, values] : spec["vary"].items()) s.axes.push_back(parse_axis(key, values));
  check_axes_apart(s.axes);
  check_case_count(s.axes);
  if (!spec["outputs"].is_array() || spec["outputs"].empty())
    throw InputError("outputs: must be a non-empty array of result keys (dotted paths)");
  for (const auto& o : spec["outputs"]) {
    if (!o.is_string() || o.get<std::string>().empty())
      throw InputError(fmt::format("outputs: {} is not a result key", model::shown_value(json(o))));
    key_pointer(o.get<std::string>(), "outputs");  // well-formed
    s.outputs.push_back(o.get<std::string>());
  }
  s.description = spec.value("description", "");
  static_cast<void>(s.case_at(0));  // throws when a key cannot be set in the base case
  return s;
}

SweepSpec read_sweep_file(const std::string& path) {
  const fs::path p(path);
  // ordered_json keeps the axes in the order written (the last one varies fastest).
  return parse_sweep_spec(model::parse_ordered_json(model::read_text_file(path, "sweep file"), path),
                          p.parent_path().string(), p.stem().string());
}

json SweepRow::to_json() const {
  json j{{"index", index}, {"outputs", outputs}};
  if (!error.empty()) {
    j["error"] = error;
    j["error_kind"] = error_kind;
  }
  return j;
}

SweepRow SweepRow::from_json(const json& j) {
  SweepRow r;
  r.index = j.at("index").get<std::size_t>();
  r.outputs = j.at("outputs");
  r.error = j.value("error", "");
  r.error_kind = j.value("error_kind", "");
  r.seconds = j.value("seconds", 0.0);
  r.rank = j.value("rank", 0);
  return r;
}

SweepRow run_sweep_case(const SweepSpec& spec, std::size_t index) {
  SweepRow row;
  row.index = index;
  const auto start = std::chrono::steady_clock::now();
  try {
    const json result = run_case(spec.case_at(index));
    for (const auto& name : spec.outputs) {
      const auto where = key_pointer(name, "outputs");
      if (!result.contains(where)) {
        std::vector<std::string> keys;
        for (const auto& item : result.items()) keys.push_back(item.key());
        throw InputError(fmt::format("outputs: \"{}\" is not in the {} result (its keys: {})", name,
                                     spec.base["kind"].get<std::string>(), fmt::join(keys, ", ")));
      }
      row.outputs[name] = result[where];
    }
  } catch (const InputError& e) {
    row.error = e.what();
    row.error_kind = "bad_input";
  } catch (const ConvergenceError& e) {
    row.error = e.what();
    row.error_kind = "not_converged";
  } catch (const std::exception& e) {
    row.error = e.what();
    row.error_kind = "internal";
  }
  if (!row.error.empty()) row.outputs = json::object();
  row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return row;
}

namespace {

/// RFC 4180 field.
std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::string csv_value(const json& v) {
  if (v.is_null()) return "";
  if (v.is_number_float()) return fmt::format("{:.10g}", v.get<double>());
  if (v.is_string()) return csv_field(v.get<std::string>());
  return csv_field(v.dump());  // integers, booleans, arrays and objects as compact JSON
}

std::string short_value(const json& v) { return v.is_string() ? v.get<std::string>() : v.dump(); }

}  // namespace

std::string sweep_csv(const SweepSpec& spec, const std::vector<SweepRow>& rows) {
  std::string out = "index";
  // Appending piece by piece (not "," + field) also keeps GCC 12's -Wrestrict false
  // positive on operator+(const char*, std::string&&) away.
  const auto cell = [&out](const std::string& text) {
    out += ',';
    out += text;
  };
  for (const auto& a : spec.axes) cell(csv_field(a.key));
  for (const auto& o : spec.outputs) cell(csv_field(o));
  out += ",error\n";
  for (const auto& r : rows) {
    out += std::to_string(r.index);
    for (const auto& v : spec.values_at(r.index)) cell(csv_value(v));
    for (const auto& o : spec.outputs) cell(r.outputs.contains(o) ? csv_value(r.outputs[o]) : std::string());
    cell(csv_field(r.error));
    out += '\n';
  }
  return out;
}

json sweep_json(const SweepSpec& spec, const std::vector<SweepRow>& rows, int ranks) {
  json axes = json::array();
  for (const auto& a : spec.axes) axes.push_back({{"key", a.key}, {"values", a.values}});
  json table = json::array(), timing = json::array();
  std::size_t failed = 0;
  for (const auto& r : rows) {
    auto row = r.to_json();
    json values = json::object();
    const auto v = spec.values_at(r.index);
    for (std::size_t k = 0; k < spec.axes.size(); ++k) values[spec.axes[k].key] = v[k];
    row["values"] = values;
    table.push_back(row);
    timing.push_back({{"index", r.index}, {"rank", r.rank}, {"seconds", r.seconds}});
    failed += r.error.empty() ? 0 : 1;
  }
  return {{"sweep", {{"name", spec.name}, {"base", spec.base_source}, {"kind", spec.base["kind"]},
                     {"description", spec.description}, {"axes", axes}, {"outputs", spec.outputs}}},
          {"summary", {{"cases", rows.size()}, {"failed", failed}}},
          {"rows", table},
          {"timing", {{"ranks", ranks}, {"cases", timing}}},
          {"gearbench", reports::provenance()}};
}

std::vector<reports::Figure> sweep_figures(const SweepSpec& spec, const std::vector<SweepRow>& rows) {
  const auto& first = spec.axes.front();
  bool numeric_x = true;
  for (const auto& v : first.values) numeric_x = numeric_x && v.is_number();
  std::vector<reports::Figure> out;
  for (const auto& name : spec.outputs) {
    reports::Figure f{.id = "sweep_", .section = "Sweep", .title = fmt::format("{}: {}", spec.name, name),
                      .xlabel = first.key, .ylabel = name};
    for (char c : name) f.id.push_back(std::isalnum(static_cast<unsigned char>(c)) ? c : '_');
    if (!numeric_x)
      for (const auto& v : first.values) f.xtic_labels.push_back(short_value(v));
    f.points = !numeric_x || first.values.size() < 12;
    std::map<std::string, std::size_t> series_of;  // label of the other axes -> series index
    bool any = false;
    for (const auto& r : rows) {
      const auto values = spec.values_at(r.index);
      std::string label;
      for (std::size_t k = 1; k < spec.axes.size(); ++k)
        label += fmt::format("{}{} = {}", label.empty() ? "" : ", ", spec.axes[k].key, short_value(values[k]));
      if (label.empty()) label = name;
      auto [it, added] = series_of.try_emplace(label, f.series.size());
      if (added) f.series.push_back({label, {}, {}});
      const auto pos = static_cast<std::size_t>(
          std::find(first.values.begin(), first.values.end(), values[0]) - first.values.begin());
      const bool ok = r.outputs.contains(name) && r.outputs[name].is_number();
      // A failed case is a gap in its line (NaN is skipped when drawn, empty in the CSV).
      f.series[it->second].x.push_back(numeric_x ? values[0].get<double>() : static_cast<double>(pos));
      f.series[it->second].y.push_back(ok ? r.outputs[name].get<double>() : std::nan(""));
      any = any || ok;
    }
    if (any) out.push_back(std::move(f));
  }
  return out;
}

namespace {

/// Every rank's rows on rank 0 in case order (elsewhere: empty), sent as JSON text.
std::vector<SweepRow> gather_rows(const MpiSession& mpi, const std::vector<SweepRow>& mine) {
  if (mpi.size() == 1) return mine;
  json j = json::array();
  for (const auto& r : mine) {
    j.push_back(r.to_json());
    j.back()["seconds"] = r.seconds;
    j.back()["rank"] = r.rank;
  }
  std::vector<SweepRow> rows;
  for (const auto& text : mpi.gather(j.dump()))
    for (const auto& row : json::parse(text)) rows.push_back(SweepRow::from_json(row));
  std::sort(rows.begin(), rows.end(), [](const auto& a, const auto& b) { return a.index < b.index; });
  return rows;
}

void write_text(const fs::path& path, const std::string& text) {
  const fs::path temp = path.string() + ".tmp";
  {
    std::ofstream out(temp);
    out << text;
    out.flush();
    if (!out) throw std::runtime_error("cannot write " + path.string());
  }
  fs::rename(temp, path);
}

std::string describe_values(const SweepSpec& spec, std::size_t index) {
  std::string s;
  const auto values = spec.values_at(index);
  for (std::size_t k = 0; k < spec.axes.size(); ++k)
    s += fmt::format("{}{}={}", k ? ", " : "", spec.axes[k].key, short_value(values[k]));
  return s;
}

/// Writes the table, JSON and figures; returns the number of failed cases.
long write_sweep_output(const SweepSpec& spec, const std::vector<SweepRow>& rows, const std::string& out_dir,
                        bool pdf, int ranks) {
  const fs::path out =
      out_dir.empty() ? fs::path(build::source_dir()) / "reports" / "out" / "sweep" / spec.name : fs::path(out_dir);
  fs::create_directories(out / "figures");
  write_text(out / "sweep.csv", sweep_csv(spec, rows));
  const json table = sweep_json(spec, rows, ranks);
  write_text(out / "sweep.json", table.dump(2) + "\n");
  for (const auto& f : sweep_figures(spec, rows)) reports::write_figure(f, (out / "figures" / f.id).string(), pdf);
  const long failed = table["summary"]["failed"].get<long>();
  std::cerr << fmt::format("sweep {}: {} of {} cases ran, {} failed (recorded in the table)\n", spec.name,
                           rows.size() - static_cast<std::size_t>(failed), rows.size(), failed);
  std::cout << out.string() << "\n";
  return failed;
}

}  // namespace

int sweep_command(const std::string& sweep_path, const std::string& out_dir, bool pdf) {
  const SweepSpec spec = read_sweep_file(sweep_path);  // every rank reads and validates it
  const MpiSession mpi;
  const std::size_t n = spec.size();
  std::vector<SweepRow> mine;
  // Cyclic distribution: case i on rank i mod size, whatever its cost.
  for (std::size_t i = static_cast<std::size_t>(mpi.rank()); i < n; i += static_cast<std::size_t>(mpi.size())) {
    auto row = run_sweep_case(spec, i);
    row.rank = mpi.rank();
    std::cerr << fmt::format("sweep {}: case {}/{} {} ({}; {:.2f} s{})\n", spec.name, i + 1, n,
                             row.error.empty() ? "ok" : "FAILED: " + row.error, describe_values(spec, i),
                             row.seconds, mpi.size() > 1 ? fmt::format(", rank {}", mpi.rank()) : "")
              << std::flush;
    mine.push_back(std::move(row));
  }
  const auto rows = gather_rows(mpi, mine);
  // Rank 0 writes; every rank learns how it went, so that none waits for a rank that failed.
  long status = 0;  // number of failed cases, or −1 when the output could not be written
  std::exception_ptr error;
  if (mpi.rank() == 0) {
    try {
      // The table, JSON and figures are written as one and are the sweep's last step: a Ctrl-C
      // from here waits for the end (deferred to the write's end only, it exited 130 with the
      // output complete, as `run` did).
      hold_interrupts_to_the_end();
      status = write_sweep_output(spec, rows, out_dir, pdf, mpi.size());
    } catch (...) {
      error = std::current_exception();
      status = -1;
    }
  }
  status = mpi.broadcast(status);
  if (error) std::rethrow_exception(error);
  if (status < 0) throw std::runtime_error("rank 0 could not write the sweep output");
  return status == 0 ? exit_ok : exit_failed;
}

}  // namespace gearbench::app
