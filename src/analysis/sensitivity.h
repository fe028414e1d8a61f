// SPDX-License-Identifier: LGPL-2.1-or-later
// Global sensitivity analysis: which uncertain input drives the spread of a result.
// A model y = f(x_1, …, x_d) with independent uncertain inputs is evaluated at sampled
// inputs; the variance of y is split into the shares of the inputs (Sobol indices), or,
// where too few evaluations exist for that, each input's rank correlation with y.
//
//  - Points: the Sobol low-discrepancy sequence of Boost.Random (boost::random::sobol,
//    Joe & Kuo's direction numbers, up to 3667 dimensions). Point n is computed from n
//    alone (the engine is positioned at n in Gray-code order), so members spread over
//    MPI ranks get the same points whatever the rank count and however many points a
//    rank drew before.
//    Optionally the sequence starts later (skip) and is digitally shifted (every
//    coordinate's 64 bits XOR a mask drawn from std::mt19937_64 for a seed), which
//    keeps its stratification and gives independent randomised replicates.
//  - Inputs: a unit-cube coordinate u ∈ (0, 1) becomes an input value through the
//    inverse CDF of its distribution (normal, lognormal, uniform, truncated normal;
//    boost::math).
//  - Saltelli sampling (Saltelli et al. 2010, Comput. Phys. Commun. 181): from N points
//    of the 2d-dimensional sequence, matrix A takes the first d coordinates of each,
//    B the last d, and A_B^(i) is A with column i taken from B: N (d + 2) evaluations.
//  - Estimators, with f_A, f_B, f_ABi the evaluations of row j and V the variance of
//    all f_A and f_B together:
//      first order (Saltelli et al. 2010):  S_i  = (1/N) Σ_j f_B (f_ABi − f_A) / V
//      total (Jansen 1999):                 S_Ti = (1/2N) Σ_j (f_A − f_ABi)² / V
//    The outputs are centred on the mean of all f_A and f_B first: S_i's estimator is
//    unbiased either way, but a large mean multiplies its sampling error.
//  - Intervals: percentile bootstrap over the N rows (B resamples drawn from
//    std::mt19937_64 with its raw 64-bit output, so the same on every platform),
//    2.5 % and 97.5 % percentiles (type 7, analysis/ensemble_statistics.h).
//  - With fewer base samples than SensitivitySettings::min_base_samples_for_indices the
//    indices' own sampling error is as large as the indices; then Spearman's rank
//    correlation of each input with y is reported instead, with a 95 % interval from
//    Fisher's z = atanh(ρ) with standard error √(1.06 / (n − 3)) (Fieller, Hartley &
//    Pearson 1957). SensitivityResult::method says which.
#pragma once

