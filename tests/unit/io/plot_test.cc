// SPDX-License-Identifier: LGPL-2.1-or-later
// The envelope a long line is drawn from (io::line_envelope): what a plot of a given width
// can show of a 100-cycle history must survive the thinning — every bin's extremes, the
// ends, the order — and a short or unordered series must pass unchanged.
#include "io/plot.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

using wearlink::io::line_envelope;

namespace
{
  /** A force-like history: noise, rare spikes, n samples over [0, 50] s. */
  void
  spiky_history(const std::size_t n, std::vector<double> &x, std::vector<double> &y)
  {
    std::mt19937                           random(7);
    std::uniform_real_distribution<double> noise(0.0, 50.0);
    x.resize(n);
    y.resize(n);
    for (std::size_t j = 0; j < n; ++j)
      {
        x[j] = 50.0 * static_cast<double>(j) / static_cast<double>(n - 1);
        y[j] = noise(random) + (j % 997 == 0 ? 1000.0 + static_cast<double>(j % 13) : 0.0);
      }
  }
} // namespace

TEST(LineEnvelope, KeepsEveryBinsExtremesInOrder)
{
  std::vector<double> x, y;
  spiky_history(50001, x, y);
  const int  columns = 1200;
  const auto keep    = line_envelope(x, y, columns);
  // Few points: at most first, lowest, highest and last per half-pixel bin (+ the end).
  EXPECT_LE(keep.size(), 4u * 2u * columns + 1u);
  EXPECT_LT(keep.size(), x.size() / 5);
  ASSERT_FALSE(keep.empty());
  EXPECT_EQ(keep.front(), 0u);
  EXPECT_EQ(keep.back(), x.size() - 1);
  EXPECT_TRUE(std::is_sorted(keep.begin(), keep.end()));
  EXPECT_EQ(std::adjacent_find(keep.begin(), keep.end()), keep.end()) << "an index kept twice";
  // Every half-pixel bin keeps its own lowest and highest value.
  const std::size_t   bins  = 2 * columns;
  const double        width = 50.0 / static_cast<double>(bins);
  std::vector<double> low(bins + 1, std::numeric_limits<double>::infinity()), high(bins + 1, -low[0]);
  std::vector<double> kept_low = low, kept_high = high;
  const auto          bin_of = [&](const std::size_t j) {
    return static_cast<std::size_t>(std::floor(x[j] / width));
  };
  for (std::size_t j = 0; j < x.size(); ++j)
    {
      low[bin_of(j)]  = std::min(low[bin_of(j)], y[j]);
      high[bin_of(j)] = std::max(high[bin_of(j)], y[j]);
    }
  for (const auto j : keep)
    {
      kept_low[bin_of(j)]  = std::min(kept_low[bin_of(j)], y[j]);
      kept_high[bin_of(j)] = std::max(kept_high[bin_of(j)], y[j]);
    }
  EXPECT_EQ(kept_low, low);
  EXPECT_EQ(kept_high, high);
}

TEST(LineEnvelope, ShortUnorderedOrGappedSeriesPassWhole)
{
  std::vector<double> x, y;
  spiky_history(2000, x, y); // ≤ 8 points per bin at 1200 columns
  EXPECT_EQ(line_envelope(x, y, 1200).size(), x.size());
  spiky_history(50001, x, y);
  EXPECT_EQ(line_envelope(x, y, 0).size(), x.size()) << "no width: no thinning";
  auto gapped = y;
  gapped[100] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(line_envelope(x, gapped, 1200).size(), x.size()) << "a gap is drawn as a gap";
  auto orbit = x;
  std::swap(orbit[10], orbit[11]); // x not increasing: an orbit, not a history
  EXPECT_EQ(line_envelope(orbit, y, 1200).size(), x.size());
  EXPECT_EQ(line_envelope({}, {}, 1200).size(), 0u);
}
