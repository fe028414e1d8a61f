// SPDX-License-Identifier: LGPL-2.1-or-later
#include "analysis/life_criteria.h"

#include "analysis/ensemble_statistics.h"
#include "base/numbers.h"
#include "base/text.h"
#include "wear/depth_measures.h"

#include <algorithm>
#include <cmath>

namespace wearlink::analysis
{
  namespace
  {
    using numbers::nan;

    /** The envelope depth of h + f Δh over @p window areas [m] (wear/depth_measures.h). */
    double
    extrapolated_envelope(const std::vector<double> &h,
                          const std::vector<double> &increment,
                          const double               f,
                          const unsigned int         window)
    {
      std::vector<double> depth(h.size());
      for (std::size_t k = 0; k < h.size(); ++k)
        depth[k] = h[k] + f * (k < increment.size() ? increment[k] : 0.0);
      return wear::envelope_depth(depth, window);
    }

    /**
     * The window [areas] of a surface of @p n_areas areas around @p radius [m] for the
     * contact width of @p state, as the wear loop's depth measures take it; one area (the
     * raw depth) without the joint's state.
     */
    unsigned int
    window_of(const wear::JointWearState *state, const double radius, const std::size_t n_areas)
    {
      if (state == nullptr)
        return 1;
      return wear::window_areas(state->contact_width, radius, static_cast<unsigned int>(n_areas));
    }

    /** [m³] → [mg] for density @p rho [kg/m³]. */
    double
    milligrams(const double volume, const double rho)
    {
      return volume * rho * 1e6;
    }

    /** The value of criterion @p kind of one joint with these envelope depths and masses. */
    double
    joint_value(const Criterion kind, const double h_pin, const double h_bore, const double m_pin, const double m_bush)
    {
      switch (kind)
        {
          case Criterion::wear_depth:
            return std::max(h_pin, h_bore);
          case Criterion::clearance_growth:
            return h_pin + h_bore;
          case Criterion::pin_mass_loss:
            return m_pin;
          case Criterion::bushing_mass_loss:
            return m_bush;
          case Criterion::response_rise:
            break;
        }
      return nan;
    }

    /** The roots r₋ ≤ r₊ of A r² − 2 B r + C = 0 for A > 0 (NaN if there are none). */
    Interval
    roots(const double a, const double b, const double c)
    {
      const double discriminant = b * b - a * c;
      if (!(a > 0) || !(discriminant >= 0))
        return {};
      const double root = std::sqrt(discriminant);
      return {(b - root) / a, (b + root) / a};
    }
  } // namespace

  std::vector<CriterionSpec>
  active_criteria(const LifeSettings &s)
  {
    const std::vector<CriterionSpec> all = {
      {Criterion::wear_depth, "wear_depth", "Maximum wear depth", "m", s.max_wear_depth},
      {Criterion::clearance_growth, "clearance_growth", "Radial clearance growth", "m", s.clearance_growth},
      {Criterion::pin_mass_loss, "pin_mass_loss", "Pin mass loss", "mg", s.pin_mass_loss},
      {Criterion::bushing_mass_loss, "bushing_mass_loss", "Bushing mass loss", "mg", s.bushing_mass_loss},
      {Criterion::response_rise, "response_rise", "Response rise", "%", s.response_rise}};
    std::vector<CriterionSpec> on;
    for (const auto &c : all)
      if (c.limit > 0)
        on.push_back(c);
    return on;
  }

  bool
  is_trend(const CriterionSpec &criterion)
  {
    return criterion.kind == Criterion::response_rise;
  }

  std::string
  status_name(const CriterionStatus status)
  {
    switch (status)
      {
        case CriterionStatus::decided:
          return "decided";
        case CriterionStatus::undecided:
          return "undecided";
        case CriterionStatus::not_reached:
          return "not reached";
      }
    return "";
  }

