// SPDX-License-Identifier: LGPL-2.1-or-later
// `wearlink lyapunov SERIES.csv --column NAME ...`: the largest Lyapunov exponent of one
// column of a CSV file by Wolf et al. 1985 or Rosenstein et al. 1993 (REFERENCE.md §6,
// analysis/lyapunov.h), with the delay and embedding dimension given or chosen by
// mutual information and false nearest neighbours (analysis/embedding.h). Prints the
// exponent with its units and the embedding used, and writes a convergence plot (PNG)
// with the plotted data (CSV) and a JSON summary, all atomically.
#include "analysis/lyapunov.h"

#include "app/command_line.h"
#include "base/atomic_file.h"
#include "base/exceptions.h"
#include "base/json.h"
#include "base/text.h"
#include "io/lyapunov_report.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <optional>
#include <sstream>

namespace wearlink::app
{
  namespace
  {
    using namespace wearlink::analysis;

    /** Fewest samples the command accepts; the methods may need more (they say so). */
    constexpr std::size_t min_series_length = 100;
    /** Largest relative deviation of a time step from the mean step [-]. */
    constexpr double time_step_tolerance = 1e-3;

    const char *const help_text = R"(wearlink lyapunov SERIES.csv --column NAME [options]

Largest Lyapunov exponent (LLE) of one column of a CSV file (first row: column names,
comma-separated; lines starting with # are ignored).

Methods (--method):
  rosenstein  (default) Rosenstein, Collins & De Luca 1993: every reference point
              gets its nearest neighbour once; the mean over pairs of ln(separation
              after k samples) grows linearly with slope LLE until it saturates. The
              slope is fitted over a linear region chosen automatically ("straightest
              rise": the window where the local slope of the curve, smoothed over one
              orbit = 4 delays, varies by less than 20 % and the curve rises most); the
              region is printed and drawn. If the curve rises less than e-fold there is
              no exponential divergence and the fit spans the whole curve (LLE ~ 0).
              Neighbours of a sampled flow are followed between samples by linear
              interpolation (automatic; off for map-like series).
  wolf        Wolf, Swift, Swinney & Vastano 1985, fixed evolution time: follow one
              neighbour for E samples, add ln(d_E/d_0), replace it by a nearby point
              whose separation keeps the old orientation (smallest angle among the 64
              nearest points within 5 % of the attractor extent; angle limit 0.3 rad,
              widened if needed), repeat. LLE = sum / total evolution time. Needs dense
              data: about 1e5 samples for 10 % on the Lorenz attractor.

Options:
  --column NAME      the column to analyse (required)
  --method M         rosenstein | wolf (default rosenstein)
  --dt S             sample interval [s]. Without it, a column named t or time_s gives
                     dt (it must be uniformly sampled); with neither, the exponent is
                     per sample (= per iteration of a map).
  --delay K          delay tau [samples]; default: first minimum of the average mutual
                     information (averaged shifted histograms, 16 bins); if the mutual
                     information decays below 5 % of I(0) without a minimum (a map), 1.
  --embedding M      embedding dimension; default: false nearest neighbours (Kennel et
                     al. 1992, R_tol 15, A_tol 2): the first dimension with < 1 % false.
  --theiler W        Theiler window [samples]: neighbours must be more than W samples
                     apart in time; default m * tau.
  --evolution E      Wolf evolution time [samples]; default 6 tau.
  --horizon K        Rosenstein divergence horizon [samples]; default: until the curve
                     saturates (at most 256 tau).
  --output DIR       output directory (default: the current directory)

Output: the exponent in natural-log units, per second when dt is known (also per sample
and in bits), the delay, dimension and Theiler window with how they were chosen, and in
DIR: lyapunov_<column>_<method>.png (Wolf: running estimate vs evolution time;
Rosenstein: mean log divergence vs time with the fitted line), .csv (the plotted data)
and .json (the summary).

Exit status: 0 success, 2 bad input (missing file, unknown column, NaN or too short
series, bad option value).
)";

    /** One column of a CSV file, and the time column if there is one. */
    struct CsvSeries
    {
      std::vector<double>      values;
      std::vector<double>      time;
      std::string              time_column; ///< "" if none
      std::vector<std::string> columns;
    };

    std::vector<std::string>
    split_row(const std::string &line)
    {
      std::vector<std::string> out;
      std::stringstream        ss(line);
      std::string              field;
      while (std::getline(ss, field, ','))
        out.push_back(trim(field, " \t\r\""));
      if (!line.empty() && line.back() == ',')
        out.push_back("");
      return out;
    }

