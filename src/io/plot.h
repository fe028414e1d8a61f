// SPDX-License-Identifier: LGPL-2.1-or-later
// PNG plots through Debian's gnuplot (gnuplot-nox). A plot is data (series) plus how to
// draw it in words (a line or points, a colour, a dash, ranges, where the key goes);
// this module alone speaks gnuplot. plot_png() writes the data and the script to a
// temporary directory, renders to a temporary PNG and renames it into place. If gnuplot
// is not installed the plot is skipped with a warning on stderr (the CSV beside it
// still holds the data).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace wearlink::io
{
  /** What a series draws at its points. */
  enum class Mark
  {
    line,        ///< joined by straight lines
    points,      ///< markers only
    line_points, ///< both
    steps,       ///< a histogram outline (each value a step centred on its x)
    area         ///< the series as a closed polygon, filled with its colour, mostly transparent
  };

  enum class Dash
  {
    solid,
    dashed,
    dotted
  };

  /** Marker shapes; numbered() picks the n-th shape of the sequence (one series per row of a study). */
  enum class Marker
  {
    automatic,
    open_square,
    filled_square,
    open_circle,
    filled_circle,
    filled_triangle,
    filled_diamond
  };

  /** How a series is drawn. */
  struct Look
  {
    Mark        mark  = Mark::line;
    double      width = 0; ///< line width; 0: the default
    Dash        dash  = Dash::solid;
    std::string colour;      ///< "#rrggbb" or a colour name; empty: the automatic sequence
    unsigned    palette = 0; ///< > 0: the palette-th colour of the automatic sequence (to pair series)
    Marker      marker  = Marker::automatic;
    unsigned    shape   = 0; ///< > 0: the shape-th marker of the sequence (overrides marker)
    double      size    = 0; ///< marker size; 0: the default

    Look &
    dashed()
    {
      dash = Dash::dashed;
      return *this;
    }
    Look &
    dotted()
    {
      dash = Dash::dotted;
      return *this;
    }
  };

  /**
   * The points of a line over x that a plot @p columns pixels wide can show (its "M4"
   * envelope), as indices into @p x and @p y: per bin of half a pixel across the data's x
   * range, the first, lowest, highest and last point, in their order. The line through
   * them covers the pixels the line through all points covers (50 000 samples of a
   * 100-cycle history become ~4 per bin, drawn ten times faster). Every index if the line
   * is short (≤ 8 points per bin), its x decreases somewhere, a value is not finite, or
   * @p columns ≤ 0.
   */
  std::vector<std::size_t>
  line_envelope(const std::vector<double> &x, const std::vector<double> &y, int columns);

  /** A line of @p colour (empty: automatic) and @p width (0: default). */
  Look
  line(const std::string &colour = "", double width = 0);

  /** Markers of @p colour and @p size (0: default), filled circles unless @p marker says otherwise. */
  Look
  points(const std::string &colour = "", double size = 0, Marker marker = Marker::filled_circle);

  /** A line of the @p n-th colour of the automatic sequence (n ≥ 1), to give a pair of series one colour. */
  Look
  palette_line(unsigned n, double width = 0);

  /** @p look with the @p n-th marker shape of gnuplot's sequence (one series per row of a study). */
  Look
  numbered_shape(Look look, unsigned n);

  /** A line with markers. */
  Look
  line_points(const std::string &colour = "", double width = 0, Marker marker = Marker::filled_circle, double size = 0);

  struct PlotSeries
  {
    std::string         title;
    std::vector<double> x;
    std::vector<double> y;
    Look                look;
  };

  /** An interval of an axis; a bound that is NaN is left to the data. */
  struct Range
  {
    double low  = 0;
    double high = 0;
  };

  /** Where the key (the series' titles) goes. */
  enum class KeyPlace
  {
    outside_right, ///< right of the plot, at the top (the default)
    below,         ///< under the plot
    inside_top_right,
    inside_top_left,     ///< boxed, opaque
    inside_bottom_right, ///< boxed, opaque
    none                 ///< no key
  };

  /** A horizontal band across the plot (low … high) with a dashed line at @p line and a label above it. */
  struct Band
  {
    double      low  = 0;
    double      high = 0;
    double      line = 0;
    std::string label;
  };

  struct PlotSpec
  {
    std::string             title;
    std::string             x_label;
    std::string             y_label;
    std::vector<PlotSeries> series;
    bool                    log_x = false;
    bool                    log_y = false;
    /** Label logarithmic axes as powers of ten (10^k). */
    bool powers_of_ten = false;
    /** Equal scales on both axes (profiles, trajectories). */
    bool equal_axes = false;
    /** Polar plot: x is the angle [rad], y the radius. */
    bool polar = false;
    /** Polar plot: the radius shown (0: the data's). */
    double               polar_reach = 0;
    std::optional<Range> x_range, y_range;
    /** Spacing of the x tics; 0: automatic. */
    double x_tic_step = 0;
    /** Names of the x positions 0, 1, …, n − 1 (names of more than 12 characters turned, with room below). */
    std::vector<std::string> categories;
    /** Names of the y positions 0, 1, …, n − 1 (room on the left for the longest). */
    std::vector<std::string> y_categories;
    /** The y axis follows the data, but not beyond these bounds. */
    std::optional<Range> y_limits;
    KeyPlace             key = KeyPlace::outside_right;
    std::optional<Band>  band;
    int                  width  = 1000;
    int                  height = 700;
  };

  /** Render @p spec to @p png_path. Returns false (and warns) if gnuplot is missing. */
  bool
  plot_png(const PlotSpec &spec, const std::string &png_path);

  /**
   * Several plots in one PNG (gnuplot multiplot), @p columns per row, under a common
   * @p title; each panel keeps its own labels and ranges (to put panels on the same
   * scale). Returns false (and warns) if gnuplot is missing.
   */
  bool
  plot_panels_png(const std::vector<PlotSpec> &panels,
                  unsigned int                 columns,
                  const std::string           &title,
                  const std::string           &png_path,
                  int                          width  = 1600,
                  int                          height = 700);

  /**
   * A field over a rectangle drawn as colours: z[j][i] at (x[i], y[j]) (nonuniform
   * spacing allowed), the colour bar labelled @p z_label.
   */
  struct HeatMap
  {
    std::string                      title, x_label, y_label, z_label;
    std::vector<double>              x, y;
    std::vector<std::vector<double>> z; ///< one row per y
    int                              width = 1100, height = 600;
    double                           z_max = 0; ///< > 0: the colour scale's top (a series shares one scale)
  };

  /** Render @p map to @p png_path. Returns false (and warns) if gnuplot is missing. */
  bool
  plot_heat_map_png(const HeatMap &map, const std::string &png_path);

  /** True if a gnuplot executable is on PATH. */
  bool
  gnuplot_available();
} // namespace wearlink::io
