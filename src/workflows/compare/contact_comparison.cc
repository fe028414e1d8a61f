// SPDX-License-Identifier: LGPL-2.1-or-later
#include "workflows/compare/contact_comparison.h"

#include "base/atomic_file.h"
#include "base/exceptions.h"
#include "base/numbers.h"
#include "base/text.h"
#include "base/timings.h"
#include "contact/cylindrical_contact.h"
#include "fe/fe_normal_force_law.h"
#include "io/output_names.h"
#include "io/plot.h"
#include "io/profile_file.h"
#include "io/scene.h"
#include "io/scene_periods.h"
#include "wear/archard.h"
#include "wear/load_recorder.h"
#include "workflows/run/run.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>

namespace wearlink::workflows
{
  namespace
  {
    using numbers::nan;
    constexpr int n_grid          = 48; ///< points of the approach grid
    const char   *dynamics_laws[] = {"lankarani-nikravesh", "johnson", "esdu-78035", "fe"};

    /** What the comparison needs of one clearance joint of the scene. */
    struct JointData
    {
      std::string                 name, law;
      contact::JointGeometry      geometry;
      contact::CylinderPair       pair;                  ///< for the closed forms
      double                      stiffness         = 0; ///< K of the sphere law [N/m^1.5]
      double                      restitution       = 1; ///< of the scene's law (1 if it has none)
      double                      winkler_thickness = 0; ///< 0: not given
      fe::FeForceLawSettings      fe;
      contact::ForceApproachTable fe_fresh, fe_worn;
      contact::JointGeometry      worn;
      bool                        has_worn      = false;
      double                      worn_bore_psi = 0; ///< deepest bore wear, bushing frame [rad]
      double                      worn_pin_psi  = 0; ///< deepest pin wear, pin frame [rad]
    };

    bool
    has_restitution(const std::string &law)
    {
      return law != "hertz";
    }

    JointData
    read_joint(const io::Scene &scene, const contact::ClearanceJoint &cj)
    {
      JointData d;
      d.name      = cj.name();
      d.geometry  = cj.get_description().geometry;
      d.pair      = contact::CylinderPair::of(d.geometry);
      d.stiffness = cj.stiffness();
      ParameterReader r(*scene.parameters, scene.file);
      r.enter("Joint " + d.name);
      r.enter("Clearance");
      d.law = r.get("Normal force law");
      if (has_restitution(d.law))
        {
          r.enter(d.law);
          d.restitution = r.get_double("Restitution coefficient");
          r.leave();
        }
      r.enter("fe");
      d.fe = fe::read_fe_force_law(r);
      r.leave();
      r.enter("winkler");
      d.winkler_thickness = r.get_double("Layer thickness"); // 0 (the placeholder) if not given
      r.leave();
      r.leave();
      r.leave(); // the handler is shared: leave it where it was
      return d;
    }

    /** The direction of the deepest wear of @p worn against @p fresh [rad, body frame]. */
    double
    deepest(const Profile &fresh, const Profile &worn, const double sign)
    {
      unsigned int best = 0;
      for (unsigned int k = 0; k < worn.n_points(); ++k)
        if (sign * (worn[k] - fresh.radius(worn.angle(k))) > sign * (worn[best] - fresh.radius(worn.angle(best))))
          best = k;
      return worn.angle(best);
    }

    /**
     * The FE curve of @p geometry in one direction as a one-direction table, the load
     * levels where the approach does not increase left out (on a worn pocket the pin can
     * slide sideways as the load grows); their number goes to @p dropped.
     */
    contact::ForceApproachTable
    fe_curve(const contact::JointGeometry &geometry,
             const fe::FeForceLawSettings &settings,
             const double                  psi_b,
             const double                  psi_p,
             fe::TableBuild               &build,
             std::size_t                  &dropped)
    {
      const std::vector<double> forces = fe::table_load_levels(settings);
      const std::vector<double> raw    = fe::fe_approach_curve(geometry, settings, forces, psi_b, psi_p, build);
      std::vector<double>       kept_forces, kept;
      for (std::size_t k = 0; k < raw.size(); ++k)
        if (kept.empty() || raw[k] > kept.back())
          {
            kept_forces.push_back(forces[k]);
            kept.push_back(raw[k]);
          }
      dropped = raw.size() - kept.size();
      if (kept.size() < 2)
        throw NumericalError("The FE approach does not increase with the load in the direction " +
                             format_number(psi_b) + " rad (bushing frame), " + format_number(psi_p) +
                             " rad (pin frame).");
      return contact::ForceApproachTable(kept_forces, 1, 1, kept);
    }

