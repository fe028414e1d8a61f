// SPDX-License-Identifier: LGPL-2.1-or-later
#include "analysis/profile_comparison.h"

#include "base/exceptions.h"
#include "base/numbers.h"

#include <algorithm>
#include <boost/math/tools/minima.hpp>
#include <cmath>
#include <limits>
#include <numeric>

namespace wearlink::analysis
{
  namespace
  {
    using numbers::pi;
    using numbers::two_pi;

    /** @p psi brought into [0, 2π). */
    double
    wrapped(const double psi)
    {
      const double w = psi - two_pi * std::floor(psi / two_pi);
      return w >= two_pi ? 0.0 : w;
    }

    /** The scan's finest step: the search range in at most this many steps. */
    constexpr double max_scan_steps = 3600;
    /** The scan's coarsest step [rad]: 1°. */
    constexpr double max_scan_step = pi / 180;

    /** InputError unless @p t is a trace as PolarTrace describes, of at least 8 points. */
    void
    check_trace(const PolarTrace &t, const std::string &what)
    {
      if (t.angle.size() != t.radius.size() || t.size() < 8)
        throw InputError("The " + what + " needs at least 8 points with an angle and a radius each.");
      for (std::size_t k = 0; k < t.size(); ++k)
        if (!(t.radius[k] > 0) || !(t.angle[k] >= 0 && t.angle[k] < two_pi) ||
            (k > 0 && !(t.angle[k] > t.angle[k - 1])))
          throw InputError("The " + what + "'s point " + std::to_string(k) +
                           " is out of order: angles must increase strictly within [0, 2π) and radii be > 0.");
    }
  } // namespace

  PolarTrace
  PolarTrace::of_profile(const Profile &profile)
  {
    PolarTrace t;
    for (unsigned int k = 0; k < profile.n_points(); ++k)
      {
        t.angle.push_back(profile.angle(k));
        t.radius.push_back(profile[k]);
      }
    return t;
  }

  double
  PolarTrace::at(const double psi) const
  {
    const double      w = wrapped(psi);
    const std::size_t n = angle.size();
    const std::size_t j = static_cast<std::size_t>(std::upper_bound(angle.begin(), angle.end(), w) - angle.begin());
    // The segment [a0, a1] that holds w; the one across 2π joins the last point to the first.
    const double a0 = j == 0 ? angle[n - 1] - two_pi : angle[j - 1];
    const double r0 = j == 0 ? radius[n - 1] : radius[j - 1];
    const double a1 = j == n ? angle[0] + two_pi : angle[j];
    const double r1 = j == n ? radius[0] : radius[j];
    return r0 + (r1 - r0) * (w - a0) / (a1 - a0);
  }

  CommonGrid
  common_grid(const PolarTrace &measured, const PolarTrace &predicted, const double rotation)
  {
    struct Entry
    {
      double angle, measured, predicted;
    };
    std::vector<Entry> entries;
    entries.reserve(measured.size() + predicted.size());
    for (std::size_t k = 0; k < predicted.size(); ++k)
      entries.push_back({predicted.angle[k], measured.at(predicted.angle[k] - rotation), predicted.radius[k]});
    for (std::size_t i = 0; i < measured.size(); ++i)
      {
        const double psi = wrapped(measured.angle[i] + rotation);
        entries.push_back({psi, measured.radius[i], predicted.at(psi)});
      }
    std::sort(entries.begin(), entries.end(), [](const Entry &a, const Entry &b) { return a.angle < b.angle; });
    CommonGrid g;
    for (const auto &e : entries)
      {
        g.angle.push_back(e.angle);
        g.measured.push_back(e.measured);
        g.predicted.push_back(e.predicted);
      }
    return g;
  }

