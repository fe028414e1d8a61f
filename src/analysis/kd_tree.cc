// SPDX-License-Identifier: LGPL-2.1-or-later
#include "analysis/kd_tree.h"

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace wearlink::analysis
{
  namespace
  {
    /** Leaves hold at most this many points: a leaf scan is cheaper than more levels. */
    constexpr std::size_t leaf_size = 12;

    /** Keeps the single nearest admissible point. */
    struct NearestCollector
    {
      double      best_sq = std::numeric_limits<double>::infinity();
      std::size_t best    = std::numeric_limits<std::size_t>::max();

      double
      bound_sq() const
      {
        return best_sq;
      }
      void
      offer(const std::size_t index, const double d_sq)
      {
        if (d_sq < best_sq)
          {
            best_sq = d_sq;
            best    = index;
          }
      }
    };

    /** Keeps the k nearest admissible points in a sorted array (k is small). */
    struct KNearestCollector
    {
      explicit KNearestCollector(const std::size_t k)
        : k(k)
      {
        items.reserve(k + 1);
      }
      std::size_t                                 k;
      std::vector<std::pair<double, std::size_t>> items;

      double
      bound_sq() const
      {
        return items.size() < k ? std::numeric_limits<double>::infinity() : items.back().first;
      }
      void
      offer(const std::size_t index, const double d_sq)
      {
        if (items.size() == k && d_sq >= items.back().first)
          return;
        const auto pos = std::upper_bound(items.begin(), items.end(), std::make_pair(d_sq, index));
        items.insert(pos, std::make_pair(d_sq, index));
        if (items.size() > k)
          items.pop_back();
      }
    };
  } // namespace

  KdTree::KdTree(const std::vector<double> &series,
                 const unsigned int         dimension,
                 const std::size_t          delay,
                 const std::size_t          n)
    : dim(dimension)
  {
    Assert(dimension >= 1 && delay >= 1, dealii::ExcInternalError());
    Assert(n == 0 || (n - 1) + (dimension - 1) * delay < series.size(), dealii::ExcInternalError());
    original_index.resize(n);
    std::iota(original_index.begin(), original_index.end(), std::size_t(0));
    if (n == 0)
      return;
    // Coordinate d of point i is x[i + d tau]. The tree is built by permuting the index
    // array; the coordinates are then copied once more, in tree order.
    nodes.reserve(2 * (n / leaf_size + 1));
    coords.resize(n * dim);
    for (std::size_t i = 0; i < n; ++i)
      for (unsigned int d = 0; d < dim; ++d)
        coords[i * dim + d] = series[i + d * delay];
    build(0, n);
    std::vector<double> ordered(n * dim);
    for (std::size_t p = 0; p < n; ++p)
      std::copy_n(&coords[original_index[p] * dim], dim, &ordered[p * dim]);
    coords.swap(ordered);
  }

  // Recursive median split. While building, coords is still in original point order and
  // original_index[begin, end) is the set of points below the node being built.
  std::size_t
  KdTree::build(const std::size_t begin, const std::size_t end)
  {
    const std::size_t id = nodes.size();
    nodes.push_back(Node{begin, end});
    if (end - begin <= leaf_size)
      return id;

    unsigned int best_dim    = 0;
    double       best_spread = -1.0;
    for (unsigned int d = 0; d < dim; ++d)
      {
        double lo = std::numeric_limits<double>::infinity();
        double hi = -lo;
        for (std::size_t p = begin; p < end; ++p)
          {
            const double c = coords[original_index[p] * dim + d];
            lo             = std::min(lo, c);
            hi             = std::max(hi, c);
          }
        if (hi - lo > best_spread)
          {
            best_spread = hi - lo;
            best_dim    = d;
          }
      }
    if (best_spread <= 0.0)
      return id; // all points coincide: keep them in one (large) leaf

    const std::size_t mid = begin + (end - begin) / 2;
    std::nth_element(original_index.begin() + begin,
                     original_index.begin() + mid,
                     original_index.begin() + end,
                     [&](const std::size_t a, const std::size_t b) {
                       return coords[a * dim + best_dim] < coords[b * dim + best_dim];
                     });
    const double split      = coords[original_index[mid] * dim + best_dim];
    nodes[id].split_dim     = best_dim;
    nodes[id].split_value   = split;
    const std::size_t left  = build(begin, mid);
    const std::size_t right = build(mid, end);
    nodes[id].left          = left;
    nodes[id].right         = right;
    return id;
  }

  template <class Collector>
  void
  KdTree::search(const std::size_t      node_id,
                 const double          *point,
                 const NeighbourFilter &filter,
                 const double           min_sq,
                 Collector             &collector) const
  {
    const Node &node = nodes[node_id];
    if (node.left == 0)
      {
        const double max_sq = filter.max_distance * filter.max_distance;
        for (std::size_t p = node.begin; p < node.end; ++p)
          {
            const double *c    = &coords[p * dim];
            double        d_sq = 0.0;
            for (unsigned int d = 0; d < dim; ++d)
              {
                const double diff = c[d] - point[d];
                d_sq += diff * diff;
              }
            if (d_sq <= min_sq || d_sq >= max_sq || d_sq >= collector.bound_sq())
              continue;
            const std::size_t j = original_index[p];
            if (filter.query_index != NeighbourFilter::no_index)
              {
                const std::size_t gap = j > filter.query_index ? j - filter.query_index : filter.query_index - j;
                if (gap <= filter.theiler_window)
                  continue;
              }
            collector.offer(j, d_sq);
          }
        return;
      }
    const double      diff = point[node.split_dim] - node.split_value;
    const std::size_t near = diff < 0 ? node.left : node.right;
    const std::size_t far  = diff < 0 ? node.right : node.left;
    search(near, point, filter, min_sq, collector);
    const double bound = std::min(collector.bound_sq(), filter.max_distance * filter.max_distance);
    if (diff * diff < bound)
      search(far, point, filter, min_sq, collector);
  }

  Neighbour
  KdTree::nearest(const double *point, const NeighbourFilter &filter) const
  {
    NearestCollector c;
    if (!nodes.empty())
      search(0, point, filter, filter.min_distance * filter.min_distance, c);
    Neighbour n;
    if (c.best != std::numeric_limits<std::size_t>::max())
      {
        n.index    = c.best;
        n.distance = std::sqrt(c.best_sq);
      }
    return n;
  }

  std::vector<Neighbour>
  KdTree::k_nearest(const double *point, const std::size_t k, const NeighbourFilter &filter) const
  {
    KNearestCollector c(k);
    if (!nodes.empty() && k > 0)
      search(0, point, filter, filter.min_distance * filter.min_distance, c);
    std::vector<Neighbour> out(c.items.size());
    for (std::size_t i = 0; i < out.size(); ++i)
      {
        out[i].index    = c.items[i].second;
        out[i].distance = std::sqrt(c.items[i].first);
      }
    return out;
  }
} // namespace wearlink::analysis
