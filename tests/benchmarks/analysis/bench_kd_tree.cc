// SPDX-License-Identifier: LGPL-2.1-or-later
// Benchmark: the hand-written kd-tree of the Lyapunov and false-nearest-neighbour
// estimators (analysis/kd_tree.h) against the same interface built on nanoflann
// (Debian's libnanoflann-dev 1.4.3, header only), in one process, on the same data and
// the same queries. It is the evidence for keeping the hand-written tree (see
// kd_tree.h).
//
// Data: delay embeddings of chaotic series generated here
// (tests/unit/analysis/reference_series.h): the Lorenz x (dt = 0.01, delay by mutual
// information as the estimators choose it, 18 samples) and the Hénon x (delay 1), in
// dimensions 3, 5 and 8, N points (default 100,000).
// Queries, those the estimators make, with the Theiler window w = m tau:
//  - nearest: Rosenstein's reference points and the false-nearest-neighbour queries, up
//    to 20,000 evenly spaced points, each asking for its nearest neighbour outside the
//    Theiler window and beyond the exact-recurrence distance 1e-9 x extent;
//  - 64 nearest: Wolf's replacement search every E = 6 tau samples, the 64 nearest points
//    outside the Theiler window in the annulus 1e-6 x extent < d < 5 x 0.05 x extent.
// Trees:
//  - hand: analysis::KdTree;
//  - nanoflann: KDTreeSingleIndexAdaptor as a drop-in replacement would use it (the
//    dimension known at run time, the points in time order);
//  - nanoflann tuned: its best form found here, the dimension a template argument (no
//    heap allocation per query) and the points copied into tree order after the build
//    like KdTree does (by renumbering nanoflann's index array vAcc; dimensions 1..8).
//    Leaf sizes 6 to 32 were also tried: none closes the gap, both use KdTree's 12.
// Every answer of the nanoflann trees is compared with KdTree's: same neighbours, same
// order, same index, bit-identical distance, or the benchmark fails (exit status 1).
// (Chaotic data has no exactly equal distances; on an exactly periodic series the two
// trees pick different points among equal distances, each the first its traversal
// meets.)
// Times are the fastest of R repetitions (the trees take turns starting), wall clock
// and process CPU time, with the ratio nanoflann / hand of the same run. Nothing about
// time is asserted: on a shared machine the wall times include other load.
//
// Instruction counts, repeatable whatever the load: under callgrind every phase (build,
// nearest, 64 nearest) of every tree is dumped separately (callgrind client requests),
//   valgrind --tool=callgrind --callgrind-out-file=cg.out bench_kd_tree --points 20000 --repetitions 1
//   grep -h -E "^(desc: Trigger|totals)" cg.out*
// prints each phase's label followed by its instruction count.
//   usage: bench_kd_tree [--points N] [--repetitions R] [--dimensions 3,5,8]
//                        [--systems lorenz,henon]
#include "analysis/embedding.h"
#include "analysis/kd_tree.h"
#include "unit/analysis/reference_series.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <deque>
#include <functional>
#include <limits>
#include <memory>
#include <nanoflann.hpp>
#include <sstream>
#include <string>
#include <vector>

#if __has_include(<valgrind/callgrind.h>)
#  include <valgrind/callgrind.h>
#else
#  define CALLGRIND_ZERO_STATS
#  define CALLGRIND_DUMP_STATS_AT(label)
#endif

using namespace wearlink::analysis;

