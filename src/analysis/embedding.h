// SPDX-License-Identifier: LGPL-2.1-or-later
// Delay embedding of a scalar series (Takens 1981) and the two methods that choose its
// parameters (doc/models.md §6.4):
//  - the delay tau as the first minimum of the average mutual information between x_n
//    and x_{n+tau} (Fraser & Swinney 1986), estimated with averaged shifted
//    equal-width histograms (Scott 1985), which keep the curve smooth enough for its
//    first minimum to be meaningful even for periodic signals;
//  - the embedding dimension m by false nearest neighbours (Kennel, Brown & Abarbanel
//    1992, Phys. Rev. A 45, 3403): a neighbour in dimension d is false if adding the
//    (d+1)-th coordinate separates it too much (criteria 1 and 2 of the paper); m is
//    the first d whose fraction of false neighbours is below a threshold.
// Delays and Theiler windows are counted in samples; distances are in the units of the
// series; mutual information is in nats (natural logarithm).
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

namespace wearlink::analysis
{
  /** Delay-embedding parameters: y_i = (x_i, x_{i+delay}, ..., x_{i+(m-1) delay}). */
  struct Embedding
  {
    /** Embedding dimension m >= 1 [-]. */
    unsigned int dimension = 0;
    /** Delay tau >= 1 [samples]. */
    std::size_t delay = 0;

    /** Number of delay vectors a series of @p n_samples gives (0 if too short). */
    std::size_t
    n_vectors(std::size_t n_samples) const;

    /** Span of one delay vector, (m - 1) tau [samples]. */
    std::size_t
    window() const
    {
      return (dimension - 1) * delay;
    }
  };

  /**
   * Default Theiler window for an embedding: w = m tau samples, the time span of one
   * delay vector plus one delay. Neighbours closer than w in time share samples or are
   * correlated through them, and would make divergence look slower (Theiler 1986).
   */
  std::size_t
  default_theiler_window(const Embedding &embedding);

  /** Settings of the mutual-information delay choice. */
  struct MutualInformationOptions
  {
    /** Histogram bins per axis (16, as TISEAN's `mutual`), at most 1000 [-]. */
    unsigned int n_bins = 16;
    /**
     * Grid shifts per axis (averaged shifted histogram): the estimate is the mean over
     * n_shifts^2 grids, each axis shifted independently by s / n_shifts of a bin [-].
     */
    unsigned int n_shifts = 8;
    /** At most this many evenly spaced pairs (x_n, x_{n+tau}) per delay [-]. */
    std::size_t max_pairs = 200000;
    /**
     * Largest delay examined [samples]; 0 = automatic: n/10, at most 1000. The search
     * stops at the first minimum, so a large limit costs nothing on well-behaved data.
     */
    std::size_t max_delay = 0;
  };

  /** Which rule chose the delay (see choose_delay()). */
  enum class DelayRule
  {
    /** First minimum of the average mutual information (Fraser & Swinney 1986). */
    first_minimum,
    /**
     * I(tau) fell below 5 % of I(0) before any minimum, and successive samples are far
     * apart (mean step above 10 % of the range): a map or a Poincaré-section series;
     * delay 1, as recommended for maps (Kantz & Schreiber 2004).
     */
    decorrelated,
    /**
     * No minimum within max_delay, or I(tau) fell below 5 % of I(0) before any minimum
     * although successive samples are close (a sampled flow that decorrelates slowly,
     * e.g. a journal rattling in its bore): the first tau with I(tau) <= I(0)/e (or
     * max_delay). A delay of 1 sample there would make the delay, and with it the
     * exponent per second, depend on the sample interval.
     */
    one_over_e
  };

  /** Result of choose_delay(). */
  struct DelayChoice
  {
    /** Chosen delay [samples]. */
    std::size_t delay = 0;
    /** The rule that chose it. */
    DelayRule rule = DelayRule::first_minimum;
    /** Average mutual information I(tau) [nats], for tau = 0, 1, ... as far as computed. */
    std::vector<double> mutual_information;
  };

  /** A one-line description of @p rule for reports. */
  const char *
  describe(DelayRule rule);

  /**
   * Average mutual information between x_n and x_{n+tau} for tau = 0 .. @p max_delay
   * [nats], estimated with @p n_bins equal-width bins over the range of the series and
   * averaged over @p n_shifts^2 grids shifted by fractions of a bin width, from at most
   * @p max_pairs evenly spaced pairs per delay.
   */
  std::vector<double>
  average_mutual_information(const std::vector<double> &series,
                             std::size_t                max_delay,
                             unsigned int               n_bins    = 16,
                             unsigned int               n_shifts  = 8,
                             std::size_t                max_pairs = 200000);

  /**
   * Delay by the first minimum of the average mutual information (Fraser & Swinney
   * 1986): the smallest tau >= 1 with I(tau - 1) > I(tau) <= min(I(tau + 1),
   * I(tau + 2)), provided I(tau) is still above 5 % of I(0); see DelayRule for what
   * happens otherwise (maps: delay 1; slowly decorrelating flows: I(0)/e). Throws
   * InputError if the series is constant or shorter than 16 samples.
   */
  DelayChoice
  choose_delay(const std::vector<double> &series, const MutualInformationOptions &options = {});

  /** Settings of the false-nearest-neighbour dimension choice (Kennel et al. 1992). */
  struct FalseNearestNeighbourOptions
  {
    /** Largest dimension examined [-]. */
    unsigned int max_dimension = 10;
    /** Criterion 1: false if |x_{i+d tau} - x_{j+d tau}| / R_d(i) > this (R_tol) [-]. */
    double distance_ratio_threshold = 15.0;
    /** Criterion 2: false if R_{d+1}(i) / R_A > this (A_tol; R_A = std. dev.) [-]. */
    double attractor_size_threshold = 2.0;
    /** m is the first d whose fraction of false neighbours is below this [-]. */
    double fraction_threshold = 0.01;
    /** Theiler window [samples]; unset = the delay tau. */
    std::optional<std::size_t> theiler_window;
    /**
     * At most this many evenly spaced query points per dimension; the neighbours are
     * still searched among all points, so the fraction is that of the whole series
     * up to sampling error (about 0.1 % for 20000 queries at a 1 % fraction) [-].
     */
    std::size_t max_queries = 20000;
  };

  /** Result of choose_dimension(). */
  struct DimensionChoice
  {
    /** Chosen embedding dimension [-]. */
    unsigned int dimension = 0;
    /** Fraction of false nearest neighbours for d = 1, 2, ... (index d - 1) [-]. */
    std::vector<double> false_fraction;
    /**
     * True if the fraction fell below the threshold at @p dimension. False if it never
     * did up to max_dimension; then @p dimension is the d with the smallest fraction.
     */
    bool below_threshold = false;
  };

  /**
   * Fraction of false nearest neighbours in dimension @p dimension with delay
   * @p delay [-] (Kennel et al. 1992, criteria 1 or 2).
   */
  double
  false_nearest_neighbour_fraction(const std::vector<double>          &series,
                                   std::size_t                         delay,
                                   unsigned int                        dimension,
                                   const FalseNearestNeighbourOptions &options = {});

  /**
   * Embedding dimension by false nearest neighbours: the first d = 1, 2, ... whose
   * fraction is below options.fraction_threshold. Throws InputError if the series is
   * too short for dimension 2 at this delay.
   */
  DimensionChoice
  choose_dimension(const std::vector<double>          &series,
                   std::size_t                         delay,
                   const FalseNearestNeighbourOptions &options = {});
} // namespace wearlink::analysis
