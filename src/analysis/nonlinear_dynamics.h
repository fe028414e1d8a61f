// SPDX-License-Identifier: LGPL-2.1-or-later
// Nonlinear-dynamics results computed from a RecordedRun (analysis/recorded_run.h):
//  - the spread of a Poincaré section per channel (max − min over the section points):
//    zero for a motion with the driving period (a periodic orbit gives one point), of
//    the order of the clearance for the rattling journal of a clearance joint;
//  - the largest Lyapunov exponent of one recorded channel (analysis/lyapunov.h),
//    with the run's sample interval, so that it is in 1/s (natural log), and also
//    expressed per driving period.
// These take recorded data only, never a live simulation, so they apply equally to a
// run that was just made and to runs being compared (before/after wear).
#pragma once

#include "analysis/lyapunov.h"
#include "analysis/recorded_run.h"

#include <string>
#include <vector>

namespace wearlink::analysis
{
  /**
   * Range of one channel over the points of a Poincaré section. Angles (unit "rad") are
   * measured on the circle, from the first point along the shorter arc.
   */
  struct ChannelSpread
  {
    std::string name;
    std::string unit;
    double      min    = 0.0;
    double      max    = 0.0;
    double      spread = 0.0; ///< max − min [unit]
  };

  /** Spread of every channel of @p section (empty if it has no points). */
  std::vector<ChannelSpread>
  section_spread(const PoincareSection &section);

  /** One Lyapunov estimate of a recorded channel, with the numbers a report needs. */
  struct ChannelLyapunov
  {
    std::string      channel;
    LyapunovEstimate estimate;
    /** Number of samples analysed [-]. */
    std::size_t n_samples = 0;
    /** Sample interval dt [s]. */
    double sample_interval = 0.0;
    /** The exponent times the driving period T: growth per cycle [nats / period]. */
    double per_driving_period = 0.0;
  };

  /**
   * Largest Lyapunov exponent of channel @p channel of @p run's series. The sample
   * interval is the run's (the result is in 1/s, natural log); every other setting
   * comes from @p settings. InputError if the channel was not recorded or is too short.
   */
  ChannelLyapunov
  lyapunov_of_channel(const RecordedRun &run, const std::string &channel, LyapunovSettings settings);
} // namespace wearlink::analysis
