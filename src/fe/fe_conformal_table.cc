// SPDX-License-Identifier: LGPL-2.1-or-later
#include "fe/fe_conformal_table.h"

#include "base/exceptions.h"
#include "base/numbers.h"
#include "base/timings.h"
#include "contact/cylindrical_contact.h"
#include "contact/table_interpolation.h"
#include "fe/fe_normal_force_law.h"
#include "fe/model_pool.h"
#include "fe/pin_bushing_model.h"
#include "fe/table_cache.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>

namespace wearlink::fe
{
  namespace
  {
    using numbers::pi;
    using numbers::two_pi;

    constexpr const char *conformal_cache_format  = "wearlink-fe-conformal-table";
    constexpr int         conformal_cache_version = 1;
    /**
     * The steepest exponent d ln F / d ln δ with which the table's force may start, below
     * its smallest level and where levels are repaired: Hertz's point contact, F ∝ δ^1.5
     * (a plane line contact starts at about 1). Steeper slopes at the lowest levels are
     * the first-order rigid overlap's, not the contact's (fill_and_repair()): continued
     * down to zero they gave forces of 1e-15 N at 0.1 nm, which the fe pressure model of
     * a wear run cannot solve (measured: the FE scene stopped at its 13th iteration).
     */
    constexpr double steepest_onset_exponent = 1.5;

    mbs::Vec2
    unit_vector(const double angle)
    {
      return {std::cos(angle), std::sin(angle)};
    }

    /** @p angle in (−π, π]. */
    double
    wrapped(const double angle)
    {
      const double a = std::remainder(angle, two_pi);
      return a <= -pi ? a + two_pi : a;
    }

    /**
     * ∫ g ds over [s0, s1] for g a power law of s through (s0, g0) and (s1, g1) (exact for a
     * power-law force; the trapezoid where the law does not exist).
     */
    double
    power_law_segment(const double s0, const double g0, const double s1, const double g1)
    {
      if (g0 > 0 && g1 > 0 && s0 > 0 && s1 > s0)
        {
          const double p = std::log(g1 / g0) / std::log(s1 / s0);
          if (std::abs(p + 1) > 1e-9)
            return (g1 * s1 - g0 * s0) / (p + 1);
        }
      return 0.5 * (g0 + g1) * (s1 - s0);
    }

    /**
     * ln V of the K nodes of one ray (file comment of the header): V = ∫ |F| cos β dρ from
     * the onset, a power law of s = ρ − ρ_onset between levels, below the first level the
     * power law of the first two. Kept positive and increasing (ln V is interpolated with
     * increasing ends), which it is wherever the force points inwards (|β| < π/2).
     */
    void
    ray_potential(const double     *ln_f,
                  const double     *beta,
                  const double     *rho,
                  const double      onset,
                  const std::size_t K,
                  double           *ln_v)
    {
      std::vector<double> g(K), s(K);
      for (std::size_t k = 0; k < K; ++k)
        {
          g[k] = std::exp(ln_f[k]) * std::cos(beta[k]);
          s[k] = rho[k] - onset;
        }
      double V = 0;
      if (g[0] > 0 && g[1] > 0 && s[0] > 0 && s[1] > s[0])
        {
          const double p = std::log(g[1] / g[0]) / std::log(s[1] / s[0]);
          V              = p > -1 ? g[0] * s[0] / (p + 1) : 0.5 * g[0] * s[0];
        }
      else
        V = 0.5 * g[0] * s[0];
      V       = std::max(V, std::numeric_limits<double>::min());
      ln_v[0] = std::log(V);
      for (std::size_t k = 1; k < K; ++k)
        {
          V       = std::max(V + power_law_segment(s[k - 1], g[k - 1], s[k], g[k]), V * (1 + 1e-9));
          ln_v[k] = std::log(V);
        }
    }
  } // namespace

