// SPDX-License-Identifier: LGPL-2.1-or-later
// The response of one body. Its peak acceleration in every driving cycle, over every accepted
// integrator step (not a sampled series, which can miss an impact's spike between
// samples): the response measure of a life run's `Response rise` criterion and of the
// before/after-wear response in a wear run's summary. A cycle is [t0 + kT, t0 + (k+1)T)
// from the run's start t0; a step is counted in the cycle its end falls in.
#pragma once

#include "mbs/mechanism.h"
#include "mbs/simulation.h"

#include <string>
#include <vector>

namespace wearlink::analysis
{
  class CyclePeakRecorder : public mbs::StepObserver
  {
  public:
    /**
     * @param n_coordinates of the mechanism (3 per body)
     * @param body index of the body
     * @param period driving period T [s]
     * @param skip_cycles cycles at the start that are not recorded (a settling transient)
     */
    CyclePeakRecorder(unsigned int n_coordinates, unsigned int body, double period, unsigned int skip_cycles = 0);

    void
    on_start(const mbs::StepContext &c) override;
    void
    on_step(const mbs::StepContext &c) override;

    /** Largest |a| (magnitude of the body's acceleration) per recorded cycle [m/s²]. */
    const std::vector<double> &
    peaks() const
    {
      return cycle_peaks;
    }
    /** The largest of peaks() (0 if none). */
    double
    largest() const;
    /** The mean of peaks() over the whole cycles recorded (the last cycle if incomplete is left out; NaN if none). */
    double
    mean_of_whole_cycles() const;

  private:
    const unsigned int  n, body;
    const double        period;
    const unsigned int  skip;
    double              t_start = 0, t_last = 0;
    std::vector<double> cycle_peaks;
  };

  /**
   * One body's position and acceleration sampled at a fixed interval on the dense output
   * for a given duration from the run's start: the response curves of a wear run
   * (io::write_response_csv writes them).
   */
  class ResponseRecorder : public mbs::StepObserver
  {
  public:
    ResponseRecorder(const mbs::Mechanism &mechanism, int body, double interval, double duration);
    void
    on_start(const mbs::StepContext &c) override;
    void
    on_step(const mbs::StepContext &c) override;

    std::string         body_name;
    std::vector<double> t, x, y, ax, ay; ///< time from the start [s], [m], [m/s²]

  private:
    const int       body;
    const unsigned  n;
    const double    interval, duration;
    double          t_start = 0;
    Eigen::VectorXd ys, fs;
  };

} // namespace wearlink::analysis
