// SPDX-License-Identifier: LGPL-2.1-or-later
// The accuracy study's chaos floor and its runs over MPI: a quick study of
// params/nine_bar_wear.prm (wear-step knob only, 2 iterations of 0.5 cycles) with a floor
// of 3 members, once on 1 rank and once on 2 ranks.
//  - The runs are the same whichever rank takes them: every error and the floor are equal
//    to the last digit of accuracy.csv (10 significant digits), and the floor's
//    quantities in accuracy_floor.csv too; both ranks took runs.
//  - The floor is what equivalent runs show: > 0 (the perturbed members part), every
//    row's worst_over_floor is its worst error over the floor's mean, the floor's mean
//    lies between its smallest and largest pair.
#include "io/csv.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

using namespace wearlink;
using namespace wearlink::testing;

namespace
{
  std::vector<std::string>
  study_args(const std::string &dir)
  {
    return {"study",
            "accuracy",
            source_path("params/nine_bar_wear.prm"),
            "--quick",
            "--knobs",
            "wear-step",
            "--ensemble",
            "3",
            "--set",
            "Wear/Cycles per iteration=0.5",
            "--output",
            dir};
  }

  double
  field(const io::CsvTable &t, const std::size_t row, const std::string &column)
  {
    return std::strtod(t.field(row, t.find(column)).c_str(), nullptr);
  }
} // namespace

TEST(StudyFloor, TheFloorIsMeasuredAndTheSameOnOneAndTwoRanks)
{
  if (std::string(WEARLINK_MPIEXEC).empty())
    GTEST_SKIP() << "no mpiexec";
  ::setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
  ::setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
  const std::string one = fresh_directory("study_floor_1"), two = fresh_directory("study_floor_2");
  const auto        r1 = run_wearlink(study_args(one));
  ASSERT_EQ(r1.exit_status, 0) << r1.output;
  const auto r2 = run_wearlink_mpi(2, study_args(two));
  ASSERT_EQ(r2.exit_status, 0) << r2.output;
  EXPECT_NE(r2.output.find("study rank 1  run"), std::string::npos) << "rank 1 took no run:\n" << r2.output;

  const auto a = io::CsvTable::read(one + "/accuracy.csv", "study"),
             b = io::CsvTable::read(two + "/accuracy.csv", "study");
  ASSERT_EQ(a.n_rows(), 3u);
  ASSERT_EQ(a.columns(), b.columns());
  for (std::size_t r = 0; r < a.n_rows(); ++r)
    for (std::size_t c = 0; c < a.columns().size(); ++c)
      {
        if (a.columns()[c] != "wall_time_s" && a.columns()[c] != "cpu_time_s")
          {
            EXPECT_EQ(a.field(r, c), b.field(r, c)) << a.columns()[c] << ", row " << r;
          }
      }
  EXPECT_EQ(file_content(one + "/accuracy_floor.csv"), file_content(two + "/accuracy_floor.csv"));

  const double floor = field(a, 0, "floor_worst_mean"), largest = field(a, 0, "floor_worst_max");
  EXPECT_GT(floor, 0) << "the perturbed members did not part";
  EXPECT_GE(largest, floor);
  for (std::size_t r = 0; r + 1 < a.n_rows(); ++r)
    EXPECT_NEAR(field(a, r, "worst_over_floor"),
                field(a, r, "worst_error") / floor,
                1e-8 * field(a, r, "worst_error") / floor);
  EXPECT_NE(file_content(one + "/accuracy.md").find("Chaos floor: 3 runs"), std::string::npos);
}
