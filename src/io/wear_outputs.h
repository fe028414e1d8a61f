// SPDX-License-Identifier: LGPL-2.1-or-later
// Files of a wear run (each written atomically; PNGs through gnuplot, io/plot.h):
//   wear_history.csv           per iteration: revolutions, factor, per joint worn volume
//                              [mm³], mass loss [mg] and largest depth [µm] per surface
//   wear_depth_<J>.csv/.png    cumulative wear depth vs body-frame angle on pin and
//                              bushing after each iteration (seed Fig 5)
//   profile_<J>_bore.png, profile_<J>_pin.png
//                              reconstructed surfaces, wear magnified by a stated factor
//                              (seed Figs 6–7); profiles_<J>.csv the radii (true scale)
//   profiles_<J>.msh           the worn bore and pin as closed gmsh curves (MSH 2.2,
//                              true scale, physical curves "bore" and "pin")
//   response_before.csv, response_after.csv, response.png
//                              acceleration of the response body before and after wear
//                              from the same initial state (seed Fig 8)
//   wear_volume.png            cumulative worn volume vs revolutions
#pragma once

#include "analysis/cycle_peaks.h"
#include "io/scene.h"
#include "mbs/simulation.h"
#include "wear/wear_state.h"

#include <string>
#include <vector>

namespace wearlink::io
{
  void
  write_wear_history(const std::string &path, const Scene &scene, const wear::WearState &state);

  /** Every file of the list above except wear_history.csv and response_before.csv. */
  void
  write_wear_outputs(const std::string                &dir,
                     const Scene                      &scene,
                     const wear::WearState            &state,
                     const analysis::ResponseRecorder &after);

  /** The recorded response as CSV: time_s, <body>_x_m, _y_m, _ax_m_s2, _ay_m_s2. */
  void
  write_response_csv(const std::string &path, const analysis::ResponseRecorder &response);

  /** Write the two closed curves as a gmsh MSH 2.2 ASCII file (true scale) [m]. */
  void
  write_profiles_msh(const std::string &path, const Profile &bore, const Profile &pin);
} // namespace wearlink::io
