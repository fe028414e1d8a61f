// SPDX-License-Identifier: LGPL-2.1-or-later
#include "analysis/lyapunov.h"

#include "analysis/kd_tree.h"
#include "analysis/lyapunov_detail.h"
#include "base/exceptions.h"
#include "base/numbers.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

namespace wearlink::analysis
{
  using namespace lyapunov_detail;
  using numbers::pi;


  std::string
  method_name(const LyapunovMethod method)
  {
    switch (method)
      {
        case LyapunovMethod::wolf:
          return "wolf";
        case LyapunovMethod::rosenstein:
          return "rosenstein";
      }
    return "unknown";
  }

  std::optional<LyapunovMethod>
  parse_method(const std::string &name)
  {
    for (const auto m : {LyapunovMethod::wolf, LyapunovMethod::rosenstein})
      if (name == method_name(m))
        return m;
    return std::nullopt;
  }

  ResolvedEmbedding
  resolve_embedding(const std::vector<double> &series, const EmbeddingSettings &settings)
  {
    ResolvedEmbedding out;
    if (settings.delay)
      {
        if (*settings.delay < 1)
          throw InputError("The delay must be at least 1 sample (given: 0).");
        out.embedding.delay = *settings.delay;
      }
    else
      {
        out.delay_choice    = choose_delay(series, settings.mutual_information);
        out.embedding.delay = out.delay_choice->delay;
      }
    if (settings.dimension)
      {
        if (*settings.dimension < 1 || *settings.dimension > 64)
          throw InputError(
            "The embedding dimension must be between 1 and 64 (given: " + std::to_string(*settings.dimension) + ").");
        out.embedding.dimension = *settings.dimension;
      }
    else
      {
        FalseNearestNeighbourOptions fnn = settings.false_nearest_neighbours;
        if (!fnn.theiler_window && settings.theiler_window)
          fnn.theiler_window = settings.theiler_window;
        out.dimension_choice    = choose_dimension(series, out.embedding.delay, fnn);
        out.embedding.dimension = out.dimension_choice->dimension;
      }
    out.theiler_window = settings.theiler_window.value_or(default_theiler_window(out.embedding));
    return out;
  }

  namespace
  {
    /** Wolf's neighbour replacement: the chosen candidate and its angle, if any. */
    struct Replacement
    {
      bool        found = false;
      std::size_t index = 0;
      double      angle = 0.0; ///< [rad]
    };

    /** Largest multiple of the maximum scale searched for a replacement. */
    constexpr unsigned int max_scale_multiplier = 5;

    /**
     * FET1's replacement of the neighbour of y_i (@p y_ref, filled by the caller):
     * among the candidates within max_scale_multiplier × @p max_scale of y_i, the one
     * whose separation from y_i makes the smallest angle with the evolved separation
     * y_{j+E} − y_i (@p j_evolved = j + E), accepted below max_angle at the smallest
     * scale multiple that has one, the angle limit doubling up to π.
     */
    Replacement
    wolf_replacement(const std::vector<double> &series,
                     const Embedding           &emb,
                     const KdTree              &tree,
                     const WolfOptions         &options,
                     const std::size_t          i,
                     const std::size_t          j_evolved,
                     const double               max_scale,
                     const std::vector<double> &y_ref,
                     std::vector<double>       &y_old,
                     NeighbourFilter           &filter)
    {
      delay_vector(series, emb, j_evolved, y_old);
      double v_norm = 0.0;
      for (unsigned int d = 0; d < emb.dimension; ++d)
        {
          y_old[d] -= y_ref[d];
          v_norm += y_old[d] * y_old[d];
        }
      v_norm                                  = std::sqrt(v_norm);
      filter.query_index                      = i;
      filter.max_distance                     = max_scale_multiplier * max_scale;
      const std::vector<Neighbour> candidates = tree.k_nearest(y_ref.data(), options.n_candidates, filter);
      std::vector<double>          angles(candidates.size());
      for (std::size_t c = 0; c < candidates.size(); ++c)
        {
          double dot = 0.0;
          for (unsigned int d = 0; d < emb.dimension; ++d)
            dot += (series[candidates[c].index + d * emb.delay] - y_ref[d]) * y_old[d];
          const double cosine = v_norm > 0.0 ? dot / (v_norm * candidates[c].distance) : 1.0;
          angles[c]           = std::acos(std::clamp(cosine, -1.0, 1.0));
        }
      std::size_t chosen = candidates.size();
      for (double angle_limit = options.max_angle; angle_limit < pi && chosen == candidates.size(); angle_limit *= 2.0)
        for (unsigned int mult = 1; mult <= max_scale_multiplier && chosen == candidates.size(); ++mult)
          {
            double best = angle_limit;
            for (std::size_t c = 0; c < candidates.size(); ++c)
              if (candidates[c].distance < mult * max_scale && angles[c] <= best)
                {
                  best   = angles[c];
                  chosen = c;
                }
          }
      Replacement r;
      if (chosen < candidates.size())
        {
          r.found = true;
          r.index = candidates[chosen].index;
          r.angle = angles[chosen];
        }
      return r;
    }
  } // namespace

