// SPDX-License-Identifier: LGPL-2.1-or-later
// Wall-clock timing of a run's phases: one typed record instead of names typed into
// maps, and one stopwatch for the whole tree.
#pragma once

#include "base/json.h"

#include <chrono>

namespace wearlink
{
  /** Measures wall time from its construction (or the last restart()). */
  class Stopwatch
  {
  public:
    Stopwatch()
      : start(std::chrono::steady_clock::now())
    {
    }

    /** Seconds since construction or the last restart(). */
    double
    seconds() const
    {
      return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }

    void
    restart()
    {
      start = std::chrono::steady_clock::now();
    }

  private:
    std::chrono::steady_clock::time_point start;
  };

  /** Adds the wall time from its construction to its destruction to a running sum [s]. */
  class ScopedSeconds
  {
  public:
    explicit ScopedSeconds(double &sum)
      : sum(sum)
    {
    }
    ~ScopedSeconds()
    {
      sum += clock.seconds();
    }
    ScopedSeconds(const ScopedSeconds &) = delete;
    ScopedSeconds &
    operator=(const ScopedSeconds &) = delete;

  private:
    double         &sum;
    const Stopwatch clock;
  };

  /**
   * Wall time spent in the phases of a (wear) run [s]. Pressure models fill the FE
   * phases (meshing, set-up, compliance); the wear loop and the workflows the rest.
   */
  struct PhaseTimings
  {
    double dynamics            = 0; ///< integrating the mechanism
    double meshing             = 0; ///< gmsh
    double fe_setup            = 0; ///< FE assembly and factorization
    double fe_compliance       = 0; ///< condensed compliance columns
    double pressure_evaluation = 0; ///< pressure models on the load history
    /** Normal force laws built from the geometry (the fe law's tables, FE set-up included when a build made the model). */
    double contact_law_tables    = 0;
    double wear_bookkeeping      = 0; ///< Archard sums, profiles, checkpoints
    double outputs               = 0; ///< files and plots
    double before_after_dynamics = 0; ///< the before/after-wear comparison runs
    double total                 = 0; ///< the whole run

    PhaseTimings &
    operator+=(const PhaseTimings &other);

    /** As summary.json's `wear_timing_s` (keys as in doc/performance.md). */
    Json
    to_json() const;

    /**
     * From to_json()'s object; false (and @p out untouched) if a key is missing or not a
     * number.
     */
    static bool
    from_json(const Json &j, PhaseTimings &out);
  };
} // namespace wearlink