  FeConformalTable::FeConformalTable(const Profile &bore, const Profile &pin, Nodes n)
    : gap(bore, pin)
    , data(std::move(n))
    , K(static_cast<unsigned int>(data.overlaps.size()))
  {
    const std::size_t runs = std::size_t(data.n_pin) * data.n_bore, size = runs * K;
    if (K < 2 || runs < 1 || data.ln_force.size() != size || data.deviation.size() != size ||
        data.radius.size() != size || data.onset.size() != runs)
      throw InputError("A conformal table needs at least 2 overlap levels and one force, deviation and radius per "
                       "node (" +
                       std::to_string(K) + " levels, " + std::to_string(data.n_pin) + " × " +
                       std::to_string(data.n_bore) + " directions, " + std::to_string(data.ln_force.size()) +
                       " forces).");
    x.resize(K);
    for (unsigned int k = 0; k < K; ++k)
      {
        if (!(data.overlaps[k] > 0) || !std::isfinite(data.overlaps[k]) ||
            (k > 0 && !(data.overlaps[k] > data.overlaps[k - 1])))
          throw InputError("The overlap levels of a conformal table must be finite, positive and increasing.");
        x[k] = std::log(data.overlaps[k]);
      }
    for (std::size_t r = 0; r < size; ++r)
      if (!std::isfinite(data.ln_force[r]) || !std::isfinite(data.deviation[r]) || !std::isfinite(data.radius[r]) ||
          (r % K > 0 && !(data.ln_force[r] > data.ln_force[r - 1])))
        throw InputError("The force of node " + std::to_string(r) +
                         " of a conformal table is not finite or not larger than at the overlap level below.");
    slope_f.resize(size);
    slope_beta.resize(size);
    slope_v.resize(size);
    ln_v.resize(size);
    for (std::size_t run = 0; run < runs; ++run)
      {
        const std::size_t o = run * K;
        contact::hermite_slopes(x.data(), &data.ln_force[o], K, contact::HermiteEnds::increasing, &slope_f[o]);
        // The power law below δ_0 starts no steeper than an elastic contact does (a
        // smaller end slope keeps the cubic monotone).
        slope_f[o] = std::min(slope_f[o], steepest_onset_exponent);
        contact::hermite_slopes(x.data(), &data.deviation[o], K, contact::HermiteEnds::flat, &slope_beta[o]);
        ray_potential(&data.ln_force[o], &data.deviation[o], &data.radius[o], data.onset[run], K, &ln_v[o]);
        contact::hermite_slopes(x.data(), &ln_v[o], K, contact::HermiteEnds::increasing, &slope_v[o]);
        slope_v[o] = std::min(slope_v[o], slope_f[o] + 1); // V ∝ δ^(n+1) below δ_0, as F ∝ δ^n
      }
  }

  double
  FeConformalTable::node_force(const unsigned int j, const unsigned int i, const unsigned int k) const
  {
    return std::exp(data.ln_force[(std::size_t(j) * data.n_bore + i) * K + k]);
  }

  double
  FeConformalTable::node_potential(const unsigned int j, const unsigned int i, const unsigned int k) const
  {
    return std::exp(ln_v[(std::size_t(j) * data.n_bore + i) * K + k]);
  }

  double
  FeConformalTable::overlap(const mbs::Vec2 &e, const double relative_angle) const
  {
    return gap.evaluate(e, 0.0, relative_angle).penetration;
  }

  FeConformalTable::CornerValue
  FeConformalTable::corner(const std::size_t run, const double xq, const bool with_potential) const
  {
    const std::size_t o = run * K;
    CornerValue       c;
    double            unused = 0;
    contact::hermite_interpolate(x.data(), &data.ln_force[o], &slope_f[o], K, xq, c.ln_f, c.d_ln_f);
    // β is held at its end values beyond the levels: flat end slopes make that C¹.
    contact::hermite_interpolate(x.data(), &data.deviation[o], &slope_beta[o], K, xq, c.beta, c.d_beta);
    if (with_potential)
      contact::hermite_interpolate(x.data(), &ln_v[o], &slope_v[o], K, xq, c.ln_v, unused);
    return c;
  }

