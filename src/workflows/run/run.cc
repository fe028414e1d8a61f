// SPDX-License-Identifier: LGPL-2.1-or-later
#include "workflows/run/run.h"

#include "base/atomic_file.h"
#include "base/effect_ledger.h"
#include "base/exceptions.h"
#include "base/interrupt.h"
#include "base/text.h"
#include "contact/axial_loads.h"
#include "io/output_names.h"
#include "io/scene_periods.h"
#include "mbs/assembly.h"
#include "mbs/body_trig.h"
#include "wear/load_recorder.h"
#include "workflows/run/analyses.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>
#include <unordered_map>

namespace wearlink::workflows
{
  namespace
  {
    constexpr double inf = std::numeric_limits<double>::infinity();

    /** The pressure model of joint @p joint ("none" if the joint does not wear). */
    std::string
    pressure_model_of(const io::Scene &scene, const std::string &joint)
    {
      for (const auto &w : scene.wear)
        if (w->joint == joint)
          return w->pressure_model;
      return "none";
    }

    struct BodyExtremes
    {
      double min_x = inf, max_x = -inf, min_y = inf, max_y = -inf;
      double max_vx = 0, max_vy = 0, max_ax = 0, max_ay = 0;
    };

    struct JointStatistics
    {
      double max_normal_force   = 0;
      double max_elastic_force  = 0;
      double max_friction_force = 0;
      double max_penetration    = -inf;
      double contact_time       = 0;
      bool   was_in_contact     = false;
      /** The joint's counters when this run started (a joint object serves many runs). */
      long impacts_at_start     = 0;
      long holds_at_start       = 0;
      long evaluations_at_start = 0;
    };

    /** A clearance joint's index in the scene, by its force element. */
    using JointIndex = std::unordered_map<const mbs::ForceElement *, unsigned int>;

    /** Significant digits of the numbers in time_series.csv. */
    constexpr int time_series_digits = 10;

    /**
     * Watches accepted steps: extremes, energy balance, time-series samples; hands its
     * diagnostics of the clearance joints on to a load history (RunOptions::loads).
     */
    class Recorder : public mbs::StepObserver
    {
    public:
      Recorder(io::Scene              &scene,
               AtomicFile             *csv,
               double                  interval,
               bool                    progress,
               const ProgressCallback &on_progress,
               wear::LoadRecorder     *loads)
        : scene(scene)
        , mech(*scene.mechanism)
        , csv(csv)
        , trig(2 * mech.n_bodies())
        , interval(interval)
        , progress(progress)
        , on_progress(on_progress)
        , bodies(mech.n_bodies())
        , joints(scene.clearance_joints.size())
        , axial(scene.clearance_joints)
        , diagnostics(scene.clearance_joints.size())
        , loads(loads)
      {
        rhs_at_start = static_cast<long>(mech.n_evaluations());
        for (unsigned int i = 0; i < joints.size(); ++i)
          {
            joints[i].impacts_at_start          = scene.clearance_joints[i]->n_impacts();
            joints[i].holds_at_start            = scene.clearance_joints[i]->n_holds();
            joints[i].evaluations_at_start      = scene.clearance_joints[i]->n_force_evaluations();
            joint_of[scene.clearance_joints[i]] = i;
          }
        if (loads)
          for (const auto *j : loads->recorded_joints())
            {
              const auto k = joint_of.find(j);
              AssertThrow(k != joint_of.end(), dealii::ExcInternalError()); // a joint of the scene
              loads_index.push_back(k->second);
            }
        loads_diagnostics.resize(loads_index.size());
      }

      void
      on_start(const mbs::StepContext &c) override
      {
        const auto n  = mech.n_coordinates();
        energy_start  = mech.kinetic_energy(c.y.data() + n) + mech.potential_energy(c.y.data(), c.y.data() + n);
        t_start       = c.t;
        next_sample   = c.t;
        wall_start    = std::chrono::steady_clock::now();
        next_progress = 0.1;
        record(c.t, c.y, c.dydt, 0.0);
        if (loads)
          loads->start(c.t, diagnostics_for_loads());
        if (csv)
          {
            write_header();
            sample(c.t, c.y, c.dydt, mech.multipliers());
            n_samples   = 1; // the next sample is t_start + interval (it was written twice)
            next_sample = t_start + interval * n_samples;
          }
      }

