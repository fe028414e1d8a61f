// SPDX-License-Identifier: LGPL-2.1-or-later
// The depth measures of a worn profile (wear/depth_measures.h): the envelope depth
// ignores a spike narrower than the contact width and follows a pocket wider than it; the
// roughness of a smooth pocket is ~0 whatever its curvature, that of a saw-tooth between
// neighbouring areas is its amplitude over the depth; the window is the odd number of
// areas nearest to the contact width, at least 3.
#include "base/numbers.h"
#include "wear/depth_measures.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace wearlink::wear;

namespace
{
  using wearlink::numbers::pi;

  /** A 30 µm pocket of half-width @p half_deg degrees (a cosine bell) on @p n areas. */
  std::vector<double>
  pocket(unsigned int n, double half_deg)
  {
    std::vector<double> h(n, 0.0);
    for (unsigned int k = 0; k < n; ++k)
      {
        double a = 360.0 * k / n;
        a        = a > 180 ? a - 360 : a;
        if (std::abs(a) < half_deg)
          h[k] = 15e-6 * (1 + std::cos(pi * a / half_deg));
      }
    return h;
  }
} // namespace

TEST(DepthMeasures, WindowIsTheOddAreaCountNearestTheContactWidth)
{
  const double area = 2 * pi * 0.012 / 360; // 0.209 mm
  EXPECT_EQ(window_areas(7.2 * area, 0.012, 360), 7u);
  EXPECT_EQ(window_areas(8.0 * area, 0.012, 360), 9u) << "an even count rounds up";
  EXPECT_EQ(window_areas(0.1 * area, 0.012, 360), 3u) << "at least 3";
  EXPECT_EQ(window_areas(0.0, 0.012, 360), 3u);
  EXPECT_EQ(window_areas(1e3, 0.012, 360), 359u) << "at most the profile";
}

TEST(DepthMeasures, EnvelopeIgnoresASpikeButFollowsAPocket)
{
  // A contact 7 areas wide in a 40° pocket feels the pocket's depth less its own
  // curvature over ±3 areas: the median of the 7 is the depth 2 areas off the centre.
  auto h = pocket(360, 20);
  EXPECT_NEAR(envelope_depth(h, 7), h[2], 1e-15) << "a 40° pocket";
  EXPECT_NEAR(envelope_depth(h, 7), 30e-6, 0.03 * 30e-6);
  h[100] = 80e-6; // one area's spike, far from the pocket
  EXPECT_NEAR(largest_depth(h), 80e-6, 1e-12);
  EXPECT_NEAR(envelope_depth(h, 7), h[2], 1e-15) << "a spike narrower than the contact is not felt";
  for (int d = -3; d <= 3; ++d)
    h[100 + d] = 80e-6; // as wide as the window: felt
  EXPECT_NEAR(envelope_depth(h, 7), 80e-6, 1e-12);
}

TEST(DepthMeasures, RoughnessReadsTheSawToothNotTheCurvature)
{
  for (const double half : {20.0, 40.0, 90.0})
    EXPECT_LT(roughness(pocket(360, half), 11), 0.01) << "a smooth " << 2 * half << "° pocket";
  // A pocket hardly wider than the window is a feature the contact cannot resolve:
  // it reads as rough.
  EXPECT_GT(roughness(pocket(360, 5), 11), roughness_limit);
  auto saw = pocket(360, 20);
  for (unsigned int k = 0; k < 360; k += 2)
    if (saw[k] > 0)
      saw[k] += 5e-6; // every other area 5 µm deeper
  // The local parabola runs through the middle of the steps: each area is half a step
  // off it, relative to the deepest area (30 + 5 µm), give or take the bell's own
  // departure from a parabola over the window (1 %).
  EXPECT_NEAR(roughness(saw, 11), 0.5 * 5e-6 / 35e-6, 0.015);
  EXPECT_GT(roughness(saw, 11), roughness_limit);
  EXPECT_EQ(roughness(std::vector<double>(360, 0.0), 11), 0.0) << "no wear, no roughness";
}
