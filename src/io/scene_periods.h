// SPDX-License-Identifier: LGPL-2.1-or-later
// What a scene's periods and response are, asked by every command that counts cycles:
// the driving period (Poincaré sections, sweeps, the contact comparison's cycles), the
// cycle of a wear run (Wear/Cycle period or the driving period), and the body whose
// response a wear run and a life run measure.
#pragma once

#include "analysis/analyses_settings.h"
#include "io/scene.h"

namespace wearlink::io
{
  /**
   * The driving period of @p scene [s] under @p settings: Analyses/Driving period if
   * given, otherwise 2π/|ω| of its angle drivers, which must all turn at the same rate
   * (|ω| equal to 1e-12 relative), and larger than the section phase. InputError if
   * neither gives one.
   */
  double
  driving_period(const Scene &scene, const analysis::AnalysesSettings &settings);

  /** driving_period() under the scene's own Analyses settings. */
  double
  driving_period(const Scene &scene);

  /** The driving period of @p scene as driving_period() finds it, or 0 if there is none. */
  double
  driving_period_if_known(const Scene &scene);

  /** The period of one wear cycle [s]: Wear/Cycle period, or else the driving period. */
  double
  cycle_period(const Scene &scene);

  /**
   * Warn (into @p warnings) when a wear scene's Wear/Cycle period is given and the
   * driving period is known, but the cycle is no whole number of driving periods (to
   * 1e-3 of a period): each wear cycle would then cover another part of the revolution,
   * and the wear of a "cycle" would be that of a fraction of a revolution. A warning,
   * not an error: short cycles are a way to try a scene quickly.
   */
  void
  check_cycle_period(const Scene &scene, ValidityWarnings &warnings);

  /** Index of Wear/Response body (default: the last body); InputError if unknown. */
  int
  response_body(const Scene &scene);
} // namespace wearlink::io
