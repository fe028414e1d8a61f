// SPDX-License-Identifier: LGPL-2.1-or-later
// The low-pass filter of the depth increments (Wear/Smoothing wavelength): the volume
// Σ h_k R_k is kept to rounding, also on a worn surface whose radii differ from area to
// area, a sinusoid at the stated wavelength keeps half its amplitude, long waves pass,
// the saw-tooth of neighbouring areas is removed, 0 changes nothing.
#include "base/numbers.h"
#include "wear/wear_loop.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

using wearlink::wear::smoothed;

namespace
{
  using wearlink::numbers::pi;
  constexpr double R = 0.012;

  /** A round surface of radius R on @p n samples. */
  std::vector<double>
  round(unsigned int n)
  {
    return std::vector<double>(n, R);
  }

  /** Σ h_k R_k, the volume over L Δψ. */
  double
  volume(const std::vector<double> &h, const std::vector<double> &radii)
  {
    double v = 0;
    for (std::size_t k = 0; k < h.size(); ++k)
      v += h[k] * radii[k];
    return v;
  }

  /** 1 µm mean plus @p amplitude × cos(m ψ) on n samples. */
  std::vector<double>
  wave(unsigned int n, unsigned int m, double amplitude)
  {
    std::vector<double> v(n);
    for (unsigned int k = 0; k < n; ++k)
      v[k] = 1e-6 + amplitude * std::cos(2 * pi * m * k / n);
    return v;
  }

  /** Amplitude of the cos(m ψ) part of @p v. */
  double
  amplitude_of(const std::vector<double> &v, unsigned int m)
  {
    double a = 0;
    for (unsigned int k = 0; k < v.size(); ++k)
      a += v[k] * std::cos(2 * pi * m * k / v.size());
    return 2 * a / v.size();
  }
} // namespace

TEST(Smoothing, KeepsTheMeanAndHalvesTheStatedWavelength)
{
  const unsigned int n = 360, m = 19; // wavelength 2πR/19 = 3.97 mm
  const double       lambda = 2 * pi * R / m;
  const auto         v      = wave(n, m, 1e-6);
  const auto         s      = smoothed(v, lambda, round(n));
  const double       mean_v = std::accumulate(v.begin(), v.end(), 0.0) / n;
  const double       mean_s = std::accumulate(s.begin(), s.end(), 0.0) / n;
  EXPECT_NEAR(mean_s, mean_v, 1e-12 * mean_v);
  // The sampled, truncated Gaussian's transfer at 19 waves (σ = 2.1 samples) is 1/2
  // to within the truncation at 4σ (e^−8).
  EXPECT_NEAR(amplitude_of(s, m), 0.5e-6, 0.01e-6);
  EXPECT_GT(amplitude_of(smoothed(wave(n, 2, 1e-6), lambda, round(n)), 2), 0.99e-6) << "long waves pass";
}

TEST(Smoothing, RemovesTheSawToothAndZeroIsTheIdentity)
{
  const unsigned int  n = 360;
  std::vector<double> saw(n);
  for (unsigned int k = 0; k < n; ++k)
    saw[k] = 8e-6 + (k % 2 == 0 ? 1 : -1) * 5e-6;
  const auto s = smoothed(saw, 2e-3, round(n));
  for (const double x : s)
    EXPECT_NEAR(x, 8e-6, 1e-9);
  EXPECT_EQ(smoothed(saw, 0, round(n)), saw);
}

// A worn bore: a 40 µm pocket over a quarter of the surface makes the radii differ by up
// to 40 µm between areas; the filtered increment (a spiky one: every third area) still
// removes the same volume Σ h_k R_k L Δψ to 1e-12 — a circular convolution alone keeps Σ h_k
// only, which here differs by ~1e-6 of the volume.
TEST(Smoothing, KeepsTheVolumeOnAWornSurface)
{
  const unsigned int  n = 720;
  std::vector<double> radii(n), h(n);
  for (unsigned int k = 0; k < n; ++k)
    {
      const double psi = 2 * pi * k / n;
      radii[k]         = R + 40e-6 * std::max(0.0, std::cos(2 * psi));
      h[k]             = (k % 3 == 0 ? 3e-6 : 0.2e-6) * (1 + std::sin(psi));
    }
  for (const double lambda : {5e-4, 2e-3, 1e-2})
    {
      const auto s = smoothed(h, lambda, radii);
      EXPECT_NEAR(volume(s, radii), volume(h, radii), 1e-12 * volume(h, radii)) << lambda;
      EXPECT_LT(*std::max_element(s.begin(), s.end()), 0.8 * *std::max_element(h.begin(), h.end())) << lambda;
    }
}
