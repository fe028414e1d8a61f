// SPDX-License-Identifier: LGPL-2.1-or-later
#include "workflows/wear/calibration.h"

#include "analysis/ensemble_statistics.h"
#include "base/exceptions.h"
#include "base/numbers.h"
#include "base/text.h"
#include "base/timings.h"
#include "io/calibration_files.h"
#include "workflows/ensemble/ensemble.h"
#include "workflows/wear/wear_run.h"

#include <deal.II/base/mpi.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>

namespace wearlink::workflows
{
  CalibrationOptions
  calibration_options(CalibrationOptions o,
                      const double       members,
                      const double       seed,
                      const double       perturbation,
                      const double       tolerance,
                      const double       max_runs)
  {
    if (!(members >= 1 && members <= 1000 && members == std::floor(members)))
      throw InputError("--ensemble " + format_number(members) + ": a whole number from 1 to 1000 (1: no ensemble).");
    if (!(seed >= 0 && seed <= 9007199254740992.0 && seed == std::floor(seed)))
      throw InputError("--seed " + format_number(seed) + ": the seed must be a whole number from 0 to 2^53.");
    if (!(max_runs >= 1 && max_runs <= 100 && max_runs == std::floor(max_runs)))
      throw InputError("--max-runs " + format_number(max_runs) + ": a whole number from 1 to 100.");
    if (!(perturbation > 0 && perturbation <= 1e-3))
      throw InputError("--perturbation " + format_number(perturbation) + ": > 0 and at most 1e-3 rad.");
    if (!(tolerance > 0 && tolerance < 1))
      throw InputError("--tolerance " + format_number(tolerance) + ": a relative residual > 0 and < 1.");
    o.members          = static_cast<unsigned int>(members);
    o.seed             = static_cast<std::uint64_t>(seed);
    o.perturbation     = perturbation;
    o.secant.tolerance = tolerance;
    o.secant.max_runs  = static_cast<unsigned int>(max_runs);
    return o;
  }

  CalibrationProblem
  load_calibration(const CalibrationOptions &options)
  {
    CalibrationProblem p{io::read_scene(options.scene_file, options.overrides), {}};
    if (!has_wear(p.scene))
      throw InputError("`wearlink calibrate` identifies wear coefficients, but no clearance joint of " +
                       options.scene_file + " has 'Wear law = archard'.");
    p.measurements = io::read_measurements(options.measurements_file, p.scene);
    // A fixed wear loop reaches R revolutions with the factor R / (simulated cycles) ≥ 1.
    const auto  &w         = p.scene.wear_loop;
    const double simulated = w.cycles_per_iteration * w.n_iterations;
    for (const auto &m : p.measurements.surfaces)
      if (w.extrapolation == wear::Extrapolation::fixed && m.revolutions < simulated)
        throw InputError("In " + p.measurements.file + ": 'Joint " + m.joint + "/Revolutions' is " +
                         format_number(m.revolutions, 6) + ", fewer than the " + format_number(simulated, 6) +
                         " cycles " + options.scene_file +
                         " simulates (Wear/Cycles per iteration × Number of iterations): the extrapolation factor "
                         "would be < 1. Lower those with --set.");
    return p;
  }

