// SPDX-License-Identifier: LGPL-2.1-or-later
// The load history of the wearing clearance joints over one wear iteration, recorded by
// an observer of the accepted integrator steps (mbs/simulation.h): the joint state at
// the end of every accepted step; sample i carries the trapezoidal weight
// (t_{i+1} − t_{i−1})/2, so Σ_i w_i f(t_i) is the trapezoidal rule on the integrator's
// own (contact-adapted, event-located) grid. Only loaded samples (F_n > 0 and sliding)
// are kept. How often the pressure model is evaluated on this history is the
// accumulator's business (ArchardAccumulator::add_history). The recorder also
// integrates the relative rotation |d(θ_pin − θ_bushing)| of each joint.
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

    std::vector<const contact::ClearanceJoint *> joints;
    double                                       t_start = 0, t_last = 0;
    std::vector<std::vector<LoadSample>>         history;
    std::vector<LoadSample>                      pending;
    std::vector<double>                          relative_angle, rotation;
  };
} // namespace wearlink::wear