    /**
     * The FE curves of joint @p d: fresh (round pairs: the fe law's own one-direction
     * table, cached like it, so an equal joint and the fe effect run reuse it), and worn,
     * in the direction of the deepest wear, if @p worn_directory is given.
     */
    void
    fe_curves(JointData &d, const std::string &worn_directory, const bool progress)
    {
      fe::TableBuild b;
      std::size_t    dropped = 0;
      const bool     round   = d.geometry.bore.is_round() && d.geometry.pin.is_round();
      d.fe_fresh =
        round ? fe::build_force_approach_table(d.geometry, d.fe, b) : fe_curve(d.geometry, d.fe, 0, 0, b, dropped);
      if (progress)
        std::cerr << "[wearlink] joint " << d.name << ": FE force–approach curve (fresh) in " << b.seconds << " s"
                  << (b.from_cache ? " (cached)" : "") << '\n';
      if (worn_directory.empty())
        return;
      const unsigned int n = d.geometry.bore.n_points();
      d.worn               = d.geometry;
      d.worn.bore          = io::read_profile_csv(worn_directory + "/bore_" + d.name + ".csv", n);
      d.worn.pin           = io::read_profile_csv(worn_directory + "/pin_" + d.name + ".csv", n);
      d.has_worn           = true;
      const double psi_b   = deepest(d.geometry.bore, d.worn.bore, 1.0);
      const double psi_p   = deepest(d.geometry.pin, d.worn.pin, -1.0);
      d.worn_bore_psi      = psi_b;
      d.worn_pin_psi       = psi_p;
      d.fe_worn            = fe_curve(d.worn, d.fe, psi_b, psi_p, b, dropped);
      if (progress)
        std::cerr << "[wearlink] joint " << d.name << ": FE curve (worn, bore " << psi_b * 180 / numbers::pi
                  << "°, pin " << psi_p * 180 / numbers::pi << "°) in " << b.seconds << " s; " << dropped << " of "
                  << d.fe.n_levels << " load levels left out where the approach did not increase\n";
    }

    /** The FE approach at which table @p t carries @p force (bisection in ln δ). */
    double
    approach_at(const contact::ForceApproachTable &t, const double force)
    {
      double lo = std::log(1e-12), hi = std::log(1e-1);
      for (int i = 0; i < 200; ++i)
        {
          const double mid                                          = 0.5 * (lo + hi);
          (t.evaluate(std::exp(mid), 0, 0).force < force ? lo : hi) = mid;
        }
      return std::exp(0.5 * (lo + hi));
    }

    /** F of law @p law of joint @p d at approach @p delta (NaN outside its validity). */
    double
    law_force(const JointData &d, const std::string &law, const double delta, const bool worn)
    {
      if (law == "lankarani-nikravesh")
        return d.stiffness * std::pow(delta, 1.5);
      if (law == "johnson")
        return contact::cylindrical_force(contact::CylindricalLaw::johnson, d.pair, delta);
      if (law == "esdu-78035")
        return contact::cylindrical_force(contact::CylindricalLaw::esdu_78035, d.pair, delta);
      if (law == "winkler")
        return d.winkler_thickness > 0 ? contact::winkler_round_force(d.geometry, d.winkler_thickness, delta) : nan;
      const auto &t = worn ? d.fe_worn : d.fe_fresh;
      if (delta < t.approaches().front() || delta > t.approaches().back())
        return nan; // the FE curve is shown where it was computed
      return t.evaluate(delta, 0, 0).force;
    }

    std::vector<std::string>
    curve_laws(const JointData &d)
    {
      std::vector<std::string> laws{"lankarani-nikravesh", "johnson", "esdu-78035"};
      if (d.winkler_thickness > 0)
        laws.push_back("winkler");
      laws.push_back("fe");
      return laws;
    }

