// SPDX-License-Identifier: LGPL-2.1-or-later
#include "workflows/compare/signal_comparison.h"

#include "analysis/signal_analysis.h"
#include "base/atomic_file.h"
#include "base/exceptions.h"
#include "base/text.h"
#include "io/output_names.h"
#include "io/plot.h"
#include "io/scene.h"
#include "io/scene_periods.h"
#include "io/signal_file.h"
#include "workflows/run/run.h"

#include <algorithm>
#include <filesystem>
#include <iomanip>
#include <numeric>
#include <sstream>

namespace wearlink::workflows
{
  namespace
  {
    /** Digits of the printed table. */
    constexpr int signal_digits = 5;
    /** The spectrum plot reaches this many times the highest dominant frequency. */
    constexpr double spectrum_reach = 4.0;

    std::string
    joined(const std::vector<std::string> &names)
    {
      std::string out;
      for (const auto &n : names)
        out += (out.empty() ? "" : ", ") + n;
      return out;
    }

    /** InputError unless a run of @p scene writes the column @p channel. */
    void
    require_channel(const io::Scene &scene, const std::string &channel)
    {
      const auto columns = time_series_columns(scene);
      if (channel.empty())
        throw InputError("Name the simulated signal with --channel: a column of the time_series.csv a run of " +
                         scene.file + " writes, e.g. " + columns[1] + ".");
      if (std::find(columns.begin(), columns.end(), channel) == columns.end() || channel == "time_s")
        throw InputError("--channel '" + channel + "' is not a column of the time_series.csv a run of " + scene.file +
                         " writes. Its columns are: " + joined(columns) + ".");
    }

    /** InputError unless @p measured overlaps the scene's simulated interval. */
    void
    require_overlap(const io::Scene &scene, const io::TimeSignal &measured)
    {
      if (measured.time.back() <= scene.start_time || measured.time.front() >= scene.end_time)
        throw InputError("The measured signal '" + measured.file + "' covers " +
                         format_number(measured.time.front(), 6) + " to " + format_number(measured.time.back(), 6) +
                         " s, outside the simulated interval " + format_number(scene.start_time, 6) + " to " +
                         format_number(scene.end_time, 6) + " s of " + scene.file +
                         ": its column 'time_s' must be in the scene's time.");
    }

    /** The simulated channel: from a finished run, or from a run of @p scene now. */
    io::TimeSignal
    simulated_signal(io::Scene &scene, const SignalComparisonOptions &o)
    {
      const std::string what = "simulated run's time series";
      if (!o.simulated_directory.empty())
        return io::read_time_signal(o.simulated_directory + "/" + io::outputs::time_series,
                                    o.channel,
                                    what,
                                    "--channel");
      RunOptions run;
      run.output_directory    = o.output_directory + "/" + io::outputs::signal_simulated;
      run.progress            = o.progress;
      scene.write_time_series = true;
      run_scene(scene, run);
      return io::read_time_signal(run.output_directory + "/" + io::outputs::time_series, o.channel, what, "--channel");
    }

    Json
    features_json(const analysis::SignalFeatures &f, const std::string &source, const std::string &column)
    {
      Json j                     = Json::object();
      j["source"]                = source;
      j["column"]                = column;
      j["dominant_frequency_Hz"] = f.dominant.empty() ? 0.0 : f.dominant.front().frequency_Hz;
      Json freqs = Json::array(), amps = Json::array();
      for (const auto &p : f.dominant)
        {
          freqs.push_back(p.frequency_Hz);
          amps.push_back(p.amplitude);
        }
      j["dominant_frequencies_Hz"] = freqs;
      j["dominant_amplitudes"]     = amps;
      j["peak_per_cycle"]          = f.peak_per_cycle;
      j["peak_per_cycle_mean"]     = std::accumulate(f.peak_per_cycle.begin(), f.peak_per_cycle.end(), 0.0) /
                                 std::max<std::size_t>(1, f.peak_per_cycle.size());
      j["rms"]  = f.rms;
      j["mean"] = f.mean;
      return j;
    }

    Json
    comparison_json(const analysis::SignalComparison &c,
                    const SignalComparisonOptions    &o,
                    const io::TimeSignal             &simulated,
                    const io::TimeSignal             &measured,
                    const double                      period)
    {
      const auto n            = c.simulated.values.size();
      Json       j            = Json::object();
      j["scene"]              = o.scene_file;
      j["channel"]            = o.channel;
      j["cycle_period_s"]     = period;
      j["grid"]               = {{"t0_s", c.simulated.t0},
                                 {"t1_s", c.simulated.t0 + (n - 1) * c.simulated.dt},
                                 {"dt_s", c.simulated.dt},
                                 {"samples", n},
                                 {"method",
                                  "linear interpolation of both signals onto the interval both cover, at the "
                                                "finer of their median sample intervals"}};
      j["lag_s"]              = c.lag;
      j["correlation_at_lag"] = c.correlation;
      j["simulated"]          = features_json(c.simulated_features, simulated.file, simulated.column);
      j["measured"]           = features_json(c.measured_features, measured.file, measured.column);
      return j;
    }

