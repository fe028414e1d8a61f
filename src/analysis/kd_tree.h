// SPDX-License-Identifier: LGPL-2.1-or-later
// A compact kd-tree for nearest-neighbour searches in delay-embedded time series
// (Friedman, Bentley & Finkel 1977: median splits on the coordinate of largest spread,
// branch-and-bound search). It exists for the Lyapunov-exponent and false-nearest-
// neighbour estimators (doc/models.md §6.4), whose searches need two filters that a
// general-purpose library does not offer directly: a Theiler window (points whose
// time index is within w samples of the query are not neighbours, because they are
// close only by temporal correlation) and a distance annulus (Wolf et al. 1985 take
// replacement points only between a minimum and a maximum scale). Points are copied
// into tree order so that a leaf scan reads contiguous memory; distances are
// Euclidean. Building costs O(N log N), a query about O(log N) on a low-dimensional
// attractor.
//
// Why not a library: nanoflann (Debian's libnanoflann-dev 1.4.3) expresses both filters in
// a custom result set and finds the same neighbours on chaotic data, but it measured
// slower on the estimators' own queries (tests/benchmarks/analysis/bench_kd_tree.cc,
// Lorenz and Hénon embeddings, m = 3, 5, 8, 10^5 points): nearest queries 1.2-1.9 times
// the time of this tree, 64-nearest 1.3-1.7, everything together 1.4-1.5 (1.15-1.25
// with the dimension as a template argument and the points copied into tree order);
// 1.13 times the instructions at 2 x 10^4 points. Only its build is faster, on the
// Lorenz data (0.7-1.0). It also breaks ties between equal distances in its own
// traversal order, so on an exactly periodic series (a sampled sine) some of Wolf's
// candidates, and with them the exponent's last digits, would change.
#pragma once

#include <cstddef>
#include <limits>
#include <vector>

namespace wearlink::analysis
{
  /** A neighbour found by KdTree: its point index and its Euclidean distance. */
  struct Neighbour
  {
    /** Index of the point (for a delay embedding: the time index of its first sample). */
    std::size_t index = std::numeric_limits<std::size_t>::max();
    /** Euclidean distance to the query point [units of the series]. */
    double distance = std::numeric_limits<double>::infinity();

    bool
    found() const
    {
      return index != std::numeric_limits<std::size_t>::max();
    }
  };

  /** Which points a search may return. */
  struct NeighbourFilter
  {
    /**
     * Time index of the query. With @p theiler_window, every point j with
     * |j - query_index| <= theiler_window is excluded. Use no_index for a query that
     * is not itself one of the points (then nothing is excluded by time).
     */
    std::size_t query_index = no_index;
    /** Theiler window w [samples]; 0 excludes only the query point itself. */
    std::size_t theiler_window = 0;
    /** Only points with distance > min_distance (strictly) [units of the series]. */
    double min_distance = 0.0;
    /** Only points with distance < max_distance [units of the series]. */
    double max_distance = std::numeric_limits<double>::infinity();

    static constexpr std::size_t no_index = std::numeric_limits<std::size_t>::max();
  };

  class KdTree
  {
  public:
    /**
     * A tree over the delay vectors y_i = (x_i, x_{i+delay}, ..., x_{i+(dimension-1)
     * delay}) for i = 0 .. n_points-1.
     * @param[in] series the scalar series x (copied; need not outlive the tree)
     * @param[in] dimension embedding dimension m >= 1
     * @param[in] delay delay tau >= 1 [samples]
     * @param[in] n_points number of delay vectors; needs (n_points - 1) + (m - 1) tau
     *   < series.size()
     */
    KdTree(const std::vector<double> &series, unsigned int dimension, std::size_t delay, std::size_t n_points);

    /** The nearest admissible point to @p point (m coordinates); not found() if none. */
    Neighbour
    nearest(const double *point, const NeighbourFilter &filter) const;

    /**
     * The @p k nearest admissible points to @p point, nearest first (fewer if fewer
     * are admissible).
     */
    std::vector<Neighbour>
    k_nearest(const double *point, std::size_t k, const NeighbourFilter &filter) const;

    unsigned int
    dimension() const
    {
      return dim;
    }

    std::size_t
    n_points() const
    {
      return original_index.size();
    }

  private:
    struct Node
    {
      /** Range [begin, end) of tree-ordered points below this node. */
      std::size_t begin;
      std::size_t end;
      /** Children (0 for a leaf; the root is node 0 and is nobody's child). */
      std::size_t  left        = 0;
      std::size_t  right       = 0;
      unsigned int split_dim   = 0;
      double       split_value = 0.0;
    };

    std::size_t
    build(std::size_t begin, std::size_t end);

    template <class Collector>
    void
    search(std::size_t node, const double *point, const NeighbourFilter &filter, double min_sq, Collector &collector)
      const;

    unsigned int             dim;
    std::vector<double>      coords;         ///< tree-ordered, row-major n x dim
    std::vector<std::size_t> original_index; ///< tree position -> point index
    std::vector<Node>        nodes;
  };
} // namespace wearlink::analysis