    void
    add_curves(ContactComparison &c, const std::vector<JointData> &joints)
    {
      double lo = std::numeric_limits<double>::infinity(), hi = 0;
      for (const auto &d : joints)
        {
          lo = std::min(lo, d.fe_fresh.approaches().front());
          hi = std::max(hi, d.fe_fresh.approaches().back());
        }
      for (int i = 0; i < n_grid; ++i)
        c.approach.push_back(lo * std::pow(hi / lo, double(i) / (n_grid - 1)));
      for (const auto &d : joints)
        for (const bool worn : {false, true})
          {
            if (worn && !d.has_worn)
              continue;
            for (const auto &law : worn ? std::vector<std::string>{"fe"} : curve_laws(d))
              {
                ForceCurve fc{d.name, law, worn ? "worn" : "fresh", {}};
                for (const double x : c.approach)
                  fc.force.push_back(law_force(d, law, x, worn));
                c.curves.push_back(fc);
                LawDeviation dev{d.name, law, fc.state, {}};
                for (const double F : c.reference_loads)
                  dev.ratio.push_back(law_force(d, law, approach_at(d.fe_fresh, F), worn) /
                                      F); // worn: against fresh FE
                c.deviations.push_back(dev);
              }
          }
    }
  } // namespace

  namespace
  {
    /**
     * ∫ F_n dt and the time in contact (F_n > 0) of every clearance joint of a run, by the
     * trapezoidal rule on the accepted steps: their ratio is the mean contact force.
     */
    class ContactForceIntegral : public mbs::StepObserver
    {
    public:
      explicit ContactForceIntegral(const io::Scene &scene)
        : joints(scene.clearance_joints)
        , impulse(joints.size(), 0.0)
        , contact_time(joints.size(), 0.0)
        , last_force(joints.size(), 0.0)
      {
      }

      void
      on_start(const mbs::StepContext &c) override
      {
        t_last = c.t;
        for (std::size_t j = 0; j < joints.size(); ++j)
          last_force[j] = normal_force(j, c);
      }

      void
      on_step(const mbs::StepContext &c) override
      {
        const double h = c.t - t_last;
        t_last         = c.t;
        for (std::size_t j = 0; j < joints.size(); ++j)
          {
            const double force = normal_force(j, c);
            impulse[j] += 0.5 * h * (force + last_force[j]);
            contact_time[j] += 0.5 * h * ((force > 0 ? 1 : 0) + (last_force[j] > 0 ? 1 : 0));
            last_force[j] = force;
          }
      }

      /** Mean F_n of joint @p j over its time in contact [N] (0 without contact). */
      double
      mean_contact_force(const std::size_t j) const
      {
        return contact_time[j] > 0 ? impulse[j] / contact_time[j] : 0.0;
      }

    private:
      double
      normal_force(const std::size_t j, const mbs::StepContext &c) const
      {
        const auto n = c.simulation.get_mechanism().n_coordinates();
        return joints[j]->diagnostics(mbs::StateView(c.y.data(), c.y.data() + n)).normal_force;
      }

      std::vector<contact::ClearanceJoint *> joints;
      std::vector<double>                    impulse, contact_time, last_force;
      double                                 t_last = 0;
    };

    /** The request's overrides with every clearance joint on @p law (its restitution kept), no files. */
    ParameterOverrides
    law_overrides(const ContactComparisonRequest &request, const std::vector<JointData> &joints, const std::string &law)
    {
      ParameterOverrides o = request.overrides;
      for (const auto &d : joints)
        o.set("Joint " + d.name + "/Clearance/Normal force law", law)
          .set("Joint " + d.name + "/Clearance/" + law + "/Restitution coefficient", d.restitution);
      o.set("Output/Time series", "false").set("Analyses/List of analyses", "");
      return o;
    }

    /** The scene with every clearance joint on @p law, up to @p end_time. */
    EffectRow
    effect_of(const ContactComparisonRequest &request,
              const std::vector<JointData>   &joints,
              const std::string              &law,
              const double                    end_time)
    {
      ParameterOverrides o = law_overrides(request, joints, law);
      o.set("Simulation/End time", end_time);
      const Stopwatch      clock;
      io::Scene            scene = io::read_scene(request.scene_file, o);
      ContactForceIntegral forces(scene);
      RunOptions           options;
      options.observers = {&forces};
      const Json s      = run_scene(scene, options);
      EffectRow  row;
      row.law       = law;
      row.wall_time = clock.seconds();
      row.steps     = s.value("steps", 0L);
      for (std::size_t k = 0; k < joints.size(); ++k)
        {
          const Json &j = s.at("clearance_joints").at(joints[k].name);
          row.contact_fraction.push_back(json_number(j.at("fraction_in_contact")));
          row.peak_force.push_back(json_number(j.at("max_normal_force_N")));
          row.mean_contact_force.push_back(forces.mean_contact_force(k));
          row.impacts.push_back(j.at("impacts").get<long>());
          if (j.contains("table_build_time_s"))
            row.table_setup_time += json_number(j.at("table_build_time_s"));
        }
      for (const auto &[name, b] : s.at("bodies").items())
        row.peak_acceleration =
          std::max({row.peak_acceleration, json_number(b.at("max_abs_ax_m_s2")), json_number(b.at("max_abs_ay_m_s2"))});
      return row;
    }

