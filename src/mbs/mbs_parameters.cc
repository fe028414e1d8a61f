// SPDX-License-Identifier: LGPL-2.1-or-later
#include "mbs/mbs_parameters.h"

#include "base/text.h"

namespace wearlink::mbs
{
  using dealii::ParameterHandler;
  namespace P = dealii::Patterns;

  namespace
  {
    Vec2
    vec(const std::array<double, 2> &p)
    {
      return {p[0], p[1]};
    }
  } // namespace

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

  Body
  read_body(ParameterReader &r, const std::string &name)
  {
    Body b;
    b.name                     = name;
    b.mass                     = r.get_positive("Mass");
    b.inertia                  = r.get_positive("Moment of inertia");
    b.initial_position         = vec(r.get_point("Initial position"));
    b.initial_angle            = r.get_double("Initial angle");
    b.initial_velocity         = vec(r.get_point("Initial velocity"));
    b.initial_angular_velocity = r.get_double("Initial angular velocity");
    return b;
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
  }

  JointEntries
  read_joint(ParameterReader &r, const Mechanism &mechanism)
  {
    JointEntries j;
    j.type   = r.get("Type");
    j.body_1 = mechanism.body_index(r.get("Body 1"));
    j.body_2 = mechanism.body_index(r.get("Body 2"));
    if (j.body_2 == ground)
      r.fail("Body 2", "it must be a moving body; put 'ground' in Body 1");
    if (j.body_1 == j.body_2)
      r.fail("Body 2", "it must differ from Body 1");
    j.point_1   = vec(r.get_point("Point on body 1"));
    j.point_2   = vec(r.get_point("Point on body 2"));
    j.clearance = r.get("Model") == "clearance";
    if (j.clearance && j.type != "revolute")
      r.fail("Model", "'clearance' is only allowed for Type = revolute");
    return j;
  }

  std::unique_ptr<Constraint>
  make_ideal_joint(ParameterReader &r, const std::string &name, const JointEntries &j)
  {
    if (j.type == "revolute")
      return make_revolute(name, j.body_1, j.point_1, j.body_2, j.point_2);
    if (j.type == "translational")
      {
        const Vec2 axis = vec(r.get_point("Axis on body 1"));
        if (!(axis.norm() > 0))
          r.fail("Axis on body 1", "it must be a non-zero direction");
        return make_translational(name, j.body_1, j.point_1, axis, j.body_2, j.point_2, r.get_double("Angle offset"));
      }
    if (j.type == "fixed-angle")
      return make_fixed_angle(name, j.body_1, j.body_2, r.get_double("Angle offset"));
    if (j.type == "angle-driver")
      return make_angle_driver(name,
                               j.body_1,
                               j.body_2,
                               r.get_double("Angle offset"),
                               r.get_double("Angular velocity"));
    r.fail("Type", "valid joint types are " + std::string(joint_types));
  }

  /** Integrator: method, tolerances, step limits and budget, Baumgarte factors. */
  void
  declare_integrator(ParameterHandler &prm)
  {
    prm.enter_subsection("Integrator");
    declare(prm,
            "Method",
            "dopri5",
            P::Selection(integrator_names()),
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
            "Event point",
            "integrated",
            P::Selection("integrated|interpolated"),
            "Where a step that crosses a contact onset or separation ends: integrated (the step is "
            "taken again up to the located event, error-controlled) or interpolated (dopri5 and "
            "dopri5-stiff's explicit phases: the point is read from the step's continuous "
            "extension, one right-hand side instead of a step's six; ~8 % fewer right-hand sides "
            "on the nine-bar, but each event point carries an error up to the tolerance rather "
            "than below it, see doc/performance.md). Other methods always integrate.",
            "none");
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

  void
  read_integrator(ParameterReader &r, SimulationSettings &settings, Mechanism &mechanism)
  {
    r.enter("Integrator");
    auto &is              = settings.integrator;
    is.type               = parse_integrator_type(r.get("Method"));
    is.time_step          = r.get_positive("Time step");
    is.relative_tolerance = r.get_positive("Relative tolerance");
    is.absolute_tolerance = {r.get_positive("Position tolerance"), r.get_positive("Velocity tolerance")};
    is.max_step           = r.get_positive("Maximum step");
    is.interpolate_events = r.get("Event point") == "interpolated";
    is.min_step           = r.get_positive("Minimum step");
    if (!(is.min_step < is.max_step))
      r.fail("Minimum step", "it must be smaller than Maximum step (" + format_number(is.max_step) + " s)");
    settings.max_steps_per_second = r.get_double("Maximum steps per second");
    mechanism.set_baumgarte(r.get_double("Baumgarte alpha"), r.get_double("Baumgarte beta"));
    r.leave();
  }
} // namespace wearlink::mbs
