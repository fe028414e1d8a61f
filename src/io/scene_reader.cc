// SPDX-License-Identifier: LGPL-2.1-or-later
// Reading a scene: see scene.h for the sequence. Every entry is declared here once, with
// its pattern (bounds), default, documentation and unit; --print-parameters prints this
// tree, so the README points to it instead of repeating it.
#include "base/exceptions.h"
#include "base/parameters.h"
#include "base/profile.h"
#include "contact/friction_law.h"
#include "contact/normal_force_law.h"
#include "io/analyses_parameters.h"
#include "io/life_parameters.h"
#include "io/profile_file.h"
#include "io/scene.h"
#include "io/uncertainty_parameters.h"
#include "mbs/assembly.h"

#include <filesystem>
#include <set>

namespace wearlink::io
{
  namespace
  {
    using dealii::ParameterHandler;
    namespace P = dealii::Patterns;

    const char *const joint_types = "revolute|translational|fixed-angle|angle-driver";

    /** Upper bound of 'Number of discrete areas' (see its documentation). */
    constexpr int max_discrete_areas = 100000;
    /** Bound of |Start time| and |End time| [s]. */
    constexpr double max_simulated_time = 1e6;
    /** Rows time_series.csv may have (1e8 rows of ~50 columns: about 100 GB). */
    constexpr double max_time_series_rows = 1e8;

    std::string
    join(const std::vector<std::string> &v, const std::string &sep = "|")
    {
      std::string s;
      for (const auto &x : v)
        s += (s.empty() ? "" : sep) + x;
      return s;
    }

    // ------------------------------------------------------------------------------
    // Declarations.

    void
    declare_top(ParameterHandler &prm)
    {
      declare_required(prm,
                       "Scene format",
                       P::Integer(1, 1),
                       "Version of the scene file format; this wearlink reads format 1.",
                       "none");
      declare(prm, "Title", "", P::Anything(), "Free text shown in the run summary.", "none");
      prm.enter_subsection("Mechanism");
      declare_required(prm,
                       "Bodies",
                       P::List(P::Anything(), 1),
                       "Names of the moving bodies; each has a 'subsection Body <name>'. "
                       "'ground' is the fixed frame and is not listed.",
                       "none");
      declare_required(prm,
                       "Joints",
                       P::List(P::Anything(), 1),
                       "Names of the joints and drivers; each has a 'subsection Joint <name>'.",
                       "none");
      declare(prm,
              "Gravity",
              "0, -9.81",
              point_pattern(),
              "Gravitational acceleration (x, y). Set 0, 0 to switch gravity off.",
              "m/s²");
      prm.leave_subsection();
    }

    void
    declare_body(ParameterHandler &prm)
    {
      declare_required(prm,
                       "Mass",
                       P::Double(0, 1e6),
                       "Mass of the body, 0 < m ≤ 1e6 kg: no link of a planar mechanism weighs more than "
                       "1000 t, so a larger value is a mistake of units or digits.",
                       "kg");
      declare_required(prm,
                       "Moment of inertia",
                       P::Double(0, 1e6),
                       "Moment of inertia about the centre of mass, 0 < I ≤ 1e6 kg m² (a 1000-t link "
                       "of 100 m would have 1e9; planar linkages stay far below 1e6).",
                       "kg m²");
      declare_required(prm,
                       "Initial position",
                       point_pattern(),
                       "Guess of the centre-of-mass position at the start time; assembly "
                       "moves it onto the constraints (the branch nearest the guess).",
                       "m");
      declare(prm,
              "Initial angle",
              "0",
              P::Double(),
              "Guess of the body angle (its x-axis from the global x-axis) at the start.",
              "rad");
      declare(prm,
              "Initial velocity",
              "0, 0",
              point_pattern(),
              "Guess of the centre-of-mass velocity, projected onto the constraints.",
              "m/s");
      declare(prm,
              "Initial angular velocity",
              "0",
              P::Double(),
              "Guess of the angular velocity, projected onto the constraints.",
              "rad/s");
    }

