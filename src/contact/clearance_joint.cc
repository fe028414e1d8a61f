// SPDX-License-Identifier: LGPL-2.1-or-later
#include "contact/clearance_joint.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace wearlink::contact
{
  double
  contact_stiffness(double          bore_radius,
                    double          pin_radius,
                    const Material &bushing,
                    const Material &pin,
                    EffectiveRadius form)
  {
    const double r_star = form == EffectiveRadius::internal ? bore_radius * pin_radius / (bore_radius - pin_radius) :
                                                              bore_radius * pin_radius / (bore_radius + pin_radius);
    return 4.0 / (3.0 * (bushing.compliance() + pin.compliance())) * std::sqrt(r_star);
  }

  ClearanceJoint::ClearanceJoint(ClearanceJointDescription       d,
                                 std::unique_ptr<NormalForceLaw> normal,
                                 std::unique_ptr<FrictionLaw>    friction)
    : description(std::move(d))
    , normal_law(std::move(normal))
    , friction_law(std::move(friction))
    , gap(description.geometry.bore, description.geometry.pin)
    , contact_stiffness(wearlink::contact::contact_stiffness(description.geometry.bore.mean_radius(),
                                                             description.geometry.pin.mean_radius(),
                                                             description.geometry.bushing,
                                                             description.geometry.pin_material,
                                                             description.effective_radius))
  {
    normal_law->update_geometry(description.geometry);
  }

  void
  ClearanceJoint::set_profiles(const Profile &bore, const Profile &pin)
  {
    description.geometry.bore = bore;
    description.geometry.pin  = pin;
    gap                       = Gap(bore, pin);
    normal_law->update_geometry(description.geometry);
  }

  void
  ClearanceJoint::contact_kinematics(const mbs::StateView &s, Contact &c) const
  {
    const int  bb       = description.bushing_body;
    const int  pb       = description.pin_body;
    const auto p_bore   = s.point(bb, description.bushing_point);
    const auto p_pin    = s.point(pb, description.pin_point);
    const bool per_area = description.clearance_form == ClearanceForm::per_area && !gap.round();
    c.bushing_angle     = s.angle(bb);
    c.pin_angle         = s.angle(pb);
    c.gap               = per_area ? gap.evaluate_per_area(p_pin - p_bore, s.angle(bb), s.angle(pb)) :
                                     gap.evaluate(p_pin - p_bore, s.angle(bb), s.angle(pb));
    c.stiffness         = per_area ? wearlink::contact::contact_stiffness(c.gap.bore_radius,
                                                                  c.gap.pin_radius,
                                                                  description.geometry.bushing,
                                                                  description.geometry.pin_material,
                                                                  description.effective_radius) :
                                     contact_stiffness;
    const auto &n       = c.gap.normal;
    c.t                 = mbs::perp(n);
    c.q_bore            = p_bore + c.gap.bore_radius * n;
    c.q_pin             = p_pin + c.gap.pin_radius * n;
    // Material-point velocities at the contact points.
    const mbs::Vec2 v_bore = s.velocity(bb) + s.angular_velocity(bb) * mbs::perp(c.q_bore - s.position(bb));
    const mbs::Vec2 v_pin  = s.velocity(pb) + s.angular_velocity(pb) * mbs::perp(c.q_pin - s.position(pb));
    const mbs::Vec2 v_rel  = v_pin - v_bore;
    c.rate                 = v_rel.dot(n);
    c.slide                = v_rel.dot(c.t);
  }

  void
  ClearanceJoint::forces(const Contact &c, double &fn, double &fel, double &ft) const
  {
    const NormalContactInput in = normal_input(c);
    NormalContactOutput      out;
    normal_law->evaluate(in, out);
    fn  = out.force;
    fel = out.elastic_force;
    ft  = friction_law ? friction_law->force(fn, c.slide) : 0.0;
  }

  void
  ClearanceJoint::add_forces(double, const mbs::StateView &s, mbs::ForceAccumulator &out) const
  {
    Contact c;
    contact_kinematics(s, c);
    if (!(c.gap.penetration > 0))
      return;
    ++force_evaluations;
    double fn, fel, ft;
    forces(c, fn, fel, ft);
    const mbs::Vec2 f_pin = -fn * c.gap.normal + ft * c.t;
    out.add_force(description.pin_body, s, f_pin, c.q_pin);
    out.add_force(description.bushing_body, s, -f_pin, c.q_bore);
    out.damping_power += (fn - fel) * c.rate;
    out.friction_power += -ft * c.slide;
  }

  namespace
  {
    /** Finite-difference steps of the stiff directions: far inside the laws' bands. */
    constexpr double penetration_step_fraction = 1e-3;  ///< of the current δ
    constexpr double velocity_step             = 1e-9;  ///< [m/s]; the ramps are 1e-4 m/s wide
    constexpr double min_penetration_step      = 1e-13; ///< [m]
  }                                                     // namespace

  void
  ClearanceJoint::stiff_directions(const mbs::StateView             &s,
                                   const unsigned int                n_coordinates,
                                   std::vector<mbs::StiffDirection> &out) const
  {
    Contact c;
    contact_kinematics(s, c);
    if (!(c.gap.penetration > 0))
      return;
    // The gradient of the relative velocity of the contact points along @p dir.
    auto gradient = [&](const mbs::Vec2 &dir) {
      Eigen::VectorXd w   = Eigen::VectorXd::Zero(n_coordinates);
      auto            add = [&](int body, const mbs::Vec2 &point, double sign) {
        if (body == mbs::ground)
          return;
        w[3 * body] += sign * dir.x();
        w[3 * body + 1] += sign * dir.y();
        w[3 * body + 2] += sign * mbs::cross(point - s.position(body), dir);
      };
      add(description.pin_body, c.q_pin, 1);
      add(description.bushing_body, c.q_bore, -1);
      return w;
    };
    mbs::StiffDirection normal;
    normal.w             = gradient(c.gap.normal);
    normal.position      = true;
    normal.velocity      = true;
    normal.position_step = std::max(min_penetration_step, penetration_step_fraction * c.gap.penetration);
    normal.velocity_step = velocity_step;
    out.push_back(std::move(normal));
    if (!friction_law)
      return;
    mbs::StiffDirection sliding;
    sliding.w             = gradient(c.t);
    sliding.velocity      = true;
    sliding.velocity_step = velocity_step;
    out.push_back(std::move(sliding));
  }

  double
  ClearanceJoint::potential_energy(const mbs::StateView &s) const
  {
    Contact c;
    contact_kinematics(s, c);
    if (!(c.gap.penetration > 0))
      return 0;
    return normal_law->potential(normal_input(c));
  }

  NormalContactInput
  ClearanceJoint::normal_input(const Contact &c) const
  {
    NormalContactInput in;
    in.penetration      = c.gap.penetration;
    in.penetration_rate = c.rate;
    in.impact_velocity  = in_contact ? captured_impact_velocity : c.rate;
    in.stiffness        = c.stiffness;
    if (normal_law->uses_direction())
      {
        const double phi = std::atan2(c.gap.normal[1], c.gap.normal[0]);
        in.bore_angle    = phi - c.bushing_angle;
        in.pin_angle     = phi - c.pin_angle;
      }
    return in;
  }

  double
  ClearanceJoint::event_value(const mbs::StateView &s) const
  {
    const auto   p_bore = s.point(description.bushing_body, description.bushing_point);
    const auto   p_pin  = s.point(description.pin_body, description.pin_point);
    const auto   e      = p_pin - p_bore;
    const double tb     = s.angle(description.bushing_body);
    const double tp     = s.angle(description.pin_body);
    if (description.clearance_form == ClearanceForm::per_area && !gap.round())
      return gap.evaluate_per_area(e, tb, tp).penetration;
    return gap.evaluate(e, tb, tp).penetration;
  }

  void
  ClearanceJoint::on_event(double, const mbs::StateView &s, bool onset)
  {
    in_contact = onset;
    if (onset)
      {
        Contact c;
        contact_kinematics(s, c);
        captured_impact_velocity = c.rate;
        ++impacts;
      }
  }

  JointDiagnostics
  ClearanceJoint::diagnostics(const mbs::StateView &s) const
  {
    JointDiagnostics d;
    Contact          c;
    contact_kinematics(s, c);
    const int bb    = description.bushing_body;
    d.bushing_angle = s.angle(bb);
    d.pin_angle     = s.angle(description.pin_body);
    d.eccentricity  = s.point(description.pin_body, description.pin_point) - s.point(bb, description.bushing_point);
    d.local_eccentricity = mbs::rotate(d.eccentricity, -d.bushing_angle);
    d.penetration        = c.gap.penetration;
    d.normal             = c.gap.normal;
    d.contact_angle      = c.gap.angle();
    if (c.gap.penetration > 0)
      {
        forces(c, d.normal_force, d.elastic_force, d.friction_force);
        d.penetration_rate = c.rate;
        d.sliding_velocity = c.slide;
        d.force_on_pin     = -d.normal_force * c.gap.normal + d.friction_force * c.t;
      }
    return d;
  }
} // namespace wearlink::contact
