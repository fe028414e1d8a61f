// SPDX-License-Identifier: LGPL-2.1-or-later
// The response criterion of a life run decided on its trend (analysis/life_criteria.h),
// on synthetic measurements with a known answer — no simulation. The series here are
// lines; the line is the model BIC chooses for them (analysis/response_models.h) and the
// line's statements are those the criterion had before it chose among models:
//  - a linear trend y = a + b N (a = 100 m/s², b = 0.0025 m/s² per revolution: the rise
//    reaches 25 % at N* = 0.25 a / b = 10,000 revolutions) plus normal scatter of known
//    σ = 5 m/s², measured at 0, 500, …, 20,000 revolutions (41 points; seeded normals of
//    analysis::member_normals). The 95 % interval of the crossing must cover N* in at
//    least 90 % of 40 cases (its nominal coverage is 95 %: 38 of 40 expected; below 36,
//    the interval is too narrow), and its mean width must be that of the delta method's
//    standard error of N̂ = 0.25 â / b̂, 2 t(0.975, 39) SE, within 20 % (Fieller's interval is
//    slightly asymmetric; a band with the wrong variance misses by far more);
//  - the interval's ends are where the band's bounds of the rise cross the limit;
//  - pure noise (no trend), or a trend of 3 measurements however steep, is not decided,
//    and an undecided criterion is never the life, however early its line crosses.
#include "analysis/ensemble_statistics.h"
#include "analysis/life_criteria.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

using namespace wearlink::analysis;

namespace
{
  constexpr double fresh = 100, slope = 0.0025, sigma = 5, limit = 25; // m/s², m/s²/rev, m/s², %
  constexpr double true_crossing = 0.25 * fresh / slope;               // 10,000 rev
  constexpr double tolerance     = 0.5;                                // Life/Response tolerance's default

  /** Case @p k: the 41 measurements at 0 … 20,000 rev of the line of slope @p b plus @p s z. */
  ResponseModels
  noisy_trend(const unsigned int k, const double b = slope, const double s = sigma)
  {
    const auto          z = member_normals(2024, k, 41);
    std::vector<double> revolutions, measures;
    for (int i = 0; i <= 40; ++i)
      {
        revolutions.push_back(500.0 * i);
        measures.push_back(fresh + b * revolutions.back() + s * z[i]);
      }
    return {revolutions, measures, revolutions.size()};
  }

  /**
   * The delta method's standard error of N̂ = ℓ â / b̂ [rev] for the design above, from
   * the true line: Var(â) = σ² (1/n + x̄²/Sxx), Var(b̂) = σ²/Sxx, Cov = −σ² x̄/Sxx.
   */
  double
  delta_standard_error()
  {
    const double n = 41, x_mean = 10000, sxx = 250000.0 * 5740; // Σ (500 (i − 20))², i = 0 … 40
    const double var_a = sigma * sigma * (1 / n + x_mean * x_mean / sxx), var_b = sigma * sigma / sxx;
    const double cov = -sigma * sigma * x_mean / sxx;
    return true_crossing * std::sqrt(var_a / (fresh * fresh) + var_b / (slope * slope) - 2 * cov / (fresh * slope));
  }
} // namespace

TEST(TrendCriterion, TheCrossingIntervalCoversTheTrueCrossing)
{
  int    decided = 0, covered = 0, line = 0;
  double width = 0;
  for (unsigned int k = 0; k < 40; ++k)
    {
      const auto models = noisy_trend(k);
      line += models.chosen() == TrendFamily::line;
      const auto x = trend_crossing(models, TrendFamily::line, limit, 20000, tolerance);
      EXPECT_EQ(trend_crossing(models, limit, 20000, tolerance).status, CriterionStatus::decided)
        << "on the chosen model (" << family_name(models.chosen()) << ") too";
      if (x.status != CriterionStatus::decided)
        continue;
      ++decided;
      covered += x.interval.low <= true_crossing && true_crossing <= x.interval.high ? 1 : 0;
      width += x.interval.high - x.interval.low;
      EXPECT_TRUE(x.reached);
      EXPECT_LT(x.interval.low, x.revolutions);
      EXPECT_GT(x.interval.high, x.revolutions);
    }
  // At 20,000 rev the true rise is 50 %, 9 standard errors above the limit: each case is
  // reached, and the expected width (~0.28 N*) is well within the tolerance 0.5.
  ASSERT_EQ(decided, 40) << "the criterion is not decided on a clear trend";
  EXPECT_GE(line, 36) << "BIC chooses the line for a line (measured 394 of 400 replicates in response_models_test)";
  EXPECT_GE(covered, 0.9 * decided) << covered << " of " << decided << " intervals cover " << true_crossing;
  const double expected = 2 * student_t_quantile(0.975, 39) * delta_standard_error();
  std::cout << "[trend] " << decided << " of 40 decided, " << covered << " cover the true crossing; mean width "
            << width / decided << " rev, delta method " << expected << " rev\n";
  EXPECT_NEAR(width / decided, expected, 0.2 * expected) << "mean width of the 95 % interval [rev]";
}

