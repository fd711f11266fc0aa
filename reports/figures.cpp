// Figures drawn by gnuplot from a figure's series (one data block per series): SVG for the
// reports, PDF (cairo) for publications, and the data itself as CSV next to them.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>

#include "build_info.h"
#include "report.h"

namespace gearbench::reports {

namespace {
std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

/// RFC 4180: a field with a comma, quote or line break is quoted, quotes doubled.
std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

/// Draws `figure` with gnuplot's `terminal` into `path`; false (and no file) on failure.
bool render(const Figure& figure, const std::string& terminal, const std::string& path) {
  const std::string gnuplot = build::gnuplot_executable();
  if (gnuplot.empty() || gnuplot.find("NOTFOUND") != std::string::npos) return false;
  const std::string script_path = path + ".gp";
  {
    std::ofstream gp(script_path);
    gp << "set terminal " << terminal << "\n"
       << "set output " << quoted(path) << "\n"
       << "set title " << quoted(figure.title) << " noenhanced\n"
       << "set xlabel " << quoted(figure.xlabel) << " noenhanced\n"
       << "set ylabel " << quoted(figure.ylabel) << " noenhanced\n"
       << "set grid\nset key below noenhanced\n"
       << (figure.log_x ? "set logscale x\n" : "") << (figure.log_y ? "set logscale y\n" : "");
    if (!figure.colour_label.empty())
      gp << "set size ratio -1\nset palette rgbformulae 22,13,-31\nset cblabel " << quoted(figure.colour_label)
         << " noenhanced\n";
    if (!figure.xtic_labels.empty()) {
      gp << "set xtics rotate by -45 noenhanced (";
      for (std::size_t i = 0; i < figure.xtic_labels.size(); ++i)
        gp << (i ? ", " : "") << quoted(figure.xtic_labels[i]) << " " << i;
      gp << ")\nset xrange [-0.5:" << static_cast<double>(figure.xtic_labels.size()) - 0.5 << "]\n";
    }
    for (std::size_t i = 0; i < figure.series.size(); ++i) {
      gp << "$d" << i << " << EOD\n";
      const auto& s = figure.series[i];
      const bool coloured = !figure.colour_label.empty();
      for (std::size_t k = 0; k < s.x.size() && k < s.y.size(); ++k) {
        if (!std::isfinite(s.x[k]) || !std::isfinite(s.y[k])) continue;
        if (!coloured) {
          gp << fmt::format("{:.10g} {:.10g}\n", s.x[k], s.y[k]);
        } else if (k < s.z.size() && std::isfinite(s.z[k])) {
          gp << fmt::format("{:.10g} {:.10g} {:.10g}\n", s.x[k], s.y[k], s.z[k]);
        }
      }
      gp << "EOD\n";
    }
    const std::string style = !figure.colour_label.empty() ? "points pt 5 ps 0.3 palette"
                              : figure.impulses          ? "impulses"
                              : figure.points            ? "linespoints pt 7"
                                                         : "lines";
    gp << "plot ";
    for (std::size_t i = 0; i < figure.series.size(); ++i)
      gp << (i ? ", " : "") << "$d" << i << (figure.colour_label.empty() ? " using 1:2 with " : " using 1:2:3 with ")
         << (figure.series[i].style.empty() ? style : figure.series[i].style)
         << (figure.colour_label.empty() ? " lw 2" : "") << " title " << quoted(figure.series[i].label);
    gp << "\n";
  }
  const int status = std::system(fmt::format("{} {} 2>/dev/null", quoted(gnuplot), quoted(script_path)).c_str());
  std::filesystem::remove(script_path);
  if (status != 0) {
    std::filesystem::remove(path);
    return false;
  }
  return true;
}
}  // namespace

bool render_svg(const Figure& figure, const std::string& svg_path) {
  return render(figure, "svg size 720,420 dynamic enhanced font 'Helvetica,12'", svg_path);
}

bool render_pdf(const Figure& figure, const std::string& pdf_path) {
  // 5.0 x 3.0 in: a single journal column at a readable font size.
  return render(figure, "pdfcairo size 5.0in,3.0in enhanced font 'Helvetica,9'", pdf_path);
}

void write_figure_csv(const Figure& figure, const std::string& csv_path) {
  std::ofstream out(csv_path);
  const bool labels = !figure.xtic_labels.empty();
  const bool coloured = !figure.colour_label.empty();
  out << "series," << csv_field(figure.xlabel) << (labels ? ",label," : ",") << csv_field(figure.ylabel);
  if (coloured) out << "," << csv_field(figure.colour_label);
  out << "\n";
  for (const auto& s : figure.series)
    for (std::size_t k = 0; k < s.x.size() && k < s.y.size(); ++k) {
      // No NaN in a report: a non-finite value is an empty cell.
      const auto number = [](double v) { return std::isfinite(v) ? fmt::format("{:.10g}", v) : std::string(); };
      std::string label;
      if (labels) {
        const double i = std::round(s.x[k]);
        label = i >= 0 && i < static_cast<double>(figure.xtic_labels.size())
                    ? csv_field(figure.xtic_labels[static_cast<std::size_t>(i)]) + ","
                    : std::string(",");
      }
      out << csv_field(s.label) << "," << number(s.x[k]) << "," << label << number(s.y[k]);
      if (coloured) out << "," << (k < s.z.size() ? number(s.z[k]) : std::string());
      out << "\n";
    }
  out.flush();
  if (!out) throw std::runtime_error("cannot write " + csv_path);
}

Figure figure_from_json(const nlohmann::json& j) {
  Figure f{.id = j.at("id").get<std::string>(), .section = j.value("section", ""), .title = j.value("title", ""),
           .xlabel = j.value("xlabel", ""), .ylabel = j.value("ylabel", ""), .log_y = j.value("log_y", false),
           .impulses = j.value("impulses", false), .points = j.value("points", false),
           .colour_label = j.value("colour_label", ""), .log_x = j.value("log_x", false)};
  if (j.contains("xtic_labels")) f.xtic_labels = j["xtic_labels"].get<std::vector<std::string>>();
  // null (a non-finite value in the report) stays non-finite and is skipped when drawn.
  const auto numbers = [](const nlohmann::json& a) {
    std::vector<double> v;
    for (const auto& x : a) v.push_back(x.is_number() ? x.get<double>() : std::nan(""));
    return v;
  };
  for (const auto& s : j.value("series", nlohmann::json::array()))
    f.series.push_back({s.value("label", ""), numbers(s.at("x")), numbers(s.at("y")),
                        s.contains("z") ? numbers(s["z"]) : std::vector<double>{}});
  return f;
}

bool write_figure(const Figure& figure, const std::string& stem, bool pdf) {
  write_figure_csv(figure, stem + ".csv");
  bool drawn = render_svg(figure, stem + ".svg");
  if (pdf) drawn = render_pdf(figure, stem + ".pdf") && drawn;
  return drawn;
}

}  // namespace gearbench::reports
