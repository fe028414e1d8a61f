// SPDX-License-Identifier: LGPL-2.1-or-later
// Rosenstein's estimate of the largest Lyapunov exponent (analysis/lyapunov.h): the mean
// log divergence of nearest-neighbour pairs and the line fitted to its linear region.
#include "analysis/kd_tree.h"
#include "analysis/lyapunov.h"
#include "analysis/lyapunov_detail.h"
#include "base/exceptions.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

namespace wearlink::analysis
{
  using namespace lyapunov_detail;

  namespace
  {
    struct LineFit
    {
      double slope = 0.0, intercept = 0.0, rms = 0.0;
    };

    LineFit
    fit_line(const std::vector<double> &y, const std::size_t a, const std::size_t b)
    {
      LineFit           f;
      const std::size_t n = b - a + 1;
      if (n < 2)
        {
          f.intercept = y[a];
          return f;
        }
      double sx = 0, sy = 0, sxx = 0, sxy = 0;
      for (std::size_t k = a; k <= b; ++k)
        {
          sx += k;
          sy += y[k];
          sxx += double(k) * k;
          sxy += k * y[k];
        }
      const double den = n * sxx - sx * sx;
      f.slope          = (n * sxy - sx * sy) / den;
      f.intercept      = (sy - f.slope * sx) / n;
      double ss        = 0.0;
      for (std::size_t k = a; k <= b; ++k)
        {
          const double r = y[k] - (f.intercept + f.slope * k);
          ss += r * r;
        }
      f.rms = std::sqrt(ss / n);
      return f;
    }
  } // namespace

  namespace
  {
    /** Centred moving average of @p y with half-width @p h (truncated at the ends). */
    std::vector<double>
    moving_average(const std::vector<double> &y, const std::size_t h)
    {
      std::vector<double> prefix(y.size() + 1, 0.0);
      for (std::size_t k = 0; k < y.size(); ++k)
        prefix[k + 1] = prefix[k] + y[k];
      std::vector<double> out(y.size());
      for (std::size_t k = 0; k < y.size(); ++k)
        {
          const std::size_t a = k > h ? k - h : 0;
          const std::size_t b = std::min(y.size() - 1, k + h);
          out[k]              = (prefix[b + 1] - prefix[a]) / (b - a + 1);
        }
      return out;
    }

    /** Smallest rise of <ln d(k)> that counts as exponential divergence [nats]. */
    constexpr double min_divergence = 1.0;
    /** Largest ratio of local slopes accepted inside the fitted (linear) region [-]. */
    constexpr double max_slope_ratio = 1.2;
    /**
     * Mean sample-to-sample step of the delay vectors below this fraction of the
     * attractor extent: the series resolves a continuous trajectory [-].
     */
    constexpr double max_trajectory_step = 0.1;

    /**
     * Rise of the smoothed curve from sample @p start to its later peak [nats]. The
     * start skips the first samples, where the curve jumps up from its minimum at k = 0
     * (the neighbour was chosen to be closest there), even for a periodic signal.
     */
    double
    rise_after(const std::vector<double> &smoothed, const std::size_t start)
    {
      return *std::max_element(smoothed.begin() + start, smoothed.end()) - smoothed[start];
    }

    /** Index where rise_after() starts: two delays, at most a quarter of the curve. */
    std::size_t
    rise_start(const std::size_t n_curve, const std::size_t delay)
    {
      return std::min(2 * delay, (n_curve - 1) / 4);
    }

    /**
     * True once the smoothed curve has levelled off: it rose by at least
     * min_divergence and its second half stays within 10 % of that rise below its peak.
     */
    bool
    has_saturated(const std::vector<double> &smoothed, const std::size_t delay)
    {
      const std::size_t start = rise_start(smoothed.size(), delay);
      const double      rise  = rise_after(smoothed, start);
      if (rise < min_divergence)
        return false;
      const double peak            = *std::max_element(smoothed.begin() + start, smoothed.end());
      const double low_second_half = *std::min_element(smoothed.begin() + smoothed.size() / 2, smoothed.end());
      return low_second_half >= peak - 0.1 * rise;
    }

    /**
     * A reference point i and its neighbour on the trajectory through sample j: the point
     * (1 - f) y_j + f y_{j+1}, 0 <= f < 1.
     */
    struct NeighbourPair
    {
      std::size_t i;
      std::size_t j;
      double      f;
    };

