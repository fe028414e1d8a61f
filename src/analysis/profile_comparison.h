// SPDX-License-Identifier: LGPL-2.1-or-later
// A measured worn profile (a profilometer or CMM trace of a pin or a bore) against the
// one a wear run predicts. The math only; files are read and written by
// workflows/compare/profile_comparison.h.
//
// Both are closed polar traces, radius [m] against angle [rad], linear in the angle
// between their points (as base/profile.h interpolates), at any spacing. Two traces are
// compared on their common angles: the union of both sets of points, each trace
// interpolated periodically onto the other's. Between two common angles both are linear,
// so their difference d is too, and its mean square over the circle is exact:
//   RMS² = (1/2π) Σ_segments h (d₀² + d₀d₁ + d₁²)/3.
// A dense stretch of one trace therefore weighs as much as a sparse one of equal arc.
//
// Alignment. A measured trace's angular origin is unknown: the rotation θ with
// |θ| ≤ search that minimises the RMS is found by a scan (step: half the mean spacing of
// the coarser trace, at most 1°, at least 2·search/3600) and Brent's minimisation
// (boost::math) within one step of the best scanned rotation. A feature that either trace
// resolves spans at least two of its spacings, so the basin of the best rotation is at
// least a spacing wide and the scan lands in it. The convention: the measured point at
// angle a lies at a + θ in the run's frame (θ > 0 turns the measured trace
// counter-clockwise onto the prediction). Nothing else is fitted: the radii are
// absolute, so an offset or an eccentricity between the traces is part of the
// difference, not removed from it.
//
// Depths are relative to the unworn surface r₀(ψ) of the run (its starting profile):
// a bore wears open, depth r − r₀; a pin wears thin, depth r₀ − r. The worn area [m²]
// (worn volume per unit length of the joint) is the difference of the areas enclosed by
// the worn and the unworn trace, taken as polygons on the common angles. On their own
// points, the polygons' areas would differ by the chord error πR²h²/6 of the coarser
// trace (2.3e-6 m² for R = 12 mm at 10° spacing, more than a typical worn area); on the
// same angles that error is the same for all three and cancels.
#pragma once

#include "base/profile.h"

#include <vector>

namespace wearlink::analysis
{
  /**
   * A closed polar trace: angles [rad] strictly increasing within [0, 2π), radii [m];
   * linear in the angle between points, periodically.
   */
  struct PolarTrace
  {
    std::vector<double> angle;
    std::vector<double> radius;

    /** The trace of a uniformly sampled profile. */
    static PolarTrace
    of_profile(const Profile &profile);

    /** The radius at @p psi [rad] (any real; periodic). */
    double
    at(double psi) const;

    std::size_t
    size() const
    {
      return angle.size();
    }
  };

  /** Which surface a trace is: the depth's sign. */
  enum class WornSurface
  {
    bore, ///< wears open: depth = r − r₀
    pin   ///< wears thin: depth = r₀ − r
  };

  /** Both traces on their common angles (run frame, sorted, in [0, 2π)). */
  struct CommonGrid
  {
    std::vector<double> angle;
    std::vector<double> measured;
    std::vector<double> predicted;
  };

  /** The measured trace turned by @p rotation [rad] and the predicted one on their common angles. */
  CommonGrid
  common_grid(const PolarTrace &measured, const PolarTrace &predicted, double rotation);

  /** How far two traces are apart on their common angles. */
  struct TraceDifference
  {
    double rms           = 0; ///< RMS over the circle of measured − predicted [m]
    double largest       = 0; ///< largest |measured − predicted| [m]
    double largest_angle = 0; ///< where, in the run's frame [rad]
  };

  /** The difference of @p measured turned by @p rotation [rad] from @p predicted. */
  TraceDifference
  trace_difference(const PolarTrace &measured, const PolarTrace &predicted, double rotation);

  /** The best rotation and what it gives. */
  struct Alignment
  {
    double          rotation = 0;    ///< [rad], in [−search, search]
    TraceDifference difference;      ///< at that rotation
    double          unaligned_rms;   ///< RMS at rotation 0 [m]
    double          scan_step   = 0; ///< [rad]
    unsigned int    evaluations = 0;
  };

  /**
   * The rotation within ±@p search [rad], 0 ≤ search ≤ π, that minimises the RMS
   * difference (see the top of the file); search = 0 takes the measured origin as it is.
   */
  Alignment
  align_trace(const PolarTrace &measured, const PolarTrace &predicted, double search);

  /** Angles [rad, run frame] and values [m] of one curve of the overlay. */
  struct AngleSeries
  {
    std::vector<double> angle;
    std::vector<double> value;
  };

  /** A worn area [m²] with its 1σ [m²]. */
  struct WornArea
  {
    double area  = 0;
    double sigma = 0;
  };

  /**
   * The worn area of the measured trace @p measured against the unworn surface
   * @p unworn (bore: r − r₀ wears open; pin: r₀ − r), as the difference of the polygons'
   * areas on the measured angles, with its 1σ for independent per-point errors @p sigma
   * [m] (σ_A² = Σ_k (∂A/∂r_k)² σ²). The unworn surface is read at the measured angles
   * as given: for a round one (the usual fresh surface) the area does not depend on the
   * trace's unknown angular origin.
   */
  WornArea
  measured_worn_area(const PolarTrace &measured, const PolarTrace &unworn, bool bore, double sigma);

  struct ProfileComparison
  {
    Alignment   alignment;
    double      max_depth_measured        = 0; ///< [m]
    double      max_depth_measured_angle  = 0; ///< [rad, run frame]
    double      max_depth_predicted       = 0; ///< [m]
    double      max_depth_predicted_angle = 0; ///< [rad]
    double      worn_area_measured        = 0; ///< [m²], worn volume per unit length
    double      worn_area_predicted       = 0; ///< [m²]
    double      largest_measured_gap      = 0; ///< widest angle between measured points [rad]
    AngleSeries measured_depth;                ///< at the measured points, aligned, sorted
    AngleSeries predicted_depth;               ///< at the predicted points
    AngleSeries depth_difference;              ///< measured − predicted, on the common angles
  };

  /**
   * Align @p measured to @p predicted within ±@p search [rad] and compare depths (from
   * @p unworn) and worn areas of @p surface. InputError if a trace is not a PolarTrace
   * of at least 8 points with positive radii.
   */
  ProfileComparison
  compare_profile(const PolarTrace &measured,
                  const PolarTrace &predicted,
                  const PolarTrace &unworn,
                  WornSurface       surface,
                  double            search);
} // namespace wearlink::analysis
