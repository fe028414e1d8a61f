// SPDX-License-Identifier: LGPL-2.1-or-later
#include "base/interrupt.h"

#include "base/exceptions.h"

#include <atomic>
#include <csignal>
#include <cstring>
#include <unistd.h>

namespace wearlink
{
  namespace
  {
    volatile std::sig_atomic_t received = 0;

    // The registry of temporary files: a slot is free, being filled by the program, or
    // ready (its path complete). The handler only reads ready slots.
    constexpr int         n_slots    = 64;
    constexpr std::size_t path_bytes = 4096;
    constexpr int         free_slot = 0, filling = 1, ready = 2;
    static_assert(std::atomic<int>::is_always_lock_free, "the handler reads the slots' states");
    std::atomic<int> slot_state[n_slots];
    char             slot_path[n_slots][path_bytes];

    /** Async-signal-safe: a flag, unlink() and _exit() only. */
    void
    on_signal(const int signal_number)
    {
      if (received == 0)
        {
          received = signal_number;
          return;
        }
      for (int k = 0; k < n_slots; ++k)
        if (slot_state[k].load() == ready)
          ::unlink(slot_path[k]);
      ::_exit(128 + signal_number);
    }
  } // namespace

  void
  install_interrupt_handlers()
  {
    struct sigaction action;
    std::memset(&action, 0, sizeof(action));
    action.sa_handler = on_signal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;
    ::sigaction(SIGINT, &action, nullptr);
    ::sigaction(SIGTERM, &action, nullptr);
    // SIGHUP (the terminal or the ssh session closed) stops a run as SIGTERM does,
    // unless it was ignored when the program started (nohup): then it stays ignored.
    struct sigaction hangup;
    if (::sigaction(SIGHUP, nullptr, &hangup) == 0 && hangup.sa_handler != SIG_IGN)
      ::sigaction(SIGHUP, &action, nullptr);
    // A file that grows past the user's file-size limit (ulimit -f) would kill the
    // program with SIGXFSZ; ignored, the write fails with EFBIG and is reported as a
    // failed write (exit 4, the file named), as on a full disk.
    ::signal(SIGXFSZ, SIG_IGN);
  }

  InterruptScope::InterruptScope()
  {
    struct sigaction action;
    std::memset(&action, 0, sizeof(action));
    action.sa_handler = on_signal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;
    received        = 0;
    ::sigaction(SIGINT, &action, &previous);
  }

  InterruptScope::~InterruptScope()
  {
    ::sigaction(SIGINT, &previous, nullptr);
    received = 0;
  }

  int
  interrupt_signal()
  {
    return received;
  }

  std::string
  signal_name(const int signal_number)
  {
    if (signal_number == SIGINT)
      return "SIGINT";
    if (signal_number == SIGTERM)
      return "SIGTERM";
    if (signal_number == SIGHUP)
      return "SIGHUP";
    return "signal " + std::to_string(signal_number);
  }

  void
  throw_if_interrupted()
  {
    const int s = received;
    if (s != 0)
      throw Interrupted("Stopped by " + signal_name(s) +
                          "; the temporary files of unfinished outputs are removed. A wear run "
                          "continues from its last checkpoint with `wearlink run SCENE.prm --resume DIR`.",
                        s);
  }

  RegisteredTemporary::RegisteredTemporary(const std::string &path)
  {
    if (path.size() >= path_bytes)
      return;
    for (int k = 0; k < n_slots; ++k)
      {
        int expected = free_slot;
        if (slot_state[k].compare_exchange_strong(expected, filling))
          {
            std::memcpy(slot_path[k], path.c_str(), path.size() + 1);
            slot_state[k].store(ready);
            slot = k;
            return;
          }
      }
  }

  RegisteredTemporary::~RegisteredTemporary()
  {
    if (slot >= 0)
      slot_state[slot].store(free_slot);
  }
} // namespace wearlink