  namespace
  {
    /** The exact RMS over the circle of the piecewise linear @p d on @p angle (see the header). */
    double
    circle_rms(const std::vector<double> &angle, const std::vector<double> &d)
    {
      double sum = 0;
      for (std::size_t k = 0; k < angle.size(); ++k)
        {
          const std::size_t next = k + 1 == angle.size() ? 0 : k + 1;
          const double      h    = next == 0 ? angle[0] + two_pi - angle[k] : angle[next] - angle[k];
          sum += h * (d[k] * d[k] + d[k] * d[next] + d[next] * d[next]) / 3;
        }
      return std::sqrt(sum / two_pi);
    }

    /** The area [m²] of the polygon through the points (@p angle, @p r), in order around the circle. */
    double
    polygon_area(const std::vector<double> &angle, const std::vector<double> &r)
    {
      double twice = 0;
      for (std::size_t k = 0; k < angle.size(); ++k)
        {
          const std::size_t next = k + 1 == angle.size() ? 0 : k + 1;
          twice += r[k] * r[next] * std::sin(angle[next] - angle[k]);
        }
      return twice / 2;
    }
  } // namespace

  WornArea
  measured_worn_area(const PolarTrace &measured, const PolarTrace &unworn, const bool bore, const double sigma)
  {
    const auto         &a = measured.angle, &r = measured.radius;
    const std::size_t   n = a.size();
    std::vector<double> r0(n);
    for (std::size_t k = 0; k < n; ++k)
      r0[k] = unworn.at(a[k]);
    WornArea out;
    out.area        = (bore ? 1 : -1) * (polygon_area(a, r) - polygon_area(a, r0));
    double variance = 0;
    for (std::size_t k = 0; k < n; ++k)
      {
        const std::size_t next = (k + 1) % n, prev = (k + n - 1) % n;
        const double      dA = 0.5 * (r[next] * std::sin(a[next] - a[k]) + r[prev] * std::sin(a[k] - a[prev]));
        variance += dA * dA;
      }
    out.sigma = sigma * std::sqrt(variance);
    return out;
  }

  TraceDifference
  trace_difference(const PolarTrace &measured, const PolarTrace &predicted, const double rotation)
  {
    const CommonGrid    g = common_grid(measured, predicted, rotation);
    std::vector<double> d(g.angle.size());
    TraceDifference     out;
    for (std::size_t k = 0; k < d.size(); ++k)
      {
        d[k] = g.measured[k] - g.predicted[k];
        if (std::abs(d[k]) > out.largest)
          {
            out.largest       = std::abs(d[k]);
            out.largest_angle = g.angle[k];
          }
      }
    out.rms = circle_rms(g.angle, d);
    return out;
  }

  namespace
  {
    /** The scan step of align_trace() (see the header). */
    double
    scan_step(const PolarTrace &measured, const PolarTrace &predicted, const double search)
    {
      const double coarser = two_pi / static_cast<double>(std::min(measured.size(), predicted.size()));
      return std::max(std::min(max_scan_step, coarser / 2), 2 * search / max_scan_steps);
    }
  } // namespace

  Alignment
  align_trace(const PolarTrace &measured, const PolarTrace &predicted, const double search)
  {
    if (!(search >= 0 && search <= pi))
      throw InputError("The angle search must lie in [0, π] rad (0 to 180°).");
    Alignment a;
    a.difference    = trace_difference(measured, predicted, 0);
    a.unaligned_rms = a.difference.rms;
    a.evaluations   = 1;
    if (search == 0)
      return a;
    const auto rms = [&](const double theta) {
      ++a.evaluations;
      return trace_difference(measured, predicted, theta).rms;
    };
    const auto   steps = static_cast<unsigned int>(std::ceil(2 * search / scan_step(measured, predicted, search)));
    const double step  = 2 * search / steps;
    a.scan_step        = step;
    double best = -search, best_rms = std::numeric_limits<double>::infinity();
    for (unsigned int k = 0; k <= steps; ++k)
      {
        const double theta = -search + k * step, r = rms(theta);
        if (r < best_rms)
          {
            best     = theta;
            best_rms = r;
          }
      }
    // Brent within one step of the best scanned rotation, to half the digits of a double
    // (the most a minimum can be located to: the objective is flat to second order there).
    const auto refined = boost::math::tools::brent_find_minima(rms,
                                                               std::max(-search, best - step),
                                                               std::min(search, best + step),
                                                               std::numeric_limits<double>::digits / 2);
    a.rotation         = refined.second < best_rms ? refined.first : best;
    a.difference       = trace_difference(measured, predicted, a.rotation);
    return a;
  }

