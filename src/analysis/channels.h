// SPDX-License-Identifier: LGPL-2.1-or-later
// Scalar channels of the mechanism state that the nonlinear-dynamics analyses look at
// (phase portraits, Poincaré sections, Lyapunov exponents, bifurcation sweeps).
//
// A channel is a function of one state (q, v) only, so that it can be evaluated on the
// integrator's dense output at any time (Simulation::state_at) — no accelerations,
// no forces. Two families, named like the columns of time_series.csv:
//  - body centre of mass:  <body>_x_m, <body>_y_m, <body>_theta_rad,
//                          <body>_vx_m_s, <body>_vy_m_s, <body>_omega_rad_s;
//    the angle is wrapped to [−π, π] (a crank's angle grows without bound; the state
//    it describes does not), unlike the unwrapped angle in time_series.csv;
//  - clearance joint, the journal (pin) centre relative to the bushing (bore) centre,
//    in global axes (doc/models.md §1.1: e = r_pin − r_bushing):
//                          <joint>_ex_m, <joint>_ey_m         e_x, e_y [m]
//                          <joint>_vex_m_s, <joint>_vey_m_s   ė_x, ė_y [m/s]
//    ė is the difference of the two centres' velocities (exact from v, not a finite
//    difference), so (e_x, ė_x) is the phase plane of the seed's Figs 9–10.
#pragma once

#include "contact/clearance_joint.h"
#include "mbs/mechanism.h"
#include "mbs/types.h"

#include <string>
#include <vector>

namespace wearlink::analysis
{
  /** One scalar channel of the state. */
  struct Channel
  {
    enum class Kind
    {
      body_x,
      body_y,
      body_theta,
      body_vx,
      body_vy,
      body_omega,
      eccentricity_x,
      eccentricity_y,
      eccentricity_rate_x,
      eccentricity_rate_y
    };

    std::string name; ///< e.g. "A_ex_m", "slider9_y_m"
    std::string unit; ///< "m", "m/s", "rad", "rad/s"
    std::string description;
    Kind        kind = Kind::body_x;
    /** Body of a body channel. */
    int body = mbs::ground;
    /** Clearance-joint channels: bore centre (bushing body, point in its frame) ... */
    int       bushing_body = mbs::ground;
    mbs::Vec2 bushing_point{0, 0};
    /** ... and pin centre (pin body, point in its frame). */
    int       pin_body = mbs::ground;
    mbs::Vec2 pin_point{0, 0};

    /** The channel's value in state @p s [unit]. */
    double
    value(const mbs::StateView &s) const;
  };

  /** The six channels of body @p body_index of @p mechanism. */
  std::vector<Channel>
  body_channels(const mbs::Mechanism &mechanism, int body_index);

  /** The four channels (e_x, e_y, ė_x, ė_y) of a clearance joint. */
  std::vector<Channel>
  clearance_joint_channels(const contact::ClearanceJoint &joint);

  /**
   * Every channel of a mechanism: the six of each body, then the four of each clearance
   * joint in @p joints.
   */
  std::vector<Channel>
  all_channels(const mbs::Mechanism &mechanism, const std::vector<contact::ClearanceJoint *> &joints);

  /**
   * The channel called @p name among @p channels; an InputError listing the valid
   * names otherwise (@p where says who asked, e.g. "--channel").
   */
  const Channel &
  find_channel(const std::vector<Channel> &channels, const std::string &name, const std::string &where);
} // namespace wearlink::analysis