    /** |y_{i+k} - ((1 - f) y_{j+k} + f y_{j+k+1})| [units of the series]. */
    double
    pair_distance(const std::vector<double> &series,
                  const Embedding           &emb,
                  const NeighbourPair       &pair,
                  const std::size_t          k)
    {
      if (pair.f == 0.0)
        return distance(series, emb, pair.i + k, pair.j + k);
      double s = 0.0;
      for (unsigned int d = 0; d < emb.dimension; ++d)
        {
          const std::size_t o = d * emb.delay;
          const double      diff =
            series[pair.i + k + o] - (1.0 - pair.f) * series[pair.j + k + o] - pair.f * series[pair.j + k + 1 + o];
          s += diff * diff;
        }
      return std::sqrt(s);
    }

    /**
     * Move the neighbour y_j of @p y to the closest point of the sampled trajectory
     * through it, on the segments y_{j-1}..y_j and y_j..y_{j+1} (linear interpolation in
     * time). Returns the pair unchanged if no point of the segments is closer. A point
     * within @p min_distance is not taken: on an exactly periodic orbit the closest
     * point of the neighbouring segment is the reference state itself (one period
     * later), and its "separation" would be integration drift (1e-13 m for the ideal
     * nine-bar), whose slow growth would pass for divergence.
     */
    NeighbourPair
    refine_along_trajectory(const std::vector<double> &series,
                            const Embedding           &emb,
                            const std::vector<double> &y,
                            const std::size_t          i,
                            const Neighbour           &nb,
                            const double               min_distance)
    {
      NeighbourPair best{i, nb.index, 0.0};
      double        best_sq = nb.distance * nb.distance;
      const double  min_sq  = min_distance * min_distance;
      for (std::size_t start = nb.index > 0 ? nb.index - 1 : 0; start <= nb.index; ++start)
        {
          double along = 0.0, length_sq = 0.0;
          for (unsigned int d = 0; d < emb.dimension; ++d)
            {
              const std::size_t o       = d * emb.delay;
              const double      segment = series[start + 1 + o] - series[start + o];
              along += (y[d] - series[start + o]) * segment;
              length_sq += segment * segment;
            }
          if (!(length_sq > 0.0))
            continue;
          const double f = std::clamp(along / length_sq, 0.0, 1.0);
          if (f <= 0.0 || f >= 1.0)
            continue; // an end point: the sample itself, already considered
          double d_sq = 0.0;
          for (unsigned int d = 0; d < emb.dimension; ++d)
            {
              const std::size_t o    = d * emb.delay;
              const double      diff = y[d] - (1.0 - f) * series[start + o] - f * series[start + 1 + o];
              d_sq += diff * diff;
            }
          if (d_sq > min_sq && d_sq < best_sq)
            {
              best_sq = d_sq;
              best    = {i, start, f};
            }
        }
      return best;
    }

    /**
     * True if consecutive delay vectors are, on average, closer than max_trajectory_step times
     * the attractor extent: the samples resolve a continuous trajectory, so
     * interpolating between them is meaningful (false for maps such as Hénon).
     */
    bool
    resolves_trajectory(const std::vector<double> &series, const Embedding &emb, const std::size_t M)
    {
      const std::size_t stride = std::max<std::size_t>(1, M / 10000);
      double            step   = 0.0;
      std::size_t       n      = 0;
      for (std::size_t i = 0; i + 1 < M; i += stride, ++n)
        step += distance(series, emb, i, i + 1);
      const double extent = series_extent(series) * std::sqrt(static_cast<double>(emb.dimension));
      return n > 0 && step / n < max_trajectory_step * extent;
    }

    struct FitRegion
    {
      std::size_t begin = 0, end = 0;
      std::string rule;
      bool        resolved = true;
    };