    /** Parse a whole field as a number; false if it is not one. */
    bool
    parse_number(const std::string &text, double &value)
    {
      if (text.empty())
        return false;
      char *end = nullptr;
      value     = std::strtod(text.c_str(), &end);
      return end == text.c_str() + text.size();
    }

    CsvSeries
    read_csv_column(const std::string &file, const std::string &column)
    {
      std::ifstream in(file);
      if (!in)
        throw InputError("Cannot open the series file '" + file + "': it does not exist or is not readable.");
      CsvSeries   out;
      std::string line;
      std::size_t line_no = 0;
      while (std::getline(in, line))
        {
          ++line_no;
          if (!trim(line, " \t\r\"").empty() && trim(line, " \t\r\"")[0] != '#')
            break;
        }
      out.columns = split_row(line);
      if (out.columns.empty() || (out.columns.size() == 1 && out.columns[0].empty()))
        throw InputError("The series file '" + file +
                         "' is empty; it needs a header row "
                         "with column names and one row per sample.");
      std::string list;
      for (const auto &c : out.columns)
        list += (list.empty() ? "" : ", ") + c;
      const auto it = std::find(out.columns.begin(), out.columns.end(), column);
      if (it == out.columns.end())
        throw InputError("The series file '" + file + "' has no column '" + column + "'. Its columns are: " + list +
                         ". Choose one with --column.");
      const std::size_t col      = it - out.columns.begin();
      std::size_t       time_col = std::numeric_limits<std::size_t>::max();
      for (const char *name : {"t", "time_s"})
        {
          const auto t = std::find(out.columns.begin(), out.columns.end(), name);
          if (t != out.columns.end() && std::size_t(t - out.columns.begin()) != col)
            {
              time_col        = t - out.columns.begin();
              out.time_column = name;
              break;
            }
        }

      while (std::getline(in, line))
        {
          ++line_no;
          const std::string trimmed = trim(line, " \t\r\"");
          if (trimmed.empty() || trimmed[0] == '#')
            continue;
          const std::vector<std::string> fields = split_row(line);
          const std::size_t needed = std::max(col, time_col == std::numeric_limits<std::size_t>::max() ? 0 : time_col);
          if (fields.size() <= needed)
            throw InputError("In '" + file + "', line " + std::to_string(line_no) + " has " +
                             std::to_string(fields.size()) + " fields; the header has " +
                             std::to_string(out.columns.size()) + ".");
          double v = 0.0;
          if (!parse_number(fields[col], v) || !std::isfinite(v))
            throw InputError("In '" + file + "', line " + std::to_string(line_no) + ", column '" + column + "' is '" +
                             fields[col] +
                             "', not a finite number. The Lyapunov exponent needs a complete "
                             "series: remove or repair that sample.");
          out.values.push_back(v);
          if (time_col != std::numeric_limits<std::size_t>::max())
            {
              double t = 0.0;
              if (!parse_number(fields[time_col], t) || !std::isfinite(t))
                throw InputError("In '" + file + "', line " + std::to_string(line_no) + ", the time column '" +
                                 out.time_column + "' is '" + fields[time_col] + "', not a finite number.");
              out.time.push_back(t);
            }
        }
      return out;
    }

    /** dt from a time column; InputError if it is not uniformly increasing. */
    double
    sample_interval_from_time(const CsvSeries &s, const std::string &file)
    {
      const std::size_t n  = s.time.size();
      const double      dt = (s.time.back() - s.time.front()) / (n - 1);
      if (!(dt > 0.0))
        throw InputError("In '" + file + "', the time column '" + s.time_column +
                         "' does not increase; give the sample interval with --dt.");
      for (std::size_t i = 1; i < n; ++i)
        if (std::abs(s.time[i] - s.time[i - 1] - dt) > time_step_tolerance * dt)
          throw InputError("In '" + file + "', the time column '" + s.time_column +
                           "' is not uniformly sampled: step " + std::to_string(i) + " is " +
                           std::to_string(s.time[i] - s.time[i - 1]) + " s, the mean step " + std::to_string(dt) +
                           " s. Resample the series at a fixed interval "
                           "(or give --dt if the time column is only approximate).");
      return dt;
    }

