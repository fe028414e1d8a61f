// SPDX-License-Identifier: LGPL-2.1-or-later
// Benchmark: the largest Lyapunov exponent of a long series. The Lorenz x(t) (dt = 0.01,
// generated here, tests/unit/analysis/reference_series.h), N samples (default 10^6),
// timed step by step in one process: delay by mutual information, dimension by false
// nearest neighbours, then Wolf and Rosenstein with that embedding. Prints wall times
// and the exponents (reference 0.906 1/s, natural log). Asserts nothing about time.
//   usage: bench_lyapunov [samples]
#include "analysis/embedding.h"
#include "analysis/lyapunov.h"
#include "unit/analysis/reference_series.h"

#include <chrono>
#include <cstdio>
#include <string>

using namespace wearlink::analysis;

namespace
{
  template <class F>
  double
  timed(F &&f)
  {
    const auto start = std::chrono::steady_clock::now();
    f();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
} // namespace

int
main(int argc, char **argv)
{
  const std::size_t   n  = argc > 1 ? std::stoul(argv[1]) : 1000000;
  const double        dt = 0.01;
  std::vector<double> x;
  const double        t_generate = timed([&] { x = wearlink::testing::lorenz_x(n, dt); });

  DelayChoice       delay;
  DimensionChoice   dimension;
  const double      t_delay = timed([&] { delay = choose_delay(x); });
  const double      t_dim   = timed([&] { dimension = choose_dimension(x, delay.delay); });
  const Embedding   emb{dimension.dimension, delay.delay};
  const std::size_t w = default_theiler_window(emb);

  WolfResult       wolf;
  RosensteinResult rosenstein;
  const double     t_wolf       = timed([&] { wolf = wolf_exponent(x, emb, w); });
  const double     t_rosenstein = timed([&] { rosenstein = rosenstein_exponent(x, emb, w); });

  std::printf("largest Lyapunov exponent of a %zu-sample Lorenz x series (dt = %.2f s), reference 0.906 1/s\n", n, dt);
  std::printf("%-44s %10s   %s\n", "step", "wall [s]", "result");
  std::printf("%-44s %10.3f\n", "generate the series (RK4)", t_generate);
  std::printf("%-44s %10.3f   tau = %zu samples\n", "delay: mutual information (first minimum)", t_delay, delay.delay);
  std::printf("%-44s %10.3f   m = %u\n", "dimension: false nearest neighbours", t_dim, dimension.dimension);
  std::printf("%-44s %10.3f   %.4f 1/s (natural log), %zu segments of %zu samples\n",
              "Wolf et al. 1985",
              t_wolf,
              wolf.exponent_per_sample / dt,
              wolf.n_segments,
              wolf.evolution_steps);
  std::printf("%-44s %10.3f   %.4f 1/s (natural log), %zu reference pairs, horizon %zu samples\n",
              "Rosenstein et al. 1993",
              t_rosenstein,
              rosenstein.exponent_per_sample / dt,
              rosenstein.n_references,
              rosenstein.mean_log_divergence.size() - 1);
  std::printf("%-44s %10.3f\n", "total, automatic embedding + Wolf", t_delay + t_dim + t_wolf);
  std::printf("%-44s %10.3f\n", "total, automatic embedding + Rosenstein", t_delay + t_dim + t_rosenstein);
  return 0;
}
