// SPDX-License-Identifier: LGPL-2.1-or-later
// SIGINT, SIGTERM and SIGHUP stop a run cleanly. The handlers (installed by the program's
// main(), never by the library or the tests) only record the signal; the run notices
// it at its next check (every accepted integrator step, every wear iteration, before a
// file written by another program is moved into place) and throws Interrupted, so that
// unwinding removes every temporary file (AtomicFile, TemporaryDirectory) and main()
// exits with 128 + the signal. A second signal does not wait: the handler removes the
// temporary files registered below (unlink is async-signal-safe) and leaves at once
// with _exit(128 + signal). What a SIGKILL leaves behind is removed by the next run in
// the same directory (remove_stale_partials in base/atomic_file.h).
#pragma once

#include <signal.h>
#include <string>

namespace wearlink
{
  /**
   * Install the SIGINT, SIGTERM and SIGHUP handlers (once per process; main() only); a
   * SIGHUP ignored at the start (nohup) stays ignored. SIGXFSZ is ignored: a file past
   * the file-size limit is a failed write (EFBIG), not a killed program.
   */
  void
  install_interrupt_handlers();

  /**
   * While it lives, SIGINT stops a run as it does the program's (the handler of
   * install_interrupt_handlers(): the run throws Interrupted at its next check; a second
   * SIGINT leaves at once); the handler that was there before — an embedding
   * interpreter's — is put back at its end, and a signal recorded in between is
   * forgotten. For a library caller (the Python module) that runs wearlink in its main
   * thread; not nested.
   */
  class InterruptScope
  {
  public:
    InterruptScope();
    ~InterruptScope();
    InterruptScope(const InterruptScope &) = delete;
    InterruptScope &
    operator=(const InterruptScope &) = delete;

  private:
    struct sigaction previous; ///< the SIGINT action before
  };

  /** The signal received so far, or 0. */
  int
  interrupt_signal();

  /** Throw Interrupted if a signal arrived (the check points named above). */
  void
  throw_if_interrupted();

  /** The name of @p signal_number ("SIGTERM"). */
  std::string
  signal_name(int signal_number);

  /**
   * While it lives, @p path is removed by the handler of a second signal. A fixed number
   * of paths can be registered (files open at the same time); beyond that a path is
   * simply not registered (the next run removes it). Paths longer than 4095 bytes are
   * not registered either.
   */
  class RegisteredTemporary
  {
  public:
    explicit RegisteredTemporary(const std::string &path);
    ~RegisteredTemporary();
    RegisteredTemporary(const RegisteredTemporary &) = delete;
    RegisteredTemporary &
    operator=(const RegisteredTemporary &) = delete;

  private:
    int slot = -1;
  };
} // namespace wearlink