namespace
{
  /**
   * The interface of analysis::KdTree on nanoflann's KDTreeSingleIndexAdaptor.
   * @tparam Dim the embedding dimension at compile time, or -1 (nanoflann's "dynamic")
   * @tparam TreeOrder copy the points into tree order after the build (see below)
   *
   * The delay vectors are copied row-major in time order; nanoflann's dataset adaptor
   * (Cloud) hands it coordinate d of point i, and its leaves reach the points through its
   * permutation vAcc. With TreeOrder the points are then copied once more in vAcc's
   * order and vAcc is renumbered 0, 1, ..., so a leaf reads contiguous memory (as in
   * KdTree); the result sets map a tree position back to the time index.
   *
   * The two filters live in the result sets: nanoflann offers every point whose squared
   * distance is below worstDist(); the result set drops it if it lies inside the Theiler
   * window or within the minimum distance; worstDist() never exceeds the squared maximum
   * distance, so nanoflann itself prunes the subtrees beyond the annulus. Distances are
   * summed coordinate by coordinate (L2_Simple_Adaptor) in the same order as KdTree, so
   * equal neighbours have bit-identical distances; among equal distances the first
   * found is kept, as KdTree does.
   */
  template <int Dim, bool TreeOrder>
  class NanoflannKdTree
  {
  public:
    NanoflannKdTree(const std::vector<double> &series,
                    const unsigned int         dimension,
                    const std::size_t          delay,
                    const std::size_t          n)
      : cloud{dimension, std::vector<double>(n * dimension)}
    {
      for (std::size_t i = 0; i < n; ++i)
        for (unsigned int d = 0; d < dimension; ++d)
          cloud.coords[i * dimension + d] = series[i + d * delay];
      index = std::make_unique<Index>(static_cast<int>(dimension),
                                      cloud,
                                      nanoflann::KDTreeSingleIndexAdaptorParams(leaf_size));
      if (TreeOrder)
        {
          time_index.resize(n);
          std::vector<double> ordered(n * dimension);
          for (std::size_t p = 0; p < n; ++p)
            {
              time_index[p] = index->vAcc[p];
              std::copy_n(&cloud.coords[time_index[p] * dimension], dimension, &ordered[p * dimension]);
              index->vAcc[p] = p;
            }
          cloud.coords.swap(ordered);
        }
    }

    Neighbour
    nearest(const double *point, const NeighbourFilter &filter) const
    {
      NearestResult result(filter, time_index);
      index->findNeighbors(result, point, nanoflann::SearchParams());
      Neighbour n;
      if (result.best != std::numeric_limits<std::size_t>::max())
        {
          n.index    = result.time_of(result.best);
          n.distance = std::sqrt(result.best_sq);
        }
      return n;
    }

    std::vector<Neighbour>
    k_nearest(const double *point, const std::size_t k, const NeighbourFilter &filter) const
    {
      KNearestResult result(filter, time_index, k);
      if (k > 0)
        index->findNeighbors(result, point, nanoflann::SearchParams());
      std::vector<Neighbour> out(result.items.size());
      for (std::size_t i = 0; i < out.size(); ++i)
        {
          out[i].index    = result.items[i].second;
          out[i].distance = std::sqrt(result.items[i].first);
        }
      return out;
    }

  private:
    /** KdTree's leaf size, so that both trees stop splitting at the same size. */
    static constexpr std::size_t leaf_size = 12;

    /** nanoflann's dataset adaptor: n points of dim coordinates, row-major. */
    struct Cloud
    {
      unsigned int        dim;
      std::vector<double> coords;

      std::size_t
      kdtree_get_point_count() const
      {
        return coords.size() / dim;
      }
      double
      kdtree_get_pt(const std::size_t i, const std::size_t d) const
      {
        return coords[i * dim + d];
      }
      template <class BoundingBox>
      bool
      kdtree_get_bbox(BoundingBox &) const
      {
        return false; // nanoflann computes it
      }
    };

    using Index = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Cloud, double, std::size_t>,
                                                      Cloud,
                                                      Dim,
                                                      std::size_t>;

    /** What both result sets share: the Theiler window and the annulus. */
    struct FilteredResult
    {
      FilteredResult(const NeighbourFilter &filter, const std::vector<std::size_t> &time_index)
        : filter(filter)
        , time_index(time_index)
        , min_sq(filter.min_distance * filter.min_distance)
        , max_sq(filter.max_distance * filter.max_distance)
      {
      }
      const NeighbourFilter          &filter;
      const std::vector<std::size_t> &time_index;
      double                          min_sq;
      double                          max_sq;

      /** The time index of nanoflann's point number @p p. */
      std::size_t
      time_of(const std::size_t p) const
      {
        return TreeOrder ? time_index[p] : p;
      }
      bool
      excluded(const std::size_t p, const double d_sq) const
      {
        if (d_sq <= min_sq)
          return true;
        if (filter.query_index == NeighbourFilter::no_index)
          return false;
        const std::size_t j   = time_of(p);
        const std::size_t gap = j > filter.query_index ? j - filter.query_index : filter.query_index - j;
        return gap <= filter.theiler_window;
      }
      bool
      full() const
      {
        return true;
      }
    };

