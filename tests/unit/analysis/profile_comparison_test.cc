// SPDX-License-Identifier: LGPL-2.1-or-later
// A measured worn profile against a predicted one (analysis/profile_comparison.h):
//  - identical traces differ by nothing, at rotation 0;
//  - a worn bore (two pockets of different depth, so that one rotation fits) measured at
//    500 unevenly spaced points with 0.5 µm of noise and an unknown origin: the
//    rotation is recovered within a tolerance derived from the data (below);
//  - a uniform radius offset δ of a round surface of radius R wears an area of
//    (R + δ)² π − R² π = 2πRδ (1 + δ/2R) — whatever the measured spacing, since the
//    areas are taken on the common angles.
#include "analysis/profile_comparison.h"
#include "base/exceptions.h"
#include "base/numbers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <iostream>
#include <random>

using namespace wearlink::analysis;
using wearlink::numbers::pi;
using wearlink::numbers::two_pi;

namespace
{
  constexpr double R = 0.012; ///< bore radius [m]

  /** A worn bore: pockets of 30 and 12 µm at 100° and 250°, Gaussian of width 15° and 10°. */
  struct WornBore
  {
    double
    radius(const double psi) const
    {
      return R + pocket(psi, 100, 15, 30e-6) + pocket(psi, 250, 10, 12e-6);
    }
    double
    slope(const double psi) const
    {
      const double h = 1e-6;
      return (radius(psi + h) - radius(psi - h)) / (2 * h);
    }
    /** The largest |r''| [m/rad²], bounding the linear interpolation's error. */
    double
    largest_curvature() const
    {
      double c = 0;
      for (int k = 0; k < 36000; ++k)
        {
          const double psi = two_pi * k / 36000, h = 1e-4;
          c = std::max(c, std::abs(radius(psi + h) - 2 * radius(psi) + radius(psi - h)) / (h * h));
        }
      return c;
    }

  private:
    static double
    pocket(const double psi, const double centre_deg, const double width_deg, const double depth)
    {
      // The angular distance to the centre, across 2π.
      double d = std::remainder(psi - centre_deg * pi / 180, two_pi);
      return depth * std::exp(-0.5 * std::pow(d / (width_deg * pi / 180), 2));
    }
  };

  PolarTrace
  uniform_trace(const std::function<double(double)> &r, const unsigned int n)
  {
    PolarTrace t;
    for (unsigned int k = 0; k < n; ++k)
      {
        t.angle.push_back(two_pi * k / n);
        t.radius.push_back(r(two_pi * k / n));
      }
    return t;
  }

  /** @p n unevenly spaced angles in [0, 2π), increasing. */
  std::vector<double>
  uneven_angles(const unsigned int n)
  {
    std::vector<double> a;
    for (unsigned int i = 0; i < n; ++i)
      a.push_back(two_pi * (i + 0.4 * std::sin(1.7 * i)) / n + 0.3 * two_pi / n);
    return a;
  }

  /** Standard normal numbers (Box–Muller on std::mt19937_64, seeded). */
  std::vector<double>
  normals(const unsigned int n)
  {
    std::mt19937_64     engine(7);
    std::vector<double> z;
    while (z.size() < n)
      {
        const double u1 = ((engine() >> 11) + 1) * 0x1.0p-53, u2 = (engine() >> 11) * 0x1.0p-53;
        z.push_back(std::sqrt(-2 * std::log(u1)) * std::cos(two_pi * u2));
      }
    return z;
  }
} // namespace

TEST(ProfileComparison, IdenticalProfilesDifferByNothing)
{
  const WornBore bore;
  const auto     p = uniform_trace([&](double psi) { return bore.radius(psi); }, 360);
  const auto     d = trace_difference(p, p, 0);
  EXPECT_EQ(d.rms, 0.0);
  EXPECT_EQ(d.largest, 0.0);
  const auto a = align_trace(p, p, pi);
  // The RMS grows like |θ| × RMS(r') ≈ |θ| × 4e-5 m/rad away from 0: Brent locates a
  // kinked minimum to about the square root of the double precision in θ (1.5e-8 rad).
  EXPECT_LT(std::abs(a.rotation), 1e-7) << "rotation " << a.rotation;
  EXPECT_LT(a.difference.rms, 1e-11);
}