  CriterionValue
  wear_criterion_value(const CriterionSpec               &c,
                       const wear::StepPreview           &p,
                       const std::vector<JointDensities> &densities,
                       const double                       f)
  {
    CriterionValue out{-1, ""};
    for (std::size_t i = 0; i < p.joints.size(); ++i)
      {
        const auto &j      = p.joints[i];
        const bool  depths = c.kind == Criterion::wear_depth || c.kind == Criterion::clearance_growth;
        double      h_pin = 0, h_bore = 0;
        if (depths) // (the mass criteria need no depths)
          {
            const double r_pin  = j.state ? j.state->initial_pin.mean_radius() : 0.0;
            const double r_bore = j.state ? j.state->initial_bore.mean_radius() : 0.0;
            h_pin =
              extrapolated_envelope(j.depth_pin, j.pin_increment, f, window_of(j.state, r_pin, j.depth_pin.size()));
            h_bore =
              extrapolated_envelope(j.depth_bore, j.bore_increment, f, window_of(j.state, r_bore, j.depth_bore.size()));
          }
        const double v = joint_value(c.kind,
                                     h_pin,
                                     h_bore,
                                     milligrams(j.volume_pin + f * j.pin_volume_increment, densities[i].pin),
                                     milligrams(j.volume_bore + f * j.bore_volume_increment, densities[i].bushing));
        if (v > out.value)
          out = {v, j.state ? j.state->name : ""};
      }
    return out;
  }

  CriterionValue
  wear_criterion_value(const CriterionSpec               &c,
                       const wear::WearState             &state,
                       const std::vector<JointDensities> &densities)
  {
    CriterionValue out{-1, ""};
    for (std::size_t i = 0; i < state.joints.size(); ++i)
      {
        const auto                 &js = state.joints[i];
        const wear::IterationRecord r  = js.history.empty() ? wear::IterationRecord() : js.history.back();
        const double                v  = joint_value(c.kind,
                                     r.envelope_depth_pin,
                                     r.envelope_depth_bore,
                                     milligrams(r.volume_pin, densities[i].pin),
                                     milligrams(r.volume_bore, densities[i].bushing));
        if (v > out.value)
          out = {v, js.name};
      }
    return out;
  }

  double
  factor_to_reach(const CriterionSpec               &c,
                  const wear::StepPreview           &p,
                  const std::vector<JointDensities> &densities,
                  const double                       f_max)
  {
    const auto value = [&](const double f) {
      return wear_criterion_value(c, p, densities, f).value;
    };
    if (value(0) >= c.limit)
      return 0;
    if (!(value(f_max) >= c.limit))
      return std::numeric_limits<double>::infinity();
    double lo = 0, hi = f_max; // value(lo) < limit ≤ value(hi): the value is non-decreasing in f
    for (int k = 0; k < 200 && hi - lo > 1e-12 * hi; ++k)
      {
        const double mid                  = 0.5 * (lo + hi);
        (value(mid) >= c.limit ? hi : lo) = mid;
      }
    return hi;
  }

  double
  approach_factor(const double f_reach, const double cycles, const double revolutions, const double tolerance)
  {
    if (!std::isfinite(f_reach))
      return f_reach;
    const double remaining = f_reach * cycles; // revolutions to the crossing
    const double total     = revolutions + remaining;
    const double step      = 0.9 * tolerance * total; // the longest last step within the tolerance
    // Close enough: overshoot the predicted crossing by what the tolerance allows, so the
    // crossing is bracketed even if this iteration wears a little less than predicted.
    if (remaining <= step)
      return step / cycles;
    // Else stop half such a step short, so that the next iteration brackets it even if
    // the wear rate changes by up to a factor of 2 meanwhile.
    return (remaining - 0.5 * step) / cycles;
  }

  bool
  Interval::bounded() const
  {
    return std::isfinite(low) && std::isfinite(high);
  }

  double
  ResponseTrend::rise(const double revolutions) const
  {
    if (points < 2)
      return 0;
    return 100 * slope * revolutions / fresh;
  }

