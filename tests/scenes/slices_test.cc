// SPDX-License-Identifier: LGPL-2.1-or-later
// Wear-in of a misaligned pin (doc/models.md §1.8), on tests/scenes/journal_pocket.prm
// cut into 10 slices with its bore tilted by γ = 1 mrad (5 µm over the half length, about
// twice the elastic approach under the load): the edge slice first carries 3.3 times
// the mean force. Over 8 iterations × 300 revolutions the bore wears the tilt in:
//  - the edge's force falls and the axial distribution flattens, iteration by
//    iteration (the spread of the slices' forces falls monotonically);
//  - Archard holds slice by slice: each slice's worn volume is k_D ∫ F_n ds of its
//    own load times ∫p dA / F_n = 1/⟨cos⟩ of its contact arc (wear/archard.h), 1 for a
//    narrow contact and 1.035 for ±30°: the ratio lies in [1, 1.04] (measured 1.003 at
//    the lightly worn edge to 1.031 in the deepest pocket);
//  - the slices' forces sum to the load, and the deepest wear sits at the loaded edge;
//  - compare-profile takes a trace at an axial position against the slice holding it.
// Aligned, the journal's slices wear as the whole joint (the slices of equal geometry share
// their field and their wear, contact/shared_fields.h, wear/wear_loop.h: sharing must not
// change a bit), and a symmetric crown's pairs of slices wear alike.
#include "base/json.h"
#include "io/csv.h"
#include "io/json_file.h"
#include "scene_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

using namespace wearlink;
using namespace wearlink::testing;

namespace sliced_journal
{
  /** The journal cut into 10 slices, its bore tilted by 1 mrad, winkler, into @p dir. */
  ProgramResult
  run(const std::string &dir, const std::string &iterations, const std::string &factor)
  {
    return run_wearlink({"run",
                         source_path("tests/scenes/journal_pocket.prm"),
                         "--output",
                         dir,
                         "--quiet",
                         "--set",
                         "Joint O/Clearance/Slices/Axial slices=10",
                         "--set",
                         "Joint O/Clearance/Slices/Misalignment=1e-3",
                         "--set",
                         "Joint O/Clearance/Initial eccentricity=0,-4.4e-5",
                         "--set",
                         "Joint O/Clearance/Pressure model=winkler",
                         "--set",
                         "Wear/Number of iterations=" + iterations,
                         "--set",
                         "Wear/Extrapolation factor=" + factor});
  }

  /** The aligned journal (hertz-strip) cut into @p slices, 3 iterations, with @p more entries set, into @p dir. */
  ProgramResult
  run_aligned(const std::string &dir, const std::string &slices, const std::vector<std::string> &more = {})
  {
    std::vector<std::string> args{"run",
                                  source_path("tests/scenes/journal_pocket.prm"),
                                  "--output",
                                  dir,
                                  "--quiet",
                                  "--set",
                                  "Joint O/Clearance/Slices/Axial slices=" + slices,
                                  "--set",
                                  "Wear/Number of iterations=3",
                                  "--set",
                                  "Wear/Extrapolation factor=300"};
    for (const auto &m : more)
      args.insert(args.end(), {"--set", m});
    return run_wearlink(args);
  }

  /** The last iteration's @p column of slice @p k (1-based) of joint O, or of the whole joint (k = 0). */
  double
  last(const io::CsvTable &h, const int k, const std::string &column)
  {
    const std::string s = k == 0 ? "O" : "O.s" + std::string(k < 10 ? "0" : "") + std::to_string(k);
    return h.numbers(h.find(s + "_" + column)).back();
  }
} // namespace sliced_journal

