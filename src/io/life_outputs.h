// SPDX-License-Identifier: LGPL-2.1-or-later
// Files of a life run (`wearlink life`, workflows/wear/life.h), each written atomically:
//   life_history.csv  one row per wear iteration (row 0: the start): iteration,
//                     revolutions, factor, per criterion its value (<name>_<unit>) and
//                     the joint that has it (<name>_joint), and with the response
//                     criterion the response measure (response_measure_m_s2); doubles to
//                     17 digits, so that a resumed run reads its history back exactly;
//   life.png          every criterion's value as a fraction of its limit against
//                     revolutions (1: reached), the wear crossings marked; the response
//                     criterion with the trend of the model its measurements chose
//                     (analysis/response_models.h), its 95 % band, the measurements as a
//                     rise over that model's fresh level, and the 95 % interval of its
//                     crossing; the criterion's own value in each row is the chosen
//                     trend's rise on the measurements up to that row;
//   the ensemble's life.png: per criterion the band (smallest to largest) of the members'
//                     value / limit against revolutions, their median, and the spread
//                     P10 … P90 of the members' decided crossings.
#pragma once

#include "analysis/life_criteria.h"

#include <string>

namespace wearlink::io
{
  void
  write_life_history(const std::string &path, const analysis::LifeHistory &history);

  /**
   * The history in @p path, written by write_life_history for @p criteria (InputError
   * naming the file if it is missing or its columns are not those of these criteria).
   */
  analysis::LifeHistory
  read_life_history(const std::string &path, const std::vector<analysis::CriterionSpec> &criteria);

  /** life.png; false (and a note on stderr) without gnuplot. */
  bool
  plot_life(const std::string &path, const analysis::LifeHistory &history, const std::string &title);

  /** One criterion's decided crossings over an ensemble's members [revolutions]. */
  struct CrossingSpread
  {
    std::string criterion; ///< CriterionSpec::name
    double      p10 = 0, p50 = 0, p90 = 0;
  };

  /** A trend criterion's crossing on the members' mean response, with its 95 % interval [rev]. */
  struct MeanTrendCrossing
  {
    std::string criterion; ///< CriterionSpec::name
    double      at = 0, low = 0, high = 0;
  };

  /**
   * The ensemble's life.png from the members' histories (the same criteria, in the same
   * order): per criterion the band of value / limit over the members that ran that far,
   * its median (percentile type 7), @p spreads at the limit, and the interval of each
   * of @p trends. False (and a note on stderr) without gnuplot.
   */
  bool
  plot_life_ensemble(const std::string                        &path,
                     const std::vector<analysis::LifeHistory> &members,
                     const std::vector<CrossingSpread>        &spreads,
                     const std::vector<MeanTrendCrossing>     &trends,
                     const std::string                        &title);
} // namespace wearlink::io