    /** The automatic fit region of RosensteinOptions (see the comment of rosenstein_exponent). */
    FitRegion
    choose_fit_region(const std::vector<double> &curve,
                      const std::vector<double> &smoothed,
                      const std::size_t          delay,
                      const double               log_attractor_size)
    {
      FitRegion         region;
      const std::size_t K     = smoothed.size() - 1;
      const std::size_t start = rise_start(smoothed.size(), delay);
      region.begin            = start;
      region.end              = K;
      if (rise_after(smoothed, start) < min_divergence)
        {
          // Divergence faster than the embedding resolves: the (unsmoothed) curve has
          // already risen by e-fold or more before 2 delays and stays up at the size of
          // the attractor (mean level after them ≥ 1 nat above the start and within
          // 2 nats of ln(attractor size)). Fitting [2 tau, K] would report ≈ 0 for a
          // strongly diverging flow; fit the initial rise up to 90 % of that level
          // instead, and say so. (A limit cycle's neighbours also drift apart a little,
          // to a level far below the attractor's size: that stays "no divergence".)
          double plateau = 0.0;
          for (std::size_t k = start; k <= K; ++k)
            plateau += curve[k] / (K - start + 1);
          const double level = plateau - curve[0];
          if (level >= min_divergence && plateau >= log_attractor_size - 2.0)
            {
              std::size_t k90 = 1;
              while (k90 < start && curve[k90] < curve[0] + 0.9 * level)
                ++k90;
              region.begin    = 0;
              region.end      = std::max<std::size_t>(k90, 2);
              region.rule     = "UNRESOLVED: the separation saturates within 2 delays (the embedding's "
                                "nearest neighbours are not close in the full state); initial rise to "
                                "90 % of the plateau fitted; compare at a shorter delay";
              region.resolved = false;
              return region;
            }
          region.rule = "no exponential divergence (the separation grows less than e-fold over the "
                        "horizon): whole curve after 2 delays";
          return region;
        }
      // Local slope of the smoothed curve over +-2 tau.
      const std::size_t   h = 2 * delay;
      std::vector<double> slope(K + 1);
      for (std::size_t k = 0; k <= K; ++k)
        {
          const std::size_t lo = k > h ? k - h : 0, hi = std::min(K, k + h);
          slope[k] = (smoothed[hi] - smoothed[lo]) / (hi - lo);
        }
      double best_rise = 0.0;
      for (std::size_t a = 0; a < K; ++a)
        {
          if (!(slope[a] > 0.0))
            continue;
          double lo = slope[a], hi = slope[a];
          for (std::size_t b = a + 1; b <= K; ++b)
            {
              lo = std::min(lo, slope[b]);
              hi = std::max(hi, slope[b]);
              if (!(lo > 0.0) || hi > max_slope_ratio * lo)
                break;
              if (b >= a + 2 && smoothed[b] - smoothed[a] > best_rise)
                {
                  best_rise    = smoothed[b] - smoothed[a];
                  region.begin = a;
                  region.end   = b;
                }
            }
        }
      region.rule = best_rise > 0.0 ? "straightest rise: the window with the largest rise in which the local "
                                      "slope varies by less than 20%" :
                                      "no straight part found: whole curve after 2 delays";
      return region;
    }
  } // namespace

  namespace
  {
    /**
     * One nearest neighbour (beyond the Theiler window) for each of up to
     * @p max_references reference points spread evenly over the tree, refined along the
     * trajectory if @p interpolated. An exact recurrence (a commensurately sampled
     * periodic signal repeats its samples to rounding) is the same state, not a
     * neighbour: its "separation" is rounding noise, whose logarithm wanders by nats and
     * would fake a divergence. Such points are skipped and the nearest distinct point is
     * taken. InputError if no reference has a neighbour.
     */
    std::vector<NeighbourPair>
    rosenstein_pairs(const std::vector<double> &series,
                     const Embedding           &emb,
                     const KdTree              &tree,
                     const std::size_t          n_tree,
                     const std::size_t          theiler_window,
                     const std::size_t          max_references,
                     const bool                 interpolated)
    {
      const std::size_t          n_ref = std::min(n_tree, std::max<std::size_t>(1, max_references));
      std::vector<NeighbourPair> pairs;
      pairs.reserve(n_ref);
      std::vector<double> y;
      NeighbourFilter     filter;
      filter.theiler_window = theiler_window;
      filter.min_distance   = exact_recurrence * series_extent(series);
      for (std::size_t r = 0; r < n_ref; ++r)
        {
          const std::size_t i = r * n_tree / n_ref;
          delay_vector(series, emb, i, y);
          filter.query_index = i;
          const Neighbour nb = tree.nearest(y.data(), filter);
          if (!nb.found())
            continue;
          pairs.push_back(interpolated ? refine_along_trajectory(series, emb, y, i, nb, filter.min_distance) :
                                         NeighbourPair{i, nb.index, 0.0});
        }
      if (pairs.empty())
        throw EstimationError("The Rosenstein method found no neighbour pairs beyond the Theiler "
                              "window; the series is too short or constant.");
      return pairs;
    }

