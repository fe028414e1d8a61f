// SPDX-License-Identifier: LGPL-2.1-or-later
#include "analysis/life_criteria.h"

#include <algorithm>
#include <cmath>

namespace wearlink::analysis
{
  namespace
  {
    double
    max_of(const std::vector<double> &v)
    {
      return v.empty() ? 0.0 : *std::max_element(v.begin(), v.end());
    }

    /** max_k (h_k + f Δh_k) [m]. */
    double
    extrapolated_max(const std::vector<double> &h, const std::vector<double> &increment, const double f)
    {
      double m = 0;
      for (std::size_t k = 0; k < h.size(); ++k)
        m = std::max(m, h[k] + f * (k < increment.size() ? increment[k] : 0.0));
      return m;
    }

    /** [m³] → [mg] for density @p rho [kg/m³]. */
    double
    milligrams(const double volume, const double rho)
    {
      return volume * rho * 1e6;
    }

    /** The value of criterion @p kind of one joint with these depths and volumes. */
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
      return std::numeric_limits<double>::quiet_NaN();
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

  CriterionValue
  wear_criterion_value(const CriterionSpec               &c,
                       const wear::StepPreview           &p,
                       const std::vector<JointDensities> &densities,
                       const double                       f)
  {
    CriterionValue out{-1, ""};
    for (std::size_t i = 0; i < p.joints.size(); ++i)
      {
        const auto  &j = p.joints[i];
        const double v = joint_value(c.kind,
                                     extrapolated_max(j.depth_pin, j.pin_increment, f),
                                     extrapolated_max(j.depth_bore, j.bore_increment, f),
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
                                     max_of(r.depth_pin),
                                     max_of(r.depth_bore),
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
    if (remaining <= tolerance * total)
      return f_reach;
    // Leave half the allowed last step, so that the next iteration lands even if the
    // wear rate changes by up to a factor of 2 meanwhile (else a tiny step may follow).
    return (remaining - 0.5 * tolerance * total) / cycles;
  }

  double
  ResponseTrend::rise(const double revolutions) const
  {
    if (points < 2)
      return 0;
    return 100 * slope * revolutions / fresh;
  }

  ResponseTrend
  response_trend(const std::vector<double> &revolutions, const std::vector<double> &measures, const std::size_t count)
  {
    ResponseTrend t;
    double        sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (std::size_t k = 0; k < count && k < measures.size(); ++k)
      if (std::isfinite(measures[k]))
        {
          sx += revolutions[k];
          sy += measures[k];
          sxx += revolutions[k] * revolutions[k];
          sxy += revolutions[k] * measures[k];
          ++t.points;
        }
    const double n = static_cast<double>(t.points), d = n * sxx - sx * sx;
    if (t.points == 0)
      return t;
    t.slope        = t.points >= 2 && d > 0 ? (n * sxy - sx * sy) / d : 0.0;
    t.fresh        = (sy - t.slope * sx) / n;
    double squares = 0;
    for (std::size_t k = 0; k < count && k < measures.size(); ++k)
      if (std::isfinite(measures[k]))
        squares += std::pow(measures[k] - t.fresh - t.slope * revolutions[k], 2);
    t.scatter = t.points > 2 ? std::sqrt(squares / (n - 2)) / t.fresh : std::numeric_limits<double>::quiet_NaN();
    return t;
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
