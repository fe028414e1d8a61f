// SPDX-License-Identifier: LGPL-2.1-or-later
// Signal files (io/signal_file.h), the measured input of `wearlink compare-signal`: each
// kind of bad input is refused with a message that names the file and the column.
#include "base/exceptions.h"
#include "io/signal_file.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

using wearlink::io::read_time_signal;

namespace
{
  std::string
  write_signal(const std::string &name, const std::string &text)
  {
    const std::string file = wearlink::testing::fresh_directory("signal_" + name) + "/" + name + ".csv";
    std::ofstream(file) << text;
    return file;
  }

  /** A header and @p n rows t = i ms, value = i; @p tweak edits the text. */
  std::string
  rows(const std::string &header, const int n, const std::string &extra_column = "")
  {
    std::ostringstream s;
    s << header << "\n";
    for (int i = 0; i < n; ++i)
      s << i * 1e-3 << "," << i << extra_column << "\n";
    return s.str();
  }

  std::string
  message(const std::string &file, const std::string &column)
  {
    return wearlink::testing::input_error_message(
      [&] { read_time_signal(file, column, "measured signal", "--column"); });
  }
} // namespace

TEST(SignalFile, ReadsTheOnlyValueColumnOrTheNamedOne)
{
  const auto one = read_time_signal(write_signal("one", rows("time_s,a_m_s2", 20)), "", "measured signal", "--column");
  EXPECT_EQ(one.column, "a_m_s2");
  ASSERT_EQ(one.values.size(), 20u);
  EXPECT_DOUBLE_EQ(one.time[5], 5e-3);
  EXPECT_DOUBLE_EQ(one.values[5], 5);
  const auto two =
    read_time_signal(write_signal("two", rows("time_s,a,b", 20, ",7")), "b", "measured signal", "--column");
  EXPECT_EQ(two.values[3], 7);
}

TEST(SignalFile, BadInputNamesTheFileAndTheColumn)
{
  const std::string missing = message("/no/such/measured.csv", "");
  EXPECT_NE(missing.find("/no/such/measured.csv"), std::string::npos) << missing;

  const std::string file_b = write_signal("no_column", rows("time_s,a", 20));
  const std::string no_col = message(file_b, "accel");
  EXPECT_NE(no_col.find(file_b), std::string::npos) << no_col;
  EXPECT_NE(no_col.find("'accel'"), std::string::npos) << no_col;
  EXPECT_NE(no_col.find("--column"), std::string::npos) << no_col;

  const std::string several = message(write_signal("several", rows("time_s,a,b", 20, ",1")), "");
  EXPECT_NE(several.find("--column"), std::string::npos) << several;

  const std::string no_time = message(write_signal("no_time", rows("t,a", 20)), "");
  EXPECT_NE(no_time.find("'time_s'"), std::string::npos) << no_time;

  std::string text = rows("time_s,a", 20);
  text += "0.005,3\n"; // back in time
  const std::string back = message(write_signal("non_monotone", text), "a");
  EXPECT_NE(back.find("'time_s'"), std::string::npos) << back;
  EXPECT_NE(back.find("line 22"), std::string::npos) << back;

  std::string nan = rows("time_s,a", 20);
  nan += "0.5,nan\n";
  const std::string not_a_number = message(write_signal("nan", nan), "a");
  EXPECT_NE(not_a_number.find("column 'a'"), std::string::npos) << not_a_number;
  EXPECT_NE(not_a_number.find("line 22"), std::string::npos) << not_a_number;

  const std::string file_few = write_signal("few", rows("time_s,a", 5));
  const std::string few      = message(file_few, "a");
  EXPECT_NE(few.find(file_few), std::string::npos) << few;
  EXPECT_NE(few.find("at least 16"), std::string::npos) << few;
}
