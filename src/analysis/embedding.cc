// SPDX-License-Identifier: LGPL-2.1-or-later
#include "analysis/embedding.h"

#include "analysis/kd_tree.h"
#include "base/exceptions.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

namespace wearlink::analysis
{
  namespace
  {
    /** Shortest series any of these methods accepts [samples]. */
    constexpr std::size_t min_samples = 16;

    /** Neighbours closer than this fraction of the standard deviation coincide [-]. */
    constexpr double exact_recurrence = 1e-9;

    /**
     * Bin indices of every sample for @p n_shifts histogram grids of @p n_bins
     * equal-width bins over [min, max], grid s shifted by s / n_shifts of a bin width
     * (grid s > 0 has n_bins + 1 bins). Averaging the mutual information over the shifted
     * grids (an averaged shifted histogram, Scott 1985) removes most of the jitter that
     * one grid gives when the samples lie on a curve (periodic signals).
     */
    std::vector<std::vector<std::uint16_t>>
    shifted_bin_indices(const std::vector<double> &x, const unsigned int n_bins, const unsigned int n_shifts)
    {
      const auto [lo_it, hi_it] = std::minmax_element(x.begin(), x.end());
      const double lo = *lo_it, hi = *hi_it;
      if (!(hi > lo))
        throw EstimationError("The series is constant (every sample is " + std::to_string(lo) +
                              "); it has no dynamics to embed. Choose another column.");
      std::vector<std::vector<std::uint16_t>> bins(n_shifts, std::vector<std::uint16_t>(x.size()));
      std::vector<double>                     u(x.size());
      for (std::size_t i = 0; i < x.size(); ++i)
        u[i] = (x[i] - lo) / (hi - lo);
      const double scale = n_bins;
      for (unsigned int s = 0; s < n_shifts; ++s)
        {
          const double offset = static_cast<double>(s) / n_shifts;
          for (std::size_t i = 0; i < x.size(); ++i)
            bins[s][i] = static_cast<std::uint16_t>(std::min(static_cast<unsigned int>(u[i] * scale + offset), n_bins));
        }
      return bins;
    }

    /**
     * I(tau) [nats] from the bin indices of x_n on one grid (@p first) and of x_{n+tau}
     * on another (@p second), @p n_cells cells per axis, using the pairs n = 0, stride,
     * 2 stride, ...
     */
    double
    mutual_information_at(const std::vector<std::uint16_t> &first,
                          const std::vector<std::uint16_t> &second,
                          const unsigned int                n_cells,
                          const std::size_t                 tau,
                          const std::size_t                 stride,
                          std::vector<double>              &joint,
                          std::vector<double>              &p_first,
                          std::vector<double>              &p_second)
    {
      std::fill(joint.begin(), joint.end(), 0.0);
      std::fill(p_first.begin(), p_first.end(), 0.0);
      std::fill(p_second.begin(), p_second.end(), 0.0);
      double n = 0.0;
      for (std::size_t i = 0; i + tau < first.size(); i += stride)
        {
          n += 1.0;
          const unsigned int a = first[i], b = second[i + tau];
          joint[a * n_cells + b] += 1.0;
          p_first[a] += 1.0;
          p_second[b] += 1.0;
        }
      double info = 0.0;
      for (unsigned int a = 0; a < n_cells; ++a)
        for (unsigned int b = 0; b < n_cells; ++b)
          {
            const double c = joint[a * n_cells + b];
            if (c > 0)
              info += c / n * std::log(c * n / (p_first[a] * p_second[b]));
          }
      return info;
    }

    /**
     * Mutual information at delays 0, 1, ... averaged over every pair of shifted grids
     * (x_n and x_{n+tau} shifted independently, n_shifts^2 histograms; shifting both axes
     * together leaves a jitter of several percent on periodic signals). At most
     * max_pairs evenly spaced pairs are used per delay.
     */
    class MutualInformation
    {
    public:
      MutualInformation(const std::vector<double> &x,
                        const unsigned int         n_bins,
                        const unsigned int         n_shifts,
                        const std::size_t          max_pairs)
        : n_cells(n_bins + 1)
        , max_pairs(std::max<std::size_t>(1, max_pairs))
        , bins(shifted_bin_indices(x, n_bins, n_shifts))
        , joint(n_cells * n_cells)
        , p_first(n_cells)
        , p_second(n_cells)
      {
      }

      double
      at(const std::size_t tau)
      {
        const std::size_t n_pairs = bins.front().size() - tau;
        const std::size_t stride  = (n_pairs + max_pairs - 1) / max_pairs;
        double            sum     = 0.0;
        for (const auto &b : bins)
          for (const auto &b2 : bins)
            sum += mutual_information_at(b, b2, n_cells, tau, stride, joint, p_first, p_second);
        return sum / (bins.size() * bins.size());
      }