    /**
     * The entries of "Joint <name>/Clearance": geometry, materials, profiles, and every
     * registered normal force law, friction law and wear model (each in its own
     * subsection; only the chosen ones are read).
     */
    void
    declare_clearance(ParameterHandler &prm)
    {
      declare(prm,
              "Bushing on",
              "body 2",
              P::Selection("body 1|body 2"),
              "Which body holds the bore (bushing); the other holds the pin. The joint's "
              "attachment points are the bore and pin centres.",
              "none");
      declare_required(prm,
                       "Bore radius",
                       P::Double(1e-6, 1),
                       "Nominal bore radius R1, 1 µm … 1 m (the range of pin joints; beyond it the "
                       "value is a mistake of units).",
                       "m");
      declare_required(prm,
                       "Radial clearance",
                       P::Double(0, 0.5),
                       "c = R1 − R2 (> 0); the pin radius is R1 − c. At most half the Bore radius: a "
                       "pin less than half the bore's size is no clearance joint (the contact laws "
                       "assume nearly conforming surfaces).",
                       "m");
      declare_required(prm,
                       "Axial length",
                       P::Double(1e-6, 1),
                       "Contact length along the pin axis (used by pressure models), 1 µm … 1 m.",
                       "m");
      declare_required(prm,
                       "Bushing elastic modulus",
                       P::Double(1e6, 1e13),
                       "E of the bushing, 1e6 … 1e13 Pa: from soft rubber (~1 MPa) to beyond diamond "
                       "(1.2e12 Pa); outside it the value is a mistake of units.",
                       "Pa");
      declare_required(prm, "Bushing Poisson ratio", P::Double(0, 0.5), "ν of the bushing, 0 ≤ ν < 0.5.", "none");
      declare_required(prm, "Pin elastic modulus", P::Double(1e6, 1e13), "E of the pin, 1e6 … 1e13 Pa.", "Pa");
      declare_required(prm, "Pin Poisson ratio", P::Double(0, 0.5), "ν of the pin, 0 ≤ ν < 0.5.", "none");
      declare(prm,
              "Effective radius",
              "internal",
              P::Selection("internal|seed-printed"),
              "Relative radius R* in the stiffness K = 4/(3(σ1 + σ2)) √R* (seed eq. 10): "
              "'internal' R1 R2/(R1 − R2), correct for a pin inside a bore; "
              "'seed-printed' R1 R2/(R1 + R2) as printed in the seed (≈5× softer here), "
              "only for reproducing the paper.",
              "none");
      declare_required(prm,
                       "Normal force law",
                       P::Selection(contact::normal_force_laws().pattern()),
                       "Normal contact force law." + contact::normal_force_laws().documentation(),
                       "none");
      declare_required(prm,
                       "Friction law",
                       P::Selection(contact::friction_law_pattern()),
                       "Tangential force law. 'none': no tangential force is computed." +
                         contact::friction_laws().documentation(),
                       "none");
      declare(prm,
              "Initial eccentricity",
              "0, 0",
              point_pattern(),
              "Pin centre − bore centre at assembly, in the bushing body's frame.",
              "m");
      declare(prm,
              "Bore profile file",
              "",
              P::Anything(),
              "CSV (angle_rad, radius_m) of a worn bore in the bushing's frame; empty: "
              "round. Relative paths are taken from the scene file's folder.",
              "none");
      declare(prm,
              "Pin profile file",
              "",
              P::Anything(),
              "CSV (angle_rad, radius_m) of a worn pin in the pin body's frame; empty: "
              "round.",
              "none");
      declare(prm,
              "Number of discrete areas",
              "360",
              P::Integer(8, max_discrete_areas),
              "Samples of each surface profile (discrete areas for wear), 8 … 100000: at 1e5 "
              "areas an area of a 10-mm bore is 0.6 µm wide, finer than its roughness and than "
              "any FE mesh of it; more would only exhaust memory.",
              "none");
      contact::normal_force_laws().declare_all(prm);
      contact::friction_laws().declare_all(prm);
      wear::declare_joint_wear(prm);
    }

