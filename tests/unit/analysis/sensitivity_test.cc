// SPDX-License-Identifier: LGPL-2.1-or-later
// Global sensitivity analysis (analysis/sensitivity.h) against analytic values:
//  - Sobol points: point n equals the n-th of a sequence drawn from the start (Boost's
//    own engine, drawn in order), whatever was drawn before; a digital shift keeps the
//    stratification of every coordinate;
//  - inverse CDFs: the sample mean and variance of each distribution against its
//    formulas;
//  - the Ishigami function f = sin x1 + a sin² x2 + b x3⁴ sin x1, x_i ~ U(−π, π), a = 7,
//    b = 0.1 (Ishigami & Homma 1990), whose variance splits analytically:
//      V   = a²/8 + b π⁴/5 + b² π⁸/18 + 1/2          = 13.8446
//      V1  = (1 + b π⁴/5)² / 2                        =  4.3459
//      V2  = a²/8                                     =  6.1250
//      V13 = b² π⁸ (1/18 − 1/50) = 8 b² π⁸ / 225      =  3.3737,  V3 = V12 = V23 = V123 = 0
//    so S1 = 0.3139, S2 = 0.4424, S3 = 0, ST1 = 0.5576, ST2 = 0.4424, ST3 = 0.2437;
//  - a linear model, whose indices are the variance shares c_i² Var x_i / Σ c_j² Var x_j;
//  - rank correlations: exactly ±1 for a monotone function, and a hand-computed case.
#include "analysis/sensitivity.h"
#include "base/exceptions.h"
#include "base/numbers.h"

#include <gtest/gtest.h>

#include <boost/math/distributions/normal.hpp>
#include <boost/random/sobol.hpp>
#include <cmath>
#include <iostream>

using namespace wearlink::analysis;
using wearlink::numbers::pi;

namespace
{
  struct Moments
  {
    double mean = 0, variance = 0;
  };

  Moments
  moments(const std::vector<double> &x)
  {
    Moments m;
    for (const double v : x)
      m.mean += v / x.size();
    for (const double v : x)
      m.variance += (v - m.mean) * (v - m.mean) / x.size();
    return m;
  }

  /** The analytic Ishigami indices (see the top of the file). */
  struct IshigamiTruth
  {
    double first[3], total[3];
  };

  IshigamiTruth
  ishigami_truth(const double a, const double b)
  {
    const double pi4 = std::pow(pi, 4), pi8 = std::pow(pi, 8);
    const double V   = a * a / 8 + b * pi4 / 5 + b * b * pi8 / 18 + 0.5;
    const double V1  = 0.5 * (1 + b * pi4 / 5) * (1 + b * pi4 / 5);
    const double V2  = a * a / 8;
    const double V13 = 8 * b * b * pi8 / 225;
    return {{V1 / V, V2 / V, 0.0}, {(V1 + V13) / V, V2 / V, V13 / V}};
  }

  /** The Ishigami design at N = 2^12 and its indices, computed once for the tests below. */
  const SensitivityResult &
  ishigami_indices()
  {
    static const SensitivityResult result = [] {
      const auto          u = InputDistribution::uniform(-pi, pi);
      SaltelliDesign      design({u, u, u}, 4096);
      std::vector<double> y;
      for (const auto &x : design.points())
        y.push_back(std::sin(x[0]) + 7 * std::pow(std::sin(x[1]), 2) + 0.1 * std::pow(x[2], 4) * std::sin(x[0]));
      return analyse_sensitivity(design, y);
    }();
    return result;
  }
} // namespace

TEST(Sensitivity, SobolPointsAreIndependentOfThoseDrawnBefore)
{
  const SobolSequence sequence(6);
  const auto          drawn = sequence.points(0, 200);
  // Boost's engine drawn in order from a fresh start: the same points.
  boost::random::sobol fresh(6);
  for (std::size_t n = 0; n < drawn.size(); ++n)
    for (unsigned int c = 0; c < 6; ++c)
      ASSERT_EQ(drawn[n][c], (static_cast<double>(fresh() >> 11) + 0.5) * 0x1.0p-53) << "point " << n << " coord " << c;
  // Point n alone, in any order, after any other points.
  for (const std::uint64_t n : {199u, 0u, 64u, 63u, 1u, 128u})
    EXPECT_EQ(sequence.point(n), drawn[n]) << "point " << n;
  EXPECT_EQ(SobolSequence(6, 10).point(5), drawn[15]) << "a skip of 10 starts at point 10";
  // The first point is the centre of the cube (Boost starts after the origin), the
  // next two the centres of the halves in the first coordinate.
  for (const double c : drawn[0])
    EXPECT_NEAR(c, 0.5, 1e-15);
  EXPECT_NEAR(drawn[1][0], 0.75, 1e-15);
  EXPECT_NEAR(drawn[2][0], 0.25, 1e-15);
}