  FeConformalTable::Blend
  FeConformalTable::blend(const double alpha,
                          const double relative_angle,
                          const double xq,
                          const bool   with_potential) const
  {
    // Periodic linear weights of the four corners and their derivatives in α.
    unsigned int i0, i1, j0, j1;
    double       fa, ft;
    contact::periodic_grid_position(alpha, data.n_bore, i0, i1, fa);
    contact::periodic_grid_position(relative_angle, data.n_pin, j0, j1, ft);
    const double       da    = data.n_bore > 1 ? data.n_bore / two_pi : 0.0; // dfa/dα
    const unsigned int ii[4] = {i0, i1, i0, i1}, jj[4] = {j0, j0, j1, j1};
    const double       w[4]   = {(1 - fa) * (1 - ft), fa * (1 - ft), (1 - fa) * ft, fa * ft};
    const double       w_a[4] = {-da * (1 - ft), da * (1 - ft), -da * ft, da * ft};
    Blend              b;
    for (int q = 0; q < 4; ++q)
      if (w[q] > 0 || w_a[q] != 0)
        {
          const CornerValue c = corner(std::size_t(jj[q]) * data.n_bore + ii[q], xq, with_potential);
          b.ln_f += w[q] * c.ln_f;
          b.d_ln_f += w[q] * c.d_ln_f;
          b.beta += w[q] * c.beta;
          b.d_beta += w[q] * c.d_beta;
          b.ln_v += w[q] * c.ln_v;
          b.ln_f_alpha += w_a[q] * c.ln_f;
          b.beta_alpha += w_a[q] * c.beta;
        }
    return b;
  }

  namespace
  {
    /**
     * The stiffness-proportional L-N damping term of the file comment for the elastic
     * force @p f with Jacobian @p J at overlap @p delta, local exponent @p n_loc, and the
     * motion @p m; scaled down so that the damped force is not tensile along @p f.
     */
    mbs::Vec2
    damping_term(const mbs::Vec2                &f,
                 const Eigen::Matrix2d          &J,
                 const double                    delta,
                 const double                    n_loc,
                 const contact::ConformalMotion &m)
    {
      const Eigen::Matrix2d D = (delta / n_loc) * 0.5 * (J + J.transpose());
      const double          a = D(0, 0), b = D(0, 1), c = D(1, 1);
      const double          mean = 0.5 * (a + c), radius = std::hypot(0.5 * (a - c), b);
      const mbs::Vec2       q1        = unit_vector(0.5 * std::atan2(2 * b, a - c)); // of the larger eigenvalue
      const mbs::Vec2       q[2]      = {q1, mbs::perp(q1)};
      const double          lambda[2] = {mean + radius, mean - radius};
      mbs::Vec2             term(0, 0);
      for (int mode = 0; mode < 2; ++mode)
        {
          const double s = q[mode].dot(m.velocity);
          const double v = std::max({m.impact_velocity, m.min_velocity, std::abs(s)});
          if (v > 0)
            term += m.factor * std::min(lambda[mode], 0.0) * (s / v) * q[mode];
        }
      const double F = f.norm(), along = term.dot(f) / F;
      if (F + along < 0) // never tensile: the damping term scaled until the force along f is 0
        term *= F / -along;
      return term;
    }
  } // namespace

