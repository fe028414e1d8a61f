// SPDX-License-Identifier: LGPL-2.1-or-later
#include "analysis/recorded_run.h"

#include "base/exceptions.h"

#include <algorithm>
#include <cmath>

namespace wearlink::analysis
{
  namespace
  {
    /**
     * A time within this many seconds past the end of a step still belongs to it: the
     * k-th target time is computed as t_first + k T, which may land a rounding error
     * past a step that ends on it (the run's end time, say) [s].
     */
    double
    time_slack(const double t)
    {
      return 1e-12 * std::max(1.0, std::abs(t));
    }

    /** First k >= 0 with begin + k interval >= t - slack. */
    std::size_t
    first_index_at_or_after(const double begin, const double interval, const double t)
    {
      if (begin >= t - time_slack(t))
        return 0;
      return static_cast<std::size_t>(std::ceil((t - time_slack(t) - begin) / interval));
    }

    void
    init_names(SampledChannels &s, const std::vector<Channel> &channels)
    {
      for (const auto &c : channels)
        {
          s.names.push_back(c.name);
          s.units.push_back(c.unit);
        }
      s.values.assign(channels.size(), {});
    }

    void
    append(SampledChannels            &s,
           const std::vector<Channel> &channels,
           const double                t,
           const Eigen::VectorXd      &y,
           const unsigned int          n_coordinates)
    {
      const mbs::StateView view(y.data(), y.data() + n_coordinates);
      s.time.push_back(t);
      for (std::size_t c = 0; c < channels.size(); ++c)
        s.values[c].push_back(channels[c].value(view));
    }
  } // namespace

  std::size_t
  SampledChannels::index(const std::string &name) const
  {
    const auto it = std::find(names.begin(), names.end(), name);
    if (it != names.end())
      return static_cast<std::size_t>(it - names.begin());
    std::string list;
    for (const auto &n : names)
      list += (list.empty() ? "" : ", ") + n;
    throw InputError("The channel '" + name +
                     "' was not recorded; recorded channels: " + (list.empty() ? std::string("none") : list) + ".");
  }

  bool
  SampledChannels::has(const std::string &name) const
  {
    return std::find(names.begin(), names.end(), name) != names.end();
  }

  // ---------------------------------------------------------------------------------

  SeriesRecorder::SeriesRecorder(std::vector<Channel> channels_, const double begin_time, const double interval)
    : channels(std::move(channels_))
    , begin(begin_time)
    , dt(interval)
  {
    AssertThrow(interval > 0.0, dealii::ExcMessage("The sample interval must be > 0 s."));
    init_names(recorded, channels);
  }

  void
  SeriesRecorder::on_start(const mbs::StepContext &c)
  {
    const unsigned int n = c.simulation.get_mechanism().n_coordinates();
    n_taken              = first_index_at_or_after(begin, dt, c.t);
    const double ts      = begin + dt * n_taken;
    if (ts <= c.t + time_slack(c.t))
      {
        sample(ts, c.y, n);
        ++n_taken;
      }
  }

  void
  SeriesRecorder::on_step(const mbs::StepContext &c)
  {
    const unsigned int n = c.simulation.get_mechanism().n_coordinates();
    for (double ts = begin + dt * n_taken; ts <= c.t + time_slack(c.t); ts = begin + dt * n_taken)
      {
        c.simulation.state_at(std::min(ts, c.t), y_dense);
        sample(ts, y_dense, n);
        ++n_taken;
      }
  }

  void
  SeriesRecorder::sample(const double t, const Eigen::VectorXd &y, const unsigned int n_coordinates)
  {
    append(recorded, channels, t, y, n_coordinates);
  }

  // ---------------------------------------------------------------------------------

  PoincareRecorder::PoincareRecorder(std::vector<Channel> channels_, const double first_time, const double period)
    : channels(std::move(channels_))
  {
    AssertThrow(period > 0.0, dealii::ExcMessage("The driving period must be > 0 s."));
    recorded.period     = period;
    recorded.first_time = first_time;
    init_names(recorded.points, channels);
  }

  void
  PoincareRecorder::on_start(const mbs::StepContext &c)
  {
    const unsigned int n = c.simulation.get_mechanism().n_coordinates();
    n_taken              = first_index_at_or_after(recorded.first_time, recorded.period, c.t);
    const double ts      = recorded.first_time + recorded.period * n_taken;
    if (ts <= c.t + time_slack(c.t))
      {
        sample(ts, c.y, n);
        ++n_taken;
      }
  }

  // The section time t_k lies in the accepted step [t_previous, t]; the integrator's
  // dense output (the step's interpolant: Dormand–Prince's fourth-order continuous
  // extension, or the cubic Hermite of rk4) gives the state there to about the accuracy
  // of the step itself.
  void
  PoincareRecorder::on_step(const mbs::StepContext &c)
  {
    const unsigned int n = c.simulation.get_mechanism().n_coordinates();
    for (double ts = recorded.first_time + recorded.period * n_taken; ts <= c.t + time_slack(c.t);
         ts        = recorded.first_time + recorded.period * n_taken)
      {
               c.simulation.state_at(std::min(ts, c.t), y_dense);
               sample(ts, y_dense, n);
               ++n_taken;
      }
  }

  void
  PoincareRecorder::sample(const double t, const Eigen::VectorXd &y, const unsigned int n_coordinates)
  {
    append(recorded.points, channels, t, y, n_coordinates);
  }
} // namespace wearlink::analysis