    /** The single nearest admissible point. */
    struct NearestResult : FilteredResult
    {
      using FilteredResult::excluded;
      using FilteredResult::FilteredResult;
      using FilteredResult::max_sq;
      double      best_sq = std::numeric_limits<double>::infinity();
      std::size_t best    = std::numeric_limits<std::size_t>::max();

      double
      worstDist() const
      {
        return std::min(best_sq, max_sq);
      }
      bool
      addPoint(const double d_sq, const std::size_t p)
      {
        if (d_sq < worstDist() && !excluded(p, d_sq))
          {
            best_sq = d_sq;
            best    = p;
          }
        return true; // never stop the search early
      }
    };

    /** The k nearest admissible points, sorted by (distance, index) as in KdTree. */
    struct KNearestResult : FilteredResult
    {
      using FilteredResult::excluded;
      using FilteredResult::max_sq;
      KNearestResult(const NeighbourFilter &filter, const std::vector<std::size_t> &time_index, const std::size_t k)
        : FilteredResult(filter, time_index)
        , k(k)
      {
        items.reserve(k + 1);
      }
      std::size_t                                 k;
      std::vector<std::pair<double, std::size_t>> items; ///< (squared distance, time index)

      double
      worstDist() const
      {
        return items.size() < k ? max_sq : items.back().first;
      }
      bool
      addPoint(const double d_sq, const std::size_t p)
      {
        if (d_sq >= worstDist() || excluded(p, d_sq))
          return true;
        const auto item = std::make_pair(d_sq, this->time_of(p));
        items.insert(std::upper_bound(items.begin(), items.end(), item), item);
        if (items.size() > k)
          items.pop_back();
        return true;
      }
    };

    Cloud                    cloud;
    std::unique_ptr<Index>   index;
    std::vector<std::size_t> time_index; ///< TreeOrder: tree position -> time index
  };

  /** A delay embedding and the scales of the estimators' queries on it. */
  struct Configuration
  {
    std::string         system;
    std::vector<double> series;
    unsigned int        dimension;
    std::size_t         delay;
    std::size_t         n_points;
    std::size_t         theiler_window;
    double              extent;
  };

  /** One query: the time index of its point and its filter. */
  struct Query
  {
    std::size_t     index;
    NeighbourFilter filter;
  };

  /** A set of queries and their points (row-major, taken from the series). */
  struct Queries
  {
    std::vector<Query>  queries;
    std::vector<double> points;

    void
    add(const Configuration &c, const NeighbourFilter &filter)
    {
      queries.push_back({filter.query_index, filter});
      for (unsigned int d = 0; d < c.dimension; ++d)
        points.push_back(c.series[filter.query_index + d * c.delay]);
    }
  };

  Queries
  nearest_queries(const Configuration &c)
  {
    // Rosenstein's reference points (max_references 20,000, i = r n / n_ref) and its
    // minimum distance; the false-nearest-neighbour queries are the same with 1e-9 x
    // the standard deviation.
    const std::size_t n_ref = std::min<std::size_t>(c.n_points, 20000);
    Queries           out;
    for (std::size_t r = 0; r < n_ref; ++r)
      {
        NeighbourFilter filter;
        filter.query_index    = r * c.n_points / n_ref;
        filter.theiler_window = c.theiler_window;
        filter.min_distance   = 1e-9 * c.extent;
        out.add(c, filter);
      }
    return out;
  }

  Queries
  k_nearest_queries(const Configuration &c)
  {
    // Wolf's replacement search at i = E, 2E, ... with the default scales.
    const std::size_t E = 6 * c.delay;
    Queries           out;
    for (std::size_t i = E; i < c.n_points; i += E)
      {
        NeighbourFilter filter;
        filter.query_index    = i;
        filter.theiler_window = c.theiler_window;
        filter.min_distance   = 1e-6 * c.extent;
        filter.max_distance   = 5 * 0.05 * c.extent;
        out.add(c, filter);
      }
    return out;
  }

  /** Wolf's number of replacement candidates (WolfOptions::n_candidates). */
  constexpr std::size_t n_candidates = 64;

