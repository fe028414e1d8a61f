// SPDX-License-Identifier: LGPL-2.1-or-later
// The elastic normal force of a clearance joint against the approach δ, tabulated from
// a model of the actual pin and bushing (the FE model: fe/fe_normal_force_law.h) and
// evaluated between and beyond the table.
//
// Layout: K load levels F_0 < … < F_{K−1} [N], shared by every direction, and per
// contact direction the approach δ_k at which the elastic force is F_k. Directions are
// n_b bushing-frame angles ψ_b,i = 2πi/n_b times n_p pin-frame angles ψ_p,j = 2πj/n_p
// (n_b = n_p = 1: the pair is round and the table direction-independent).
//
// Evaluation at (δ, ψ_b, ψ_p):
//  1. per table direction, in x = ln δ, y = ln F, a monotone cubic Hermite interpolant
//     of (ln δ_k, ln F_k) (Fritsch–Carlson / Brodlie slopes: the weighted harmonic mean
//     of the neighbouring secants; three-point slopes at the ends, kept within
//     [d/2, 3d] of the end secant d): F_ij(δ) is C¹ and increasing, so error-controlled
//     integrators see no kinks;
//  2. outside [δ_0, δ_{K−1}] of a direction, the power law F = F_end (δ/δ_end)^m with
//     the interpolant's end slope m (C¹ across the end; F → 0 as δ → 0);
//  3. between directions, F = Σ w_ij F_ij(δ) with the bilinear, periodic weights of the
//     four surrounding directions — a positive combination of C¹ increasing functions,
//     so still C¹ and increasing in δ.
// Each evaluation reports whether a direction it used was extrapolated, for the joint's
// counters. The potential V(δ) = ∫₀^δ F ds is exact for the power laws and by 8-point
// Gauss–Legendre quadrature (in x) inside, with the node values precomputed.
// Every per-direction curve is set up at construction: an evaluation allocates nothing.
#pragma once

#include <cstddef>
#include <vector>

namespace wearlink::contact
{
  class ForceApproachTable
  {
  public:
    /** Where an evaluation fell. */
    enum class Region
    {
      below, ///< δ < δ_0: power-law extrapolation to zero force
      table, ///< inside the table
      above  ///< δ > δ_{K−1}: power-law extrapolation beyond the largest load
    };

    struct Value
    {
      double force     = 0; ///< F [N]
      double stiffness = 0; ///< dF/dδ [N/m]
      Region region    = Region::table;
    };

    ForceApproachTable() = default;

    /**
     * @p forces: K ≥ 2 increasing positive load levels [N]; @p approach: n_bore × n_pin × K
     * values [m], direction (i, j) at (i n_pin + j) K, each run positive and strictly
     * increasing. InputError otherwise.
     */
    ForceApproachTable(std::vector<double> forces,
                       unsigned int        n_bore,
                       unsigned int        n_pin,
                       std::vector<double> approach);

    bool
    empty() const
    {
      return levels.empty();
    }
    unsigned int
    n_levels() const
    {
      return static_cast<unsigned int>(levels.size());
    }
    unsigned int
    n_bore_directions() const
    {
      return n_b;
    }
    unsigned int
    n_pin_directions() const
    {
      return n_p;
    }
    const std::vector<double> &
    forces() const
    {
      return levels;
    }
    const std::vector<double> &
    approaches() const
    {
      return delta;
    }

    /** Elastic force at approach @p approach > 0 [m] in the given direction [rad]. */
    Value
    evaluate(double approach, double bore_angle, double pin_angle) const;

    /** ∫₀^δ F ds [J] in the given direction. */
    double
    potential(double approach, double bore_angle, double pin_angle) const;

  private:
    std::vector<double> levels; ///< F_k [N]
    unsigned int        n_b = 0, n_p = 0;
    std::vector<double> delta; ///< δ [m], see the constructor
    /** Per direction d, node k at d K + k: ln δ, ln F, the Hermite slope dy/dx, V(δ_k). */
    std::vector<double> x, y, m, v;

    struct DirectionValue
    {
      double force = 0, stiffness = 0;
      int    region = 0; ///< −1 below, 0 inside, +1 above
    };
    DirectionValue
    evaluate_direction(std::size_t d, double approach) const;
    double
    potential_direction(std::size_t d, double approach) const;
    /** The up to four directions around (ψ_b, ψ_p) and their weights. */
    unsigned int
    neighbours(double bore_angle, double pin_angle, std::size_t (&d)[4], double (&w)[4]) const;
  };
} // namespace wearlink::contact