TEST(TrendCriterion, TheIntervalEndsAreWhereTheBandCrossesTheLimit)
{
  const auto   trend    = noisy_trend(3);
  const auto   line     = TrendFamily::line;
  const auto   interval = trend.crossing_interval(line, limit);
  const double crossing = trend.model(line).crossing(limit);
  ASSERT_TRUE(interval.bounded());
  EXPECT_NEAR(trend.model(line).rise(crossing), limit, 1e-9) << "the line crosses the limit at N̂";
  // At the high end the lower bound of the rise is the limit; at the low end the upper.
  EXPECT_NEAR(trend.rise_interval(line, interval.high).low, limit, 1e-6);
  EXPECT_NEAR(trend.rise_interval(line, interval.low).high, limit, 1e-6);
  EXPECT_NEAR(trend.excess_band(line, interval.high, limit).low, 0, 1e-9 * fresh);
  // Between them the band contains the limit: undecided there.
  const double middle = 0.5 * (interval.low + interval.high);
  EXPECT_EQ(trend_crossing(trend, line, limit, middle, tolerance).status, CriterionStatus::undecided);
  EXPECT_FALSE(trend_crossing(trend, line, limit, middle, tolerance).reason.empty());
}

TEST(TrendCriterion, PureNoiseOrTooFewPointsIsNeverTheLife)
{
  // No trend (b = 0) under the nine-bar's scatter (18 %): the rise at the end, 0 with a
  // standard error of ~10 %, would have to read ~45 % for its lower 95 % bound to reach
  // 25 % (4 standard errors: p ~ 3e-5 per case) — while one sample of 41 is above
  // 125 m/s² (+25 %, 1.4 σ) with p = 8 % each. None of 40 is decided.
  int decided = 0, samples_above = 0;
  for (unsigned int k = 0; k < 40; ++k)
    {
      decided += trend_crossing(noisy_trend(k, 0.0, 18), limit, 20000, tolerance).status == CriterionStatus::decided;
      for (const double z : member_normals(2024, k, 41))
        samples_above += 18 * z > 25;
    }
  EXPECT_EQ(decided, 0);
  EXPECT_GT(samples_above, 0) << "a one-sample criterion would have been reached";
  // ±2 % alternating about a flat line (the slope is exactly 0): the 95 % interval of the
  // rise at the end, about ±5 %, is below 25 %: not reached.
  std::vector<double> revolutions, flat;
  for (int i = 0; i <= 10; ++i)
    {
      revolutions.push_back(2000.0 * i);
      flat.push_back(i % 2 ? 102 : 98);
    }
  const auto none = trend_crossing(ResponseModels(revolutions, flat, 11), limit, 20000, tolerance);
  EXPECT_EQ(none.status, CriterionStatus::not_reached) << none.reason;
  // Three measurements rising by 60 % and 120 %: a steep trend, but not yet a trend.
  const auto few = trend_crossing(ResponseModels({0, 1000, 2000}, {100, 160, 220}, 3), limit, 2000, tolerance);
  EXPECT_EQ(few.status, CriterionStatus::undecided);
  EXPECT_NE(few.reason.find("counts from 4"), std::string::npos) << few.reason;

  // The life is the decided criterion with the fewest revolutions: the wear depth at
  // 50,000 rev, not the undecided response whose line crosses at 3,000.
  const std::vector<CriterionOutcome> outcomes = {{CriterionStatus::decided, 50000},
                                                  {CriterionStatus::undecided, 3000},
                                                  {CriterionStatus::not_reached, NAN}};
  EXPECT_EQ(headline_criterion(outcomes), std::optional<std::size_t>(0));
  EXPECT_FALSE(headline_criterion({{CriterionStatus::undecided, 3000}}).has_value()) << "no life at all";
  EXPECT_EQ(headline_criterion({{CriterionStatus::decided, 50000}, {CriterionStatus::decided, 3000}}),
            std::optional<std::size_t>(1));
}

TEST(TrendCriterion, AMeasurementRepeatedAtTheSameRevolutionsCountsOnce)
{
  // An iteration that wore nothing measures the same profiles again: the same number.
  const ResponseModels once({0, 1000, 2000, 3000}, {100, 120, 105, 125}, 4);
  const ResponseModels twice({0, 1000, 2000, 2000, 3000}, {100, 120, 105, 105, 125}, 5);
  EXPECT_EQ(twice.points(), 4u);
  EXPECT_DOUBLE_EQ(twice.model(TrendFamily::line).fit.beta, once.model(TrendFamily::line).fit.beta);
  EXPECT_DOUBLE_EQ(twice.residual_std(TrendFamily::line), once.residual_std(TrendFamily::line));
  EXPECT_FALSE(twice.has(TrendFamily::step)) << "a step needs 5 measurements";
}
