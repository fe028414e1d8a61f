// SPDX-License-Identifier: LGPL-2.1-or-later
// Ensemble statistics (analysis/ensemble_statistics.h): Student's t quantiles against
// the printed table (Fisher & Yates; any statistics text): t(0.975) = 12.706 for 1
// degree of freedom, 4.303 for 2, 2.776 for 4, 2.262 for 9, 2.045 for 29, → 1.960; the
// mean, sample standard deviation and interval of a known sample; and the coverage of
// the 95 % interval over many small samples of the members' own normal numbers, which
// must be 95 % — with the normal quantile 1.96 instead of Student's it would be 88 % for
// 5 members.
#include "analysis/ensemble_statistics.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace wearlink::analysis;

TEST(EnsembleStatistics, StudentQuantilesMatchTheTable)
{
  // The table's values are rounded to 3 decimals: ±5e-4.
  const std::pair<double, double> table[] =
    {{1, 12.706}, {2, 4.303}, {4, 2.776}, {9, 2.262}, {29, 2.045}, {1e6, 1.960}};
  for (const auto &[dof, t] : table)
    EXPECT_NEAR(student_t_quantile(0.975, dof), t, 5e-4) << dof << " degrees of freedom";
}

TEST(EnsembleStatistics, MeanStdAndIntervalOfAKnownSample)
{
  // 2, 4, 4, 5: mean 3.75, squares about the mean 4.75, s = √(4.75/3) = 1.2583;
  // half-width t(0.975, 3) s/√4 = 3.1824 × 1.2583/2 = 2.0022.
  const auto f = ensemble_figure({2, 4, 4, 5, std::nan("")});
  EXPECT_EQ(f.members, 4u) << "the NaN is not a member's value";
  EXPECT_DOUBLE_EQ(f.mean, 3.75);
  EXPECT_NEAR(f.std, std::sqrt(4.75 / 3), 1e-14);
  EXPECT_NEAR(f.ci95_high - f.mean, 3.182446 * std::sqrt(4.75 / 3) / 2, 1e-5);
  EXPECT_NEAR(f.mean - f.ci95_low, f.ci95_high - f.mean, 1e-14);
  const auto one = ensemble_figure({7});
  EXPECT_EQ(one.mean, 7);
  EXPECT_TRUE(std::isnan(one.std) && std::isnan(one.ci95_low)) << "one member has no spread";
}

TEST(EnsembleStatistics, MemberNormalsAreReproducibleAndStandardNormal)
{
  EXPECT_EQ(member_normals(42, 3, 5), member_normals(42, 3, 5));
  EXPECT_NE(member_normals(42, 3, 5), member_normals(42, 4, 5)) << "members differ";
  EXPECT_NE(member_normals(42, 3, 5), member_normals(43, 3, 5)) << "seeds differ";
  EXPECT_EQ(member_normals(42, 3, 2)[1], member_normals(42, 3, 5)[1]) << "a prefix of the same stream";
  // 1e5 draws: mean within 4 standard errors (4/√1e5 = 0.013) of 0, variance within
  // 4 √(2/1e5) = 0.018 of 1.
  const auto z   = member_normals(1, 0, 100000);
  double     sum = 0, squares = 0;
  for (const double v : z)
    {
      sum += v;
      squares += v * v;
    }
  EXPECT_NEAR(sum / z.size(), 0, 0.013);
  EXPECT_NEAR(squares / z.size(), 1, 0.018);
}

TEST(EnsembleStatistics, TheIntervalCoversTheMeanNineteenTimesInTwenty)
{
  // 4000 samples of 5 members (N(0, 1), mean 0): the fraction of intervals holding 0 is
  // binomial around 0.95 with a standard deviation √(0.95 × 0.05 / 4000) = 0.0034;
  // accept 0.95 ± 4 of those. The normal quantile (1.96) would cover 0.88.
  unsigned int covered = 0;
  const int    samples = 4000;
  for (int k = 0; k < samples; ++k)
    {
      const auto f = ensemble_figure(member_normals(2024, k, 5));
      covered += f.ci95_low <= 0 && 0 <= f.ci95_high ? 1 : 0;
    }
  EXPECT_NEAR(double(covered) / samples, 0.95, 4 * 0.0034);
}

// Percentiles of type 7 (linear interpolation between the order statistics; R's and
// NumPy's default): for 1, 2, 3, 4 (in any order) h = 3 p, so P10 = 1 + 0.3 = 1.3,
// P50 = 2.5, P90 = 3 + 0.7 = 3.7 (numpy.percentile gives the same); P0 and P100 are the
// extremes, one value is every percentile, NaN is no value.
TEST(EnsembleStatistics, PercentilesInterpolateBetweenOrderStatistics)
{
  const std::vector<double> v = {4, 1, std::nan(""), 3, 2};
  EXPECT_DOUBLE_EQ(percentile(v, 0.1), 1.3);
  EXPECT_DOUBLE_EQ(percentile(v, 0.5), 2.5);
  EXPECT_DOUBLE_EQ(percentile(v, 0.9), 3.7);
  EXPECT_EQ(percentile(v, 0), 1);
  EXPECT_EQ(percentile(v, 1), 4);
  EXPECT_EQ(percentile({7}, 0.1), 7);
  EXPECT_TRUE(std::isnan(percentile({}, 0.5)));
}
