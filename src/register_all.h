// SPDX-License-Identifier: LGPL-2.1-or-later
// Explicit plugin registration: one function per layer, called once by every executable.
#pragma once

namespace wearlink
{
  /** Fill every registry (idempotent). */
  void
  register_all();
} // namespace wearlink
