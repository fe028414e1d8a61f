// SPDX-License-Identifier: LGPL-2.1-or-later
// The scene entries the multibody layer reads, declared here once with their bounds,
// defaults, documentation and units (doc/contributing.md §4), and read back into the
// layer's own types:
//   "Body <name>"                 mass, inertia, initial position, angle and velocities
//   "Joint <name>"                type, bodies, attachment points, axis, angle offset,
//                                 angular velocity, ideal or clearance (the Clearance
//                                 subsection is the contact layer's)
//   "Integrator"                  method, tolerances, step limits and budget, Baumgarte
// The scene reader (io/scene_reader.cc) only assembles what these functions read.
#pragma once

#include "base/parameters.h"
#include "mbs/constraint.h"
#include "mbs/mechanism.h"
#include "mbs/simulation.h"

#include <memory>
#include <string>

namespace wearlink::mbs
{
  /** The joint types a scene may give ('Joint <j>/Type'). */
  inline constexpr const char *joint_types = "revolute|translational|fixed-angle|angle-driver";

  /** The entries of "Body <name>". */
  void
  declare_body(dealii::ParameterHandler &prm);

  /** The body @p name from its subsection (@p r is inside it). */
  Body
  read_body(ParameterReader &r, const std::string &name);

  /** The entries of "Joint <name>" except its Clearance subsection; @p body_names "ground|B1|…". */
  void
  declare_joint(dealii::ParameterHandler &prm, const std::string &body_names);

  /** What every joint says: its type, bodies, attachment points and model. */
  struct JointEntries
  {
    std::string type;
    int         body_1 = ground, body_2 = ground;
    Vec2        point_1{0, 0}, point_2{0, 0};
    bool        clearance = false; ///< a revolute joint with a pin in a bore
  };

  /** A joint's entries (@p r inside its subsection), checked against @p mechanism's bodies. */
  JointEntries
  read_joint(ParameterReader &r, const Mechanism &mechanism);

  /** The constraint of a joint without clearance (reads its axis, offset and rate from @p r). */
  std::unique_ptr<Constraint>
  make_ideal_joint(ParameterReader &r, const std::string &name, const JointEntries &joint);

  /** The entries of "Integrator". */
  void
  declare_integrator(dealii::ParameterHandler &prm);

  /** "Integrator" into @p settings (step budget included) and @p mechanism's Baumgarte factors. */
  void
  read_integrator(ParameterReader &r, SimulationSettings &settings, Mechanism &mechanism);
} // namespace wearlink::mbs
