// SPDX-License-Identifier: LGPL-2.1-or-later
// The wear loop (doc/architecture.md §2; seed §4.2). One iteration is six named
// steps, in this order:
//   1. record_loads           simulate Cycles per iteration of the mechanism, continuing
//                             from the state where the previous iteration ended, while a
//                             LoadRecorder keeps the load history of every wearing joint;
//   2. archard_increments     feed that history through each joint's pressure model into
//                             Archard's law on both surfaces (wear/archard.h);
//   3. extrapolation_factor   the fixed factor, or the adaptive one that caps the largest
//                             depth increment, never past Target revolutions;
//   4. update_profiles        bore R1* += f h, pin R2* −= f h (each in its own frame; h the
//                             iteration's rate, or with Wear/Wear integration = adams-bashforth
//                             its second-order combination with the previous one's,
//                             wear/wear_step.h), and the iteration's cumulative records;
//   5. update_clearance_model rebuild the clearance joints' gap from the new profiles and
//                             give the pressure models the new geometry (the fe model
//                             re-meshes only beyond its 'Remesh depth');
//   6. commit                 (called by the workflow once it wrote the iteration's files)
//                             count the iteration in the effect ledger, keep the ledger,
//                             the phase timings and the validity warnings in the
//                             state, and write the state (wear/wear_state.h), if a
//                             path is set.
// The loop knows the mechanism only through the joints it wears and a function that
// advances the dynamics (the workflow's run of the scene), so it sits below the scene
// reader and the workflows. A resumed loop starts from a checkpoint: everything the next
// iteration depends on is in it, so it ends with the same profiles as an uninterrupted
// loop; it also continues the checkpoint's effect ledger, timings and validity warnings,
// so that the resumed run reports the whole run, not only its own part. The warnings of
// step 2 (a pressure model outside its validity, PressureModel::check_validity) and
// those the dynamics raise go into the list given to set_warnings().
#pragma once

#include "base/timings.h"
#include "base/validity_warnings.h"
#include "contact/clearance_joint.h"
#include "mbs/simulation.h"
#include "wear/archard.h"
#include "wear/load_recorder.h"
#include "wear/wear_settings.h"
#include "wear/wear_state.h"