  // Wolf et al. 1985, fixed evolution time (their program FET1). The reference
  // trajectory starts at the first delay vector; its neighbour is the nearest
  // admissible point. Each segment evolves both for E samples and adds ln(d_E / d_0).
  // The replacement search then follows FET1: among candidate points within the
  // maximum scale (and beyond the minimum scale), take the one whose separation from
  // the reference makes the smallest angle with the evolved separation; accept it if
  // the angle is below max_angle; otherwise widen the scale (x2 .. x5), then double the
  // angle limit; if still nothing qualifies, keep the evolved neighbour.
  WolfResult
  wolf_exponent(const std::vector<double> &series,
                const Embedding           &emb,
                const std::size_t          theiler_window,
                const WolfOptions         &options)
  {
    WolfResult        out;
    const std::size_t E = options.evolution_steps.value_or(6 * emb.delay);
    if (E < 1)
      throw InputError("The Wolf evolution time must be at least 1 sample.");
    check_length("Wolf", series.size(), emb, 2 * E, theiler_window);
    const std::size_t M      = emb.n_vectors(series.size());
    const std::size_t n_tree = M - E; // points that can be evolved for E samples
    const KdTree      tree(series, emb.dimension, emb.delay, n_tree);
    const double      extent = series_extent(series);
    out.evolution_steps      = E;
    out.min_scale            = options.min_scale * extent;
    out.max_scale            = options.max_scale * extent;

    std::vector<double> y_ref, y_old;
    NeighbourFilter     filter;
    filter.theiler_window = theiler_window;
    filter.min_distance   = out.min_scale;

    std::size_t i = 0;
    delay_vector(series, emb, i, y_ref);
    filter.query_index = i;
    Neighbour first    = tree.nearest(y_ref.data(), filter);
    if (!first.found())
      throw EstimationError("The Wolf method found no neighbour of the first point beyond the "
                            "Theiler window; the series is too short or constant.");
    std::size_t j = first.index;

    double      sum_log = 0.0, sum_angle = 0.0;
    std::size_t n_replaced = 0;
    while (i + E < M && i < n_tree && j < n_tree)
      {
        const double d0 = distance(series, emb, i, j);
        const double d1 = distance(series, emb, i + E, j + E);
        if (d0 > 0.0 && d1 > 0.0)
          {
            sum_log += std::log(d1 / d0);
            ++out.n_segments;
            out.running_time.push_back(static_cast<double>(out.n_segments * E));
            out.running_exponent.push_back(sum_log / (out.n_segments * E));
          }
        i += E;
        if (i >= n_tree)
          break;

        delay_vector(series, emb, i, y_ref);
        const Replacement r =
          wolf_replacement(series, emb, tree, options, i, j + E, out.max_scale, y_ref, y_old, filter);
        if (r.found)
          {
            j = r.index;
            sum_angle += r.angle;
            ++n_replaced;
          }
        else
          {
            ++out.n_kept_neighbours;
            j = j + E;
            if (j >= n_tree)
              {
                filter.max_distance = std::numeric_limits<double>::infinity();
                const Neighbour any = tree.nearest(y_ref.data(), filter);
                if (!any.found())
                  break;
                j = any.index;
              }
          }
      }
    if (out.n_segments == 0)
      throw EstimationError("The Wolf method could not follow any neighbour pair (all separations "
                            "were zero); the series may be constant or repeat exactly.");
    out.exponent_per_sample    = sum_log / (out.n_segments * E);
    out.mean_replacement_angle = n_replaced > 0 ? sum_angle / n_replaced : 0.0;
    return out;
  }
} // namespace wearlink::analysis
