// SPDX-License-Identifier: LGPL-2.1-or-later
// What a scene's `subsection Analyses` asks for (read by analysis/analyses_parameters.h, run by
// workflows/run/analyses.h): which nonlinear-dynamics analyses, of which joints and bodies,
// with which sampling and embedding, and the before/after-wear comparison settings.
#pragma once

#include "analysis/lyapunov.h"

#include <optional>
#include <string>
#include <vector>

namespace wearlink::analysis
{
  /** A published pair of exponents of one channel, before and after wear. */
  struct PublishedExponents
  {
    std::string channel;
    double      before = 0.0;
    double      after  = 0.0;
  };

  /** What the scene's `subsection Analyses` asked for (names resolved and checked). */
  struct AnalysesSettings
  {
    bool phase_portrait = false;
    bool poincare       = false;
    bool lyapunov       = false;
    /** Clearance joints analysed (default: every clearance joint of the scene). */
    std::vector<std::string> joints;
    /** Bodies whose centre-of-mass motion is analysed too. */
    std::vector<std::string> bodies;
    /** Driving period T as given [s]; 0 = from the angle drivers (driving_period()). */
    double given_driving_period = 0.0;
    /** Sections at Start time + section_phase + k T [s]. */
    double section_phase = 0.0;
    /** Nothing is recorded before Start time + transient [s]. */
    double transient = 0.0;
    /** Sample interval of the phase-portrait / Lyapunov series [s]. */
    double sample_interval = 1e-3;
    /** Lyapunov: methods, directions ("x", "y") and embedding. */
    std::vector<LyapunovMethod> methods;
    /** Also the exponent of the simulation itself (workflows/run/shadow_trajectory.h). */
    bool                        two_trajectory            = false;
    double                      two_trajectory_separation = 1e-6; ///< d0 [m]
    double                      renormalization_interval  = 0.02; ///< τ [s]
    std::vector<std::string>    directions;
    std::optional<std::size_t>  delay;
    std::optional<unsigned int> dimension;

    /**
     * Wear scenes: the before/after-wear comparison (workflows/compare/dynamics_comparison.h), from the
     * entries of `subsection Before-after wear`: common delay [s] and dimension (0 =
     * automatic on the before-wear run), delay scan [s], published exponents to print.
     */
    double              comparison_delay     = 0.0;
    unsigned int        comparison_dimension = 0;
    std::vector<double> delay_scan;
    std::string         published_exponents;
    std::string         published_note;
    /** Two-trajectory exponent runs of the comparison: cycles after Transient, tolerance. */
    double two_trajectory_cycles    = 10;
    double two_trajectory_tolerance = 1e-11;

    /** True if any analysis is listed. */
    bool
    any() const
    {
      return phase_portrait || poincare || lyapunov;
    }
    /** The listed names, in the canonical order. */
    std::vector<std::string>
    names() const;
  };
} // namespace wearlink::analysis
