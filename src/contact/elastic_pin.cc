// SPDX-License-Identifier: LGPL-2.1-or-later
#include "contact/elastic_pin.h"

#include "contact/clearance_joint.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace wearlink::contact
{
  namespace
  {
    /** The beam's nodes: its supports and the load points, in order along z. */
    std::vector<double>
    beam_nodes(const PinBending &b, const double length, const std::vector<double> &positions)
    {
      const double        s = 0.5 * length + b.support_distance;
      std::vector<double> z{-s};
      z.insert(z.end(), positions.begin(), positions.end());
      if (b.support != PinSupport::cantilever)
        z.push_back(s);
      return z;
    }

    /** The stiffness matrix of cubic Hermite beam elements over @p z (w, w′ per node). */
    Eigen::MatrixXd
    beam_stiffness(const std::vector<double> &z, const double ei)
    {
      const auto      n = static_cast<Eigen::Index>(z.size());
      Eigen::MatrixXd k = Eigen::MatrixXd::Zero(2 * n, 2 * n);
      for (Eigen::Index e = 0; e + 1 < n; ++e)
        {
          const double h = z[static_cast<std::size_t>(e + 1)] - z[static_cast<std::size_t>(e)];
          if (!(h > 0))
            throw std::logic_error("pin_flexibility: the load points must lie between the supports, in order");
          Eigen::Matrix4d ke;
          ke << 12, 6 * h, -12, 6 * h,           //
            6 * h, 4 * h * h, -6 * h, 2 * h * h, //
            -12, -6 * h, 12, -6 * h,             //
            6 * h, 2 * h * h, -6 * h, 4 * h * h;
          k.block<4, 4>(2 * e, 2 * e) += ei / (h * h * h) * ke;
        }
      return k;
    }
  } // namespace

  Eigen::MatrixXd
  pin_flexibility(const PinBending &b, const double length, const std::vector<double> &positions)
  {
    if (b.support == PinSupport::rigid)
      return {};
    const auto z = beam_nodes(b, length, positions);
    const auto k = beam_stiffness(z, b.bending_stiffness);
    // The supports hold the deflection (pinned) and the slope (clamped, the cantilever's root).
    const auto        last = static_cast<Eigen::Index>(z.size()) - 1;
    std::vector<bool> held(static_cast<std::size_t>(2 * z.size()), false);
    held[0] = true;
    held[1] = b.support != PinSupport::pinned;
    if (b.support != PinSupport::cantilever)
      {
        held[static_cast<std::size_t>(2 * last)]     = true;
        held[static_cast<std::size_t>(2 * last + 1)] = b.support == PinSupport::clamped;
      }
    std::vector<Eigen::Index> free;
    for (Eigen::Index i = 0; i < k.rows(); ++i)
      if (!held[static_cast<std::size_t>(i)])
        free.push_back(i);
    const auto      m = static_cast<Eigen::Index>(free.size());
    Eigen::MatrixXd kf(m, m);
    for (Eigen::Index i = 0; i < m; ++i)
      for (Eigen::Index j = 0; j < m; ++j)
        kf(i, j) = k(free[static_cast<std::size_t>(i)], free[static_cast<std::size_t>(j)]);
    // The load points are nodes 1 … n; their deflection dofs 2, 4, … sit in the free set.
    const auto                n = static_cast<Eigen::Index>(positions.size());
    std::vector<Eigen::Index> at(static_cast<std::size_t>(n));
    for (Eigen::Index i = 0; i < n; ++i)
      at[static_cast<std::size_t>(i)] = std::find(free.begin(), free.end(), 2 * (i + 1)) - free.begin();
    Eigen::MatrixXd loads = Eigen::MatrixXd::Zero(m, n);
    for (Eigen::Index j = 0; j < n; ++j)
      loads(at[static_cast<std::size_t>(j)], j) = 1;
    const Eigen::MatrixXd x = kf.ldlt().solve(loads);
    Eigen::MatrixXd       c(n, n);
    for (Eigen::Index i = 0; i < n; ++i)
      c.row(i) = x.row(at[static_cast<std::size_t>(i)]);
    return 0.5 * (c + c.transpose()); // Maxwell–Betti, exactly
  }

  ElasticPin::ElasticPin(const PinBending &bending, const double length, const std::vector<double> &positions)
    : c(pin_flexibility(bending, length, positions))
  {
  }

  void
  ElasticPin::attach(std::vector<const ClearanceJoint *> s)
  {
    if (s.empty() || static_cast<Eigen::Index>(s.size()) != c.rows())
      throw std::logic_error("ElasticPin::attach: one slice per load point");
    slices = std::move(s);
    offsets.clear();
    for (const auto *j : slices)
      offsets.push_back(j->get_description().slice.bore_offset);
    const auto &d         = slices.front()->get_description();
    bushing_body          = d.bushing_body;
    pin_body              = d.pin_body;
    pin_point             = d.pin_point;
    nominal_bushing_point = d.bushing_point - d.slice.bore_offset;
    solved                = false;
    have_jacobian         = false;
    warm                  = Eigen::VectorXd::Zero(2 * c.rows());
  }

  void
  ElasticPin::slice_forces(const Eigen::VectorXd &x, std::vector<mbs::Vec2> &out) const
  {
    out.resize(slices.size());
    for (std::size_t i = 0; i < slices.size(); ++i)
      out[i] = slices[i]->elastic_force(last_e - offsets[i] + mbs::Vec2(x[2 * i], x[2 * i + 1]), last_angle);
  }

  Eigen::VectorXd
  ElasticPin::residual(const Eigen::VectorXd &x, std::vector<mbs::Vec2> &out) const
  {
    slice_forces(x, out);
    const auto      n = c.rows();
    Eigen::VectorXd fx(n), fy(n);
    for (Eigen::Index i = 0; i < n; ++i)
      {
        fx[i] = out[static_cast<std::size_t>(i)].x();
        fy[i] = out[static_cast<std::size_t>(i)].y();
      }
    const Eigen::VectorXd vx = c * fx, vy = c * fy;
    Eigen::VectorXd       r(2 * n);
    for (Eigen::Index i = 0; i < n; ++i)
      {
        r[2 * i]     = x[2 * i] - vx[i];
        r[2 * i + 1] = x[2 * i + 1] - vy[i];
      }
    return r;
  }

  void
  ElasticPin::update_jacobian(const Eigen::VectorXd &x) const
  {
    // J = I − C G, G the slices' force gradients in the pin's position (2 × 2 each,
    // central differences a thousandth of the slice's overlap wide).
    const auto      n        = c.rows();
    Eigen::MatrixXd jacobian = Eigen::MatrixXd::Identity(2 * n, 2 * n);
    for (Eigen::Index j = 0; j < n; ++j)
      {
        const auto      k  = static_cast<std::size_t>(j);
        const mbs::Vec2 ej = last_e - offsets[k] + mbs::Vec2(x[2 * j], x[2 * j + 1]);
        const double    h  = std::max(1e-13, 1e-3 * std::abs(slices[k]->overlap(ej, last_angle)));
        Eigen::Matrix2d g;
        for (int a = 0; a < 2; ++a)
          {
            mbs::Vec2 step(0, 0);
            step[a] = h;
            g.col(a) =
              (slices[k]->elastic_force(ej + step, last_angle) - slices[k]->elastic_force(ej - step, last_angle)) /
              (2 * h);
          }
        if (g.isZero(0)) // a slice apart: its column stays the identity's
          continue;
        for (Eigen::Index i = 0; i < n; ++i)
          jacobian.block<2, 2>(2 * i, 2 * j) -= c(i, j) * g;
      }
    lu.compute(jacobian);
    fresh = true;
  }

  namespace
  {
    /** Newton's tolerance on the deflections: of their size, and an absolute floor [m]. */
    constexpr double relative_tolerance = 1e-10, absolute_tolerance = 1e-16;
    constexpr int    max_iterations = 40;
    /** A kept Jacobian is renewed when a step cuts the residual by less than this. */
    constexpr double kept_jacobian_rate = 0.2;
  } // namespace

  void
  ElasticPin::solve(const mbs::Vec2 &e, const double relative_angle) const
  {
    if (solved && e == last_e && relative_angle == last_angle)
      return;
    last_e     = e;
    last_angle = relative_angle;
    solved     = true;
    // Newton's method from the last solution, keeping the Jacobian of an earlier state
    // while it still cuts the residual fast (the states a time step visits are close).
    const auto             n = c.rows();
    Eigen::VectorXd        x = warm;
    std::vector<mbs::Vec2> force, trial_force;
    Eigen::VectorXd        r    = residual(x, force);
    const auto             done = [&](const Eigen::VectorXd &res, const Eigen::VectorXd &at) {
      return res.lpNorm<Eigen::Infinity>() <= relative_tolerance * at.lpNorm<Eigen::Infinity>() + absolute_tolerance;
    };
    bool converged = done(r, x);
    fresh          = false;
    for (int it = 0; it < max_iterations && !converged; ++it)
      {
        if (!have_jacobian)
          update_jacobian(x);
        have_jacobian               = true;
        const Eigen::VectorXd step  = -lu.solve(r);
        double                scale = 1;
        bool                  moved = false;
        for (int k = 0; k < 30 && !moved; ++k, scale *= 0.5)
          {
            const Eigen::VectorXd trial = x + scale * step;
            const Eigen::VectorXd rt    = residual(trial, trial_force);
            if (rt.lpNorm<Eigen::Infinity>() < r.lpNorm<Eigen::Infinity>())
              {
                moved = true;
                if (!fresh && rt.lpNorm<Eigen::Infinity>() > kept_jacobian_rate * r.lpNorm<Eigen::Infinity>())
                  have_jacobian = false; // slow: renew it at the next step
                x     = trial;
                r     = rt;
                force = trial_force;
              }
            else if (!fresh)
              break; // a kept Jacobian that does not descend: renew it and try again
          }
        converged = done(r, x);
        if (!moved && fresh)
          break;
        if (!moved)
          have_jacobian = false;
        fresh = false; // the Jacobian is now of an earlier point
      }
    failures += converged ? 0 : 1;
    warm = x;
    v.resize(static_cast<std::size_t>(n));
    for (Eigen::Index i = 0; i < n; ++i)
      v[static_cast<std::size_t>(i)] = mbs::Vec2(x[2 * i], x[2 * i + 1]);
    f = force;
  }

  mbs::Vec2
  ElasticPin::rigid_eccentricity(const mbs::StateView &s) const
  {
    return s.to_local(bushing_body, s.point(pin_body, pin_point) - s.point(bushing_body, nominal_bushing_point));
  }

  mbs::Vec2
  ElasticPin::deflection(const unsigned int i, const mbs::StateView &s) const
  {
    solve(rigid_eccentricity(s), s.angle(pin_body) - s.angle(bushing_body));
    return s.to_global(bushing_body, v[i]);
  }

  double
  ElasticPin::bending_energy(const mbs::StateView &s) const
  {
    solve(rigid_eccentricity(s), s.angle(pin_body) - s.angle(bushing_body));
    double energy = 0;
    for (std::size_t i = 0; i < v.size(); ++i)
      energy += 0.5 * v[i].dot(f[i]);
    return energy;
  }

  const std::vector<mbs::Vec2> &
  ElasticPin::forces(const mbs::Vec2 &e, const double relative_angle) const
  {
    solve(e, relative_angle);
    return f;
  }

  const std::vector<mbs::Vec2> &
  ElasticPin::deflections(const mbs::Vec2 &e, const double relative_angle) const
  {
    solve(e, relative_angle);
    return v;
  }
} // namespace wearlink::contact
