// SPDX-License-Identifier: LGPL-2.1-or-later
#include "analysis/life_criteria.h"

#include "base/numbers.h"
#include "base/text.h"
#include "wear/depth_measures.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

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

    /** One wearing joint's depths [m] and mass losses [mg], the criteria's arguments. */
    struct WearFigures
    {
      std::string name;
      double      h_pin = 0, h_bore = 0, m_pin = 0, m_bush = 0;
    };

    /**
     * The largest value of @p row over the joints: a depth criterion's over the wearing
     * joints (slices included: the deepest slice), a mass criterion's over the whole
     * joints (a sliced joint's slices summed, named by the joint).
     */
    CriterionValue
    largest_value(const CriterionRow                &row,
                  const std::vector<WearFigures>    &wear,
                  const std::vector<JointDensities> &densities)
    {
      std::vector<WearFigures> whole;
      for (std::size_t i = 0; i < wear.size(); ++i)
        {
          const std::string &joint = densities[i].joint;
          auto               it    = std::find_if(whole.begin(), whole.end(), [&](const WearFigures &w) {
            return !joint.empty() && w.name == joint;
          });
          if (row.depths || joint.empty() || it == whole.end())
            {
              whole.push_back(wear[i]);
              if (!row.depths && !joint.empty())
                whole.back().name = joint;
              continue;
            }
          it->m_pin += wear[i].m_pin;
          it->m_bush += wear[i].m_bush;
        }
      CriterionValue out{-1, ""};
      for (const auto &w : whole)
        {
          const double v = row.joint_value(w.h_pin, w.h_bore, w.m_pin, w.m_bush);
          if (v > out.value)
            out = {v, w.name};
        }
      return out;
    }

  } // namespace

  const std::vector<CriterionRow> &
  criteria_table()
  {
    static const std::vector<CriterionRow> table = {
      {Criterion::wear_depth,
       "wear_depth",
       "Maximum wear depth",
       "m",
       0.1,
       "Stop criterion of `wearlink life`: the largest envelope depth of any surface (pin or bore) of any wearing "
       "joint — the largest running median of the depth over the joint's contact width (2b of the Hertz strip at "
       "the first iteration's peak force), so a one-area spike does not reach it and a pocket as wide as the "
       "contact does — 0 … 0.1 m (a wear depth beyond 10 cm is no joint's); 0: off.",
       false,
       true,
       [](double h_pin, double h_bore, double, double) {
         return std::max(h_pin, h_bore);
       }},
      {Criterion::clearance_growth,
       "clearance_growth",
       "Radial clearance growth",
       "m",
       0.1,
       "Stop criterion: the growth of a joint's radial clearance, the envelope depth of its bore plus that of its "
       "pin (see Maximum wear depth; they face each other once per relative revolution), 0 … 0.1 m; 0: off.",
       false,
       true,
       [](double h_pin, double h_bore, double, double) {
         return h_pin + h_bore;
       }},
      {Criterion::pin_mass_loss,
       "pin_mass_loss",
       "Pin mass loss",
       "mg",
       1e9,
       "Stop criterion: the mass worn off a joint's pin (worn volume × Pin density), 0 … 1e9 mg (1 t); 0: off.",
       false,
       false,
       [](double, double, double m_pin, double) {
         return m_pin;
       }},
      {Criterion::bushing_mass_loss,
       "bushing_mass_loss",
       "Bushing mass loss",
       "mg",
       1e9,
       "Stop criterion: the mass worn off a joint's bushing, 0 … 1e9 mg; 0: off.",
       false,
       false,
       [](double, double, double, double m_bush) {
         return m_bush;
       }},
      {Criterion::response_rise,
       "response_rise",
       "Response rise",
       "%",
       1e4,
       "Stop criterion: the rise of the response measure — the mean over Response cycles of the per-cycle peak "
       "acceleration magnitude of Response body, over every accepted integrator step, in a run from the initial "
       "assembly with the current profiles after one settling cycle, measured after every wear iteration — over "
       "its value with the fresh profiles, 0 … 1e4 %; 0: off (and no response runs). The measure scatters, so the "
       "criterion is decided on a trend fitted through all measurements — a line, a step or a ramp, chosen by "
       "BIC: reached when the lower 95 % confidence bound of the trend's rise is at the limit, located where the "
       "trend crosses it, with the 95 % interval of that crossing (profile likelihood; see Response tolerance); "
       "an undecided criterion is never the life, unless it is reached and its whole interval lies before every "
       "reached wear criterion.",
       true,
       false,
       nullptr}};
    return table;
  }

  const CriterionRow &
  row_of(const Criterion kind)
  {
    for (const auto &r : criteria_table())
      if (r.kind == kind)
        return r;
    throw std::logic_error("a criterion without a row in criteria_table()");
  }

  double
  LifeSettings::limit(const Criterion kind) const
  {
    const auto &t = criteria_table();
    for (std::size_t k = 0; k < t.size() && k < limits.size(); ++k)
      if (t[k].kind == kind)
        return limits[k];
    return 0;
  }

  std::vector<CriterionSpec>
  active_criteria(const LifeSettings &s)
  {
    std::vector<CriterionSpec> on;
    for (const auto &r : criteria_table())
      if (s.limit(r.kind) > 0)
        on.push_back({r.kind, r.name, r.entry, r.unit, s.limit(r.kind)});
    return on;
  }

  bool
  is_trend(const CriterionSpec &criterion)
  {
    return row_of(criterion.kind).trend;
  }

  bool
  first_for_certain(const TrendCrossing &t, const double wear_life)
  {
    return t.status != CriterionStatus::decided && t.reached && t.interval.bounded() && t.interval.high < wear_life;
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
    const auto &row = row_of(c.kind);
    if (!row.joint_value)
      return {nan, ""};
    std::vector<WearFigures> wear;
    for (std::size_t i = 0; i < p.joints.size(); ++i)
      {
        const auto &j = p.joints[i];
        WearFigures w{j.state ? j.state->name : "",
                      0,
                      0,
                      milligrams(j.volume_pin + f * j.pin_volume_increment, densities[i].pin),
                      milligrams(j.volume_bore + f * j.bore_volume_increment, densities[i].bushing)};
        if (row.depths) // (the mass criteria need no depths)
          {
            const double r_pin  = j.state ? j.state->initial_pin.mean_radius() : 0.0;
            const double r_bore = j.state ? j.state->initial_bore.mean_radius() : 0.0;
            w.h_pin =
              extrapolated_envelope(j.depth_pin, j.pin_increment, f, window_of(j.state, r_pin, j.depth_pin.size()));
            w.h_bore =
              extrapolated_envelope(j.depth_bore, j.bore_increment, f, window_of(j.state, r_bore, j.depth_bore.size()));
          }
        wear.push_back(w);
      }
    return largest_value(row, wear, densities);
  }

  CriterionValue
  wear_criterion_value(const CriterionSpec               &c,
                       const wear::WearState             &state,
                       const std::vector<JointDensities> &densities)
  {
    const auto &row = row_of(c.kind);
    if (!row.joint_value)
      return {nan, ""};
    std::vector<WearFigures> wear;
    for (std::size_t i = 0; i < state.joints.size(); ++i)
      {
        const auto                 &js = state.joints[i];
        const wear::IterationRecord r  = js.history.empty() ? wear::IterationRecord() : js.history.back();
        wear.push_back({js.name,
                        r.envelope_depth_pin,
                        r.envelope_depth_bore,
                        milligrams(r.volume_pin, densities[i].pin),
                        milligrams(r.volume_bore, densities[i].bushing)});
      }
    return largest_value(row, wear, densities);
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

  namespace
  {
    /** Whole revolutions, without an exponent. */
    std::string
    revolutions_text(const double v)
    {
      return format_number(std::round(v), 15);
    }

    /**
     * Why a reached criterion is not decided ("" if it is): its crossing is not bounded or
     * wider than @p tolerance × the crossing.
     */
    std::string
    why_not_located(const TrendCrossing &x, const std::string &model, const double tolerance)
    {
      if (!std::isfinite(x.revolutions))
        return "reached, but the " + model + "'s crossing is not located";
      if (!x.interval.bounded())
        return "reached, but the 95 % interval of the " + model + "'s crossing is unbounded";
      if (x.interval.high - x.interval.low > tolerance * x.revolutions)
        return "reached, but the 95 % interval of the " + model + "'s crossing, " + revolutions_text(x.interval.low) +
               " … " + revolutions_text(x.interval.high) + " rev, is " +
               format_number(100 * (x.interval.high - x.interval.low) / x.revolutions, 4) +
               " % of it wide (Life/Response tolerance " + format_number(100 * tolerance, 4) + " %)";
      return "";
    }
  } // namespace

  TrendCrossing
  trend_crossing(const ResponseModels &models,
                 const TrendFamily     family,
                 const double          limit,
                 const double          revolutions_run,
                 const double          tolerance)
  {
    TrendCrossing x;
    x.family = family;
    if (models.points() < min_response_points || !models.has(family))
      {
        x.reason = std::to_string(models.points()) + " measurement(s): the trend counts from " +
                   std::to_string(min_response_points);
        return x;
      }
    const std::string model = family_name(family);
    x.revolutions           = models.model(family).crossing(limit);
    x.interval              = models.crossing_interval(family, limit);
    x.rise_at_end           = models.rise_interval(family, revolutions_run);
    const auto g            = models.excess_band(family, revolutions_run, limit);
    const auto rise_ci = format_number(x.rise_at_end.low, 4) + " … " + format_number(x.rise_at_end.high, 4) + " %";
    const auto at_end =
      "the " + model + "'s 95 % interval of the rise at " + revolutions_text(revolutions_run) + " rev, " + rise_ci;
    if (!g.bounded())
      x.reason = "the measurements have no spread in revolutions: no trend";
    else if (g.high < 0)
      {
        x.status = CriterionStatus::not_reached;
        x.reason = at_end + ", is below the limit";
      }
    else if (g.low < 0)
      x.reason = at_end + ", contains the limit " + format_number(limit, 4) + " %";
    else
      {
        x.reached = true;
        x.reason  = why_not_located(x, model, tolerance);
        if (x.reason.empty())
          x.status = CriterionStatus::decided;
      }
    return x;
  }

  TrendCrossing
  trend_crossing(const ResponseModels &models, const double limit, const double revolutions_run, const double tolerance)
  {
    return trend_crossing(models, models.chosen(), limit, revolutions_run, tolerance);
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
