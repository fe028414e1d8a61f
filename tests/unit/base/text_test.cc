// SPDX-License-Identifier: LGPL-2.1-or-later
// append_number() writes the characters iostream writes (time_series.csv and every number
// in messages go through it): the same digits at every precision, across magnitudes, at
// the switch between fixed and scientific notation, and for zero, infinities and NaN.
#include "base/text.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iomanip>
#include <limits>
#include <random>
#include <sstream>

namespace
{
  std::string
  by_stream(const double value, const int digits)
  {
    std::ostringstream os;
    os << std::setprecision(digits) << value;
    return os.str();
  }
} // namespace

TEST(AppendNumber, WritesWhatIostreamWrites)
{
  std::vector<double>                    values = {0.0,
                                                   -0.0,
                                                   1.0,
                                                   -1.0,
                                                   0.1,
                                                   1e-4,
                                                   9.99999999999e-5, // %g turns scientific below 1e-4
                                                   123456789012.0,
                                                   1e16,
                                                   0.5e-310, // subnormal
                                                   std::numeric_limits<double>::max(),
                                                   std::numeric_limits<double>::infinity(),
                                                   -std::numeric_limits<double>::infinity(),
                                                   std::numeric_limits<double>::quiet_NaN()};
  std::mt19937                           random(11);
  std::uniform_real_distribution<double> mantissa(-10.0, 10.0);
  std::uniform_int_distribution<int>     exponent(-30, 30);
  for (int k = 0; k < 2000; ++k)
    values.push_back(mantissa(random) * std::pow(10.0, exponent(random)));
  for (const int digits : {1, 2, 4, 6, 10, 12, 15, 17, 20, 0})
    for (const double v : values)
      {
        std::string appended = "x=";
        wearlink::append_number(appended, v, digits);
        ASSERT_EQ(appended, "x=" + by_stream(v, digits)) << "value " << by_stream(v, 17) << ", digits " << digits;
        ASSERT_EQ(wearlink::format_number(v, digits), by_stream(v, digits));
      }
}
