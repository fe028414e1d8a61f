// SPDX-License-Identifier: LGPL-2.1-or-later
// The FE layer calls the BLAS from several threads at once: the condensed solver's
// factorization in two tasks, and the compliance columns on every core (CHOLMOD's
// supernodal solves). That is safe with OpenBLAS's threaded builds (Debian
// libopenblas0-pthread, what bootstrap.sh installs), the reference BLAS or MKL, but not
// with OpenBLAS's serial build (libopenblas0-serial: its buffer pool has no locks; two
// threads' dtrsm/dgemm were measured to corrupt each other's results in 3 of 20 trials).
// And a threaded OpenBLAS must not start threads of its own inside those tasks (a worn
// pair's compliance columns took 38 s with 2 OpenBLAS threads per task against 10.6 s
// with 1).
#pragma once

namespace wearlink::fe
{
  /**
   * Once per process: a threaded OpenBLAS is set to one thread per call; true if the
   * loaded BLAS may be called from several threads at once (false for OpenBLAS's serial
   * build, with a note on stderr the first time). The FE layer's parallel tasks that
   * call the BLAS run one after the other when false.
   */
  bool
  blas_is_thread_safe();
} // namespace wearlink::fe
