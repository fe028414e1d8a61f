// SPDX-License-Identifier: LGPL-2.1-or-later
// Discrete profiles R*(ψ): periodic linear interpolation, enclosed area, CSV input with
// the error paths the FE and wear layers rely on.
#include "base/exceptions.h"
#include "base/profile.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

using wearlink::InputError;
using wearlink::Profile;

namespace
{
  constexpr double pi = 3.14159265358979323846;

  std::string
  write(const std::string &name, const std::string &text)
  {
    const std::string dir  = wearlink::testing::fresh_directory("profile_" + name);
    const std::string file = dir + "/" + name + ".csv";
    std::ofstream(file) << text;
    return file;
  }
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

TEST(Profile, ReadsAndResamplesCsv)
{
  // 16 points of R = 1 + 0.1 cos ψ; resampled onto 32 points the values at the old
  // nodes are unchanged and the new mid-points are linear averages.
  std::string text = "angle_rad,radius_m\n";
  for (int k = 0; k < 16; ++k)
    text += std::to_string(2 * pi * k / 16) + "," + std::to_string(1 + 0.1 * std::cos(2 * pi * k / 16)) + "\n";
  const Profile p = Profile::read_csv(write("cos", text), 32);
  ASSERT_EQ(p.n_points(), 32u);
  EXPECT_NEAR(p[2], 1 + 0.1 * std::cos(2 * pi * 1 / 16), 1e-6);
  EXPECT_NEAR(p[1], 0.5 * (p[0] + p[2]), 1e-6);
}

TEST(Profile, RejectsBadFiles)
{
  EXPECT_THROW(Profile::read_csv("/nonexistent/profile.csv"), InputError);
  std::string few = "";
  for (int k = 0; k < 5; ++k)
    few += std::to_string(k * 0.5) + ",1\n";
  EXPECT_THROW(Profile::read_csv(write("few", few)), InputError);
  std::string nan = "";
  for (int k = 0; k < 10; ++k)
    nan += std::to_string(k * 0.5) + (k == 3 ? ",nan\n" : ",1\n");
  EXPECT_THROW(Profile::read_csv(write("nan", nan), 16), InputError);
  std::string back = "";
  for (int k = 0; k < 10; ++k)
    back += std::to_string(k == 4 ? 0.1 : k * 0.5) + ",1\n";
  EXPECT_THROW(Profile::read_csv(write("back", back), 16), InputError);
  EXPECT_THROW(Profile::round(-1, 16), InputError);
  EXPECT_THROW(Profile::round(1, 4), InputError);
}

// A profile written by write_csv (comment line, then the header) reads back exactly:
// the worn profiles of a wear run can start another scene.
TEST(Profile, WrittenProfileReadsBack)
{
  std::vector<double> r(36);
  for (unsigned k = 0; k < r.size(); ++k)
    r[k] = 0.012 + 1e-6 * std::sin(0.3 * k);
  const auto        p   = wearlink::Profile::from_samples(r);
  const std::string dir = wearlink::testing::fresh_directory("profile_round_trip");
  p.write_csv(dir + "/p.csv", "a worn bore");
  const auto q = wearlink::Profile::read_csv(dir + "/p.csv");
  ASSERT_EQ(q.n_points(), p.n_points());
  for (unsigned k = 0; k < r.size(); ++k)
    EXPECT_EQ(q[k], p[k]);
}
