// SPDX-License-Identifier: LGPL-2.1-or-later
#include "base/effect_ledger.h"

namespace wearlink
{
  namespace
  {
    const std::string constructed = "constructed";
    const std::string resource    = "resources";
    const std::string call        = "calls";
  } // namespace

  EffectLedger &
  EffectLedger::instance()
  {
    static EffectLedger ledger;
    return ledger;
  }

  void
  EffectLedger::record_construction(const std::string &family, const std::string &name)
  {
    std::lock_guard<std::mutex> lock(mutex);
    ++counts[constructed][family + "/" + name];
  }

  void
  EffectLedger::add_resource(const std::string &what, long n)
  {
    std::lock_guard<std::mutex> lock(mutex);
    counts[resource][what] += n;
  }

  void
  EffectLedger::add_calls(const std::string &what, long n)
  {
    std::lock_guard<std::mutex> lock(mutex);
    counts[call][what] += n;
  }

  long
  EffectLedger::constructions(const std::string &family, const std::string &name) const
  {
    std::lock_guard<std::mutex> lock(mutex);
    const auto                  c = counts.find(constructed);
    if (c == counts.end())
      return 0;
    const auto e = c->second.find(family + "/" + name);
    return e == c->second.end() ? 0 : e->second;
  }

  long
  EffectLedger::constructions(const std::string &family) const
  {
    std::lock_guard<std::mutex> lock(mutex);
    const auto                  c = counts.find(constructed);
    if (c == counts.end())
      return 0;
    long n = 0;
    for (const auto &[key, value] : c->second)
      if (key.compare(0, family.size() + 1, family + "/") == 0)
        n += value;
    return n;
  }

  long
  EffectLedger::resources(const std::string &what) const
  {
    std::lock_guard<std::mutex> lock(mutex);
    const auto                  c = counts.find(resource);
    if (c == counts.end())
      return 0;
    const auto e = c->second.find(what);
    return e == c->second.end() ? 0 : e->second;
  }

  long
  EffectLedger::calls(const std::string &what) const
  {
    std::lock_guard<std::mutex> lock(mutex);
    const auto                  c = counts.find(call);
    if (c == counts.end())
      return 0;
    const auto e = c->second.find(what);
    return e == c->second.end() ? 0 : e->second;
  }

  std::map<std::string, std::map<std::string, long>>
  EffectLedger::snapshot() const
  {
    std::lock_guard<std::mutex> lock(mutex);
    return counts;
  }

  void
  EffectLedger::restore(const std::map<std::string, std::map<std::string, long>> &c)
  {
    std::lock_guard<std::mutex> lock(mutex);
    counts = c;
  }

  void
  EffectLedger::reset()
  {
    std::lock_guard<std::mutex> lock(mutex);
    counts.clear();
  }
} // namespace wearlink
