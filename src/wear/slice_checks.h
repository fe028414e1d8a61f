// SPDX-License-Identifier: LGPL-2.1-or-later
// The wear loop's explicit axial feedback of a sliced joint (doc/models.md §1.8): the
// dynamics of an iteration see the geometry it started from, so a slice that wears more
// in one iteration than the slices' elastic approach takes itself out of contact and
// throws its load on the others — the axial distribution then oscillates from iteration
// to iteration instead of wearing in. The check compares, per iteration, the largest
// depth increment of a slice (bore and pin) with the elastic approach of a slice under
// the slices' mean force, δ = (F̄/K)^(1/n) of the slice's point law; beyond twice the
// approach (measured: 1.0 wears in monotonically, 3.8 oscillates) it warns.
#pragma once

#include "base/validity_warnings.h"
#include "contact/clearance_joint.h"
#include "wear/wear_state.h"

#include <vector>

namespace wearlink::wear
{
  /**
   * Warn (in @p warnings) about a sliced joint among @p joints whose largest per-iteration
   * depth increment in @p state exceeds that approach.
   */
  void
  check_axial_increments(const WearState                              &state,
                         const std::vector<contact::ClearanceJoint *> &joints,
                         ValidityWarnings                             &warnings);
} // namespace wearlink::wear