  // Fieller: the ρ with (b N − ρ a)² ≤ k (ρ²/n + (N + ρ x̄)²/Sxx), k = t² s², are those
  // between the roots of A ρ² − 2 B ρ + C with A = a² − k (1/n + x̄²/Sxx),
  // B = N (a b + k x̄/Sxx), C = N² (b² − k/Sxx) — bounded if A > 0 (a significant).
  Interval
  ResponseTrend::rise_interval(const double revolutions) const
  {
    if (points < 3 || !std::isfinite(residual_std) || !(sxx > 0))
      return {};
    const double k = t95 * t95 * residual_std * residual_std, n = static_cast<double>(points);
    const double a = fresh * fresh - k * (1 / n + mean_revolutions * mean_revolutions / sxx);
    const double b = revolutions * (fresh * slope + k * mean_revolutions / sxx);
    const double c = revolutions * revolutions * (slope * slope - k / sxx);
    const auto   r = roots(a, b, c);
    return {100 * r.low, 100 * r.high};
  }

  Interval
  ResponseTrend::excess_band(const double revolutions, const double limit) const
  {
    if (points < 3 || !std::isfinite(residual_std) || !(sxx > 0))
      return {};
    const double l = limit / 100, n = static_cast<double>(points);
    const double g = slope * revolutions - l * fresh;
    const double half =
      t95 * residual_std * std::sqrt(l * l / n + std::pow(revolutions + l * mean_revolutions, 2) / sxx);
    return {g - half, g + half};
  }

  // The N with (b N − ℓ a)² ≤ k (ℓ²/n + (N + ℓ x̄)²/Sxx) lie between the roots of
  // A N² − 2 B N + C with A = b² − k/Sxx, B = ℓ (a b + k x̄/Sxx),
  // C = ℓ² (a² − k (1/n + x̄²/Sxx)) — bounded if A > 0 (b significant).
  double
  ResponseTrend::limit_crossing(const double limit, Interval &interval) const
  {
    interval = Interval();
    if (!(slope > 0))
      return nan;
    const double l = limit / 100, crossing = l * fresh / slope;
    if (points < 3 || !std::isfinite(residual_std) || !(sxx > 0))
      return crossing;
    const double k = t95 * t95 * residual_std * residual_std, n = static_cast<double>(points);
    const double a = slope * slope - k / sxx;
    const double b = l * (fresh * slope + k * mean_revolutions / sxx);
    const double c = l * l * (fresh * fresh - k * (1 / n + mean_revolutions * mean_revolutions / sxx));
    const auto   r = roots(a, b, c);
    if (r.bounded())
      interval = {std::max(0.0, r.low), r.high};
    return crossing;
  }

  ResponseTrend
  response_trend(const std::vector<double> &revolutions, const std::vector<double> &measures, const std::size_t count)
  {
    std::vector<double> x, y;
    for (std::size_t k = 0; k < count && k < measures.size() && k < revolutions.size(); ++k)
      if (std::isfinite(measures[k]) && std::find(x.begin(), x.end(), revolutions[k]) == x.end())
        {
          x.push_back(revolutions[k]);
          y.push_back(measures[k]);
        }
    ResponseTrend t;
    t.points = x.size();
    if (x.empty())
      return t;
    const double n      = static_cast<double>(x.size());
    double       x_mean = 0, y_mean = 0, sxy = 0, sxx = 0;
    for (std::size_t k = 0; k < x.size(); ++k)
      {
        x_mean += x[k] / n;
        y_mean += y[k] / n;
      }
    for (std::size_t k = 0; k < x.size(); ++k)
      {
        sxx += (x[k] - x_mean) * (x[k] - x_mean);
        sxy += (x[k] - x_mean) * (y[k] - y_mean);
      }
    t.mean_revolutions = x_mean;
    t.sxx              = sxx;
    t.slope            = t.points >= 2 && sxx > 0 ? sxy / sxx : 0.0;
    t.fresh            = y_mean - t.slope * x_mean;
    if (t.points < 3)
      return t;
    double squares = 0;
    for (std::size_t k = 0; k < x.size(); ++k)
      squares += std::pow(y[k] - t.fresh - t.slope * x[k], 2);
    t.residual_std = std::sqrt(squares / (n - 2));
    t.scatter      = t.residual_std / t.fresh;
    t.t95          = student_t_quantile(0.975, n - 2);
    return t;
  }

