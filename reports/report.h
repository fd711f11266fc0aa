#pragma once
// A versioned verification report: every figure a solver produced, compared with an
// independent reference under a stated tolerance, with provenance. Written as a folder
// <UTC date>_<short sha>/ holding report.json, report.md and figures/*.svg.
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace gearbench::reports {

/// |value − reference| ≤ abs + rel·|reference| passes.
struct Tolerance {
  double abs = 0.0;
  double rel = 0.0;
};

/// What a check found. The rules that decide it live in verification/ (outcome.h); a report
/// stores and renders the outcome.
enum class Outcome { pass, reproduced, missed, fail };
/// "pass", "reproduced", "missed", "fail": the `status` of a check in report.json.
std::string outcome_name(Outcome outcome);

struct CheckRecord {
  std::string id;             ///< stable identifier, e.g. "geometry.seed004.contact_ratio"
  std::string section;        ///< report section, e.g. "Involute geometry"
  std::string solver;
  std::string reference;
  std::string quantity;
  std::string unit;
  double value = 0.0;
  double reference_value = 0.0;
  Tolerance tolerance;
  std::string justification;  ///< why this tolerance
  double seconds = 0.0;
  nlohmann::json diagnostics = nlohmann::json::object();
  std::string error;          ///< set when the check threw instead of producing a value
  /// A seed reproduction: reference_value is the paper's figure, `recorded` the figure
  /// reached when the gap to it was analysed, `recorded_tolerance` the relative drift from
  /// it that counts as a regression.
  bool reproduction = false;
  double recorded = 0.0;
  double recorded_tolerance = 0.0;
  Outcome outcome = Outcome::fail;  ///< set by verification::classify

  [[nodiscard]] double abs_error() const;
  [[nodiscard]] double rel_error() const;
};

struct Series {
  std::string label;
  std::vector<double> x;
  std::vector<double> y;
  std::vector<double> z;  ///< colour value per point (Figure::colour_label set), else empty
  /// gnuplot style when it differs from the figure's, e.g. marks without lines for a spread.
  std::string style;
};

struct Figure {
  std::string id;       ///< file stem under figures/
  std::string section;
  std::string title;
  std::string xlabel;
  std::string ylabel;
  std::vector<Series> series;
  bool log_y = false;
  bool impulses = false;  ///< spectra: one vertical line per bin
  /// Categorical x axis: label i is drawn at x = i (e.g. commits of a performance history).
  std::vector<std::string> xtic_labels;
  bool points = false;    ///< mark every point (sparse data such as one value per commit)
  /// Non-empty: a colour map — each series' points (x, y) filled by z on a palette with
  /// this label, equal axis scales (e.g. a stress field sampled on a grid).
  std::string colour_label;
  /// Logarithmic x axis (last, so that positional initialisers of the fields above keep
  /// their meaning).
  bool log_x = false;
};

/// Free text for a section (e.g. what a seed reproduction reached and why it differs).
struct Note {
  std::string section;
  std::string text;
};

/// A report section whose figures and notes could not be built.
struct SectionFailure {
  std::string id;
  std::string error;
};

/// How many checks ended in each outcome, and how many sections could not be built.
struct OutcomeCounts {
  int checks = 0;
  int pass = 0;
  int reproduced = 0;
  int missed = 0;
  int failed = 0;
  int sections_failed = 0;
};

struct Report {
  std::string tier;
  std::vector<CheckRecord> checks;
  std::vector<Figure> figures;
  std::vector<Note> notes;
  std::vector<SectionFailure> section_failures;

  [[nodiscard]] OutcomeCounts counts() const;
};

/// One line with every count, e.g. "170 checks: 150 pass, 6 reproduced, 14 missed, 0 failed".
std::string headline(const OutcomeCounts& counts);

/// Code, build and machine provenance as a JSON object.
nlohmann::json provenance();
/// A fingerprint of the machine and toolchain (FNV-1a 64, `fingerprint_digest`): timings
/// are comparable only when equal.
std::string machine_fingerprint();
/// The digest of machine_fingerprint(), recorded next to it in a report. Reports written
/// before it was recorded carry an std::hash fingerprint, which is not stable between builds.
inline constexpr const char* fingerprint_digest = "fnv1a64";
/// 64-bit FNV-1a of text (Fowler, Noll, Vo; IETF draft-eastlake-fnv, section 2).
std::uint64_t fnv1a64(const std::string& text);
/// A stable hash of the hardware alone (CPU model, core count, memory): benchmark times
/// are compared across commits only between runs with the same one.
std::string hardware_fingerprint();
/// "<UTC date>_<short sha>", the report folder name.
std::string report_folder_name();

nlohmann::json to_json(const Report& report);
std::string to_markdown(const Report& report, const nlohmann::json& meta);

/// Writes the report atomically into parent/<folder>: a temporary folder is filled and
/// renamed. An existing folder of that name is never overwritten (a suffix -2, -3, ...
/// is added). Returns the folder written.
std::string write_report(const Report& report, const std::string& parent);

/// Renders a figure to SVG with gnuplot; returns false (and leaves no file) when gnuplot
/// is not available or fails.
bool render_svg(const Figure& figure, const std::string& svg_path);
/// The same as a PDF for publications (gnuplot's pdfcairo terminal).
bool render_pdf(const Figure& figure, const std::string& pdf_path);
/// The figure's data as CSV: one row per point, columns series, x, [x label,] y.
void write_figure_csv(const Figure& figure, const std::string& csv_path);
/// A figure back from its report.json entry (as written by to_json).
Figure figure_from_json(const nlohmann::json& j);
/// Writes stem.csv and stem.svg, and stem.pdf when `pdf`; false when a drawing failed
/// (the CSV is always written).
bool write_figure(const Figure& figure, const std::string& stem, bool pdf = false);

}  // namespace gearbench::reports