      void
      on_step(const mbs::StepContext &c) override
      {
        throw_if_interrupted(); // SIGINT/SIGTERM: stop here, unwinding removes the temporaries
        ++steps;
        record(c.t, c.y, c.dydt, c.t - c.t_previous);
        if (loads)
          loads->step(c.t, diagnostics_for_loads());
        if (csv)
          {
            if (interval <= 0)
              sample(c.t, c.y, c.dydt, mech.multipliers());
            else
              while (next_sample <= c.t + 1e-12 * std::abs(c.t))
                {
                  const double ts = std::min(next_sample, c.t);
                  c.simulation.state_at(ts, y_sample);
                  c.simulation.derivative_at(ts, y_sample, f_sample);
                  sample(ts, y_sample, f_sample, mech.multipliers());
                  next_sample = t_start + interval * (++n_samples);
                }
          }
        if (progress || on_progress)
          {
            const double fraction = (c.t - t_start) / (scene.end_time - t_start);
            if (fraction >= next_progress - 1e-12)
              {
                long impacts = 0;
                for (unsigned int i = 0; i < joints.size(); ++i)
                  impacts += scene.clearance_joints[i]->n_impacts() - joints[i].impacts_at_start;
                const double wall =
                  std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
                std::ostringstream os;
                os << std::setw(3) << static_cast<int>(std::round(100 * fraction)) << "%  t = " << c.t << " s  steps "
                   << steps << "  impacts " << impacts << "  wall " << std::setprecision(3) << wall << " s";
                if (progress)
                  std::cerr << "[wearlink] " << os.str() << "\n";
                if (on_progress)
                  on_progress(std::min(1.0, fraction), os.str());
                next_progress += 0.1;
              }
          }
      }

      /** Right-hand-side evaluations of this run (the mechanism counts over its lifetime). */
      long
      rhs_evaluations() const
      {
        return static_cast<long>(mech.n_evaluations()) - rhs_at_start;
      }

      /** Contact-law evaluations of this run, all clearance joints. */
      long
      force_evaluations() const
      {
        long n = 0;
        for (unsigned int i = 0; i < joints.size(); ++i)
          n += scene.clearance_joints[i]->n_force_evaluations() - joints[i].evaluations_at_start;
        return n;
      }