  namespace
  {
    /** MPI_COMM_WORLD's rank and size (0 and 1 without MPI). */
    std::pair<unsigned int, unsigned int>
    rank_and_size()
    {
      int initialised = 0;
      MPI_Initialized(&initialised);
      if (!initialised)
        return {0u, 1u};
      return {dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD),
              dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD)};
    }

    /** The run's state of the problem: the groups of surfaces by revolutions, the counters. */
    struct Calibration
    {
      CalibrationProblem       &problem;
      const CalibrationOptions &options;
      std::vector<double>       revolutions; ///< the distinct revolution counts
      unsigned int              forward_runs = 0;
      bool                      root         = true;
      Stopwatch                 wall;

      const std::vector<io::SurfaceMeasurement> &
      surfaces() const
      {
        return problem.measurements.surfaces;
      }
    };

    /** The overrides of a forward run at @p k of the surfaces measured after @p revolutions. */
    ParameterOverrides
    forward_overrides(const Calibration &c, const std::vector<double> &k, const double revolutions)
    {
      ParameterOverrides o = c.options.overrides;
      for (std::size_t s = 0; s < k.size(); ++s)
        o.set(io::wear_coefficient_entry(c.surfaces()[s].joint, c.surfaces()[s].surface), k[s]);
      const auto &w = c.problem.scene.wear_loop;
      if (w.extrapolation == wear::Extrapolation::fixed)
        o.set("Wear/Extrapolation factor", revolutions / (w.cycles_per_iteration * w.n_iterations));
      else
        o.set("Wear/Target revolutions", revolutions);
      return o;
    }

    /** One wear run (nothing written) with @p overrides that must reach @p revolutions: its final state. */
    wear::WearState
    run_forward(const Calibration &c, const ParameterOverrides &overrides, const double revolutions)
    {
      io::Scene      scene = io::read_scene(c.options.scene_file, overrides);
      WearRunOptions w;
      w.progress      = false;
      w.final_outputs = false;
      auto r          = run_wear(scene, w);
      if (r.state.revolutions < revolutions * (1 - 1e-9))
        throw InputError("The wear loop of " + c.options.scene_file + " ended at " +
                         format_number(r.state.revolutions, 6) + " revolutions, before the measured " +
                         format_number(revolutions, 6) +
                         " (Wear/Number of iterations caps the adaptive loop); raise "
                         "it with --set \"Wear/Number of iterations=...\".");
      return std::move(r.state);
    }

    /** One wear run with @p overrides → the mass loss [mg] of each surface measured after @p revolutions (else NaN). */
    std::vector<double>
    mass_losses(const Calibration &c, const ParameterOverrides &overrides, const double revolutions)
    {
      const auto          state = run_forward(c, overrides, revolutions);
      std::vector<double> m(c.surfaces().size(), NAN);
      for (std::size_t s = 0; s < m.size(); ++s)
        for (std::size_t j = 0; j < state.joints.size(); ++j)
          if (c.surfaces()[s].revolutions == revolutions &&
              io::whole_joint(c.problem.scene, state.joints[j].name) == c.surfaces()[s].joint)
            {
              // The densities are data of the scene, not calibrated: the prior scene's. A
              // sliced joint's slices add up to its surfaces.
              const auto &h   = state.joints[j].history;
              const auto &a   = c.problem.scene.wear[j]->archard;
              const bool  pin = c.surfaces()[s].surface == "pin";
              m[s]            = (std::isnan(m[s]) ? 0. : m[s]) +
                     (h.empty() ?
                        0. :
                        (pin ? h.back().volume_pin * a.pin_density : h.back().volume_bore * a.bushing_density) * 1e6);
            }
      return m;
    }

    /** The secant's forward model: a run per revolution count at @p k; every surface's mass loss [mg]. */
    std::vector<double>
    forward(Calibration &c, const std::vector<double> &k)
    {
      std::vector<double> m(k.size(), NAN);
      for (const double r : c.revolutions)
        {
          const auto part = mass_losses(c, forward_overrides(c, k, r), r);
          ++c.forward_runs;
          for (std::size_t s = 0; s < m.size(); ++s)
            if (!std::isnan(part[s]))
              m[s] = part[s];
        }
      for (std::size_t s = 0; s < m.size(); ++s)
        if (!(m[s] > 0))
          throw InputError("The forward run of " + c.options.scene_file + " at " +
                           io::wear_coefficient_entry(c.surfaces()[s].joint, c.surfaces()[s].surface) + " = " +
                           format_number(k[s], 6) + " predicts no wear of joint " + c.surfaces()[s].joint + "'s " +
                           c.surfaces()[s].surface + " (mass loss " + format_number(m[s], 6) +
                           " mg): its coefficient cannot be calibrated from " + c.problem.measurements.file + ".");
      return m;
    }

    /** The progress line of secant run @p run. */
    void
    report_run(const Calibration &c, const unsigned int run, const std::vector<double> &k, const std::vector<double> &m)
    {
      if (!c.options.progress || !c.root)
        return;
      std::ostringstream os;
      os << "[wearlink] calibrate: secant run " << run + 1 << "/" << c.options.secant.max_runs << std::setprecision(4);
      for (std::size_t s = 0; s < k.size(); ++s)
        os << "  " << c.surfaces()[s].joint << " " << c.surfaces()[s].surface << ": k " << k[s] << " → " << m[s]
           << " mg (measured " << c.surfaces()[s].mass_loss << ", " << std::showpos
           << 100 * (m[s] / c.surfaces()[s].mass_loss - 1) << std::noshowpos << " %)";
      os << "  (" << std::setprecision(3) << c.wall.seconds() << " s so far)\n";
      std::cerr << os.str();
    }

    /** One ensemble member at @p k: its mass losses [mg], or its failure's message. */
    Json
    run_member(Calibration &c, const std::vector<double> &k, const unsigned int n)
    {
      const EnsembleRequest request{c.options.members, c.options.seed, c.options.perturbation};
      const Stopwatch       wall;
      Json                  out = {{"index", n}};
      try
        {
          std::vector<double> m(k.size(), NAN);
          for (const double r : c.revolutions)
            {
              const auto part =
                mass_losses(c, member_overrides(c.problem.scene, forward_overrides(c, k, r), request, n), r);
              for (std::size_t s = 0; s < m.size(); ++s)
                if (!std::isnan(part[s]))
                  m[s] = part[s];
            }
          out["mass_loss_mg"] = m;
        }
      catch (const NumericalError &e)
        {
          out["failed"] = trim(e.message());
        }
      if (c.options.progress)
        std::cerr << "[wearlink] calibrate: ensemble member " << n + 1 << "/" << c.options.members
                  << (out.contains("failed") ? " failed" : " done") << " in " << std::setprecision(3) << wall.seconds()
                  << " s (" << c.wall.seconds() << " s so far)\n";
      return out;
    }

    /** The members at @p k over the ranks (member n on rank n mod R), gathered on every rank in member order. */
    std::vector<Json>
    run_members(Calibration &c, const std::vector<double> &k)
    {
      const auto [rank, size] = rank_and_size();
      Json mine               = Json::array();
      for (unsigned int n = rank; n < c.options.members; n += size)
        mine.push_back(run_member(c, k, n));
      std::vector<std::string> texts = {mine.dump(-1)};
      if (size > 1)
        texts = dealii::Utilities::MPI::all_gather(MPI_COMM_WORLD, mine.dump(-1));
      std::vector<Json> members(c.options.members);
      for (const auto &text : texts)
        for (const auto &m : Json::parse(text))
          members[m.at("index").get<std::size_t>()] = m;
      c.forward_runs += c.options.members * static_cast<unsigned int>(c.revolutions.size());
      return members;
    }

    /** Surface @p s's mass losses over the members that ran. */
    std::vector<double>
    member_values(const std::vector<Json> &members, const std::size_t s)
    {
      std::vector<double> v;
      for (const auto &m : members)
        if (m.contains("mass_loss_mg"))
          v.push_back(json_number(m.at("mass_loss_mg")[s]));
      return v;
    }

    /** The prior coefficient of each measured surface [m³/(N m)], as the scene sets it. */
    std::vector<double>
    prior_coefficients(const Calibration &c)
    {
      std::vector<double> k0;
      for (const auto &m : c.surfaces())
        for (const auto &w : c.problem.scene.wear)
          if (io::whole_joint(c.problem.scene, w->joint) == m.joint) // a sliced joint's: its first slice's
            {
              k0.push_back(m.surface == "pin" ? w->archard.pin_coefficient : w->archard.bushing_coefficient);
              break;
            }
      return k0;
    }

    /** joints.<J>.<surface>_* of calibration.json for surface @p s. */
    void
    add_surface(Json                           &joints,
                const Calibration              &c,
                const std::size_t               s,
                const analysis::CoefficientFit &fit,
                const std::vector<double>      &values,
                const double                    prior)
    {
      const auto &meas = c.surfaces()[s];
      const auto  f    = analysis::ensemble_figure(values);
      // σ_c: the measured test is one chaotic sample (scatter s about the mean), the mean is known to s/√N.
      const double std = values.size() > 1 ? f.std : 0, sigma_mean = std / std::sqrt(double(values.size()));
      const double sigma_chaos = std::hypot(std, sigma_mean);
      const double k           = analysis::corrected_coefficient(fit.k[s], meas.mass_loss, f.mean, fit.slope[s]);
      const auto   ci =
        analysis::coefficient_interval(k, meas.mass_loss, meas.uncertainty, f.mean, sigma_chaos, fit.slope[s]);
      Json secant = Json::array();
      for (const auto &p : fit.history[s])
        secant.push_back({{"k", std::exp(p.log_k)},
                          {"predicted_mg", meas.mass_loss * std::exp(p.residual)},
                          {"relative_residual", std::expm1(p.residual)}});
      Json &j                               = joints[meas.joint];
      j["revolutions"]                      = meas.revolutions;
      j[meas.surface + "_wear_coefficient"] = {{"value", k},
                                               {"ci95_low", ci.low},
                                               {"ci95_high", ci.high},
                                               {"sigma_log_k", ci.sigma_log_k},
                                               {"prior", prior},
                                               {"secant_value", fit.k[s]},
                                               {"slope_dlogm_dlogk", fit.slope[s]},
                                               {"unit", "m^3/(N m)"}};
      j[meas.surface + "_mass_loss_mg"]     = {{"measured", meas.mass_loss},
                                               {"measured_uncertainty", meas.uncertainty},
                                               {"predicted_mean", f.mean},
                                               {"predicted_std", std},
                                               {"predicted_std_of_mean", sigma_mean},
                                               {"chaos_uncertainty", sigma_chaos},
                                               {"predicted_members", values},
                                               {"relative_residual_of_mean", f.mean / meas.mass_loss - 1},
                                               {"predicted_at_value", f.mean * std::pow(k / fit.k[s], fit.slope[s])}};
      j[meas.surface + "_mass_loss_mg"]["measured_by"] =
        meas.from_profile.empty() ? std::string("weighing") : "the worn area of " + meas.from_profile;
      j[meas.surface + "_secant"] = {{"runs", secant}, {"relative_residual", fit.predicted[s] / meas.mass_loss - 1}};
    }

    /** Everything of calibration.json but the per-surface blocks. */
    Json
    report_header(const Calibration &c, const analysis::CoefficientFit &fit, const std::vector<Json> &members)
    {
      Json failed = Json::array();
      for (const auto &m : members)
        if (m.contains("failed"))
          failed.push_back(m);
      return {{"command", "calibrate"},
              {"scene", c.options.scene_file},
              {"measurements", c.problem.measurements.file},
              {"overrides", c.options.overrides.settings()},
              {"method",
               "secant on log k from the prior with whole wear runs of the unperturbed scene, then an "
               "ensemble at the secant's k; value = k_secant (measured / ensemble mean)^(1/slope)"},
              {"interval",
               "95 %: value exp(±1.96 σ), σ = sqrt((σ_m/m)² + (σ_c/m̄)²) / |slope|, σ_m the measurement's 1σ, "
               "σ_c = s sqrt(1 + 1/N) (chaos_uncertainty) with s the std of the N ensemble runs: the measured test "
               "is one chaotic sample (scatter s), the mean is known to s/√N; 0 without ensemble"},
              {"secant",
               {{"tolerance", c.options.secant.tolerance},
                {"max_runs", c.options.secant.max_runs},
                {"runs", fit.runs},
                {"converged", fit.converged},
                {"located", fit.located},
                {"stop",
                 fit.converged ? "every relative residual below the tolerance" :
                 fit.located   ? "every root bracketed within the tolerance in log k (the chaotic scatter of single "
                                 "runs is larger than the tolerance)" :
                                 "the run limit"}}},
              {"ensemble",
               {{"members", c.options.members},
                {"seed", c.options.seed},
                {"perturbation_rad", c.options.perturbation},
                {"mpi_ranks", rank_and_size().second},
                {"failed", failed}}},
              {"iterations", fit.runs},
              {"joints", Json::object()}};
    }

    /**
     * calibrated.prm: the effective scene (every entry as the scene reader holds it, the
     * user's --set applied, the includes resolved) with the calibrated coefficients, so
     * that the file stands alone; a comment on top names the measurements and intervals.
     */
    std::string
    calibrated_scene(const Calibration &c, const Json &report)
    {
      ParameterOverrides o = c.options.overrides;
      std::ostringstream os;
      os << std::setprecision(6) << "# " << c.options.scene_file << " calibrated by `wearlink calibrate` against the "
         << "measured mass losses of " << c.problem.measurements.file << " (calibration.json beside this file).\n"
         << "# The whole effective scene (includes resolved";
      if (!c.options.overrides.empty())
        os << "; --set " << join(c.options.overrides.settings(), ", --set ");
      os << ") with the calibrated wear coefficients [m³/(N m)], value and 95 % interval:\n";
      for (const auto &m : c.surfaces())
        {
          const Json &k = report.at("joints").at(m.joint).at(m.surface + "_wear_coefficient");
          o.set(io::wear_coefficient_entry(m.joint, m.surface), json_number(k.at("value")));
          os << "#   " << io::wear_coefficient_entry(m.joint, m.surface) << " = " << json_number(k.at("value")) << "  ["
             << json_number(k.at("ci95_low")) << ", " << json_number(k.at("ci95_high")) << "] (prior "
             << json_number(k.at("prior")) << ")\n";
        }
      os << "# Relative file names in it (profile and mesh files) are as the scene gave them.\n";
      const io::Scene scene = io::read_scene(c.options.scene_file, o);
      scene.parameters->print_parameters(os, dealii::ParameterHandler::ShortText);
      return os.str();
    }

    /** joints.<J>.<surface>_profile of one measured profile against the worn surface of @p state. */
    Json
    profile_report(const io::ProfileMeasurement &p, const wear::WearState &state)
    {
      for (const auto &j : state.joints)
        if (j.name == p.joint)
          {
            const bool pin = p.surface == "pin";
            const auto cmp =
              analysis::compare_profile(p.trace,
                                        analysis::PolarTrace::of_profile(pin ? j.pin : j.bore),
                                        analysis::PolarTrace::of_profile(pin ? j.initial_pin : j.initial_bore),
                                        pin ? analysis::WornSurface::pin : analysis::WornSurface::bore,
                                        p.angle_search * numbers::pi / 180);
            return {{"file", p.file},
                    {"uncertainty_m", p.uncertainty},
                    {"rotation_deg", cmp.alignment.rotation * 180 / numbers::pi},
                    {"rms_difference_m", cmp.alignment.difference.rms},
                    {"rms_over_uncertainty", cmp.alignment.difference.rms / p.uncertainty},
                    {"largest_difference_m", cmp.alignment.difference.largest},
                    {"worn_area_measured_m2", cmp.worn_area_measured},
                    {"worn_area_predicted_m2", cmp.worn_area_predicted},
                    {"max_depth_measured_m", cmp.max_depth_measured},
                    {"max_depth_predicted_m", cmp.max_depth_predicted}};
          }
      return Json();
    }

    /**
     * The measured profiles against one unperturbed run at the calibrated coefficients per
     * revolution count (a check, not part of the fit), into joints.<J>.<surface>_profile.
     */
    void
    add_profiles(Json &report, Calibration &c)
    {
      std::vector<double> k;
      for (const auto &m : c.surfaces())
        k.push_back(json_number(report.at("joints").at(m.joint).at(m.surface + "_wear_coefficient").at("value")));
      for (const double r : c.revolutions)
        {
          bool any = false;
          for (const auto &p : c.problem.measurements.profiles)
            any = any || p.revolutions == r;
          if (!any)
            continue;
          const auto state = run_forward(c, forward_overrides(c, k, r), r);
          ++c.forward_runs;
          for (const auto &p : c.problem.measurements.profiles)
            if (p.revolutions == r)
              report["joints"][p.joint][p.surface + "_profile"] = profile_report(p, state);
        }
      if (c.options.progress && c.root && !c.problem.measurements.profiles.empty())
        std::cerr << "[wearlink] calibrate: profiles compared at the calibrated coefficients (" << std::setprecision(3)
                  << c.wall.seconds() << " s so far)\n";
    }
  } // namespace

  Json
  calibrate(CalibrationProblem &problem, const CalibrationOptions &options)
  {
    Calibration c{problem, options, {}, 0, true, Stopwatch()};
    c.root = rank_and_size().first == 0;
    for (const auto &m : c.surfaces())
      if (std::find(c.revolutions.begin(), c.revolutions.end(), m.revolutions) == c.revolutions.end())
        c.revolutions.push_back(m.revolutions);
    const auto          prior = prior_coefficients(c);
    std::vector<double> measured;
    for (const auto &m : c.surfaces())
      measured.push_back(m.mass_loss);
    const auto fit =
      analysis::fit_coefficients([&c](const std::vector<double> &k) { return forward(c, k); },
                                 prior,
                                 measured,
                                 options.secant,
                                 [&c](unsigned int r, const auto &k, const auto &m) { report_run(c, r, k, m); });
    const auto members = options.members > 1 ? run_members(c, fit.k) : std::vector<Json>();
    Json       report  = report_header(c, fit, members);
    for (std::size_t s = 0; s < c.surfaces().size(); ++s)
      {
        const auto values = options.members > 1 ? member_values(members, s) : std::vector<double>{fit.predicted[s]};
        if (values.empty())
          throw NumericalError("Every member of the calibration's ensemble failed: " +
                               members.front().at("failed").get<std::string>());
        add_surface(report["joints"], c, s, fit, values, prior[s]);
      }
    add_profiles(report, c);
    report["forward_runs"] = c.forward_runs;
    report["wall_time_s"]  = c.wall.seconds();
    if (c.root && !options.output_directory.empty())
      io::write_calibration_files(options.output_directory, report, calibrated_scene(c, report));
    return report;
  }
} // namespace wearlink::workflows

