// SPDX-License-Identifier: LGPL-2.1-or-later
#include "workflows/study/convergence_study.h"

#include "base/atomic_file.h"
#include "base/exceptions.h"
#include "base/numbers.h"
#include "base/text.h"
#include "io/output_names.h"
#include "io/plot.h"
#include "io/scene.h"
#include "wear/periodic_samples.h"
#include "workflows/ensemble/ensemble.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace wearlink::workflows
{
  namespace
  {
    using numbers::nan;

    /** The two surfaces of a wearing joint: the measurement's tag and the name shown. */
    const std::vector<std::pair<std::string, std::string>> surface_tags = {{"pin", "pin"}, {"bush", "bushing"}};

    /** ‖a − b‖/‖b‖ on the coarser of the two grids (the finer one interpolated). */
    double
    l2_difference(const std::vector<double> &a, const std::vector<double> &b)
    {
      const std::size_t n = std::min(a.size(), b.size());
      if (n == 0)
        return nan;
      const auto x = wear::periodic_resampled(a, n), y = wear::periodic_resampled(b, n);
      double     d = 0, r = 0;
      for (std::size_t k = 0; k < n; ++k)
        {
          d += (x[k] - y[k]) * (x[k] - y[k]);
          r += y[k] * y[k];
        }
      return r > 0 ? std::sqrt(d / r) : nan;
    }

    /** max |a − b| / max b on the coarser grid. */
    double
    pointwise_difference(const std::vector<double> &a, const std::vector<double> &b)
    {
      const std::size_t n = std::min(a.size(), b.size());
      if (n == 0)
        return nan;
      const auto x = wear::periodic_resampled(a, n), y = wear::periodic_resampled(b, n);
      double     d = 0, top = 0;
      for (std::size_t k = 0; k < n; ++k)
        {
          d   = std::max(d, std::abs(x[k] - y[k]));
          top = std::max(top, y[k]);
        }
      return top > 0 ? d / top : nan;
    }

    double
    relative_change(const double v, const double ref)
    {
      return ref != 0 ? (v - ref) / ref : nan;
    }

    /** One level's entries: the surfaces and the wear step refined by @p r. */
    ParameterOverrides
    level_overrides(const io::Scene &scene, const double r, std::vector<std::string> &settings)
    {
      ParameterOverrides o;
      const auto         set = [&](const std::string &path, const std::string &value) {
        o.set(path, value);
        settings.push_back(path + "=" + value);
      };
      for (const auto &w : scene.wear)
        {
          const std::string c = "Joint " + w->joint + "/Clearance/";
          if (w->pressure_model == "fe")
            {
              const double h = std::stod(entry_value(*scene.parameters, c + "fe/Surface element size"));
              set(c + "fe/Surface element size", format_number(h / r, 6));
            }
          else
            {
              const double n = std::stod(entry_value(*scene.parameters, c + "Number of discrete areas"));
              set(c + "Number of discrete areas", std::to_string(std::max(8L, std::lround(n * r))));
            }
        }
      const auto &ws = scene.wear_loop;
      if (ws.extrapolation == wear::Extrapolation::adaptive)
        set("Wear/Maximum depth increment", format_number(ws.max_depth_increment / r, 6));
      else
        {
          const double iterations = ws.n_iterations * r;
          if (std::abs(iterations - std::round(iterations)) > 1e-9 || iterations < 1)
            throw InputError("The refinement " + format_number(r) + " makes " + format_number(iterations) + " of the " +
                             std::to_string(ws.n_iterations) + " wear iterations of " + scene.file +
                             ": a refinement must turn them into a whole number (e.g. 0.5, 1, 2, 4 with 10 "
                             "iterations).");
          set("Wear/Number of iterations", std::to_string(std::lround(iterations)));
          set("Wear/Extrapolation factor", format_number(ws.extrapolation_factor / r, 12));
        }
      return o;
    }

    /** The jobs: per level, the scene's own run and members − 1 perturbed ones. */
    std::vector<StudyJob>
    plan_jobs(const std::string             &file,
              const ConvergenceRequest      &request,
              const io::Scene               &scene,
              std::vector<ConvergenceLevel> &levels)
    {
      std::vector<StudyJob> jobs;
      EnsembleRequest       e{request.members, request.seed, request.perturbation};
      for (const double r : request.refinements)
        {
          ConvergenceLevel level;
          level.refinement       = r;
          ParameterOverrides lvl = request.overrides;
          lvl.append(level_overrides(scene, r, level.settings));
          const io::Scene level_scene = io::read_scene(file, lvl); // InputError if a level's settings do not fit
          for (unsigned int m = 0; m < request.members; ++m)
            {
              const auto overrides = m == 0 ? lvl : member_overrides(level_scene, lvl, e, m);
              jobs.push_back({overrides,
                              "refinement " + format_number(r) + ", member " + std::to_string(m),
                              r * predicted_cost(level_scene, scene)});
            }
          levels.push_back(std::move(level));
        }
      return jobs;
    }

    /** The surfaces' names ("A pin", "A bushing", …) of @p scene. */
    std::vector<std::string>
    surface_names(const io::Scene &scene)
    {
      std::vector<std::string> names;
      for (const auto &w : scene.wear)
        for (const auto &[tag, name] : surface_tags)
          names.push_back(w->joint + " " + name);
      return names;
    }

    /** The standard error of the mean of @p v (NaN below two values). */
    double
    standard_error_of_mean(const std::vector<double> &v)
    {
      if (v.size() < 2)
        return nan;
      double mean = 0, var = 0;
      for (const double x : v)
        mean += x / v.size();
      for (const double x : v)
        var += (x - mean) * (x - mean) / (v.size() - 1);
      return std::sqrt(var / v.size());
    }

    /** The statistics of surface @p tag of joint @p joint over the members @p ms. */
    SurfaceLevel
    surface_statistics(const std::vector<const Measurement *> &ms, const std::string &joint, const std::string &tag)
    {
      SurfaceLevel                     s;
      const std::string                key = joint + " profile_" + tag;
      std::vector<std::vector<double>> profiles;
      for (const auto *m : ms)
        if (m->profiles.count(key))
          profiles.push_back(m->profiles.at(key));
      if (profiles.empty())
        return s;
      const std::size_t n = profiles.front().size();
      const double      k = static_cast<double>(profiles.size());
      s.mean.assign(n, 0.0);
      s.low.assign(n, std::numeric_limits<double>::infinity());
      s.high.assign(n, -std::numeric_limits<double>::infinity());
      for (const auto &p : profiles)
        for (std::size_t i = 0; i < n; ++i)
          {
            s.mean[i] += p[i] / k;
            s.low[i]  = std::min(s.low[i], p[i]);
            s.high[i] = std::max(s.high[i], p[i]);
          }
      double var = 0, norm = 0;
      for (std::size_t i = 0; i < n; ++i)
        {
          double v = 0;
          for (const auto &p : profiles)
            v += (p[i] - s.mean[i]) * (p[i] - s.mean[i]);
          var += profiles.size() > 1 ? v / (k - 1) : 0;
          norm += s.mean[i] * s.mean[i];
        }
      s.standard_error = norm > 0 ? std::sqrt(var / k / norm) : nan;
      double pairs = 0, count = 0;
      for (std::size_t a = 0; a < profiles.size(); ++a)
        for (std::size_t b = a + 1; b < profiles.size(); ++b)
          {
            pairs += l2_difference(profiles[a], profiles[b]);
            count += 1;
          }
      s.pair_difference  = count > 0 ? pairs / count : nan;
      const auto mean_of = [&](const std::string &q) {
        double sum = 0, c = 0;
        for (const auto *m : ms)
          if (m->quantities.count(joint + " " + q))
            {
              sum += m->quantities.at(joint + " " + q);
              c += 1;
            }
        return c > 0 ? sum / c : nan;
      };
      const auto error_of = [&](const std::string &q) {
        std::vector<double> v;
        for (const auto *m : ms)
          if (m->quantities.count(joint + " " + q))
            v.push_back(m->quantities.at(joint + " " + q));
        return standard_error_of_mean(v);
      };
      s.largest        = mean_of("h_" + tag);
      s.envelope       = mean_of("he_" + tag);
      s.largest_error  = error_of("h_" + tag);
      s.envelope_error = error_of("he_" + tag);
      s.volume         = mean_of("V_" + tag);
      s.roughness      = mean_of("rough_" + tag);
      return s;
    }

    /**
     * The Richardson estimates of every surface's depths from the three finest levels,
     * if they refine by one ratio.
     */
    void
    extrapolate(ConvergenceStudy &study)
    {
      const auto &lv = study.levels;
      if (lv.size() < 3)
        return;
      const std::size_t n = lv.size();
      const double      r = lv[n - 2].refinement / lv[n - 3].refinement;
      if (std::abs(lv[n - 1].refinement / lv[n - 2].refinement - r) > 1e-9 * r)
        return;
      study.extrapolation_ratio = r;
      for (std::size_t s = 0; s < study.surfaces.size(); ++s)
        {
          analysis::RefinementTriple largest, envelope;
          largest.ratio = envelope.ratio = r;
          for (int l = 0; l < 3; ++l)
            {
              const auto &x              = lv[n - 3 + l].surfaces[s];
              largest.value[l]           = x.largest;
              largest.standard_error[l]  = x.largest_error;
              envelope.value[l]          = x.envelope;
              envelope.standard_error[l] = x.envelope_error;
            }
          study.extrapolations.push_back({analysis::richardson(largest), analysis::richardson(envelope)});
        }
    }

    /** Each level's statistics, and its differences against the finest. */
    void
    evaluate_levels(const io::Scene &scene, const std::vector<Measurement> &measured, ConvergenceStudy &study)
    {
      const unsigned int m = study.members;
      for (std::size_t l = 0; l < study.levels.size(); ++l)
        {
          auto                            &level = study.levels[l];
          std::vector<const Measurement *> ok;
          for (unsigned int k = 0; k < m; ++k)
            {
              const auto &x = measured[l * m + k];
              if (x.ok)
                {
                  ok.push_back(&x);
                  level.wall_time += x.wall_time;
                }
              else
                level.failures.push_back("member " + std::to_string(k) + ": " + x.failure);
            }
          level.ran       = static_cast<unsigned int>(ok.size());
          level.wall_time = ok.empty() ? nan : level.wall_time / ok.size();
          for (const auto &w : scene.wear)
            for (const auto &[tag, name] : surface_tags)
              level.surfaces.push_back(surface_statistics(ok, w->joint, tag));
        }
      extrapolate(study);
      const auto &finest = study.levels.back();
      for (auto &level : study.levels)
        for (std::size_t s = 0; s < level.surfaces.size(); ++s)
          {
            auto       &x     = level.surfaces[s];
            const auto &f     = finest.surfaces[s];
            x.l2              = l2_difference(x.mean, f.mean);
            x.pointwise       = pointwise_difference(x.mean, f.mean);
            x.largest_change  = relative_change(x.largest, f.largest);
            x.envelope_change = relative_change(x.envelope, f.envelope);
            x.volume_change   = relative_change(x.volume, f.volume);
          }
    }

    std::string
    percent(const double v)
    {
      if (!std::isfinite(v))
        return "—";
      std::ostringstream os;
      os << std::fixed << std::setprecision(1) << 100 * v << " %";
      return os.str();
    }

    std::string
    micrometres(const double v)
    {
      std::ostringstream os;
      os << std::setprecision(3) << v * 1e6;
      return os.str();
    }

    /** One row of the Richardson table. */
    std::string
    extrapolation_row(const std::string &surface, const char *depth, const analysis::RichardsonEstimate &e)
    {
      std::ostringstream os;
      os << "| " << surface << " | " << depth << " | ";
      if (!e.determinable)
        return os.str() + "— | — | — | — | — | " + e.reason + " |\n";
      os << std::fixed << std::setprecision(2) << e.order << std::defaultfloat << " | " << micrometres(e.extrapolated)
         << " | " << percent(e.error[0]) << " | " << percent(e.error[1]) << " | " << percent(e.error[2]) << " | "
         << e.reason << " |\n";
      return os.str();
    }

    /** convergence.md's Richardson section (empty without three levels of one ratio). */
    std::string
    extrapolation_markdown(const ConvergenceStudy &study)
    {
      if (study.extrapolations.empty())
        return "";
      const auto         n = study.levels.size();
      std::ostringstream os;
      os << "\n**Extrapolated depths** (Richardson, levels";
      for (std::size_t l = n - 3; l < n; ++l)
        os << " ×" << format_number(study.levels[l].refinement);
      os << "): with the members' mean depth f ≈ f* + C h^p, the observed order p = ln((f₁ − f₂)/(f₂ − f₃))/ln "
         << format_number(study.extrapolation_ratio)
         << ", the extrapolated depth f* and each level's error (f − f*)/f*. Not determinable when a difference "
            "is within twice its noise (the members' standard errors) or the levels do not approach monotonically."
            "\n\n| surface | depth | order | extrapolated [µm] | error, coarse | error, medium | error, fine | note "
            "|\n|---|---|---:|---:|---:|---:|---:|---|\n";
      for (std::size_t s = 0; s < study.surfaces.size(); ++s)
        os << extrapolation_row(study.surfaces[s], "largest", study.extrapolations[s].largest)
           << extrapolation_row(study.surfaces[s], "envelope", study.extrapolations[s].envelope);
      return os.str();
    }

    /** A Richardson estimate as JSON (nulls where not determinable). */
    Json
    estimate_json(const analysis::RichardsonEstimate &e)
    {
      const auto number = [&](const double v) {
        return e.determinable ? Json(v) : Json();
      };
      return {{"determinable", e.determinable},
              {"observed_order", number(e.order)},
              {"extrapolated_m", number(e.extrapolated)},
              {"relative_error_of_levels", Json::array({number(e.error[0]), number(e.error[1]), number(e.error[2])})},
              {"note", e.reason}};
    }
  } // namespace

  ConvergenceStudy
  run_convergence_study(const std::string &scene_file, const ConvergenceRequest &request)
  {
    if (request.members < 2)
      throw InputError("A convergence study needs at least 2 ensemble members per level (--ensemble; default 4): "
                       "the chaos floor is their spread.");
    if (request.refinements.size() < 2 || !std::is_sorted(request.refinements.begin(), request.refinements.end()) ||
        std::adjacent_find(request.refinements.begin(), request.refinements.end()) != request.refinements.end() ||
        !(request.refinements.front() > 0) || !(request.refinements.back() <= 64))
      throw InputError("--refinements: give at least two increasing factors above 0 and at most 64, e.g. 1,2,4 "
                       "(the scene's own discretization is 1).");
    const io::Scene scene = io::read_scene(scene_file, request.overrides);
    if (scene.wear.empty())
      throw InputError("A convergence study refines the worn profiles of a wear scene, but no clearance joint of " +
                       scene_file + " has 'Wear law = archard'.");
    ConvergenceStudy study;
    study.scene_file     = scene_file;
    study.base_overrides = request.overrides.settings();
    study.members        = request.members;
    study.surfaces       = surface_names(scene);
    const auto jobs      = plan_jobs(scene_file, request, scene, study.levels);
    if (request.progress && is_study_root())
      std::cerr << "[wearlink] study convergence: " << study.levels.size() << " levels × " << request.members
                << " members = " << jobs.size() << " wear runs\n";
    const auto measured = measure_jobs(scene_file, jobs, request.progress);
    study.root          = is_study_root();
    if (!study.root)
      return study;
    evaluate_levels(scene, measured, study);
    return study;
  }

  std::string
  ConvergenceStudy::markdown() const
  {
    std::ostringstream os;
    os << "Convergence study of `" << scene_file << "`";
    if (!base_overrides.empty())
      os << " with `" << join(base_overrides, "`, `") << "`";
    os << ": " << members
       << " ensemble members per level (the scene's own run and perturbed ones). Each level refines the "
          "worn surfaces (discrete areas, or fe surface elements) and the wear step together; its members' mean "
          "profile is compared with the finest level's on the coarser grid. L2: ‖mean − mean_finest‖/‖mean_finest‖; "
          "pointwise: max |mean − mean_finest| / max mean_finest; largest, envelope, volume: change of the members' "
          "mean against the finest. Floor: a single run's L2 difference from another (mean over member pairs) and the "
          "standard error of a level's mean profile (‖std‖/√members/‖mean‖).\n\n";
    os << "| level | settings | runs | wall [s] |\n|---|---|---:|---:|\n";
    for (const auto &l : levels)
      os << "| ×" << format_number(l.refinement) << " | `" << join(l.settings, "`, `") << "` | " << l.ran << "/"
         << members << " | " << std::fixed << std::setprecision(1) << l.wall_time << std::defaultfloat << " |\n";
    for (std::size_t s = 0; s < surfaces.size(); ++s)
      {
        os << "\n**" << surfaces[s] << "**\n\n"
           << "| level | largest [µm] | envelope [µm] | roughness | L2 | pointwise | largest | envelope | volume | "
              "floor: pair L2 | floor: std. error |\n"
           << "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
        for (const auto &l : levels)
          {
            const auto &x = l.surfaces[s];
            os << "| ×" << format_number(l.refinement) << " | " << micrometres(x.largest) << " | "
               << micrometres(x.envelope) << " | " << percent(x.roughness) << " | " << percent(x.l2) << " | "
               << percent(x.pointwise) << " | " << percent(x.largest_change) << " | " << percent(x.envelope_change)
               << " | " << percent(x.volume_change) << " | " << percent(x.pair_difference) << " | "
               << percent(x.standard_error) << " |\n";
          }
      }
    os << extrapolation_markdown(*this);
    for (const auto &l : levels)
      for (const auto &f : l.failures)
        os << "\nlevel ×" << format_number(l.refinement) << " " << f << "\n";
    return os.str();
  }

  Json
  ConvergenceStudy::json() const
  {
    Json j         = Json::object();
    j["scene"]     = scene_file;
    j["overrides"] = base_overrides;
    j["members"]   = members;
    j["levels"]    = Json::array();
    for (const auto &l : levels)
      {
        Json lj           = Json::object();
        lj["refinement"]  = l.refinement;
        lj["settings"]    = l.settings;
        lj["members_ran"] = l.ran;
        lj["failures"]    = l.failures;
        lj["wall_time_s"] = l.wall_time;
        lj["surfaces"]    = Json::object();
        for (std::size_t s = 0; s < surfaces.size(); ++s)
          {
            const auto &x               = l.surfaces[s];
            lj["surfaces"][surfaces[s]] = {{"largest_depth_m", x.largest},
                                           {"envelope_depth_m", x.envelope},
                                           {"volume_m3", x.volume},
                                           {"roughness", x.roughness},
                                           {"l2_to_finest", x.l2},
                                           {"pointwise_to_finest", x.pointwise},
                                           {"largest_depth_change", x.largest_change},
                                           {"envelope_depth_change", x.envelope_change},
                                           {"volume_change", x.volume_change},
                                           {"floor_pair_l2", x.pair_difference},
                                           {"floor_standard_error", x.standard_error},
                                           {"largest_depth_standard_error_m", x.largest_error},
                                           {"envelope_depth_standard_error_m", x.envelope_error}};
          }
        j["levels"].push_back(lj);
      }
    if (!extrapolations.empty())
      {
        Json e      = Json::object();
        e["ratio"]  = extrapolation_ratio;
        e["levels"] = Json::array(
          {levels[levels.size() - 3].refinement, levels[levels.size() - 2].refinement, levels.back().refinement});
        for (std::size_t s = 0; s < surfaces.size(); ++s)
          e["surfaces"][surfaces[s]] = {{"largest_depth", estimate_json(extrapolations[s].largest)},
                                        {"envelope_depth", estimate_json(extrapolations[s].envelope)}};
        j["extrapolation"] = e;
      }
    return j;
  }

  namespace
  {
    /** convergence.csv: one row per level and surface. */
    std::string
    table_csv(const ConvergenceStudy &study)
    {
      std::ostringstream os;
      os << std::setprecision(10)
         << "refinement,surface,members_ran,wall_time_s,largest_depth_m,envelope_depth_m,volume_m3,roughness,"
            "l2_to_finest,pointwise_to_finest,largest_depth_change,envelope_depth_change,volume_change,"
            "floor_pair_l2,floor_standard_error\n";
      for (const auto &l : study.levels)
        for (std::size_t s = 0; s < study.surfaces.size(); ++s)
          {
            const auto &x = l.surfaces[s];
            os << l.refinement << ',' << study.surfaces[s] << ',' << l.ran << ',' << l.wall_time << ',' << x.largest
               << ',' << x.envelope << ',' << x.volume << ',' << x.roughness << ',' << x.l2 << ',' << x.pointwise << ','
               << x.largest_change << ',' << x.envelope_change << ',' << x.volume_change << ',' << x.pair_difference
               << ',' << x.standard_error << '\n';
          }
      return os.str();
    }

    /** The profiles of surface @p s: angle [deg] and per level its mean, low and high [µm]. */
    void
    write_profiles(const std::string &dir, const ConvergenceStudy &study, const std::size_t s)
    {
      std::string stem = study.surfaces[s];
      std::replace(stem.begin(), stem.end(), ' ', '_');
      std::ostringstream csv;
      csv << "# worn depth per level of `wearlink study convergence`: the members' mean, smallest and largest [um] "
             "at each body-frame angle (each level on its own areas; empty where a level has no area)\n";
      csv << "level,angle_deg,mean_um,low_um,high_um\n" << std::setprecision(10);
      io::PlotSpec spec;
      spec.title   = "Worn depth of " + study.surfaces[s] + " at each refinement (members' mean; band: their range)";
      spec.x_label = "angle in the body's own frame [deg]";
      spec.y_label = "wear depth [um]";
      const char *colours[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b"};
      for (std::size_t l = 0; l < study.levels.size(); ++l)
        {
          const auto       &x = study.levels[l].surfaces[s];
          const auto        n = x.mean.size();
          io::PlotSeries    mean, low, high;
          const std::string colour = colours[l % 6];
          const std::string name   = "x" + format_number(study.levels[l].refinement);
          mean.title               = name + " mean";
          low.title                = name + " range";
          high.title               = "";
          mean.look                = io::line(colour, 2);
          low.look = high.look = io::line(colour, 0.5).dashed();
          for (std::size_t k = 0; k < n; ++k)
            {
              const double angle = 360.0 * k / n;
              csv << study.levels[l].refinement << ',' << angle << ',' << x.mean[k] * 1e6 << ',' << x.low[k] * 1e6
                  << ',' << x.high[k] * 1e6 << '\n';
              for (auto *series : {&mean, &low, &high})
                series->x.push_back(angle);
              mean.y.push_back(x.mean[k] * 1e6);
              low.y.push_back(x.low[k] * 1e6);
              high.y.push_back(x.high[k] * 1e6);
            }
          spec.series.push_back(low);
          spec.series.push_back(high);
          spec.series.push_back(mean);
        }
      spec.x_range    = io::Range{0, 360};
      spec.x_tic_step = 45;
      write_file_atomically(dir + "/convergence_" + stem + ".csv", csv.str());
      io::plot_png(spec, dir + "/convergence_" + stem + ".png");
    }
  } // namespace

  void
  write_convergence_study(const std::string &dir, const ConvergenceStudy &study)
  {
    write_file_atomically(dir + "/" + io::outputs::convergence_report, study.markdown());
    write_file_atomically(dir + "/" + io::outputs::convergence_table, table_csv(study));
    write_file_atomically(dir + "/" + io::outputs::convergence_json, study.json().dump(2));
    for (std::size_t s = 0; s < study.surfaces.size(); ++s)
      write_profiles(dir, study, s);
  }
} // namespace wearlink::workflows
