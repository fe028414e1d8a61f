// SPDX-License-Identifier: LGPL-2.1-or-later
// The input values of ensemble members (analysis/input_distributions.h):
//  - the mapping: over the first 2^12 members (Sobol points, digitally shifted by the
//    seed, through the inverse CDFs) each input's sample mean and standard deviation are
//    within 4 standard errors of plain Monte Carlo of the analytic values (σ/√n for the
//    mean, σ √(κ − 1) / (2 √n) for the standard deviation with κ the kurtosis; the
//    low-discrepancy points do better, while a wrong parametrisation — σ² for σ, the mean
//    for the median — misses by far more); a truncated normal stays within its bounds;
//  - reproducibility: member k's values depend on the seed and k only, not on the number
//    of members; another seed gives other values; a Saltelli layout needs a member count
//    that is a multiple of d + 2 and reproduces SaltelliDesign's points.
#include "analysis/input_distributions.h"
#include "base/exceptions.h"

#include <gtest/gtest.h>

#include <boost/math/distributions/normal.hpp>
#include <cmath>

using namespace wearlink::analysis;

namespace
{
  UncertaintySettings
  four_inputs(const std::uint64_t seed)
  {
    UncertaintySettings s;
    s.seed   = seed;
    s.inputs = {{"Joint A/Clearance/archard/Pin wear coefficient", InputDistribution::lognormal(4.6e-14, 0.3)},
                {"Joint A/Clearance/modified-coulomb/Friction coefficient", InputDistribution::uniform(0.1, 0.2)},
                {"Joint A/Clearance/Radial clearance", InputDistribution::truncated_normal(2e-4, 2e-6, 2e-4, 2.055e-4)},
                {"Body 1/Mass", InputDistribution::normal(1.5, 0.05)}};
    return s;
  }

  /** Mean and standard deviation of the truncated normal (μ, σ) on [a, b]. */
  std::pair<double, double>
  truncated_moments(const double mu, const double s, const double a, const double b)
  {
    const boost::math::normal n;
    const double              al = (a - mu) / s, be = (b - mu) / s;
    const double              Z  = boost::math::cdf(n, be) - boost::math::cdf(n, al);
    const double              pa = boost::math::pdf(n, al), pb = boost::math::pdf(n, be);
    const double              r = (pa - pb) / Z;
    return {mu + s * r, s * std::sqrt(1 + (al * pa - be * pb) / Z - r * r)};
  }
} // namespace

TEST(InputDistributions, SobolMembersReproduceEachDistributionsMeanAndStd)
{
  const auto                       settings = four_inputs(7);
  const unsigned int               n        = 1u << 12;
  std::vector<std::vector<double>> x(4);
  for (unsigned int k = 0; k < n; ++k)
    {
      const auto v = member_inputs(settings, InputSampling::sobol, n, k);
      for (int i = 0; i < 4; ++i)
        x[i].push_back(v[i]);
    }
  const double s2 = 0.3 * 0.3, e = std::exp(s2);
  const auto   tn = truncated_moments(2e-4, 2e-6, 2e-4, 2.055e-4);
  // Analytic mean, std and kurtosis (for the tolerance; 3 for the normal, 1.8 uniform).
  const double exact[4][3] = {{4.6e-14 * std::exp(s2 / 2),
                               4.6e-14 * std::sqrt((e - 1) * e),
                               e * e * e * e + 2 * e * e * e + 3 * e * e - 3},
                              {0.15, 0.1 / std::sqrt(12.0), 1.8},
                              {tn.first, tn.second, 3},
                              {1.5, 0.05, 3}};
  for (int i = 0; i < 4; ++i)
    {
      double mean = 0, var = 0;
      for (const double v : x[i])
        mean += v / n;
      for (const double v : x[i])
        var += (v - mean) * (v - mean) / (n - 1);
      const double sd = exact[i][1];
      EXPECT_NEAR(mean, exact[i][0], 4 * sd / std::sqrt(double(n))) << settings.inputs[i].entry;
      EXPECT_NEAR(std::sqrt(var), sd, 4 * sd * std::sqrt(exact[i][2] - 1) / (2 * std::sqrt(double(n))))
        << settings.inputs[i].entry;
    }
  for (const double v : x[2])
    {
      ASSERT_GE(v, 2e-4);
      ASSERT_LE(v, 2.055e-4);
    }
}

TEST(InputDistributions, MemberValuesDependOnTheSeedAndTheIndexOnly)
{
  const auto settings = four_inputs(3);
  for (const unsigned int k : {0u, 1u, 5u, 17u})
    {
      const auto few = member_inputs(settings, InputSampling::sobol, 20, k);
      EXPECT_EQ(few, member_inputs(settings, InputSampling::sobol, 1000, k)) << "member " << k;
      EXPECT_EQ(few, member_inputs(four_inputs(3), InputSampling::sobol, 2, k)) << "member " << k;
      EXPECT_NE(few, member_inputs(four_inputs(4), InputSampling::sobol, 20, k)) << "another seed";
    }
  EXPECT_NE(member_inputs(settings, InputSampling::sobol, 8, 0), member_inputs(settings, InputSampling::sobol, 8, 1));
  // A Saltelli layout: N = n (d + 2) members, member k = design point k.
  EXPECT_THROW(member_inputs(settings, InputSampling::saltelli, 10, 0), wearlink::InputError);
  const auto design = member_design(settings, 12);
  EXPECT_EQ(design.n_base(), 2u);
  EXPECT_EQ(member_inputs(settings, InputSampling::saltelli, 12, 9), design.point(9));
  UncertaintySettings none;
  EXPECT_THROW(member_inputs(none, InputSampling::sobol, 4, 0), wearlink::InputError);
}