namespace wearlink::workflows
{
  std::string
  calibration_table(const Json &report)
  {
    std::ostringstream os;
    os << std::setprecision(4) << "calibrated wear coefficients [m^3/(N m)] (95 % interval) and mass losses [mg]:\n";
    for (auto j = report.at("joints").begin(); j != report.at("joints").end(); ++j)
      for (const std::string surface : {"pin", "bushing"})
        if (j.value().contains(surface + "_wear_coefficient"))
          {
            const Json &k = j.value().at(surface + "_wear_coefficient");
            const Json &m = j.value().at(surface + "_mass_loss_mg");
            os << "  " << j.key() << " " << surface << ": k = " << json_number(k.at("value")) << " ["
               << json_number(k.at("ci95_low")) << ", " << json_number(k.at("ci95_high")) << "] (prior "
               << json_number(k.at("prior")) << "); measured " << json_number(m.at("measured")) << " ± "
               << json_number(m.at("measured_uncertainty")) << ", predicted " << json_number(m.at("predicted_mean"))
               << " ± " << json_number(m.at("predicted_std")) << " (std over " << m.at("predicted_members").size()
               << " runs at k " << json_number(k.at("secant_value")) << ")\n";
          }
    os << "  " << json_number(report.at("forward_runs")) << " forward runs (" << json_number(report.at("iterations"))
       << " secant, stopped at " << report.at("secant").at("stop").get<std::string>() << "), "
       << json_number(report.at("wall_time_s")) << " s\n";
    return os.str();
  }
} // namespace wearlink::workflows