#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace wearlink::analysis
{
  /**
   * The Sobol sequence in (0, 1)^d, d ≤ max_dimension(). Coordinates are the engine's
   * 64-bit integers v mapped to ((v >> 11) + ½) 2⁻⁵³: the 53 leading bits, centred in
   * their cell, so that no coordinate is 0 or 1 (the inverse CDFs of unbounded
   * distributions are finite everywhere). Boost's sequence starts after the origin (whose
   * inverse CDF would be an extreme input, −8σ of a normal): point 0 is (½, …, ½), and
   * its first 2^k points are the stratified 2^k of Sobol's sequence with the origin
   * replaced by one more point.
   */
  class SobolSequence
  {
  public:
    /**
     * @p dimension coordinates per point; the sequence's point n is Sobol point
     * @p skip + n; @p shift_seed ≠ 0 applies the digital shift of that seed (0: none).
     */
    explicit SobolSequence(unsigned int dimension, std::uint64_t skip = 0, std::uint64_t shift_seed = 0);

    unsigned int
    dimension() const
    {
      return n_dimensions;
    }

    /** Point @p n (n = 0, 1, …), independent of any point drawn before. */
    std::vector<double>
    point(std::uint64_t n) const;

    /** Points @p first … @p first + @p count − 1, drawn in sequence (the same as point()). */
    std::vector<std::vector<double>>
    points(std::uint64_t first, std::uint64_t count) const;

    /** The largest dimension Boost's direction-number table supports. */
    static unsigned int
    max_dimension();

  private:
    struct Engine;
    unsigned int                  n_dimensions;
    std::uint64_t                 start;
    std::vector<std::uint64_t>    shift;
    std::shared_ptr<const Engine> prototype;
  };

  /** The distribution families of an uncertain input. */
  enum class DistributionKind
  {
    normal,
    lognormal,
    uniform,
    truncated_normal
  };

  /**
   * The distribution of one uncertain input. Values and bounds are in the input's own
   * unit (that of the scene entry it stands for; m³/(N m) for a wear coefficient, m for
   * a clearance, dimensionless for a friction coefficient):
   *  - normal(mean, std_dev): std_dev > 0;
   *  - lognormal(median, log_std): ln x is normal with mean ln(median) and standard
   *    deviation log_std [dimensionless; 0.4 means a factor e^0.4 = 1.49 per σ];
   *    median > 0, log_std > 0; mean median·e^(σ²/2);
   *  - uniform(lower, upper): lower < upper;
   *  - truncated_normal(mean, std_dev, lower, upper): the normal of that mean and
   *    standard deviation (those of the untruncated normal, not of the result)
   *    restricted to [lower, upper], lower < upper; the interval must carry a
   *    probability of at least 1e-12 under the untruncated normal.
   * The constructors check their parameters (InputError naming the family and the
   * parameter); a caller that reads them from a file adds where they came from.
   */
  struct InputDistribution
  {
    DistributionKind kind    = DistributionKind::uniform;
    double           mean    = 0; ///< normal, truncated normal [unit of the input]
    double           std_dev = 0; ///< normal, truncated normal [unit of the input]
    double           median  = 0; ///< lognormal [unit of the input]
    double           log_std = 0; ///< lognormal: standard deviation of ln x [-]
    double           lower   = 0; ///< uniform, truncated normal [unit of the input]
    double           upper   = 0; ///< uniform, truncated normal [unit of the input]

    static InputDistribution
    normal(double mean, double std_dev);
    static InputDistribution
    lognormal(double median, double log_std);
    static InputDistribution
    uniform(double lower, double upper);
    static InputDistribution
    truncated_normal(double mean, double std_dev, double lower, double upper);

    /** The value whose cumulative probability is @p u ∈ (0, 1) (the inverse CDF). */
    double
    quantile(double u) const;

    /** E.g. "lognormal(median 4.6e-14, log_std 0.4)". */
    std::string
    describe() const;
  };

  /**
   * The Saltelli design of N base samples for the given inputs. Design point
   * k = j (d + 2) + c belongs to base row j: c = 0 is A_j, c = 1 is B_j, c = 2 + i is
   * A_B^(i)_j. Row-major by j, so that the first m (d + 2) evaluations are the design of
   * m base samples (a design can grow without discarding evaluations). Powers of two for
   * N keep the Sobol points balanced.
   */
  class SaltelliDesign
  {
  public:
    /** @p skip and @p shift_seed as for SobolSequence (of dimension 2d). */
    SaltelliDesign(std::vector<InputDistribution> inputs,
                   std::uint64_t                  n_base,
                   std::uint64_t                  skip       = 0,
                   std::uint64_t                  shift_seed = 0);

    unsigned int
    n_inputs() const
    {
      return static_cast<unsigned int>(distributions.size());
    }
    std::uint64_t
    n_base() const
    {
      return base_samples;
    }
    /** N (d + 2): the number of model evaluations. */
    std::uint64_t
    n_points() const
    {
      return base_samples * (n_inputs() + 2);
    }

    /** The unit-cube coordinates of design point @p k. */
    std::vector<double>
    unit_point(std::uint64_t k) const;

    /** The input values of design point @p k (unit_point() through the inverse CDFs). */
    std::vector<double>
    point(std::uint64_t k) const;

    /** The input values of every design point, in design order. */
    std::vector<std::vector<double>>
    points() const;

  private:
    std::vector<InputDistribution> distributions;
    std::uint64_t                  base_samples;
    SobolSequence                  sequence;
  };

  /** A sensitivity measure and its 95 % interval (NaN where not estimated). */
  struct IndexEstimate
  {
    double value     = std::numeric_limits<double>::quiet_NaN();
    double ci95_low  = std::numeric_limits<double>::quiet_NaN();
    double ci95_high = std::numeric_limits<double>::quiet_NaN();
  };

  /** Which measure a SensitivityResult holds. */
  enum class SensitivityMethod
  {
    sobol_indices,   ///< first-order and total Sobol indices, bootstrap intervals
    rank_correlation ///< Spearman rank correlations, Fisher-z intervals
  };

  /** The name of @p method in reports: "sobol-indices" or "rank-correlation". */
  std::string
  method_name(SensitivityMethod method);

  /** The sensitivities of one input: the indices or the rank correlation, per method. */
  struct InputSensitivity
  {
    IndexEstimate first_order;      ///< S_i (sobol_indices)
    IndexEstimate total;            ///< S_Ti (sobol_indices)
    IndexEstimate rank_correlation; ///< Spearman ρ (rank_correlation)
  };

  struct SensitivityResult
  {
    SensitivityMethod method = SensitivityMethod::sobol_indices;
    /** Base rows (sobol_indices) or evaluations (rank_correlation) that entered. */
    std::uint64_t samples = 0;
    /** Base rows or evaluations left out because an output was not finite. */
    std::uint64_t dropped = 0;
    /** Bootstrap resamples behind the intervals (0 for rank correlations). */
    unsigned int bootstrap_resamples = 0;
    /** Mean and variance of the outputs that entered [unit of the output, squared]. */
    double                        output_mean     = 0;
    double                        output_variance = 0;
    std::vector<InputSensitivity> inputs;
  };

  struct SensitivitySettings
  {
    /** Bootstrap resamples for the intervals of the indices (0: no intervals). */
    unsigned int bootstrap_resamples = 1000;
    /** Seed of the bootstrap's std::mt19937_64. */
    std::uint64_t bootstrap_seed = 1;
    /**
     * Fewer base samples than this: rank correlations instead of indices. At N = 64 the
     * standard error of an index is of the order of 1/√N ≈ 0.13, the largest that still
     * separates a dominant input from a negligible one; below, the bootstrap intervals
     * span most of [0, 1].
     */
    std::uint64_t min_base_samples_for_indices = 64;
  };

  /**
   * First-order and total Sobol indices from the evaluations of a Saltelli design of
   * @p n_inputs inputs, in design order (size N (d + 2)), with bootstrap intervals.
   * Base rows with a non-finite output are left out (counted in `dropped`). InputError
   * if the size is not a multiple of d + 2 or fewer than 2 rows remain. With a zero
   * output variance every index is NaN.
   */
  SensitivityResult
  sobol_indices(unsigned int n_inputs, const std::vector<double> &outputs, const SensitivitySettings &settings = {});

  /**
   * Spearman rank correlation of each input column of @p inputs (one row per evaluation,
   * each of the same length) with @p outputs, ties given their mean rank, and the
   * Fisher-z interval. Evaluations with a non-finite output are left out. InputError
   * unless at least 4 remain (the interval needs n − 3 > 0). A constant input or output
   * has no rank correlation: NaN.
   */
  SensitivityResult
  rank_correlations(const std::vector<std::vector<double>> &inputs, const std::vector<double> &outputs);

  /**
   * The sensitivities of a Saltelli design's evaluations (design order): Sobol indices
   * if the design has at least settings.min_base_samples_for_indices base samples,
   * otherwise rank correlations over its A and B rows (2N independent samples; the
   * A_B^(i) rows repeat their coordinates and would overstate n).
   */
  SensitivityResult
  analyse_sensitivity(const SaltelliDesign      &design,
                      const std::vector<double> &outputs,
                      const SensitivitySettings &settings = {});
} // namespace wearlink::analysis
