// SVG figures drawn by gnuplot from a figure's series (one data block per series).
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
}  // namespace

bool render_svg(const Figure& figure, const std::string& svg_path) {
  const std::string gnuplot = build::gnuplot_executable();
  if (gnuplot.empty() || gnuplot.find("NOTFOUND") != std::string::npos) return false;
  const std::string script_path = svg_path + ".gp";
  {
    std::ofstream gp(script_path);
    gp << "set terminal svg size 720,420 dynamic enhanced font 'Helvetica,12'\n"
       << "set output " << quoted(svg_path) << "\n"
       << "set title " << quoted(figure.title) << " noenhanced\n"
       << "set xlabel " << quoted(figure.xlabel) << " noenhanced\n"
       << "set ylabel " << quoted(figure.ylabel) << " noenhanced\n"
       << "set grid\nset key below noenhanced\n"
       << (figure.log_y ? "set logscale y\n" : "");
    for (std::size_t i = 0; i < figure.series.size(); ++i) {
      gp << "$d" << i << " << EOD\n";
      const auto& s = figure.series[i];
      for (std::size_t k = 0; k < s.x.size() && k < s.y.size(); ++k)
        gp << fmt::format("{:.10g} {:.10g}\n", s.x[k], s.y[k]);
      gp << "EOD\n";
    }
    gp << "plot ";
    for (std::size_t i = 0; i < figure.series.size(); ++i)
      gp << (i ? ", " : "") << "$d" << i << " using 1:2 with " << (figure.impulses ? "impulses" : "lines")
         << " lw 2 title "
         << quoted(figure.series[i].label);
    gp << "\n";
  }
  const int status = std::system(fmt::format("{} {} 2>/dev/null", quoted(gnuplot), quoted(script_path)).c_str());
  std::filesystem::remove(script_path);
  if (status != 0) {
    std::filesystem::remove(svg_path);
    return false;
  }
  return true;
}

}  // namespace gearbench::reports