TEST(ProfileComparison, RecoversAKnownRotationOfANoisyTrace)
{
  const WornBore bore;
  const auto     predicted = uniform_trace([&](double psi) { return bore.radius(psi); }, 360);
  const auto     unworn    = uniform_trace([](double) { return R; }, 360);
  const double   sigma     = 0.5e-6;
  const auto     a         = uneven_angles(500);
  const auto     z         = normals(500);
  for (const double truth : {0.6, -2.5, 3.0})
    {
      PolarTrace measured;
      measured.angle = a;
      for (std::size_t i = 0; i < a.size(); ++i)
        measured.radius.push_back(bore.radius(a[i] + truth) + sigma * z[i]);
      // The tolerance. Linearised least squares over the measured points, θ̂ − θ ≈
      // Σ e_i r'_i / Σ r'_i², has the standard deviation σ/√(Σ r'_i²) for noise e of
      // σ, and an error of at most ε Σ|r'_i| / Σ r'_i² from the predicted trace's linear
      // interpolation error ε ≤ h² max|r''|/8 (h = 1°). The RMS over the circle weighs
      // the points a little differently, so 5 standard deviations plus that bound.
      double s2 = 0, s1 = 0;
      for (const double ai : a)
        {
          s2 += std::pow(bore.slope(ai + truth), 2);
          s1 += std::abs(bore.slope(ai + truth));
        }
      const double eps = std::pow(two_pi / 360, 2) * bore.largest_curvature() / 8;
      const double tol = 5 * sigma / std::sqrt(s2) + eps * s1 / s2;
      const auto   c   = compare_profile(measured, predicted, unworn, WornSurface::bore, pi);
      const double err = std::remainder(c.alignment.rotation - truth, two_pi);
      std::cout << "  truth " << truth << " rad: found " << c.alignment.rotation << " (error " << err
                << " rad, tolerance " << tol << "), RMS " << c.alignment.difference.rms << " m, "
                << c.alignment.evaluations << " evaluations\n";
      EXPECT_LT(std::abs(err), tol) << "truth " << truth;
      // At the right rotation only the noise is left: RMS about σ (the measured trace's
      // interpolation between its points averages some of it away: at least σ/2).
      EXPECT_NEAR(c.alignment.difference.rms, sigma, sigma / 2);
      EXPECT_GT(c.alignment.unaligned_rms, 10 * sigma) << "unaligned, the pockets do not meet";
      // The deepest wear: 30 µm at 100°, measured within the noise (4σ) and near there.
      EXPECT_NEAR(c.max_depth_predicted, 30e-6, 1e-9);
      EXPECT_NEAR(c.max_depth_predicted_angle, 100 * pi / 180, 1e-12);
      EXPECT_NEAR(c.max_depth_measured, 30e-6, 4 * sigma);
      EXPECT_NEAR(c.max_depth_measured_angle, 100 * pi / 180, 5 * pi / 180);
    }
}

TEST(ProfileComparison, AUniformOffsetWearsTheAreaTwoPiRDelta)
{
  const double delta     = 2e-6;
  const auto   predicted = uniform_trace([](double) { return R; }, 360);
  for (const unsigned int m : {12u, 97u, 1000u})
    {
      PolarTrace measured;
      measured.angle = uneven_angles(m);
      measured.radius.assign(m, R + delta);
      const auto c = compare_profile(measured, predicted, predicted, WornSurface::bore, 0);
      // On the common angles (spacing h ≤ 1°) the polygons' areas are ½ Σ sin h_k r²,
      // and Σ sin h_k = 2π (1 − O(h²/6)): 2πRδ (1 + δ/2R) within 2πRδ h²/6 + round-off.
      const double first_order = two_pi * R * delta;
      const double tol         = first_order * (delta / (2 * R) + std::pow(pi / 180, 2) / 6) + 1e-18;
      EXPECT_NEAR(c.worn_area_measured, first_order, tol) << m << " measured points";
      EXPECT_EQ(c.worn_area_predicted, 0.0) << "the prediction is the unworn surface";
      EXPECT_NEAR(c.alignment.difference.rms, delta, 1e-15);
      EXPECT_NEAR(c.alignment.difference.largest, delta, 1e-15);
      EXPECT_NEAR(c.max_depth_measured, delta, 1e-15);
      // A pin measured δ larger than it started has lost −2πRδ.
      const auto pin = compare_profile(measured, predicted, predicted, WornSurface::pin, 0);
      EXPECT_NEAR(pin.worn_area_measured, -first_order, tol);
    }
}

TEST(ProfileComparison, RefusesATraceOutOfOrder)
{
  auto p = uniform_trace([](double) { return R; }, 16);
  std::swap(p.angle[3], p.angle[4]);
  const auto q = uniform_trace([](double) { return R; }, 16);
  EXPECT_THROW(compare_profile(p, q, q, WornSurface::bore, 0), wearlink::InputError);
  EXPECT_THROW(align_trace(q, q, 4.0), wearlink::InputError) << "a search beyond π";
}
