// SPDX-License-Identifier: LGPL-2.1-or-later
// The kd-tree behind every neighbour search of the Lyapunov and false-nearest-neighbour
// estimators (analysis/kd_tree.h) against brute force: same nearest and k nearest
// neighbours under the Theiler window and the distance annulus.
#include "analysis/kd_tree.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

using namespace wearlink::analysis;

namespace
{
  /** A reproducible pseudo-random series in [0, 1) (64-bit linear congruential). */
  std::vector<double>
  random_series(const std::size_t n)
  {
    std::uint64_t       state = 12345;
    std::vector<double> x(n);
    for (auto &v : x)
      {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        v     = static_cast<double>(state >> 11) / 9007199254740992.0;
      }
    return x;
  }

  /** All admissible neighbours of point q, nearest first, by brute force. */
  std::vector<Neighbour>
  brute_force(const std::vector<double> &x,
              const unsigned int         m,
              const std::size_t          tau,
              const std::size_t          n,
              const std::size_t          q,
              const NeighbourFilter     &filter)
  {
    std::vector<Neighbour> out;
    for (std::size_t j = 0; j < n; ++j)
      {
        const std::size_t gap = j > q ? j - q : q - j;
        if (gap <= filter.theiler_window)
          continue;
        double s = 0.0;
        for (unsigned int d = 0; d < m; ++d)
          s += (x[q + d * tau] - x[j + d * tau]) * (x[q + d * tau] - x[j + d * tau]);
        const double dist = std::sqrt(s);
        if (dist > filter.min_distance && dist < filter.max_distance)
          out.push_back({j, dist});
      }
    std::sort(out.begin(), out.end(), [](const Neighbour &a, const Neighbour &b) { return a.distance < b.distance; });
    return out;
  }
} // namespace

TEST(KdTree, NearestAndKNearestMatchBruteForce)
{
  // 3000 random delay vectors in dimension 3 (delay 2): exact arithmetic on the same
  // coordinates, so the indices must agree exactly (ties have probability ~0 with
  // random doubles) and the distances to rounding (1e-12).
  const std::vector<double> x   = random_series(3006);
  const unsigned int        m   = 3;
  const std::size_t         tau = 2, n = 3000;
  const KdTree              tree(x, m, tau, n);
  ASSERT_EQ(tree.n_points(), n);
  for (std::size_t q = 0; q < n; q += 37)
    {
      NeighbourFilter filter;
      filter.query_index    = q;
      filter.theiler_window = 5;
      filter.min_distance   = (q % 3 == 0) ? 0.05 : 0.0;
      filter.max_distance   = (q % 2 == 0) ? 0.3 : std::numeric_limits<double>::infinity();
      const double point[3] = {x[q], x[q + tau], x[q + 2 * tau]};
      const auto   expected = brute_force(x, m, tau, n, q, filter);

      const Neighbour nearest = tree.nearest(point, filter);
      ASSERT_EQ(nearest.found(), !expected.empty()) << "query " << q;
      if (nearest.found())
        {
          EXPECT_EQ(nearest.index, expected[0].index) << "query " << q;
          EXPECT_NEAR(nearest.distance, expected[0].distance, 1e-12);
        }
      const auto k_nearest = tree.k_nearest(point, 10, filter);
      ASSERT_EQ(k_nearest.size(), std::min<std::size_t>(10, expected.size())) << "query " << q;
      for (std::size_t k = 0; k < k_nearest.size(); ++k)
        EXPECT_EQ(k_nearest[k].index, expected[k].index) << "query " << q << ", rank " << k;
    }
}

TEST(KdTree, TheilerWindowExcludesTemporalNeighbours)
{
  // A slowly increasing ramp: the nearest point of sample q in time is also nearest in
  // space, so with a Theiler window w the nearest admissible point is q +- (w + 1).
  std::vector<double> x(500);
  for (std::size_t i = 0; i < x.size(); ++i)
    x[i] = 0.001 * i;
  const KdTree    tree(x, 1, 1, x.size());
  NeighbourFilter filter;
  filter.query_index    = 200;
  filter.theiler_window = 7;
  const Neighbour n     = tree.nearest(&x[200], filter);
  ASSERT_TRUE(n.found());
  EXPECT_TRUE(n.index == 192 || n.index == 208) << n.index;
  EXPECT_NEAR(n.distance, 0.008, 1e-12);
}
