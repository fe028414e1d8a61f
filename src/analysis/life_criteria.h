// SPDX-License-Identifier: LGPL-2.1-or-later
// When is a joint worn out? The stop criteria of `wearlink life`, the values
// they take during a wear run, how far each wear iteration may extrapolate so that every
// wear criterion is located within a stated tolerance, and how a noisy criterion is
// decided on its trend with a confidence band.
//
// Criteria (scene section "Life"; a limit of 0 switches one off):
//   wear_depth        the largest envelope depth of any surface (pin or bore) of any
//                     wearing joint [m];
//   clearance_growth  the growth of a joint's radial clearance: the envelope depth of its
//                     bore plus that of its pin, which face each other once per relative
//                     revolution of pin and bushing [m];
//   pin_mass_loss     the mass worn off a joint's pin (volume × density) [mg];
//   bushing_mass_loss the same of a bushing [mg];
//   response_rise     the rise of the response measure's trend over its value with the
//                     fresh profiles [%]. The measure: the mean over `Response cycles`
//                     driving cycles of the per-cycle peak |a| of the response body (every
//                     accepted integrator step, analysis/cycle_peaks.h), in a run from the
//                     initial assembly with the current profiles after one settling cycle,
//                     measured before the first iteration and after each.
// A joint criterion is reached when any wearing joint reaches it (the summary names it).
//
// The envelope depth (wear/depth_measures.h): the largest running median of a surface's
// depth over the joint's contact width (JointWearState::contact_width, 2b of the Hertz
// strip at the first iteration's peak force; the window of the wear loop's own depth
// measures). A spike of one discrete area deeper than its neighbours is no clearance the
// contact meets and does not reach a depth limit; a pocket as wide as the contact does.
//
// Locating a wear crossing. An iteration extrapolates its simulated wear by a factor f:
// the depths become h + f Δh, the volumes V + f ΔV, so each wear criterion is a known
// function of f before the step (wear::StepPreview), non-decreasing (a running median of
// values that each grow with f grows with f; so does a maximum or a sum of them); the
// factor at which it reaches its limit is found by bisection to 1e-12. With tolerance τ
// the iteration that crosses must represent at most τ × the revolutions at its end. The
// last step is 0.9 τ × the revolutions at the predicted crossing: if the crossing is
// within it, the iteration takes that whole step and overshoots the prediction (a wear
// rate a little below the predicted one still crosses); if it is farther, the iteration
// stops half such a step short (room for the rate to change by up to a factor of 2), and
// the next one takes the last step. The life is the crossing interpolated between the two
// iterations that bracket it, with that bracket, ≤ τ × life wide. A wear
// criterion is decided when it is reached.
//
// Deciding a noisy criterion on its trend. The response measure scatters by 10–30 % from
// one measurement to the next (the impacts of a chaotic clearance mechanism): one sample
// above the limit says nothing. The criterion follows a trend fitted by least squares to
// every measurement (the fresh one included; a measurement at the revolutions of an
// earlier one, an iteration that wore nothing, is the same run and is counted once): a
// line, a step (the level jumps between two measurements) or a ramp (the fresh level, a
// straight rise, a plateau), the one with the smallest BIC (analysis/response_models.h:
// the models, their fits, the choice and the 95 % statements). The rise is the trend's
// over its own fresh level, r(N) = 100 β w(N)/a. At the revolutions of the last
// measurement the criterion is, on the chosen model,
//   reached      if the lower 95 % bound of the rise there is at or above the limit,
//   not reached  if the upper 95 % bound is below it,
//   undecided    otherwise (the band contains the limit),
// and it counts from the 4th measurement (min_response_points). For a line the bounds are
// Fieller's, exact for normal scatter: with ℓ the limit as a fraction, r ≥ ℓ ⇔
// g(N) = b N − ℓ a ≥ 0, g ± t s √(ℓ²/n + (N + ℓ x̄)²/Sxx), t = t(0.975, n − 2); for a step
// or a ramp they are the union of those of the change points the data admit (profile
// likelihood). Where it crosses: the model's crossing N̂ (a line's ℓ a/b, a ramp's point
// on its rise, a step's jump) with its 95 % interval (a line's inverse regression, bounded
// only if the slope is significant; a step's gaps, a ramp's points where the limit may be
// crossed). The criterion is decided when it is reached and that interval is at most
// Response tolerance × N̂ wide; a reached criterion with a wider interval, like one whose
// band contains the limit, is undecided and reported with what is known (N̂, the interval
// if bounded, the model and the others' scores). An undecided criterion is never a life:
// the headline is the decided criterion with the fewest revolutions (headline_criterion).
#pragma once

#include "analysis/response_models.h"
#include "wear/wear_loop.h"