    /**
     * One wear iteration of the scene with every clearance joint on @p law, as steps 1–2
     * of WearLoop::iterate (wear/wear_loop.h) make it: the scene's Cycles per iteration
     * from assembly with a LoadRecorder, then each wearing joint's load history through
     * its pressure model into Archard's law (add_history, with the scene's Pressure
     * evaluation), as `compare-pressure` does. Not run_wear(): its iteration goes on to
     * update the profiles, and the fe law then builds the worn pair's force table
     * (8 × 8 directions), which nothing here would use: measured on the nine-bar, 126 s for
     * the fe law's iteration through run_wear() against 2–4 s for the other laws.
     * The volumes of each wearing joint go into @p row.
     */
    void
    add_wear_iteration(EffectRow                      &row,
                       const ContactComparisonRequest &request,
                       const std::vector<JointData>   &joints,
                       const std::string              &law)
    {
      const Stopwatch clock;
      io::Scene       scene  = io::read_scene(request.scene_file, law_overrides(request, joints, law));
      const double    period = io::cycle_period(scene);
      std::vector<const contact::ClearanceJoint *> wearing;
      for (const auto &w : scene.wear)
        for (const auto *j : scene.clearance_joints)
          if (j->name() == w->joint)
            wearing.push_back(j);
      wear::LoadRecorder loads(wearing);
      RunOptions         options;
      options.end_time  = scene.start_time + scene.wear_loop.cycles_per_iteration * period;
      options.observers = {&loads};
      options.analyses  = false;
      run_scene(scene, options);
      loads.finish();
      for (std::size_t i = 0; i < wearing.size(); ++i)
        {
          const wear::JointWear        &w = *scene.wear[i];
          const contact::JointGeometry &g = wearing[i]->get_description().geometry;
          w.model->update_geometry(g);
          wear::ArchardAccumulator wear(g, w.archard.bushing_coefficient, w.archard.pin_coefficient, *w.model);
          wear.add_history(loads.samples(i),
                           scene.wear_loop.evaluation == wear::PressureEvaluation::every_step,
                           period / scene.wear_loop.samples_per_cycle,
                           scene.start_time);
          row.wear_volume_pin.push_back(wear.pin_volume);
          row.wear_volume_bushing.push_back(wear.bore_volume);
          row.archard_volume_pin.push_back(wear.pin_archard);
          row.archard_volume_bushing.push_back(wear.bore_archard);
        }
      row.wear_wall_time = clock.seconds();
    }

    /** The effect runs of every dynamics law (and in a wear scene their wear iterations). */
    void
    add_effects(ContactComparison              &c,
                const ContactComparisonRequest &request,
                const std::vector<JointData>   &joints,
                const io::Scene                &scene)
    {
      c.cycles              = request.cycles;
      const double end_time = scene.start_time + request.cycles * io::driving_period(scene);
      for (const auto &w : scene.wear)
        c.wear_joints.push_back(w->joint);
      if (!c.wear_joints.empty())
        c.wear_cycles = scene.wear_loop.cycles_per_iteration;
      for (const char *law : dynamics_laws)
        {
          if (request.progress)
            std::cerr << "[wearlink] effect run: " << law << ", " << request.cycles << " cycles"
                      << (c.wear_joints.empty() ? "" : ", then one wear iteration") << "\n";
          c.effects.push_back(effect_of(request, joints, law, end_time));
          if (!c.wear_joints.empty())
            add_wear_iteration(c.effects.back(), request, joints, law);
        }
    }