    /**
     * The mean log divergence ⟨ln d_k⟩ of the @p pairs for k = 0 … @p K_cap; with
     * @p stop_at_saturation it stops early (at power-of-two lengths from
     * max(64, 16 τ) on) once the smoothed curve has saturated.
     */
    std::vector<double>
    mean_log_divergence(const std::vector<double>        &series,
                        const Embedding                  &emb,
                        const std::vector<NeighbourPair> &pairs,
                        const std::size_t                 K_cap,
                        const bool                        stop_at_saturation)
    {
      const std::size_t   smoothing  = 2 * emb.delay;
      const std::size_t   min_length = std::max<std::size_t>(64, 16 * emb.delay);
      std::vector<double> curve;
      for (std::size_t k = 0; k <= K_cap; ++k)
        {
          double      sum = 0.0;
          std::size_t n   = 0;
          for (const NeighbourPair &pair : pairs)
            {
              const double d = pair_distance(series, emb, pair, k);
              if (d > 0.0)
                {
                  sum += std::log(d);
                  ++n;
                }
            }
          curve.push_back(n > 0 ? sum / n : curve.empty() ? 0.0 : curve.back());
          const bool checkpoint = k + 1 >= min_length && ((k + 1) & k) == 0;
          if (stop_at_saturation && checkpoint && has_saturated(moving_average(curve, smoothing), emb.delay))
            break;
        }
      return curve;
    }
  } // namespace

