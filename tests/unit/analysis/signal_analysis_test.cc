// SPDX-License-Identifier: LGPL-2.1-or-later
// The signal comparison of `wearlink compare-signal` (analysis/signal_analysis.h) on
// synthetic signals whose answers are known in closed form:
// - x(t) = 3 + 2 sin(2π 12.3 t) + 0.5 sin(2π 40 t + 0.3), 4 s at 1 kHz: the spectrum's
//   bins are 0.25 Hz apart and 12.3 Hz lies 0.2 bin off one, so the interpolation is
//   tested; dominant frequency 12.3 Hz (to 0.05 Hz, a fifth of a bin), its amplitude 2
//   (to 2 %), the second peak 40 Hz with amplitude 0.5, RMS √(9 + 2 + 0.125) (to 0.1 %:
//   49.2 periods are not a whole number), mean 3;
// - 2 sin(2π 10 t) in cycles of 0.5 s: every cycle's peak is 2 (sampled at its crest);
// - a quasi-periodic sum of 12 incommensurate sines and the same sum delayed by
//   12.34 ms: the lag is recovered to a tenth of a sample, positive for a measured
//   signal that comes later, with correlation ≈ 1.
#include "analysis/signal_analysis.h"
#include "base/exceptions.h"
#include "base/numbers.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <random>

using namespace wearlink::analysis;
using wearlink::numbers::pi;

namespace
{
  UniformSignal
  sampled(const std::function<double(double)> &f, const double dt, const std::size_t n, const double t0 = 0)
  {
    UniformSignal s{t0, dt, std::vector<double>(n)};
    for (std::size_t i = 0; i < n; ++i)
      s.values[i] = f(t0 + i * dt);
    return s;
  }

  double
  two_tones(const double t)
  {
    return 3 + 2 * std::sin(2 * pi * 12.3 * t) + 0.5 * std::sin(2 * pi * 40 * t + 0.3);
  }

  /** A quasi-periodic signal: 12 sines of random frequency 1–60 Hz, amplitude and phase. */
  std::function<double(double)>
  quasi_periodic()
  {
    std::mt19937                           rng(42);
    std::uniform_real_distribution<double> f(1, 60), a(0.2, 1.0), p(0, 2 * pi);
    std::vector<std::array<double, 3>>     tones;
    for (int k = 0; k < 12; ++k)
      {
        const double fk = f(rng), ak = a(rng), pk = p(rng);
        tones.push_back({{fk, ak, pk}});
      }
    return [tones](double t) {
      double x = 0;
      for (const auto &[fk, ak, pk] : tones)
        x += ak * std::sin(2 * pi * fk * t + pk);
      return x;
    };
  }
} // namespace

TEST(SignalAnalysis, RecoversFrequencyAmplitudeMeanAndRmsOfTwoTones)
{
  const auto               s = sampled(two_tones, 1e-3, 4000);
  SignalComparisonSettings settings;
  settings.cycle_period = 0.5;
  const auto f          = signal_features(s, settings);
  ASSERT_GE(f.dominant.size(), 2u);
  EXPECT_NEAR(f.dominant[0].frequency_Hz, 12.3, 0.05);
  EXPECT_NEAR(f.dominant[0].amplitude, 2.0, 0.04);
  EXPECT_NEAR(f.dominant[1].frequency_Hz, 40.0, 0.05);
  EXPECT_NEAR(f.dominant[1].amplitude, 0.5, 0.01);
  EXPECT_NEAR(f.mean, 3.0, 1e-2);
  EXPECT_NEAR(f.rms, std::sqrt(11.125), 1e-3 * std::sqrt(11.125));
  EXPECT_EQ(f.peak_per_cycle.size(), 8u); // 4 s in cycles of 0.5 s
  EXPECT_NEAR(f.frequencies_Hz[1], 0.25, 1e-12);
}

TEST(SignalAnalysis, PeakPerCycleIsTheLargestMagnitudeOfEachWholeCycle)
{
  const auto               s = sampled([](double t) { return 2 * std::sin(2 * pi * 10 * t); }, 1e-3, 2100);
  SignalComparisonSettings settings;
  settings.cycle_period = 0.5;
  const auto f          = signal_features(s, settings);
  ASSERT_EQ(f.peak_per_cycle.size(), 4u); // 2.1 s: four whole cycles, the rest dropped
  for (const double p : f.peak_per_cycle)
    EXPECT_NEAR(p, 2.0, 1e-9);
}

TEST(SignalAnalysis, RecoversAKnownLagAndItsSign)
{
  const auto   x   = quasi_periodic();
  const double dt  = 1e-3;
  const double lag = 12.34e-3;
  const auto   s   = sampled(x, dt, 3000);
  const auto   m   = sampled([&](double t) { return x(t - lag); }, dt, 3000);
  double       r   = 0;
  EXPECT_NEAR(cross_correlation_lag(s, m, 0.1, r), lag, 0.1 * dt);
  EXPECT_GT(r, 0.95);
  EXPECT_NEAR(cross_correlation_lag(m, s, 0.1, r), -lag, 0.1 * dt);
}

TEST(SignalAnalysis, CompareSignalsResamplesOntoTheOverlapAtTheFinerStep)
{
  const auto          x = quasi_periodic();
  std::vector<double> ts, vs, tm, vm;
  const double        lag = 5e-3;
  for (int i = 0; i <= 2000; ++i) // simulated: 0 … 2 s at 1 ms
    {
      ts.push_back(i * 1e-3);
      vs.push_back(x(ts.back()));
    }
  for (int i = 0; i <= 1200; ++i) // measured: 0.1 … 2.5 s at 2 ms, delayed
    {
      tm.push_back(0.1 + i * 2e-3);
      vm.push_back(x(tm.back() - lag));
    }
  SignalComparisonSettings settings;
  settings.cycle_period = 0.25;
  const auto c          = compare_signals(ts, vs, tm, vm, settings);
  EXPECT_NEAR(c.simulated.t0, 0.1, 1e-12);
  EXPECT_NEAR(c.simulated.dt, 1e-3, 1e-12);
  EXPECT_EQ(c.simulated.values.size(), 1901u); // 0.1 … 2.0 s
  EXPECT_EQ(c.measured.values.size(), c.simulated.values.size());
  // Linear interpolation of the 2 ms samples smooths the peaks a little: a fifth of a sample.
  EXPECT_NEAR(c.lag, lag, 0.2e-3);
  EXPECT_NEAR(c.simulated_features.rms, c.measured_features.rms, 0.02 * c.simulated_features.rms);
}

TEST(SignalAnalysis, ResamplingIsExactForALinearSignal)
{
  const std::vector<double> t{0.0, 0.3, 0.35, 1.0}, v{1.0, 1.6, 1.7, 3.0}; // v = 1 + 2t
  const auto                s = resample_uniform(t, v, 0.0, 0.1, 11);
  for (std::size_t i = 0; i < s.values.size(); ++i)
    EXPECT_NEAR(s.values[i], 1 + 2 * 0.1 * i, 1e-12);
}

TEST(SignalAnalysis, SignalsThatBarelyOverlapAreRefused)
{
  const std::vector<double> a{0, 1, 2, 3, 4, 5}, b{4.5, 5.5, 6.5, 7.5, 8.5, 9.5};
  EXPECT_THROW(compare_signals(a, a, b, b, {}), wearlink::EstimationError);
}