  template <class Tree>
  std::unique_ptr<Tree>
  build_tree(const Configuration &c)
  {
    return std::make_unique<Tree>(c.series, c.dimension, c.delay, c.n_points);
  }

  template <class Tree>
  std::vector<std::vector<Neighbour>>
  run_nearest(const Tree &tree, const Configuration &c, const Queries &q)
  {
    std::vector<std::vector<Neighbour>> out(q.queries.size());
    for (std::size_t i = 0; i < q.queries.size(); ++i)
      {
        const Neighbour n = tree.nearest(&q.points[i * c.dimension], q.queries[i].filter);
        if (n.found())
          out[i].push_back(n);
      }
    return out;
  }

  template <class Tree>
  std::vector<std::vector<Neighbour>>
  run_k_nearest(const Tree &tree, const Configuration &c, const Queries &q)
  {
    std::vector<std::vector<Neighbour>> out(q.queries.size());
    for (std::size_t i = 0; i < q.queries.size(); ++i)
      out[i] = tree.k_nearest(&q.points[i * c.dimension], n_candidates, q.queries[i].filter);
    return out;
  }

  /** Wall and process CPU time [s]. */
  struct Times
  {
    double wall = std::numeric_limits<double>::infinity();
    double cpu  = std::numeric_limits<double>::infinity();

    void
    keep_fastest(const Times &t)
    {
      wall = std::min(wall, t.wall);
      cpu  = std::min(cpu, t.cpu);
    }
  };

  /**
   * Times one call of @p f; under callgrind its instructions are dumped separately,
   * labelled @p label.
   */
  template <class F>
  Times
  measured(const std::string &label, F &&f)
  {
    CALLGRIND_ZERO_STATS;
    const auto    wall_start = std::chrono::steady_clock::now();
    const clock_t cpu_start  = std::clock();
    f();
    Times t;
    t.cpu  = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
    t.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
    CALLGRIND_DUMP_STATS_AT(label.c_str());
    (void)label;
    return t;
  }

  enum Phase
  {
    build,
    nearest,
    k_nearest,
    n_phases
  };
  const char *const phase_names[n_phases] = {"build", "nearest", "64 nearest"};

  /** One tree type under test: its fastest times and its last answers. */
  struct Candidate
  {
    std::string                         name;
    Times                               times[n_phases];
    std::vector<std::vector<Neighbour>> answers[n_phases]; ///< nearest, 64 nearest
    std::function<void()>               repeat;            ///< build and query once
  };

  template <class Tree>
  void
  add_candidate(std::deque<Candidate> &candidates,
                const std::string     &name,
                const Configuration   &c,
                const Queries         &near,
                const Queries         &k_near)
  {
    Candidate &t = candidates.emplace_back();
    t.name       = name;
    t.repeat     = [&t, &c, &near, &k_near]() {
      const std::string     label = t.name + " " + c.system + " m=" + std::to_string(c.dimension) + " ";
      std::unique_ptr<Tree> tree;
      t.times[build].keep_fastest(measured(label + phase_names[build], [&] { tree = build_tree<Tree>(c); }));
      t.times[nearest].keep_fastest(
        measured(label + phase_names[nearest], [&] { t.answers[nearest] = run_nearest(*tree, c, near); }));
      t.times[k_nearest].keep_fastest(
        measured(label + phase_names[k_nearest], [&] { t.answers[k_nearest] = run_k_nearest(*tree, c, k_near); }));
    };
  }

  /** The tuned nanoflann tree needs the dimension at compile time: 1 .. 8 here. */
  template <int Dim = 1>
  void
  add_tuned_nanoflann(std::deque<Candidate> &candidates,
                      const Configuration   &c,
                      const Queries         &near,
                      const Queries         &k_near)
  {
    if constexpr (Dim <= 8)
      {
        if (c.dimension == Dim)
          add_candidate<NanoflannKdTree<Dim, true>>(candidates, "nanoflann-tuned", c, near, k_near);
        else
          add_tuned_nanoflann<Dim + 1>(candidates, c, near, k_near);
      }
  }

