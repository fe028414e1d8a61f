// SPDX-License-Identifier: LGPL-2.1-or-later
// The evolving state of a wear run, and its checkpoint (doc/architecture.md §2):
// everything needed to continue a run after its last finished iteration exactly as an
// uninterrupted run would: the mechanism state [q | v | z] and time at the end of the
// iteration, each joint's contact mode and captured impact velocity, the worn profiles
// (and those the fe model was last meshed with), the cumulative volumes and the
// per-iteration history used by the outputs; and, so that a resumed run reports the
// whole run, the effect ledger, the phase timings and the validity warnings up to the
// checkpoint.
//
// The checkpoint (format version 7; 4 added the warnings, 5 the contact width and the
// depth measures, 6 the last iteration's wear rate and the response before wear, 7 the
// settling and the joints' start-up and carries) is JSON in two parts: a header line
//   {"format": "wearlink wear checkpoint", "version": 7, "payload_bytes": N,
//    "payload_crc32": "89abcdef",
// and the payload, `"payload": {...}}`, whose N bytes carry zlib's CRC-32. Reading
// checks, before anything is used: the header, the version, the length (a truncated
// file), the checksum (a changed byte), every entry's type, and that the sizes agree
// with each other (iterations, factors, history, profiles, depths); check_shape()
// then checks them against the scene of the resuming run. Any failure is an
// InputError naming the file and what is wrong; nothing of a refused checkpoint is
// used. Doubles are written in the shortest form that reads back to the same bits
// (exact round trip), and the file is replaced atomically (base/atomic_file.h), so a
// run killed at any moment leaves the previous complete checkpoint.
#pragma once

#include "base/profile.h"
#include "base/timings.h"
#include "base/validity_warnings.h"

#include <Eigen/Core>

#include <map>
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
    double              max_depth_pin        = 0; ///< cumulative, deepest area [m]
    double              max_depth_bore       = 0; ///< cumulative, deepest area [m]
    double              envelope_depth_pin   = 0; ///< cumulative, at the contact width [m] (wear/depth_measures.h)
    double              envelope_depth_bore  = 0; ///< cumulative, at the contact width [m]
    double              roughness_pin        = 0; ///< of the cumulative depth [-] (wear/depth_measures.h)
    double              roughness_bore       = 0; ///< [-]
    double              mean_normal_force    = 0; ///< over the simulated cycles [N]
    double              sliding_distance     = 0; ///< cumulative, extrapolated [m]
    double              relative_revolutions = 0; ///< cumulative, extrapolated [-]
    std::vector<double> depth_pin;                ///< cumulative depth per pin area [m]
    std::vector<double> depth_bore;               ///< cumulative depth per bore area [m]
  };

  /**
   * One iteration's wear per unit extrapolation factor, after smoothing (step 4 of the
   * wear loop applies f times it, or with Wear/Wear integration = adams-bashforth its
   * combination with the previous iteration's; wear/wear_step.h).
   */
  struct WearRate
  {
    std::vector<double> depth_pin, depth_bore;             ///< per area [m]
    double              volume_pin = 0, volume_bore = 0;   ///< [m³]
    double              archard_pin = 0, archard_bore = 0; ///< [m³]
    double              sliding_distance     = 0;          ///< [m]
    double              relative_revolutions = 0;          ///< [-]

    /** True before the first iteration (no rate known). */
    bool
    empty() const
    {
      return depth_pin.empty() && depth_bore.empty();
    }
  };

  /**
   * A wearing joint's start-up, over the settling cycles before the first iteration
   * (Wear/Settling cycles), and how the state was carried onto its worn profiles after
   * each iteration (WearLoop).
   */
  struct StartUp
  {
    double impacts           = 0; ///< contact onsets during the settling [-]
    double mean_normal_force = 0; ///< time mean of F_n over the settling [N]
    double peak_normal_force = 0; ///< largest F_n of the settling [N]
    double carries           = 0; ///< iterations that carried a contact onto new profiles [-]
    double largest_carry     = 0; ///< the largest move of the pin centre against the bore [m]
    double carry_failures    = 0; ///< carries whose force was not matched to 1e-9 (best point kept) [-]
  };

  struct JointWearState
  {
    std::string name;
    Profile     initial_bore, initial_pin; ///< at the start of the run
    Profile     bore, pin;                 ///< current worn profiles
    Profile     meshed_bore, meshed_pin;   ///< geometry of the pressure model's mesh (fe; else = bore, pin)
    std::vector<IterationRecord> history;  ///< one per finished iteration
    /**
     * The contact width the depth measures use [m]: 2b of the Hertz line contact of the
     * unworn radii at the largest normal force of the first iteration (0 before it).
     */
    double contact_width = 0;
    /** The last iteration's own rate (not combined; empty before the first iteration). */
    WearRate last_rate;
    /** The start-up and the carries of the state (see StartUp). */
    StartUp start_up;
  };

  /** What the scene of a resuming run needs of a state (WearState::check_shape). */
  struct StateShape
  {
    std::size_t n_state = 0; ///< [q | v | z]
    std::size_t n_modes = 0; ///< 2 per clearance joint
    struct Joint
    {
      std::string  name;
      unsigned int n_bore = 0, n_pin = 0; ///< profile samples
    };
    std::vector<Joint> joints; ///< the wearing joints, in order
  };

  struct WearState
  {
    std::string fingerprint; ///< of the scene (resume refuses another scene)
    /** The scene's entries ("Section/Entry" → value) that a resume must find unchanged. */
    std::map<std::string, std::string> scene;
    unsigned int                       iterations_done = 0;
    double                             revolutions     = 0; ///< mechanism revolutions represented so far
    double                             time            = 0; ///< simulated time at the end of the last iteration [s]
    Eigen::VectorXd                    state;               ///< [q | v | z] there
    std::vector<double>                factors;             ///< extrapolation factor of each iteration
    double                             settling_cycles = 0; ///< simulated before the first iteration [-]
    /** Per clearance joint of the scene (worn or not): contact mode (0/1), δ̇⁻ [m/s]. */
    std::vector<double>         modes;
    std::vector<JointWearState> joints;
    /** The effect ledger at the checkpoint (base/effect_ledger.h), all processes of the run. */
    std::map<std::string, std::map<std::string, long>> ledger;
    /** Wall time of the run's phases up to the checkpoint [s], all processes of the run. */
    PhaseTimings timings;
    /** The validity warnings raised up to the checkpoint (base/validity_warnings.h). */
    ValidityWarnings warnings;
    /**
     * The response body's per-cycle peak accelerations before wear [m/s²] (recorded in
     * the first iteration; empty if none were), so that a resumed run reports the
     * before/after response of the whole run.
     */
    std::vector<double> response_before_peaks;

    /** Write to @p path atomically. */
    void
    write(const std::string &path) const;

    /**
     * Read from @p path; InputError naming the file if it is missing, truncated,
     * damaged (checksum), of another format version, malformed, or inconsistent.
     */
    static WearState
    read(const std::string &path);

    /**
     * InputError naming @p where and the first size that differs from @p shape (the
     * resuming scene's), with both values.
     */
    void
    check_shape(const StateShape &shape, const std::string &where) const;
  };
} // namespace wearlink::wear