    std::string
    signal_table(const Json &j)
    {
      std::ostringstream out;
      const auto         row = [&](const std::string &name, const std::string &key) {
        const double s = json_number(j.at("simulated").at(key)), m = json_number(j.at("measured").at(key));
        out << "  " << std::left << std::setw(28) << name << std::right << std::setw(14)
            << format_number(s, signal_digits) << std::setw(14) << format_number(m, signal_digits) << std::setw(14)
            << format_number(m - s, signal_digits) << "\n";
      };
      out << "  " << std::left << std::setw(28) << j.at("channel").get<std::string>() << std::right << std::setw(14)
          << "simulated" << std::setw(14) << "measured" << std::setw(14) << "difference\n";
      row("dominant frequency [Hz]", "dominant_frequency_Hz");
      row("mean peak per cycle", "peak_per_cycle_mean");
      row("rms", "rms");
      row("mean", "mean");
      out << "  cycles: " << j.at("simulated").at("peak_per_cycle").size() << " of "
          << format_number(json_number(j.at("cycle_period_s")), signal_digits)
          << " s; lag of the measured signal: " << format_number(json_number(j.at("lag_s")), signal_digits)
          << " s (correlation " << format_number(json_number(j.at("correlation_at_lag")), 3) << ")\n";
      return out.str();
    }

    io::PlotSpec
    overlay_plot(const analysis::SignalComparison &c, const SignalComparisonOptions &o, const std::string &column)
    {
      io::PlotSpec p;
      p.title   = "Simulated " + o.channel + " against measured " + column;
      p.x_label = "time [s]";
      p.y_label = o.channel;
      p.width   = 1200;
      p.key     = io::KeyPlace::below;
      std::vector<double> t(c.simulated.values.size()), shifted(t.size());
      for (std::size_t i = 0; i < t.size(); ++i)
        {
          t[i]       = c.simulated.t0 + i * c.simulated.dt;
          shifted[i] = t[i] - c.lag;
        }
      p.series = {{"simulated", t, c.simulated.values, io::line("#1f77b4", 1.5)},
                  {"measured", t, c.measured.values, io::line("#d62728", 1.5)},
                  {"measured shifted back by the lag " + format_number(c.lag * 1e3, 4) + " ms",
                   shifted,
                   c.measured.values,
                   io::line("#ff9896").dashed()}};
      return p;
    }

    io::PlotSpec
    spectrum_plot(const analysis::SignalComparison &c, const SignalComparisonOptions &o)
    {
      io::PlotSpec p;
      p.title       = "Amplitude spectra of " + o.channel + " (Hann window)";
      p.x_label     = "frequency [Hz]";
      p.y_label     = "amplitude [unit of the signal]";
      const auto &s = c.simulated_features, &m = c.measured_features;
      p.series   = {{"simulated", s.frequencies_Hz, s.amplitudes, io::line("#1f77b4", 1.5)},
                    {"measured", m.frequencies_Hz, m.amplitudes, io::line("#d62728", 1.5)}};
      double top = 0;
      for (const auto *f : {&s, &m})
        for (const auto &peak : f->dominant)
          top = std::max(top, peak.frequency_Hz);
      if (top > 0)
        p.x_range = io::Range{0, std::min(spectrum_reach * top, s.frequencies_Hz.back())};
      return p;
    }
  } // namespace

  SignalComparisonResult
  compare_signal(const SignalComparisonOptions &o)
  {
    io::Scene scene = io::read_scene(o.scene_file, o.overrides);
    require_channel(scene, o.channel);
    const auto   measured = io::read_time_signal(o.measured_file, o.measured_column, "measured signal", "--column");
    const double period   = io::driving_period_if_known(scene);
    require_overlap(scene, measured);
    if (!o.simulated_directory.empty() && !std::filesystem::is_directory(o.simulated_directory))
      throw InputError("--simulated '" + o.simulated_directory + "' is not a directory (a finished run's folder).");
    if (o.simulated_directory.empty())
      make_output_directory(o.output_directory); // the run goes into OUTPUT/simulated
    const auto simulated = simulated_signal(scene, o);

    analysis::SignalComparisonSettings settings;
    settings.cycle_period = period;
    const auto c =
      analysis::compare_signals(simulated.time, simulated.values, measured.time, measured.values, settings);

    SignalComparisonResult r;
    make_output_directory(o.output_directory);
    r.json                = comparison_json(c, o, simulated, measured, period);
    r.table               = signal_table(r.json);
    const std::string dir = o.output_directory + "/";
    if (io::plot_png(overlay_plot(c, o, measured.column), dir + io::outputs::signal_overlay))
      r.files.push_back(dir + io::outputs::signal_overlay);
    if (io::plot_png(spectrum_plot(c, o), dir + io::outputs::signal_spectrum))
      r.files.push_back(dir + io::outputs::signal_spectrum);
    write_file_atomically(dir + io::outputs::signal_comparison, r.json.dump(2));
    r.files.push_back(dir + io::outputs::signal_comparison);
    return r;
  }
} // namespace wearlink::workflows