TEST(SlicedJournal, MisalignedPinWearsInAndFlattensItsAxialLoad)
{
  const std::string dir = fresh_directory("sliced_journal");
  const auto        r   = sliced_journal::run(dir, "8", "300");
  ASSERT_EQ(r.exit_status, 0) << r.output;
  const auto   h             = io::CsvTable::read(dir + "/wear_history.csv", "wear history");
  const auto   n             = h.numbers(0).size();
  double       previous_edge = 1e300, previous_spread = 1e300;
  const double normal_force = 100 * 9.81 / std::sqrt(1 + 0.01);
  for (std::size_t it = 0; it < n; ++it)
    {
      std::vector<double> f;
      for (int k = 1; k <= 10; ++k)
        f.push_back(
          h.numbers(h.find("O.s" + std::string(k < 10 ? "0" : "") + std::to_string(k) + "_mean_normal_force_N"))[it]);
      double sum = 0;
      for (const double x : f)
        sum += x;
      EXPECT_NEAR(sum / normal_force, 1.0, 5e-3) << "iteration " << it + 1 << ": the slices carry the load";
      const double mean   = sum / 10;
      const double edge   = f.front() / mean;
      const double spread = (*std::max_element(f.begin(), f.end()) - *std::min_element(f.begin(), f.end())) / mean;
      EXPECT_LT(edge, previous_edge) << "iteration " << it + 1;
      EXPECT_LT(spread, previous_spread) << "iteration " << it + 1;
      if (it == 0)
        {
          EXPECT_GT(edge, 2.5) << "the tilt edge-loads the pin";
        }
      previous_edge   = edge;
      previous_spread = spread;
    }
  EXPECT_LT(previous_edge, 1.8) << "worn in";
  // Archard per slice: V_i = k_D ∫ F_n,i ds (the history's global volume of each slice).
  for (int k = 1; k <= 10; ++k)
    {
      const std::string s      = "O.s" + std::string(k < 10 ? "0" : "") + std::to_string(k);
      const double      local  = h.numbers(h.find(s + "_volume_bushing_mm3")).back();
      const double      global = h.numbers(h.find(s + "_archard_volume_bushing_mm3")).back();
      EXPECT_GE(local / global, 1.0) << s;
      EXPECT_LE(local / global, 1.04) << s;
    }
  const Json  summary = io::read_json_file(dir + "/summary.json");
  const auto &w       = summary.at("sliced_joints_wear").at("O");
  EXPECT_EQ(summary.at("warnings").dump().find("elastic approach"), std::string::npos)
    << "an increment of about the approach (ratio 1.0 here) wears in: no warning";
  EXPECT_LT(w.at("max_depth_bushing_position_m").get<double>(), -0.004) << "the deepest wear at the loaded edge";

  // compare-profile at an axial position: a trace taken 0.3 mm inside the loaded edge
  // slice (z_1 = −4.5 mm, the slice spans −5 … −4 mm) is that slice's; it matches the
  // run's edge bore exactly, and the bore at the other edge (z = +4.7 mm) by the tilt's
  // worn-in difference, which the comparison reports as the difference of worn areas.
  const auto compare = [&](const std::string &z, const std::string &out) {
    return run_wearlink({"compare-profile",
                         dir,
                         dir + "/bore_O.s01.csv",
                         "--surface",
                         "bore",
                         "--joint",
                         "O",
                         "--axial-position",
                         z,
                         "--angle-search",
                         "0",
                         "--output",
                         out,
                         "--quiet"});
  };
  const std::string same = fresh_directory("sliced_compare_same"), other = fresh_directory("sliced_compare_other");
  ASSERT_EQ(compare("-0.0042", same).exit_status, 0);
  const Json at_edge = io::read_json_file(same + "/profile_comparison.json");
  EXPECT_EQ(at_edge.at("joint").get<std::string>(), "O.s01");
  EXPECT_DOUBLE_EQ(at_edge.at("slice_centre_m").get<double>(), -0.0045);
  EXPECT_EQ(at_edge.at("rms_difference_m").get<double>(), 0.0);
  ASSERT_EQ(compare("0.0047", other).exit_status, 0);
  const Json across = io::read_json_file(other + "/profile_comparison.json");
  EXPECT_EQ(across.at("joint").get<std::string>(), "O.s10");
  EXPECT_GT(across.at("worn_area_difference_m2").get<double>(), 0.0) << "the loaded edge wore more";
  const auto beyond = compare("0.0051", fresh_directory("sliced_compare_beyond") + "/out");
  EXPECT_EQ(beyond.exit_status, 2) << beyond.output;
  EXPECT_NE(beyond.output.find("spans"), std::string::npos) << beyond.output;
}