TEST(Sensitivity, PlainAndShiftedPointsKeepTheirStratification)
{
  const SobolSequence plain(4), shifted(4, 0, 12345), again(4, 0, 12345);
  EXPECT_EQ(shifted.point(7), again.point(7)) << "the same seed, the same points";
  EXPECT_NE(shifted.point(7), plain.point(7));
  // A Sobol coordinate is a (0, 1)-sequence in base 2: its first 2^k points, the origin
  // included, fall one into each interval [m/2^k, (m+1)/2^k). Boost leaves the origin
  // out, so its first 2^k − 1 points must hit 2^k − 1 different intervals. XOR with a
  // fixed mask permutes those intervals: a shifted sequence must do the same.
  const unsigned int k = 8, n = 1u << k;
  for (const auto *sequence : {&plain, &shifted})
    {
      const auto p = sequence->points(0, n - 1);
      for (unsigned int c = 0; c < 4; ++c)
        {
          std::vector<int> hits(n, 0);
          for (const auto &x : p)
            ++hits[static_cast<unsigned int>(x[c] * n)];
          EXPECT_EQ(std::count(hits.begin(), hits.end(), 1), static_cast<long>(n - 1))
            << (sequence == &plain ? "plain" : "shifted") << ", coordinate " << c;
        }
    }
}

TEST(Sensitivity, InverseCdfsReproduceMeanAndVariance)
{
  const boost::math::normal standard;
  const auto                phi = [&](const double z) {
    return boost::math::pdf(standard, z);
  };
  const auto Phi = [&](const double z) {
    return boost::math::cdf(standard, z);
  };
  // Truncated normal, N(μ σ²) on [a, b], α, β the standardised bounds, Z = Φ(β) − Φ(α):
  //   mean μ + σ (φ(α) − φ(β))/Z,  variance σ² [1 + (α φ(α) − β φ(β))/Z − ((φ(α) − φ(β))/Z)²].
  const auto truncated = [&](double mu, double s, double a, double b) {
    const double al = (a - mu) / s, be = (b - mu) / s, Z = Phi(be) - Phi(al);
    const double r = (phi(al) - phi(be)) / Z;
    return Moments{mu + s * r, s * s * (1 + (al * phi(al) - be * phi(be)) / Z - r * r)};
  };
  const double ln_s = 0.4, ln_m = std::log(4.6e-14);
  struct Case
  {
    InputDistribution dist;
    Moments           exact;
    double            fourth_moment; ///< E(X − μ)⁴, for the tolerance
  };
  const double       e2 = std::exp(ln_s * ln_s), var_ln = (e2 - 1) * std::exp(2 * ln_m + ln_s * ln_s);
  const Case         cases[] = {{InputDistribution::normal(0.15, 0.02), {0.15, 4e-4}, 3 * 4e-4 * 4e-4},
                                {InputDistribution::lognormal(4.6e-14, ln_s),
                                 {std::exp(ln_m + ln_s * ln_s / 2), var_ln},
                                 var_ln * var_ln * (e2 * e2 * e2 * e2 + 2 * e2 * e2 * e2 + 3 * e2 * e2 - 3)},
                                {InputDistribution::uniform(0.8, 0.95), {0.875, 0.15 * 0.15 / 12}, std::pow(0.15, 4) / 80},
                                {InputDistribution::truncated_normal(2e-4, 1e-5, 1.89e-4, 2e-4),
                                 truncated(2e-4, 1e-5, 1.89e-4, 2e-4),
                                 0},
                                {InputDistribution::truncated_normal(0, 1, 3, 4), truncated(0, 1, 3, 4), 0}};
  const unsigned int n       = 1u << 14;
  const auto         points  = SobolSequence(std::size(cases)).points(0, n);
  for (std::size_t c = 0; c < std::size(cases); ++c)
    {
      std::vector<double> x;
      for (const auto &p : points)
        x.push_back(cases[c].dist.quantile(p[c]));
      const Moments m = moments(x);
      // Tolerances: 4 standard errors of plain Monte Carlo with n points (σ/√n for the
      // mean, √((μ4 − σ⁴)/n) for the variance); Sobol points integrate these smooth
      // quantile functions with a smaller error, so a correct mapping stays inside while
      // a wrong parameter (σ² for σ, the mean for the median: 8 % here) does not. For a
      // truncated normal |X − μ| ≤ b − a bounds μ4 by (b − a)² σ².
      const double var    = cases[c].exact.variance;
      const double bounds = cases[c].dist.upper - cases[c].dist.lower;
      const double mu4    = cases[c].fourth_moment > 0 ? cases[c].fourth_moment : bounds * bounds * var;
      EXPECT_NEAR(m.mean, cases[c].exact.mean, 4 * std::sqrt(var / n)) << cases[c].dist.describe();
      EXPECT_NEAR(m.variance, var, 4 * std::sqrt((mu4 - var * var) / n)) << cases[c].dist.describe();
      if (cases[c].dist.kind == DistributionKind::truncated_normal)
        {
          EXPECT_GE(*std::min_element(x.begin(), x.end()), cases[c].dist.lower) << cases[c].dist.describe();
          EXPECT_LE(*std::max_element(x.begin(), x.end()), cases[c].dist.upper) << cases[c].dist.describe();
        }
    }
  EXPECT_NEAR(InputDistribution::normal(1, 2).quantile(0.975), 1 + 2 * 1.959963984540054, 1e-12);
}

