// SPDX-License-Identifier: LGPL-2.1-or-later
// The one CSV reader (io/csv.h) and the profile files read through it: header detection,
// separators, comments, and error messages that name the file, the line and the column.
#include "base/exceptions.h"
#include "base/numbers.h"
#include "io/csv.h"
#include "io/profile_file.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

using wearlink::InputError;
using wearlink::Profile;
using wearlink::io::CsvTable;
using wearlink::numbers::pi;

namespace
{
  std::string
  write(const std::string &name, const std::string &text)
  {
    const std::string dir  = wearlink::testing::fresh_directory("csv_" + name);
    const std::string file = dir + "/" + name + ".csv";
    std::ofstream(file) << text;
    return file;
  }

} // namespace

TEST(Csv, HeaderCommentsQuotesAndBlankLines)
{
  const std::string file = write("table", "# made by hand\n\"t\", \"x\"  # names\n\n0, 1.5\n0.1,2.5 # note\n");
  const CsvTable    t    = CsvTable::read(file, "test file");
  ASSERT_EQ(t.columns(), (std::vector<std::string>{"t", "x"}));
  EXPECT_EQ(t.n_rows(), 2u);
  EXPECT_EQ(t.numbers(t.find("x")), (std::vector<double>{1.5, 2.5}));
  EXPECT_EQ(t.line_of(1), 5u);
  EXPECT_EQ(t.find("y"), CsvTable::npos);
}

TEST(Csv, PlainRowsSplitAsRowsWithCommentsAndQuotes)
{
  // Rows without quotes or comments (all that wearlink writes) take a shorter path; it
  // must split them as the general one splits the same fields with a comment or quotes.
  const CsvTable t = CsvTable::read(write("plain",
                                          "a,b,c,d\n"
                                          " 1 , 2,, 3 \n"
                                          " 1 , 2,, 3 # a comment\n"
                                          "\"1\",2,,3\n"
                                          ",,,\n"
                                          "-1.5e-05,2,3,4\n"),
                                    "test file");
  ASSERT_EQ(t.n_rows(), 5u);
  for (std::size_t r = 0; r < 3; ++r)
    {
      EXPECT_EQ(t.field(r, 0), "1") << "row " << r;
      EXPECT_EQ(t.field(r, 1), "2") << "row " << r;
      EXPECT_EQ(t.field(r, 2), "") << "row " << r;
      EXPECT_EQ(t.field(r, 3), "3") << "row " << r;
    }
  EXPECT_EQ(t.field(3, 3), "");
  EXPECT_NO_THROW(t.require_rectangular());
  EXPECT_EQ(t.field(4, 0), "-1.5e-05");
}

TEST(Csv, ReadsOnlyTheNamedColumns)
{
  const std::string file = write("some", "t,x,y,z\n0,1,2,3\n# a comment\n1,4,5,6\n");
  const CsvTable    t    = CsvTable::read(file, "test file", {"z", "t", "absent"});
  EXPECT_EQ(t.columns(), (std::vector<std::string>{"t", "z"})) << "the file's order, absent names left out";
  EXPECT_EQ(t.n_columns(), 2u);
  EXPECT_EQ(t.numbers(t.find("z")), (std::vector<double>{3, 6}));
  EXPECT_EQ(t.numbers(t.find("t")), (std::vector<double>{0, 1}));
  EXPECT_EQ(t.line_of(1), 4u);
  EXPECT_EQ(t.find("x"), CsvTable::npos);
  // A row shorter than the header cannot give its columns: said at once, with its line.
  const std::string short_row = wearlink::testing::input_error_message(
    [&] { CsvTable::read(write("short", "t,x,y\n0,1,2\n1,2\n"), "test file", {"y"}); });
  EXPECT_NE(short_row.find("line 3 has 2 fields; the header has 3"), std::string::npos) << short_row;
  // Without a header there are no names to select by: every column.
  EXPECT_EQ(CsvTable::read(write("bare", "0,1\n2,3\n"), "test file", {"t"}).n_columns(), 2u);
}

TEST(Csv, WithoutHeaderAndBlankSeparated)
{
  const CsvTable t = CsvTable::read(write("blank", "1 2\n3\t4\n"), "test file");
  EXPECT_TRUE(t.columns().empty());
  EXPECT_EQ(t.numbers(1), (std::vector<double>{2, 4}));
}

