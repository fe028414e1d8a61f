// SPDX-License-Identifier: LGPL-2.1-or-later
// PNG plots through Debian's gnuplot (gnuplot-nox). A plot is data (series) plus
// labels; plot_png() writes the data and a gnuplot script to a temporary directory,
// renders to a temporary PNG and renames it into place. If gnuplot is not installed the
// plot is skipped with a warning on stderr (the CSV beside it still holds the data).
#pragma once

#include <string>
#include <vector>

namespace wearlink::io
{
  struct PlotSeries
  {
    std::string         title;
    std::vector<double> x;
    std::vector<double> y;
    /** gnuplot style: "lines", "points", "linespoints", "dots". */
    std::string style = "lines";
    /** Extra gnuplot "with" options, e.g. "pt 7 ps 0.5 lc rgb 'red'". */
    std::string options;
  };

  struct PlotSpec
  {
    std::string             title;
    std::string             x_label;
    std::string             y_label;
    std::vector<PlotSeries> series;
    bool                    log_x = false;
    bool                    log_y = false;
    /** Equal scales on both axes (profiles, trajectories). */
    bool equal_axes = false;
    /** Polar plot: x is the angle [rad], y the radius. */
    bool polar  = false;
    int  width  = 1000;
    int  height = 700;
    /** Extra gnuplot commands, placed before the plot command. */
    std::string extra;
  };

  /** Render @p spec to @p png_path. Returns false (and warns) if gnuplot is missing. */
  bool
  plot_png(const PlotSpec &spec, const std::string &png_path);

  /**
   * Several plots in one PNG (gnuplot multiplot), @p columns per row, under a common
   * @p title; each panel keeps its own labels and its `extra` commands (axis ranges, to
   * put panels on the same scale). Returns false (and warns) if gnuplot is missing.
   */
  bool
  plot_panels_png(const std::vector<PlotSpec> &panels,
                  unsigned int                 columns,
                  const std::string           &title,
                  const std::string           &png_path,
                  int                          width  = 1600,
                  int                          height = 700);

  /** True if a gnuplot executable is on PATH. */
  bool
  gnuplot_available();
} // namespace wearlink::io
