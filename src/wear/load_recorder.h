// SPDX-License-Identifier: LGPL-2.1-or-later
// The load history of the wearing clearance joints over one wear iteration, recorded by
// an observer of the accepted integrator steps (mbs/simulation.h): the joint state at
// the end of every accepted step; sample i carries the trapezoidal weight
// (t_{i+1} − t_{i−1})/2, so Σ_i w_i f(t_i) is the trapezoidal rule on the integrator's
// own (contact-adapted, event-located) grid. Only loaded samples (F_n > 0 and sliding)
// are kept. How often the pressure model is evaluated on this history is the
// accumulator's business (ArchardAccumulator::add_history). The recorder also
// integrates the relative rotation |d(θ_pin − θ_bushing)| of each joint.
//
// As an observer it evaluates its joints itself. A run that evaluates the joints at
// every accepted step anyway (workflows/run/run.h, RunOptions::loads) hands it those
// diagnostics through start() and step() instead, so that each joint is evaluated once
// per step.
#pragma once

#include "contact/clearance_joint.h"
#include "mbs/simulation.h"
#include "wear/archard.h"
#include "wear/wear_settings.h"

#include <vector>

namespace wearlink::wear
{
  /** The quantities Archard needs from a joint state. */
  LoadSample
  load_sample(const contact::JointDiagnostics &d);

  class LoadRecorder : public mbs::StepObserver
  {
  public:
    /** @param joints the joints to record (not owned). */
    explicit LoadRecorder(std::vector<const contact::ClearanceJoint *> joints);

    void
    on_start(const mbs::StepContext &c) override;
    void
    on_step(const mbs::StepContext &c) override;

    /**
     * The state at time @p t where the recording starts, from the diagnostics @p d of the
     * joints there (d[j] of joint j), evaluated as on_start() does: in an mbs::StateView
     * without precomputed cos and sin of the bodies' angles.
     */
    void
    start(double t, const std::vector<contact::JointDiagnostics> &d);
    /** The accepted step that ends at time @p t, from the diagnostics @p d there, as for start(). */
    void
    step(double t, const std::vector<contact::JointDiagnostics> &d);

    /** The joints recorded, in the order of samples(). */
    const std::vector<const contact::ClearanceJoint *> &
    recorded_joints() const
    {
      return joints;
    }

    /** Close the history (the last step's half weight); call after the run. */
    void
    finish();

    /** Loaded samples of joint @p j. */
    const std::vector<LoadSample> &
    samples(unsigned int j) const
    {
      return history[j];
    }
    /** ∫ |d(θ_pin − θ_bushing)| / 2π of joint @p j [revolutions]. */
    double
    relative_revolutions(unsigned int j) const;

  private:
    void
    take(unsigned int j, const LoadSample &s, double weight);
    /** Every joint's diagnostics at the state of @p c, into `current`. */
    void
    evaluate(const mbs::StepContext &c);

    std::vector<const contact::ClearanceJoint *> joints;
    std::vector<contact::JointDiagnostics>       current; ///< of the observed step
    double                                       t_start = 0, t_last = 0;
    std::vector<std::vector<LoadSample>>         history;
    std::vector<LoadSample>                      pending;
    std::vector<double>                          relative_angle, rotation;
  };
} // namespace wearlink::wear
