// SPDX-License-Identifier: LGPL-2.1-or-later
// run_concurrently(): every task runs once, no more than the allowed number at a time, and
// a task's exception reaches the caller only after every task has ended.
#include "base/concurrent.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>

using wearlink::run_concurrently;

namespace
{
  /** @p n tasks that count their runs and the most of them running at once. */
  std::vector<std::function<void()>>
  counting_tasks(const std::size_t n, std::vector<int> &runs, std::atomic<int> &running, std::atomic<int> &most)
  {
    runs.assign(n, 0);
    std::vector<std::function<void()>> tasks;
    for (std::size_t k = 0; k < n; ++k)
      tasks.push_back([&, k] {
        const int now = ++running;
        for (int seen = most.load(); now > seen && !most.compare_exchange_weak(seen, now);)
          ;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
        ++runs[k];
        --running;
      });
    return tasks;
  }
} // namespace

TEST(RunConcurrently, EveryTaskOnceAndNoMoreThanAllowedAtATime)
{
  for (const unsigned int threads : {1u, 2u, 3u})
    {
      std::vector<int> runs;
      std::atomic<int> running{0}, most{0};
      run_concurrently(counting_tasks(7, runs, running, most), threads);
      EXPECT_EQ(runs, std::vector<int>(7, 1)) << threads << " threads";
      EXPECT_LE(most.load(), static_cast<int>(threads));
      EXPECT_GE(most.load(), 1);
      EXPECT_EQ(running.load(), 0);
    }
  run_concurrently({}); // nothing to do: returns
}

TEST(RunConcurrently, TheFirstFailureIsRethrownAfterAllTasksEnded)
{
  std::vector<int> runs;
  std::atomic<int> running{0}, most{0};
  auto             tasks = counting_tasks(6, runs, running, most);
  tasks[4]               = [] {
    throw std::runtime_error("second");
  };
  tasks[1] = [] {
    throw std::runtime_error("first");
  };
  try
    {
      run_concurrently(tasks, 2);
      FAIL() << "no exception";
    }
  catch (const std::runtime_error &e)
    {
      EXPECT_STREQ(e.what(), "first");
    }
  EXPECT_EQ(runs, (std::vector<int>{1, 0, 1, 1, 0, 1})) << "the others ran to their end";
  EXPECT_EQ(running.load(), 0);
}