      Json
      summary(const mbs::Simulation &sim, double wall_time) const
      {
        Json s                          = Json::object();
        s["scene"]                      = scene.file;
        s["title"]                      = scene.title;
        s["wall_time_s"]                = wall_time;
        s["simulated_time_s"]           = sim.time() - t_start;
        s["integrator"]                 = mbs::integrator_name(scene.simulation.integrator.type);
        s["steps"]                      = sim.get_integrator().n_accepted;
        s["rejected_steps"]             = sim.get_integrator().n_rejected;
        s["rhs_evaluations"]            = rhs_evaluations();
        s["contact_events"]             = sim.n_events();
        s["event_restarts"]             = sim.n_event_restarts();
        s["max_constraint_violation_m"] = max_violation;

        // Energy balance: ΔT + ΔV = W_reactions − D_damping − D_friction, with the
        // error relative to the energy that flowed (∫|P_reactions| dt + dissipation).
        const auto &y          = sim.state();
        const auto  n          = mech.n_coordinates();
        const auto  z          = 2 * n;
        using Q                = mbs::MechanismOde;
        const double kinetic   = mech.kinetic_energy(y.data() + n);
        const double potential = mech.potential_energy(y.data(), y.data() + n);
        const double throughput =
          y[z + Q::reaction_work_abs] + y[z + Q::damping_dissipation] + y[z + Q::friction_dissipation];
        Json e                             = Json::object();
        e["kinetic_J"]                     = kinetic;
        e["potential_J"]                   = potential;
        e["change_J"]                      = kinetic + potential - energy_start;
        e["reaction_work_J"]               = y[z + Q::reaction_work];
        e["reaction_work_abs_J"]           = y[z + Q::reaction_work_abs];
        e["damping_dissipation_J"]         = y[z + Q::damping_dissipation];
        e["friction_dissipation_J"]        = y[z + Q::friction_dissipation];
        e["max_residual_J"]                = max_energy_residual;
        s["energy"]                        = e;
        s["energy_balance_relative_error"] = throughput > 0 ? max_energy_residual / throughput : max_energy_residual;

        Json b = Json::object();
        for (unsigned int i = 0; i < mech.n_bodies(); ++i)
          {
            const auto &x                = bodies[i];
            Json        o                = Json::object();
            o["min_x_m"]                 = x.min_x;
            o["max_x_m"]                 = x.max_x;
            o["min_y_m"]                 = x.min_y;
            o["max_y_m"]                 = x.max_y;
            o["max_abs_vx_m_s"]          = x.max_vx;
            o["max_abs_vy_m_s"]          = x.max_vy;
            o["max_abs_ax_m_s2"]         = x.max_ax;
            o["max_abs_ay_m_s2"]         = x.max_ay;
            b[mech.get_bodies()[i].name] = o;
          }
        s["bodies"] = b;

        Json j = Json::object();
        for (unsigned int i = 0; i < joints.size(); ++i)
          {
            const auto *cj            = scene.clearance_joints[i];
            const auto &x             = joints[i];
            Json        o             = Json::object();
            o["radial_clearance_m"]   = cj->radial_clearance();
            o["stiffness_N_m1.5"]     = cj->stiffness();
            o["max_normal_force_N"]   = x.max_normal_force;
            o["max_elastic_force_N"]  = x.max_elastic_force;
            o["max_friction_force_N"] = x.max_friction_force;
            o["max_penetration_m"]    = std::max(0.0, x.max_penetration);
            o["fraction_in_contact"]  = x.contact_time / std::max(1e-300, sim.time() - t_start);
            o["impacts"]              = cj->n_impacts() - x.impacts_at_start;
            if (cj->get_description().hold_persistent_contact)
              o["held_episodes"] = cj->n_holds() - x.holds_at_start;
            o["force_evaluations"] = cj->n_force_evaluations() - x.evaluations_at_start;
            o["normal_force_law"]  = cj->get_description().normal_force_law;
            o["pressure_model"]    = pressure_model_of(scene, cj->name());
            const Json law         = cj->normal_force_law().report(); // outlives the loop below
            for (const auto &[key, value] : law.items())
              o[key] = value;
            j[cj->name()] = o;
          }
        s["clearance_joints"] = j;
        if (axial.any())
          s["sliced_joints"] = axial.json();
        return s;
      }

