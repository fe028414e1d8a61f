// SPDX-License-Identifier: LGPL-2.1-or-later
// The effect ledger: proof that an effect a scene did not ask for costs nothing.
// It counts, for the whole process:
//   - constructions of effects, by family and plugin name ("normal force law" /
//     "lankarani-nikravesh");
//   - heavy resources created ("gmsh sessions", "triangulations", "factorizations", …);
//   - calls of expensive operations ("contact law evaluations", "fe solves", …).
// Hot paths keep their own counters and add them once (add_calls) at the end of a run,
// so the ledger is never on an inner loop. The run summary prints it; tests assert on it.
#pragma once

#include <map>
#include <mutex>
#include <string>

namespace wearlink
{
  class EffectLedger
  {
  public:
    static EffectLedger &
    instance();

    void
    record_construction(const std::string &family, const std::string &name);
    void
    add_resource(const std::string &what, long n = 1);
    void
    add_calls(const std::string &what, long n);

    long
    constructions(const std::string &family, const std::string &name) const;
    /** Constructions of any plugin of @p family. */
    long
    constructions(const std::string &family) const;
    long
    resources(const std::string &what) const;
    long
    calls(const std::string &what) const;

    /** Snapshot for the run summary: category -> key -> count. */
    std::map<std::string, std::map<std::string, long>>
    snapshot() const;

    /**
     * Replace every count by @p counts: a resumed wear run continues the ledger of its
     * checkpoint (which counted the set-up of the scene and the iterations before it).
     */
    void
    restore(const std::map<std::string, std::map<std::string, long>> &counts);

    /** Forget everything (tests, and each member of a sweep). */
    void
    reset();

  private:
    EffectLedger() = default;
    mutable std::mutex                                 mutex;
    std::map<std::string, std::map<std::string, long>> counts;
  };
} // namespace wearlink
