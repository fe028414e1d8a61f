// SPDX-License-Identifier: LGPL-2.1-or-later
// When is a joint worn out? The stop criteria of `wearlink life` (issue 15), the values
// they take during a wear run, and how far each wear iteration may extrapolate so that
// every criterion is located within a stated tolerance.
//
// Criteria (scene section "Life"; a limit of 0 switches one off):
//   wear_depth        the largest wear depth of any surface (pin or bore) of any wearing
//                     joint [m];
//   clearance_growth  the growth of the largest radial clearance of a joint: its deepest
//                     bore wear plus its deepest pin wear, which face each other once per
//                     relative revolution of pin and bushing [m];
//   pin_mass_loss     the mass worn off a joint's pin (volume × density) [mg];
//   bushing_mass_loss the same of a bushing [mg];
//   response_rise     the rise of the response measure's trend over its value with the
//                     fresh profiles [%]. The measure: the mean over `Response cycles`
//                     driving cycles of the per-cycle peak |a| of the response body (every
//                     accepted integrator step, analysis/cycle_peaks.h), in a run from the
//                     initial assembly with the current profiles after one settling cycle.
//                     It scatters by ~10 % from one measurement to the next (the impacts
//                     of a chaotic clearance mechanism: a rise is reached by noise long
//                     before the joint has changed), so the criterion follows its trend:
//                     the least-squares line through every measurement so far (the fresh
//                     one included) against revolutions, rise = line(N)/line(0) − 1; it
//                     counts from the 4th measurement on.
// A joint criterion is reached when any wearing joint reaches it (the summary names it).
//
// Locating a crossing. An iteration extrapolates its simulated wear by a factor f: the
// depths become h + f Δh, the volumes V + f ΔV, so each wear criterion is a
// non-decreasing, piecewise-linear function of f, known before the step
// (wear::StepPreview); the factor at which it reaches its limit is found by bisection to
// 1e-12. The response is measured after each iteration; its next crossing is predicted
// from the trend of the last two measurements. With tolerance τ the iteration that
// crosses must represent at most τ × the revolutions at its end: if the predicted
// crossing is farther, the iteration stops short of it by half such a step (room for the
// rate to change by up to a factor of 2), and the next one lands on it. The life is reported as the revolutions at the crossing (linear
// interpolation between the two iterations that bracket it; for the wear criteria the
// landing makes the crossing the iteration's end) with the bracket, whose width is then
// ≤ τ × life unless a response measurement jumped past its prediction (then the summary
// says that the bracket is wider than the tolerance).
#pragma once

#include "wear/wear_loop.h"

#include <limits>
#include <string>
#include <vector>

namespace wearlink::analysis
{
  enum class Criterion
  {
    wear_depth,
    clearance_growth,
    pin_mass_loss,
    bushing_mass_loss,
    response_rise
  };

  /** The scene's "Life" section (declared and read by io/life_parameters.h). */
  struct LifeSettings
  {
    double       max_wear_depth    = 0;  ///< [m]; 0: off
    double       clearance_growth  = 0;  ///< [m]; 0: off
    double       pin_mass_loss     = 0;  ///< [mg]; 0: off
    double       bushing_mass_loss = 0;  ///< [mg]; 0: off
    double       response_rise     = 0;  ///< [%]; 0: off
    std::string  response_body;          ///< "" : Wear/Response body
    unsigned int response_cycles = 3;    ///< cycles averaged (after one settling cycle)
    double       tolerance       = 0.02; ///< τ [-]
    double       max_revolutions = 1e8;  ///< the run ends there at the latest [-]
    unsigned int max_iterations  = 1000; ///< and after this many iterations
  };

  /** One active criterion. */
  struct CriterionSpec
  {
    Criterion   kind;
    std::string name;  ///< "wear_depth", …: the key in summary.json and the CSV
    std::string entry; ///< "Maximum wear depth", …: the scene entry
    std::string unit;  ///< "m", "mg", "%"
    double      limit = 0;
  };

  /** The criteria switched on by @p settings, in the order above. */
  std::vector<CriterionSpec>
  active_criteria(const LifeSettings &settings);

  /** Densities of a wearing joint's pin and bushing [kg/m³], for the mass losses. */
  struct JointDensities
  {
    double pin = 0, bushing = 0;
  };

