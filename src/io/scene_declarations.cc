// SPDX-License-Identifier: LGPL-2.1-or-later
#include "io/scene_declarations.h"

#include "base/exceptions.h"
#include "base/parameters.h"
#include "base/text.h"
#include "contact/friction_law.h"
#include "contact/normal_force_law.h"
#include "io/analyses_parameters.h"
#include "io/life_parameters.h"
#include "io/uncertainty_parameters.h"
#include "wear/wear_settings.h"

namespace wearlink::io
{
  namespace
  {
    using dealii::ParameterHandler;
    namespace P = dealii::Patterns;

    /** Upper bound of 'Number of discrete areas' (see its documentation). */
    constexpr int max_discrete_areas = 100000;
    /** Bound of |Start time| and |End time| [s]. */
    constexpr double max_simulated_time = 1e6;

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
  } // namespace

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
    const std::string names = "ground|" + join(bodies, "|");
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
} // namespace wearlink::io