    private:
      unsigned int                            n_cells;
      std::size_t                             max_pairs;
      std::vector<std::vector<std::uint16_t>> bins;
      std::vector<double>                     joint, p_first, p_second;
    };

    /**
     * Mean |x_{n+1} - x_n| below this fraction of the range: successive samples are
     * close, the series resolves a continuous trajectory (a flow) [-].
     */
    constexpr double max_flow_step = 0.1;

    /**
     * True if the series is a sampled flow rather than a map: consecutive samples
     * differ on average by less than max_flow_step of the range (Hénon x: about 40 %;
     * a flow sampled 20 times per oscillation: about 5 %).
     */
    bool
    is_sampled_flow(const std::vector<double> &x)
    {
      const auto [lo, hi] = std::minmax_element(x.begin(), x.end());
      double step         = 0.0;
      for (std::size_t i = 1; i < x.size(); ++i)
        step += std::abs(x[i] - x[i - 1]);
      return step / (x.size() - 1) < max_flow_step * (*hi - *lo);
    }

    double
    standard_deviation(const std::vector<double> &x)
    {
      double mean = 0.0;
      for (const double v : x)
        mean += v;
      mean /= x.size();
      double var = 0.0;
      for (const double v : x)
        var += (v - mean) * (v - mean);
      return std::sqrt(var / x.size());
    }
  } // namespace

  const char *
  describe(const DelayRule rule)
  {
    switch (rule)
      {
        case DelayRule::first_minimum:
          return "first minimum of the average mutual information";
        case DelayRule::decorrelated:
          return "mutual information decays below 5% of I(0) without a minimum (map-like "
                 "series): delay 1";
        case DelayRule::one_over_e:
          return "no minimum of the mutual information before it decayed (a slowly "
                 "decorrelating flow) or up to the largest delay examined: first delay "
                 "with I <= I(0)/e";
      }
    return "";
  }

  std::size_t
  Embedding::n_vectors(const std::size_t n_samples) const
  {
    return n_samples > window() ? n_samples - window() : 0;
  }

  std::size_t
  default_theiler_window(const Embedding &embedding)
  {
    return static_cast<std::size_t>(embedding.dimension) * embedding.delay;
  }

  std::vector<double>
  average_mutual_information(const std::vector<double> &series,
                             const std::size_t          max_delay,
                             const unsigned int         n_bins,
                             const unsigned int         n_shifts,
                             const std::size_t          max_pairs)
  {
    if (series.size() < min_samples || max_delay + min_samples > series.size())
      throw EstimationError("The mutual information up to a delay of " + std::to_string(max_delay) +
                            " samples needs at least " + std::to_string(max_delay + min_samples) +
                            " samples; the series has " + std::to_string(series.size()) + ".");
    MutualInformation   mi(series, std::clamp(n_bins, 2u, 1000u), std::max(1u, n_shifts), max_pairs);
    std::vector<double> info(max_delay + 1);
    for (std::size_t tau = 0; tau <= max_delay; ++tau)
      info[tau] = mi.at(tau);
    return info;
  }

  // The search walks tau upwards and stops two delays after the first minimum, so its
  // cost is (first minimum + 3) estimates. A minimum must hold against the next two
  // delays (a one-sample wiggle of the estimate is not a minimum), and at least
  // minimum_information of I(0) must remain there: below that, successive samples are
  // practically independent and a "minimum" would be estimator noise.
  DelayChoice
  choose_delay(const std::vector<double> &series, const MutualInformationOptions &options)
  {
    if (series.size() < min_samples)
      throw EstimationError("Choosing the delay needs at least " + std::to_string(min_samples) +
                            " samples; the series has " + std::to_string(series.size()) + ".");
    constexpr double  minimum_information = 0.05;
    const std::size_t max_delay           = options.max_delay > 0 ?
                                              std::min(options.max_delay, series.size() - min_samples) :
                                              std::min<std::size_t>(1000, std::max<std::size_t>(2, series.size() / 10));
    MutualInformation mi(series,
                         std::clamp(options.n_bins, 2u, 1000u),
                         std::max(1u, options.n_shifts),
                         options.max_pairs);

    DelayChoice out;
    auto       &info = out.mutual_information;
    info.push_back(mi.at(0));
    const double floor = minimum_information * info[0];
    auto         at    = [&](const std::size_t tau) {
      while (info.size() <= tau)
        info.push_back(mi.at(info.size()));
      return info[tau];
    };
    for (std::size_t tau = 1; tau < max_delay; ++tau)
      {
        if (at(tau) < floor)
          {
            if (is_sampled_flow(series))
              break; // a flow that decorrelates slowly: the 1/e rule below
            out.delay = 1;
            out.rule  = DelayRule::decorrelated;
            return out;
          }
        if (!(at(tau - 1) > at(tau)))
          continue;
        const std::size_t look_ahead = std::min(max_delay, tau + 2);
        bool              is_minimum = true;
        for (std::size_t later = tau + 1; later <= look_ahead && is_minimum; ++later)
          is_minimum = at(later) >= at(tau);
        if (is_minimum)
          {
            out.delay = tau;
            out.rule  = DelayRule::first_minimum;
            return out;
          }
      }
    out.rule  = DelayRule::one_over_e;
    out.delay = max_delay;
    for (std::size_t tau = 1; tau < info.size(); ++tau)
      if (info[tau] <= info[0] / std::exp(1.0))
        {
          out.delay = tau;
          break;
        }
    return out;
  }