    void
    declare_joint(ParameterHandler &prm, const std::string &body_names)
    {
      declare_required(prm,
                       "Type",
                       P::Selection(joint_types),
                       "revolute: hinge (ideal or with clearance); translational: body 2 slides "
                       "along an axis fixed in body 1 without rotating relative to it; "
                       "fixed-angle: θ2 − θ1 = Angle offset; angle-driver: θ2 − θ1 = Angle "
                       "offset + Angular velocity · t (a rheonomic driver).",
                       "none");
      declare(prm,
              "Body 1",
              "ground",
              P::Selection(body_names),
              "First body (the guide of a translational joint, the frame a driver "
              "measures from). 'ground' is the fixed frame.",
              "none");
      declare_required(prm, "Body 2", P::Selection(body_names), "Second body.", "none");
      declare(prm,
              "Point on body 1",
              "0, 0",
              point_pattern(),
              "Attachment point in body 1's frame (centre of mass origin, body x-axis); "
              "global coordinates if body 1 is ground.",
              "m");
      declare(prm, "Point on body 2", "0, 0", point_pattern(), "Attachment point in body 2's frame.", "m");
      declare(prm,
              "Axis on body 1",
              "1, 0",
              point_pattern(),
              "Translational joints: sliding direction in body 1's frame.",
              "none");
      declare(prm,
              "Angle offset",
              "0",
              P::Double(),
              "translational, fixed-angle and angle-driver: θ2 − θ1 at t = 0.",
              "rad");
      declare(prm,
              "Angular velocity",
              "0",
              P::Double(-1e4, 1e4),
              "angle-driver: constant rate of θ2 − θ1, at most 1e4 rad/s in magnitude (95,000 rpm: "
              "beyond any mechanism this tool models).",
              "rad/s");
      declare(prm,
              "Model",
              "ideal",
              P::Selection("ideal|clearance"),
              "Revolute joints: 'ideal' is a kinematic constraint (no contact code runs); "
              "'clearance' is a pin in a bore with contact forces (subsection Clearance).",
              "none");

      prm.enter_subsection("Clearance");
      declare_clearance(prm);
      prm.leave_subsection();
    }

    /** Integrator: method, tolerances, step limits and budget, Baumgarte factors. */
    void
    declare_integrator(ParameterHandler &prm)
    {
      prm.enter_subsection("Integrator");
      declare(prm,
              "Method",
              "dopri5",
              P::Selection(mbs::integrator_names()),
              "rk4: fixed step (the seed's 1e-4 s), contact events switch at step ends; "
              "dopri5: adaptive Dormand–Prince 5(4) with error control, dense output and "
              "contact onset/separation located in time (recommended); "
              "dop853: adaptive Dormand–Prince 8(5,3), the same with a higher order (fewer, "
              "dearer steps: 12 evaluations each, 3 more where dense output is read); "
              "ros34pw2: the linearly implicit Rosenbrock-W method ROS34PW2 (order 3), its "
              "Jacobian from the contacts' stiff directions only, events as dopri5 (for "
              "studies: on its own it is slower than dopri5 wherever the motion is not "
              "stiff); dopri5-stiff: dopri5 that hands over to ros34pw2 while its steps are "
              "limited by stability (a pin sticking in its bushing during an impact, where "
              "the friction ramp is a damper of ~1e6 N s/m) and back when they are not.",
              "none");
      declare(prm,
              "Time step",
              "1e-4",
              P::Double(0, 1),
              "rk4 step size, 0 < h ≤ 1 s. A step above 1/100 of the driving period cannot follow "
              "a cycle and is warned about (summary.json, warnings).",
              "s");
      declare(prm,
              "Relative tolerance",
              "1e-6",
              P::Double(1e-14, 1),
              "dopri5: relative error tolerance per step, 1e-14 … 1 (below 1e-14 is round-off).",
              "none");
      declare(prm,
              "Position tolerance",
              "1e-9",
              P::Double(1e-15, 1e-3),
              "dopri5: absolute error tolerance of positions (m) and angles (rad), 1e-15 … 1e-3 "
              "(a looser one could not resolve any clearance).",
              "m");
      declare(prm,
              "Velocity tolerance",
              "1e-6",
              P::Double(1e-15, 1),
              "dopri5: absolute error tolerance of velocities (m/s, rad/s), 1e-15 … 1.",
              "m/s");
      declare(prm,
              "Maximum step",
              "1e-3",
              P::Double(1e-7, 1),
              "dopri5: largest step, 1e-7 … 1 s (below 1e-7 s a simulated second would take more than "
              "ten million steps: the error control, not this cap, resolves fast contact).",
              "s");
      declare(prm,
              "Minimum step",
              "1e-14",
              P::Double(0, 1e-3),
              "dopri5: a step below this is a numerical failure; at most 1e-3 s.",
              "s");
      declare(prm,
              "Maximum steps per second",
              "1e7",
              P::Double(0),
              "Step budget: more than 50,000 + this × the simulated time (s) steps, rejected ones "
              "included, end the run as a numerical failure (exit 3) instead of crawling on for "
              "hours; 0: no budget. The shipped scenes need 1.2e4 (nine-bar) to 1.3e5 (slider-crank "
              "at 5000 rpm) steps per second; a scene that needs 1e7 has contact or constraint "
              "stiffness far beyond its model (a geometry error, a modulus off by orders).",
              "1/s");
      declare(prm,
              "Baumgarte alpha",
              "5",
              P::Double(0, 1e6),
              "α of the Baumgarte stabilization γ − 2αΦ̇ − β²Φ (seed eq. 27), 0 … 1e6 1/s (a "
              "faster correction than 1 µs is stiffer than any step can follow).",
              "1/s");
      declare(prm, "Baumgarte beta", "5", P::Double(0, 1e6), "β of the Baumgarte stabilization, 0 … 1e6 1/s.", "1/s");
      prm.leave_subsection();
    }

