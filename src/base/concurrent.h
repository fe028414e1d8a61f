// SPDX-License-Identifier: LGPL-2.1-or-later
// Independent tasks on the machine's cores: the plots of a run, each drawn by its own
// gnuplot process, need not wait for each other.
#pragma once

#include <functional>
#include <vector>

namespace wearlink
{
  /**
   * Run every task of @p tasks, at most @p threads at a time (0: as many as the machine
   * has cores), in the order given as threads free up; return when all have ended. If
   * tasks threw, the first of their exceptions (in the tasks' order) is rethrown then.
   * The tasks must not share unguarded state.
   */
  void
  run_concurrently(const std::vector<std::function<void()>> &tasks, unsigned int threads = 0);
} // namespace wearlink
