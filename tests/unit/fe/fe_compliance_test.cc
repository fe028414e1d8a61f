// SPDX-License-Identifier: LGPL-2.1-or-later
// A periodic mesh (round profiles, fe/pin_bushing_mesher.h) makes each body's compliance
// the same in every sector; BoundaryCompliance then computes one sector's columns and
// hands out the others as shifted views in the frames of the sectors. Checked against the columns computed
// directly on the same mesh (a BoundaryCompliance told nothing of the sectors), for
// candidates in other sectors, every entry: equal to 1e-9 of the column's largest.
// And a worn profile gives no periodic mesh, so every column is computed.
#include "fe/boundary_compliance.h"
#include "fe/pin_bushing_mesher.h"
#include "fe_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace wearlink;
using namespace wearlink::fe;
using namespace wearlink::fe::testing;

namespace
{
  MeshSpecification
  coarse_spec()
  {
    MeshSpecification spec;
    spec.core_radius          = 0.4 * R2;
    spec.outer_radius         = 0.024;
    spec.surface_element_size = 200e-6;
    spec.max_element_size     = 2e-3;
    spec.size_growth          = 0.3;
    spec.layer_thickness      = 0.2e-3;
    return spec;
  }

  /** Largest |difference| between two columns' entries i, over the largest |entry|. */
  template <typename A, typename B>
  double
  relative_difference(const unsigned int n, A a, B b)
  {
    double difference = 0, scale = 0;
    for (unsigned int i = 0; i < n; ++i)
      {
        difference = std::max(difference, std::abs(a(i) - b(i)));
        scale      = std::max(scale, std::abs(b(i)));
      }
    return difference / scale;
  }
} // namespace

TEST(FeCompliance, RotatedSectorColumnsAreTheComputedOnes)
{
  const auto        g     = steel_pair();
  const std::string msh   = mesh_file("periodic_compliance");
  const auto        stats = write_pin_bushing_mesh(g.bore, g.pin, coarse_spec(), msh);
  ASSERT_GT(stats.pin_sectors, 3u);
  ASSERT_GT(stats.bore_sectors, 3u);
  ElasticityProblem problem(msh, 1, 0, g.pin_material, g.bushing, g.pin, g.bore);
  problem.run();
  BoundaryCompliance periodic(problem, stats.pin_sectors, stats.bore_sectors), direct(problem);
  ASSERT_TRUE(periodic.pin_periodic());
  ASSERT_TRUE(periodic.bore_periodic());
  ASSERT_FALSE(direct.pin_periodic());
  const unsigned int m = problem.pin_nodes.size(), q = problem.bore_nodes.size();
  for (const unsigned int j : {0u, 37u, m / 3, m - 1})
    {
      const auto p = periodic.pin_column(j), d = direct.pin_column(j);
      EXPECT_EQ(d.shift, 0u);
      const double difference = relative_difference(
        m,
        [&](unsigned i) { return p.base[(i + m - p.shift) % m]; },
        [&](unsigned i) { return d.base[i]; });
      EXPECT_LT(difference, 1e-9) << "pin column " << j;
    }
  for (const unsigned int c : {5u, q / 2 + 3, q - 2})
    for (unsigned int dir = 0; dir < 2; ++dir)
      for (unsigned int comp = 0; comp < 2; ++comp)
        {
          const auto p = periodic.bore_column(c), d = direct.bore_column(c);
          EXPECT_EQ(d.shift, 0u);
          // Displacement component comp at node a for a unit force along dir, both in
          // the x–y frame: the periodic view's entries are in the nodes' sector frames.
          auto rotated = [&](unsigned a) {
            const auto         rc = periodic.sector_rotation(c), ra = periodic.sector_rotation(a);
            const double       fx = dir == 0, fy = dir == 1;
            const double       gx = rc[0] * fx + rc[1] * fy, gy = rc[0] * fy - rc[1] * fx;
            const unsigned int b  = (a + q - p.shift) % q;
            const double       ux = gx * p.base[b] + gy * p.base[2 * q + b];
            const double       uy = gx * p.base[q + b] + gy * p.base[3 * q + b];
            return comp == 0 ? ra[0] * ux - ra[1] * uy : ra[1] * ux + ra[0] * uy;
          };
          const double difference =
            relative_difference(q, rotated, [&](unsigned a) { return d.base[2 * q * dir + q * comp + a]; });
          EXPECT_LT(difference, 1e-9) << "bore column " << c << ", force " << dir << ", component " << comp;
        }
  EXPECT_LT(periodic.n_back_substitutions(), direct.n_back_substitutions())
    << "one sector's columns (and blocks of 32) instead of each one's";
}

TEST(FeCompliance, WornProfilesGiveNoPeriodicMesh)
{
  auto                g = steel_pair();
  std::vector<double> bore(g.bore.samples());
  bore[10] += 5e-6;
  g.bore                = Profile::from_samples(bore, "dented bore");
  const std::string msh = mesh_file("worn_not_periodic");
  const auto        s   = write_pin_bushing_mesh(g.bore, g.pin, coarse_spec(), msh);
  EXPECT_EQ(s.pin_sectors, 0u);
  EXPECT_EQ(s.bore_sectors, 0u);
}

// precompute_all() solves its blocks on every core, each thread with a CHOLMOD workspace
// of its own, through the same factor: every column of a worn (not periodic) pair equals
// the one computed on demand by a second BoundaryCompliance on the same problem, in
// every entry, and the solves add up to one per pin candidate and two per bore one.
TEST(FeCompliance, ColumnsOnEveryCoreAreTheOnDemandOnes)
{
  const auto        g   = dented_pair(30e-6, 10e-6);
  const std::string msh = mesh_file("worn_parallel_compliance");
  write_pin_bushing_mesh(g.bore, g.pin, coarse_spec(), msh);
  ElasticityProblem problem(msh, 1, 0, g.pin_material, g.bushing, g.pin, g.bore);
  problem.run();
  BoundaryCompliance all(problem), on_demand(problem);
  all.precompute_all();
  const unsigned int m = problem.pin_nodes.size(), q = problem.bore_nodes.size();
  EXPECT_EQ(all.n_back_substitutions(), m + 2 * q);
  double pin = 0, bore = 0;
  for (unsigned int j = m; j-- > 0;) // the other way round: other blocks
    pin = std::max(pin,
                   relative_difference(
                     m,
                     [&](unsigned i) { return all.pin_column(j).base[i]; },
                     [&](unsigned i) { return on_demand.pin_column(j).base[i]; }));
  for (unsigned int c = q; c-- > 0;)
    bore = std::max(bore,
                    relative_difference(
                      4 * q,
                      [&](unsigned i) { return all.bore_column(c).base[i]; },
                      [&](unsigned i) { return on_demand.bore_column(c).base[i]; }));
  EXPECT_EQ(all.n_back_substitutions(), m + 2 * q) << "precompute_all() left columns to compute on demand";
  EXPECT_LT(pin, 1e-12);
  EXPECT_LT(bore, 1e-12);
}