    /** Simulation: the simulated interval. */
    void
    declare_simulation(ParameterHandler &prm)
    {
      prm.enter_subsection("Simulation");
      declare(prm,
              "Start time",
              "0",
              P::Double(-max_simulated_time, max_simulated_time),
              "Time at which assembly happens, |t| ≤ 1e6 s.",
              "s");
      declare_required(prm,
                       "End time",
                       P::Double(-max_simulated_time, max_simulated_time),
                       "Time at which the run stops, |t| ≤ 1e6 s: 11.6 days of motion, far more than "
                       "any run integrates step by step (wear runs represent long service by "
                       "extrapolation instead).",
                       "s");
      prm.leave_subsection();
    }

    /** Output: time series and plots. */
    void
    declare_output(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      declare(prm,
              "Time series",
              "true",
              P::Bool(),
              "Write time_series.csv (positions, velocities, accelerations, joint "
              "quantities, driver torques, energies).",
              "none");
      declare(prm,
              "Time series interval",
              "1e-3",
              P::Double(0),
              "Sampling interval of time_series.csv (dense output); 0 writes every "
              "accepted step.",
              "s");
      declare(prm,
              "Plots",
              "true",
              P::Bool(),
              "Write the first-look PNGs of `wearlink run` (read back from time_series.csv, "
              "so only with Time series = true): orbit_<J>.png, the journal-centre orbit of "
              "each clearance joint in its bushing's frame inside the clearance circle; "
              "contact_forces.png, the normal and friction force of each clearance joint "
              "against time; accelerations.png, the acceleration of the Plot bodies. false "
              "writes none (tests, benchmarks, sweeps).",
              "none");
      declare(prm,
              "Plot bodies",
              "",
              P::Anything(),
              "Comma-separated bodies whose acceleration accelerations.png shows and the "
              "printed summary reports. Empty: the bodies that slide on a translational "
              "joint (Body 2 of it, e.g. the slider of a press); if there is none, the body "
              "with the largest peak acceleration component of the run.",
              "none");
      prm.leave_subsection();
    }

    void
    declare_numerics(ParameterHandler &prm)
    {
      declare_integrator(prm);
      declare_simulation(prm);
      declare_output(prm);
    }

    void
    declare_scene(ParameterHandler &prm, const std::vector<std::string> &bodies, const std::vector<std::string> &joints)
    {
      declare_top(prm);
      for (const auto &b : bodies)
        {
          prm.enter_subsection("Body " + b);
          declare_body(prm);
          prm.leave_subsection();
        }
      const std::string names = "ground|" + join(bodies);
      for (const auto &j : joints)
        {
          prm.enter_subsection("Joint " + j);
          declare_joint(prm, names);
          prm.leave_subsection();
        }
      declare_numerics(prm);
      declare_analyses(prm);
      wear::declare_wear_loop(prm);
      declare_life(prm);
      declare_uncertainty(prm);
    }

    // ------------------------------------------------------------------------------
    // Pre-scan: the names that decide which subsections exist.

