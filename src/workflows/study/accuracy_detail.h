// SPDX-License-Identifier: LGPL-2.1-or-later
// What the accuracy study's knobs (accuracy_knobs.cc) and its runs (accuracy_study.cc)
// share. Internal to those two files.
#pragma once

#include "base/parameters.h"
#include "io/scene.h"
#include "workflows/study/accuracy_study.h"

#include <string>
#include <vector>

namespace wearlink::workflows::accuracy_detail
{
  /** The value of entry "Section/Sub/Entry" of the scene's parameters. */
  std::string
  entry_of(const io::Scene &scene, const std::string &path);

  /** @p base, then the settings of value @p v of knob @p k. */
  ParameterOverrides
  with_knob_value(const ParameterOverrides &base, const Knob &k, const std::vector<std::string> &v);
} // namespace wearlink::workflows::accuracy_detail