    /**
     * The four pressure loads of each joint: from the mean to the peak normal force in
     * contact of the lankarani-nikravesh run (the effect run, else a run of
     * request.load_range_cycles); the reference loads for a joint without contact in it.
     * The direction: the deepest bore wear with --worn, else the bushing's −y. How they
     * were chosen, as one sentence, into @p load_range.
     */
    std::vector<PressureJoint>
    pressure_joints(const ContactComparison        &c,
                    const ContactComparisonRequest &request,
                    const std::vector<JointData>   &joints,
                    const io::Scene                &scene,
                    std::string                    &load_range)
    {
      const char *law = dynamics_laws[0];
      auto it = std::find_if(c.effects.begin(), c.effects.end(), [&](const EffectRow &e) { return e.law == law; });
      const double       cycles = it != c.effects.end() ? request.cycles : request.load_range_cycles;
      const EffectRow    range  = it != c.effects.end() ?
                                    *it :
                                    effect_of(request, joints, law, scene.start_time + cycles * io::driving_period(scene));
      std::ostringstream note;
      note << "per joint from the mean to the peak normal force in contact of the " << law << " run (" << cycles
           << " cycles), spaced geometrically; the pin pushed into the bore at ";
      std::vector<PressureJoint> out;
      for (std::size_t k = 0; k < joints.size(); ++k)
        {
          const JointData &d = joints[k];
          PressureJoint    p;
          p.name          = d.name;
          p.fresh         = d.geometry;
          p.worn          = d.worn;
          p.has_worn      = d.has_worn;
          p.direction     = d.has_worn ? d.worn_bore_psi : 1.5 * numbers::pi;
          p.pin_direction = d.has_worn ? d.worn_pin_psi : 0.0;
          p.loads         = spanning_loads(range.mean_contact_force[k], range.peak_force[k]);
          note << (k ? ", " : "") << d.name << " " << format_number(p.direction * 180 / numbers::pi, 4) << "°";
          if (p.loads.empty())
            {
              p.loads = c.reference_loads;
              note << " (no contact in that run: " << format_number(p.loads.front()) << " … "
                   << format_number(p.loads.back()) << " N)";
            }
          out.push_back(p);
        }
      note << (joints.front().has_worn ? " (bushing frame, the deepest bore wear)" : " (bushing frame, its −y)");
      load_range = note.str();
      return out;
    }
  } // namespace

  ContactComparison
  compare_contact(const ContactComparisonRequest &request)
  {
    if (!(request.cycles > 0 && request.cycles <= 1e4))
      throw InputError("--cycles is " + format_number(request.cycles) +
                       "; it must be > 0 and at most 1e4 (the load history of the cycles is kept in memory).");
    if (!request.worn_directory.empty() && !std::filesystem::is_directory(request.worn_directory))
      throw InputError("--worn '" + request.worn_directory +
                       "' is not a directory; give the output directory of a wear run (it holds bore_<J>.csv "
                       "and pin_<J>.csv).");
    io::Scene scene = io::read_scene(request.scene_file, request.overrides);
    if (scene.clearance_joints.empty())
      throw InputError("The scene '" + request.scene_file +
                       "' has no clearance joint ('Model = clearance'): there is no contact law to compare.");
    std::vector<JointData> joints;
    for (const auto *cj : scene.clearance_joints)
      joints.push_back(read_joint(scene, *cj));
    ContactComparison c;
    for (auto &d : joints)
      {
        c.joints.push_back(d.name);
        fe_curves(d, request.worn_directory, request.progress);
      }
    add_curves(c, joints);
    if (request.effects)
      add_effects(c, request, joints, scene);
    std::string load_range;
    const auto  pressure   = pressure_joints(c, request, joints, scene, load_range);
    c.pressures            = contact_pressures(scene, pressure, request.progress);
    c.pressures.load_range = load_range;
    return c;
  }
} // namespace wearlink::workflows