  void
  FeConformalTable::evaluate(const mbs::Vec2                &e,
                             const double                    relative_angle,
                             const contact::ConformalMotion *motion,
                             const bool                      with_potential,
                             contact::ConformalForce        &out) const
  {
    out                         = contact::ConformalForce();
    const contact::GapResult gr = gap.evaluate(e, 0.0, relative_angle);
    out.overlap                 = gr.penetration;
    out.deepest                 = std::atan2(gr.normal.y(), gr.normal.x());
    if (!(gr.penetration > 0))
      return;
    const double delta = gr.penetration, xq = std::log(delta), alpha = std::atan2(e.y(), e.x());
    ++evaluations;
    below += xq < x.front() ? 1 : 0;
    above += xq > x.back() ? 1 : 0;
    const Blend     b = blend(alpha, relative_angle, xq, with_potential);
    const double    F = std::exp(b.ln_f);
    const mbs::Vec2 u = unit_vector(alpha + pi + b.beta), t = mbs::perp(u);
    out.force  = F * u;
    out.damped = out.force;
    if (with_potential)
      out.potential = std::exp(b.ln_v);
    if (motion != nullptr && motion->factor > 0)
      {
        // J = ∂F/∂δ ⊗ ∂δ/∂e + ∂F/∂α ⊗ ∂α/∂e (file comment of the header).
        const mbs::Vec2       dF_ddelta = (F / delta) * (b.d_ln_f * u + b.d_beta * t);
        const mbs::Vec2       dF_dalpha = F * (b.ln_f_alpha * u + (1 + b.beta_alpha) * t);
        const mbs::Vec2       da_de     = mbs::perp(e) / e.squaredNorm();
        const Eigen::Matrix2d J         = dF_ddelta * gr.normal.transpose() + dF_dalpha * da_de.transpose();
        const mbs::Vec2       d         = damping_term(out.force, J, delta, b.d_ln_f, *motion);
        out.damped                      = out.force + d;
        out.damping_power               = -d.dot(motion->velocity);
      }
    // The force acts on the line through the pin centre: its moment about the bore centre.
    out.bushing_torque = -mbs::cross(e, out.damped);
  }

  std::vector<double>
  conformal_overlap_levels(const contact::JointGeometry &g, const std::vector<double> &forces)
  {
    using contact::CylindricalLaw;
    const contact::CylinderPair pair  = contact::CylinderPair::of(g);
    const double                f_max = contact::cylindrical_valid_max_force(CylindricalLaw::johnson, pair);
    const double                d_max = contact::cylindrical_approach(CylindricalLaw::johnson, pair, f_max);
    // d ln δ / d ln F at the valid maximum, from the closed form itself.
    const double slope =
      std::log(d_max / contact::cylindrical_approach(CylindricalLaw::johnson, pair, f_max / 1.01)) / std::log(1.01);
    std::vector<double> levels(forces.size());
    for (std::size_t k = 0; k < forces.size(); ++k)
      {
        levels[k] = forces[k] <= f_max ? contact::cylindrical_approach(CylindricalLaw::johnson, pair, forces[k]) :
                                         d_max * std::pow(forces[k] / f_max, slope);
        AssertThrow(levels[k] > 0 && (k == 0 || levels[k] > levels[k - 1]),
                    dealii::ExcMessage("The overlap levels of a conformal table do not increase with the load."));
      }
    return levels;
  }
} // namespace wearlink::fe

namespace wearlink::fe
{
  namespace
  {
    /**
     * The radius ρ > @p lo along u(@p alpha) (bushing frame, pin at @p theta) at which the
     * rigid overlap is @p delta [m]; the overlap at @p lo must be below it. The overlap is
     * a maximum over directions of functions increasing in ρ where it is positive, so it
     * increases along the ray and is convex in ρ: bracketed by @p lo and c(α) + δ (where
     * the direction α alone overlaps by δ), the Illinois variant of the secant method
     * converges superlinearly from either side.
     */
    double
    ray_radius(const contact::Gap           &gap,
               const contact::JointGeometry &g,
               const double                  alpha,
               const double                  theta,
               const double                  delta,
               const double                  lo)
    {
      const mbs::Vec2 u = unit_vector(alpha);
      const auto      f = [&](const double rho) {
        return gap.evaluate(rho * u, 0.0, theta).penetration - delta;
      };
      double a = lo, b = g.bore.radius(alpha) - g.pin.radius(alpha - theta) + delta;
      double fa = f(a), fb = f(b);
      for (int grow = 0; grow < 60 && fb < 0; ++grow) // round-off of the gap at c(α) + δ
        fb = f(b += 1e-15 + 1e-12 * b);
      AssertThrow(fa < 0 && fb >= 0,
                  dealii::ExcMessage("The overlap along a ray of a conformal table is not bracketed."));
      int side = 0;
      for (int it = 0; it < 200 && fb != 0; ++it)
        {
          const double c  = (a * fb - b * fa) / (fb - fa);
          const double fc = f(c);
          if (std::abs(fc) <= 1e-10 * delta || b - a <= 1e-14 * b)
            return c;
          if (fc > 0)
            {
              b = c, fb = fc;
              fa *= side == -1 ? 0.5 : 1.0;
              side = -1;
            }
          else
            {
              a = c, fa = fc;
              fb *= side == 1 ? 0.5 : 1.0;
              side = 1;
            }
        }
      return b;
    }

