// SPDX-License-Identifier: LGPL-2.1-or-later
// Shared set-up of the contract tests that run over a registry (laws_test.cc,
// pressure_contract_test.cc): a registered plugin constructed with the entries a test
// gives it, and the GoogleTest name of a plugin's name.
#pragma once

#include "base/parameters.h"
#include "base/registry.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace wearlink::contact::testing
{
  /**
   * Plugin @p name of @p registry with @p entries set in its subsection; an entry the
   * plugin does not declare (one of another plugin of the family) is left out, so that
   * one list serves every member.
   */
  template <class Interface>
  std::unique_ptr<Interface>
  make_plugin(const Registry<Interface>                              &registry,
              const std::string                                      &name,
              const std::vector<std::pair<std::string, std::string>> &entries)
  {
    dealii::ParameterHandler prm;
    registry.declare_all(prm);
    prm.enter_subsection(name);
    for (const auto &[entry, value] : entries)
      try
        {
          prm.set(entry, value);
        }
      catch (const dealii::ExceptionBase &) // not an entry of this plugin
        {
        }
    prm.leave_subsection();
    ParameterReader reader(prm, "test");
    return registry.create(name, reader, registry.family());
  }

  /** The test name of a plugin: its registered name with '-' as '_' ("hertz-strip" → "hertz_strip"). */
  inline std::string
  plugin_test_name(const ::testing::TestParamInfo<std::string> &info)
  {
    std::string n = info.param;
    std::replace(n.begin(), n.end(), '-', '_');
    return n;
  }
} // namespace wearlink::contact::testing