    private:
      void
      record(double t, const Eigen::VectorXd &y, const Eigen::VectorXd &f, double h)
      {
        const auto n = mech.n_coordinates();
        // The bodies' cos and sin once for the joints' diagnostics and the potentials.
        mbs::body_trig(y.data(), mech.n_bodies(), trig.data());
        for (unsigned int i = 0; i < mech.n_bodies(); ++i)
          {
            auto &x  = bodies[i];
            x.min_x  = std::min(x.min_x, y[3 * i]);
            x.max_x  = std::max(x.max_x, y[3 * i]);
            x.min_y  = std::min(x.min_y, y[3 * i + 1]);
            x.max_y  = std::max(x.max_y, y[3 * i + 1]);
            x.max_vx = std::max(x.max_vx, std::abs(y[n + 3 * i]));
            x.max_vy = std::max(x.max_vy, std::abs(y[n + 3 * i + 1]));
            x.max_ax = std::max(x.max_ax, std::abs(f[n + 3 * i]));
            x.max_ay = std::max(x.max_ay, std::abs(f[n + 3 * i + 1]));
          }
        max_violation = std::max(max_violation, mech.last_constraint_violation());
        // With a load history the joints are evaluated as it records them (RunOptions::loads).
        const mbs::StateView s =
          loads ? mbs::StateView(y.data(), y.data() + n) : mbs::StateView(y.data(), y.data() + n, trig.data());
        for (unsigned int k = 0; k < joints.size(); ++k)
          {
            const auto &d = diagnostics[k] = scene.clearance_joints[k]->diagnostics(s);
            auto       &js                 = joints[k];
            js.max_normal_force            = std::max(js.max_normal_force, d.normal_force);
            js.max_elastic_force           = std::max(js.max_elastic_force, d.elastic_force);
            js.max_friction_force          = std::max(js.max_friction_force, std::abs(d.friction_force));
            js.max_penetration             = std::max(js.max_penetration, d.penetration);
            const bool in                  = d.penetration > 0;
            js.contact_time += 0.5 * h * ((in ? 1 : 0) + (js.was_in_contact ? 1 : 0));
            js.was_in_contact = in;
          }
        if (axial.any())
          axial.record(diagnostics, h);
        using Q               = mbs::MechanismOde;
        const auto   z        = 2 * n;
        const double energy   = mech.kinetic_energy(y.data() + n) + potential_energy(y, trig.data(), diagnostics);
        const double residual = energy - energy_start - y[z + Q::reaction_work] + y[z + Q::damping_dissipation] +
                                y[z + Q::friction_dissipation];
        max_energy_residual = std::max(max_energy_residual, std::abs(residual));
        (void)t;
      }

      /**
       * The mechanism's potential energy at @p y (@p trig as for mbs::StateView), the
       * clearance joints' taken from their diagnostics @p d at that state.
       */
      double
      potential_energy(const Eigen::VectorXd                        &y,
                       const double                                 *trig,
                       const std::vector<contact::JointDiagnostics> &d) const
      {
        const auto n = mech.n_coordinates();
        return mech.potential_energy(y.data(),
                                     y.data() + n,
                                     trig,
                                     [&](const mbs::ForceElement &f, const mbs::StateView &s) {
                                       const auto k = joint_of.find(&f);
                                       return k != joint_of.end() ? d[k->second].potential_energy :
                                                                    f.potential_energy(s);
                                     });
      }

      /** The diagnostics of the last recorded step, of the load history's joints in its order. */
      const std::vector<contact::JointDiagnostics> &
      diagnostics_for_loads()
      {
        for (unsigned int i = 0; i < loads_index.size(); ++i)
          loads_diagnostics[i] = diagnostics[loads_index[i]];
        return loads_diagnostics;
      }

      void
      write_header()
      {
        auto       &os      = csv->stream();
        const auto  columns = time_series_columns(scene);
        const char *sep     = "";
        for (const auto &c : columns)
          {
            os << sep << c;
            sep = ",";
          }
        os << '\n';
      }

      void
      sample(double t, const Eigen::VectorXd &y, const Eigen::VectorXd &f, const Eigen::VectorXd &lambda)
      {
        const auto n = mech.n_coordinates();
        line.clear();
        append_number(line, t, time_series_digits);
        const auto put = [this](const double x) {
          line += ',';
          append_number(line, x, time_series_digits);
        };
        for (unsigned int i = 0; i < mech.n_bodies(); ++i)
          {
            for (unsigned int d = 0; d < 3; ++d)
              put(y[3 * i + d]);
            for (unsigned int d = 0; d < 3; ++d)
              put(y[n + 3 * i + d]);
            for (unsigned int d = 0; d < 3; ++d)
              put(f[n + 3 * i + d]);
          }
        const mbs::StateView s(y.data(), y.data() + n);
        sampled.resize(scene.clearance_joints.size());
        for (unsigned int k = 0; k < sampled.size(); ++k)
          {
            const auto &d = sampled[k] = scene.clearance_joints[k]->diagnostics(s);
            for (const double x : {d.eccentricity.x(),
                                   d.eccentricity.y(),
                                   d.local_eccentricity.x(),
                                   d.local_eccentricity.y(),
                                   d.penetration,
                                   d.normal_force,
                                   d.friction_force,
                                   d.sliding_velocity,
                                   d.contact_angle})
              put(x);
          }
        // The driver applies −λ to body 2's rotation (Φq row +1 on θ2).
        for (const auto d : scene.drivers)
          put(-lambda[mech.constraint_row(d)]);
        using Q      = mbs::MechanismOde;
        const auto z = 2 * n;
        put(mech.kinetic_energy(y.data() + n));
        put(potential_energy(y, nullptr, sampled));
        put(y[z + Q::reaction_work]);
        put(y[z + Q::damping_dissipation] + y[z + Q::friction_dissipation]);
        line += '\n';
        csv->stream().write(line.data(), static_cast<std::streamsize>(line.size()));
        csv->throw_if_failed(); // a full disk stops the run here, not at its end
      }

