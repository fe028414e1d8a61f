// SPDX-License-Identifier: LGPL-2.1-or-later
#include "base/plot.h"

#include "base/atomic_file.h"
#include "base/exceptions.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

#include <unistd.h>

namespace wearlink
{
  namespace
  {
    std::string
    quote(const std::string &s)
    {
      std::string out = "\"";
      for (const char c : s)
        {
          if (c == '"' || c == '\\')
            out += '\\';
          out += c;
        }
      return out + "\"";
    }
  } // namespace

  bool
  gnuplot_available()
  {
    return std::system("command -v gnuplot > /dev/null 2>&1") == 0;
  }

  bool
  plot_png(const PlotSpec &spec, const std::string &png_path)
  {
    namespace fs = std::filesystem;
    if (!gnuplot_available())
      {
        std::cerr << "warning: gnuplot is not installed; skipping plot " << png_path
                  << " (apt-get install gnuplot-nox)\n";
        return false;
      }
    const fs::path dir = fs::temp_directory_path() /
                         ("wearlink-plot-" + std::to_string(::getpid()) + "-" +
                          std::to_string(std::hash<std::string>()(png_path)));
    fs::create_directories(dir);

    std::ostringstream script;
    const std::string  tmp_png = temporary_name_for(png_path);
    script << "set terminal pngcairo size " << spec.width << "," << spec.height
           << " enhanced font 'Sans,11'\n"
           << "set output " << quote(tmp_png) << "\n"
           << "set title " << quote(spec.title) << " noenhanced\n"
           << "set xlabel " << quote(spec.x_label) << " noenhanced\n"
           << "set ylabel " << quote(spec.y_label) << " noenhanced\n"
           << "set grid\nset key outside right top noenhanced\n";
    if (spec.log_x)
      script << "set logscale x\n";
    if (spec.log_y)
      script << "set logscale y\n";
    if (spec.equal_axes)
      script << "set size ratio -1\n";
    if (spec.polar)
      script << "set polar\nset angles radians\nset size ratio -1\nunset xtics\nunset ytics\n"
                "set border 0\nset grid polar\n";
    script << spec.extra << "\n";

    std::string plot_cmd = "plot ";
    for (std::size_t i = 0; i < spec.series.size(); ++i)
      {
        const auto &     s    = spec.series[i];
        const fs::path   data = dir / ("series" + std::to_string(i) + ".dat");
        std::ofstream    out(data);
        out << std::setprecision(12);
        for (std::size_t j = 0; j < s.x.size() && j < s.y.size(); ++j)
          {
            if (std::isfinite(s.x[j]) && std::isfinite(s.y[j]))
              out << s.x[j] << ' ' << s.y[j] << '\n';
            else
              out << '\n'; // a gap in the line
          }
        plot_cmd += (i ? ", " : "") + quote(data.string()) + " using 1:2 with " + s.style +
                    " " + s.options + " title " + quote(s.title);
      }
    if (spec.series.empty())
      plot_cmd += "NaN notitle";
    script << plot_cmd << "\nunset output\n";

    const fs::path script_file = dir / "plot.gp";
    {
      std::ofstream out(script_file);
      out << script.str();
    }
    const std::string cmd =
      "gnuplot " + quote(script_file.string()) + " > " + quote((dir / "log").string()) + " 2>&1";
    const int status = std::system(cmd.c_str());
    std::error_code ec;
    if (status != 0 || !fs::exists(tmp_png))
      {
        std::ifstream     log(dir / "log");
        std::stringstream ls;
        ls << log.rdbuf();
        fs::remove(tmp_png, ec);
        fs::remove_all(dir, ec);
        std::cerr << "warning: gnuplot failed for " << png_path << ": " << ls.str() << "\n";
        return false;
      }
    commit_external_file(tmp_png, png_path);
    fs::remove_all(dir, ec);
    return true;
  }
} // namespace wearlink
