// SPDX-License-Identifier: LGPL-2.1-or-later
#include "analysis/channels.h"

#include "base/exceptions.h"
#include "base/numbers.h"

#include <cmath>

namespace wearlink::analysis
{
  namespace
  {
    using numbers::two_pi;
  }

  double
  Channel::value(const mbs::StateView &s) const
  {
    switch (kind)
      {
        case Kind::body_x:
          return s.position(body).x();
        case Kind::body_y:
          return s.position(body).y();
        case Kind::body_theta:
          return std::remainder(s.angle(body), two_pi);
        case Kind::body_vx:
          return s.velocity(body).x();
        case Kind::body_vy:
          return s.velocity(body).y();
        case Kind::body_omega:
          return s.angular_velocity(body);
        case Kind::eccentricity_x:
          return (s.point(pin_body, pin_point) - s.point(bushing_body, bushing_point)).x();
        case Kind::eccentricity_y:
          return (s.point(pin_body, pin_point) - s.point(bushing_body, bushing_point)).y();
        case Kind::eccentricity_rate_x:
          return (s.point_velocity(pin_body, pin_point) - s.point_velocity(bushing_body, bushing_point)).x();
        case Kind::eccentricity_rate_y:
          return (s.point_velocity(pin_body, pin_point) - s.point_velocity(bushing_body, bushing_point)).y();
      }
    Assert(false, dealii::ExcInternalError());
    return 0.0;
  }

  std::vector<Channel>
  body_channels(const mbs::Mechanism &mechanism, const int body_index)
  {
    const std::string &b = mechanism.get_bodies().at(body_index).name;
    using K              = Channel::Kind;
    struct Def
    {
      const char *suffix, *unit, *what;
      K           kind;
    };
    const Def            defs[] = {{"_x_m", "m", "centre-of-mass x", K::body_x},
                                   {"_y_m", "m", "centre-of-mass y", K::body_y},
                                   {"_theta_rad", "rad", "angle, wrapped to [-pi, pi]", K::body_theta},
                                   {"_vx_m_s", "m/s", "centre-of-mass velocity x", K::body_vx},
                                   {"_vy_m_s", "m/s", "centre-of-mass velocity y", K::body_vy},
                                   {"_omega_rad_s", "rad/s", "angular velocity", K::body_omega}};
    std::vector<Channel> out;
    for (const Def &d : defs)
      {
        Channel c;
        c.name        = b + d.suffix;
        c.unit        = d.unit;
        c.description = "body " + b + ", " + d.what;
        c.kind        = d.kind;
        c.body        = body_index;
        out.push_back(c);
      }
    return out;
  }

  std::vector<Channel>
  clearance_joint_channels(const contact::ClearanceJoint &joint)
  {
    const auto &d = joint.get_description();
    using K       = Channel::Kind;
    struct Def
    {
      const char *suffix, *unit, *what;
      K           kind;
    };
    const Def defs[] = {
      {"_ex_m", "m", "journal centre x relative to the bushing centre", K::eccentricity_x},
      {"_ey_m", "m", "journal centre y relative to the bushing centre", K::eccentricity_y},
      {"_vex_m_s", "m/s", "journal centre velocity x relative to the bushing centre", K::eccentricity_rate_x},
      {"_vey_m_s", "m/s", "journal centre velocity y relative to the bushing centre", K::eccentricity_rate_y}};
    std::vector<Channel> out;
    for (const Def &def : defs)
      {
        Channel c;
        c.name          = joint.name() + def.suffix;
        c.unit          = def.unit;
        c.description   = "joint " + joint.name() + ", " + def.what;
        c.kind          = def.kind;
        c.bushing_body  = d.bushing_body;
        c.bushing_point = d.bushing_point;
        c.pin_body      = d.pin_body;
        c.pin_point     = d.pin_point;
        out.push_back(c);
      }
    return out;
  }

  std::vector<Channel>
  all_channels(const mbs::Mechanism &mechanism, const std::vector<contact::ClearanceJoint *> &joints)
  {
    std::vector<Channel> out;
    for (unsigned int b = 0; b < mechanism.n_bodies(); ++b)
      for (auto &c : body_channels(mechanism, static_cast<int>(b)))
        out.push_back(std::move(c));
    for (const auto *j : joints)
      for (auto &c : clearance_joint_channels(*j))
        out.push_back(std::move(c));
    return out;
  }

  const Channel &
  find_channel(const std::vector<Channel> &channels, const std::string &name, const std::string &where)
  {
    for (const auto &c : channels)
      if (c.name == name)
        return c;
    std::string list;
    for (const auto &c : channels)
      list += (list.empty() ? "" : ", ") + c.name;
    throw InputError(where + ": there is no channel '" + name + "'. The channels of this scene are: " + list + ".");
  }
} // namespace wearlink::analysis
