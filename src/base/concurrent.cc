// SPDX-License-Identifier: LGPL-2.1-or-later
#include "base/concurrent.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <system_error>
#include <thread>

namespace wearlink
{
  void
  run_concurrently(const std::vector<std::function<void()>> &tasks, unsigned int threads)
  {
    if (threads == 0)
      threads = std::max(1u, std::thread::hardware_concurrency());
    threads = std::min<unsigned int>(threads, static_cast<unsigned int>(tasks.size()));
    std::vector<std::exception_ptr> failures(tasks.size());
    std::atomic<std::size_t>        next{0};
    const auto                      work = [&] {
      for (std::size_t k = next++; k < tasks.size(); k = next++)
        try
          {
            tasks[k]();
          }
        catch (...)
          {
            failures[k] = std::current_exception();
          }
    };
    std::vector<std::thread> helpers;
    try
      {
        for (unsigned int t = 1; t < threads; ++t)
          helpers.emplace_back(work);
      }
    catch (const std::system_error &) // no thread to be had: the calling thread does the rest
      {
      }
    work();
    for (auto &h : helpers)
      h.join();
    for (const auto &f : failures)
      if (f)
        std::rethrow_exception(f);
  }
} // namespace wearlink
