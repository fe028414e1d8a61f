// SPDX-License-Identifier: LGPL-2.1-or-later
#include "analysis/richardson.h"

#include "base/numbers.h"
#include "base/text.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace wearlink::analysis
{
  namespace
  {
    using numbers::nan;

    /** Not determinable, with why. */
    RichardsonEstimate
    undetermined(const std::string &why)
    {
      RichardsonEstimate e;
      e.order = e.extrapolated = nan;
      e.error[0] = e.error[1] = e.error[2] = nan;
      e.reason                             = why;
      return e;
    }
  } // namespace

  RichardsonEstimate
  richardson(const RefinementTriple &t)
  {
    for (int l = 0; l < 3; ++l)
      if (!std::isfinite(t.value[l]) || !(t.standard_error[l] >= 0))
        return undetermined("a level's value or standard error is not finite");
    if (!(t.ratio > 1))
      return undetermined("the refinement ratio is not above 1");
    if (t.value[0] == 0 && t.value[1] == 0 && t.value[2] == 0)
      return undetermined("no wear at any level");
    const double d_coarse = t.value[1] - t.value[0], d_fine = t.value[2] - t.value[1];
    const auto   noise = [&](int a, int b) {
      return std::hypot(t.standard_error[a], t.standard_error[b]);
    };
    if (std::abs(d_coarse) <= 2 * noise(0, 1) || std::abs(d_fine) <= 2 * noise(1, 2))
      return undetermined("a difference between levels is within twice its noise (the chaos floor)");
    if ((d_coarse > 0) != (d_fine > 0))
      return undetermined("the levels do not approach monotonically");
    const double order = std::log(d_coarse / d_fine) / std::log(t.ratio);
    if (!(order >= 0.5))
      {
        auto e  = undetermined("the differences do not shrink by at least √ratio per level (observed order " +
                              format_number(order, 3) + "): not converging at these levels");
        e.order = order;
        return e;
      }
    RichardsonEstimate e;
    e.determinable = true;
    e.order        = order;
    const double p = std::min(order, 4.0);
    if (p != order)
      e.reason = "observed order above 4 (not in the asymptotic range): extrapolated with order 4";
    e.extrapolated = t.value[2] + d_fine / (std::pow(t.ratio, p) - 1);
    for (int l = 0; l < 3; ++l)
      e.error[l] = e.extrapolated != 0 ? (t.value[l] - e.extrapolated) / e.extrapolated : nan;
    return e;
  }
} // namespace wearlink::analysis