  /** A criterion's value and the joint that has it ("" for the response). */
  struct CriterionValue
  {
    double      value = 0;
    std::string joint;
  };

  /**
   * The value of the wear criterion @p c after extrapolating @p preview's iteration by
   * @p factor (0: the wear before the iteration). @p densities: per joint of the preview.
   */
  CriterionValue
  wear_criterion_value(const CriterionSpec               &c,
                       const wear::StepPreview           &preview,
                       const std::vector<JointDensities> &densities,
                       double                             factor);

  /** The value of the wear criterion @p c in @p state (after its last iteration). */
  CriterionValue
  wear_criterion_value(const CriterionSpec               &c,
                       const wear::WearState             &state,
                       const std::vector<JointDensities> &densities);

  /**
   * The smallest factor in [0, @p f_max] at which the wear criterion @p c reaches its
   * limit (bisection to 1e-12 relative; the value there is ≥ the limit), or +∞ if it
   * stays below up to @p f_max.
   */
  double
  factor_to_reach(const CriterionSpec               &c,
                  const wear::StepPreview           &preview,
                  const std::vector<JointDensities> &densities,
                  double                             f_max);

  /**
   * The factor of an iteration of @p cycles simulated cycles that starts at
   * @p revolutions when the crossing is predicted at factor @p f_reach: f_reach if that
   * step is at most @p tolerance × the revolutions at its end, else the factor that
   * leaves half such a step to the crossing (see the file comment).
   */
  double
  approach_factor(double f_reach, double cycles, double revolutions, double tolerance);

  /** Where a criterion was crossed, from the values after each iteration. */
  struct Crossing
  {
    bool   reached     = false;
    double revolutions = std::numeric_limits<double>::quiet_NaN(); ///< interpolated
    double low = std::numeric_limits<double>::quiet_NaN(), high = std::numeric_limits<double>::quiet_NaN(); ///< bracket
    std::size_t iteration = 0; ///< the row at which it was first reached
  };

  /** How many response measurements the trend needs before the response criterion counts. */
  constexpr std::size_t min_response_points = 4;

  /** The least-squares line of the response measures [m/s²] against revolutions. */
  struct ResponseTrend
  {
    double      fresh   = std::numeric_limits<double>::quiet_NaN(); ///< the line at 0 revolutions [m/s²]
    double      slope   = std::numeric_limits<double>::quiet_NaN(); ///< [m/s² per revolution]
    double      scatter = std::numeric_limits<double>::quiet_NaN(); ///< residuals' standard deviation / fresh [-]
    std::size_t points  = 0;

    /** The rise of the line at @p revolutions over its fresh value [%] (0 with one point). */
    double
    rise(double revolutions) const;
  };

  /** The trend of the finite @p measures at @p revolutions (the first @p count rows). */
  ResponseTrend
  response_trend(const std::vector<double> &revolutions, const std::vector<double> &measures, std::size_t count);

  /**
   * What a life run knows after each iteration: one row per iteration (row 0: the start,
   * before any wear), each criterion's value and the joint that has it, and the response
   * measure [m/s²] (NaN without the response criterion). Kept in life_history.csv, from
   * which a resumed run reads it back.
   */
  struct LifeHistory
  {
    std::vector<CriterionSpec>            criteria;
    std::vector<unsigned int>             iterations;
    std::vector<double>                   revolutions, factors;
    std::vector<std::vector<double>>      values;   ///< [row][criterion]
    std::vector<std::vector<std::string>> joints;   ///< [row][criterion]
    std::vector<double>                   response; ///< the measure of each row [m/s²]

    std::size_t
    rows() const
    {
      return revolutions.size();
    }
    /** The values of criterion @p c, one per row. */
    std::vector<double>
    column(std::size_t c) const;
    /** Drop the rows of iterations after @p iterations_done (a run resumed from that checkpoint). */
    void
    truncate(unsigned int iterations_done);
  };

  /**
   * The first crossing of @p limit by @p values (one per row; row 0 the start) at
   * @p revolutions (the same rows), linearly interpolated inside its bracket. A value
   * counts as reaching the limit from limit × (1 − 1e-9) (the rounding of a landing).
   */
  Crossing
  first_crossing(const std::vector<double> &revolutions, const std::vector<double> &values, double limit);
} // namespace wearlink::analysis