  double
  false_nearest_neighbour_fraction(const std::vector<double>          &series,
                                   const std::size_t                   delay,
                                   const unsigned int                  dimension,
                                   const FalseNearestNeighbourOptions &options)
  {
    const Embedding   emb{dimension, delay};
    const std::size_t w = options.theiler_window.value_or(delay);
    // Points that also have the (d+1)-th coordinate x_{i + d tau}.
    const std::size_t n = series.size() > dimension * delay ? series.size() - dimension * delay : 0;
    if (n < 2 * w + min_samples)
      throw EstimationError("False nearest neighbours in dimension " + std::to_string(dimension + 1) +
                            " with a delay of " + std::to_string(delay) + " samples need at least " +
                            std::to_string(2 * w + min_samples + dimension * delay) + " samples; the series has " +
                            std::to_string(series.size()) +
                            ". Give a longer series, or a smaller delay or embedding dimension.");
    const KdTree tree(series, emb.dimension, emb.delay, n);
    const double r_a = standard_deviation(series);

    // Exact recurrences (a periodic signal sampled commensurately repeats its samples to
    // rounding) are the same state, not a neighbour: in dimension 1 the repeat of x_i
    // on the same branch would always be found first, hiding the point of the other
    // branch with nearly the same value and making a sine look one-dimensional. So the
    // search skips points within rounding distance and takes the nearest distinct one
    // (as Wolf's minimum scale does), and the test is made on that neighbour.
    const std::size_t   n_queries = std::min(n, std::max<std::size_t>(1, options.max_queries));
    std::size_t         n_false = 0, n_tested = 0;
    std::vector<double> query(dimension);
    for (std::size_t q = 0; q < n_queries; ++q)
      {
        const std::size_t i = q * n / n_queries;
        for (unsigned int d = 0; d < dimension; ++d)
          query[d] = series[i + d * delay];
        NeighbourFilter filter;
        filter.query_index    = i;
        filter.theiler_window = w;
        filter.min_distance   = exact_recurrence * r_a;
        const Neighbour nb    = tree.nearest(query.data(), filter);
        if (!nb.found())
          continue; // every admissible point repeats this one: nothing to test
        const std::size_t j      = nb.index;
        const double      extra  = std::abs(series[i + dimension * delay] - series[j + dimension * delay]);
        const double      r_next = std::sqrt(nb.distance * nb.distance + extra * extra);
        ++n_tested;
        if (extra / nb.distance > options.distance_ratio_threshold || r_next / r_a > options.attractor_size_threshold)
          ++n_false;
      }
    if (n_tested == 0)
      throw EstimationError("False nearest neighbours in dimension " + std::to_string(dimension) +
                            ": no query point has a distinct neighbour beyond the Theiler window (the "
                            "series repeats one state). Give the embedding dimension explicitly.");
    return static_cast<double>(n_false) / n_tested;
  }

  DimensionChoice
  choose_dimension(const std::vector<double>          &series,
                   const std::size_t                   delay,
                   const FalseNearestNeighbourOptions &options)
  {
    if (delay < 1)
      throw InputError("The delay must be at least 1 sample.");
    DimensionChoice out;
    for (unsigned int d = 1; d <= std::max(1u, options.max_dimension); ++d)
      {
        const std::size_t w = options.theiler_window.value_or(delay);
        if (d > 1 && series.size() < d * delay + 2 * w + min_samples)
          break; // too short for this dimension: keep the best found so far
        out.false_fraction.push_back(false_nearest_neighbour_fraction(series, delay, d, options));
        if (out.false_fraction.back() < options.fraction_threshold)
          {
            out.dimension       = d;
            out.below_threshold = true;
            return out;
          }
      }
    out.below_threshold = false;
    out.dimension =
      1 + static_cast<unsigned int>(std::min_element(out.false_fraction.begin(), out.false_fraction.end()) -
                                    out.false_fraction.begin());
    return out;
  }
} // namespace wearlink::analysis