      io::Scene                             &scene;
      mbs::Mechanism                        &mech;
      AtomicFile                            *csv;
      std::vector<double>                    trig; ///< per step: the bodies' (cos θ, sin θ)
      double                                 interval;
      bool                                   progress;
      ProgressCallback                       on_progress;
      std::vector<BodyExtremes>              bodies;
      std::vector<JointStatistics>           joints;
      contact::AxialLoads                    axial;       ///< the sliced joints' axial load
      std::vector<contact::JointDiagnostics> diagnostics; ///< of the last recorded step, per clearance joint
      std::vector<contact::JointDiagnostics> sampled;     ///< of the last time-series sample, per clearance joint
      double                                 energy_start = 0, t_start = 0, next_sample = 0;
      long                                   n_samples = 0, steps = 0, rhs_at_start = 0;
      double                                 max_violation = 0, max_energy_residual = 0;
      double                                 next_progress = 0.1;
      std::chrono::steady_clock::time_point  wall_start;
      Eigen::VectorXd                        y_sample, f_sample;
      std::string                            line;              ///< one time-series row, written at once
      JointIndex                             joint_of;          ///< of every clearance joint
      wear::LoadRecorder                    *loads;             ///< the load history fed, or null
      std::vector<unsigned int>              loads_index;       ///< its joints' indices in the scene
      std::vector<contact::JointDiagnostics> loads_diagnostics; ///< its joints' diagnostics of the step
    };
  } // namespace

  namespace
  {
    /** The warnings of the integrator: constraint violation, energy balance, rk4 step. */
    void
    integrator_warnings(const io::Scene &scene, const Json &summary, ValidityWarnings &w)
    {
      const auto       &is       = scene.simulation.integrator;
      const bool        rk4      = is.type == mbs::IntegratorType::rk4;
      const double      position = is.absolute_tolerance.empty() ? 1e-9 : is.absolute_tolerance[0];
      const double      limit    = std::max(1e3 * position, 1e-6);
      const std::string reason = "1000 × the Position tolerance " + format_number(position, 3) + " m, at least 1 µm";
      w.check({"largest constraint violation",
               json_number(summary.at("max_constraint_violation_m")),
               limit,
               "m",
               reason,
               "the bodies drift off their joints; the motion is not that of the mechanism. Use a smaller Time "
               "step (rk4) or the dopri5 integrator"});
      // dopri5 keeps each step's local error near its relative tolerance; over a run the
      // balance may lose a few hundred of them. rk4 promises no tolerance: 1 % is far off.
      const double energy_limit = rk4 ? 1e-2 : std::max(1e3 * is.relative_tolerance, 1e-3);
      w.check({"energy balance relative error",
               json_number(summary.at("energy_balance_relative_error")),
               energy_limit,
               "",
               rk4 ? std::string("1 % for the fixed-step rk4") :
                     "1000 × the Relative tolerance " + format_number(is.relative_tolerance, 3) + ", at least 1e-3",
               "the integrator does not conserve the energy it should; reduce the Time step (rk4) or the "
               "tolerances (dopri5)"});
      const double period = io::driving_period_if_known(scene);
      if (rk4 && period > 0)
        w.check({"rk4 Time step",
                 is.time_step,
                 period / 100,
                 "s",
                 "1/100 of the driving period " + format_number(period, 3) + " s",
                 "a fixed step this long cannot follow the motion of one cycle, let alone contact impacts"});
    }
  } // namespace

