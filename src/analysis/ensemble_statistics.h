// SPDX-License-Identifier: LGPL-2.1-or-later
// Ensembles: N runs of one scene that differ only by a physically tiny
// perturbation of the initial conditions sample the chaos of the clearance dynamics;
// their spread is the floor below which no figure of a single run means anything.
//
//  - member_normals(): the perturbation's random numbers, reproducible anywhere: member
//    k of seed S draws standard normal numbers by Box–Muller from std::mt19937_64 seeded
//    through std::seed_seq{S mod 2³², S / 2³², k} (both engine and seed sequence are
//    specified by the C++ standard, unlike std::normal_distribution), so a member's
//    perturbation depends on S and k only — not on the rank that runs it or on the
//    number of ranks.
//  - ensemble_figure(): mean, sample standard deviation (n − 1) and the 95 % confidence
//    interval of the mean, mean ± t(0.975, n − 1) s/√n with Student's t for n members
//    (boost::math; t = 12.706 for 2 members, 2.365 for 8, → 1.960).
//  - percentile(): P_p of the members by linear interpolation between the order
//    statistics (Hyndman & Fan's type 7, the default of R and NumPy): with the values
//    sorted x_1 ≤ … ≤ x_n and h = (n − 1) p, P_p = x_{⌊h⌋+1} + (h − ⌊h⌋)(x_{⌊h⌋+2} − x_{⌊h⌋+1});
//    P_0 the smallest, P_1 the largest value. For 4 members P10 = x_1 + 0.3 (x_2 − x_1).
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace wearlink::analysis
{
  /** The quantile t of Student's t distribution with @p dof > 0 degrees of freedom: P(T ≤ t) = @p p. */
  double
  student_t_quantile(double p, double dof);

  /** Statistics of one figure over the members that have it. */
  struct EnsembleFigure
  {
    double      mean      = 0;
    double      std       = 0; ///< sample standard deviation (n − 1); NaN for one member
    double      ci95_low  = 0; ///< 95 % confidence interval of the mean (Student t); NaN for one member
    double      ci95_high = 0;
    std::size_t members   = 0; ///< how many values (the finite ones) entered
  };

  /** The statistics of the finite values of @p values (at least one). */
  EnsembleFigure
  ensemble_figure(const std::vector<double> &values);

  /**
   * Per figure name, the statistics over @p members (each a map figure → value; a
   * member without a figure, or with a non-finite value, does not count for it).
   */
  std::map<std::string, EnsembleFigure>
  ensemble_figures(const std::vector<std::map<std::string, double>> &members);

  /**
   * The @p p-quantile (0 ≤ p ≤ 1) of the finite @p values, type 7 (see above); NaN
   * without a finite value.
   */
  double
  percentile(std::vector<double> values, double p);

  /** @p count standard normal numbers of member @p member of seed @p seed (see above). */
  std::vector<double>
  member_normals(std::uint64_t seed, unsigned int member, unsigned int count);
} // namespace wearlink::analysis
