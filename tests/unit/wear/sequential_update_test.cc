// SPDX-License-Identifier: LGPL-2.1-or-later
// The sequential wear update (wear/archard.h) against the simultaneous one, on a dwell:
// a constant load that sits at one direction of the bushing while the pin turns under
// it (the bore's worst case: all its wear on one spot), extrapolated far beyond the
// contact's elastic approach. Simultaneously, every state wears the unworn surfaces and
// the bore gets a trench as narrow as the Hertz strip; sequentially, each state meets the
// surfaces the earlier ones wore, the pocket conforms to the pin and widens (for the
// rigid imprint of a 15 µm deep pocket, ±14° against the strip's ±2°). Both remove the
// same Archard volume k_D F s f; the sequential pocket is smooth (roughness below 5 %).
// Each pressure model: hertz-strip (explicit, split states), winkler (implicit).
#include "base/numbers.h"
#include "unit/contact/pressure_model_support.h"
#include "wear/archard.h"
#include "wear/depth_measures.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace wearlink;
using namespace wearlink::wear::testing;

namespace
{
  using wearlink::numbers::pi;

  /** Width of the region deeper than half the deepest area [areas]. */
  unsigned int
  width_at_half_depth(const std::vector<double> &h)
  {
    const double top = *std::max_element(h.begin(), h.end());
    return static_cast<unsigned int>(std::count_if(h.begin(), h.end(), [&](double x) { return x > 0.5 * top; }));
  }

  struct Dwell
  {
    std::vector<double> bore;
    double              volume = 0, archard = 0, splits = 0;
  };

  /** 1 s of a 500 N dwell at −90° under a pin turning at 2 rev/s, × @p factor. */
  Dwell
  dwell(const std::string &model_name, const double factor, const bool sequential)
  {
    const auto g     = steel_joint(360);
    auto       model = pressure_model(model_name);
    model->update_geometry(g);
    const double             k = 4.6e-14, force = 500, omega = 4 * pi, dt = 1e-4;
    wear::ArchardAccumulator acc(g, k, k, *model);
    acc.set_sequential_factor(sequential ? factor : 0);
    for (unsigned int i = 0; i < 10000; ++i)
      {
        wear::LoadSample s;
        s.load.pin_angle     = omega * i * dt;
        s.load.contact_angle = -pi / 2;
        s.load.normal_force  = force;
        s.load.force         = {{0, force}};
        s.load.eccentricity  = {{0, -5e-4}};
        s.sliding_speed      = omega * g.pin[0];
        s.weight             = dt;
        s.time               = i * dt;
        acc.add(s);
      }
    Dwell d;
    for (const double x : acc.bore_depth())
      d.bore.push_back(factor * x);
    d.volume  = factor * acc.bore_volume;
    d.archard = factor * acc.bore_archard;
    d.splits  = static_cast<double>(acc.split_states);
    return d;
  }

  class SequentialUpdate : public ::testing::TestWithParam<std::string>
  {
  };
} // namespace

TEST_P(SequentialUpdate, ADwellDigsAConformingPocketNotATrench)
{
  const double factor       = 1000; // 2000 revolutions of the pin under the load
  const auto   simultaneous = dwell(GetParam(), factor, false);
  const auto   sequential   = dwell(GetParam(), factor, true);
  // Archard's volume k F s f (4.6e-14 × 500 N × 1.445 m × 1000 = 3.3e-9 m³ of the bore)
  // is the same for both. The local volume Σ h A exceeds it by the pressure's spread
  // over the arc (Σ p A is F divided by the mean cosine of the arc: ~1e-4 for the strip,
  // ~2 % for a ±20° pocket) and by the radii of the areas worn before (h/R, 3e-3).
  EXPECT_NEAR(sequential.archard, simultaneous.archard, 1e-12 * simultaneous.archard);
  EXPECT_NEAR(simultaneous.volume, simultaneous.archard, 1e-3 * simultaneous.archard);
  EXPECT_GT(sequential.volume, (1 - 3e-3) * sequential.archard);
  EXPECT_LT(sequential.volume, 1.03 * sequential.archard);
  const double deep_sim = *std::max_element(simultaneous.bore.begin(), simultaneous.bore.end());
  const double deep_seq = *std::max_element(sequential.bore.begin(), sequential.bore.end());
  EXPECT_GT(width_at_half_depth(sequential.bore), 3 * width_at_half_depth(simultaneous.bore)) << GetParam();
  EXPECT_LT(deep_seq, 0.5 * deep_sim) << GetParam();
  EXPECT_LT(wear::roughness(sequential.bore, 11), wear::roughness_limit) << GetParam();
}

INSTANTIATE_TEST_SUITE_P(Models, SequentialUpdate, ::testing::Values("hertz-strip", "winkler"));
