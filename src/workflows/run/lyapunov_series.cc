// SPDX-License-Identifier: LGPL-2.1-or-later
#include "workflows/run/lyapunov_series.h"

#include "base/atomic_file.h"
#include "base/exceptions.h"
#include "base/json.h"
#include "base/text.h"
#include "io/csv_series.h"
#include "io/lyapunov_report.h"

#include <cctype>
#include <cmath>
#include <filesystem>
#include <sstream>

namespace wearlink::workflows
{
  namespace
  {
    using namespace wearlink::analysis;

    std::string
    safe_name(const std::string &s)
    {
      std::string out;
      for (const char c : s)
        out += std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' ? c : '_';
      return out.empty() ? "series" : out;
    }


    /** How the exponent was obtained: embedding, method, fit, value. */
    std::string
    describe(const LyapunovEstimate &est,
             const LyapunovSettings &settings,
             const io::CsvSeries    &series,
             const std::string      &file,
             const std::string      &column,
             const std::string      &dt_source)
    {
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

      return report.str();
    }

    /** lyapunov_<column>_<method>.json: the figures. */
    void
    write_summary(const std::string      &stem,
                  const LyapunovEstimate &est,
                  const std::string      &file,
                  const std::string      &column,
                  const std::size_t       n_samples)
    {
      const auto  &emb                  = est.embedding;
      const double dt                   = est.sample_interval.value_or(1.0);
      const double per_sample           = est.exponent_per_sample;
      Json         summary              = Json::object();
      summary["file"]                   = file;
      summary["column"]                 = column;
      summary["n_samples"]              = n_samples;
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
    }
  } // namespace

  std::string
  analyse_lyapunov_series(const LyapunovSeriesRequest &request)
  {
    const std::string  &file      = request.file;
    const std::string  &column    = request.column;
    LyapunovSettings    settings  = request.settings;
    std::string         dt_source = settings.sample_interval ? "--dt" : "none: exponent per sample";
    const io::CsvSeries series    = io::read_csv_column(file, column);
    if (series.values.size() < min_lyapunov_samples)
      throw InputError("The column '" + column + "' of '" + file + "' has " + std::to_string(series.values.size()) +
                       " samples; the Lyapunov exponent needs at least " + std::to_string(min_lyapunov_samples) +
                       " (in practice thousands).");
    if (!settings.sample_interval && !series.time_column.empty())
      {
        settings.sample_interval = io::sample_interval_from_time(series, file);
        dt_source                = "column '" + series.time_column + "'";
      }
    LyapunovEstimate est;
    try
      {
        est = estimate_largest_lyapunov_exponent(series.values, settings);
      }
    catch (const Error &e) // InputError (settings) or EstimationError (this series): the user's file
      {
        throw InputError("Column '" + column + "' of '" + file + "': " + e.message());
      }

    std::string report = describe(est, settings, series, file, column, dt_source);

    // Outputs: data first (all computed above), each file atomically.
    make_output_directory(request.output_directory);
    const std::string stem = (std::filesystem::path(request.output_directory) /
                              ("lyapunov_" + safe_name(column) + "_" + method_name(est.method)))
                               .string();
    const bool plotted = io::write_lyapunov_curve(est, column, stem);
    write_summary(stem, est, file, column, series.values.size());
    report += "  wrote " + stem + ".csv, " + stem + ".json" +
              (plotted ? ", " + stem + ".png" : std::string(" (no PNG: gnuplot missing)")) + "\n";
    return report;
  }
} // namespace wearlink::workflows