  // Rosenstein et al. 1993. Each reference point y_i (evenly spaced, at most
  // max_references) gets its nearest neighbour y_j with |i - j| > w once; then
  // <ln d(k)> = mean over pairs of ln |y_{i+k} - y_{j+k}|.
  //
  // Refinement along the trajectory (on when the samples resolve a continuous
  // trajectory, see RosensteinOptions::interpolate): with a coarse sample interval the
  // nearest sample of a neighbouring trajectory is offset along the flow by up to half a
  // sample step, often more than the distance between the trajectories themselves. That
  // offset does not grow, so ln d(k) first rises slower than lambda and bends the
  // curve (Rössler: -10 % to -15 %). The neighbour is therefore moved to the closest
  // point of the segments y_{j-1}..y_j..y_{j+1} and followed by linear interpolation.
  //
  // The curve is computed k by k; with the automatic horizon it stops at the first
  // power of two (at least 64 and 16 tau samples) at which it has saturated, or at the
  // cap.
  //
  // Automatic fit region: the curve is smoothed with a centred moving average over
  // 4 tau + 1 samples (tau is about a quarter of the dominant period, so this spans one
  // orbit and removes the orbital ripple). If the smoothed curve rises by less than
  // 1 nat after its first 2 tau samples, there is no exponential divergence and the
  // line is fitted over [2 tau, K] (about 0 for a periodic signal) — unless the curve
  // rose by 1 nat or more before 2 tau and stays there (divergence faster than the
  // embedding resolves), where the initial rise is fitted. Otherwise the fit
  // region is the "straightest rise": among all windows in which the local slope of
  // the smoothed curve stays positive and varies by less than a factor 1.2, the one
  // whose smoothed curve rises most. This excludes the initial alignment of the
  // separation with the unstable direction (steeper or flatter) and the bend into
  // saturation, without fixed levels. The least-squares line is fitted to the
  // unsmoothed curve.
  RosensteinResult
  rosenstein_exponent(const std::vector<double> &series,
                      const Embedding           &emb,
                      const std::size_t          theiler_window,
                      const RosensteinOptions   &options)
  {
    RosensteinResult out;
    check_length("Rosenstein", series.size(), emb, 8, theiler_window);
    const std::size_t M = emb.n_vectors(series.size());
    std::size_t       K_cap;
    if (options.horizon)
      {
        K_cap = *options.horizon;
        if (K_cap < 2)
          throw InputError("The Rosenstein horizon must be at least 2 samples.");
      }
    else
      {
        const std::size_t cap = options.max_horizon.value_or(std::max<std::size_t>(64, 256 * emb.delay));
        K_cap                 = std::max<std::size_t>(8, std::min(cap, M / 4));
      }
    check_length("Rosenstein", series.size(), emb, K_cap + 1, theiler_window);
    // Neighbours need K_cap + 1 samples of future (the +1 for the interpolation).
    const std::size_t n_tree = M - K_cap - 1;
    const KdTree      tree(series, emb.dimension, emb.delay, n_tree);
    out.interpolated = options.interpolate.value_or(resolves_trajectory(series, emb, M));

    const std::vector<NeighbourPair> pairs =
      rosenstein_pairs(series, emb, tree, n_tree, theiler_window, options.max_references, out.interpolated);
    out.n_references = pairs.size();

    const std::size_t smoothing      = 2 * emb.delay;
    auto             &curve          = out.mean_log_divergence;
    curve                            = mean_log_divergence(series, emb, pairs, K_cap, !options.horizon);
    const std::vector<double> smooth = moving_average(curve, smoothing);
    out.saturated                    = has_saturated(smooth, emb.delay);
    const std::size_t K              = curve.size() - 1;
    FitRegion         region;
    if (options.fit_begin || options.fit_end)
      {
        region.begin = options.fit_begin.value_or(0);
        region.end   = std::min(options.fit_end.value_or(K), K);
        if (region.begin >= region.end)
          throw InputError("The Rosenstein fit region [" + std::to_string(region.begin) + ", " +
                           std::to_string(region.end) +
                           "] samples is empty; the divergence "
                           "curve has " +
                           std::to_string(curve.size()) + " samples.");
        region.rule = "given by the caller";
      }
    else
      {
        double mean = 0.0, var = 0.0;
        for (const double x : series)
          mean += x / series.size();
        for (const double x : series)
          var += (x - mean) * (x - mean) / series.size();
        region = choose_fit_region(curve, smooth, emb.delay, 0.5 * std::log(var * emb.dimension));
      }
    const LineFit f         = fit_line(curve, region.begin, region.end);
    out.fit_begin           = region.begin;
    out.fit_end             = region.end;
    out.fit_rule            = region.rule;
    out.resolved            = region.resolved;
    out.exponent_per_sample = f.slope;
    out.intercept           = f.intercept;
    out.fit_residual        = f.rms;
    return out;
  }

  double
  LyapunovEstimate::exponent() const
  {
    return sample_interval ? exponent_per_sample / *sample_interval : exponent_per_sample;
  }

  std::string
  LyapunovEstimate::unit() const
  {
    return sample_interval ? "1/s (natural log, per second)" : "1/sample (natural log, per sample = per iteration)";
  }

  LyapunovEstimate
  estimate_largest_lyapunov_exponent(const std::vector<double> &series, const LyapunovSettings &settings)
  {
    for (std::size_t i = 0; i < series.size(); ++i)
      if (!std::isfinite(series[i]))
        throw InputError("Sample " + std::to_string(i) +
                         " of the series is not a finite number; "
                         "the Lyapunov exponent needs a complete series.");
    if (settings.sample_interval && !(*settings.sample_interval > 0.0))
      throw InputError("The sample interval dt must be > 0 s (given: " + std::to_string(*settings.sample_interval) +
                       ").");
    LyapunovEstimate out;
    out.method          = settings.method;
    out.sample_interval = settings.sample_interval;
    out.embedding       = resolve_embedding(series, settings.embedding);
    switch (settings.method)
      {
        case LyapunovMethod::wolf:
          out.wolf = wolf_exponent(series, out.embedding.embedding, out.embedding.theiler_window, settings.wolf);
          out.exponent_per_sample = out.wolf->exponent_per_sample;
          break;
        case LyapunovMethod::rosenstein:
          out.rosenstein =
            rosenstein_exponent(series, out.embedding.embedding, out.embedding.theiler_window, settings.rosenstein);
          out.exponent_per_sample = out.rosenstein->exponent_per_sample;
          break;
        default:
          throw InputError("Unknown Lyapunov method; the methods are wolf and rosenstein.");
      }
    return out;
  }
} // namespace wearlink::analysis