  TrendCrossing
  trend_crossing(const ResponseTrend &trend, const double limit, const double revolutions_run, const double tolerance)
  {
    TrendCrossing x;
    x.revolutions     = trend.limit_crossing(limit, x.interval);
    x.rise_at_end     = trend.rise_interval(revolutions_run);
    const auto g      = trend.excess_band(revolutions_run, limit);
    const auto number = [](const double v) {
      return format_number(v, 4);
    };
    const auto revs = [](const double v) { // whole revolutions, without an exponent
      return format_number(std::round(v), 15);
    };
    const auto rise_ci = number(x.rise_at_end.low) + " … " + number(x.rise_at_end.high) + " %";
    const auto at_end  = " at " + revs(revolutions_run) + " rev";
    if (trend.points < min_response_points)
      x.reason =
        std::to_string(trend.points) + " measurement(s): the trend counts from " + std::to_string(min_response_points);
    else if (!g.bounded())
      x.reason = "the measurements have no spread in revolutions: no trend";
    else if (g.high < 0)
      {
        x.status = CriterionStatus::not_reached;
        x.reason = "the 95 % interval of the rise" + at_end + ", " + rise_ci + ", is below the limit";
      }
    else if (g.low < 0)
      x.reason =
        "the 95 % interval of the rise" + at_end + ", " + rise_ci + ", contains the limit " + number(limit) + " %";
    else
      {
        x.reached = true;
        if (!x.interval.bounded())
          x.reason = "reached, but the slope is not significant: the interval of the crossing is unbounded";
        else if (x.interval.high - x.interval.low > tolerance * x.revolutions)
          x.reason = "reached, but the 95 % interval of the crossing, " + revs(x.interval.low) + " … " +
                     revs(x.interval.high) + " rev, is " +
                     number(100 * (x.interval.high - x.interval.low) / x.revolutions) +
                     " % of it wide (Life/Response tolerance " + number(100 * tolerance) + " %)";
        else
          x.status = CriterionStatus::decided;
      }
    return x;
  }

  std::optional<std::size_t>
  headline_criterion(const std::vector<CriterionOutcome> &outcomes)
  {
    std::optional<std::size_t> first;
    for (std::size_t c = 0; c < outcomes.size(); ++c)
      if (outcomes[c].status == CriterionStatus::decided && std::isfinite(outcomes[c].revolutions) &&
          (!first || outcomes[c].revolutions < outcomes[*first].revolutions))
        first = c;
    return first;
  }

  std::vector<double>
  LifeHistory::column(const std::size_t c) const
  {
    std::vector<double> v;
    for (const auto &row : values)
      v.push_back(row.at(c));
    return v;
  }

  void
  LifeHistory::truncate(const unsigned int iterations_done)
  {
    std::size_t keep = 0;
    while (keep < iterations.size() && iterations[keep] <= iterations_done)
      ++keep;
    iterations.resize(keep);
    revolutions.resize(keep);
    factors.resize(keep);
    values.resize(keep);
    joints.resize(keep);
    response.resize(keep);
  }

  Crossing
  first_crossing(const std::vector<double> &revolutions, const std::vector<double> &values, const double limit)
  {
    Crossing c;
    for (std::size_t k = 0; k < values.size() && k < revolutions.size(); ++k)
      {
        if (!(values[k] >= limit * (1 - 1e-9)))
          continue;
        c.reached   = true;
        c.iteration = k;
        c.high      = revolutions[k];
        c.low       = k == 0 ? revolutions[k] : revolutions[k - 1];
        if (k == 0 || !(values[k] > values[k - 1]))
          c.revolutions = c.high;
        else
          {
            const double w = std::clamp((limit - values[k - 1]) / (values[k] - values[k - 1]), 0.0, 1.0);
            c.revolutions  = c.low + w * (c.high - c.low);
          }
        return c;
      }
    return c;
  }
} // namespace wearlink::analysis