    void
    pre_scan(const std::string        &file,
             const ParameterOverrides &overrides,
             std::vector<std::string> &bodies,
             std::vector<std::string> &joints)
    {
      ParameterHandler prm;
      prm.enter_subsection("Mechanism");
      prm.declare_entry("Bodies", "", P::Anything());
      prm.declare_entry("Joints", "", P::Anything());
      prm.leave_subsection();
      read_prm_file(prm, file, true);
      ParameterOverrides mech;
      for (const auto &o : overrides.settings())
        if (o.rfind("Mechanism/Bodies", 0) == 0 || o.rfind("Mechanism/Joints", 0) == 0)
          mech.append({{o}});
      apply_overrides(prm, mech);
      ParameterReader r(prm, file);
      r.enter("Mechanism");
      bodies = r.get_list("Bodies");
      joints = r.get_list("Joints");
      std::set<std::string> seen;
      for (const auto &b : bodies)
        {
          if (b == "ground")
            r.fail("Bodies", "'ground' is the fixed frame and must not be listed as a body");
          if (!seen.insert(b).second)
            r.fail("Bodies", "the body name '" + b + "' appears twice; names must be unique");
        }
      seen.clear();
      for (const auto &j : joints)
        if (!seen.insert(j).second)
          r.fail("Joints", "the joint name '" + j + "' appears twice; names must be unique");
    }

    /** Required entries inside inactive parts of the tree are not required. */
    void
    check_active_required_entries(const ParameterHandler         &prm,
                                  const std::string              &file,
                                  const std::vector<std::string> &inactive_prefixes)
    {
      std::vector<std::string> missing;
      for (const auto &m : prm.get_entries_wrongly_not_set())
        {
          // Demangle deal.II's internal path ("_20" = blank, "." between levels).
          std::string p;
          for (std::size_t i = 0; i < m.size(); ++i)
            if (m[i] == '.')
              p += '/';
            else if (m[i] == '_' && i + 2 < m.size() + 1 && std::isxdigit(m[i + 1]) && std::isxdigit(m[i + 2]))
              {
                p += static_cast<char>(std::stoi(m.substr(i + 1, 2), nullptr, 16));
                i += 2;
              }
            else
              p += m[i];
          bool inactive = false;
          for (const auto &prefix : inactive_prefixes)
            if (p.rfind(prefix, 0) == 0)
              inactive = true;
          if (!inactive)
            missing.push_back(p);
        }
      if (!missing.empty())
        throw InputError("In " + file +
                         ", these required entries are not set (physical data has no "
                         "default; set them in the scene or with --set):\n  " +
                         join(missing, "\n  "));
    }

    mbs::Vec2
    vec(const std::array<double, 2> &p)
    {
      return {p[0], p[1]};
    }

    std::string
    resolve_relative(const std::string &scene_file, const std::string &path)
    {
      namespace fs = std::filesystem;
      fs::path p   = path;
      if (p.is_relative())
        p = fs::path(scene_file).parent_path() / p;
      return p.string();
    }

    // ------------------------------------------------------------------------------
    // Construction.

    /**
     * Bore radius, clearance and the two profiles (round, or from profile files) of the
     * clearance joint in @p r's current section into @p d; returns the radial clearance.
     */
    double
    read_clearance_profiles(ParameterReader &r, contact::ClearanceJointDescription &d)
    {
      const double bore      = r.get_positive("Bore radius");
      const double clearance = r.get_double("Radial clearance");
      if (!(clearance > 0))
        r.fail("Radial clearance",
               "it must be > 0 m",
               "A clearance joint needs a gap; use Model = ideal for a joint without one.");
      if (!(clearance < bore))
        r.fail("Radial clearance",
               "it must be smaller than the Bore radius (" + format_number(bore) +
                 " m): the pin radius R1 − c would be ≤ 0 (pin larger than the bore)");
      if (!(clearance <= 0.5 * bore))
        r.fail("Radial clearance",
               "it must be at most half the Bore radius (" + format_number(0.5 * bore, 4) +
                 " m): the pin would be less than half the bore's size, no clearance joint",
               "Radial clearances of pin joints are micrometres to a few tenths of a millimetre.");
      const double pin_radius = bore - clearance;
      const auto   n_areas    = static_cast<unsigned int>(r.get_integer("Number of discrete areas"));

      auto profile = [&](const std::string &entry, double radius) {
        const std::string f = r.get(entry);
        if (f.empty())
          return Profile::round(radius, n_areas);
        const std::string path = resolve_relative(r.file(), f);
        if (!std::filesystem::exists(path))
          r.fail(entry, "the file '" + path + "' does not exist");
        return io::read_profile_csv(path, n_areas);
      };
      d.geometry.bore = profile("Bore profile file", bore);
      d.geometry.pin  = profile("Pin profile file", pin_radius);
      if (!(d.geometry.bore.mean_radius() > d.geometry.pin.mean_radius()))
        r.fail_section("the pin profile (mean radius " + format_number(d.geometry.pin.mean_radius()) +
                       " m) is not smaller than the bore profile (mean radius " +
                       format_number(d.geometry.bore.mean_radius()) + " m): the pin does not fit in the bore.");
      io::check_pin_inside_bore(r, d.geometry.bore, d.geometry.pin);
      return clearance;
    }

