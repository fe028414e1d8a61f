// SPDX-License-Identifier: LGPL-2.1-or-later
// Discrete profiles R*(ψ): periodic linear interpolation, enclosed area, resampling of
// polar points with the error paths the FE and wear layers rely on (files: unit/io).
#include "base/exceptions.h"
#include "base/profile.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using wearlink::InputError;
using wearlink::Profile;

namespace
{
  constexpr double pi = 3.14159265358979323846;

} // namespace

TEST(Profile, RoundProfileHasPolygonArea)
{
  // Linear interpolation of R in ψ between equal samples is the circle itself, so the
  // area is exactly πR² (no polygon error: the curve is R(ψ) = const).
  const Profile p = Profile::round(0.012, 64);
  EXPECT_NEAR(p.enclosed_area(), pi * 0.012 * 0.012, 1e-15);
  EXPECT_TRUE(p.is_round());
  EXPECT_DOUBLE_EQ(p.radius(-7.3), 0.012);
}

TEST(Profile, InterpolatesLinearlyAndPeriodically)
{
  std::vector<double> r(8, 1.0);
  r[1]            = 2.0;
  const Profile p = Profile::from_samples(r);
  const double  h = 2 * pi / 8;
  EXPECT_NEAR(p.radius(0.5 * h), 1.5, 1e-14);
  EXPECT_NEAR(p.radius(1.5 * h), 1.5, 1e-14);
  EXPECT_NEAR(p.radius(0.5 * h + 2 * pi), 1.5, 1e-14);
  EXPECT_NEAR(p.radius(0.5 * h - 4 * pi), 1.5, 1e-14);
  EXPECT_NEAR(p.slope(0.5 * h), 1.0 / h, 1e-12);
}

TEST(Profile, ResamplesPolarPoints)
{
  // 16 points of R = 1 + 0.1 cos ψ; resampled onto 32 points the values at the old
  // nodes are unchanged and the new mid-points are linear averages.
  std::vector<double> a, r;
  for (int k = 0; k < 16; ++k)
    {
      a.push_back(2 * pi * k / 16);
      r.push_back(1 + 0.1 * std::cos(2 * pi * k / 16));
    }
  const Profile p = Profile::from_polar_points(a, r, 32, "test profile");
  ASSERT_EQ(p.n_points(), 32u);
  EXPECT_DOUBLE_EQ(p[2], r[1]);
  EXPECT_NEAR(p[1], 0.5 * (p[0] + p[2]), 1e-15);
  // Shifted by a quarter step and kept at 16 points: a non-uniform grid is refused.
  a[5] += 0.01;
  EXPECT_THROW(Profile::from_polar_points(a, r, 0, "test profile"), InputError);
}

TEST(Profile, RejectsBadPoints)
{
  std::vector<double> a{0, 0.5, 1.0, 1.5, 2.0}, r(5, 1.0);
  EXPECT_THROW(Profile::from_polar_points(a, r, 16, "few"), InputError); // fewer than 8
  a = {0, 0.5, 1.0, 1.5, 0.1, 2.5, 3.0, 3.5, 4.0, 4.5};
  r.assign(10, 1.0);
  EXPECT_THROW(Profile::from_polar_points(a, r, 16, "back"), InputError); // turns back
  a = {0, 1, 2, 3, 4, 5, 6, 7};
  r.assign(8, 1.0);
  EXPECT_THROW(Profile::from_polar_points(a, r, 16, "two turns"), InputError); // > 2π
  EXPECT_THROW(Profile::round(-1, 16), InputError);
  EXPECT_THROW(Profile::round(1, 4), InputError);
}
