// SPDX-License-Identifier: LGPL-2.1-or-later
// What the nonlinear-dynamics analyses need from a run, recorded while it runs, and the
// observers that record it:
//  - a uniformly sampled series of some channels (phase portraits, Lyapunov exponents):
//    SeriesRecorder samples them every `interval` seconds on the integrator's dense
//    output, so the samples do not depend on where the adaptive steps fell;
//  - a Poincaré section with one point per driving period T: PoincareRecorder evaluates
//    the channels at the exact section times t_k = t_first + k T on the dense output of
//    the step that contains t_k (Simulation::state_at), never at the nearest sample.
// A RecordedRun holds both plus a label. Everything downstream (poincare_spread,
// lyapunov_of_channel in analysis/nonlinear_dynamics.h, the writers in workflows/run/analyses.h)
// takes a RecordedRun, so a before/after-wear comparison can feed it two runs.
#pragma once

#include "analysis/channels.h"
#include "mbs/simulation.h"

#include <string>
#include <vector>

namespace wearlink::analysis
{
  /** Several channels sampled at common times. */
  struct SampledChannels
  {
    std::vector<std::string> names;
    std::vector<std::string> units;
    /** Sample times [s]. */
    std::vector<double> time;
    /** values[c][k]: channel c at time[k] [units[c]]. */
    std::vector<std::vector<double>> values;

    std::size_t
    n_samples() const
    {
      return time.size();
    }
    /** Index of channel @p name; InputError listing the recorded names if absent. */
    std::size_t
    index(const std::string &name) const;
    bool
    has(const std::string &name) const;
  };

  /** Poincaré section: the channels at t_k = first_time + k period. */
  struct PoincareSection
  {
    /** Driving period T [s]. */
    double period = 0.0;
    /** t_0 [s]. */
    double          first_time = 0.0;
    SampledChannels points;
  };

  /** The recorded part of one run. */
  struct RecordedRun
  {
    /** Free text used in plot titles ("before wear", a sweep value, ...). */
    std::string label;
    /** Driving period T of the mechanism [s] (0 if unknown). */
    double driving_period = 0.0;
    /** Sample interval of @p series [s] (0 if no series was recorded). */
    double          sample_interval = 0.0;
    SampledChannels series;
    PoincareSection section;
  };

  /**
   * Samples @p channels at t = begin_time + k interval, k = 0, 1, ... (times before the
   * start of the run are skipped), each from the dense output of the accepted step that
   * contains it.
   */
  class SeriesRecorder : public mbs::StepObserver
  {
  public:
    SeriesRecorder(std::vector<Channel> channels, double begin_time, double interval);

    void
    on_start(const mbs::StepContext &context) override;
    void
    on_step(const mbs::StepContext &context) override;

    const SampledChannels &
    series() const
    {
      return recorded;
    }
    double
    interval() const
    {
      return dt;
    }

  private:
    void
    sample(double t, const Eigen::VectorXd &y, unsigned int n_coordinates);

    std::vector<Channel> channels;
    double               begin;
    double               dt;
    std::size_t          n_taken = 0;
    SampledChannels      recorded;
    Eigen::VectorXd      y_dense;
  };

  /**
   * Records the channels at t_k = @p first_time + k @p period, k = 0, 1, ..., each from
   * the dense output of the accepted step [t_previous, t] that contains t_k.
   */
  class PoincareRecorder : public mbs::StepObserver
  {
  public:
    PoincareRecorder(std::vector<Channel> channels, double first_time, double period);

    void
    on_start(const mbs::StepContext &context) override;
    void
    on_step(const mbs::StepContext &context) override;

    const PoincareSection &
    section() const
    {
      return recorded;
    }

  private:
    void
    sample(double t, const Eigen::VectorXd &y, unsigned int n_coordinates);

    std::vector<Channel> channels;
    std::size_t          n_taken = 0;
    PoincareSection      recorded;
    Eigen::VectorXd      y_dense;
  };
} // namespace wearlink::analysis