TEST(Csv, ErrorsNameFileLineAndColumn)
{
  const std::string file = write("bad", "t,x\n0,1\n1,nan\n2\n");
  const CsvTable    t    = CsvTable::read(file, "test file");
  const std::string nan  = wearlink::testing::input_error_message([&] { t.numbers(1, "Repair it."); });
  EXPECT_NE(nan.find(file), std::string::npos) << nan;
  EXPECT_NE(nan.find("line 3, column 'x' is 'nan', not a finite number. Repair it."), std::string::npos) << nan;
  EXPECT_NE(wearlink::testing::input_error_message([&] {
              t.require_rectangular();
            }).find("line 4 has 1 fields; the header has 2"),
            std::string::npos);
  EXPECT_NE(wearlink::testing::input_error_message([] {
              CsvTable::read("/nonexistent/x.csv", "series file");
            }).find("Cannot open the series file '/nonexistent/x.csv'"),
            std::string::npos);
}

TEST(ProfileFile, ReadsAndResamples)
{
  // 16 points of R = 1 + 0.1 cos ψ; resampled onto 32 points the values at the old
  // nodes are unchanged and the new mid-points are linear averages.
  std::string text = "angle_rad,radius_m\n";
  for (int k = 0; k < 16; ++k)
    text += std::to_string(2 * pi * k / 16) + "," + std::to_string(1 + 0.1 * std::cos(2 * pi * k / 16)) + "\n";
  const Profile p = wearlink::io::read_profile_csv(write("cos", text), 32);
  ASSERT_EQ(p.n_points(), 32u);
  EXPECT_NEAR(p[2], 1 + 0.1 * std::cos(2 * pi * 1 / 16), 1e-6);
  EXPECT_NEAR(p[1], 0.5 * (p[0] + p[2]), 1e-6);
}

TEST(ProfileFile, RejectsBadFiles)
{
  using wearlink::io::read_profile_csv;
  EXPECT_THROW(read_profile_csv("/nonexistent/profile.csv"), InputError);
  std::string few = "";
  for (int k = 0; k < 5; ++k)
    few += std::to_string(k * 0.5) + ",1\n";
  EXPECT_THROW(read_profile_csv(write("few", few)), InputError);
  std::string nan = "";
  for (int k = 0; k < 10; ++k)
    nan += std::to_string(k * 0.5) + (k == 3 ? ",nan\n" : ",1\n");
  const std::string nan_file = write("nan", nan);
  EXPECT_NE(wearlink::testing::input_error_message([&] {
              read_profile_csv(nan_file, 16);
            }).find("line 4, column 2 is 'nan'"),
            std::string::npos);
  std::string back = "";
  for (int k = 0; k < 10; ++k)
    back += std::to_string(k == 4 ? 0.1 : k * 0.5) + ",1\n";
  EXPECT_NE(wearlink::testing::input_error_message([&] {
              read_profile_csv(write("back", back), 16);
            }).find("line 5: angles must increase"),
            std::string::npos);
  std::string negative = "";
  for (int k = 0; k < 10; ++k)
    negative += std::to_string(k * 0.5) + (k == 2 ? ",-1\n" : ",1\n");
  EXPECT_NE(wearlink::testing::input_error_message([&] {
              read_profile_csv(write("negative", negative), 16);
            }).find("line 3: the radius must be > 0"),
            std::string::npos);
}

// A profile written by write_profile_csv (comment line, then the header) reads back
// exactly: the worn profiles of a wear run can start another scene.
TEST(ProfileFile, WrittenProfileReadsBack)
{
  std::vector<double> r(36);
  for (unsigned k = 0; k < r.size(); ++k)
    r[k] = 0.012 + 1e-6 * std::sin(0.3 * k);
  const auto        p   = Profile::from_samples(r);
  const std::string dir = wearlink::testing::fresh_directory("profile_round_trip");
  wearlink::io::write_profile_csv(p, dir + "/p.csv", "a worn bore");
  const auto q = wearlink::io::read_profile_csv(dir + "/p.csv");
  ASSERT_EQ(q.n_points(), p.n_points());
  for (unsigned k = 0; k < r.size(); ++k)
    EXPECT_EQ(q[k], p[k]);
}