    /**
     * One node: the FE solve with the pin centre at @p rho u(@p alpha), the pin at the
     * relative angle @p theta; ln|F| and β into @p n at @p node, NaN if the solve failed
     * (counted, the first failure kept in @p build).
     */
    void
    solve_node(PinBushingModel         &model,
               const double             theta,
               const double             alpha,
               const double             rho,
               FeConformalTable::Nodes &n,
               const std::size_t        node,
               TableBuild              &build)
    {
      LoadCase lc;
      lc.control       = Control::displacement;
      lc.bushing_angle = 0;
      lc.pin_angle     = theta;
      lc.eccentricity  = {{rho * std::cos(alpha), rho * std::sin(alpha)}};
      ++build.n_solves;
      try
        {
          const ContactResult r = model.solve(lc, SolverKind::condensed);
          // The resultant Σ λ_i n_i (n_i the pin's outward normals, fe/contact_solver.h) is
          // the load the contact carries, the force of the pin on the bushing; the
          // bushing pushes the pin with its opposite.
          const mbs::Vec2 F(-r.resultant[0], -r.resultant[1]);
          if (!std::isfinite(F.norm()))
            throw NumericalError("the contact force is not finite");
          // No force at all: the overlap is below what the FE model resolves (see
          // fill_and_repair()); marked −∞, repaired from the level above.
          n.ln_force[node]     = F.norm() > 0 ? std::log(F.norm()) : -std::numeric_limits<double>::infinity();
          n.deviation[node]    = F.norm() > 0 ? wrapped(std::atan2(F.y(), F.x()) - alpha - pi) : n.ln_force[node];
          build.max_half_angle = std::max(build.max_half_angle, r.half_angle);
        }
      catch (const NumericalError &e) // filled from its neighbours and counted
        {
          n.ln_force[node] = n.deviation[node] = numbers::nan;
          if (build.n_failed++ == 0)
            build.first_failure = "overlap " + std::to_string(n.overlaps[node % n.overlaps.size()]) +
                                  " m in the direction " + std::to_string(alpha) +
                                  " rad (bushing frame) at the relative angle " + std::to_string(theta) +
                                  " rad: " + e.what();
        }
    }

    /** Every node of @p n (its grid set) on @p model: the radii on the rays and the FE solves. */
    void
    solve_nodes(PinBushingModel &model, const contact::JointGeometry &g, FeConformalTable::Nodes &n, TableBuild &build)
    {
      const Stopwatch solving;
      use_profiles(model, g);
      const contact::Gap gap(g.bore, g.pin);
      const std::size_t  K = n.overlaps.size(), runs = std::size_t(n.n_pin) * n.n_bore;
      n.ln_force.assign(runs * K, 0.0);
      n.deviation.assign(runs * K, 0.0);
      n.radius.assign(runs * K, 0.0);
      n.onset.assign(runs, 0.0);
      for (unsigned int j = 0; j < n.n_pin; ++j)
        for (unsigned int i = 0; i < n.n_bore; ++i)
          {
            const double      theta = two_pi * j / n.n_pin, alpha = two_pi * i / n.n_bore;
            const std::size_t run = std::size_t(j) * n.n_bore + i;
            double            rho = ray_radius(gap, g, alpha, theta, 0.0, 0.0);
            n.onset[run]          = rho;
            for (std::size_t k = 0; k < K; ++k)
              {
                rho                   = ray_radius(gap, g, alpha, theta, n.overlaps[k], rho);
                n.radius[run * K + k] = rho;
                solve_node(model, theta, alpha, rho, n, run * K + k, build);
              }
          }
      build.solve_seconds = solving.seconds();
    }

