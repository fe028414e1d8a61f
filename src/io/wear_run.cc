// SPDX-License-Identifier: LGPL-2.1-or-later
#include "io/wear_run.h"

#include "base/atomic_file.h"
#include "base/effect_ledger.h"
#include "base/exceptions.h"
#include "io/analyses.h"
#include "io/dynamics_comparison.h"
#include "io/run.h"
#include "io/wear_outputs.h"
#include "wear/archard.h"
#include "wear/load_recorder.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace wearlink::io
{
  namespace
  {
    constexpr double two_pi = 6.283185307179586476925286766559;
    using Clock             = std::chrono::steady_clock;

    double
    seconds_since(const Clock::time_point &t0)
    {
      return std::chrono::duration<double>(Clock::now() - t0).count();
    }

    /**
     * The scene's identity for resuming: its effective parameters without the entries
     * that say how far to go (so a run can be resumed to more iterations).
     */
    std::string
    fingerprint(const Scene &scene)
    {
      std::ostringstream os;
      scene.parameters->print_parameters(os, dealii::ParameterHandler::ShortText);
      std::istringstream in(os.str());
      std::string        line, kept;
      while (std::getline(in, line))
        if (line.find("Number of iterations") == std::string::npos &&
            line.find("Target revolutions") == std::string::npos)
          kept += line + '\n';
      std::ostringstream h;
      h << std::hex << std::hash<std::string>()(kept) << '-' << kept.size();
      return h.str();
    }

    contact::JointGeometry
    geometry_with(const contact::ClearanceJoint &j, const Profile &bore, const Profile &pin)
    {
      auto g = j.get_description().geometry;
      g.bore = bore;
      g.pin  = pin;
      return g;
    }

    double
    max_of(const std::vector<double> &v)
    {
      return v.empty() ? 0.0 : *std::max_element(v.begin(), v.end());
    }

    /**
     * The two-trajectory exponent (io/shadow_trajectory.h) of the fresh and of the worn
     * mechanism: the scene read again with its overrides plus the analysis, duration and
     * tightened tolerances, and for the worn state the profiles written into @p dir
     * (bore_<J>.csv, pin_<J>.csv). Outputs in DIR/exponent_before, DIR/exponent_after.
     */
    SimulationExponents
    two_trajectory_exponents(const Scene &scene, const wear::WearState &st, const std::string &dir, const bool progress)
    {
      const auto &a      = scene.analyses;
      const auto &is     = scene.simulation.integrator;
      const double scale = a.two_trajectory_tolerance / is.relative_tolerance;
      const double T     = driving_period(scene);
      SimulationExponents out;
      out.separation = a.two_trajectory_separation;
      out.interval   = a.renormalization_interval;
      out.tolerance  = a.two_trajectory_tolerance;
      out.duration   = a.two_trajectory_cycles * T;
      const std::string abs_dir = std::filesystem::absolute(dir).string();
      for (int k = 0; k < 2; ++k)
        {
          std::vector<std::string> o = scene.overrides;
          std::ostringstream       v;
          v << std::setprecision(17);
          auto set = [&](const std::string &entry, const double value) {
            v.str("");
            v << value;
            o.push_back(entry + "=" + v.str());
          };
          o.push_back("Analyses/List of analyses=lyapunov");
          o.push_back("Analyses/Lyapunov/Methods=two-trajectory");
          o.push_back("Output/Time series=false");
          set("Simulation/End time", scene.start_time + a.transient + out.duration);
          set("Integrator/Relative tolerance", a.two_trajectory_tolerance);
          set("Integrator/Position tolerance", is.absolute_tolerance[0] * scale);
          set("Integrator/Velocity tolerance", is.absolute_tolerance[1] * scale);
          if (k == 1)
            for (const auto &j : st.joints)
              {
                o.push_back("Joint " + j.name + "/Clearance/Bore profile file=" + abs_dir + "/bore_" + j.name + ".csv");
                o.push_back("Joint " + j.name + "/Clearance/Pin profile file=" + abs_dir + "/pin_" + j.name + ".csv");
              }
          if (progress)
            std::cerr << "[wearlink] two-trajectory exponent " << (k == 0 ? "before" : "after") << " wear, "
                      << a.two_trajectory_cycles << " periods at relative tolerance " << a.two_trajectory_tolerance
                      << "\n";
          Scene      s = read_scene(scene.file, o);
          RunOptions ro;
          ro.output_directory = dir + (k == 0 ? "/exponent_before" : "/exponent_after");
          ro.progress         = progress;
          const Json summary  = run_scene(s, ro);
          const Json &l       = summary.at("analyses").at("lyapunov");
          for (std::size_t i = 0; i < l.size(); ++i)
            if (l[i].at("method").as_string() == "two-trajectory")
              (k == 0 ? out.before : out.after) = l[i].at("exponent_per_s").as_number();
        }
      return out;
    }

    /**
     * The scene's analyses once with the fresh and once with the worn profiles, each run
     * from assembly at Start time to End time (outputs in DIR/dynamics_before and
     * DIR/dynamics_after), then compared (io/dynamics_comparison.h) into DIR. The joints
     * are left with the worn profiles.
     */
    DynamicsComparison
    before_after_dynamics(Scene &                                      scene,
                          const wear::WearState &                      st,
                          const std::vector<contact::ClearanceJoint *> &joints,
                          const std::string &                          dir,
                          const bool                                   progress)
    {
      ComparedRun       runs[2];
      const char *const names[2] = {"before", "after"};
      // The shadow trajectory needs its own tolerance and the profiles as files (it
      // reads the scene again): separate runs below, not these.
      const bool       two_trajectory = scene.analyses.lyapunov && scene.analyses.two_trajectory;
      AnalysesSettings without_shadow = scene.analyses;
      without_shadow.two_trajectory   = false;
      for (int k = 0; k < 2; ++k)
        {
          for (unsigned int i = 0; i < joints.size(); ++i)
            joints[i]->set_profiles(k == 0 ? st.joints[i].initial_bore : st.joints[i].bore,
                                    k == 0 ? st.joints[i].initial_pin : st.joints[i].pin);
          for (auto *j : scene.clearance_joints)
            j->set_mode(false, 0);
          if (progress)
            std::cerr << "[wearlink] dynamics " << names[k] << " wear with the scene's analyses, t = "
                      << scene.start_time << " … " << scene.end_time << " s\n";
          RunOptions ro;
          ro.output_directory = dir.empty() ? std::string() : dir + "/dynamics_" + names[k];
          ro.progress         = progress;
          ro.recorded         = &runs[k].run;
          ro.analyses_settings = &without_shadow;
          runs[k].summary     = run_scene(scene, ro);
          std::ostringstream label;
          label << (k == 0 ? "before wear" : "after wear");
          if (k == 1)
            label << " (" << std::setprecision(6) << st.revolutions << " rev)";
          runs[k].run.label = label.str();
        }
      const auto &             a = scene.analyses;
      DynamicsComparisonSettings cs;
      cs.joints     = a.joints;
      cs.directions = a.directions;
      if (a.lyapunov)
        cs.methods = a.methods;
      cs.delay          = a.comparison_delay;
      cs.dimension      = a.comparison_dimension;
      cs.delay_scan     = a.delay_scan;
      cs.bodies         = a.bodies;
      const std::string response = scene.mechanism->get_bodies()[response_body(scene)].name;
      if (!response.empty() && std::find(cs.bodies.begin(), cs.bodies.end(), response) == cs.bodies.end())
        cs.bodies.push_back(response);
      cs.published      = parse_published_exponents(a.published_exponents, scene.file);
      cs.published_note = a.published_note;
      if (two_trajectory && !dir.empty())
        cs.simulation_exponents = two_trajectory_exponents(scene, st, dir, progress);
      return compare_dynamics(runs[0], runs[1], cs, dir);
    }
  } // namespace

  bool
  has_wear(const Scene &scene)
  {
    return !scene.wear.empty();
  }

  double
  cycle_period(const Scene &scene)
  {
    if (scene.wear_loop.cycle_period > 0)
      return scene.wear_loop.cycle_period;
    for (const auto d : scene.drivers)
      {
        auto &prm = *scene.parameters;
        prm.enter_subsection("Joint " + scene.mechanism->get_constraints()[d]->name);
        const double omega = prm.get_double("Angular velocity");
        prm.leave_subsection();
        if (std::abs(omega) > 0)
          return two_pi / std::abs(omega);
      }
    throw InputError("In " + scene.file +
                     ", 'Wear/Cycle period' is 0 and no angle driver has a non-zero Angular "
                     "velocity to take it from; set Wear/Cycle period (s).");
  }

  WearRunResult
  run_wear(Scene &scene, const WearRunOptions &options)
  {
    const auto t_total = Clock::now();
    AssertThrow(has_wear(scene), dealii::ExcMessage("run_wear() on a scene without wear."));
    const auto &     ws     = scene.wear_loop;
    const double     period = cycle_period(scene);
    const double     t_iter = ws.cycles_per_iteration * period;
    const bool       write  = !options.output_directory.empty();
    const std::string dir   = options.output_directory;
    const std::string checkpoint = dir + "/checkpoint.txt";
    if (options.resume && !write)
      throw InputError("--resume needs the output directory of the run to continue.");

    // The wearing joints, in the order of scene.wear.
    std::vector<contact::ClearanceJoint *> joints;
    for (const auto &w : scene.wear)
      for (auto *j : scene.clearance_joints)
        if (j->name() == w->joint)
          joints.push_back(j);
    AssertThrow(joints.size() == scene.wear.size(), dealii::ExcInternalError());

    WearRunResult result;
    auto &        timings = result.timings;
    for (const char *k : {"dynamics", "meshing", "fe set-up", "fe compliance", "pressure evaluation",
                          "wear bookkeeping", "outputs", "total"})
      timings[k] = 0;
    wear::WearState &st = result.state;

    Eigen::VectorXd q0, v0;
    const auto      n = scene.mechanism->n_coordinates();
    if (options.resume)
      {
        st = wear::WearState::read(checkpoint);
        if (st.fingerprint != fingerprint(scene))
          throw InputError("Cannot resume from '" + checkpoint + "': it was written for a different scene "
                           "(or different parameters) than " + scene.file +
                           ". Only Wear/Number of iterations and Wear/Target revolutions may "
                           "change on resume.");
        bool match = st.joints.size() == joints.size() &&
                     st.modes.size() == 2 * scene.clearance_joints.size();
        for (unsigned int i = 0; match && i < joints.size(); ++i)
          match = st.joints[i].name == joints[i]->name() &&
                  st.joints[i].bore.n_points() == joints[i]->get_description().geometry.bore.n_points();
        if (!match)
          throw InputError("Cannot resume from '" + checkpoint + "': its joints do not match " + scene.file + ".");
      }
    else
      {
        if (write)
          {
            make_output_directory(dir);
            std::error_code ec;
            std::filesystem::remove(checkpoint, ec); // a fresh run never continues an old one
          }
        assemble_scene(scene, q0, v0);
        st.fingerprint = fingerprint(scene);
        st.time        = scene.start_time;
        st.state       = Eigen::VectorXd::Zero(2 * n + mbs::MechanismOde::n_quadratures);
        st.state.head(n)        = q0;
        st.state.segment(n, n)  = v0;
        st.modes.assign(2 * scene.clearance_joints.size(), 0.0);
        for (auto *j : joints)
          {
            wear::JointWearState js;
            js.name         = j->name();
            js.initial_bore = js.bore = js.meshed_bore = j->get_description().geometry.bore;
            js.initial_pin = js.pin = js.meshed_pin = j->get_description().geometry.pin;
            st.joints.push_back(std::move(js));
          }
      }

    // Bring the joints and the pressure models to the state's geometry.
    for (unsigned int i = 0; i < joints.size(); ++i)
      {
        joints[i]->set_profiles(st.joints[i].bore, st.joints[i].pin);
        scene.wear[i]->model->update_geometry(
          geometry_with(*joints[i], st.joints[i].meshed_bore, st.joints[i].meshed_pin));
      }

    auto target_reached = [&] {
      return ws.extrapolation == wear::Extrapolation::adaptive &&
             st.revolutions >= ws.target_revolutions * (1 - 1e-12);
    };

    std::vector<const contact::ClearanceJoint *> recorded(joints.begin(), joints.end());
    unsigned int                                 done_here = 0;
    ResponseRecorder before(*scene.mechanism, response_body(scene), period / 400,
                            ws.response_cycles * period);
    while (st.iterations_done < ws.n_iterations && !target_reached())
      {
        if (options.stop_after > 0 && done_here == options.stop_after)
          return result;
        const auto t_iteration = Clock::now();

        // 1. Dynamics over one iteration, continuing from the stored state and modes.
        for (unsigned int k = 0; k < scene.clearance_joints.size(); ++k)
          scene.clearance_joints[k]->set_mode(st.modes[2 * k] != 0, st.modes[2 * k + 1]);
        Eigen::VectorXd y0 = st.state, y1;
        y0.tail(mbs::MechanismOde::n_quadratures).setZero();
        wear::LoadRecorder rec(recorded);
        RunOptions         ro;
        ro.initial_state = &y0;
        ro.start_time    = st.time;
        ro.end_time      = st.time + t_iter;
        ro.final_state   = &y1;
        ro.observers     = {&rec};
        ro.observers.insert(ro.observers.end(), options.observers.begin(), options.observers.end());
        ro.analyses = false; // the scene's analyses run before and after wear, not per iteration
        const bool first = st.iterations_done == 0;
        if (first)
          ro.observers.push_back(&before);
        auto t0 = Clock::now();
        run_scene(scene, ro);
        rec.finish();
        timings["dynamics"] += seconds_since(t0);
        if (first && write && options.final_outputs)
          before.write_csv(dir + "/response_before.csv");

        // 2. Archard on both surfaces of every wearing joint.
        std::vector<std::unique_ptr<wear::ArchardAccumulator>> acc;
        double max_depth = 0;
        for (unsigned int i = 0; i < joints.size(); ++i)
          {
            const auto &w = *scene.wear[i];
            acc.push_back(std::make_unique<wear::ArchardAccumulator>(
              geometry_with(*joints[i], st.joints[i].bore, st.joints[i].pin),
              w.archard.bushing_coefficient,
              w.archard.pin_coefficient,
              *w.model));
            t0 = Clock::now();
            acc[i]->add_history(rec.samples(i), ws.evaluation == wear::PressureEvaluation::every_step,
                                period / ws.samples_per_cycle, ro.start_time);
            timings["pressure evaluation"] += seconds_since(t0);
            max_depth = std::max({max_depth, max_of(acc[i]->pin_depth()), max_of(acc[i]->bore_depth())});
          }

        // 3. Extrapolation factor.
        t0 = Clock::now();
        double factor = ws.extrapolation_factor;
        if (ws.extrapolation == wear::Extrapolation::adaptive)
          {
            factor = max_depth > 0 ? std::min(ws.max_factor, ws.max_depth_increment / max_depth) : ws.max_factor;
            factor = std::min(factor, (ws.target_revolutions - st.revolutions) / ws.cycles_per_iteration);
          }

        // 4. Profile update, records.
        for (unsigned int i = 0; i < joints.size(); ++i)
          {
            auto &js = st.joints[i];
            auto  bore = js.bore.samples();
            auto  pin  = js.pin.samples();
            for (unsigned int k = 0; k < bore.size(); ++k)
              bore[k] += factor * acc[i]->bore_depth()[k];
            for (unsigned int k = 0; k < pin.size(); ++k)
              pin[k] -= factor * acc[i]->pin_depth()[k];
            js.bore = Profile::from_samples(bore, "worn bore of joint " + js.name);
            try
              {
                js.pin = Profile::from_samples(pin, "worn pin of joint " + js.name);
              }
            catch (const InputError &)
              {
                throw NumericalError("Wear iteration " + std::to_string(st.iterations_done + 1) +
                                     ": the pin of joint " + js.name +
                                     " is worn through (a radius ≤ 0). Reduce the extrapolation.");
              }
            wear::IterationRecord r = js.history.empty() ? wear::IterationRecord() : js.history.back();
            r.volume_pin += factor * acc[i]->pin_volume;
            r.volume_bore += factor * acc[i]->bore_volume;
            r.archard_pin += factor * acc[i]->pin_archard;
            r.archard_bore += factor * acc[i]->bore_archard;
            r.sliding_distance += factor * acc[i]->sliding_distance;
            r.relative_revolutions += factor * rec.relative_revolutions(i);
            double impulse = 0;
            for (const auto &s : rec.samples(i))
              impulse += s.load.normal_force * s.weight;
            r.mean_normal_force = impulse / t_iter;
            r.depth_pin.resize(pin.size());
            r.depth_bore.resize(bore.size());
            for (unsigned int k = 0; k < pin.size(); ++k)
              r.depth_pin[k] = js.initial_pin[k] - js.pin[k];
            for (unsigned int k = 0; k < bore.size(); ++k)
              r.depth_bore[k] = js.bore[k] - js.initial_bore[k];
            r.max_depth_pin  = max_of(r.depth_pin);
            r.max_depth_bore = max_of(r.depth_bore);
            js.history.push_back(std::move(r));
          }
        st.factors.push_back(factor);
        st.revolutions += factor * ws.cycles_per_iteration;
        st.time  = ro.end_time;
        st.state = y1;
        for (unsigned int k = 0; k < scene.clearance_joints.size(); ++k)
          {
            st.modes[2 * k]     = scene.clearance_joints[k]->mode() ? 1 : 0;
            st.modes[2 * k + 1] = scene.clearance_joints[k]->impact_velocity();
          }
        ++st.iterations_done;
        ++done_here;
        timings["wear bookkeeping"] += seconds_since(t0);

        // 5. Rebuild the clearance model and the pressure model's geometry.
        for (unsigned int i = 0; i < joints.size(); ++i)
          {
            auto &js = st.joints[i];
            joints[i]->set_profiles(js.bore, js.pin);
            const bool fe = scene.wear[i]->model->requires_fe_geometry();
            if (!fe || st.iterations_done % ws.remesh_interval == 0)
              {
                js.meshed_bore = js.bore;
                js.meshed_pin  = js.pin;
                t0             = Clock::now();
                scene.wear[i]->model->update_geometry(geometry_with(*joints[i], js.bore, js.pin));
                if (!fe)
                  timings["pressure evaluation"] += seconds_since(t0);
              }
          }

        // 6. Checkpoint and progress.
        t0 = Clock::now();
        if (write)
          {
            st.write(checkpoint);
            write_wear_history(dir + "/wear_history.csv", scene, st);
          }
        timings["wear bookkeeping"] += seconds_since(t0);
        if (options.progress)
          {
            std::ostringstream os;
            os << "[wearlink] wear iteration " << st.iterations_done << '/' << ws.n_iterations
               << "  revolutions " << std::setprecision(6) << st.revolutions << "  factor " << factor;
            for (unsigned int i = 0; i < joints.size(); ++i)
              {
                const auto &r = st.joints[i].history.back();
                os << "  " << st.joints[i].name << ": h_pin " << std::setprecision(3)
                   << r.max_depth_pin * 1e6 << " µm, h_bore " << r.max_depth_bore * 1e6
                   << " µm, V " << (r.volume_pin + r.volume_bore) * 1e9 << " mm³";
              }
            os << "  (" << std::setprecision(3) << seconds_since(t_iteration) << " s)\n";
            std::cerr << os.str();
          }
      }

    // FE phases, as the models measured them.
    for (const auto &w : scene.wear)
      for (const auto &[phase, t] : w->model->timings())
        timings[phase] += t;

    EffectLedger::instance().add_calls("wear iterations", done_here);
    result.finished = true;
    if (!options.final_outputs)
      {
        timings["total"] = seconds_since(t_total);
        return result;
      }

    // After wear: the same start (assembly) with the final profiles.
    const auto t_out = Clock::now();
    for (auto *j : scene.clearance_joints)
      j->set_mode(false, 0);
    ResponseRecorder after(*scene.mechanism, response_body(scene), period / 400, ws.response_cycles * period);
    RunOptions       ro;
    ro.end_time  = scene.start_time + std::max(ws.response_cycles, 1e-9) * period;
    ro.observers = {&after};
    ro.analyses  = false;
    auto t0      = Clock::now();
    result.summary = run_scene(scene, ro);
    timings["dynamics"] += seconds_since(t0);

    auto &cj = result.summary["clearance_joints"];
    for (unsigned int i = 0; i < joints.size(); ++i)
      {
        const auto &js = st.joints[i];
        const auto &w  = *scene.wear[i];
        const wear::IterationRecord r = js.history.empty() ? wear::IterationRecord() : js.history.back();
        auto &o = cj[js.name];
        o["pressure_model"]           = w.pressure_model;
        o["wear_volume_pin_m3"]       = r.volume_pin;
        o["wear_volume_bushing_m3"]   = r.volume_bore;
        o["archard_volume_pin_m3"]    = r.archard_pin;
        o["archard_volume_bushing_m3"] = r.archard_bore;
        o["max_wear_depth_pin_m"]     = r.max_depth_pin;
        o["max_wear_depth_bushing_m"] = r.max_depth_bore;
        o["mass_loss_pin_mg"]         = r.volume_pin * w.archard.pin_density * 1e6;
        o["mass_loss_bushing_mg"]     = r.volume_bore * w.archard.bushing_density * 1e6;
        o["revolutions"]              = st.revolutions;
        o["relative_revolutions"]     = r.relative_revolutions;
        o["sliding_distance_m"]       = r.sliding_distance;
        o["mean_normal_force_N"]      = r.mean_normal_force;
      }
    result.summary["wear_iterations"]  = st.iterations_done;
    result.summary["wear_revolutions"] = st.revolutions;
    if (write)
      {
        write_wear_outputs(dir, scene, st, after); // the worn profile files first: the
        timings["outputs"] += seconds_since(t_out); // two-trajectory runs read them
      }
    if (scene.analyses.any())
      {
        t0               = Clock::now();
        auto comparison  = before_after_dynamics(scene, st, joints, write ? dir : std::string(), options.progress);
        timings["before/after dynamics"] = seconds_since(t0);
        result.summary["before_after"] = comparison.json;
        result.before_after_report     = comparison.report;
      }
    if (write)
      {
        timings["total"] = seconds_since(t_total);
        Json t = Json::object();
        for (const auto &[k, v] : timings)
          t[k] = v;
        result.summary["wear_timing_s"] = t;
        std::ostringstream prm;
        scene.parameters->print_parameters(prm, dealii::ParameterHandler::ShortText);
        write_file_atomically(dir + "/parameters.prm", prm.str());
        write_file_atomically(dir + "/summary.json", result.summary.dump());
      }
    timings["total"] = seconds_since(t_total);
    return result;
  }
} // namespace wearlink::io
