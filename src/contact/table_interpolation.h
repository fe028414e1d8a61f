// SPDX-License-Identifier: LGPL-2.1-or-later
// The interpolation shared by the contact laws' tables (contact/force_approach_table.h
// and the fe law's conformal table, fe/fe_conformal_table.h):
//   - periodic linear weights of an angle on a uniform grid over 2π;
//   - shape-preserving cubic Hermite interpolation of nodes (x_k, y_k) (Fritsch & Carlson,
//     SIAM J. Numer. Anal. 17 (1980) 238–246, with the slopes of Brodlie: the weighted
//     harmonic mean of the neighbouring secants where they have one sign, zero where they
//     change sign): C¹, monotone where the data are, no overshoot at an extremum.
#pragma once

#include <cstddef>

namespace wearlink::contact
{
  /**
   * The grid neighbours @p i0, @p i1 of angle @p angle [rad] on a periodic grid of @p n
   * points 2πi/n, and the weight @p f ∈ [0, 1) of @p i1 (n = 1: both 0, f = 0).
   */
  void
  periodic_grid_position(double angle, unsigned int n, unsigned int &i0, unsigned int &i1, double &f);

  /** How the Hermite slopes are chosen at the first and last node. */
  enum class HermiteEnds
  {
    /**
     * The three-point slope kept within [d/2, 3d] of the end secant d > 0 (increasing
     * data): the interpolant stays monotone, and a power law that continues it in
     * (ln δ, ln F) has a positive exponent.
     */
    increasing,
    /** Zero: a value held constant beyond the ends joins the interpolant C¹. */
    flat
  };

  /** The Hermite slopes @p m of the @p n ≥ 2 nodes (@p x increasing, @p y) (see above). */
  void
  hermite_slopes(const double *x, const double *y, std::size_t n, HermiteEnds ends, double *m);

  /**
   * The Hermite cubic between nodes 0 and 1 of (@p x, @p y, @p m) at @p t ∈ [0, 1]
   * (t = (x − x0)/(x1 − x0)): its value @p yt and derivative @p dy = dy/dx.
   */
  void
  hermite(const double *x, const double *y, const double *m, double t, double &yt, double &dy);

  /**
   * The interpolant of the @p n nodes at @p xq: the Hermite cubic inside [x_0, x_{n−1}],
   * beyond it the line of the end slope (in the tables' logarithmic variables: a power
   * law). Value @p yq and slope @p dy; returns −1 below x_0, +1 above x_{n−1}, else 0.
   */
  int
  hermite_interpolate(const double *x,
                      const double *y,
                      const double *m,
                      std::size_t   n,
                      double        xq,
                      double       &yq,
                      double       &dy);
} // namespace wearlink::contact
