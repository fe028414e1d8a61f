// SPDX-License-Identifier: LGPL-2.1-or-later
// The worn profiles of a wear run as a ParaView series, to play the wear:
//   profiles/profile_<J>_<k>.vtu  after iteration k (k = 0: the unworn profiles): the bore
//                                 and the pin of joint J as two closed poly-lines at true
//                                 scale, each in its own body frame (centre at the origin),
//                                 with point data
//                                   wear_depth_m         cumulative depth of each area [m]
//                                   wear_displacement_m  the depth along the worn direction
//                                                        (outwards on the bore, inwards on
//                                                        the pin): ParaView's "Warp By
//                                                        Vector" with a scale of ~1000 shows
//                                                        the wear magnified
//                                   radius_m             the worn radius [m]
//                                   contact_pressure_Pa  the pressure model's pressure at the
//                                                        iteration's largest load, on the
//                                                        surfaces as they are after it
//                                 and cell data `surface` (0 bore, 1 pin);
//   profiles_<J>.pvd              the collection, time = revolutions after each iteration.
// Files are VTK XML (ASCII), each written atomically; the .pvd is rewritten after each
// iteration and lists the frames kept: every iteration's with Wear/Output every
// iteration, else the unworn profiles' (k = 0) and the last iteration's, each frame
// removing the one before (about 120 kB per frame at 360 areas: 5 MB for the 20
// iterations of two joints).
#pragma once

#include "contact/pressure_model.h"
#include "wear/wear_state.h"

#include <string>
#include <vector>

namespace wearlink::io
{
  /**
   * Write iteration @p state.iterations_done's profiles of joint @p joint (and those of
   * iteration 0 if they are missing) into @p dir/profiles/, with @p pressure (the
   * joint's pressure at the iteration's largest load; empty vectors: zero), remove the
   * frames of the iterations in between unless @p every_iteration, and rewrite
   * @p dir/profiles_<J>.pvd. @p cycles_per_iteration turns the factors into revolutions.
   */
  void
  write_profile_frame(const std::string              &dir,
                      const wear::WearState          &state,
                      unsigned int                    joint,
                      const contact::SurfacePressure &pressure,
                      double                          cycles_per_iteration,
                      bool                            every_iteration);

  /**
   * Remove the files @p dir/<prefix><k><suffix> of a numbered series (k a decimal
   * number) for every k that @p keep does not hold: what a run that keeps only some
   * iterations' files leaves of a series, also of its earlier processes (resume).
   */
  void
  remove_series_files(const std::string               &dir,
                      const std::string               &prefix,
                      const std::string               &suffix,
                      const std::vector<unsigned int> &keep);

  /**
   * A ParaView collection (.pvd) at @p path of @p files (paths relative to the .pvd's
   * folder) at @p times.
   */
  void
  write_pvd(const std::string &path, const std::vector<double> &times, const std::vector<std::string> &files);
} // namespace wearlink::io