#include <limits>
#include <optional>
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

  /**
   * One row of the criteria table: everything that defines a criterion. A new criterion
   * is a member of Criterion and a row (life_criteria.cc); the scene entry is declared,
   * read and switched on from its row.
   */
  struct CriterionRow
  {
    Criterion   kind;
    const char *name;    ///< the key in summary.json and life_history.csv
    const char *entry;   ///< its limit's entry in the scene's Life section
    const char *unit;    ///< of the limit: "m", "mg", "%"
    double      upper;   ///< the largest limit accepted (0 … upper; 0: off)
    const char *meaning; ///< the entry's documentation (--print-parameters, doc/parameters.md)
    bool        trend;   ///< decided on a trend of noisy measurements, not when reached
    bool        depths;  ///< its joint value needs the envelope depths (extrapolated per factor)
    /** A wearing joint's value from its envelope depths [m] and mass losses [mg] (wear criteria). */
    double (*joint_value)(double h_pin, double h_bore, double m_pin, double m_bush);
  };

  /** Every criterion, in the order they are reported. */
  const std::vector<CriterionRow> &
  criteria_table();

  /** The row of @p kind. */
  const CriterionRow &
  row_of(Criterion kind);

  /** The scene's "Life" section (declared and read by analysis/life_parameters.h). */
  struct LifeSettings
  {
    std::vector<double> limits;                    ///< per row of criteria_table(), in its unit; 0: off
    std::string         response_body;             ///< "" : Wear/Response body
    unsigned int        response_cycles    = 3;    ///< cycles averaged (after one settling cycle)
    double              response_tolerance = 0.5;  ///< largest width of the trend's 95 % interval / its crossing [-]
    double              tolerance          = 0.02; ///< τ [-]
    double              max_revolutions    = 1e9;  ///< the run ends there at the latest [-]
    unsigned int        max_iterations     = 1000; ///< and after this many iterations

    /** The limit of @p kind (0: off). */
    double
    limit(Criterion kind) const;
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

  /** True for a criterion decided on its trend (response_rise), false for a wear criterion. */
  bool
  is_trend(const CriterionSpec &criterion);

  /** Where a criterion stands at the end of a run (see the file comment). */
  enum class CriterionStatus
  {
    decided,
    undecided,
    not_reached
  };

  /** "decided", "undecided", "not reached": the status in summary.json. */
  std::string
  status_name(CriterionStatus status);

  /**
   * Densities of a wearing joint's pin and bushing [kg/m³], for the mass losses, and the
   * joint it is part of: a sliced joint's name for each of its slices (their masses add
   * up to the pin's and the bushing's; the deepest slice has the joint's depth), else
   * empty (the wearing joint is a whole joint).
   */
  struct JointDensities
  {
    double      pin = 0, bushing = 0;
    std::string joint;
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
   * The depth criteria take the envelope of h + f Δh over the window of the joint's
   * contact width (StepPreview::Joint::state; a joint without its state has no contact
   * width and takes one area, the raw largest depth).
   */
  CriterionValue
  wear_criterion_value(const CriterionSpec               &c,
                       const wear::StepPreview           &preview,
                       const std::vector<JointDensities> &densities,
                       double                             factor);

  /**
   * The value of the wear criterion @p c in @p state (after its last iteration); the depth
   * criteria from the records' envelope depths (IterationRecord::envelope_depth_pin/bore).
   */
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
   * @p revolutions when the crossing is predicted at factor @p f_reach. The last step
   * may be 0.9 × @p tolerance × the revolutions at the crossing: if the crossing is
   * within it, the factor of that whole step (it overshoots the prediction, so a slightly
   * smaller wear rate still brackets the crossing); else the factor that leaves half
   * such a step to the crossing.
   */
  double
  approach_factor(double f_reach, double cycles, double revolutions, double tolerance);

  /** Where a wear criterion was crossed, from the values after each iteration. */
  struct Crossing
  {
    bool   reached     = false;
    double revolutions = std::numeric_limits<double>::quiet_NaN(); ///< interpolated
    double low = std::numeric_limits<double>::quiet_NaN(), high = std::numeric_limits<double>::quiet_NaN(); ///< bracket
    std::size_t iteration = 0; ///< the row at which it was first reached
  };

  /** How many response measurements the trend needs before the response criterion counts. */
  constexpr std::size_t min_response_points = 4;

  /** Where a trend criterion stands (see the file comment). */
  struct TrendCrossing
  {
    CriterionStatus status      = CriterionStatus::undecided;
    TrendFamily     family      = TrendFamily::line; ///< the model it stands on
    bool            reached     = false; ///< the lower 95 % bound of the rise at the last measurement ≥ the limit
    double          revolutions = std::numeric_limits<double>::quiet_NaN(); ///< the model's crossing
    Interval        interval;                                               ///< of the crossing [revolutions]
    Interval        rise_at_end; ///< 95 % interval of the rise at the last measurement [%]
    std::string     reason;      ///< why it is not decided ("" if it is)
  };

  /**
   * Where the trend criterion of limit @p limit [%] stands on the model @p family of
   * @p models after measurements up to @p revolutions_run: decided if reached with an
   * interval of the crossing at most @p tolerance × the crossing wide, not reached if the
   * upper 95 % bound of the rise there is below the limit, else undecided (also with fewer
   * than min_response_points measurements, or without a fit of that family).
   */
  TrendCrossing
  trend_crossing(const ResponseModels &models,
                 TrendFamily           family,
                 double                limit,
                 double                revolutions_run,
                 double                tolerance);

  /** trend_crossing() on the model @p models chose (ResponseModels::chosen). */
  TrendCrossing
  trend_crossing(const ResponseModels &models, double limit, double revolutions_run, double tolerance);

  /**
   * True if the trend criterion @p t, reached but located less precisely than its
   * tolerance, still certainly comes first: the whole 95 % interval of its crossing ends
   * before @p wear_life (the earliest wear life it competes with; +∞ if none). Then it is
   * the life, with that interval.
   */
  bool
  first_for_certain(const TrendCrossing &t, double wear_life);

  /** What the headline needs of a criterion's result. */
  struct CriterionOutcome
  {
    CriterionStatus status      = CriterionStatus::not_reached;
    double          revolutions = std::numeric_limits<double>::quiet_NaN(); ///< its life, if decided
  };

  /**
   * The headline: the index of the decided criterion with the fewest revolutions (the
   * first of equal ones); none if no criterion is decided. An undecided criterion is
   * never the headline, however early its estimate.
   */
  std::optional<std::size_t>
  headline_criterion(const std::vector<CriterionOutcome> &outcomes);

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