    /** Axial length, materials and the effective-radius convention into @p d. */
    void
    read_clearance_materials(ParameterReader &r, contact::ClearanceJointDescription &d)
    {
      d.geometry.axial_length                = r.get_positive("Axial length");
      d.geometry.bushing.youngs_modulus      = r.get_positive("Bushing elastic modulus");
      d.geometry.bushing.poisson_ratio       = r.get_double("Bushing Poisson ratio");
      d.geometry.pin_material.youngs_modulus = r.get_positive("Pin elastic modulus");
      d.geometry.pin_material.poisson_ratio  = r.get_double("Pin Poisson ratio");
      if (!(d.geometry.bushing.poisson_ratio < 0.5))
        r.fail("Bushing Poisson ratio", "it must be < 0.5 (incompressible is not allowed)");
      if (!(d.geometry.pin_material.poisson_ratio < 0.5))
        r.fail("Pin Poisson ratio", "it must be < 0.5 (incompressible is not allowed)");
      d.effective_radius = r.get("Effective radius") == "internal" ? contact::EffectiveRadius::internal :
                                                                     contact::EffectiveRadius::seed_printed;
    }

    void
    build_clearance_joint(Scene             &scene,
                          ParameterReader   &r,
                          const std::string &joint,
                          int                body_1,
                          const mbs::Vec2   &point_1,
                          int                body_2,
                          const mbs::Vec2   &point_2)
    {
      r.enter("Clearance");
      contact::ClearanceJointDescription d;
      d.name               = joint;
      const bool bush_on_1 = r.get("Bushing on") == "body 1";
      d.bushing_body       = bush_on_1 ? body_1 : body_2;
      d.bushing_point      = bush_on_1 ? point_1 : point_2;
      d.pin_body           = bush_on_1 ? body_2 : body_1;
      d.pin_point          = bush_on_1 ? point_2 : point_1;
      if (d.pin_body == mbs::ground && d.bushing_body == mbs::ground)
        r.fail_section("a clearance joint needs at least one moving body.");

      const double clearance = read_clearance_profiles(r, d);
      read_clearance_materials(r, d);

      d.normal_force_law = r.get("Normal force law");
      auto normal        = contact::normal_force_laws().create(d.normal_force_law, r, "Normal force law");
      std::unique_ptr<contact::FrictionLaw> friction;
      if (r.get("Friction law") != "none")
        friction = contact::friction_laws().create(r.get("Friction law"), r, "Friction law");

      // Assembly pins the pin centre at the initial eccentricity (bushing frame).
      const mbs::Vec2 e0 = vec(r.get_point("Initial eccentricity"));
      if (!(e0.norm() < clearance))
        r.fail("Initial eccentricity",
               "its length must be smaller than the radial clearance (" + format_number(clearance) + " m)");
      if (auto w = wear::read_joint_wear(r, joint))
        scene.wear.push_back(std::move(w));
      r.leave();

      auto joint_element =
        std::make_unique<contact::ClearanceJoint>(std::move(d), std::move(normal), std::move(friction));
      const auto &desc = joint_element->get_description();
      // Rotate e0 with the bushing's initial angle guess (exact after assembly for a
      // ground bushing; a good guess otherwise).
      const double bushing_angle =
        desc.bushing_body == mbs::ground ? 0.0 : scene.mechanism->get_bodies()[desc.bushing_body].initial_angle;
      // A revolute constraint's second body moves: with the pin on the ground, the pair is
      // written the other way round (p_bushing − p_pin = −e).
      const mbs::Vec2 e = mbs::rotate(e0, bushing_angle);
      scene.assembly_constraints.push_back(
        desc.pin_body == mbs::ground ?
          mbs::make_revolute(joint, desc.pin_body, desc.pin_point, desc.bushing_body, desc.bushing_point, -e) :
          mbs::make_revolute(joint, desc.bushing_body, desc.bushing_point, desc.pin_body, desc.pin_point, e));
      scene.clearance_joints.push_back(joint_element.get());
      scene.mechanism->add_force_element(std::move(joint_element));
    }