  std::vector<std::string>
  time_series_columns(const io::Scene &scene)
  {
    std::vector<std::string> c{"time_s"};
    const auto              &mech = *scene.mechanism;
    for (const auto &b : mech.get_bodies())
      for (const char *q : {"_x_m",
                            "_y_m",
                            "_theta_rad",
                            "_vx_m_s",
                            "_vy_m_s",
                            "_omega_rad_s",
                            "_ax_m_s2",
                            "_ay_m_s2",
                            "_alpha_rad_s2"})
        c.push_back(b.name + q);
    for (const auto *j : scene.clearance_joints)
      for (const char *q : {"_ex_m",
                            "_ey_m",
                            "_ex_local_m",
                            "_ey_local_m",
                            "_penetration_m",
                            "_normal_force_N",
                            "_friction_force_N",
                            "_sliding_velocity_m_s",
                            "_contact_angle_rad"})
        c.push_back(j->name() + q);
    for (const auto d : scene.drivers)
      c.push_back(mech.get_constraints()[d]->name + "_torque_N_m");
    for (const char *e : {"kinetic_energy_J", "potential_energy_J", "reaction_work_J", "dissipated_J"})
      c.push_back(e);
    return c;
  }

  ValidityWarnings
  run_validity_warnings(const io::Scene &scene, const Json &summary)
  {
    ValidityWarnings w = scene.warnings; // the implausible entries first
    integrator_warnings(scene, summary, w);
    for (const auto &[name, joint] : summary.at("clearance_joints").items())
      {
        const double clearance = json_number(joint.at("radial_clearance_m"));
        w.check({"joint " + name + ": largest penetration",
                 json_number(joint.at("max_penetration_m")),
                 0.2 * clearance,
                 "m",
                 "20 % of the radial clearance " + format_number(clearance, 3) + " m",
                 "the contact arc exceeds ±34°, where force laws that assume a contact narrow against the radii "
                 "(hertz, lankarani-nikravesh, flores, the hertz-strip pressure) no longer hold; check the elastic "
                 "moduli and the loads"});
        // A tabulated law: the accepted states, not the evaluations, decide. The count of
        // evaluations beyond the table (extrapolations_above_table) includes the trial
        // stages of rejected steps, which overshoot far into the wall and leave no trace
        // in the result; it stays in the summary as a count.
        const Json *range = joint.contains("table_force_range_N") ? &joint.at("table_force_range_N") : nullptr;
        if (range != nullptr && range->is_array() && range->size() == 2)
          w.check({"joint " + name + ": largest elastic contact force at an accepted step",
                   json_number(joint.at("max_elastic_force_N")),
                   json_number(range->at(1)),
                   "N",
                   "the largest load of the contact-law table, whose range is " + range->dump() + " N",
                   "the force there comes from a power law extrapolated beyond the tabulated (FE) solutions; raise "
                   "Table maximum force above this force"});
      }
    if (summary.contains("sliced_joints"))
      for (const auto &[name, joint] : summary.at("sliced_joints").items())
        if (joint.contains("pin_solve_failures"))
          w.check({"joint " + name + ": states where the bent pin's deflection was not found",
                   json_number(joint.at("pin_solve_failures")),
                   0,
                   "",
                   "none: Newton's method on the slices' forces and the beam converges at every state",
                   "the forces there come from the best deflection found, not the equilibrium one; a slice may be "
                   "switching between contact and lift-off at a kink of its law; use more slices or a stiffer pin"});
    return w;
  }

  void
  assemble_scene(const io::Scene &scene, Eigen::VectorXd &q, Eigen::VectorXd &v)
  {
    mbs::assemble(*scene.mechanism, scene.start_time, scene.assembly_constraints, {}, q, v);
  }

