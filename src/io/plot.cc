// SPDX-License-Identifier: LGPL-2.1-or-later
#include "io/plot.h"

#include "base/atomic_file.h"
#include "base/exceptions.h"
#include "base/text.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <numeric>
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

  Look
  line(const std::string &colour, const double width)
  {
    Look l;
    l.colour = colour;
    l.width  = width;
    return l;
  }

  Look
  points(const std::string &colour, const double size, const Marker marker)
  {
    Look l;
    l.mark   = Mark::points;
    l.colour = colour;
    l.size   = size;
    l.marker = marker;
    return l;
  }

  Look
  palette_line(const unsigned n, const double width)
  {
    Look l    = line("", width);
    l.palette = n;
    return l;
  }

  Look
  numbered_shape(Look look, const unsigned n)
  {
    look.shape = n;
    return look;
  }

  Look
  line_points(const std::string &colour, const double width, const Marker marker, const double size)
  {
    Look l   = line(colour, width);
    l.mark   = Mark::line_points;
    l.marker = marker;
    l.size   = size;
    return l;
  }

  namespace
  {
    /**
     * Points a long solid line is drawn in pieces of. Cairo strokes one path as one
     * polygon, whose cost grows with the path's self-intersections: a 100-cycle orbit
     * (50 000 points crossing each other in a 1 mm circle) took 1.8 s to draw whole and
     * 0.9 s in pieces of 16, which look the same (each piece starts where the last ended).
     */
    constexpr std::size_t stroke_piece = 16;

    /**
     * The (x, y) rows gnuplot reads for @p s in a plot @p columns pixels wide: a blank
     * line is a gap (a value not finite).
     */
    void
    write_series_data(const PlotSeries &s, const int columns, std::ofstream &out)
    {
      const auto  points = line_envelope(s.x, s.y, s.look.mark == Mark::line ? columns : 0);
      const bool  pieces = s.look.mark == Mark::line && s.look.dash == Dash::solid && points.size() > 64 * stroke_piece;
      std::string text, last;
      std::size_t run = 0; // points of the current piece
      for (const auto j : points)
        {
          if (!std::isfinite(s.x[j]) || !std::isfinite(s.y[j]))
            {
              text += '\n'; // a gap in the line
              run = 0;
              continue;
            }
          std::string point;
          append_number(point, s.x[j], 12);
          point += ' ';
          append_number(point, s.y[j], 12);
          point += '\n';
          if (pieces && run == stroke_piece)
            {
              text += '\n' + last; // a new path from the last point
              run = 1;
            }
          text += point;
          ++run;
          last = std::move(point);
        }
      out << text;
    }

    /** gnuplot's "with ..." of a series drawn as @p l. */
    std::string
    with_clause(const Look &l)
    {
      std::ostringstream s;
      switch (l.mark)
        {
          case Mark::line:
            s << "lines";
            break;
          case Mark::points:
            s << "points";
            break;
          case Mark::line_points:
            s << "linespoints";
            break;
          case Mark::steps:
            s << "histeps";
            break;
          case Mark::area:
            s << "filledcurves closed fs transparent solid 0.25 noborder";
            break;
        }
      if (l.width > 0)
        s << " lw " << l.width;
      if (l.dash == Dash::dashed)
        s << " dt 2";
      else if (l.dash == Dash::dotted)
        s << " dt 3";
      // gnuplot's point types: 4 open square, 5 filled square, 6 open circle, 7 filled
      // circle, 9 filled triangle, 13 filled diamond.
      const bool marks = l.mark == Mark::points || l.mark == Mark::line_points;
      if (marks && l.shape > 0)
        s << " pt " << l.shape;
      else if (marks && l.marker != Marker::automatic)
        s << " pt "
          << (l.marker == Marker::open_square     ? 4 :
              l.marker == Marker::filled_square   ? 5 :
              l.marker == Marker::open_circle     ? 6 :
              l.marker == Marker::filled_circle   ? 7 :
              l.marker == Marker::filled_triangle ? 9 :
                                                    13);
      if (l.size > 0)
        s << " ps " << l.size;
      if (!l.colour.empty())
        s << " lc rgb '" << l.colour << "'";
      else if (l.palette > 0)
        s << " lc " << l.palette;
      return s.str();
    }

    std::string
    range(const Range &r)
    {
      std::ostringstream s;
      s << std::setprecision(10) << "[";
      if (std::isfinite(r.low))
        s << r.low;
      else
        s << "*";
      s << ":";
      if (std::isfinite(r.high))
        s << r.high;
      else
        s << "*";
      s << "]";
      return s.str();
    }

    const char *
    key_place(const KeyPlace k)
    {
      switch (k)
        {
          case KeyPlace::below:
            return "below";
          case KeyPlace::inside_top_right:
            return "top right inside";
          case KeyPlace::inside_top_left:
            return "inside left top box opaque";
          case KeyPlace::inside_bottom_right:
            return "inside bottom right box opaque";
          case KeyPlace::none:
            return "off";
          case KeyPlace::outside_right:
            break;
        }
      return "outside right top";
    }

    /** Ranges, tics, categories and the band of @p spec. */
    std::string
    axes_script(const PlotSpec &spec)
    {
      std::ostringstream s;
      if (spec.powers_of_ten && spec.log_x)
        s << "set format x '10^{%L}'\n";
      if (spec.powers_of_ten && spec.log_y)
        s << "set format y '10^{%L}'\n";
      if (spec.polar && spec.polar_reach > 0)
        s << std::setprecision(10) << "set rrange [0:" << spec.polar_reach << "]\nset xrange [" << -spec.polar_reach
          << ":" << spec.polar_reach << "]\nset yrange [" << -spec.polar_reach << ":" << spec.polar_reach << "]\n";
      if (spec.x_range)
        s << "set xrange " << range(*spec.x_range) << "\n";
      if (spec.y_range)
        s << "set yrange " << range(*spec.y_range) << "\n";
      else if (spec.y_limits)
        s << std::setprecision(10) << "set yrange [" << spec.y_limits->low << "<*:*<" << spec.y_limits->high << "]\n";
      if (spec.x_tic_step > 0)
        s << "set xtics " << spec.x_tic_step << "\n";
      if (!spec.categories.empty())
        {
          // Names longer than a tic's room are turned, with room below for them.
          std::size_t longest = 0;
          for (const auto &c : spec.categories)
            longest = std::max(longest, c.size());
          const bool turn = longest > 12;
          s << "set xtics " << (turn ? "rotate by -40 " : "") << "noenhanced (";
          for (std::size_t i = 0; i < spec.categories.size(); ++i)
            s << (i ? ", " : "") << quote(spec.categories[i]) << " " << i;
          s << ")\n" << (turn ? "set bmargin 14\n" : "");
        }
      if (!spec.y_categories.empty())
        {
          std::size_t margin = 10; // characters: the longest name and a gap
          s << "set ytics noenhanced (";
          for (std::size_t i = 0; i < spec.y_categories.size(); ++i)
            {
              s << (i ? ", " : "") << quote(spec.y_categories[i]) << " " << i;
              margin = std::max(margin, spec.y_categories[i].size() + 2);
            }
          s << ")\nset lmargin " << margin << "\n";
        }
      if (spec.band)
        {
          const Band &b = *spec.band;
          s << std::setprecision(6) << "set object 1 rect from graph 0, first " << b.low << " to graph 1, first "
            << b.high << " fc rgb '#d8d8f0' fs solid 1.0 noborder behind\n"
            << "set arrow 1 from graph 0, first " << b.line << " to graph 1, first " << b.line
            << " nohead dt 2 lw 2 lc rgb '#5050a0'\n"
            << "set label 1 " << quote(b.label) << " at graph 0.02, first " << b.high
            << " offset 0, 0.7 font ',10' tc rgb '#5050a0' noenhanced\n";
        }
      return s.str();
    }
  } // namespace

  bool
  gnuplot_available()
  {
    return std::system("command -v gnuplot > /dev/null 2>&1") == 0;
  }

  namespace
  {
    /**
     * Close the scratch file @p out (@p file: a plot's script or data); IoError unless it
     * was written whole. gnuplot would draw a cut data file without a word.
     */
    void
    check_scratch_written(std::ofstream &out, const std::filesystem::path &file)
    {
      out.close();
      if (out.fail())
        throw IoError("Cannot write the plot's scratch file '" + file.string() +
                      "': the temporary directory's disk is full or not writable. Free some space there (or "
                      "set TMPDIR to another folder) and run again.");
    }

    /** The gnuplot commands of one plot (one panel), data files written into @p dir. */
    std::string
    panel_script(const PlotSpec &spec, const int columns, const std::filesystem::path &dir, const std::string &prefix)
    {
      namespace fs = std::filesystem;
      std::ostringstream script;
      script << "reset\n"
             << "set title " << quote(spec.title) << " noenhanced\n"
             << "set xlabel " << quote(spec.x_label) << " noenhanced\n"
             << "set ylabel " << quote(spec.y_label) << " noenhanced\n"
             << "set grid\n";
      if (spec.key == KeyPlace::none)
        script << "unset key\n";
      else
        script << "set key " << key_place(spec.key) << " noenhanced\n";
      if (spec.log_x)
        script << "set logscale x\n";
      if (spec.log_y)
        script << "set logscale y\n";
      if (spec.equal_axes)
        script << "set size ratio -1\n";
      if (spec.polar)
        script << "set polar\nset angles radians\nset size ratio -1\nunset xtics\nunset ytics\n"
                  "set border 0\nset grid polar\n";
      script << axes_script(spec);

      std::string plot_cmd = "plot ";
      for (std::size_t i = 0; i < spec.series.size(); ++i)
        {
          const auto    &s    = spec.series[i];
          const fs::path data = dir / (prefix + "series" + std::to_string(i) + ".dat");
          std::ofstream  out(data);
          write_series_data(s, spec.log_x || spec.x_range || spec.polar ? 0 : columns, out);
          check_scratch_written(out, data);
          plot_cmd += (i ? ", " : "") + quote(data.string()) + " using 1:2 with " + with_clause(s.look) + " title " +
                      quote(s.title);
        }
      if (spec.series.empty())
        plot_cmd += "NaN notitle";
      script << plot_cmd << "\n";
      return script.str();
    }

    /**
     * True if @p path ends with a PNG's closing chunk (IEND and its CRC). gnuplot exits
     * 0 also when the disk filled under it; the image is then cut short.
     */
    bool
    png_is_complete(const std::string &path)
    {
      static const std::string iend("IEND\xae\x42\x60\x82", 8);
      std::ifstream            in(path, std::ios::binary | std::ios::ate);
      const auto               size = static_cast<long>(in.tellg());
      if (!in || size < static_cast<long>(iend.size()))
        return false;
      in.seekg(size - static_cast<long>(iend.size()));
      std::string tail(iend.size(), '\0');
      in.read(tail.data(), static_cast<long>(tail.size()));
      return in && tail == iend;
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
      const fs::path           script_file = dir / "plot.gp";
      try
        {
          script << "set terminal pngcairo size " << width << "," << height << " enhanced font 'Sans,11'\n"
                 << "set output " << quote(tmp_png) << "\n"
                 << body(dir) << "unset output\n";
          std::ofstream out(script_file);
          out << script.str();
          check_scratch_written(out, script_file);
        }
      catch (const IoError &e) // a plot comes after its results: a warning, no PNG
        {
          std::cerr << "warning: " << e.message() << " The plot " << png_path << " is not written.\n";
          return false;
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
      if (!png_is_complete(tmp_png))
        {
          // As any plot gnuplot cannot draw: a warning and no PNG (plots come after the
          // results they show, which are written whole), never a cut image in place.
          fs::remove(tmp_png, ec);
          std::cerr << "warning: gnuplot left the plot " << png_path
                    << " incomplete, as it does when the disk is full or a write fails; it is not written\n";
          return false;
        }
      commit_external_file(tmp_png, png_path);
      return true;
    }
  } // namespace

  std::vector<std::size_t>
  line_envelope(const std::vector<double> &x, const std::vector<double> &y, const int columns)
  {
    const std::size_t        n = std::min(x.size(), y.size());
    std::vector<std::size_t> keep;
    const std::size_t        bins = 2 * static_cast<std::size_t>(std::max(columns, 1));
    bool                     thin = columns > 0 && n > 8 * bins;
    for (std::size_t j = 0; thin && j < n; ++j)
      thin = std::isfinite(x[j]) && std::isfinite(y[j]) && (j == 0 || x[j] >= x[j - 1]);
    if (!thin || !(x[n - 1] > x[0]))
      {
        keep.resize(n);
        std::iota(keep.begin(), keep.end(), std::size_t(0));
        return keep;
      }
    const double width = (x[n - 1] - x[0]) / static_cast<double>(bins);
    const auto   bin   = [&](const std::size_t j) {
      return std::floor((x[j] - x[0]) / width);
    };
    for (std::size_t first = 0; first < n;)
      {
        const double current = bin(first);
        std::size_t  last = first, low = first, high = first;
        while (last + 1 < n && bin(last + 1) == current)
          {
            ++last;
            low  = y[last] < y[low] ? last : low;
            high = y[last] > y[high] ? last : high;
          }
        for (const auto j : {first, std::min(low, high), std::max(low, high), last})
          if (keep.empty() || keep.back() != j)
            keep.push_back(j);
        first = last + 1;
      }
    return keep;
  }

  bool
  plot_png(const PlotSpec &spec, const std::string &png_path)
  {
    return render(png_path, spec.width, spec.height, [&](const std::filesystem::path &dir) {
      return panel_script(spec, spec.width, dir, "");
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
        s << panel_script(panels[i], width / static_cast<int>(cols), dir, "p" + std::to_string(i) + "_");
      s << "unset multiplot\n";
      return s.str();
    });
  }

  bool
  plot_heat_map_png(const HeatMap &map, const std::string &png_path)
  {
    return render(png_path, map.width, map.height, [&](const std::filesystem::path &dir) {
      // gnuplot's nonuniform matrix: a first row of the x values after the count, then
      // one row per y, its y value first.
      const auto    data = dir / "map.dat";
      std::ofstream out(data);
      out << std::setprecision(9) << map.x.size();
      for (const double x : map.x)
        out << ' ' << x;
      out << '\n';
      for (std::size_t j = 0; j < map.y.size(); ++j)
        {
          out << map.y[j];
          for (const double z : map.z[j])
            out << ' ' << z;
          out << '\n';
        }
      check_scratch_written(out, data);
      std::ostringstream script;
      script << "reset\n"
             << "set title " << quote(map.title) << " noenhanced\n"
             << "set xlabel " << quote(map.x_label) << " noenhanced\n"
             << "set ylabel " << quote(map.y_label) << " noenhanced\n"
             << "set cblabel " << quote(map.z_label) << " noenhanced\n"
             << "set palette defined (0 '#ffffff', 1 '#fee391', 2 '#fe9929', 3 '#cc4c02', 4 '#662506')\n"
             << "set autoscale xfix\nset autoscale yfix\nset tics out\n";
      if (map.z_max > 0)
        script << "set cbrange [0:" << map.z_max << "]\n";
      script << "plot " << quote(data.string()) << " nonuniform matrix using 1:2:3 with image notitle\n";
      return script.str();
    });
  }
} // namespace wearlink::io
