// SPDX-License-Identifier: LGPL-2.1-or-later
#include "analysis/cycle_peaks.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace wearlink::analysis
{
  CyclePeakRecorder::CyclePeakRecorder(const unsigned int n_coordinates,
                                       const unsigned int body,
                                       const double       period,
                                       const unsigned int skip_cycles)
    : n(n_coordinates)
    , body(body)
    , period(period)
    , skip(skip_cycles)
  {
  }

  void
  CyclePeakRecorder::on_start(const mbs::StepContext &c)
  {
    t_start = t_last = c.t;
    cycle_peaks.clear();
  }

  void
  CyclePeakRecorder::on_step(const mbs::StepContext &c)
  {
    t_last         = c.t;
    const double k = std::floor((c.t - t_start) / period);
    if (k < skip)
      return;
    const auto index = static_cast<std::size_t>(k) - skip;
    if (cycle_peaks.size() <= index)
      cycle_peaks.resize(index + 1, 0.0);
    const double a     = std::hypot(c.dydt[n + 3 * body], c.dydt[n + 3 * body + 1]);
    cycle_peaks[index] = std::max(cycle_peaks[index], a);
  }

  double
  CyclePeakRecorder::largest() const
  {
    return cycle_peaks.empty() ? 0.0 : *std::max_element(cycle_peaks.begin(), cycle_peaks.end());
  }

  double
  CyclePeakRecorder::mean_of_whole_cycles() const
  {
    const double whole = std::floor((t_last - t_start) / period * (1 + 1e-12)) - skip;
    const auto   m     = std::min(cycle_peaks.size(), static_cast<std::size_t>(std::max(0.0, whole)));
    if (m == 0)
      return std::numeric_limits<double>::quiet_NaN();
    double sum = 0;
    for (std::size_t k = 0; k < m; ++k)
      sum += cycle_peaks[k];
    return sum / m;
  }

  ResponseRecorder::ResponseRecorder(const mbs::Mechanism &m, int b, double dt, double d)
    : body_name(m.get_bodies()[b].name)
    , body(b)
    , n(m.n_coordinates())
    , interval(dt)
    , duration(d)
  {
  }

  void
  ResponseRecorder::on_start(const mbs::StepContext &c)
  {
    t_start = c.t;
    t.clear();
    x.clear();
    y.clear();
    ax.clear();
    ay.clear();
  }

  void
  ResponseRecorder::on_step(const mbs::StepContext &c)
  {
    for (double ts = t_start + t.size() * interval; ts <= c.t && ts - t_start <= duration * (1 + 1e-12);
         ts        = t_start + t.size() * interval)
      {
               c.simulation.state_at(ts, ys);
               c.simulation.derivative_at(ts, ys, fs);
               t.push_back(ts - t_start);
               x.push_back(ys[3 * body]);
               y.push_back(ys[3 * body + 1]);
               ax.push_back(fs[n + 3 * body]);
               ay.push_back(fs[n + 3 * body + 1]);
      }
  }

} // namespace wearlink::analysis
