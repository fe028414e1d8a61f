// SPDX-License-Identifier: LGPL-2.1-or-later
// The identity of a scene for resuming a wear run: its effective entries
// ("Section/Subsection/Entry" → value, --set overrides applied) without those that
// only say how far to go and what to write (run control: Output/*, Wear/Number of
// iterations, Wear/Target revolutions, Wear/FE output, Wear/Profile magnification,
// Life/Maximum revolutions, Life/Maximum iterations, Life/Response tolerance), and
// a fingerprint of them (64-bit FNV-1a, the same on every platform). A checkpoint keeps
// both, so that a resume with another scene is refused with the entries that differ.
#pragma once

#include "io/scene.h"

#include <map>
#include <string>

namespace wearlink::workflows
{
  /** True for the entries a resume may change (see above). */
  bool
  is_run_control(const std::string &entry);

  /** The scene's entries that are not run control. */
  std::map<std::string, std::string>
  scene_entries(const io::Scene &scene);

  /** Hexadecimal fingerprint of @p entries. */
  std::string
  fingerprint(const std::map<std::string, std::string> &entries);

  /**
   * The entries that differ between @p was (a checkpoint's) and @p now, as
   * "'Title' is 'A' in the checkpoint and 'B' now; …" (at most @p shown of them, then
   * how many more); "" if none.
   */
  std::string
  scene_differences(const std::map<std::string, std::string> &was,
                    const std::map<std::string, std::string> &now,
                    unsigned int                              shown = 5);
} // namespace wearlink::workflows