  namespace
  {
    /**
     * The files of a finished run: time_series.csv committed, parameters.prm, summary.json
     * (and its warnings on stderr).
     */
    void
    write_run_files(const io::Scene        &scene,
                    const RunOptions       &options,
                    const Json             &summary,
                    const ValidityWarnings &warnings,
                    AtomicFile             *csv)
    {
      if (csv)
        csv->commit();
      write_run_summary(scene, options.output_directory, summary, warnings);
    }
  } // namespace

  void
  write_run_summary(const io::Scene        &scene,
                    const std::string      &directory,
                    const Json             &summary,
                    const ValidityWarnings &warnings)
  {
    std::ostringstream prm;
    scene.parameters->print_parameters(prm, dealii::ParameterHandler::ShortText);
    write_file_atomically(directory + "/" + io::outputs::parameters, prm.str());
    write_file_atomically(directory + "/" + io::outputs::summary, summary.dump(2));
    warnings.print(std::cerr);
  }

  IntegratedRun
  integrate_scene(io::Scene &scene, const RunOptions &options, const std::function<AtomicFile *()> &time_series)
  {
    const auto      wall_start = std::chrono::steady_clock::now();
    Eigen::VectorXd q0, v0;
    if (options.initial_state == nullptr)
      assemble_scene(scene, q0, v0);
    const double end_time = std::isnan(options.end_time) ? scene.end_time : options.end_time;
    AtomicFile  *csv      = time_series ? time_series() : nullptr;

    mbs::Simulation sim(*scene.mechanism, scene.simulation);
    if (options.initial_state != nullptr)
      sim.initialize_state(options.start_time, *options.initial_state);
    else
      sim.initialize(scene.start_time, q0, v0);
    Recorder recorder(scene, csv, scene.output_interval, options.progress, options.on_progress, options.loads);
    std::unique_ptr<SceneAnalyses> analyses;
    if (options.analyses)
      analyses =
        std::make_unique<SceneAnalyses>(scene, options.analyses_settings ? *options.analyses_settings : scene.analyses);
    std::vector<mbs::StepObserver *> observers{&recorder};
    if (analyses)
      for (auto *o : analyses->observers())
        observers.push_back(o);
    observers.insert(observers.end(), options.observers.begin(), options.observers.end());
    sim.run(end_time, observers);
    if (options.final_state != nullptr)
      *options.final_state = sim.state();

    EffectLedger::instance().add_calls("contact law evaluations", recorder.force_evaluations());
    EffectLedger::instance().add_calls("rhs evaluations", recorder.rhs_evaluations());

    const Json analyses_summary = analyses ? analyses->finish(options.output_directory) : Json();
    if (analyses && options.recorded != nullptr)
      *options.recorded = analyses->recorded_run();
    const double wall    = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
    Json         summary = recorder.summary(sim, wall);
    if (analyses_summary.is_null() == false)
      summary["analyses"] = analyses_summary;
    Json ledger = Json::object();
    for (const auto &[category, entries] : EffectLedger::instance().snapshot())
      {
        Json c = Json::object();
        for (const auto &[key, count] : entries)
          c[key] = count;
        ledger[category] = c;
      }
    summary["effect_ledger"]  = ledger;
    ValidityWarnings warnings = run_validity_warnings(scene, summary);
    summary["warnings"]       = warnings.json();
    if (options.warnings != nullptr)
      options.warnings->merge(warnings);
    return {std::move(summary), std::move(warnings)};
  }

  Json
  run_scene(io::Scene &scene, const RunOptions &options)
  {
    if (options.output_directory.empty())
      return integrate_scene(scene, options).summary;
    std::unique_ptr<AtomicFile> csv;
    // The folder and the time series are made after assembly: a scene that cannot be
    // assembled leaves nothing behind.
    const auto open_time_series = [&]() -> AtomicFile * {
      make_output_directory(options.output_directory);
      if (!scene.write_time_series)
        return nullptr;
      csv = std::make_unique<AtomicFile>(options.output_directory + "/" + io::outputs::time_series);
      return csv.get();
    };
    const IntegratedRun run = integrate_scene(scene, options, open_time_series);
    write_run_files(scene, options, run.summary, run.warnings, csv.get());
    return run.summary;
  }
} // namespace wearlink::workflows