TEST(Sensitivity, DistributionsRefuseImpossibleParameters)
{
  EXPECT_THROW(InputDistribution::normal(1, 0), wearlink::InputError);
  EXPECT_THROW(InputDistribution::lognormal(-1, 0.4), wearlink::InputError);
  EXPECT_THROW(InputDistribution::uniform(2, 1), wearlink::InputError);
  EXPECT_THROW(InputDistribution::truncated_normal(0, 1, 40, 41), wearlink::InputError) << "no mass in [40σ, 41σ]";
  EXPECT_THROW(InputDistribution::normal(std::nan(""), 1), wearlink::InputError);
}

TEST(Sensitivity, SaltelliRowsCombineTheTwoHalvesOfASobolPoint)
{
  const auto     u = InputDistribution::uniform(0, 1);
  SaltelliDesign design({u, u, u}, 8);
  EXPECT_EQ(design.n_points(), 8u * 5u);
  const auto all = design.points();
  for (std::uint64_t j = 0; j < 8; ++j)
    {
      const auto &a = all[j * 5], &b = all[j * 5 + 1];
      const auto  sobol = SobolSequence(6).point(j);
      for (unsigned int c = 0; c < 3; ++c)
        {
          EXPECT_EQ(a[c], sobol[c]);
          EXPECT_EQ(b[c], sobol[3 + c]);
        }
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int c = 0; c < 3; ++c)
          EXPECT_EQ(all[j * 5 + 2 + i][c], c == i ? b[c] : a[c]) << "A_B^(" << i << ") row " << j;
    }
  // Any point alone equals its place in the whole design (points spread over ranks).
  for (std::uint64_t k = design.n_points(); k-- > 0;)
    EXPECT_EQ(design.point(k), all[k]) << "design point " << k;
}

TEST(Sensitivity, IshigamiIndicesMatchTheAnalyticValues)
{
  const auto &r     = ishigami_indices();
  const auto  truth = ishigami_truth(7, 0.1);
  ASSERT_EQ(r.method, SensitivityMethod::sobol_indices) << "N = 4096 allows indices";
  EXPECT_EQ(r.samples, 4096u);
  // The required accuracy: within 0.02 at N = 2^12. The bootstrap intervals below, which
  // treat the rows as independent draws, are ±0.015 … ±0.03 around the estimates: plain
  // Monte Carlo rows would miss 0.02 now and then. The Sobol rows do much better
  // (measured: every index within 5e-4), so 0.02 fails any estimator that is wrong in
  // its form, not just noisy.
  for (int i = 0; i < 3; ++i)
    {
      std::cout << "  x" << i + 1 << ": S = " << r.inputs[i].first_order.value << " (analytic " << truth.first[i]
                << ", 95 % " << r.inputs[i].first_order.ci95_low << " … " << r.inputs[i].first_order.ci95_high
                << ")   ST = " << r.inputs[i].total.value << " (analytic " << truth.total[i] << ", 95 % "
                << r.inputs[i].total.ci95_low << " … " << r.inputs[i].total.ci95_high << ")\n";
      EXPECT_NEAR(r.inputs[i].first_order.value, truth.first[i], 0.02) << "S" << i + 1;
      EXPECT_NEAR(r.inputs[i].total.value, truth.total[i], 0.02) << "ST" << i + 1;
    }
  EXPECT_NEAR(truth.first[0], 0.3139, 1e-4) << "the formulas at the top of the file";
  EXPECT_NEAR(truth.total[2], 0.2437, 1e-4);
}