// The same journal extrapolated 2000-fold per iteration: a slice wears 3.8 times the
// slices' elastic approach in one iteration, and the axial load jumps between the edges
// instead of wearing in. The run must say so (doc/models.md §1.8).
TEST(SlicedJournal, AnIterationThatWearsPastTheApproachIsFlagged)
{
  const std::string dir = fresh_directory("sliced_journal_overshoot");
  const auto        r   = sliced_journal::run(dir, "2", "2000");
  ASSERT_EQ(r.exit_status, 0) << r.output;
  const Json summary = io::read_json_file(dir + "/summary.json");
  EXPECT_NE(summary.at("warnings").dump().find("joint O: largest depth increment of a slice"), std::string::npos)
    << summary.at("warnings").dump(1);
}

// Aligned slices are the whole joint cut into equal parts: each wears as deep as the
// whole joint and carries 1/n of its volume, to round-off. With a circular crown the
// slices at ±z have the same profiles and loads, so they wear alike to the last bit.
TEST(SlicedJournal, AlignedSlicesWearAsTheWholeJointAndACrownsPairsAlike)
{
  const std::string whole = fresh_directory("aligned_whole"), cut = fresh_directory("aligned_cut"),
                    crowned = fresh_directory("aligned_crowned");
  ASSERT_EQ(sliced_journal::run_aligned(whole, "1").exit_status, 0);
  const auto r = sliced_journal::run_aligned(cut, "4");
  ASSERT_EQ(r.exit_status, 0) << r.output;
  const auto   h1     = io::CsvTable::read(whole + "/wear_history.csv", "wear history");
  const auto   h4     = io::CsvTable::read(cut + "/wear_history.csv", "wear history");
  const double depth  = sliced_journal::last(h1, 0, "max_depth_bushing_um");
  const double volume = sliced_journal::last(h1, 0, "volume_bushing_mm3");
  ASSERT_GT(depth, 0.0);
  for (int k = 1; k <= 4; ++k)
    {
      EXPECT_NEAR(sliced_journal::last(h4, k, "max_depth_bushing_um"), depth, 1e-9 * depth) << "slice " << k;
      EXPECT_NEAR(4 * sliced_journal::last(h4, k, "volume_bushing_mm3"), volume, 1e-9 * volume) << "slice " << k;
    }
  const auto c = sliced_journal::run_aligned(crowned,
                                             "4",
                                             {"Joint O/Clearance/Slices/Pin crown=circular",
                                              "Joint O/Clearance/Slices/Crown drop=2e-6"});
  ASSERT_EQ(c.exit_status, 0) << c.output;
  const auto hc = io::CsvTable::read(crowned + "/wear_history.csv", "wear history");
  for (const std::string column : {"max_depth_bushing_um", "volume_bushing_mm3", "mean_normal_force_N"})
    {
      EXPECT_EQ(sliced_journal::last(hc, 1, column), sliced_journal::last(hc, 4, column)) << column;
      EXPECT_EQ(sliced_journal::last(hc, 2, column), sliced_journal::last(hc, 3, column)) << column;
    }
  EXPECT_GT(sliced_journal::last(hc, 2, "mean_normal_force_N"),
            1.2 * sliced_journal::last(hc, 1, "mean_normal_force_N"))
    << "the crown takes load off the ends";
}