    /** Output/Plots and Output/Plot bodies (the sliders are already in plot_bodies). */
    void
    read_plot_settings(ParameterReader &r, Scene &scene, const mbs::Mechanism &mech)
    {
      scene.plots       = r.get_bool("Plots");
      const auto chosen = r.get_list("Plot bodies");
      for (const auto &b : chosen)
        if (mech.body_index(b) < 0)
          {
            std::vector<std::string> names;
            for (const auto &body : mech.get_bodies())
              names.push_back(body.name);
            r.fail("Plot bodies", "'" + b + "' is not a moving body; the bodies are " + join(names, ", "));
          }
      if (!chosen.empty())
        scene.plot_bodies = chosen;
    }

    /** Integrator, simulated interval and time-series output of @p scene. */
    void
    read_numerics(ParameterReader &r, Scene &scene, mbs::Mechanism &mech)
    {
      r.enter("Integrator");
      auto &is              = scene.simulation.integrator;
      is.type               = mbs::parse_integrator_type(r.get("Method"));
      is.time_step          = r.get_positive("Time step");
      is.relative_tolerance = r.get_positive("Relative tolerance");
      is.absolute_tolerance = {r.get_positive("Position tolerance"), r.get_positive("Velocity tolerance")};
      is.max_step           = r.get_positive("Maximum step");
      is.min_step           = r.get_positive("Minimum step");
      if (!(is.min_step < is.max_step))
        r.fail("Minimum step", "it must be smaller than Maximum step (" + format_number(is.max_step) + " s)");
      scene.simulation.max_steps_per_second = r.get_double("Maximum steps per second");
      mech.set_baumgarte(r.get_double("Baumgarte alpha"), r.get_double("Baumgarte beta"));
      r.leave();

      r.enter("Simulation");
      scene.start_time = r.get_double("Start time");
      scene.end_time   = r.get_double("End time");
      if (!(scene.end_time > scene.start_time))
        r.fail("End time", "it must be later than Start time (" + format_number(scene.start_time) + " s)");
      r.leave();

      r.enter("Output");
      scene.write_time_series = r.get_bool("Time series");
      scene.output_interval   = r.get_double("Time series interval");
      const double rows       = (scene.end_time - scene.start_time) / scene.output_interval;
      if (scene.write_time_series && scene.output_interval > 0 && rows > max_time_series_rows)
        r.fail("Time series interval",
               "it would write " + format_number(rows, 3) + " rows over " +
                 format_number(scene.end_time - scene.start_time) + " s; at most " +
                 format_number(max_time_series_rows, 3) + " are allowed",
               "Choose a longer interval, or set Time series = false.");
      read_plot_settings(r, scene, mech);
      r.leave();
    }