    /** A non-negative integer option (at least @p min), or unset. */
    template <class T>
    std::optional<T>
    integer_option(const ParsedArguments &args, const std::string &option, const long min)
    {
      if (!args.has(option))
        return std::nullopt;
      const std::string text = args.value(option);
      std::size_t       used = 0;
      long              v    = 0;
      try
        {
          v = std::stol(text, &used);
        }
      catch (const std::exception &)
        {
          used = 0;
        }
      if (text.empty() || used != text.size() || v < min)
        throw InputError("The option " + option + " needs a whole number >= " + std::to_string(min) + ", not '" + text +
                         "'.");
      return static_cast<T>(v);
    }

    std::string
    safe_name(const std::string &s)
    {
      std::string out;
      for (const char c : s)
        out += std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' ? c : '_';
      return out.empty() ? "series" : out;
    }

    int
    run(const std::vector<std::string> &argv)
    {
      const ParsedArguments args = parse_arguments(argv,
                                                   {{"--column", true},
                                                    {"--method", true},
                                                    {"--dt", true},
                                                    {"--delay", true},
                                                    {"--embedding", true},
                                                    {"--theiler", true},
                                                    {"--evolution", true},
                                                    {"--horizon", true},
                                                    {"--output", true}},
                                                   "lyapunov");
      if (args.positional.size() != 1)
        throw InputError("`wearlink lyapunov` needs exactly one series file (CSV), got " +
                         std::to_string(args.positional.size()) +
                         ". Usage: wearlink lyapunov SERIES.csv --column NAME (see --help).");
      const std::string file = args.positional[0];
      if (!args.has("--column"))
        throw InputError("`wearlink lyapunov` needs --column NAME: the column of '" + file + "' to analyse.");
      const std::string column = args.value("--column");

      LyapunovSettings  settings;
      const std::string method = args.value("--method", "rosenstein");
      if (const auto m = parse_method(method))
        settings.method = *m;
      else
        throw InputError("Unknown --method '" + method + "'. The methods are: rosenstein, wolf.");
      settings.embedding.delay          = integer_option<std::size_t>(args, "--delay", 1);
      settings.embedding.dimension      = integer_option<unsigned int>(args, "--embedding", 1);
      settings.embedding.theiler_window = integer_option<std::size_t>(args, "--theiler", 0);
      settings.wolf.evolution_steps     = integer_option<std::size_t>(args, "--evolution", 1);
      settings.rosenstein.horizon       = integer_option<std::size_t>(args, "--horizon", 2);
      if (settings.embedding.dimension && *settings.embedding.dimension > 64)
        throw InputError("The option --embedding must be at most 64.");
      std::string dt_source = "none: exponent per sample";
      if (args.has("--dt"))
        {
          const double dt = args.number("--dt", 0.0);
          if (!(dt > 0.0))
            throw InputError("The option --dt is the sample interval in seconds and must be > 0, not " +
                             args.value("--dt") + ".");
          settings.sample_interval = dt;
          dt_source                = "--dt";
        }
      const std::string output_dir = args.value("--output", ".");

      const CsvSeries series = read_csv_column(file, column);
      if (series.values.size() < min_series_length)
        throw InputError("The column '" + column + "' of '" + file + "' has " + std::to_string(series.values.size()) +
                         " samples; the Lyapunov "
                         "exponent needs at least " +
                         std::to_string(min_series_length) + " (in practice thousands).");
      if (!settings.sample_interval && !series.time_column.empty())
        {
          settings.sample_interval = sample_interval_from_time(series, file);
          dt_source                = "column '" + series.time_column + "'";
        }

      LyapunovEstimate est;
      try
        {
          est = estimate_largest_lyapunov_exponent(series.values, settings);
        }
      catch (const InputError &e)
        {
          throw InputError("Column '" + column + "' of '" + file + "': " + e.message());
        }

      // Report.
      const auto       &emb  = est.embedding;
      const double      dt   = est.sample_interval.value_or(1.0);
      const std::string tu   = est.sample_interval ? " s" : " samples";
      auto              time = [&](const std::size_t samples) {
        return est.sample_interval ? " (" + format_number(samples * dt, 4) + " s)" : std::string();
      };
      std::ostringstream report;
      report << "wearlink lyapunov: '" << file << "', column '" << column << "', " << series.values.size()
             << " samples, dt " << (est.sample_interval ? format_number(dt, 6) + " s" : std::string("unknown")) << " ("
             << dt_source << ")\n";
      report << "  delay tau            " << emb.embedding.delay << " samples" << time(emb.embedding.delay) << "  ["
             << (emb.delay_choice ? describe(emb.delay_choice->rule) : "given by --delay") << "]\n";
      report << "  embedding dimension  " << emb.embedding.dimension << "  [";
      if (emb.dimension_choice)
        {
          report << "false nearest neighbours:";
          for (std::size_t d = 0; d < emb.dimension_choice->false_fraction.size(); ++d)
            report << " m=" << d + 1 << ": " << format_number(100 * emb.dimension_choice->false_fraction[d], 3) << "%";
          report << (emb.dimension_choice->below_threshold ? "; first below 1%" : "; none below 1%, smallest taken");
        }
      else
        report << "given by --embedding";
      report << "]\n";
      report << "  Theiler window       " << emb.theiler_window << " samples" << time(emb.theiler_window) << "  ["
             << (settings.embedding.theiler_window ? "given by --theiler" : "default m * tau") << "]\n";
      report << "  method               " << method_name(est.method)
             << (est.method == LyapunovMethod::wolf ? " (Wolf et al. 1985, fixed evolution time)" :
                                                      " (Rosenstein et al. 1993)")
             << "\n";
      if (est.wolf)
        report << "  evolution time       " << est.wolf->evolution_steps << " samples"
               << time(est.wolf->evolution_steps) << ", " << est.wolf->n_segments
               << " segments, mean replacement angle " << format_number(est.wolf->mean_replacement_angle, 3) << " rad, "
               << est.wolf->n_kept_neighbours << " without replacement\n";
      if (est.rosenstein)
        {
          const auto &r = *est.rosenstein;
          report << "  fit region           samples " << r.fit_begin << " .. " << r.fit_end;
          if (est.sample_interval)
            report << " (" << format_number(r.fit_begin * dt, 4) << " .. " << format_number(r.fit_end * dt, 4) << " s)";
          report << "  [" << r.fit_rule << "; rms residual " << format_number(r.fit_residual, 3) << "]\n  "
                 << r.n_references << " reference points, horizon " << r.mean_log_divergence.size() - 1 << " samples"
                 << (r.saturated ? ", divergence saturated" : ", no saturation within the horizon")
                 << (r.interpolated ? ", neighbours interpolated between samples" : "") << "\n";
        }
      const double per_sample = est.exponent_per_sample;
      report << "  largest Lyapunov exponent " << format_number(est.exponent(), 5) << " "
             << (est.sample_interval ? "1/s" : "1/sample") << " (natural log";
      if (est.sample_interval)
        report << "; = " << format_number(per_sample, 5)
               << " per sample; = " << format_number(est.exponent() / std::log(2.0), 5) << " bits/s)\n";
      else
        report << ", per sample = per iteration; = " << format_number(per_sample / std::log(2.0), 5)
               << " bits/sample)\n";

      // Outputs: data first (all computed above), each file atomically.
      make_output_directory(output_dir);
      const std::string stem =
        (std::filesystem::path(output_dir) / ("lyapunov_" + safe_name(column) + "_" + method_name(est.method)))
          .string();
      const bool plotted = io::write_lyapunov_curve(est, column, stem);

      Json summary                      = Json::object();
      summary["file"]                   = file;
      summary["column"]                 = column;
      summary["n_samples"]              = series.values.size();
      summary["method"]                 = method_name(est.method);
      summary["sample_interval_s"]      = est.sample_interval ? Json(dt) : Json();
      summary["delay_samples"]          = emb.embedding.delay;
      summary["embedding_dimension"]    = emb.embedding.dimension;
      summary["theiler_window_samples"] = emb.theiler_window;
      summary["exponent"]               = est.exponent();
      summary["exponent_unit"]          = est.sample_interval ? "1/s (natural log)" : "1/sample (natural log)";
      summary["exponent_per_sample"]    = per_sample;
      if (est.rosenstein)
        {
          summary["fit_begin_samples"] = est.rosenstein->fit_begin;
          summary["fit_end_samples"]   = est.rosenstein->fit_end;
          summary["fit_rule"]          = est.rosenstein->fit_rule;
        }
      if (est.wolf)
        summary["evolution_samples"] = est.wolf->evolution_steps;
      write_file_atomically(stem + ".json", summary.dump(2) + "\n");

      report << "  wrote " << stem << ".csv, " << stem << ".json"
             << (plotted ? ", " + stem + ".png" : std::string(" (no PNG: gnuplot missing)")) << "\n";
      std::cout << report.str();
      return 0;
    }
  } // namespace

  extern const Command lyapunov_command;
  const Command        lyapunov_command = {
           "lyapunov",
           "lyapunov SERIES.csv --column NAME [--method wolf|rosenstein] [--dt S] [--embedding M] "
                  "[--delay K] [--output DIR]",
           help_text,
           run};
} // namespace wearlink::app
