// SPDX-License-Identifier: LGPL-2.1-or-later
// The evolving state of a wear run, and its checkpoint (ARCHITECTURE.md wear/):
// everything needed to continue a run after its last finished iteration exactly as an
// uninterrupted run would: the mechanism state [q | v | z] and time at the end of the
// iteration, each joint's contact mode and captured impact velocity, the worn profiles
// (and those the fe model was last meshed with), the cumulative volumes and the
// per-iteration history used by the outputs. The checkpoint is JSON (format name and
// version first); doubles are written in the shortest form that reads back to the same
// bits (exact round trip), and the file is replaced atomically, so a run killed at any
// moment leaves the previous complete checkpoint. Reading checks every entry's type;
// a damaged file is an InputError naming the file and the entry.
#pragma once

#include "base/profile.h"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace wearlink::wear
{
  /** Per joint and iteration: what the outputs plot and the summary reports. */
  struct IterationRecord
  {
    double              volume_pin           = 0; ///< cumulative Σ h A removed from the pin [m³]
    double              volume_bore          = 0; ///< cumulative, bore [m³]
    double              archard_pin          = 0; ///< cumulative k_D ∫ F_n |v_t| dt, pin k_D [m³]
    double              archard_bore         = 0;
    double              max_depth_pin        = 0; ///< cumulative [m]
    double              max_depth_bore       = 0; ///< cumulative [m]
    double              mean_normal_force    = 0; ///< over the simulated cycles [N]
    double              sliding_distance     = 0; ///< cumulative, extrapolated [m]
    double              relative_revolutions = 0; ///< cumulative, extrapolated [-]
    std::vector<double> depth_pin;                ///< cumulative depth per pin area [m]
    std::vector<double> depth_bore;               ///< cumulative depth per bore area [m]
  };

  struct JointWearState
  {
    std::string name;
    Profile     initial_bore, initial_pin; ///< at the start of the run
    Profile     bore, pin;                 ///< current worn profiles
    Profile     meshed_bore, meshed_pin;   ///< geometry of the pressure model's mesh (fe; else = bore, pin)
    std::vector<IterationRecord> history;  ///< one per finished iteration
  };

  struct WearState
  {
    std::string         fingerprint; ///< of the scene (resume refuses another scene)
    unsigned int        iterations_done = 0;
    double              revolutions     = 0; ///< mechanism revolutions represented so far
    double              time            = 0; ///< simulated time at the end of the last iteration [s]
    Eigen::VectorXd     state;               ///< [q | v | z] there
    std::vector<double> factors;             ///< extrapolation factor of each iteration
    /** Per clearance joint of the scene (worn or not): contact mode (0/1), δ̇⁻ [m/s]. */
    std::vector<double>         modes;
    std::vector<JointWearState> joints;

    /** Write to @p path atomically. */
    void
    write(const std::string &path) const;

    /** Read from @p path; InputError naming the file if it is missing or malformed. */
    static WearState
    read(const std::string &path);
  };
} // namespace wearlink::wear
