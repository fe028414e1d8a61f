// SPDX-License-Identifier: LGPL-2.1-or-later
// Files of a life run (`wearlink life`, workflows/life.h), each written atomically:
//   life_history.csv  one row per wear iteration (row 0: the start): iteration,
//                     revolutions, factor, per criterion its value (<name>_<unit>) and
//                     the joint that has it (<name>_joint), and with the response
//                     criterion the response measure (response_measure_m_s2); doubles to
//                     17 digits, so that a resumed run reads its history back exactly;
//   life.png          every criterion's value as a fraction of its limit against
//                     revolutions (1: reached), the crossings marked.
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
} // namespace wearlink::io
