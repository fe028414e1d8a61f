// SPDX-License-Identifier: LGPL-2.1-or-later
#include "contact/conformal_contact.h"

#include "base/exceptions.h"
#include "base/numbers.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace wearlink::contact
{
  namespace
  {
    using numbers::pi;
    using numbers::two_pi;

    /** Three-point Gauss–Legendre on [0, 1]. */
    constexpr double gauss_t[3] = {0.11270166537925831148, 0.5, 0.88729833462074168852};
    constexpr double gauss_w[3] = {5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0};

    /**
     * The integrals of one cell per unit weight, for an overlap linear from @p a (left
     * edge) to @p b (right edge) across it (t ∈ [0, 1]): ∂E/∂a = ∫ p (1 − t) dt,
     * ∂E/∂b = ∫ p t dt and E = ∫ P dt.
     */
    struct Cell
    {
      double left = 0, right = 0, energy = 0;
    };

    /** Gauss–Legendre over [t0, t1] ⊂ [0, 1] of the overlap a + (b − a) t (smooth there). */
    Cell
    gauss_cell(const Foundation &f, const double a, const double b, const double t0, const double t1)
    {
      Cell         c;
      const double span = t1 - t0;
      for (int q = 0; q < 3; ++q)
        {
          const double t = t0 + span * gauss_t[q];
          const double x = a + (b - a) * t;
          const double p = f.pressure(x);
          c.left += gauss_w[q] * span * p * (1 - t);
          c.right += gauss_w[q] * span * p * t;
          c.energy += gauss_w[q] * span * f.energy(x);
        }
      return c;
    }

    /** A power law p = k x^m over a cell whose left edge is clear (a ≤ 0 < b): from the root on, exactly. */
    Cell
    power_cell_from_root(const double k, const double m, const double a, const double b)
    {
      const double delta = b - a, t0 = -a / delta;
      const double b1 = m == 1 ? b * b : std::pow(b, m + 1), b2 = b1 * b;
      Cell         c;
      c.left   = k * b2 / (delta * delta * (m + 1) * (m + 2));
      c.right  = k * (b2 / ((m + 2) * delta * delta) + t0 * b1 / ((m + 1) * delta));
      c.energy = k * b2 / ((m + 1) * (m + 2) * delta);
      return c;
    }

    /** A power law over a cell that overlaps at both edges. */
    Cell
    power_cell_inside(const Foundation &f, const double a, const double b)
    {
      const double k = f.coefficient(), m = f.exponent();
      if (m == 1)
        return {k * (a / 3 + b / 6), k * (a / 6 + b / 3), k * (a * a + a * b + b * b) / 6};
      const double delta = b - a;
      if (std::abs(delta) <= 0.5 * std::max(a, b)) // smooth: closed forms would cancel
        return gauss_cell(f, a, b, 0, 1);
      const double a1 = std::pow(a, m + 1), b1 = std::pow(b, m + 1);
      const double a2 = a1 * a, b2 = b1 * b;
      const double whole = k * (b1 - a1) / ((m + 1) * delta);
      Cell         c;
      c.right  = k * ((b2 - a2) / (m + 2) - a * (b1 - a1) / (m + 1)) / (delta * delta);
      c.left   = whole - c.right;
      c.energy = k * (b2 - a2) / ((m + 1) * (m + 2) * delta);
      return c;
    }

    /** The integrals of a cell with edge overlaps @p a, @p b (Cell). */
    Cell
    cell_integrals(const Foundation &f, const double a, const double b)
    {
      if (a <= 0 && b <= 0)
        return {};
      if (a > 0 && b > 0)
        return f.is_power_law() ? power_cell_inside(f, a, b) : gauss_cell(f, a, b, 0, 1);
      if (a <= 0) // the cell overlaps from the root t0 = a/(a − b) to its right edge
        return f.is_power_law() ? power_cell_from_root(f.coefficient(), f.exponent(), a, b) :
                                  gauss_cell(f, a, b, a / (a - b), 1);
      // b ≤ 0 < a: the mirror image (t → 1 − t swaps the edges)
      Cell c = f.is_power_law() ? power_cell_from_root(f.coefficient(), f.exponent(), b, a) :
                                  gauss_cell(f, b, a, b / (b - a), 1);
      std::swap(c.left, c.right);
      return c;
    }
  } // namespace

  double
  narrow_contact_integral(const double m)
  {
    return std::sqrt(pi) * std::tgamma(m + 1) / std::tgamma(m + 1.5);
  }

  Foundation
  Foundation::power_law(const double k, const double m)
  {
    Foundation f;
    f.k = k;
    f.m = m;
    return f;
  }

  Foundation
  foundation_of_power_law(const double stiffness,
                          const double exponent,
                          const double clearance,
                          const double radius,
                          const double length)
  {
    const double m = exponent - 0.5;
    return Foundation::power_law(stiffness / (length * radius * std::sqrt(2 / clearance) * narrow_contact_integral(m)),
                                 m);
  }

  Foundation
  Foundation::of_curve(const std::function<double(double)> &force,
                       const double                         clearance,
                       const double                         radius,
                       const double                         length,
                       const double                         smallest,
                       const double                         largest,
                       const unsigned int                   n_nodes)
  {
    AssertThrow(n_nodes >= 3 && smallest > 0 && largest > smallest && clearance > 0,
                dealii::ExcMessage("Foundation::of_curve needs at least three nodes over a positive range."));
    Foundation          f;
    const double        step = std::log(largest / smallest) / (n_nodes - 1);
    std::vector<double> ln_f(n_nodes);
    f.ln_d.resize(n_nodes);
    for (unsigned int j = 0; j < n_nodes; ++j)
      {
        f.ln_d[j] = std::log(smallest) + j * step;
        ln_f[j]   = std::log(force(std::exp(f.ln_d[j])));
        AssertThrow(std::isfinite(ln_f[j]),
                    dealii::ExcMessage("A normal force law's round curve is not positive where the conformal "
                                       "foundation samples it."));
      }
    const double scale = length * radius * std::sqrt(2 / clearance);
    f.ln_p.resize(n_nodes);
    for (unsigned int j = 0; j < n_nodes; ++j)
      {
        const unsigned int lo = j == 0 ? 0 : j - 1, hi = j + 1 == n_nodes ? j : j + 1;
        const double       n = (ln_f[hi] - ln_f[lo]) / (f.ln_d[hi] - f.ln_d[lo]); // local exponent
        const double       m = std::max(n - 0.5, 0.01);
        f.ln_p[j]            = ln_f[j] - std::log(scale * narrow_contact_integral(m)) - 0.5 * f.ln_d[j];
      }
    f.slope.resize(n_nodes);
    for (unsigned int j = 0; j + 1 < n_nodes; ++j)
      f.slope[j] = std::max((f.ln_p[j + 1] - f.ln_p[j]) / step, -0.99);
    f.slope[n_nodes - 1] = f.slope[n_nodes - 2];
    // Below the first node: the power law of the first segment; k, m hold it.
    f.m = f.slope[0];
    f.k = std::exp(f.ln_p[0] - f.m * f.ln_d[0]);
    f.cum.resize(n_nodes);
    f.cum[0] = std::exp(f.ln_p[0] + f.ln_d[0]) / (f.m + 1);
    for (unsigned int j = 0; j + 1 < n_nodes; ++j)
      {
        const double pd = std::exp(f.ln_p[j] + f.ln_d[j]);
        f.cum[j + 1]    = f.cum[j] + pd / (f.slope[j] + 1) * (std::exp((f.slope[j] + 1) * step) - 1);
      }
    return f;
  }

  double
  Foundation::pressure(const double d) const
  {
    if (!(d > 0))
      return 0;
    if (ln_d.empty())
      return m == 1 ? k * d : k * std::pow(d, m);
    const double x = std::log(d);
    if (x <= ln_d.front())
      return k * std::pow(d, m);
    const double step = ln_d[1] - ln_d[0];
    const auto   j    = std::min<std::size_t>(static_cast<std::size_t>((x - ln_d[0]) / step), ln_d.size() - 1);
    return std::exp(ln_p[j] + slope[j] * (x - ln_d[j]));
  }

  double
  Foundation::energy(const double d) const
  {
    if (!(d > 0))
      return 0;
    if (ln_d.empty())
      return m == 1 ? 0.5 * k * d * d : k * std::pow(d, m + 1) / (m + 1);
    const double x = std::log(d);
    if (x <= ln_d.front())
      return k * std::pow(d, m + 1) / (m + 1);
    const double step = ln_d[1] - ln_d[0];
    const auto   j    = std::min<std::size_t>(static_cast<std::size_t>((x - ln_d[0]) / step), ln_d.size() - 1);
    const double pd   = std::exp(ln_p[j] + ln_d[j]);
    return cum[j] + pd / (slope[j] + 1) * (std::exp((slope[j] + 1) * (x - ln_d[j])) - 1);
  }

  OverlapFoundation::OverlapFoundation(const Profile     &bore,
                                       const Profile     &pin,
                                       const double       length,
                                       const double       radius,
                                       Foundation         f,
                                       const unsigned int cells_per_area)
    : r2(pin.samples())
    , cells(std::max(1u, cells_per_area))
    , cell(two_pi / (bore.n_points() * cells))
    , pin_spacing(two_pi / pin.n_points())
    , weight(length * radius * cell)
    , min_clearance(bore.min_radius() - pin.max_radius())
    , foundation(std::move(f))
  {
    const unsigned int n = bore.n_points() * cells;
    r1.resize(n);
    ux.resize(n);
    uy.resize(n);
    for (unsigned int i = 0; i < n; ++i)
      {
        const double psi = i * cell;
        r1[i]            = bore.radius(psi);
        ux[i]            = std::cos(psi);
        uy[i]            = std::sin(psi);
      }
    // A kink of R2* where its slope falls by s lifts it above the chord of an interval w
    // wide by at most s w/4; a bore area holds at most ⌈w/spacing⌉ + 1 pin kinks.
    const std::size_t np   = r2.size();
    double            fall = 0; // the largest fall of the slope at a kink [m/rad]
    for (std::size_t k = 0; k < np; ++k)
      fall = std::max(fall, -(r2[(k + 1) % np] - 2 * r2[k] + r2[(k + np - 1) % np]) / pin_spacing);
    const double area = two_pi / bore.n_points();
    pin_bulge         = (std::ceil(area / pin_spacing) + 1) * fall * area / 4;
  }

  template <class Visit>
  double
  OverlapFoundation::scan(const mbs::Vec2 &e, const double relative_angle, Visit &&visit) const
  {
    const double rho = e.norm();
    if (min_clearance > 0 && !(rho > min_clearance))
      return rho - min_clearance;
    // Edges farther than acos(min_clearance/|e|) from e's direction cannot overlap; the
    // window takes whole bore areas around that bound.
    const double half  = min_clearance > 0 ? std::acos(std::min(1.0, min_clearance / rho)) : pi;
    const double phi_e = std::atan2(e.y(), e.x());
    const long   s     = cells;
    const auto   n     = static_cast<long>(r1.size());
    const auto   np    = static_cast<long>(r2.size());
    long         first = s * static_cast<long>(std::floor((phi_e - half) / (s * cell)));
    long         last  = s * static_cast<long>(std::ceil((phi_e + half) / (s * cell)));
    if (last - first >= n)
      last = first + n;
    // The pin sample below edge `first`, and the fraction to the next; advanced per edge.
    const double step       = cell / pin_spacing;
    const double x          = (first * cell - relative_angle) / pin_spacing;
    double       fl         = std::floor(x);
    double       frac       = x - fl;
    long         j          = static_cast<long>(fl - np * std::floor(fl / np));
    long         i          = ((first % n) + n) % n;
    const auto   overlap_at = [&](const long edge, const long sample, const double fraction, double &rise) {
      const long next = sample + 1 == np ? 0 : sample + 1;
      rise            = r2[next] - r2[sample];
      return r2[sample] + fraction * rise + e.x() * ux[edge] + e.y() * uy[edge] - r1[edge];
    };
    const auto forward = [&](long &edge, long &sample, double &fraction, const long count) {
      edge += count;
      if (edge >= n)
        edge -= n;
      fraction += count * step;
      while (fraction >= 1) // step ≤ 1 unless the pin has more samples than the cells
        {
          fraction -= 1;
          if (++sample == np)
            sample = 0;
        }
    };
    // What bounds the overlap inside an area above the larger of its ends: the concavity of
    // e·u over the area (ρ w²/8) and the pin's kinks.
    const double bulge = rho * (s * cell) * (s * cell) / 8 + pin_bulge;
    double       rise  = 0;
    double       d     = overlap_at(i, j, frac, rise);
    double       best  = d;
    visit(d, i, rise, false);
    for (long k = first; k < last; k += s)
      {
        // The area's far edge first, to bound the area.
        long   i_far = i, j_far = j;
        double f_far = frac, rise_far = 0;
        forward(i_far, j_far, f_far, s);
        const double d_far = overlap_at(i_far, j_far, f_far, rise_far);
        if (s > 1 && std::max(d, d_far) + bulge > 0)
          for (long m = 1; m < s; ++m) // the area's inner edges, in order
            {
              forward(i, j, frac, 1);
              double       r  = 0;
              const double di = overlap_at(i, j, frac, r);
              best            = std::max(best, di);
              visit(di, i, r, true);
            }
        const bool adjacent = s == 1 || std::max(d, d_far) + bulge > 0;
        i = i_far, j = j_far, frac = f_far;
        d    = d_far;
        best = std::max(best, d);
        visit(d, i, rise_far, adjacent);
      }
    return best;
  }

  double
  OverlapFoundation::overlap(const mbs::Vec2 &e, const double relative_angle) const
  {
    return scan(e, relative_angle, [](double, long, double, bool) {});
  }

  namespace
  {
    /**
     * What the edges of the overlap add up to: each edge carries the weight G = ∂E/∂d of
     * its two cells (elastic), and with a motion the damped weight G (1 + χ ḋ/v)⁺.
     */
    struct EdgeSums
    {
      double fx = 0, fy = 0, dx = 0, dy = 0; ///< −Σ G u, −Σ G_damped u
      double t_pin = 0, t_bushing = 0, power = 0;

      /**
       * Edge of weight @p g, direction (@p ux, @p uy), pin slope @p slope; @p e the pin
       * centre (for ∂d/∂θ_bushing = R2*' + e·perp(u)).
       */
      void
      add(const double           g,
          const double           ux,
          const double           uy,
          const double           slope,
          const mbs::Vec2       &e,
          const ConformalMotion *m)
      {
        const double turn = slope - e.x() * uy + e.y() * ux;
        double       gd   = g;
        if (m != nullptr && m->factor > 0)
          {
            // ḋ = (velocity)·u − R2*' θ̇_rel (the rate of the overlap at the edge)
            const double rate = m->velocity.x() * ux + m->velocity.y() * uy - slope * m->relative_rate;
            const double v    = std::max(m->impact_velocity, m->min_velocity);
            const double a    = std::abs(rate);
            gd                = std::max(0.0, g * (1 + m->factor * (a > v ? (rate > 0 ? 1.0 : -1.0) : rate / v)));
            power += (gd - g) * rate;
          }
        fx -= g * ux;
        fy -= g * uy;
        dx -= gd * ux;
        dy -= gd * uy;
        t_pin += gd * slope;
        t_bushing -= gd * turn;
      }
    };
  } // namespace

  void
  OverlapFoundation::evaluate(const mbs::Vec2       &e,
                              const double           relative_angle,
                              const ConformalMotion *motion,
                              const bool             with_potential,
                              ConformalForce        &out) const
  {
    out                      = ConformalForce();
    const double inv_spacing = 1 / pin_spacing;
    // The previous edge: overlap, index, the pin's rise there, and the part of its weight
    // from the cell before it; the deepest edge.
    double   d_prev = 0, rise_prev = 0, g_prev = 0, d_best = -std::numeric_limits<double>::infinity();
    long     i_prev = -1, i_best = -1;
    double   energy = 0;
    EdgeSums sums;
    // (inlined into the scan: it runs for every edge near the contact)
    out.overlap = scan(
      e,
      relative_angle,
      [&](const double d, const long i, const double rise, const bool adjacent) __attribute__((always_inline)) {
        double g = 0; // this edge's weight from the cell before it
        if (adjacent && (d > 0 || d_prev > 0))
          {
            const Cell c = cell_integrals(foundation, d_prev, d);
            g_prev += weight * c.left;
            g = weight * c.right;
            energy += weight * c.energy;
          }
        if (g_prev > 0) // the previous edge is complete
          sums.add(g_prev, ux[i_prev], uy[i_prev], rise_prev * inv_spacing, e, motion);
        if (d > d_best)
          d_best = d, i_best = i;
        d_prev    = d;
        i_prev    = i;
        rise_prev = rise;
        g_prev    = g;
      });
    if (g_prev > 0)
      sums.add(g_prev, ux[i_prev], uy[i_prev], rise_prev * inv_spacing, e, motion);
    out.deepest        = i_best >= 0 ? i_best * cell : std::atan2(e.y(), e.x());
    out.force          = mbs::Vec2(sums.fx, sums.fy);
    out.damped         = mbs::Vec2(sums.dx, sums.dy);
    out.pin_torque     = sums.t_pin;
    out.bushing_torque = sums.t_bushing;
    out.damping_power  = sums.power;
    if (with_potential)
      out.potential = energy;
  }
} // namespace wearlink::contact