TEST(Sensitivity, BootstrapIntervalsCoverTheAnalyticIshigamiIndices)
{
  const auto &r     = ishigami_indices();
  const auto  truth = ishigami_truth(7, 0.1);
  EXPECT_EQ(r.bootstrap_resamples, 1000u);
  for (int i = 0; i < 3; ++i)
    for (const auto &[e, exact, name] : {std::tuple{r.inputs[i].first_order, truth.first[i], "S"},
                                         std::tuple{r.inputs[i].total, truth.total[i], "ST"}})
      {
        EXPECT_LE(e.ci95_low, exact) << name << i + 1;
        EXPECT_GE(e.ci95_high, exact) << name << i + 1;
        // The bootstrap treats the rows as independent draws, so its interval is about
        // ±2 Monte Carlo standard errors (≤ 0.03 each at N = 4096): wider than 0.15
        // would mean the resampling is broken, and an interval that wide would cover
        // almost anything.
        EXPECT_LT(e.ci95_high - e.ci95_low, 0.15) << name << i + 1;
        EXPECT_TRUE(e.ci95_low <= e.value && e.value <= e.ci95_high) << name << i + 1;
      }
}

TEST(Sensitivity, BootstrapIsReproducibleFromItsSeed)
{
  const auto          u = InputDistribution::uniform(0, 1);
  SaltelliDesign      design({u, u}, 128);
  std::vector<double> y;
  for (const auto &x : design.points())
    y.push_back(x[0] + x[0] * x[1]);
  SensitivitySettings s;
  const auto          a = sobol_indices(2, y, s), b = sobol_indices(2, y, s);
  EXPECT_EQ(a.inputs[1].total.ci95_low, b.inputs[1].total.ci95_low);
  s.bootstrap_seed = 2;
  EXPECT_NE(sobol_indices(2, y, s).inputs[1].total.ci95_low, a.inputs[1].total.ci95_low);
}

TEST(Sensitivity, LinearModelIndicesAreItsVarianceShares)
{
  // y = x1 + x2 + 2 x3: Var x1 = 1 (normal, σ 1), Var x2 = 3 (uniform on [0, 6]),
  // Var x3 = (e^{σ²} − 1) e^{σ²} = 0.36474 (lognormal, median 1, σ 0.5). An additive
  // model has S_i = ST_i = c_i² Var x_i / Σ_j c_j² Var x_j.
  const double        e     = std::exp(0.25);
  const double        v[3]  = {1.0, 3.0, 4 * (e - 1) * e};
  const double        total = v[0] + v[1] + v[2];
  SaltelliDesign      design({InputDistribution::normal(10, 1),
                              InputDistribution::uniform(0, 6),
                              InputDistribution::lognormal(1, 0.5)},
                        4096);
  std::vector<double> y;
  for (const auto &x : design.points())
    y.push_back(x[0] + x[1] + 2 * x[2]);
  const auto r = analyse_sensitivity(design, y);
  for (int i = 0; i < 3; ++i)
    {
      std::cout << "  x" << i + 1 << ": S = " << r.inputs[i].first_order.value << " ("
                << r.inputs[i].first_order.ci95_low << " … " << r.inputs[i].first_order.ci95_high
                << "), ST = " << r.inputs[i].total.value << " (" << r.inputs[i].total.ci95_low << " … "
                << r.inputs[i].total.ci95_high << "), share " << v[i] / total << "\n";
      // 0.01: about one Monte Carlo standard error of these estimators at this N (the
      // bootstrap intervals, which treat the rows as independent draws, are ±0.01 …
      // ±0.03); the Sobol rows do better (measured: within 0.004). Shares that ignored
      // the inputs' distributions (the unit cube's variance 1/12 for each) would be
      // 0.17, 0.17, 0.67: x2 and x3 0.4 off.
      EXPECT_NEAR(r.inputs[i].first_order.value, v[i] / total, 0.01) << "S" << i + 1;
      EXPECT_NEAR(r.inputs[i].total.value, v[i] / total, 0.01) << "ST" << i + 1;
    }
  EXPECT_NEAR(r.output_variance, total, 0.02 * total) << "the output variance, from 8192 Sobol points";
}