#include <Eigen/Core>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace wearlink::wear
{
  /** A clearance joint that wears, with what the scene says about its wear. */
  struct WearingJoint
  {
    contact::ClearanceJoint *joint = nullptr; ///< not owned
    JointWear               *wear  = nullptr; ///< not owned
  };

  /**
   * Advances the mechanism's dynamics from time @p t0 and full state @p y0 ([q | v | z])
   * to time @p t1, handing every accepted step to @p loads (if not null; through
   * LoadRecorder::start() and step(), from the joints' diagnostics the run evaluates
   * anyway), then notifying @p observers of it; returns the state at @p t1.
   */
  using AdvanceDynamics = std::function<Eigen::VectorXd(double                                  t0,
                                                        double                                  t1,
                                                        const Eigen::VectorXd                  &y0,
                                                        LoadRecorder                           *loads,
                                                        const std::vector<mbs::StepObserver *> &observers)>;

  /**
   * Moves the mechanism's full state @p y ([q | v | z]) at time @p t so that the pin
   * centre − bore centre of every clearance joint (in the order the loop was given them)
   * is @p eccentricities (global) [m], with the least change of the state.
   */
  using CarryState = std::function<void(double t, Eigen::VectorXd &y, const std::vector<mbs::Vec2> &eccentricities)>;

  /**
   * What step 3 knows when it chooses an iteration's factor, for a caller that limits
   * the factor (WearLoop::set_factor_limit; the life run's stop criteria): per wearing
   * joint the wear so far and this iteration's increments as step 4 applies them
   * (smoothed), for a factor of 1. Step 4 makes the depths depth + f · increment and the
   * volumes volume + f · volume increment.
   */
  struct StepPreview
  {
    struct Joint
    {
      const JointWearState *state = nullptr;                 ///< the joint's wear so far (its history)
      std::vector<double>   depth_pin, depth_bore;           ///< cumulative depth per area [m]
      double                volume_pin = 0, volume_bore = 0; ///< cumulative [m³]
      std::vector<double>   pin_increment, bore_increment;   ///< depth per area, factor 1 [m]
      double                pin_volume_increment = 0, bore_volume_increment = 0; ///< [m³]
    };
    double             revolutions = 0; ///< represented before this iteration [-]
    double             cycles      = 0; ///< simulated in this iteration [-]
    double             factor      = 0; ///< the factor step 3 chose itself [-]
    std::vector<Joint> joints;
  };

  /**
   * The largest factor a caller allows for the iteration of @p preview (≥ 0; the loop
   * takes the smaller of it and its own).
   */
  using FactorLimit = std::function<double(const StepPreview &preview)>;

  /**
   * Periodic samples @p values around a circle of radius @p radius [m], low-pass filtered
   * at @p wavelength [m] (a periodic Gaussian, transfer 1/2 there, weights summing to 1:
   * Σ values is kept); unchanged for a wavelength of 0.
   */
  std::vector<double>
  low_pass(const std::vector<double> &values, double wavelength, double radius);

  /**
   * @p depth (periodic samples around a surface of radii @p radii [m]) low-pass filtered
   * at @p wavelength [m] (Wear/Smoothing wavelength: Gaussian, transfer 1/2 there), with
   * its volume Σ h_k R_k L Δψ kept to rounding; unchanged for a wavelength of 0.
   */
  std::vector<double>
  smoothed(const std::vector<double> &depth, double wavelength, const std::vector<double> &radii);

  /**
   * Warn (in @p warnings) about every final worn profile of @p state whose roughness
   * exceeds roughness_limit (wear/depth_measures.h): such a profile is not resolved.
   * The run's end calls it; an early iteration's profile, a few thousand revolutions of
   * chaotic impacts, is not a result.
   */
  void
  check_roughness(const WearState &state, ValidityWarnings &warnings);

  /** What a wearing joint in contact carried before its profiles changed (wear_loop.cc). */
  struct CarriedContact;

  class WearLoop
  {
  public:
    /**
     * @param settings the scene's "Wear" section
     * @param wearing the wearing joints (order = the order of the state's joints)
     * @param clearance_joints every clearance joint of the mechanism (their contact
     *        modes are part of the state)
     * @param cycle_period duration of one mechanism cycle [s]
     * @param advance the dynamics
     */
    WearLoop(const WearLoopSettings                &settings,
             std::vector<WearingJoint>              wearing,
             std::vector<contact::ClearanceJoint *> clearance_joints,
             double                                 cycle_period,
             AdvanceDynamics                        advance);

    /**
     * Start a fresh loop at time @p t0 from the assembled positions @p q0 and velocities
     * @p v0 (n_coordinates each), with the joints' current profiles as the unworn ones.
     * @p fingerprint and @p scene identify the scene in the checkpoints.
     */
    void
    start(double                                    t0,
          const Eigen::VectorXd                    &q0,
          const Eigen::VectorXd                    &v0,
          const std::string                        &fingerprint,
          const std::map<std::string, std::string> &scene = {});

    /**
     * Continue from @p state (read from a checkpoint and checked against the scene with
     * WearState::check_shape), with its effect ledger (which replaces this process's:
     * it counted the set-up of the same scene) and its timings. InputError naming
     * @p where if its joints or sizes do not match this loop's.
     */
    void
    resume(WearState state, const std::string &where);

    /** Wall time of the run's earlier processes, up to the checkpoint resumed [s]. */
    double
    earlier_wall_time() const
    {
      return earlier_total;
    }

    /**
     * Carry the state onto the worn profiles after every iteration with @p carry (see
     * update_clearance_model); without it the state stays where it was.
     */
    void
    set_carry(CarryState carry)
    {
      carry_state = std::move(carry);
    }

    /** Checkpoint after every iteration into @p path ("" : none). */
    void
    set_checkpoint(const std::string &path)
    {
      checkpoint_path = path;
    }

    /**
     * The run's validity warnings, not owned: the loop adds the pressure models' (step 2),
     * keeps the list in every checkpoint, and on resume() merges the checkpoint's into it
     * (so they precede the resumed part's, as in an uninterrupted run). Call before
     * start() or resume().
     */
    void
    set_warnings(ValidityWarnings *list)
    {
      warnings = list;
    }

    /**
     * Keep @p peaks (the response body's per-cycle peaks before wear [m/s²]) in the
     * state and so in the checkpoints; call after the first iteration, before its commit().
     */
    void
    keep_response_before(std::vector<double> peaks)
    {
      st.response_before_peaks = std::move(peaks);
    }

    /**
     * Limit every iteration's factor by @p limit (see StepPreview), after the loop's own
     * choice (fixed, or adaptive up to Target revolutions). The limited factor is the
     * iteration's: it is in the state, the checkpoint and the revolutions.
     */
    void
    set_factor_limit(FactorLimit limit)
    {
      factor_limit = std::move(limit);
    }

    /** True when the iterations are done or the adaptive target is reached. */
    bool
    finished() const;

    /**
     * One iteration (steps 1–5), with @p extra_observers of its dynamics. The workflow
     * writes the iteration's files next, then commit()s it: a checkpoint never stands
     * for an iteration whose files are missing (a run killed in between redoes it).
     */
    void
    iterate(const std::vector<mbs::StepObserver *> &extra_observers = {});

    /** Step 6 of the iteration just done: count it and write its checkpoint. */
    void
    commit();

    const WearState &
    state() const
    {
      return st;
    }

    /** Per wearing joint, the load sample of the largest normal force of the last iteration. */
    const std::vector<contact::ContactLoad> &
    peak_loads() const
    {
      return peaks;
    }
    /** The extrapolation factor of the last iteration [-]. */
    double
    last_factor() const
    {
      return st.factors.empty() ? 0.0 : st.factors.back();
    }

    /**
     * Wall time of the loop's phases so far [s], the pressure models' FE phases and
     * the clearance joints' contact-law tables (NormalForceLaw::timings()) included.
     */
    PhaseTimings
    timings() const;

  private:
    /** Step 1. The load history of one iteration; advances the stored state. */
    std::unique_ptr<LoadRecorder>
    record_loads(const std::vector<mbs::StepObserver *> &extra_observers, double t_end);

    /**
     * The factor the sequential update wears the surfaces with (0 for the simultaneous
     * update): the fixed factor; adaptive, the previous iteration's (within Target
     * revolutions), or for the first iteration what a simultaneous step chooses.
     */
    double
    planned_factor(const LoadRecorder &loads, double t_start);

    /**
     * Step 2. Archard depths and volumes of this iteration, per wearing joint, with the
     * sequential update at @p sequential_factor (0: simultaneous; wear/archard.h). If
     * step 3 then takes a smaller factor, the sequential pass is made again with it.
     */
    std::vector<std::unique_ptr<ArchardAccumulator>>
    archard_increments(const LoadRecorder &loads, double t_start, double sequential_factor);

    /**
     * A slice j < @p i of the same sliced joint whose wear this iteration is joint @p i's:
     * the same profiles, wear coefficients and closed-form pressure model, and the same
     * recorded loads bit for bit (an aligned joint's slices, a symmetric crown's pairs).
     * Its increment then serves @p i too (the same inputs give the same bits); −1: none.
     * The fe model is not shared (its mesh state follows each joint's own updates).
     */
    int
    twin_of(unsigned int i, const LoadRecorder &loads) const;

    /** Step 3. The factor this iteration stands for (see WearLoopSettings). */
    double
    extrapolation_factor(const std::vector<std::unique_ptr<ArchardAccumulator>> &increments) const;

    /** Per wearing joint, this iteration's own rate (smoothed, per unit factor). */
    std::vector<WearRate>
    own_rates(const std::vector<std::unique_ptr<ArchardAccumulator>> &increments, const LoadRecorder &loads) const;

    /** The rate step 4 applies to joint @p i at @p factor (Wear/Wear integration; wear/wear_step.h). */
    WearRate
    applied_rate(unsigned int i, const WearRate &own, double factor) const;

    /**
     * What set_factor_limit's function sees of this iteration (step 3): the rates
     * applied at the loop's own @p factor (a smaller factor changes the Adams–Bashforth
     * extrapolation slightly; the preview stays linear in f).
     */
    StepPreview
    preview(const std::vector<WearRate> &rates, double factor) const;

    /** Step 4. New profiles (+ @p factor × @p rate) and the cumulative records of joint @p i. */
    void
    update_profiles(unsigned int i, const WearRate &rate, const LoadRecorder &loads, double factor);

    /** The contact width of joint @p i (JointWearState::contact_width), from the iteration's peak, once. */
    void
    set_contact_width(unsigned int i);

    /** The depth measures of joint @p i's record @p r (wear/depth_measures.h). */
    void
    depth_measures(unsigned int i, IterationRecord &r) const;

    /**
     * Step 5. Gap and pressure-model geometry from the new profiles; with @p carry, the
     * state is carried onto them: a wearing joint in contact gets the pin position at
     * which the new profiles carry the elastic force the old ones carried (started from
     * the old position moved by the depth worn at the contact), the other clearance
     * joints keep theirs, and the mechanism follows with the least change
     * (set_carry). So an iteration starts where the previous one ended, without the
     * fall into a pocket deepened by the extrapolated wear.
     */
    void
    update_clearance_model(bool carry = false);

    /** The settling cycles before the first iteration (Wear/Settling cycles), and the start-up they show. */
    void
    settle();

    /** The pin positions that carry @p carried on the new profiles, and the state moved there. */
    void
    carry_contacts(const std::vector<CarriedContact> &carried);

    /** Step 6. */

    /** The contact modes of the clearance joints into / out of the state. */
    void
    restore_contact_modes();
    void
    store_contact_modes();

    /** Joint @p i's geometry with the given profiles. */
    contact::JointGeometry
    geometry(unsigned int i, const Profile &bore, const Profile &pin) const;

    const WearLoopSettings                 settings;
    std::vector<WearingJoint>              wearing;
    std::vector<contact::ClearanceJoint *> clearance_joints;
    const double                           period;
    AdvanceDynamics                        advance;
    CarryState                             carry_state;
    WearState                              st;
    std::string                            checkpoint_path;
    FactorLimit                            factor_limit; ///< see set_factor_limit()
    PhaseTimings                           own_timings;
    double                                 earlier_total = 0;  ///< see earlier_wall_time()
    Stopwatch                              process_time;       ///< since start() or resume()
    std::vector<contact::ContactLoad>      peaks;              ///< see peak_loads()
    ValidityWarnings                      *warnings = nullptr; ///< see set_warnings()
  };
} // namespace wearlink::wear