  /** Number of queries whose answers differ from @p reference; the first few are printed. */
  std::size_t
  count_differences(const std::vector<std::vector<Neighbour>> &reference,
                    const std::vector<std::vector<Neighbour>> &answers,
                    const std::string                         &what)
  {
    std::size_t n_different = 0;
    for (std::size_t q = 0; q < reference.size(); ++q)
      {
        bool equal = reference[q].size() == answers[q].size();
        for (std::size_t k = 0; equal && k < reference[q].size(); ++k)
          equal = reference[q][k].index == answers[q][k].index && reference[q][k].distance == answers[q][k].distance;
        if (!equal && ++n_different <= 5)
          std::printf("  DIFFERENT %s, query %zu: %zu vs %zu neighbours, first %zu (%.17g) vs %zu (%.17g)\n",
                      what.c_str(),
                      q,
                      reference[q].size(),
                      answers[q].size(),
                      reference[q].empty() ? 0 : reference[q][0].index,
                      reference[q].empty() ? 0.0 : reference[q][0].distance,
                      answers[q].empty() ? 0 : answers[q][0].index,
                      answers[q].empty() ? 0.0 : answers[q][0].distance);
      }
    return n_different;
  }

  std::vector<std::string>
  split_list(const std::string &text)
  {
    std::vector<std::string> out;
    std::stringstream        ss(text);
    std::string              item;
    while (std::getline(ss, item, ','))
      out.push_back(item);
    return out;
  }
} // namespace

