// SPDX-License-Identifier: LGPL-2.1-or-later
#include "workflows/wear/wear_run.h"

#include "analysis/cycle_peaks.h"
#include "base/atomic_file.h"
#include "base/exceptions.h"
#include "base/text.h"
#include "io/output_names.h"
#include "io/profile_series.h"
#include "io/scene_periods.h"
#include "io/slice_outputs.h"
#include "io/wear_outputs.h"
#include "mbs/assembly.h"
#include "mbs/constraint.h"
#include "wear/slice_checks.h"
#include "wear/wear_loop.h"
#include "workflows/run/analyses.h"
#include "workflows/run/run.h"
#include "workflows/wear/scene_identity.h"
#include "workflows/wear/wear_dynamics_comparison.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace wearlink::workflows
{
  /**
   * What a wear run takes from its scene, read once. Outside the anonymous namespace
   * because WearRun::Members holds one (GCC's -Wsubobject-linkage in a unity build).
   */
  struct WearSetup
  {
    double                          period   = 0; ///< one wear cycle [s]
    int                             response = 0; ///< index of the response body
    std::string                     response_name;
    std::vector<wear::WearingJoint> wearing; ///< in the order of scene.wear
  };

  namespace
  {
    WearSetup
    wear_setup(io::Scene &scene)
    {
      WearSetup s;
      s.period        = io::cycle_period(scene);
      s.response      = io::response_body(scene);
      s.response_name = scene.mechanism->get_bodies()[s.response].name;
      for (const auto &w : scene.wear)
        for (auto *j : scene.clearance_joints)
          if (j->name() == w->joint)
            s.wearing.push_back({j, w.get()});
      AssertThrow(s.wearing.size() == scene.wear.size(), dealii::ExcInternalError());
      return s;
    }

    /**
     * The scene's dynamics as the wear loop advances them (no analyses per iteration).
     * Their validity warnings go into @p warnings named as the iterations' ("wear
     * iterations' dynamics: largest constraint violation …", the largest over them): the
     * summary's dynamics figures are those of the response run after wear.
     */
    wear::AdvanceDynamics
    dynamics_of(io::Scene &scene, ValidityWarnings &warnings)
    {
      return [&scene, &warnings](const double                            t0,
                                 const double                            t1,
                                 const Eigen::VectorXd                  &y0,
                                 wear::LoadRecorder                     *loads,
                                 const std::vector<mbs::StepObserver *> &observers) {
        Eigen::VectorXd y1;
        RunOptions      ro;
        ro.initial_state = &y0;
        ro.start_time    = t0;
        ro.end_time      = t1;
        ro.final_state   = &y1;
        ro.loads         = loads;
        ro.observers     = observers;
        ro.analyses      = false; // the scene's analyses run before and after wear instead
        ValidityWarnings own;
        ro.warnings = &own;
        integrate_scene(scene, ro);
        for (auto w : own.warnings())
          {
            w.quantity = "wear iterations' dynamics: " + w.quantity;
            warnings.check(w);
          }
        return y1;
      };
    }

    /**
     * How the wear loop carries the mechanism's state onto worn profiles: every clearance
     * joint (a sliced joint by its first slice) pinned at its target eccentricity as a revolute with that offset (as the
     * scene's assembly pins them at their initial ones), positions moved by the least
     * change that satisfies them and the mechanism, velocities kept on the mechanism's
     * constraints (mbs::carry).
     */
    wear::CarryState
    carry_of(io::Scene &scene)
    {
      return [&scene](const double t, Eigen::VectorXd &y, const std::vector<mbs::Vec2> &eccentricities) {
        std::vector<std::unique_ptr<mbs::Constraint>> pins;
        for (std::size_t k = 0; k < scene.clearance_joints.size(); ++k)
          {
            const auto &d = scene.clearance_joints[k]->get_description();
            const auto &e = eccentricities[k];
            if (d.slice.index > 0) // a sliced joint's pin: its first slice pins it
              continue;
            pins.push_back(d.pin_body == mbs::ground ?
                             mbs::make_revolute(d.name, d.pin_body, d.pin_point, d.bushing_body, d.bushing_point, -e) :
                             mbs::make_revolute(d.name, d.bushing_body, d.bushing_point, d.pin_body, d.pin_point, e));
          }
        const auto      n = scene.mechanism->n_coordinates();
        Eigen::VectorXd q = y.head(n), v = y.segment(n, n);
        mbs::carry(*scene.mechanism, t, pins, {}, q, v);
        y.head(n)       = q;
        y.segment(n, n) = v;
      };
    }

    /**
     * The state of a checkpoint must be one the mechanism can be in: finite, with its
     * bodies on their joints (largest |Φ| at most a millimetre, far above what a run's
     * constraint-violation warning allows and far below a state of another place). A
     * state edited or damaged behind an intact checksum is refused here, instead of
     * being integrated into NaN.
     */
    void
    check_state_on_the_joints(const io::Scene &scene, const wear::WearState &st, const std::string &checkpoint)
    {
      constexpr double  largest_violation = 1e-3; // [m] (rad for angle rows)
      const auto       &mech              = *scene.mechanism;
      const auto        n                 = mech.n_coordinates();
      const std::string cannot            = "Cannot resume from '" + checkpoint + "': ";
      for (Eigen::Index i = 0; i < st.state.size(); ++i)
        if (!std::isfinite(st.state[i]))
          throw InputError(cannot + "its state[" + std::to_string(i) + "] is not a finite number: it is damaged.");
      Eigen::VectorXd phi, phi_t, gamma;
      Eigen::MatrixXd jacobian;
      mech.evaluate_constraints(st.time, st.state.data(), st.state.data() + n, phi, jacobian, phi_t, gamma);
      Eigen::Index worst = 0;
      if (phi.size() > 0 && !(phi.cwiseAbs().maxCoeff(&worst) <= largest_violation))
        throw InputError(cannot + "its state puts the bodies " + format_number(std::abs(phi[worst]), 3) +
                         " off their joints (constraint row " + std::to_string(worst) + "; at most " +
                         format_number(largest_violation) +
                         " m is a state of this mechanism): it was edited or damaged behind its checksum. Start "
                         "afresh (`--overwrite`).");
    }

    /**
     * The checkpoint of a resumed run, refused (InputError naming what differs, with both
     * values) unless it was written for this scene and fits its sizes.
     */
    wear::WearState
    checked_checkpoint(const io::Scene &scene, const std::string &checkpoint)
    {
      auto       st      = wear::WearState::read(checkpoint);
      const auto entries = scene_entries(scene);
      if (st.fingerprint != fingerprint(entries) || st.scene != entries)
        {
          const std::string differences = scene_differences(st.scene, entries);
          throw InputError(
            "Cannot resume from '" + checkpoint + "': it was written for another scene than " + scene.file +
            " with these settings: " + (differences.empty() ? "its fingerprint differs" : differences) +
            ". Resume with the scene and --set options the run was started with (only Output/*, "
            "Wear/Number of iterations, Wear/Target revolutions, Wear/FE output, Wear/Profile "
            "magnification, Life/Maximum revolutions and Life/Maximum iterations may change), or start afresh (`--overwrite`).");
        }
      wear::StateShape shape;
      const auto       n = scene.mechanism->n_coordinates();
      shape.n_state      = 2 * n + mbs::MechanismOde::n_quadratures;
      shape.n_modes      = 2 * scene.clearance_joints.size();
      for (const auto &w : scene.wear)
        for (const auto *j : scene.clearance_joints)
          if (j->name() == w->joint)
            shape.joints.push_back(
              {j->name(), j->get_description().geometry.bore.n_points(), j->get_description().geometry.pin.n_points()});
      st.check_shape(shape, checkpoint);
      check_state_on_the_joints(scene, st, checkpoint);
      return st;
    }

    /** Start @p loop from the scene's assembly, or resume it from its checkpoint. */
    void
    start_or_resume(wear::WearLoop       &loop,
                    io::Scene            &scene,
                    const WearRunOptions &options,
                    const std::string    &checkpoint)
    {
      if (options.resume)
        {
          loop.resume(checked_checkpoint(scene, checkpoint), checkpoint);
          return;
        }
      if (!options.output_directory.empty())
        {
          make_output_directory(options.output_directory);
          std::error_code ec;
          std::filesystem::remove(checkpoint, ec); // a fresh run never continues an old one
        }
      Eigen::VectorXd q0, v0;
      assemble_scene(scene, q0, v0);
      const auto entries = scene_entries(scene);
      loop.start(scene.start_time, q0, v0, fingerprint(entries), entries);
    }

    /** The progress line of an iteration: revolutions, factor, depths and volume per joint. */
    std::string
    progress_line(const wear::WearLoop &loop,
                  const unsigned int    n_iterations,
                  const double          seconds,
                  const std::string    &prefix)
    {
      const auto        &st = loop.state();
      std::ostringstream os;
      os << prefix << "wear iteration " << st.iterations_done << '/' << n_iterations << "  revolutions "
         << std::setprecision(6) << st.revolutions << "  factor " << loop.last_factor();
      for (const auto &j : st.joints)
        {
          const auto &r = j.history.back();
          os << "  " << j.name << ": h_pin " << std::setprecision(3) << r.max_depth_pin * 1e6 << " µm, h_bore "
             << r.max_depth_bore * 1e6 << " µm, V " << (r.volume_pin + r.volume_bore) * 1e9 << " mm³";
        }
      os << "  (" << std::setprecision(3) << seconds << " s)";
      return os.str();
    }

    /** The wear figures of each wearing joint, into summary["clearance_joints"][J]. */
    void
    add_wear_summary(Json &summary, const io::Scene &scene, const wear::WearState &st)
    {
      auto &cj = summary["clearance_joints"];
      for (unsigned int i = 0; i < st.joints.size(); ++i)
        {
          const auto                 &js     = st.joints[i];
          const auto                 &w      = *scene.wear[i];
          const wear::IterationRecord r      = js.history.empty() ? wear::IterationRecord() : js.history.back();
          auto                       &o      = cj[js.name];
          o["pressure_model"]                = w.pressure_model;
          o["wear_volume_pin_m3"]            = r.volume_pin;
          o["wear_volume_bushing_m3"]        = r.volume_bore;
          o["archard_volume_pin_m3"]         = r.archard_pin;
          o["archard_volume_bushing_m3"]     = r.archard_bore;
          o["max_wear_depth_pin_m"]          = r.max_depth_pin;
          o["max_wear_depth_bushing_m"]      = r.max_depth_bore;
          o["envelope_wear_depth_pin_m"]     = r.envelope_depth_pin;
          o["envelope_wear_depth_bushing_m"] = r.envelope_depth_bore;
          o["roughness_pin"]                 = r.roughness_pin;
          o["roughness_bushing"]             = r.roughness_bore;
          o["contact_width_m"]               = js.contact_width;
          o["mass_loss_pin_mg"]              = r.volume_pin * w.archard.pin_density * 1e6;
          o["mass_loss_bushing_mg"]          = r.volume_bore * w.archard.bushing_density * 1e6;
          o["revolutions"]                   = st.revolutions;
          o["relative_revolutions"]          = r.relative_revolutions;
          o["sliding_distance_m"]            = r.sliding_distance;
          o["mean_normal_force_N"]           = r.mean_normal_force;
          const auto &u                      = js.start_up;
          o["wear_start_up"]                 = {{"settling_cycles", st.settling_cycles},
                                                {"settling_impacts", u.impacts},
                                                {"settling_mean_normal_force_N", u.mean_normal_force},
                                                {"settling_peak_normal_force_N", u.peak_normal_force},
                                                {"first_iteration_mean_normal_force_N",
                                 js.history.empty() ? 0.0 : js.history.front().mean_normal_force},
                                                {"carried_iterations", u.carries},
                                                {"largest_carry_m", u.largest_carry},
                                                {"carries_not_matched", u.carry_failures}};
        }
      summary["wear_iterations"]  = st.iterations_done;
      summary["wear_revolutions"] = st.revolutions;
    }

    /**
     * The peak acceleration magnitude of the response body over every accepted step, in
     * the Wear/Response cycles after the settling cycles from the initial assembly,
     * before wear (the first iteration's start, kept in the checkpoint; @p before its
     * per-cycle peaks) and after wear: the largest over them, the mean of the per-cycle
     * peaks (without settling cycles, after the first: the start-up; with one response
     * cycle, that one), and the ratios after/before.
     */
    Json
    response_block(const WearSetup                   &setup,
                   const wear::WearLoopSettings      &ws,
                   const std::vector<double>         &before,
                   const analysis::CyclePeakRecorder &after)
    {
      const double cycles = ws.response_cycles;
      const auto   whole  = static_cast<std::size_t>(std::max(1.0, std::floor(cycles + 1e-9)));
      // Settled before (Wear/Settling cycles), every response cycle is measured; from
      // the assembly, the first is the start-up.
      const auto settle  = std::size_t(ws.settling_cycles > 0 || whole < 2 ? 0 : 1);
      const auto measure = [&](const std::vector<double> &peaks, double &largest, double &mean) {
        const auto n = std::min(whole, peaks.size());
        largest = mean = 0;
        for (std::size_t k = 0; k < n; ++k)
          largest = std::max(largest, peaks[k]);
        for (std::size_t k = settle; k < n; ++k)
          mean += peaks[k] / (n - settle);
        return n > settle;
      };
      Json r                     = Json::object();
      r["body"]                  = setup.response_name;
      r["cycles"]                = cycles;
      r["settling_cycles"]       = ws.settling_cycles; // before the response cycles
      r["first_cycles_left_out"] = settle;             // of the mean per-cycle peaks
      double a_largest = 0, a_mean = 0, b_largest = 0, b_mean = 0;
      if (measure(after.peaks(), a_largest, a_mean))
        {
          r["peak_acceleration_after_m_s2"] = a_largest;
          r["mean_cycle_peak_after_m_s2"]   = a_mean;
        }
      if (measure(before, b_largest, b_mean) && b_largest > 0)
        {
          r["peak_acceleration_before_m_s2"] = b_largest;
          r["mean_cycle_peak_before_m_s2"]   = b_mean;
          r["peak_acceleration_ratio"]       = a_largest / b_largest;
          r["mean_cycle_peak_ratio"]         = a_mean / b_mean;
        }
      return r;
    }

    /**
     * Warn when an adaptive run ended at its Number of iterations before its Target
     * revolutions: the results stand for fewer revolutions than the scene asked for.
     */
    void
    check_target_reached(const wear::WearLoopSettings &ws, const wear::WearState &st, ValidityWarnings &warnings)
    {
      if (ws.extrapolation != wear::Extrapolation::adaptive || st.iterations_done < ws.n_iterations)
        return;
      warnings.check({"revolutions short of Wear/Target revolutions",
                      ws.target_revolutions - st.revolutions,
                      1e-9 * ws.target_revolutions,
                      "cycles",
                      "the run ended at its Number of iterations (" + std::to_string(ws.n_iterations) +
                        ") having represented " + format_number(st.revolutions, 6) + " of " +
                        format_number(ws.target_revolutions, 6) + " revolutions",
                      "the worn profiles and volumes stand for fewer revolutions than the target; raise Number of "
                      "iterations, Maximum extrapolation factor or Maximum depth increment"});
    }

    /**
     * After the loop: the response after wear from the initial assembly with the final
     * profiles (its settling cycles first, as before wear), the summary, the worn profiles and plots, and the before/after-wear
     * comparison if the scene lists analyses.
     */
    void
    after_wear(io::Scene              &scene,
               const WearSetup        &setup,
               const WearRunOptions   &options,
               const ValidityWarnings *more_warnings,
               WearRunResult          &result)
    {
      const bool        write  = !options.output_directory.empty();
      const std::string dir    = options.output_directory;
      const double      period = setup.period;
      const auto       &ws     = scene.wear_loop;
      const auto       &st     = result.state;
      Stopwatch         outputs;
      for (auto *j : scene.clearance_joints)
        j->set_mode(false, 0);
      analysis::ResponseRecorder  after(*scene.mechanism, setup.response, period / 400, ws.response_cycles * period);
      analysis::CyclePeakRecorder after_peaks(scene.mechanism->n_coordinates(), setup.response, period);
      Stopwatch                   dynamics;
      // Measured as before wear: from the assembly, the Wear/Settling cycles first (the
      // start-up, not measured), then the response cycles.
      Eigen::VectorXd settled;
      double          start = scene.start_time;
      if (ws.settling_cycles > 0)
        {
          RunOptions so;
          so.end_time    = start + ws.settling_cycles * period;
          so.analyses    = false;
          so.final_state = &settled;
          ValidityWarnings ignored; // the settling is not part of the response run
          so.warnings = &ignored;
          integrate_scene(scene, so);
          start = so.end_time;
        }
      RunOptions ro;
      if (ws.settling_cycles > 0)
        {
          ro.initial_state = &settled;
          ro.start_time    = start;
        }
      ro.end_time    = start + std::max(ws.response_cycles, 1e-9) * period;
      ro.observers   = {&after, &after_peaks};
      ro.analyses    = false;
      ro.warnings    = &result.warnings;
      result.summary = integrate_scene(scene, ro).summary;
      if (more_warnings != nullptr)
        result.warnings.merge(*more_warnings);
      wear::check_roughness(st, result.warnings);
      wear::check_axial_increments(st, scene.clearance_joints, result.warnings);
      check_target_reached(ws, st, result.warnings);
      result.summary["warnings"] = result.warnings.json(); // every iteration's and this run's
      result.timings.dynamics += dynamics.seconds();
      add_wear_summary(result.summary, scene, st);
      if (io::has_sliced_joints(scene))
        result.summary["sliced_joints_wear"] = io::sliced_wear_summary(scene, st);
      result.summary["response"] = response_block(setup, ws, st.response_before_peaks, after_peaks);
      if (write)
        {
          io::write_wear_outputs(dir, scene, st, after); // the worn profile files first:
          io::write_sliced_wear_outputs(dir, scene, st);
          result.timings.outputs += outputs.seconds(); // the two-trajectory runs read them
        }
      if (scene.analyses.any())
        {
          Stopwatch                              comparison_time;
          std::vector<contact::ClearanceJoint *> wearing;
          for (const auto &w : setup.wearing)
            wearing.push_back(w.joint);
          auto comparison                      = before_after_dynamics(scene,
                                                  st,
                                                  wearing,
                                                  setup.response_name,
                                                  write ? dir : std::string(),
                                                  options.progress);
          result.timings.before_after_dynamics = comparison_time.seconds();
          result.summary["before_after"]       = comparison.json;
          result.before_after_report           = comparison.report;
        }
    }

    /** summary.json and parameters.prm of a finished wear run. */
    void
    write_run_files(const io::Scene &scene, const std::string &dir, WearRunResult &result)
    {
      result.summary["wear_timing_s"] = result.timings.to_json();
      write_run_summary(scene, dir, result.summary, result.warnings);
    }
  } // namespace

  bool
  has_wear(const io::Scene &scene)
  {
    return !scene.wear.empty();
  }

  namespace
  {
    /**
     * The profile series of an iteration (io/profile_series.h): per wearing joint the
     * worn surfaces, with the pressure its model gives at the iteration's largest load
     * on them (one evaluation per joint and iteration).
     */
    void
    write_profile_frames(const std::vector<wear::WearingJoint> &wearing,
                         const wear::WearLoop                  &loop,
                         const std::string                     &dir,
                         const wear::WearLoopSettings          &ws)
    {
      for (std::size_t i = 0; i < wearing.size(); ++i)
        {
          contact::SurfacePressure p;
          const auto              &peak = loop.peak_loads()[i];
          if (peak.normal_force > 0)
            wearing[i].wear->model->evaluate(peak, p);
          io::write_profile_frame(dir,
                                  loop.state(),
                                  static_cast<unsigned int>(i),
                                  p,
                                  ws.cycles_per_iteration,
                                  ws.every_iteration_output);
        }
    }

    /**
     * The FE files of an iteration (Wear/FE output): the mesh of every joint on the fe
     * pressure model when it changed since @p copied (its last copied mesh, per joint),
     * the fields at the iteration's peak load, and their collection fe/fields_<J>.pvd
     * (time: revolutions). Unless Wear/Output every iteration, the older meshes and
     * fields of the joint are removed, also those of a resumed run's earlier processes.
     */
    void
    write_fe_files(const std::vector<wear::WearingJoint> &wearing,
                   const wear::WearLoop                  &loop,
                   const std::string                     &dir,
                   const wear::WearLoopSettings          &ws,
                   std::vector<std::string>              &copied)
    {
      const double       cycles_per_iteration = ws.cycles_per_iteration;
      const unsigned int k                    = loop.state().iterations_done;
      copied.resize(wearing.size());
      for (std::size_t i = 0; i < wearing.size(); ++i)
        {
          auto *const       hooks = wearing[i].wear->model->fe_hooks();
          const std::string mesh  = hooks ? hooks->mesh_file() : std::string();
          if (mesh.empty())
            continue;
          const std::string name = wearing[i].joint->name();
          make_output_directory(dir + "/fe");
          if (mesh != copied[i])
            {
              copy_file_atomically(mesh, dir + "/fe/mesh_" + name + "_" + std::to_string(k) + ".msh");
              copied[i] = mesh;
              if (!ws.every_iteration_output)
                io::remove_series_files(dir + "/fe", "mesh_" + name + "_", ".msh", {k});
            }
          const std::string fields = dir + "/fe/fields_" + name + "_iteration";
          if (hooks->write_fields(loop.peak_loads()[i], fields + std::to_string(k)) && !ws.every_iteration_output)
            for (const char *suffix : {".vtu", "_pressure.csv"})
              io::remove_series_files(dir + "/fe", "fields_" + name + "_iteration", suffix, {k});
          std::vector<double>      times;
          std::vector<std::string> files;
          double                   revolutions = 0;
          for (unsigned int j = 1; j <= k && j <= loop.state().factors.size(); ++j)
            {
              revolutions += loop.state().factors[j - 1] * cycles_per_iteration;
              const std::string file = "fields_" + name + "_iteration" + std::to_string(j) + ".vtu";
              if (std::filesystem::exists(dir + "/fe/" + file))
                {
                  times.push_back(revolutions);
                  files.push_back(file);
                }
            }
          io::write_pvd(dir + "/fe/fields_" + name + ".pvd", times, files);
        }
    }
  } // namespace

  struct WearRun::Members
  {
    Members(io::Scene &scene, const WearRunOptions &options)
      : scene(scene)
      , options(options)
      , dir(options.output_directory)
      , write(!dir.empty())
      , checkpoint(dir + "/" + io::outputs::checkpoint)
      , setup(wear_setup(scene))
      , loop(scene.wear_loop, setup.wearing, scene.clearance_joints, setup.period, dynamics_of(scene, result.warnings))
      , before_peaks(scene.mechanism->n_coordinates(), setup.response, setup.period)
      , before(*scene.mechanism, setup.response, setup.period / 400, scene.wear_loop.response_cycles * setup.period)
    {
    }

    io::Scene                  &scene;
    const WearRunOptions        options;
    const Stopwatch             total;
    const std::string           dir;
    const bool                  write;
    const std::string           checkpoint;
    const WearSetup             setup;
    WearRunResult               result;
    wear::WearLoop              loop;
    analysis::CyclePeakRecorder before_peaks; ///< the response before wear: the first iteration's
    analysis::ResponseRecorder  before;
    std::vector<std::string>    fe_meshes_copied;
  };

  WearRun::WearRun(io::Scene &scene, const WearRunOptions &options)
  {
    AssertThrow(has_wear(scene), dealii::ExcMessage("WearRun on a scene without wear."));
    if (options.resume && options.output_directory.empty())
      throw InputError("--resume needs the output directory of the run to continue.");
    m = std::make_unique<Members>(scene, options);
    m->loop.set_warnings(&m->result.warnings); // kept in the checkpoints: a resumed run reports them all
    m->loop.set_carry(carry_of(scene));
    m->loop.set_checkpoint(m->write ? m->checkpoint : std::string());
    start_or_resume(m->loop, scene, options, m->checkpoint);
  }

  WearRun::~WearRun() = default;

  bool
  WearRun::finished() const
  {
    return m->loop.finished();
  }

  wear::WearLoop &
  WearRun::loop()
  {
    return m->loop;
  }

  void
  WearRun::iterate()
  {
    const Stopwatch iteration;
    auto           &loop      = m->loop;
    const auto     &ws        = m->scene.wear_loop;
    auto            observers = m->options.observers;
    const bool      first     = loop.state().iterations_done == 0;
    if (first)
      {
        observers.push_back(&m->before);
        observers.push_back(&m->before_peaks);
      }
    loop.iterate(observers);
    if (first)
      loop.keep_response_before(m->before_peaks.peaks());
    if (m->write)
      {
        if (first && m->options.final_outputs)
          io::write_response_csv(m->dir + "/" + io::outputs::response_before, m->before);
        io::write_wear_history(m->dir + "/" + io::outputs::wear_history, m->scene, loop.state());
        write_profile_frames(m->setup.wearing, loop, m->dir, ws);
        if (ws.fe_output)
          write_fe_files(m->setup.wearing, loop, m->dir, ws, m->fe_meshes_copied);
      }
    if (m->options.progress || m->options.on_progress)
      {
        const auto line = progress_line(loop, ws.n_iterations, iteration.seconds(), m->options.progress_prefix);
        if (m->options.progress)
          std::cerr << "[wearlink] " + line + "\n";
        if (m->options.on_progress)
          {
            const auto  &st       = loop.state();
            const double fraction = ws.extrapolation == wear::Extrapolation::adaptive ?
                                      st.revolutions / ws.target_revolutions :
                                      static_cast<double>(st.iterations_done) / ws.n_iterations;
            m->options.on_progress(std::min(1.0, fraction), line);
          }
      }
  }

  void
  WearRun::commit()
  {
    m->loop.commit();
  }

  WearRunResult
  WearRun::interrupted() const
  {
    WearRunResult r;
    r.state         = m->loop.state();
    r.timings       = m->loop.timings();
    r.timings.total = m->loop.earlier_wall_time() + m->total.seconds();
    r.warnings      = m->result.warnings;
    return r;
  }

  WearRunResult
  WearRun::finish(const ValidityWarnings *more_warnings)
  {
    auto &result    = m->result;
    result.state    = m->loop.state();
    result.timings  = m->loop.timings();
    result.finished = true;
    if (m->options.final_outputs)
      after_wear(m->scene, m->setup, m->options, more_warnings, result);
    // A resumed run's wall time includes its earlier processes' up to the checkpoint.
    result.timings.total = m->loop.earlier_wall_time() + m->total.seconds();
    return result;
  }

  void
  WearRun::write_summary(WearRunResult &result) const
  {
    if (m->options.final_outputs && m->write)
      write_run_files(m->scene, m->dir, result);
  }

  WearRunResult
  run_wear(io::Scene &scene, const WearRunOptions &options)
  {
    WearRun      run(scene, options);
    unsigned int done_here = 0;
    while (!run.finished())
      {
        if (options.stop_after > 0 && done_here == options.stop_after)
          return run.interrupted();
        run.iterate();
        run.commit();
        ++done_here;
      }
    auto result = run.finish();
    run.write_summary(result);
    return result;
  }
} // namespace wearlink::workflows