    void
    build_scene(Scene                          &scene,
                ParameterHandler               &prm,
                const std::vector<std::string> &bodies,
                const std::vector<std::string> &joints)
    {
      ParameterReader r(prm, scene.file);
      scene.title     = r.get("Title");
      scene.mechanism = std::make_unique<mbs::Mechanism>();
      auto &mech      = *scene.mechanism;

      r.enter("Mechanism");
      mech.set_gravity(vec(r.get_point("Gravity")));
      r.leave();

      for (const auto &name : bodies)
        {
          r.enter("Body " + name);
          mbs::Body b;
          b.name                     = name;
          b.mass                     = r.get_positive("Mass");
          b.inertia                  = r.get_positive("Moment of inertia");
          b.initial_position         = vec(r.get_point("Initial position"));
          b.initial_angle            = r.get_double("Initial angle");
          b.initial_velocity         = vec(r.get_point("Initial velocity"));
          b.initial_angular_velocity = r.get_double("Initial angular velocity");
          mech.add_body(b);
          r.leave();
        }

      for (const auto &name : joints)
        {
          r.enter("Joint " + name);
          const std::string type = r.get("Type");
          const int         b1   = mech.body_index(r.get("Body 1"));
          const int         b2   = mech.body_index(r.get("Body 2"));
          if (b2 == mbs::ground)
            r.fail("Body 2", "it must be a moving body; put 'ground' in Body 1");
          if (b1 == b2)
            r.fail("Body 2", "it must differ from Body 1");
          const mbs::Vec2 p1        = vec(r.get_point("Point on body 1"));
          const mbs::Vec2 p2        = vec(r.get_point("Point on body 2"));
          const bool      clearance = r.get("Model") == "clearance";
          if (clearance && type != "revolute")
            r.fail("Model", "'clearance' is only allowed for Type = revolute");

          if (type == "revolute" && clearance)
            {
              build_clearance_joint(scene, r, name, b1, p1, b2, p2);
              EffectLedger::instance().record_construction("joint model", "clearance");
            }
          else if (type == "revolute")
            {
              mech.add_constraint(mbs::make_revolute(name, b1, p1, b2, p2));
              EffectLedger::instance().record_construction("joint model", "ideal");
            }
          else if (type == "translational")
            {
              const mbs::Vec2 axis = vec(r.get_point("Axis on body 1"));
              if (!(axis.norm() > 0))
                r.fail("Axis on body 1", "it must be a non-zero direction");
              mech.add_constraint(mbs::make_translational(name, b1, p1, axis, b2, p2, r.get_double("Angle offset")));
              scene.plot_bodies.push_back(r.get("Body 2")); // a slider (Output/Plot bodies)
            }
          else if (type == "fixed-angle")
            mech.add_constraint(mbs::make_fixed_angle(name, b1, b2, r.get_double("Angle offset")));
          else if (type == "angle-driver")
            {
              scene.drivers.push_back(static_cast<unsigned int>(mech.get_constraints().size()));
              mech.add_constraint(
                mbs::make_angle_driver(name, b1, b2, r.get_double("Angle offset"), r.get_double("Angular velocity")));
            }
          else
            r.fail("Type", "valid joint types are " + std::string(joint_types));
          r.leave();
        }

      read_numerics(r, scene, mech);

      scene.wear_loop = wear::read_wear_loop(r);
      for (auto *j : scene.clearance_joints)
        j->set_clearance_form(scene.wear_loop.clearance_form);

      mech.finalize();
      unsigned int m = mech.n_constraint_equations();
      for (const auto &c : scene.assembly_constraints)
        m += c->n_equations();
      if (m > mech.n_coordinates())
        throw InputError("In " + scene.file + ", the joints impose " + std::to_string(m) + " constraint equations on " +
                         std::to_string(mech.n_coordinates()) +
                         " coordinates (3 per body): the mechanism is over-constrained. "
                         "Remove a joint or driver.");
    }
  } // namespace

  Scene
  read_scene(const std::string &file, const ParameterOverrides &overrides)
  {
    std::vector<std::string> bodies, joints;
    pre_scan(file, overrides, bodies, joints);

    Scene scene;
    scene.file       = file;
    scene.overrides  = overrides;
    scene.parameters = std::make_unique<ParameterHandler>();
    auto &prm        = *scene.parameters;
    declare_scene(prm, bodies, joints);
    read_prm_file(prm, file, false);
    apply_overrides(prm, overrides);

    // Required entries count only where they are used: the Clearance subsection of an
    // ideal joint and the subsections of laws a joint did not choose are inactive.
    std::vector<std::string> inactive;
    for (const auto &j : joints)
      {
        prm.enter_subsection("Joint " + j);
        const bool clearance = prm.get("Model") == "clearance" && prm.get("Type") == "revolute";
        if (!clearance)
          inactive.push_back("Joint " + j + "/Clearance/");
        else
          {
            prm.enter_subsection("Clearance");
            for (const auto &law : contact::normal_force_laws().names())
              if (law != prm.get("Normal force law"))
                inactive.push_back("Joint " + j + "/Clearance/" + law + "/");
            for (const auto &law : contact::friction_laws().names())
              if (law != prm.get("Friction law"))
                inactive.push_back("Joint " + j + "/Clearance/" + law + "/");
            for (const auto &section : wear::inactive_wear_sections(prm))
              inactive.push_back("Joint " + j + "/Clearance/" + section);
            prm.leave_subsection();
          }
        prm.leave_subsection();
      }
    check_active_required_entries(prm, file, inactive);

    build_scene(scene, prm, bodies, joints);
    scene.analyses    = parse_analyses(prm, scene);
    scene.life        = parse_life(prm, scene);
    scene.uncertainty = parse_uncertainty(prm, file, inactive);
    return scene;
  }

  void
  print_scene_parameters(std::ostream &out, const std::string &file)
  {
    std::vector<std::string> bodies = {"<name>"}, joints = {"<name>"};
    if (!file.empty())
      pre_scan(file, {}, bodies, joints);
    ParameterHandler prm;
    declare_scene(prm, bodies, joints);
    if (!file.empty())
      read_prm_file(prm, file, false);
    prm.print_parameters(out, ParameterHandler::Text);
  }
} // namespace wearlink::io
