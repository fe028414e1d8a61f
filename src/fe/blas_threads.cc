// SPDX-License-Identifier: LGPL-2.1-or-later
#include "fe/blas_threads.h"

#include <dlfcn.h>
#include <iostream>
#include <mutex>

namespace wearlink::fe
{
  namespace
  {
    /** OpenBLAS's build kind (0 serial, 1 pthreads, 2 OpenMP), −1 for another BLAS. */
    int
    openblas_parallel_kind()
    {
      using Get      = int (*)();
      const auto get = reinterpret_cast<Get>(dlsym(RTLD_DEFAULT, "openblas_get_parallel"));
      return get != nullptr ? get() : -1;
    }

    bool
    prepare()
    {
      const int kind = openblas_parallel_kind();
      if (kind == 0)
        {
          std::cerr << "[wearlink] note: the BLAS is OpenBLAS's serial build, which is not safe to call from "
                       "several threads; the FE solver's dense work runs on one core. Install "
                       "libopenblas0-pthread (bootstrap.sh does) for all cores.\n";
          return false;
        }
      if (kind > 0)
        {
          using Set = void (*)(int);
          if (const auto set = reinterpret_cast<Set>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads")); set != nullptr)
            set(1);
        }
      return true;
    }
  } // namespace

  bool
  blas_is_thread_safe()
  {
    static std::once_flag once;
    static bool           safe = false;
    std::call_once(once, [] { safe = prepare(); });
    return safe;
  }
} // namespace wearlink::fe
