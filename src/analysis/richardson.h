// SPDX-License-Identifier: LGPL-2.1-or-later
// Richardson extrapolation of a figure computed at three resolutions that refine by the
// same ratio r (e.g. discrete areas and wear step ×1, ×2, ×4). With f(h) ≈ f* + C h^p,
// the observed order is p = ln((f_1 − f_2)/(f_2 − f_3)) / ln r, the extrapolated value
// f* = f_3 + (f_3 − f_2)/(r^p − 1), and each level's error its distance from f*. The
// figures of a chaotic wear run are ensemble means with a standard error: the two
// differences must each exceed twice their noise and have the same sign (a monotone
// approach), and they must shrink by at least √r per level (observed order ≥ 0.5), else
// nothing is extrapolated and the reason is given. An observed order above 4 says the
// levels are not in the asymptotic range; it is reported, and the extrapolation is made
// with order 4 (the larger correction).
#pragma once

#include <string>

namespace wearlink::analysis
{
  /** Three levels of one figure, coarse to fine, with the standard error of each. */
  struct RefinementTriple
  {
    double ratio = 2;                  ///< refinement ratio between levels [-]
    double value[3]{0, 0, 0};          ///< coarse, medium, fine
    double standard_error[3]{0, 0, 0}; ///< of each value (same unit)
  };

  struct RichardsonEstimate
  {
    bool        determinable = false;
    double      order        = 0;  ///< observed p [-] (NaN if the differences do not allow one)
    double      extrapolated = 0;  ///< f* (NaN if not determinable)
    double      error[3]{0, 0, 0}; ///< (f_l − f*)/f* of each level [-] (NaN if not determinable)
    std::string reason;            ///< why not determinable, or a note on the order ("" if none)
  };

  /** The estimate of @p t (see the file comment). */
  RichardsonEstimate
  richardson(const RefinementTriple &t);
} // namespace wearlink::analysis
