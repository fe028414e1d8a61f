// SPDX-License-Identifier: LGPL-2.1-or-later
#include "contact/clearance_joint.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
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
    , reference_radius(description.slice.count > 1 ? description.slice.nominal_bore_radius :
                                                     description.geometry.bore.mean_radius())
    , reference_clearance(description.slice.count > 1 ?
                            description.slice.nominal_bore_radius - description.slice.nominal_pin_radius :
                            description.geometry.bore.mean_radius() - description.geometry.pin.mean_radius())
  {
    // A slice: the share of the joint's stiffness, from its radii before its crown and
    // relief (they change its gap, not its K).
    const bool sliced = description.slice.count > 1;
    contact_stiffness = wearlink::contact::contact_stiffness(sliced ? description.slice.nominal_bore_radius :
                                                                      description.geometry.bore.mean_radius(),
                                                             sliced ? description.slice.nominal_pin_radius :
                                                                      description.geometry.pin.mean_radius(),
                                                             description.geometry.bushing,
                                                             description.geometry.pin_material,
                                                             description.effective_radius);
    if (sliced)
      contact_stiffness *= description.slice.share;
    // The law builds what the form needs (NormalForceLaw::use_conformal()).
    normal_law->use_conformal(description.clearance_form == ClearanceForm::conformal);
    normal_law->update_geometry(description.geometry);
    update_field();
  }

  void
  ClearanceJoint::set_profiles(const Profile &bore, const Profile &pin)
  {
    description.geometry.bore = bore;
    description.geometry.pin  = pin;
    gap                       = Gap(bore, pin);
    normal_law->update_geometry(description.geometry);
    update_field();
    held = held && (gap.round() || field != nullptr);
  }

  void
  ClearanceJoint::set_clearance_form(const ClearanceForm form, const unsigned int conformal_cells)
  {
    description.clearance_form  = form;
    description.conformal_cells = conformal_cells;
    normal_law->use_conformal(form == ClearanceForm::conformal); // rebuilds only if that changes what it needs
    update_field();
  }

  void
  ClearanceJoint::update_field()
  {
    field = nullptr;
    own_field.reset();
    if (gap.round() || description.clearance_form != ClearanceForm::conformal)
      return;
    field = normal_law->conformal_field();
    if (field != nullptr)
      return;
    const auto  &g = description.geometry;
    const double n = normal_law->exponent();
    // The closed-form laws: the foundation that carries the law of the nominal round pair.
    const Foundation f =
      std::isfinite(n) ?
        foundation_of_power_law(contact_stiffness, n, reference_clearance, reference_radius, g.axial_length) :
        Foundation::of_curve([this](double d) { return normal_law->round_elastic_force(d, contact_stiffness); },
                             reference_clearance,
                             reference_radius,
                             g.axial_length,
                             1e-12,
                             std::max(1e-6, reference_clearance),
                             161);
    const auto make = [&] {
      return std::make_unique<OverlapFoundation>(g.bore,
                                                 g.pin,
                                                 g.axial_length,
                                                 reference_radius,
                                                 f,
                                                 description.conformal_cells);
    };
    if (const auto &pool = description.slice.field_pool)
      own_field = pool->field(g.bore,
                              g.pin,
                              FieldKey{description.normal_force_law,
                                       contact_stiffness,
                                       n,
                                       reference_clearance,
                                       reference_radius,
                                       g.axial_length,
                                       description.conformal_cells},
                              make);
    else
      own_field = make();
    field = own_field.get();
  }

  void
  ClearanceJoint::conformal_contact(const mbs::StateView &s,
                                    const mbs::Vec2      &e,
                                    Contact              &c,
                                    const bool            with_potential) const
  {
    const int       bb = description.bushing_body, pb = description.pin_body;
    const mbs::Vec2 e_local = s.to_local(bb, e);
    // The motion of the pin centre seen from the bushing: d/dt(Aᵀ e) = Aᵀ ė − θ̇_b perp(Aᵀ e).
    const mbs::Vec2 e_rate =
      s.point_velocity(pb, description.pin_point) - s.point_velocity(bb, description.bushing_point);
    const auto      h = normal_law->hysteresis();
    ConformalMotion m;
    m.velocity        = s.to_local(bb, e_rate) - s.angular_velocity(bb) * mbs::perp(e_local);
    m.relative_rate   = s.angular_velocity(pb) - s.angular_velocity(bb);
    m.factor          = h.factor;
    m.impact_velocity = in_contact ? captured_impact_velocity : 0.0;
    m.min_velocity    = h.min_impact_velocity;
    ConformalForce cf;
    field->evaluate(e_local, c.pin_angle - c.bushing_angle, &m, with_potential, cf);
    // The contact normal: opposite to the force on the pin (from the bore centre towards
    // the contact); before any force, the direction of the deepest overlap.
    const double    f       = cf.damped.norm();
    const mbs::Vec2 n_local = f > 0 ? mbs::Vec2(-cf.damped / f) : mbs::Vec2(std::cos(cf.deepest), std::sin(cf.deepest));
    const double    psi     = std::atan2(n_local.y(), n_local.x());
    c.gap.penetration       = cf.overlap;
    c.gap.normal            = s.to_global(bb, n_local);
    c.gap.bore_radius       = description.geometry.bore.radius(psi);
    c.gap.pin_radius        = description.geometry.pin.radius(psi + c.bushing_angle - c.pin_angle);
    c.conformal             = true;
    c.elastic               = cf.force.norm();
    c.damped                = f;
    c.pin_torque            = cf.pin_torque;
    c.bushing_torque        = cf.bushing_torque;
    c.damping_power         = cf.damping_power;
    c.potential             = cf.potential;
  }

  mbs::Vec2
  ClearanceJoint::pin_centre(const mbs::StateView &s) const
  {
    mbs::Vec2 p = s.point(description.pin_body, description.pin_point);
    if (const auto &pin = description.slice.elastic_pin)
      p += pin->deflection(description.slice.index, s);
    return p;
  }

  void
  ClearanceJoint::contact_kinematics(const mbs::StateView &s, Contact &c, const bool with_potential) const
  {
    const int  bb       = description.bushing_body;
    const int  pb       = description.pin_body;
    const auto p_bore   = s.point(bb, description.bushing_point);
    const auto p_pin    = pin_centre(s);
    const bool per_area = description.clearance_form == ClearanceForm::per_area && !gap.round();
    c.bushing_angle     = s.angle(bb);
    c.pin_angle         = s.angle(pb);
    if (field != nullptr)
      conformal_contact(s, p_pin - p_bore, c, with_potential);
    else
      c.gap = per_area ? gap.evaluate_per_area(p_pin - p_bore, s.angle(bb), s.angle(pb)) :
                         gap.evaluate(p_pin - p_bore, s.angle(bb), s.angle(pb));
    c.stiffness   = per_area ? wearlink::contact::contact_stiffness(c.gap.bore_radius,
                                                                  c.gap.pin_radius,
                                                                  description.geometry.bushing,
                                                                  description.geometry.pin_material,
                                                                  description.effective_radius) :
                               contact_stiffness;
    const auto &n = c.gap.normal;
    c.t           = mbs::perp(n);
    c.q_bore      = p_bore + c.gap.bore_radius * n;
    c.q_pin       = p_pin + c.gap.pin_radius * n;
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
    if (c.conformal)
      {
        fel = c.elastic;
        fn  = c.damped;
      }
    else
      {
        NormalContactOutput out;
        normal_law->evaluate(in, out);
        fn  = out.force;
        fel = out.elastic_force;
      }
    ft = friction_law ? friction_law->force(fn, c.slide) : 0.0;
  }

  void
  ClearanceJoint::add_forces(double, const mbs::StateView &s, mbs::ForceAccumulator &out) const
  {
    Contact c;
    contact_kinematics(s, c);
    if (!(c.gap.penetration > 0))
      return;
    ++force_evaluations;
    if (held) // the mechanism applies the held force (held_contact())
      return;
    double fn, fel, ft;
    forces(c, fn, fel, ft);
    const mbs::Vec2 f_pin = -fn * c.gap.normal + ft * c.t;
    out.add_force(description.pin_body, s, f_pin, c.q_pin);
    out.add_force(description.bushing_body, s, -f_pin, c.q_bore);
    if (c.conformal) // the worn profiles' slopes: elastic couples (the field's gradient in the angles)
      {
        out.add_torque(description.pin_body, c.pin_torque);
        out.add_torque(description.bushing_body, c.bushing_torque);
      }
    out.damping_power += c.conformal ? c.damping_power : (fn - fel) * c.rate;
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
  ClearanceJoint::velocity_gradient(const mbs::StateView &s,
                                    const Contact        &c,
                                    const mbs::Vec2      &dir,
                                    const double          sign,
                                    double               *w) const
  {
    auto add = [&](int body, const mbs::Vec2 &point, double side) {
      if (body == mbs::ground)
        return;
      w[3 * body] += sign * side * dir.x();
      w[3 * body + 1] += sign * side * dir.y();
      w[3 * body + 2] += sign * side * mbs::cross(point - s.position(body), dir);
    };
    add(description.pin_body, c.q_pin, 1);
    add(description.bushing_body, c.q_bore, -1);
  }

  void
  ClearanceJoint::stiff_directions(const mbs::StateView             &s,
                                   const unsigned int                n_coordinates,
                                   std::vector<mbs::StiffDirection> &out) const
  {
    Contact c;
    contact_kinematics(s, c);
    if (!(c.gap.penetration > 0))
      return;
    // A held contact has no normal compliance left; its friction ramp is still stiff.
    if (!held)
      {
        mbs::StiffDirection normal;
        normal.w = Eigen::VectorXd::Zero(n_coordinates);
        velocity_gradient(s, c, c.gap.normal, 1, normal.w.data());
        normal.position      = true;
        normal.velocity      = true;
        normal.position_step = std::max(min_penetration_step, penetration_step_fraction * c.gap.penetration);
        normal.velocity_step = velocity_step;
        out.push_back(std::move(normal));
      }
    if (!friction_law)
      return;
    mbs::StiffDirection sliding;
    sliding.w = Eigen::VectorXd::Zero(n_coordinates);
    velocity_gradient(s, c, c.t, 1, sliding.w.data());
    sliding.velocity      = true;
    sliding.velocity_step = velocity_step;
    out.push_back(std::move(sliding));
  }

  namespace
  {
    /** Time shift of the held row's convective difference [s]: q moves by q̇ × this. */
    constexpr double convective_shift = 1e-6;
  } // namespace

  double
  ClearanceJoint::convective_rate(const mbs::StateView &s, const unsigned int n) const
  {
    shifted.resize(2 * n);
    double *q = shifted.data(), *v = shifted.data() + n;
    for (unsigned int b = 0; 3 * b < n; ++b)
      {
        const mbs::Vec2 p = s.position(static_cast<int>(b)), u = s.velocity(static_cast<int>(b));
        v[3 * b]     = u.x();
        v[3 * b + 1] = u.y();
        v[3 * b + 2] = s.angular_velocity(static_cast<int>(b));
        q[3 * b]     = p.x();
        q[3 * b + 1] = p.y();
        q[3 * b + 2] = s.angle(static_cast<int>(b));
      }
    double rate[2];
    for (int side = 0; side < 2; ++side)
      {
        const double h = side == 0 ? convective_shift : -2 * convective_shift; // +h, then −h
        for (unsigned int i = 0; i < n; ++i)
          q[i] += h * v[i];
        Contact c;
        contact_kinematics(mbs::StateView(q, v), c);
        rate[side] = c.rate;
      }
    return (rate[0] - rate[1]) / (2 * convective_shift);
  }

  void
  ClearanceJoint::held_contact(const mbs::StateView &s, mbs::HeldContact &out) const
  {
    Contact c;
    contact_kinematics(s, c);
    const double phi = friction_law ? friction_law->force(1.0, c.slide) : 0.0;
    velocity_gradient(s, c, c.gap.normal, 1, out.w.data());
    velocity_gradient(s, c, c.gap.normal, -1, out.g.data());
    if (phi != 0)
      velocity_gradient(s, c, c.t, phi, out.g.data());
    out.penetration = c.gap.penetration;
    out.rate        = c.rate;
    out.stiffness   = c.stiffness;
    out.exponent    = normal_law->exponent();
    if (c.conformal)
      local_power_law(s, c, out.stiffness, out.exponent);
    out.sliding_velocity   = c.slide;
    out.friction_per_force = phi;
    out.convective         = convective_rate(s, static_cast<unsigned int>(out.w.size()));
  }

  // A conformal contact's elastic force against its overlap δ along its normal n, as the
  // power law K δᵉ through the current state with the local slope d ln F / d ln δ (a
  // difference over a thousandth of δ along n): the held row's quasi-static overlap.
  void
  ClearanceJoint::local_power_law(const mbs::StateView &s, const Contact &c, double &stiffness, double &exponent) const
  {
    if (!(c.gap.penetration > 0 && c.elastic > 0)) // a trial stage past the separation: the law's own form
      return;
    const int       bb = description.bushing_body;
    const mbs::Vec2 e =
      s.to_local(bb, s.point(description.pin_body, description.pin_point) - s.point(bb, description.bushing_point));
    const mbs::Vec2 n        = s.to_local(bb, c.gap.normal);
    const double    relative = c.pin_angle - c.bushing_angle;
    ConformalForce  pushed;
    field->evaluate(e + 1e-3 * c.gap.penetration * n, relative, nullptr, false, pushed);
    const double slope = std::log(pushed.force.norm() / c.elastic) / std::log(pushed.overlap / c.gap.penetration);
    if (!(slope > 0 && std::isfinite(slope)))
      return;
    exponent  = slope;
    stiffness = c.elastic / std::pow(c.gap.penetration, exponent);
  }

  // A held conformal contact stays quasi-static while the compliant law would carry about
  // the held force at the same state: where the pin's contact patch moves across a worn
  // profile (onto another pocket or flank) the resultant turns within tens of µs, the
  // held row's overlap no longer follows its force, and the contact is given back.
  bool
  ClearanceJoint::quasi_static(const mbs::StateView &s) const
  {
    if (field == nullptr)
      return true;
    Contact c;
    contact_kinematics(s, c);
    return std::abs(c.elastic - held_normal_force) <= hold_force_tolerance * std::max(c.elastic, held_normal_force);
  }

  bool
  ClearanceJoint::update_hold(double, const mbs::StateView &s, const double *a)
  {
    if (held)
      {
        if (held_normal_force > 0 && quasi_static(s))
          return false;
        held = false; // no longer pressed (or no longer quasi-static): the compliant law takes over
        return true;
      }
    // Round profiles, or worn ones as a conformal contact: its normal, the direction of
    // the resultant, moves smoothly with the pin. (The deepest point of a worn profile
    // jumps between discrete areas, and a held row on it did not keep δ — measured on
    // params/nine_bar_worn.prm with Clearance model = deepest-point: peak forces ×10 —
    // so the point forms are left to the compliant law on worn profiles.)
    if (!in_contact || !(gap.round() || field != nullptr))
      return false;
    Contact c;
    contact_kinematics(s, c);
    if (!(c.gap.penetration > 0) || !(std::abs(c.rate) < description.hold_velocity))
      return false;
    // δ̈ = w·q̈ + c: w is non-zero on the two bodies' coordinates only, which the
    // coordinates up to the later of them cover.
    const auto n = static_cast<unsigned int>(3 * (std::max(description.pin_body, description.bushing_body) + 1));
    hold_row.assign(n, 0.0);
    velocity_gradient(s, c, c.gap.normal, 1, hold_row.data());
    double acceleration = convective_rate(s, n);
    for (unsigned int i = 0; i < n; ++i)
      acceleration += hold_row[i] * a[i];
    if (!(std::abs(acceleration) < description.hold_acceleration))
      return false;
    held              = true;
    held_normal_force = 0;
    ++holds;
    return true;
  }

  double
  ClearanceJoint::potential_energy(const mbs::StateView &s) const
  {
    Contact c;
    contact_kinematics(s, c, true);
    return stored_energy(s, c);
  }

  // potential_energy() and diagnostics() both take the energy from here: an observer may
  // use either. A bent pin's strain energy counts once, with its first slice.
  double
  ClearanceJoint::stored_energy(const mbs::StateView &s, const Contact &c) const
  {
    const auto  &pin     = description.slice.elastic_pin;
    const double bending = pin && description.slice.index == 0 ? pin->bending_energy(s) : 0.0;
    if (c.conformal)
      return c.potential + bending;
    if (!(c.gap.penetration > 0))
      return bending;
    return normal_law->potential(normal_input(c)) + bending;
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
    const auto      p_bore = s.point(description.bushing_body, description.bushing_point);
    const mbs::Vec2 e      = pin_centre(s) - p_bore;
    const double    tb     = s.angle(description.bushing_body);
    const double    tp     = s.angle(description.pin_body);
    if (field != nullptr)
      return field->overlap(s.to_local(description.bushing_body, e), tp - tb);
    if (description.clearance_form == ClearanceForm::per_area && !gap.round())
      return gap.evaluate_per_area(e, tb, tp).penetration;
    return gap.evaluate(e, tb, tp).penetration;
  }

  void
  ClearanceJoint::on_event(double, const mbs::StateView &s, bool onset)
  {
    in_contact = onset;
    held       = held && onset;
    if (onset)
      {
        Contact c;
        contact_kinematics(s, c);
        captured_impact_velocity = c.rate;
        ++impacts;
      }
  }

  mbs::Vec2
  ClearanceJoint::elastic_force(const mbs::Vec2 &e, const double relative_angle) const
  {
    if (field != nullptr)
      {
        ConformalForce cf;
        field->evaluate(e, relative_angle, nullptr, false, cf);
        return cf.force;
      }
    Contact c;
    c.bushing_angle = 0;
    c.pin_angle     = relative_angle;
    c.gap           = description.clearance_form == ClearanceForm::per_area && !gap.round() ?
                        gap.evaluate_per_area(e, 0, relative_angle) :
                        gap.evaluate(e, 0, relative_angle);
    if (!(c.gap.penetration > 0))
      return mbs::Vec2(0, 0);
    c.stiffness = description.clearance_form == ClearanceForm::per_area && !gap.round() ?
                    wearlink::contact::contact_stiffness(c.gap.bore_radius,
                                                         c.gap.pin_radius,
                                                         description.geometry.bushing,
                                                         description.geometry.pin_material,
                                                         description.effective_radius) :
                    contact_stiffness;
    NormalContactOutput out;
    normal_law->evaluate(normal_input(c), out);
    return -out.elastic_force * c.gap.normal;
  }

  mbs::Vec2
  ClearanceJoint::eccentricity_carrying(const mbs::Vec2 &force,
                                        const double     relative_angle,
                                        const mbs::Vec2 &start,
                                        bool            &converged) const
  {
    return contact::eccentricity_carrying({this}, force, relative_angle, start, converged);
  }

  mbs::Vec2
  slices_elastic_force(const std::vector<const ClearanceJoint *> &slices,
                       const mbs::Vec2                           &e,
                       const double                               relative_angle)
  {
    mbs::Vec2   sum(0, 0);
    const auto &first = slices.front()->get_description().slice;
    if (first.elastic_pin) // a bent pin: its slices' forces where it is in equilibrium
      {
        for (const auto &f : first.elastic_pin->forces(e + first.bore_offset, relative_angle))
          sum += f;
        return sum;
      }
    for (const auto *j : slices)
      sum += j->elastic_force(e + slices.front()->get_description().slice.bore_offset -
                                j->get_description().slice.bore_offset,
                              relative_angle);
    return sum;
  }

  namespace
  {
    /** The largest overlap of @p slices with the pin at @p e (the first slice's frame) [m]. */
    double
    largest_overlap(const std::vector<const ClearanceJoint *> &slices, const mbs::Vec2 &e, const double relative_angle)
    {
      double largest = -std::numeric_limits<double>::infinity();
      for (const auto *j : slices)
        largest = std::max(largest,
                           j->overlap(e + slices.front()->get_description().slice.bore_offset -
                                        j->get_description().slice.bore_offset,
                                      relative_angle));
      return largest;
    }
  } // namespace

  mbs::Vec2
  eccentricity_carrying(const std::vector<const ClearanceJoint *> &slices,
                        const mbs::Vec2                           &force,
                        const double                               relative_angle,
                        const mbs::Vec2                           &start,
                        bool                                      &converged)
  {
    // Damped Newton on r(e) = F(e) − force, the Jacobian by central differences a
    // thousandth of the overlap wide (the force is smooth there), halving the step until
    // |r| falls.
    const auto carried = [&](const mbs::Vec2 &e) {
      return slices_elastic_force(slices, e, relative_angle);
    };
    const double target   = force.norm();
    mbs::Vec2    e        = start;
    mbs::Vec2    residual = carried(e) - force;
    converged             = residual.norm() <= 1e-9 * target;
    for (int it = 0; it < 50 && !converged; ++it)
      {
        const double    h = std::max(1e-13, 1e-3 * std::abs(largest_overlap(slices, e, relative_angle)));
        Eigen::Matrix2d jacobian;
        for (int k = 0; k < 2; ++k)
          {
            mbs::Vec2 step(0, 0);
            step[k]         = h;
            jacobian.col(k) = (carried(e + step) - carried(e - step)) / (2 * h);
          }
        const mbs::Vec2 delta = -jacobian.colPivHouseholderQr().solve(residual);
        double          scale = 1;
        bool            moved = false;
        for (int k = 0; k < 40 && !moved; ++k, scale *= 0.5)
          {
            const mbs::Vec2 trial = e + scale * delta;
            const mbs::Vec2 r     = carried(trial) - force;
            if (r.norm() < residual.norm())
              {
                e        = trial;
                residual = r;
                moved    = true;
              }
          }
        if (!moved)
          break;
        converged = residual.norm() <= 1e-9 * target;
      }
    return e;
  }

  double
  ClearanceJoint::overlap(const mbs::Vec2 &e, const double relative_angle) const
  {
    return field != nullptr ? field->overlap(e, relative_angle) : gap.evaluate(e, 0, relative_angle).penetration;
  }

  JointDiagnostics
  ClearanceJoint::diagnostics(const mbs::StateView &s) const
  {
    JointDiagnostics d;
    Contact          c;
    contact_kinematics(s, c, true);
    const int bb    = description.bushing_body;
    d.bushing_angle = s.angle(bb);
    d.pin_angle     = s.angle(description.pin_body);
    d.eccentricity  = pin_centre(s) - s.point(bb, description.bushing_point);
    if (description.slice.elastic_pin)
      d.pin_deflection = description.slice.elastic_pin->deflection(description.slice.index, s);
    d.local_eccentricity = mbs::rotate(d.eccentricity, -d.bushing_angle);
    d.penetration        = c.gap.penetration;
    d.normal             = c.gap.normal;
    d.contact_angle      = c.gap.angle();
    d.potential_energy   = stored_energy(s, c);
    if (c.gap.penetration > 0)
      {
        forces(c, d.normal_force, d.elastic_force, d.friction_force);
        if (held)
          {
            d.normal_force   = held_normal_force;
            d.friction_force = friction_law ? friction_law->force(held_normal_force, c.slide) : 0.0;
          }
        d.penetration_rate = c.rate;
        d.sliding_velocity = c.slide;
        d.force_on_pin     = -d.normal_force * c.gap.normal + d.friction_force * c.t;
      }
    return d;
  }
} // namespace wearlink::contact