  namespace
  {
    /** The largest of @p depth at @p angle, and where. */
    std::pair<double, double>
    deepest(const AngleSeries &s)
    {
      const auto k = std::max_element(s.value.begin(), s.value.end()) - s.value.begin();
      return {s.value[k], s.angle[k]};
    }

    /** The widest angle between consecutive points of @p t, across 2π too. */
    double
    largest_gap(const PolarTrace &t)
    {
      double gap = t.angle.front() + two_pi - t.angle.back();
      for (std::size_t k = 1; k < t.size(); ++k)
        gap = std::max(gap, t.angle[k] - t.angle[k - 1]);
      return gap;
    }

    /** The depth curves and worn areas of @p c at its alignment. */
    void
    depths_and_areas(ProfileComparison &c,
                     const PolarTrace  &measured,
                     const PolarTrace  &predicted,
                     const PolarTrace  &unworn,
                     const double       sign)
    {
      const double theta = c.alignment.rotation;
      for (std::size_t k = 0; k < predicted.size(); ++k)
        {
          c.predicted_depth.angle.push_back(predicted.angle[k]);
          c.predicted_depth.value.push_back(sign * (predicted.radius[k] - unworn.at(predicted.angle[k])));
        }
      std::vector<std::pair<double, double>> aligned;
      for (std::size_t i = 0; i < measured.size(); ++i)
        {
          const double psi = wrapped(measured.angle[i] + theta);
          aligned.emplace_back(psi, sign * (measured.radius[i] - unworn.at(psi)));
        }
      std::sort(aligned.begin(), aligned.end());
      for (const auto &[psi, depth] : aligned)
        {
          c.measured_depth.angle.push_back(psi);
          c.measured_depth.value.push_back(depth);
        }
      const CommonGrid    g = common_grid(measured, predicted, theta);
      std::vector<double> r0(g.angle.size());
      for (std::size_t k = 0; k < g.angle.size(); ++k)
        {
          r0[k] = unworn.at(g.angle[k]);
          c.depth_difference.angle.push_back(g.angle[k]);
          c.depth_difference.value.push_back(sign * (g.measured[k] - g.predicted[k]));
        }
      const double unworn_area = polygon_area(g.angle, r0);
      c.worn_area_measured     = sign * (polygon_area(g.angle, g.measured) - unworn_area);
      c.worn_area_predicted    = sign * (polygon_area(g.angle, g.predicted) - unworn_area);
    }
  } // namespace

  ProfileComparison
  compare_profile(const PolarTrace &measured,
                  const PolarTrace &predicted,
                  const PolarTrace &unworn,
                  const WornSurface surface,
                  const double      search)
  {
    check_trace(measured, "measured profile");
    check_trace(predicted, "predicted profile");
    check_trace(unworn, "unworn profile");
    ProfileComparison c;
    c.alignment = align_trace(measured, predicted, search);
    depths_and_areas(c, measured, predicted, unworn, surface == WornSurface::bore ? 1.0 : -1.0);
    std::tie(c.max_depth_measured, c.max_depth_measured_angle)   = deepest(c.measured_depth);
    std::tie(c.max_depth_predicted, c.max_depth_predicted_angle) = deepest(c.predicted_depth);
    c.largest_measured_gap                                       = largest_gap(measured);
    return c;
  }
} // namespace wearlink::analysis
