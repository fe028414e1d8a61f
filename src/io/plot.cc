// SPDX-License-Identifier: LGPL-2.1-or-later
#include "io/plot.h"

#include "base/atomic_file.h"
#include "base/exceptions.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <unistd.h>

namespace wearlink::io
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

  namespace
  {
    /** The gnuplot commands of one plot (one panel), data files written into @p dir. */
    std::string
    panel_script(const PlotSpec &spec, const std::filesystem::path &dir, const std::string &prefix)
    {
      namespace fs = std::filesystem;
      std::ostringstream script;
      script << "reset\n"
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
          const auto    &s    = spec.series[i];
          const fs::path data = dir / (prefix + "series" + std::to_string(i) + ".dat");
          std::ofstream  out(data);
          out << std::setprecision(12);
          for (std::size_t j = 0; j < s.x.size() && j < s.y.size(); ++j)
            {
              if (std::isfinite(s.x[j]) && std::isfinite(s.y[j]))
                out << s.x[j] << ' ' << s.y[j] << '\n';
              else
                out << '\n'; // a gap in the line
            }
          plot_cmd += (i ? ", " : "") + quote(data.string()) + " using 1:2 with " + s.style + " " + s.options +
                      " title " + quote(s.title);
        }
      if (spec.series.empty())
        plot_cmd += "NaN notitle";
      script << plot_cmd << "\n";
      return script.str();
    }

    /**
     * Run gnuplot on the commands @p body returns (the panels; their data files go into
     * the directory it is given) with a PNG terminal of the given size, into a temporary
     * name, then rename to @p png_path.
     */
    bool
    render(const std::string                                                  &png_path,
           const int                                                           width,
           const int                                                           height,
           const std::function<std::string(const std::filesystem::path &dir)> &body)
    {
      namespace fs = std::filesystem;
      if (!gnuplot_available())
        {
          std::cerr << "warning: gnuplot is not installed; skipping plot " << png_path
                    << " (apt-get install gnuplot-nox)\n";
          return false;
        }
      const TemporaryDirectory scratch("plot");
      const fs::path           dir     = scratch.path();
      const std::string        tmp_png = temporary_name_for(png_path);
      std::ostringstream       script;
      script << "set terminal pngcairo size " << width << "," << height << " enhanced font 'Sans,11'\n"
             << "set output " << quote(tmp_png) << "\n"
             << body(dir) << "unset output\n";
      const fs::path script_file = dir / "plot.gp";
      {
        std::ofstream out(script_file);
        out << script.str();
      }
      const std::string cmd =
        "gnuplot " + quote(script_file.string()) + " > " + quote((dir / "log").string()) + " 2>&1";
      const int       status = std::system(cmd.c_str());
      std::error_code ec;
      if (status != 0 || !fs::exists(tmp_png))
        {
          std::ifstream     log(dir / "log");
          std::stringstream ls;
          ls << log.rdbuf();
          fs::remove(tmp_png, ec);
          std::cerr << "warning: gnuplot failed for " << png_path << ": " << ls.str() << "\n";
          return false;
        }
      commit_external_file(tmp_png, png_path);
      return true;
    }
  } // namespace

  bool
  plot_png(const PlotSpec &spec, const std::string &png_path)
  {
    return render(png_path, spec.width, spec.height, [&](const std::filesystem::path &dir) {
      return panel_script(spec, dir, "");
    });
  }

  bool
  plot_panels_png(const std::vector<PlotSpec> &panels,
                  const unsigned int           columns,
                  const std::string           &title,
                  const std::string           &png_path,
                  const int                    width,
                  const int                    height)
  {
    const unsigned int n    = static_cast<unsigned int>(panels.size());
    const unsigned int cols = std::max(1u, std::min(columns, n));
    const unsigned int rows = std::max(1u, (n + cols - 1) / cols);
    return render(png_path, width, height, [&](const std::filesystem::path &dir) {
      std::ostringstream s;
      s << "set multiplot layout " << rows << "," << cols << " title " << quote(title) << " noenhanced\n";
      for (unsigned int i = 0; i < n; ++i)
        s << panel_script(panels[i], dir, "p" + std::to_string(i) + "_");
      s << "unset multiplot\n";
      return s.str();
    });
  }
} // namespace wearlink::io
