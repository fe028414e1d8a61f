// SPDX-License-Identifier: LGPL-2.1-or-later
// Largest Lyapunov exponent (LLE) of a scalar time series, by two methods
// (doc/models.md §6.4):
//  - Wolf, Swift, Swinney & Vastano 1985 (Physica D 16, 285), the fixed-evolution-time
//    program: follow one neighbour of the reference trajectory for E samples, add
//    ln(d_end / d_start), then replace the neighbour by a point close to the reference
//    whose separation keeps the old orientation (smallest angle), and repeat;
//    lambda = (sum of the logarithms) / (total evolution time).
//  - Rosenstein, Collins & De Luca 1993 (Physica D 65, 117): every reference point gets
//    its nearest neighbour once; the mean over pairs of ln(separation after k samples),
//    <ln d(k)>, grows linearly with slope lambda until the separation saturates at the
//    attractor size; the slope is fitted over a linear region chosen automatically
//    (see RosensteinOptions) and reported.
// The delay and dimension are given or chosen by embedding.h (mutual information, false
// nearest neighbours). Exponents are in nats (natural logarithm) per sample; divided by
// the sample interval dt they are per second. For a map (Hénon) or a series without a
// known dt they stay per sample (= per iteration).
#pragma once

#include "analysis/embedding.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace wearlink::analysis
{
  /** The two estimators; names (user API): "wolf", "rosenstein". */
  enum class LyapunovMethod
  {
    wolf,
    rosenstein
  };

  /**
   * Fewest samples of a series worth estimating an exponent from: below it no embedding
   * leaves neighbours beyond a Theiler window to follow. The methods may need more for
   * the embedding they use (they say so); in practice thousands.
   */
  constexpr std::size_t min_lyapunov_samples = 100;

  /** "wolf" or "rosenstein". */
  std::string
  method_name(LyapunovMethod method);

  /** The method named @p name ("wolf", "rosenstein"); empty for any other name. */
  std::optional<LyapunovMethod>
  parse_method(const std::string &name);

  /** How the embedding is set: a value given by the caller, or chosen automatically. */
  struct EmbeddingSettings
  {
    /** Delay [samples]; unset = first minimum of the average mutual information. */
    std::optional<std::size_t> delay;
    /** Embedding dimension [-]; unset = false nearest neighbours (Kennel 1992). */
    std::optional<unsigned int> dimension;
    /** Theiler window [samples]; unset = default_theiler_window() = m tau. */
    std::optional<std::size_t>   theiler_window;
    MutualInformationOptions     mutual_information;
    FalseNearestNeighbourOptions false_nearest_neighbours;
  };

  /** The embedding actually used, and how it was found. */
  struct ResolvedEmbedding
  {
    Embedding embedding;
    /** Theiler window w [samples]: neighbours must be more than w samples apart. */
    std::size_t theiler_window = 0;
    /** Set when the delay was chosen automatically. */
    std::optional<DelayChoice> delay_choice;
    /** Set when the dimension was chosen automatically. */
    std::optional<DimensionChoice> dimension_choice;
  };

  /**
   * Resolve @p settings on @p series: given values are checked and kept, missing ones
   * are chosen (delay first, then the dimension at that delay). InputError if a given
   * value is out of range or the series is too short.
   */
  ResolvedEmbedding
  resolve_embedding(const std::vector<double> &series, const EmbeddingSettings &settings);

  /** Settings of Wolf's fixed-evolution-time algorithm. */
  struct WolfOptions
  {
    /**
     * Evolution time E between replacements [samples]; unset = 6 tau, about one and a
     * half dominant periods when tau is at the first mutual-information minimum (about
     * a quarter period). Each replacement leaves a small misalignment whose transient
     * (fast on attractors with nearly tangent stable and unstable directions, such as
     * Lorenz) biases ln(d_E / d_0) upward; the bias per unit time falls like 1/E, while
     * E must stay short enough that separations starting at the nearest-neighbour scale
     * do not saturate.
     */
    std::optional<std::size_t> evolution_steps;
    /**
     * Largest separation of a replacement point, as a fraction of the attractor extent
     * (the range max - min of the series) [-]. Wolf et al. recommend a few percent to
     * stay in the linear regime.
     */
    double max_scale = 0.05;
    /**
     * Smallest separation of a replacement point, as a fraction of the attractor extent
     * [-]; points closer than this are treated as noise (Wolf's SCALMN).
     */
    double min_scale = 1e-6;
    /** Largest accepted angle between the old and the new separation [rad] (Wolf: 0.3). */
    double max_angle = 0.3;
    /**
     * The replacement is the smallest-angle point among this many nearest admissible
     * candidates (Wolf scans all points within the maximum scale; with 10^6 samples
     * that ball holds thousands of points, so the scan is limited to the nearest
     * ones) [-].
     */
    std::size_t n_candidates = 64;
  };

  /** Result of wolf_exponent(). */
  struct WolfResult
  {
    /** Largest Lyapunov exponent [nats / sample]. */
    double exponent_per_sample = 0.0;
    /** Evolution time E used [samples]. */
    std::size_t evolution_steps = 0;
    /** Absolute replacement scales used [units of the series]. */
    double min_scale = 0.0;
    double max_scale = 0.0;
    /** Number of evolution segments summed [-]. */
    std::size_t n_segments = 0;
    /**
     * Segments after which no replacement within the angle and scale limits existed, even
     * after widening (Wolf's fallback), so the evolved neighbour was kept [-].
     */
    std::size_t n_kept_neighbours = 0;
    /** Mean angle between old and new separation over the replacements [rad]. */
    double mean_replacement_angle = 0.0;
    /** Running estimate after each segment [nats / sample] ... */
    std::vector<double> running_exponent;
    /** ... at these evolution times since the start [samples]. */
    std::vector<double> running_time;
  };

  /**
   * Wolf et al. 1985 fixed-evolution-time estimate of the largest Lyapunov exponent of
   * @p series embedded with @p embedding, neighbours at least @p theiler_window samples
   * apart in time. EstimationError if the series is too short.
   */
  WolfResult
  wolf_exponent(const std::vector<double> &series,
                const Embedding           &embedding,
                std::size_t                theiler_window,
                const WolfOptions         &options = {});

  /** Settings of Rosenstein's method. */
  struct RosensteinOptions
  {
    /**
     * Longest divergence time K followed [samples]; unset = automatic: the curve is
     * extended to the first power of two (at least 64 and 16 tau samples) at which it
     * has saturated (it rose at least 1 nat and its second half stays within 10 % of
     * that rise below its peak), at most to max_horizon.
     */
    std::optional<std::size_t> horizon;
    /**
     * Cap of the automatic horizon [samples]; unset = 256 tau (at least 64). Never more
     * than a quarter of the delay vectors.
     */
    std::optional<std::size_t> max_horizon;
    /**
     * Follow each neighbour along its own trajectory between samples (linear
     * interpolation), after moving it to the closest point of the segments next to it;
     * this removes the separation along the flow that coarse sampling leaves. Unset =
     * automatic: on if consecutive delay vectors are on average closer than 10 % of the
     * attractor extent (a resolved flow), off otherwise (a map).
     */
    std::optional<bool> interpolate;
    /**
     * At most this many evenly spaced reference points [-]. Their neighbours are still
     * searched among all points; the mean of ln d over 2e4 pairs is already known to
     * about 0.01 nat, far below the rise of the curve (on Lorenz and Rössler, 1e4 and
     * 1e5 references give the same exponent to 0.3 %).
     */
    std::size_t max_references = 20000;
    /**
     * Given fit region [first, last] sample of the curve; unset = automatic: the curve is
     * smoothed over 4 tau + 1 samples (one orbit, to remove orbital ripple). If it rises
     * less than 1 nat after its first 2 tau samples there is no exponential divergence
     * and the line is fitted over [2 tau, end] (about 0 for a periodic signal).
     * Otherwise the region is the "straightest rise": the window in which the local
     * slope of the smoothed curve stays positive and varies by less than a factor 1.2,
     * and over which the curve rises most.
     */
    std::optional<std::size_t> fit_begin;
    std::optional<std::size_t> fit_end;
  };

  /** Result of rosenstein_exponent(). */
  struct RosensteinResult
  {
    /** Largest Lyapunov exponent, slope of the fitted line [nats / sample]. */
    double exponent_per_sample = 0.0;
    /** <ln d(k)> for k = 0, 1, ... [ln of units of the series]. */
    std::vector<double> mean_log_divergence;
    /** Fit region, samples k of the curve (inclusive). */
    std::size_t fit_begin = 0;
    std::size_t fit_end   = 0;
    /** Fitted line <ln d(k)> = intercept + exponent_per_sample k. */
    double intercept = 0.0;
    /** Root-mean-square residual of the fit [nats]. */
    double fit_residual = 0.0;
    /** True if the curve rose and levelled off within the horizon (divergence saturated). */
    bool saturated = false;
    /**
     * False if the fit could only use the curve's initial jump: the separation reached
     * the attractor's size within 2 delays, so the nearest neighbours of the embedding
     * were not close in the full state and the slope says more about the embedding than
     * about the dynamics (on the clearance-joint series the slope then scales like
     * 1/delay). Report such a value as unresolved, not as an exponent.
     */
    bool resolved = true;
    /** True if neighbours were followed between samples (RosensteinOptions::interpolate). */
    bool interpolated = false;
    /** How the fit region was chosen, in words (for reports). */
    std::string fit_rule;
    /** Number of reference points (pairs) averaged [-]. */
    std::size_t n_references = 0;
  };

  /**
   * Rosenstein et al. 1993 estimate of the largest Lyapunov exponent of @p series
   * embedded with @p embedding, nearest neighbours at least @p theiler_window samples
   * apart in time. EstimationError if the series is too short.
   */
  RosensteinResult
  rosenstein_exponent(const std::vector<double> &series,
                      const Embedding           &embedding,
                      std::size_t                theiler_window,
                      const RosensteinOptions   &options = {});

  /** Everything a caller needs to report one estimate. */
  struct LyapunovEstimate
  {
    LyapunovMethod    method = LyapunovMethod::rosenstein;
    ResolvedEmbedding embedding;
    /** Sample interval [s]; unset for a map or a series without time stamps. */
    std::optional<double> sample_interval;
    /** Largest Lyapunov exponent [nats / sample]. */
    double exponent_per_sample = 0.0;
    /** Set for method wolf. */
    std::optional<WolfResult> wolf;
    /** Set for method rosenstein. */
    std::optional<RosensteinResult> rosenstein;

    /** The exponent in the unit of unit(): per second if dt is known, else per sample. */
    double
    exponent() const;
    /** "1/s" or "1/sample", always natural log: "nats/s" ... spelled out. */
    std::string
    unit() const;
  };

  /** Settings of estimate_largest_lyapunov_exponent(). */
  struct LyapunovSettings
  {
    LyapunovMethod        method = LyapunovMethod::rosenstein;
    EmbeddingSettings     embedding;
    std::optional<double> sample_interval; ///< dt [s]; unset = per-sample units
    WolfOptions           wolf;
    RosensteinOptions     rosenstein;
  };

  /**
   * The library entry point: resolve the embedding of @p series (e.g. the x coordinate
   * of a joint centre [m] sampled every dt seconds) and estimate its largest Lyapunov
   * exponent with the selected method. InputError for NaN/inf samples or out-of-range
   * settings; EstimationError if this series does not allow the estimate (too short
   * for the embedding, constant, no neighbour beyond the Theiler window).
   */
  LyapunovEstimate
  estimate_largest_lyapunov_exponent(const std::vector<double> &series, const LyapunovSettings &settings);
} // namespace wearlink::analysis