    /**
     * Fill the failed nodes from their neighbours along the levels (fill_failed_levels:
     * ln|F| and β linear in ln δ), then make ln|F| increase along every ray from the top
     * level down: a level not below the next, or with no force at all, is put on the
     * power law of the segment above it (exponent 1 at the top, at most
     * steepest_onset_exponent) and counted, its β that of the level above. Displacement
     * control makes |F| grow with the overlap along a ray (the contact's energy is convex
     * in e); what breaks it at the lowest levels is the rigid overlap itself
     * (contact/gap.h), first-order in e/R: a pin whose deepest point lies at γ from e
     * meets the bore e² sin²γ/(2 R2) later than it says, 0.35 µm at γ = 10° in a 0.5 mm
     * clearance — measured in joint A's pocket of the nine-bar: no FE force up to the
     * fourth level (0.16 µm), 0.9 N where the round pair carries 10 N at 43 nm.
     */
    void
    fill_and_repair(FeConformalTable::Nodes &n, TableBuild &build)
    {
      const std::size_t   K = n.overlaps.size();
      std::vector<double> x(K);
      for (std::size_t k = 0; k < K; ++k)
        x[k] = std::log(n.overlaps[k]);
      const auto name = [&](const std::size_t run) {
        return std::to_string(two_pi * (run % n.n_bore) / n.n_bore) + " rad (bushing frame) at the relative angle " +
               std::to_string(two_pi * (run / n.n_bore) / n.n_pin) + " rad";
      };
      if (build.n_failed > 0)
        {
          const std::string what = "overlap levels of the conformal table";
          fill_failed_levels(n.ln_force, x, name, what, build.first_failure);
          fill_failed_levels(n.deviation, x, name, what, build.first_failure);
        }
      for (std::size_t run = 0; run * K < n.ln_force.size(); ++run)
        {
          double *y = &n.ln_force[run * K], *beta = &n.deviation[run * K];
          if (!std::isfinite(y[K - 1]))
            throw NumericalError("The FE model carries no contact force at the largest overlap level of the conformal "
                                 "table (" +
                                 std::to_string(n.overlaps[K - 1]) + " m) in the direction " + name(run) +
                                 "; raise 'Table maximum force'.");
          for (std::size_t k = K - 1; k-- > 0;)
            {
              if (y[k] < y[k + 1] && std::isfinite(y[k]))
                continue;
              const double slope =
                std::min(k + 2 < K && y[k + 2] > y[k + 1] ? (y[k + 2] - y[k + 1]) / (x[k + 2] - x[k + 1]) : 1.0,
                         steepest_onset_exponent);
              y[k]    = y[k + 1] - slope * (x[k + 1] - x[k]);
              beta[k] = std::isfinite(beta[k]) ? beta[k] : beta[k + 1];
              ++build.n_repaired;
            }
        }
    }

    /** The cached nodes for @p key into @p n (false: none). */
    bool
    read_cached_nodes(const std::string &file, const std::string &key, FeConformalTable::Nodes &n, TableBuild &build)
    {
      const Json j = read_table_cache(file, conformal_cache_format, conformal_cache_version, key);
      if (j.is_null())
        return false;
      try
        {
          n.n_pin              = j.at("pin_directions").get<unsigned int>();
          n.n_bore             = j.at("bore_directions").get<unsigned int>();
          n.overlaps           = j.at("overlaps_m").get<std::vector<double>>();
          n.ln_force           = j.at("ln_force_N").get<std::vector<double>>();
          n.deviation          = j.at("deviation_rad").get<std::vector<double>>();
          n.radius             = j.at("radius_m").get<std::vector<double>>();
          n.onset              = j.at("onset_m").get<std::vector<double>>();
          build.n_solves       = j.at("solves").get<unsigned int>();
          build.n_failed       = j.at("failed_solves").get<unsigned int>();
          build.n_repaired     = j.at("repaired_points").get<unsigned int>();
          build.max_half_angle = j.at("max_half_angle_rad").get<double>();
          return true;
        }
      catch (const std::exception &) // a damaged entry: rebuild (the file is overwritten)
        {
          return false;
        }
    }

