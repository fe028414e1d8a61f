// SPDX-License-Identifier: LGPL-2.1-or-later
#include "contact/force_approach_table.h"

#include "base/exceptions.h"
#include "contact/table_interpolation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace wearlink::contact
{
  namespace
  {
    /** ∫ F ds over [x_a, x_b] within the interval starting at @p x (s = e^x), 8-point Gauss–Legendre. */
    double
    interval_integral(const double *x, const double *y, const double *m, const double xa, const double xb)
    {
      static constexpr std::array<double, 4> node{
        {0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363}};
      static constexpr std::array<double, 4> weight{
        {0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763}};
      const double mid = 0.5 * (xa + xb), half = 0.5 * (xb - xa), h = x[1] - x[0];
      double       sum = 0;
      for (std::size_t q = 0; q < node.size(); ++q)
        for (const double sign : {-1.0, 1.0})
          {
            const double xq = mid + sign * half * node[q];
            double       yq, dy;
            hermite(x, y, m, (xq - x[0]) / h, yq, dy);
            sum += weight[q] * std::exp(yq + xq);
          }
      return sum * half;
    }
  } // namespace

  ForceApproachTable::ForceApproachTable(std::vector<double> forces,
                                         const unsigned int  n_bore,
                                         const unsigned int  n_pin,
                                         std::vector<double> approach)
    : levels(std::move(forces))
    , n_b(n_bore)
    , n_p(n_pin)
    , delta(std::move(approach))
  {
    const std::size_t K = levels.size();
    if (K < 2 || n_b < 1 || n_p < 1 || delta.size() != std::size_t(n_b) * n_p * K)
      throw InputError("A force–approach table needs at least 2 load levels and one approach per level and "
                       "direction (" +
                       std::to_string(K) + " levels, " + std::to_string(n_b) + " × " + std::to_string(n_p) +
                       " directions, " + std::to_string(delta.size()) + " approaches).");
    for (std::size_t k = 0; k < K; ++k)
      if (!(levels[k] > 0) || !std::isfinite(levels[k]) || (k > 0 && !(levels[k] > levels[k - 1])))
        throw InputError("The load levels of a force–approach table must be finite, positive and increasing.");
    for (std::size_t r = 0; r < delta.size(); ++r)
      if (!(delta[r] > 0) || !std::isfinite(delta[r]) || (r % K > 0 && !(delta[r] > delta[r - 1])))
        throw InputError("The approach of direction " + std::to_string(r / K) + " at load level " +
                         std::to_string(r % K) + " (" + std::to_string(delta[r]) +
                         " m) is not positive or not larger than at the level below: the force would not "
                         "increase with the approach.");
    const std::size_t n = delta.size();
    x.resize(n);
    y.resize(n);
    m.resize(n);
    v.resize(n);
    for (std::size_t d = 0; d < n / K; ++d)
      {
        double *xd = &x[d * K], *yd = &y[d * K], *md = &m[d * K], *vd = &v[d * K];
        for (std::size_t k = 0; k < K; ++k)
          {
            xd[k] = std::log(delta[d * K + k]);
            yd[k] = std::log(levels[k]);
          }
        hermite_slopes(xd, yd, K, HermiteEnds::increasing, md);
        // V(δ_0) of the power law F_0 (δ/δ_0)^m below, then interval by interval.
        vd[0] = levels[0] * delta[d * K] / (md[0] + 1);
        for (std::size_t k = 1; k < K; ++k)
          vd[k] = vd[k - 1] + interval_integral(xd + k - 1, yd + k - 1, md + k - 1, xd[k - 1], xd[k]);
      }
  }

  ForceApproachTable::DirectionValue
  ForceApproachTable::evaluate_direction(const std::size_t d, const double approach) const
  {
    const std::size_t K  = levels.size();
    const double     *xd = &x[d * K], *yd = &y[d * K], *md = &m[d * K];
    const double      xq = std::log(approach);
    DirectionValue    out;
    double            yq, dy;
    out.region    = hermite_interpolate(xd, yd, md, K, xq, yq, dy);
    out.force     = std::exp(yq);
    out.stiffness = out.force / approach * dy;
    return out;
  }

  double
  ForceApproachTable::potential_direction(const std::size_t d, const double approach) const
  {
    const std::size_t K  = levels.size();
    const double     *xd = &x[d * K], *yd = &y[d * K], *md = &m[d * K], *vd = &v[d * K];
    const double      xq = std::log(approach);
    if (xq <= xd[0]) // V = V(δ_0) (δ/δ_0)^(m+1)
      return vd[0] * std::exp((md[0] + 1) * (xq - xd[0]));
    if (xq >= xd[K - 1]) // + F_end δ_end ((δ/δ_end)^(m+1) − 1)/(m + 1)
      return vd[K - 1] +
             std::exp(yd[K - 1] + xd[K - 1]) / (md[K - 1] + 1) * (std::exp((md[K - 1] + 1) * (xq - xd[K - 1])) - 1);
    const std::size_t k = std::min<std::size_t>(K - 2, std::upper_bound(xd, xd + K, xq) - xd - 1);
    return vd[k] + interval_integral(xd + k, yd + k, md + k, xd[k], xq);
  }

  unsigned int
  ForceApproachTable::neighbours(const double bore_angle,
                                 const double pin_angle,
                                 std::size_t (&d)[4],
                                 double (&w)[4]) const
  {
    unsigned int i0, i1, j0, j1;
    double       fi, fj;
    periodic_grid_position(bore_angle, n_b, i0, i1, fi);
    periodic_grid_position(pin_angle, n_p, j0, j1, fj);
    const unsigned int ii[4] = {i0, i1, i0, i1}, jj[4] = {j0, j0, j1, j1};
    const double       ww[4] = {(1 - fi) * (1 - fj), fi * (1 - fj), (1 - fi) * fj, fi * fj};
    unsigned int       n     = 0;
    for (unsigned int q = 0; q < 4; ++q)
      if (ww[q] > 0)
        {
          d[n]   = std::size_t(ii[q]) * n_p + jj[q];
          w[n++] = ww[q];
        }
    return n;
  }

  ForceApproachTable::Value
  ForceApproachTable::evaluate(const double approach, const double bore_angle, const double pin_angle) const
  {
    Value out;
    if (!(approach > 0))
      return out;
    std::size_t        d[4];
    double             w[4];
    const unsigned int n      = neighbours(bore_angle, pin_angle, d, w);
    int                region = 0;
    for (unsigned int q = 0; q < n; ++q)
      {
        const DirectionValue f = evaluate_direction(d[q], approach);
        out.force += w[q] * f.force;
        out.stiffness += w[q] * f.stiffness;
        region = f.region != 0 ? f.region : region;
      }
    out.region = region < 0 ? Region::below : region > 0 ? Region::above : Region::table;
    return out;
  }

  double
  ForceApproachTable::potential(const double approach, const double bore_angle, const double pin_angle) const
  {
    if (!(approach > 0))
      return 0;
    std::size_t        d[4];
    double             w[4];
    const unsigned int n = neighbours(bore_angle, pin_angle, d, w);
    double             V = 0;
    for (unsigned int q = 0; q < n; ++q)
      V += w[q] * potential_direction(d[q], approach);
    return V;
  }
} // namespace wearlink::contact
