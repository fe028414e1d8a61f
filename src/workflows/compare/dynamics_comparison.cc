// SPDX-License-Identifier: LGPL-2.1-or-later
#include "workflows/compare/dynamics_comparison.h"

#include "analysis/nonlinear_dynamics.h"
#include "base/atomic_file.h"
#include "base/exceptions.h"
#include "base/text.h"
#include "io/output_names.h"
#include "io/plot.h"

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace wearlink::workflows
{
  namespace
  {
    /** Delay in samples of a run for a delay @p seconds; InputError below one sample. */
    std::size_t
    delay_samples(const double seconds, const analysis::RecordedRun &run, const std::string &what)
    {
      const double k = std::round(seconds / run.sample_interval);
      if (k < 1.0)
        throw InputError("The " + what + " delay of " + format_number(seconds, 4) +
                         " s is shorter than the sample interval " + format_number(run.sample_interval, 4) +
                         " s of the " + (run.label.empty() ? std::string("recorded") : run.label) + " run.");
      return static_cast<std::size_t>(k);
    }

    const std::vector<double> &
    channel_values(const analysis::RecordedRun &run, const std::string &channel)
    {
      if (!(run.sample_interval > 0.0))
        throw InputError("The " + run.label + " run recorded no series (list lyapunov or phase-portrait).");
      return run.series.values[run.series.index(channel)];
    }

    /** One exponent at a given embedding; NaN (and the message) if the series does not allow it. */
    struct Estimate
    {
      double      per_s    = std::numeric_limits<double>::quiet_NaN();
      bool        resolved = true;
      std::string note;
    };

    Estimate
    estimate(const analysis::RecordedRun   &run,
             const std::string             &channel,
             const analysis::LyapunovMethod method,
             const double                   delay_s,
             const unsigned int             dimension)
    {
      Estimate                   out;
      analysis::LyapunovSettings ls;
      ls.method              = method;
      ls.sample_interval     = run.sample_interval;
      ls.embedding.delay     = delay_samples(delay_s, run, "embedding");
      ls.embedding.dimension = dimension;
      try
        {
          const auto e = analysis::estimate_largest_lyapunov_exponent(channel_values(run, channel), ls);
          out.per_s    = e.exponent();
          if (e.rosenstein && !e.rosenstein->resolved)
            {
              out.resolved = false;
              out.note     = "unresolved: separation saturates within 2 delays";
            }
        }
      catch (const EstimationError &e)
        {
          out.note = e.message(); // this series at this embedding gives no estimate: a missing value, not an error
        }
      return out;
    }

    /** Peak |a| of body @p b from a run summary (max of the x and y components), NaN if absent. */
    double
    peak_acceleration(const Json &summary, const std::string &b)
    {
      if (summary.is_object() == false || !summary.contains("bodies") || !summary.at("bodies").contains(b))
        return std::numeric_limits<double>::quiet_NaN();
      const Json &x = summary.at("bodies").at(b);
      return std::max(json_number(x.at("max_abs_ax_m_s2")), json_number(x.at("max_abs_ay_m_s2")));
    }

    double
    joint_value(const Json &summary, const std::string &joint, const std::string &key)
    {
      if (summary.is_object() == false || !summary.contains("clearance_joints") ||
          !summary.at("clearance_joints").contains(joint) || !summary.at("clearance_joints").at(joint).contains(key))
        return std::numeric_limits<double>::quiet_NaN();
      return json_number(summary.at("clearance_joints").at(joint).at(key));
    }

    /** Number of driving periods a run simulated (NaN if unknown). */
    double
    periods(const ComparedRun &r)
    {
      if (r.summary.is_object() == false || !r.summary.contains("simulated_time_s") || !(r.run.driving_period > 0.0))
        return std::numeric_limits<double>::quiet_NaN();
      return json_number(r.summary.at("simulated_time_s")) / r.run.driving_period;
    }

    double
    section_spread(const analysis::RecordedRun &run, const std::string &channel)
    {
      for (const auto &c : analysis::section_spread(run.section))
        if (c.name == channel)
          return c.spread;
      return std::numeric_limits<double>::quiet_NaN();
    }

    /** Phase-portrait panel of one run, on the given axis ranges. */
    io::PlotSpec
    phase_panel(const analysis::RecordedRun           &run,
                const std::string                     &position,
                const std::string                     &velocity,
                const std::pair<io::Range, io::Range> &ranges)
    {
      io::PlotSpec p;
      p.title   = run.label;
      p.x_label = position + " [m]";
      p.y_label = velocity + " [m/s]";
      p.x_range = ranges.first;
      p.y_range = ranges.second;
      p.key     = io::KeyPlace::below;
      io::PlotSeries orbit;
      orbit.title =
        std::to_string(run.series.n_samples()) + " samples every " + format_number(run.sample_interval, 3) + " s";
      orbit.x    = run.series.values[run.series.index(position)];
      orbit.y    = run.series.values[run.series.index(velocity)];
      orbit.look = io::line("#707070", 0.4);
      p.series.push_back(orbit);
      const auto &s = run.section.points;
      if (s.n_samples() > 0 && s.has(position) && s.has(velocity))
        {
          io::PlotSeries points;
          points.title =
            std::to_string(s.n_samples()) + " Poincaré points (one per " + format_number(run.section.period, 3) + " s)";
          points.look = io::points("red", 0.7);
          points.x    = s.values[s.index(position)];
          points.y    = s.values[s.index(velocity)];
          p.series.push_back(points);
        }
      return p;
    }

    /** The x and y ranges covering both runs' channel values, 5 % margin. */
    std::pair<io::Range, io::Range>
    common_range(const analysis::RecordedRun &a,
                 const analysis::RecordedRun &b,
                 const std::string           &x,
                 const std::string           &y)
    {
      auto range = [&](const std::string &c) {
        double lo = std::numeric_limits<double>::infinity(), hi = -lo;
        for (const auto *r : {&a, &b})
          for (const double v : r->series.values[r->series.index(c)])
            if (std::isfinite(v))
              {
                lo = std::min(lo, v);
                hi = std::max(hi, v);
              }
        const double pad = 0.05 * std::max(hi - lo, 1e-30);
        return io::Range{lo - pad, hi + pad};
      };
      return {range(x), range(y)};
    }
  } // namespace

  namespace
  {
    /** What the comparison writes, gathered section by section. */
    struct Report
    {
      Json               json  = Json::object();
      Json               files = Json::array();
      std::ostringstream md;
    };

    /** The Lyapunov tables: rows, the delay scan, and its plot panels. */
    struct ExponentTables
    {
      std::ostringstream        csv, scan_csv;
      Json                      lle  = Json::array();
      Json                      scan = Json::array();
      std::vector<io::PlotSpec> scan_panels;
    };

    /** 1. Robust indicators from the summaries (impacts, contact, peaks, section spread). */
    void
    add_indicators(const ComparedRun                &before,
                   const ComparedRun                &after,
                   const DynamicsComparisonSettings &settings,
                   Report                           &report)
    {
      const auto  &b  = before.run;
      const auto  &a  = after.run;
      auto        &md = report.md;
      const double pb = periods(before), pa = periods(after);
      md << "\n## Contact and motion indicators\n\n| quantity | before | after | after / before |\n|---|---|---|---|\n";
      Json ind = Json::object();
      auto row = [&](const std::string &name, const std::string &key, const double vb, const double va) {
        md << "| " << name << " | " << format_number(vb, 4) << " | " << format_number(va, 4) << " | "
           << format_number(va / vb, 3) << " |\n";
        Json r      = Json::object();
        r["before"] = vb;
        r["after"]  = va;
        ind[key]    = r;
      };
      for (const auto &j : settings.joints)
        {
          row("joint " + j + ": impacts per driving period",
              j + "_impacts_per_period",
              joint_value(before.summary, j, "impacts") / pb,
              joint_value(after.summary, j, "impacts") / pa);
          row("joint " + j + ": fraction of time in contact",
              j + "_fraction_in_contact",
              joint_value(before.summary, j, "fraction_in_contact"),
              joint_value(after.summary, j, "fraction_in_contact"));
          row("joint " + j + ": peak contact force [N]",
              j + "_max_normal_force_N",
              joint_value(before.summary, j, "max_normal_force_N"),
              joint_value(after.summary, j, "max_normal_force_N"));
          for (const char *d : {"x", "y"})
            {
              const std::string c = j + "_e" + d + "_m";
              if (b.section.points.n_samples() > 0 || a.section.points.n_samples() > 0)
                row("joint " + j + ": spread of the Poincaré points in e_" + d + " [m]",
                    c + "_poincare_spread",
                    section_spread(b, c),
                    section_spread(a, c));
            }
        }
      for (const auto &body : settings.bodies)
        row("body " + body + ": peak acceleration [m/s²]",
            body + "_peak_acceleration_m_s2",
            peak_acceleration(before.summary, body),
            peak_acceleration(after.summary, body));
      report.json["indicators"] = ind;
    }

    /** 2. Phase portraits, before | after, same axes, Poincaré points overlaid. */
    void
    add_phase_portraits(const analysis::RecordedRun      &b,
                        const analysis::RecordedRun      &a,
                        const DynamicsComparisonSettings &settings,
                        const std::string                &dir,
                        Report                           &report)
    {
      auto &files = report.files;
      if (b.series.n_samples() > 0 && a.series.n_samples() > 0)
        for (const auto &j : settings.joints)
          for (const char *d : {"x", "y"})
            {
              const std::string x = j + "_e" + d + "_m", v = j + "_ve" + d + "_m_s";
              if (!b.series.has(x) || !b.series.has(v) || !a.series.has(x) || !a.series.has(v))
                continue;
              const auto        range = common_range(b, a, x, v);
              const std::string png   = "before_after_phase_" + j + "_" + d + ".png";
              if (io::plot_panels_png({phase_panel(b, x, v, range), phase_panel(a, x, v, range)},
                                      2,
                                      "Joint " + j + ": journal centre relative to the bushing, " + d +
                                        " direction (phase portrait, Poincaré points in red)",
                                      dir + png,
                                      1600,
                                      750))
                files.push_back(png);
            }
    }

    /**
     * The scan of one channel and method: the same comparison at the other delays of
     * @p delays (same dimension @p m), reusing the estimates at the common delay; rows
     * for the CSV and JSON, and the resolved estimates as two series of @p panel.
     */
    void
    add_scan(const analysis::RecordedRun   &b,
             const analysis::RecordedRun   &a,
             const std::string             &c,
             const analysis::LyapunovMethod method,
             const unsigned int             m,
             const double                   delay_s,
             const Estimate                &eb,
             const Estimate                &ea,
             const std::vector<double>     &delays,
             ExponentTables                &t,
             io::PlotSpec                  &panel)
    {
      auto          &scan_csv = t.scan_csv;
      auto          &scan     = t.scan;
      io::PlotSeries sb, sa;
      sb.title                = "before, " + analysis::method_name(method);
      sa.title                = "after, " + analysis::method_name(method);
      const bool       wolf   = method == analysis::LyapunovMethod::wolf;
      const io::Marker marker = wolf ? io::Marker::open_circle : io::Marker::filled_circle;
      sb.look                 = io::line_points("#1f5fbf", 2, marker);
      sa.look                 = io::line_points("#c0392b", 2, marker);
      if (wolf)
        {
          sb.look.dashed();
          sa.look.dashed();
        }
      for (const double tau : delays)
        {
          if (std::round(tau / b.sample_interval) < 1.0 || std::round(tau / a.sample_interval) < 1.0)
            continue; // below a sample interval: not measurable from these recordings
          // The common delay is usually one of the scan's: reuse its estimates.
          const bool common = std::lround(tau / b.sample_interval) == std::lround(delay_s / b.sample_interval) &&
                              std::lround(tau / a.sample_interval) == std::lround(delay_s / a.sample_interval);
          const auto sb_e = common ? eb : estimate(b, c, method, tau, m);
          const auto sa_e = common ? ea : estimate(a, c, method, tau, m);
          scan_csv << c << ',' << analysis::method_name(method) << ',' << tau << ',' << m << ',' << sb_e.per_s << ','
                   << sa_e.per_s << ',' << sa_e.per_s / sb_e.per_s << ',' << sb_e.resolved << ',' << sa_e.resolved
                   << '\n';
          Json s               = Json::object();
          s["channel"]         = c;
          s["method"]          = analysis::method_name(method);
          s["delay_s"]         = tau;
          s["before_per_s"]    = sb_e.per_s;
          s["after_per_s"]     = sa_e.per_s;
          s["before_resolved"] = sb_e.resolved;
          s["after_resolved"]  = sa_e.resolved;
          scan.push_back(s);
          // Unresolved estimates (the initial jump only) are left out of the plot.
          if (sb_e.per_s > 0.0 && sb_e.resolved)
            {
              sb.x.push_back(tau);
              sb.y.push_back(sb_e.per_s);
            }
          if (sa_e.per_s > 0.0 && sa_e.resolved)
            {
              sa.x.push_back(tau);
              sa.y.push_back(sa_e.per_s);
            }
        }
      panel.series.push_back(sb);
      panel.series.push_back(sa);
    }

    /**
     * 3a. One channel's exponents at the common embedding (given, or the before-wear
     * run's automatic choice), for every method, and over the delay scan.
     */
    void
    add_channel_exponents(const analysis::RecordedRun      &b,
                          const analysis::RecordedRun      &a,
                          const DynamicsComparisonSettings &settings,
                          const std::string                &c,
                          std::ostream                     &md,
                          ExponentTables                   &t)
    {
      const bool have_published = !settings.published.empty();
      auto      &csv            = t.csv;
      auto      &lle            = t.lle;
      // The common embedding: given, or the before-wear run's automatic choice.
      analysis::EmbeddingSettings es;
      if (settings.delay > 0.0)
        es.delay = delay_samples(settings.delay, b, "common");
      if (settings.dimension > 0)
        es.dimension = settings.dimension;
      const auto   emb     = analysis::resolve_embedding(channel_values(b, c), es);
      const double delay_s = emb.embedding.delay * b.sample_interval;
      const auto   m       = emb.embedding.dimension;
      const auto   pub     = std::find_if(settings.published.begin(),
                                    settings.published.end(),
                                    [&](const analysis::PublishedExponents &p) { return p.channel == c; });

      io::PlotSpec panel;
      panel.title   = c;
      panel.x_label = "embedding delay [s]";
      panel.y_label = "largest Lyapunov exponent [1/s]";
      panel.log_x = panel.log_y = true;
      panel.key                 = io::KeyPlace::inside_top_right;

      for (const auto method : settings.methods)
        {
          const auto   eb = estimate(b, c, method, delay_s, m), ea = estimate(a, c, method, delay_s, m);
          const double ratio = ea.per_s / eb.per_s;
          md << "| " << c << " | " << analysis::method_name(method) << " | " << format_number(delay_s, 3) << " | " << m
             << " | " << format_number(eb.per_s, 3) << (eb.resolved ? "" : " (unresolved)") << " | "
             << format_number(ea.per_s, 3) << (ea.resolved ? "" : " (unresolved)") << " | " << format_number(ratio, 3)
             << " | " << format_number(eb.per_s * b.sample_interval, 3) << " | "
             << format_number(ea.per_s * a.sample_interval, 3);
          if (have_published)
            {
              if (pub != settings.published.end())
                md << " | " << format_number(pub->before, 3) << " | " << format_number(pub->after, 3) << " | "
                   << format_number(pub->after / pub->before, 3);
              else
                md << " | | |";
            }
          md << " |\n";
          csv << c << ',' << analysis::method_name(method) << ',' << delay_s << ',' << m << ',' << eb.per_s << ','
              << ea.per_s << ',' << ratio << ',' << eb.per_s * b.sample_interval << ',' << ea.per_s * a.sample_interval
              << ',' << eb.resolved << ',' << ea.resolved << ',';
          if (pub != settings.published.end())
            csv << pub->before << ',' << pub->after;
          else
            csv << ',';
          csv << '\n';
          Json r                   = Json::object();
          r["channel"]             = c;
          r["method"]              = analysis::method_name(method);
          r["delay_s"]             = delay_s;
          r["embedding_dimension"] = m;
          r["before_per_s"]        = eb.per_s;
          r["after_per_s"]         = ea.per_s;
          r["before_resolved"]     = eb.resolved;
          r["after_resolved"]      = ea.resolved;
          r["before_per_sample"]   = eb.per_s * b.sample_interval;
          r["after_per_sample"]    = ea.per_s * a.sample_interval;
          r["unit"]                = "1/s (natural log)";
          if (!eb.note.empty())
            r["before_note"] = eb.note;
          if (!ea.note.empty())
            r["after_note"] = ea.note;
          if (pub != settings.published.end())
            {
              r["published_before"] = pub->before;
              r["published_after"]  = pub->after;
            }
          lle.push_back(r);

          add_scan(b, a, c, method, m, delay_s, eb, ea, settings.delay_scan, t, panel);
        }
      t.scan_panels.push_back(panel);
    }

    /** 3b. The row of the simulated model's own (two-trajectory) exponent. */
    void
    add_simulation_exponents(const SimulationExponents &se_value,
                             const bool                 have_published,
                             std::ostream              &md,
                             ExponentTables            &t)
    {
      const auto *const se    = &se_value;
      auto             &csv   = t.csv;
      auto             &lle   = t.lle;
      const double      ratio = se->after / se->before;
      const auto        cell  = [](const double v) {
        return std::isfinite(v) ? format_number(v, 3) : std::string("–");
      };
      md << "| state (simulation) | two-trajectory | – | – | " << cell(se->before) << " | " << cell(se->after) << " | "
         << cell(ratio) << " | – | –" << (have_published ? " | | |" : "") << " |\n";
      md << "\nThe two-trajectory row is the exponent of the simulated model itself, no embedding: a "
            "shadow copy d0 = "
         << format_number(se->separation, 3) << " m away, renormalized every " << format_number(se->interval, 3)
         << " s, over " << format_number(se->duration, 3) << " s of each state, relative tolerance "
         << format_number(se->tolerance, 3) << ".\n";
      for (const auto &[when, failure] : {std::pair<std::string, std::string>{"before", se->failure_before},
                                          std::pair<std::string, std::string>{"after", se->failure_after}})
        if (!failure.empty())
          md << "The two-trajectory run " << when << " wear gave no exponent: " << failure << "\n";
      // A ratio of two zero exponents (no renormalization within the run) is undefined:
      // its cell stays empty, as a table of numbers holds no NaN.
      csv << "state,two-trajectory,,," << se->before << ',' << se->after << ','
          << (std::isfinite(ratio) ? format_number(ratio, 8) : std::string()) << ",,,1,1,,\n";
      Json r                          = Json::object();
      r["channel"]                    = "state";
      r["method"]                     = "two-trajectory";
      r["before_per_s"]               = se->before;
      r["after_per_s"]                = se->after;
      r["separation_m"]               = se->separation;
      r["renormalization_interval_s"] = se->interval;
      r["relative_tolerance"]         = se->tolerance;
      r["duration_s"]                 = se->duration;
      if (!se->failure_before.empty())
        r["failure_before"] = se->failure_before;
      if (!se->failure_after.empty())
        r["failure_after"] = se->failure_after;
      r["unit"] = "1/s (natural log)";
      lle.push_back(r);
    }

    /** 3c. The delay scan as a Markdown table. */
    void
    add_delay_scan_table(const Json &scan, std::ostream &md)
    {
      md << "\n## Delay scan\n\nThe same estimates at other delays (same dimension). If after / before "
            "changes sign across the scan, the comparison depends on the embedding, not only on the "
            "wear.\n\n| channel | method | delay [s] | before [1/s] | after [1/s] | after / before |\n"
            "|---|---|---|---|---|---|\n";
      for (std::size_t k = 0; k < scan.size(); ++k)
        md << "| " << scan[k].at("channel").get<std::string>() << " | " << scan[k].at("method").get<std::string>()
           << " | " << format_number(json_number(scan[k].at("delay_s")), 3) << " | "
           << format_number(json_number(scan[k].at("before_per_s")), 3)
           << (scan[k].at("before_resolved").get<bool>() ? "" : " (unresolved)") << " | "
           << format_number(json_number(scan[k].at("after_per_s")), 3)
           << (scan[k].at("after_resolved").get<bool>() ? "" : " (unresolved)") << " | "
           << format_number(json_number(scan[k].at("after_per_s")) / json_number(scan[k].at("before_per_s")), 3)
           << " |\n";
    }

    /** 3d. before_after_lyapunov.csv, before_after_delay_scan.csv/.png into @p dir. */
    void
    write_exponent_files(const std::string &dir, const bool scanned, const ExponentTables &t, Json &files)
    {
      const auto &csv         = t.csv;
      const auto &scan_csv    = t.scan_csv;
      const auto &scan_panels = t.scan_panels;
      write_file_atomically(dir + io::outputs::before_after_table, csv.str());
      files.push_back(io::outputs::before_after_table);
      if (scanned)
        {
          write_file_atomically(dir + "before_after_delay_scan.csv", scan_csv.str());
          files.push_back("before_after_delay_scan.csv");
          if (io::plot_panels_png(scan_panels,
                                  2,
                                  "Largest Lyapunov exponent vs embedding delay, before (blue) and after (red) "
                                  "wear; solid rosenstein, dashed wolf; unresolved estimates left out",
                                  dir + "before_after_delay_scan.png",
                                  1600,
                                  700))
            files.push_back("before_after_delay_scan.png");
        }
    }

    /** 3. Lyapunov exponents at a common embedding, and over the delay scan. */
    void
    add_exponents(const analysis::RecordedRun      &b,
                  const analysis::RecordedRun      &a,
                  const DynamicsComparisonSettings &settings,
                  const std::string                &dir,
                  const bool                        write,
                  Report                           &report)
    {
      auto                    &md = report.md;
      std::vector<std::string> channels;
      for (const auto &j : settings.joints)
        for (const auto &d : settings.directions)
          channels.push_back(j + "_e" + d + "_m");
      md
        << "\n## Largest Lyapunov exponents at one embedding for both runs\n\n"
        << "Natural log, per second; per sample = times the sample interval (before "
        << format_number(b.sample_interval, 3) << " s, after " << format_number(a.sample_interval, 3) << " s).\n\n"
        << "| channel | method | delay [s] | m | before [1/s] | after [1/s] | after / before | before per sample | after per sample";
      const bool have_published = !settings.published.empty();
      if (have_published)
        md << " | published before | published after | published after / before";
      md << " |\n|---|---|---|---|---|---|---|---|---" << (have_published ? "|---|---|---" : "") << "|\n";

      ExponentTables t;
      t.csv << std::setprecision(8)
            << "channel,method,delay_s,embedding_dimension,before_per_s,after_per_s,ratio,before_per_sample,"
               "after_per_sample,before_resolved,after_resolved,published_before,published_after\n";
      t.scan_csv << std::setprecision(8)
                 << "channel,method,delay_s,embedding_dimension,before_per_s,after_per_s,ratio,before_resolved,"
                    "after_resolved\n";
      for (const auto &c : channels)
        add_channel_exponents(b, a, settings, c, md, t);
      if (const auto &se = settings.simulation_exponents)
        add_simulation_exponents(*se, have_published, md, t);
      report.json["lyapunov"] = t.lle;
      const bool scanned      = !settings.delay_scan.empty() && !settings.methods.empty();
      if (scanned)
        {
          report.json["delay_scan"] = t.scan;
          add_delay_scan_table(t.scan, md);
        }
      if (!settings.published.empty())
        md << "\nPublished values: " << settings.published_note << "\n";
      if (write)
        write_exponent_files(dir, scanned, t, report.files);
    }
  } // namespace

  DynamicsComparison
  compare_dynamics(const ComparedRun                &before,
                   const ComparedRun                &after,
                   const DynamicsComparisonSettings &settings,
                   const std::string                &output_directory)
  {
    const bool        write = !output_directory.empty();
    const std::string dir   = output_directory + "/";
    const auto       &b     = before.run;
    const auto       &a     = after.run;
    // Check what would make the comparison fail before anything is written.
    if (!settings.methods.empty())
      for (const auto *r : {&b, &a})
        {
          for (const auto &j : settings.joints)
            for (const auto &d : settings.directions)
              channel_values(*r, j + "_e" + d + "_m");
          if (settings.delay > 0.0)
            delay_samples(settings.delay, *r, "common");
        }
    if (write)
      make_output_directory(output_directory);

    Report report;
    report.json["before"] = b.label;
    report.json["after"]  = a.label;
    report.md << "# Dynamics before and after wear\n\n"
              << "Before: " << b.label << "; after: " << a.label << ".\n";
    add_indicators(before, after, settings, report);
    if (write)
      add_phase_portraits(b, a, settings, dir, report);
    if (!settings.methods.empty() || settings.simulation_exponents)
      add_exponents(b, a, settings, dir, write, report);

    DynamicsComparison out;
    out.json   = report.json;
    out.report = report.md.str();
    if (write)
      {
        write_file_atomically(dir + io::outputs::before_after_report, out.report);
        report.files.push_back(io::outputs::before_after_report);
        out.json["files"] = report.files;
      }
    return out;
  }
} // namespace wearlink::workflows