namespace wearlink::workflows
{
  namespace
  {
    std::string
    effects_table(const ContactComparison &c)
    {
      std::ostringstream os;
      os << "Effect of the law on the dynamics (" << format_or_na(c.cycles)
         << " driving cycles; F_mean: over the time in "
         << "contact):\n";
      os << std::left << std::setw(22) << "law";
      for (const auto &j : c.joints)
        os << std::right << std::setw(12) << (j + " contact") << std::setw(12) << (j + " F_max N") << std::setw(13)
           << (j + " F_mean N") << std::setw(11) << (j + " impacts");
      os << std::setw(14) << "a_max m/s²" << std::setw(10) << "steps" << std::setw(10) << "wall s" << std::setw(12)
         << "(tables s)" << '\n';
      for (const auto &e : c.effects)
        {
          os << std::left << std::setw(22) << e.law << std::right;
          for (std::size_t k = 0; k < c.joints.size(); ++k)
            os << std::setw(12) << format_or_na(e.contact_fraction[k], 3) << std::setw(12)
               << format_or_na(e.peak_force[k], 5) << std::setw(13) << format_or_na(e.mean_contact_force[k], 4)
               << std::setw(11) << e.impacts[k];
          os << std::setw(14) << format_or_na(e.peak_acceleration, 5) << std::setw(10) << e.steps << std::setw(10)
             << format_or_na(e.wall_time, 3) << std::setw(12) << format_or_na(e.table_setup_time, 3) << '\n';
        }
      return os.str();
    }

    std::string
    wear_table(const ContactComparison &c)
    {
      std::ostringstream os;
      os << "One wear iteration with each law (" << format_or_na(c.wear_cycles)
         << " simulated cycles from assembly, the scene's pressure model, no extrapolation): worn volume Σ h A of pin "
            "and bushing and Archard's k_D ∫ F_n |v_t| dt of the pin [mm³]:\n";
      os << std::left << std::setw(22) << "law";
      for (const auto &j : c.wear_joints)
        os << std::right << std::setw(14) << (j + " V_pin") << std::setw(14) << (j + " V_bush") << std::setw(14)
           << (j + " kFs_pin");
      os << std::setw(10) << "wall s" << '\n';
      for (const auto &e : c.effects)
        {
          os << std::left << std::setw(22) << e.law << std::right;
          for (std::size_t k = 0; k < c.wear_joints.size(); ++k)
            os << std::setw(14) << format_or_na(e.wear_volume_pin[k] * 1e9, 4) << std::setw(14)
               << format_or_na(e.wear_volume_bushing[k] * 1e9, 4) << std::setw(14)
               << format_or_na(e.archard_volume_pin[k] * 1e9, 4);
          os << std::setw(10) << format_or_na(e.wear_wall_time, 3) << '\n';
        }
      return os.str();
    }
  } // namespace

  std::string
  ContactComparison::table() const
  {
    std::ostringstream os;
    os << "Force of each law at the approach where the FE model of the fresh joint carries the reference load, "
          "relative to that load (1 = FE; the worn row: the FE model of the worn profiles):\n";
    os << std::left << std::setw(8) << "joint" << std::setw(22) << "law" << std::setw(8) << "state";
    for (const double F : reference_loads)
      os << std::right << std::setw(10) << (format_number(F) + " N");
    os << '\n';
    for (const auto &d : deviations)
      {
        os << std::left << std::setw(8) << d.joint << std::setw(22) << d.law << std::setw(8) << d.state;
        for (const double r : d.ratio)
          os << std::right << std::setw(10) << format_or_na(r, 3);
        os << '\n';
      }
    if (!effects.empty())
      os << '\n' << effects_table(*this);
    if (!wear_joints.empty())
      os << '\n' << wear_table(*this);
    if (!pressures.curves.empty())
      os << '\n' << pressures.table();
    return os.str();
  }

