// SPDX-License-Identifier: LGPL-2.1-or-later
// Small planar-kinematics vocabulary shared by the multibody layer and the force
// elements: 2-vectors, rotation A(θ), its derivative B(θ) = dA/dθ, and read access to the
// state vector y = [q | v | quadratures] with q = (x_i, y_i, θ_i) per body (doc/models.md §2).
#pragma once

#include <Eigen/Core>

#include <cmath>

namespace wearlink::mbs
{
  using Vec2 = Eigen::Vector2d;

  /** Index of the ground (fixed frame) in joint and force-element definitions. */
  constexpr int ground = -1;

  /** A(θ) s: rotate body-frame vector @p s by @p theta. */
  inline Vec2
  rotate(const Vec2 &s, double theta)
  {
    const double c = std::cos(theta), si = std::sin(theta);
    return {c * s.x() - si * s.y(), si * s.x() + c * s.y()};
  }

  /** Rotate by +90°: k × v. */
  inline Vec2
  perp(const Vec2 &v)
  {
    return {-v.y(), v.x()};
  }

  /** 2D cross product a × b (z component). */
  inline double
  cross(const Vec2 &a, const Vec2 &b)
  {
    return a.x() * b.y() - a.y() * b.x();
  }

  /**
   * Read access to the positions and velocities of the bodies inside a state vector.
   * Body index ground (−1) reads as the fixed frame (zero position, angle, velocity).
   */
  class StateView
  {
  public:
    /**
     * @param trig optional (cos θ_b, sin θ_b) per body, precomputed by the caller so that
     * the many rotations of one right-hand side share one sincos per body.
     */
    StateView(const double *q, const double *v, const double *trig = nullptr)
      : q(q)
      , v(v)
      , trig(trig)
    {
    }

    /** A(θ_b) s: body-frame vector @p s of body @p b in global axes. */
    Vec2
    to_global(int b, const Vec2 &s) const
    {
      if (b == ground)
        return s;
      if (trig == nullptr)
        return rotate(s, q[3 * b + 2]);
      const double c = trig[2 * b], si = trig[2 * b + 1];
      return {c * s.x() - si * s.y(), si * s.x() + c * s.y()};
    }

    /** A(θ_b)ᵀ g: global vector @p g in body @p b's frame. */
    Vec2
    to_local(int b, const Vec2 &g) const
    {
      if (b == ground)
        return g;
      if (trig == nullptr)
        return rotate(g, -q[3 * b + 2]);
      const double c = trig[2 * b], si = trig[2 * b + 1];
      return {c * g.x() + si * g.y(), -si * g.x() + c * g.y()};
    }

    Vec2
    position(int b) const
    {
      return b == ground ? Vec2(0, 0) : Vec2(q[3 * b], q[3 * b + 1]);
    }
    double
    angle(int b) const
    {
      return b == ground ? 0.0 : q[3 * b + 2];
    }
    Vec2
    velocity(int b) const
    {
      return b == ground ? Vec2(0, 0) : Vec2(v[3 * b], v[3 * b + 1]);
    }
    double
    angular_velocity(int b) const
    {
      return b == ground ? 0.0 : v[3 * b + 2];
    }

    /** Global position of the body-fixed point @p s (body frame) of body @p b. */
    Vec2
    point(int b, const Vec2 &s) const
    {
      return b == ground ? s : Vec2(position(b) + to_global(b, s));
    }
    /** Global velocity of the body-fixed point @p s of body @p b. */
    Vec2
    point_velocity(int b, const Vec2 &s) const
    {
      return b == ground ? Vec2(0, 0) : Vec2(velocity(b) + angular_velocity(b) * perp(to_global(b, s)));
    }

  private:
    const double *q;
    const double *v;
    const double *trig;
  };
} // namespace wearlink::mbs