int
main(int argc, char **argv)
{
  std::size_t              n_points    = 100000;
  unsigned int             repetitions = 5;
  std::vector<std::string> dimensions  = {"3", "5", "8"};
  std::vector<std::string> systems     = {"lorenz", "henon"};
  for (int a = 1; a < argc; a += 2)
    {
      const std::string option = argv[a], value = a + 1 < argc ? argv[a + 1] : "";
      if (option == "--points" && !value.empty())
        n_points = std::stoul(value);
      else if (option == "--repetitions" && !value.empty())
        repetitions = std::max(1ul, std::stoul(value));
      else if (option == "--dimensions" && !value.empty())
        dimensions = split_list(value);
      else if (option == "--systems" && !value.empty())
        systems = split_list(value);
      else
        {
          std::fprintf(stderr,
                       "usage: bench_kd_tree [--points N] [--repetitions R] [--dimensions 3,5,8] "
                       "[--systems lorenz,henon]\n");
          return 2;
        }
    }

  // Debian's libnanoflann-dev 1.4.3 still defines NANOFLANN_VERSION 0x142.
  std::printf("kd-tree queries of the Lyapunov estimators: hand-written analysis::KdTree vs nanoflann "
              "(NANOFLANN_VERSION 0x%x)\n%zu points, fastest of %u repetition(s); ratio = nanoflann / hand of the "
              "wall-clock times, (cpu) the same for the process CPU times\n",
              NANOFLANN_VERSION,
              n_points,
              repetitions);
  std::printf("%-7s %2s %4s %4s %-16s %7s | %9s | %9s %6s %6s | %9s %6s %6s\n",
              "system",
              "m",
              "tau",
              "w",
              "phase",
              "count",
              "hand [s]",
              "nano [s]",
              "ratio",
              "(cpu)",
              "tuned [s]",
              "ratio",
              "(cpu)");

  // Samples beyond the N points for the last delay vectors: (m - 1) tau for m <= 8 and
  // the Lorenz delay (18 samples).
  constexpr std::size_t extra_samples     = 1024;
  std::size_t           total_differences = 0;
  // Sums over all configurations: hand, nanoflann, nanoflann tuned, and hand over the
  // configurations that have a tuned tree.
  Times totals[4];
  for (auto &t : totals)
    t.wall = t.cpu = 0.0;
  for (const std::string &system : systems)
    {
      Configuration base;
      base.system = system;
      if (system == "lorenz")
        base.series = wearlink::testing::lorenz_x(n_points + extra_samples);
      else if (system == "henon")
        base.series = wearlink::testing::henon_x(n_points + extra_samples);
      else
        {
          std::fprintf(stderr, "unknown system %s (lorenz, henon)\n", system.c_str());
          return 2;
        }
      base.delay          = system == "henon" ? 1 : choose_delay(base.series).delay;
      const auto [lo, hi] = std::minmax_element(base.series.begin(), base.series.end());
      base.extent         = *hi - *lo;
      for (const std::string &m : dimensions)
        {
          Configuration c    = base;
          c.dimension        = std::stoul(m);
          c.theiler_window   = c.dimension * c.delay;
          c.n_points         = std::min(n_points, c.series.size() - (c.dimension - 1) * c.delay);
          const Queries near = nearest_queries(c), k_near = k_nearest_queries(c);

          std::deque<Candidate> candidates;
          add_candidate<KdTree>(candidates, "hand", c, near, k_near);
          add_candidate<NanoflannKdTree<-1, false>>(candidates, "nanoflann", c, near, k_near);
          add_tuned_nanoflann(candidates, c, near, k_near);
          for (unsigned int r = 0; r < repetitions; ++r)
            for (std::size_t k = 0; k < candidates.size(); ++k)
              candidates[(r + k) % candidates.size()].repeat();

          std::size_t differences = 0;
          for (std::size_t t = 1; t < candidates.size(); ++t)
            for (const Phase p : {nearest, k_nearest})
              differences += count_differences(candidates[0].answers[p],
                                               candidates[t].answers[p],
                                               candidates[t].name + " " + phase_names[p]);
          total_differences += differences;

          // One row per phase, then per estimator: Rosenstein and the false nearest
          // neighbours build a tree and make the nearest queries, Wolf builds one and
          // makes the 64-nearest queries.
          auto row = [&](const char *name, const std::size_t count, const std::vector<Phase> &phases) {
            Times sum[3];
            for (std::size_t t = 0; t < candidates.size(); ++t)
              {
                sum[t].wall = sum[t].cpu = 0.0;
                for (const Phase p : phases)
                  {
                    sum[t].wall += candidates[t].times[p].wall;
                    sum[t].cpu += candidates[t].times[p].cpu;
                  }
              }
            std::printf("%-7s %2u %4zu %4zu %-16s %7zu | %9.4f | %9.4f %6.2f %6.2f",
                        c.system.c_str(),
                        c.dimension,
                        c.delay,
                        c.theiler_window,
                        name,
                        count,
                        sum[0].wall,
                        sum[1].wall,
                        sum[1].wall / sum[0].wall,
                        sum[1].cpu / sum[0].cpu);
            if (candidates.size() > 2)
              std::printf(" | %9.4f %6.2f %6.2f\n", sum[2].wall, sum[2].wall / sum[0].wall, sum[2].cpu / sum[0].cpu);
            else
              std::printf(" | %9s\n", "-");
          };
          row(phase_names[build], c.n_points, {build});
          row(phase_names[nearest], near.queries.size(), {nearest});
          row(phase_names[k_nearest], k_near.queries.size(), {k_nearest});
          row("Rosenstein, FNN", near.queries.size(), {build, nearest});
          row("Wolf", k_near.queries.size(), {build, k_nearest});
          for (const Phase p : {build, nearest, k_nearest})
            {
              for (std::size_t t = 0; t < candidates.size(); ++t)
                {
                  totals[t].wall += candidates[t].times[p].wall;
                  totals[t].cpu += candidates[t].times[p].cpu;
                }
              if (candidates.size() > 2)
                {
                  totals[3].wall += candidates[0].times[p].wall;
                  totals[3].cpu += candidates[0].times[p].cpu;
                }
            }
          std::printf("%-7s %2u %4zu %4zu answers: %s\n",
                      c.system.c_str(),
                      c.dimension,
                      c.delay,
                      c.theiler_window,
                      differences == 0 ? "identical neighbours (index and distance) for every query" : "DIFFERENT");
        }
    }
  std::printf("total, build + queries of all configurations: hand %.3f s, nanoflann %.3f s (ratio %.2f, CPU %.2f)",
              totals[0].wall,
              totals[1].wall,
              totals[1].wall / totals[0].wall,
              totals[1].cpu / totals[0].cpu);
  if (totals[2].wall > 0.0)
    std::printf(", nanoflann tuned %.3f s (ratio %.2f, CPU %.2f)",
                totals[2].wall,
                totals[2].wall / totals[3].wall,
                totals[2].cpu / totals[3].cpu);
  std::printf("\n");
  if (total_differences > 0)
    {
      std::printf("FAILED: %zu queries answered differently\n", total_differences);
      return 1;
    }
  return 0;
}