    void
    write_cached_nodes(const std::string             &file,
                       const std::string             &key,
                       const FeConformalTable::Nodes &n,
                       const TableBuild              &b)
    {
      Json j;
      j["pin_directions"]     = n.n_pin;
      j["bore_directions"]    = n.n_bore;
      j["overlaps_m"]         = n.overlaps;
      j["ln_force_N"]         = n.ln_force;
      j["deviation_rad"]      = n.deviation;
      j["radius_m"]           = n.radius;
      j["onset_m"]            = n.onset;
      j["solves"]             = b.n_solves;
      j["failed_solves"]      = b.n_failed;
      j["repaired_points"]    = b.n_repaired;
      j["max_half_angle_rad"] = b.max_half_angle;
      write_table_cache(file, conformal_cache_format, conformal_cache_version, key, std::move(j));
    }

    /** Solve every node on the joint's shared model (kept in @p shared), filled and repaired. */
    void
    solve_on_shared_model(const contact::JointGeometry     &g,
                          const FeForceLawSettings         &s,
                          FeConformalTable::Nodes          &n,
                          TableBuild                       &build,
                          std::shared_ptr<PinBushingModel> *shared)
    {
      bool reused = false;
      auto model  = shared_model(g, s.fe, &reused);
      if (!reused)
        {
          build.mesh_seconds  = model->statistics().mesh_time;
          build.setup_seconds = model->statistics().assembly_time + model->statistics().factorization_time;
        }
      if (shared != nullptr)
        *shared = model;
      // The rays go all around both surfaces: every compliance column is asked for, and
      // computed up front they run on every core (as for the force–approach table).
      const Stopwatch columns;
      if (n.n_pin * n.n_bore > 1 || model->compliance_is_periodic())
        model->precompute_compliance();
      const double column_seconds = columns.seconds();
      solve_nodes(*model, g, n, build);
      build.solve_seconds += column_seconds;
      fill_and_repair(n, build);
      if (build.n_failed > 0)
        std::cerr << "[wearlink] warning: the FE contact solver failed at " << build.n_failed << " of "
                  << build.n_solves
                  << " nodes of the conformal table; they were filled from their neighbours (table_failed_solves in "
                  << "summary.json). The first failure: " << build.first_failure << "\n";
    }
  } // namespace

  std::unique_ptr<FeConformalTable>
  build_conformal_table(const contact::JointGeometry     &g,
                        const FeForceLawSettings         &s,
                        TableBuild                       &build,
                        std::shared_ptr<PinBushingModel> *shared)
  {
    const Stopwatch clock;
    build = TableBuild();
    FeConformalTable::Nodes n;
    n.n_pin    = g.pin.is_round() ? 1 : s.n_pin_directions;
    n.n_bore   = s.n_bore_directions;
    n.overlaps = conformal_overlap_levels(g, table_load_levels(s));
    // As the force–approach table: the shared model's meshed profiles belong to the key,
    // and a table in the cache needs no model.
    auto              model = find_shared_model(g, s.fe);
    const std::string key   = table_geometry_key(g, s, model ? &model->meshed_geometry() : nullptr);
    if (s.cache)
      {
        build.cache_file = table_cache_file("fe_conformal_table", key);
        if (read_cached_nodes(build.cache_file, key, n, build))
          {
            build.from_cache = true;
            if (shared != nullptr)
              *shared = model;
            auto table    = std::make_unique<FeConformalTable>(g.bore, g.pin, std::move(n));
            build.seconds = clock.seconds();
            return table;
          }
      }
    solve_on_shared_model(g, s, n, build, shared);
    if (s.cache)
      write_cached_nodes(build.cache_file, key, n, build);
    auto table    = std::make_unique<FeConformalTable>(g.bore, g.pin, std::move(n));
    build.seconds = clock.seconds();
    return table;
  }
} // namespace wearlink::fe