  namespace
  {
    void
    write_curves(const std::string &dir, const ContactComparison &c)
    {
      std::ostringstream csv;
      csv << std::setprecision(10) << "approach_m";
      for (const auto &fc : c.curves)
        csv << ",force_N_" << fc.law << '_' << fc.state << '_' << fc.joint;
      csv << '\n';
      for (std::size_t i = 0; i < c.approach.size(); ++i)
        {
          csv << c.approach[i];
          for (const auto &fc : c.curves)
            csv << ',' << fc.force[i];
          csv << '\n';
        }
      write_file_atomically(dir + "/" + io::outputs::force_approach_table, csv.str());
      std::vector<io::PlotSpec> panels;
      for (const auto &joint : c.joints)
        {
          io::PlotSpec spec;
          spec.title   = "joint " + joint;
          spec.x_label = "approach δ [m] (rigid-profile overlap at the FE pin position)";
          spec.y_label = "normal force F [N]";
          spec.log_x = spec.log_y = true;
          spec.key                = io::KeyPlace::inside_top_left;
          spec.powers_of_ten      = true;
          for (const auto &fc : c.curves)
            {
              if (fc.joint != joint)
                continue;
              io::PlotSeries s;
              s.title = fc.law + " (" + fc.state + ")";
              for (std::size_t i = 0; i < c.approach.size(); ++i)
                if (std::isfinite(fc.force[i]) && fc.force[i] > 0)
                  {
                    s.x.push_back(c.approach[i]);
                    s.y.push_back(fc.force[i]);
                  }
              s.look = fc.law == "fe" ? io::line_points("", 3, io::Marker::filled_circle, 0.6) : io::line("", 2);
              spec.series.push_back(s);
            }
          panels.push_back(spec);
        }
      io::plot_panels_png(panels,
                          static_cast<unsigned int>(panels.size()),
                          "Force against approach: simplified contact laws and the FE model",
                          dir + "/" + io::outputs::force_approach_plot,
                          800 * static_cast<int>(panels.size()),
                          700);
    }

    void
    write_tables(const std::string &dir, const ContactComparison &c)
    {
      std::ostringstream dev;
      dev << std::setprecision(8) << "joint,law,state";
      for (const double F : c.reference_loads)
        dev << ",ratio_at_" << F << "_N";
      dev << '\n';
      for (const auto &d : c.deviations)
        {
          dev << d.joint << ',' << d.law << ',' << d.state;
          for (const double r : d.ratio)
            dev << ',' << r;
          dev << '\n';
        }
      write_file_atomically(dir + "/" + io::outputs::deviations, dev.str());
    }

    /**
     * effects.csv: law, cycles; per joint contact fraction, peak and mean contact force,
     * impacts; peak acceleration, steps, wall and table time; in a wear scene then
     * wear_cycles, per wearing joint the volumes of one wear iteration (Σ h A and
     * k_D ∫ F_n |v_t| dt of pin and bushing) and its wall time.
     */
    void
    write_effects(const std::string &dir, const ContactComparison &c)
    {
      std::ostringstream eff;
      eff << std::setprecision(8) << "law,cycles";
      for (const auto &j : c.joints)
        eff << ",contact_fraction_" << j << ",peak_force_N_" << j << ",mean_contact_force_N_" << j << ",impacts_" << j;
      eff << ",peak_acceleration_m_s2,steps,wall_time_s,table_setup_time_s";
      if (!c.wear_joints.empty())
        eff << ",wear_cycles";
      for (const auto &j : c.wear_joints)
        eff << ",wear_volume_pin_m3_" << j << ",wear_volume_bushing_m3_" << j << ",archard_volume_pin_m3_" << j
            << ",archard_volume_bushing_m3_" << j;
      if (!c.wear_joints.empty())
        eff << ",wear_wall_time_s";
      eff << '\n';
      for (const auto &e : c.effects)
        {
          eff << e.law << ',' << c.cycles;
          for (std::size_t k = 0; k < c.joints.size(); ++k)
            eff << ',' << e.contact_fraction[k] << ',' << e.peak_force[k] << ',' << e.mean_contact_force[k] << ','
                << e.impacts[k];
          eff << ',' << e.peak_acceleration << ',' << e.steps << ',' << e.wall_time << ',' << e.table_setup_time;
          if (!c.wear_joints.empty())
            eff << ',' << c.wear_cycles;
          for (std::size_t k = 0; k < c.wear_joints.size(); ++k)
            eff << ',' << e.wear_volume_pin[k] << ',' << e.wear_volume_bushing[k] << ',' << e.archard_volume_pin[k]
                << ',' << e.archard_volume_bushing[k];
          if (!c.wear_joints.empty())
            eff << ',' << e.wear_wall_time;
          eff << '\n';
        }
      write_file_atomically(dir + "/" + io::outputs::effects, eff.str());
    }
  } // namespace

  void
  write_contact_comparison(const std::string &dir, const ContactComparison &c)
  {
    make_output_directory(dir);
    write_curves(dir, c);
    write_tables(dir, c);
    write_effects(dir, c);
    write_contact_pressures(dir, c.pressures);
    write_file_atomically(dir + "/" + io::outputs::compare_contact_log, c.table());
  }
} // namespace wearlink::workflows