TEST(Sensitivity, FewSamplesGiveRankCorrelationsOfAMonotoneFunctionEqualToOne)
{
  const auto          u = InputDistribution::uniform(-1, 2);
  SaltelliDesign      design({u, InputDistribution::normal(0, 1)}, 16);
  std::vector<double> up, down;
  for (const auto &x : design.points())
    {
      up.push_back(std::exp(x[0]));         // increasing in x1, independent of x2
      down.push_back(-std::pow(x[1], 3.0)); // decreasing in x2
    }
  const auto r = analyse_sensitivity(design, up);
  ASSERT_EQ(r.method, SensitivityMethod::rank_correlation) << "16 base samples are below the 64 for indices";
  EXPECT_EQ(method_name(r.method), "rank-correlation");
  EXPECT_EQ(r.samples, 32u) << "the A and B rows";
  EXPECT_DOUBLE_EQ(r.inputs[0].rank_correlation.value, 1.0);
  EXPECT_DOUBLE_EQ(r.inputs[0].rank_correlation.ci95_low, 1.0);
  EXPECT_LT(std::abs(r.inputs[1].rank_correlation.value), 0.5) << "x2 does not enter";
  EXPECT_LT(r.inputs[1].rank_correlation.ci95_low, 0.0);
  EXPECT_GT(r.inputs[1].rank_correlation.ci95_high, 0.0) << "its interval includes 0";
  EXPECT_DOUBLE_EQ(analyse_sensitivity(design, down).inputs[1].rank_correlation.value, -1.0);
  EXPECT_TRUE(std::isnan(r.inputs[0].first_order.value)) << "no indices from 16 samples";
}

TEST(Sensitivity, RankCorrelationOfAHandComputedCase)
{
  // x = 1..5, y = 2 1 4 3 5: Σ d² = 4, ρ = 1 − 6·4/(5·24) = 0.8. Fisher: z = atanh 0.8,
  // se = √(1.06/2), interval tanh(z ∓ 1.96 se) = −0.318 … 0.987.
  const auto r = rank_correlations({{1}, {2}, {3}, {4}, {5}}, {2, 1, 4, 3, 5});
  EXPECT_NEAR(r.inputs[0].rank_correlation.value, 0.8, 1e-14);
  const double z = std::atanh(0.8), se = std::sqrt(1.06 / 2), c = 1.959963984540054;
  EXPECT_NEAR(r.inputs[0].rank_correlation.ci95_low, std::tanh(z - c * se), 1e-12);
  EXPECT_NEAR(r.inputs[0].rank_correlation.ci95_high, std::tanh(z + c * se), 1e-12);
  // Ties share their mean rank: y = 1 1 2 2 has ranks 1.5 1.5 3.5 3.5, and the Pearson
  // correlation of those with 1 2 3 4 is 4/√20.
  EXPECT_NEAR(rank_correlations({{1}, {2}, {3}, {4}}, {1, 1, 2, 2}).inputs[0].rank_correlation.value,
              4 / std::sqrt(20.0),
              1e-14);
}

TEST(Sensitivity, RowsWithAFailedEvaluationAreLeftOut)
{
  const auto          u = InputDistribution::uniform(0, 1);
  SaltelliDesign      design({u, u}, 64);
  std::vector<double> y;
  for (const auto &x : design.points())
    y.push_back(x[0] + 2 * x[1]);
  y[4 * 10 + 2] = std::nan(""); // A_B^(1) of row 10
  const auto r  = sobol_indices(2, y);
  EXPECT_EQ(r.samples, 63u);
  EXPECT_EQ(r.dropped, 1u);
  EXPECT_TRUE(std::isfinite(r.inputs[0].first_order.value));
  EXPECT_THROW(sobol_indices(2, std::vector<double>(7, 1.0)), wearlink::InputError) << "7 is not a multiple of 4";
}
