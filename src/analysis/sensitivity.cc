// SPDX-License-Identifier: LGPL-2.1-or-later
#include "analysis/sensitivity.h"

#include "analysis/ensemble_statistics.h"
#include "base/exceptions.h"
#include "base/text.h"

#include <algorithm>
#include <boost/math/distributions/lognormal.hpp>
#include <boost/math/distributions/normal.hpp>
#include <boost/random/sobol.hpp>
#include <cmath>
#include <numeric>
#include <random>

namespace wearlink::analysis
{
  struct SobolSequence::Engine
  {
    explicit Engine(const unsigned int dimension)
      : sobol(dimension)
    {
    }
    boost::random::sobol sobol;
  };

  namespace
  {
    /** The engine's 64-bit integer as a coordinate in (0, 1): 53 leading bits, centred. */
    double
    unit_coordinate(const std::uint64_t v)
    {
      return (static_cast<double>(v >> 11) + 0.5) * 0x1.0p-53;
    }

    /** std::mt19937_64 seeded through std::seed_seq from the two halves of @p seed. */
    std::mt19937_64
    seeded_engine(const std::uint64_t seed)
    {
      std::seed_seq sequence{static_cast<std::uint32_t>(seed & 0xffffffffu), static_cast<std::uint32_t>(seed >> 32)};
      return std::mt19937_64(sequence);
    }
  } // namespace

  SobolSequence::SobolSequence(const unsigned int dimension, const std::uint64_t skip, const std::uint64_t shift_seed)
    : n_dimensions(dimension)
    , start(skip)
    , shift(dimension, 0)
  {
    if (dimension < 1 || dimension > max_dimension())
      throw InputError("A Sobol sequence has 1 to " + std::to_string(max_dimension()) + " dimensions; asked for " +
                       std::to_string(dimension) + ".");
    prototype = std::make_shared<const Engine>(dimension);
    if (shift_seed != 0)
      {
        auto engine = seeded_engine(shift_seed);
        for (auto &mask : shift)
          mask = engine();
      }
  }

  unsigned int
  SobolSequence::max_dimension()
  {
    return BOOST_RANDOM_SOBOL_MAX_DIMENSION;
  }

  std::vector<std::vector<double>>
  SobolSequence::points(const std::uint64_t first, const std::uint64_t count) const
  {
    if (start + first < start)
      throw InputError("The Sobol point " + std::to_string(first) + " after a skip of " + std::to_string(start) +
                       " is beyond the sequence's 2^64 points.");
    // A copy of the engine (its direction numbers, a few kB) positioned at the first
    // point: seed(n) builds point n from n's Gray code, whatever was drawn before.
    Engine engine = *prototype;
    engine.sobol.seed(start + first);
    std::vector<std::vector<double>> out(count, std::vector<double>(n_dimensions));
    for (auto &p : out)
      for (unsigned int c = 0; c < n_dimensions; ++c)
        p[c] = unit_coordinate(engine.sobol() ^ shift[c]);
    return out;
  }

  std::vector<double>
  SobolSequence::point(const std::uint64_t n) const
  {
    return points(n, 1).front();
  }

  // ---------------------------------------------------------------- distributions

  namespace
  {
    void
    require(const bool ok, const std::string &family, const std::string &what)
    {
      if (!ok)
        throw InputError("A " + family + " distribution needs " + what + ".");
    }

    bool
    finite(const double v)
    {
      return std::isfinite(v);
    }

    /**
     * The truncated normal's quantile: x = μ + σ Φ⁻¹(Φ(α) + u (Φ(β) − Φ(α))) with
     * α, β the standardised bounds. Bounds in the upper tail use the complementary
     * functions (Q = 1 − Φ), which keep their digits where Φ rounds to 1.
     */
    double
    truncated_normal_quantile(const InputDistribution &d, const double u)
    {
      const boost::math::normal standard;
      const double              alpha = (d.lower - d.mean) / d.std_dev, beta = (d.upper - d.mean) / d.std_dev;
      if (alpha > 0)
        {
          const double qa = boost::math::cdf(boost::math::complement(standard, alpha));
          const double qb = boost::math::cdf(boost::math::complement(standard, beta));
          const double q  = qa - u * (qa - qb);
          return std::clamp(d.mean + d.std_dev * boost::math::quantile(boost::math::complement(standard, q)),
                            d.lower,
                            d.upper);
        }
      const double pa = boost::math::cdf(standard, alpha), pb = boost::math::cdf(standard, beta);
      return std::clamp(d.mean + d.std_dev * boost::math::quantile(standard, pa + u * (pb - pa)), d.lower, d.upper);
    }

    /** The probability of [lower, upper] under the untruncated normal. */
    double
    truncation_mass(const InputDistribution &d)
    {
      const boost::math::normal standard;
      const double              alpha = (d.lower - d.mean) / d.std_dev, beta = (d.upper - d.mean) / d.std_dev;
      if (alpha > 0)
        return boost::math::cdf(boost::math::complement(standard, alpha)) -
               boost::math::cdf(boost::math::complement(standard, beta));
      return boost::math::cdf(standard, beta) - boost::math::cdf(standard, alpha);
    }
  } // namespace

  InputDistribution
  InputDistribution::normal(const double mean, const double std_dev)
  {
    require(finite(mean), "normal", "a finite mean");
    require(finite(std_dev) && std_dev > 0, "normal", "a standard deviation > 0, not " + format_number(std_dev, 6));
    InputDistribution d;
    d.kind    = DistributionKind::normal;
    d.mean    = mean;
    d.std_dev = std_dev;
    return d;
  }

  InputDistribution
  InputDistribution::lognormal(const double median, const double log_std)
  {
    require(finite(median) && median > 0, "lognormal", "a median > 0, not " + format_number(median, 6));
    require(finite(log_std) && log_std > 0,
            "lognormal",
            "a standard deviation of ln x > 0, not " + format_number(log_std, 6));
    InputDistribution d;
    d.kind    = DistributionKind::lognormal;
    d.median  = median;
    d.log_std = log_std;
    return d;
  }

  InputDistribution
  InputDistribution::uniform(const double lower, const double upper)
  {
    require(finite(lower) && finite(upper) && lower < upper,
            "uniform",
            "finite bounds with lower < upper, not " + format_number(lower, 6) + " and " + format_number(upper, 6));
    InputDistribution d;
    d.kind  = DistributionKind::uniform;
    d.lower = lower;
    d.upper = upper;
    return d;
  }

  InputDistribution
  InputDistribution::truncated_normal(const double mean, const double std_dev, const double lower, const double upper)
  {
    InputDistribution d = normal(mean, std_dev);
    require(finite(lower) && finite(upper) && lower < upper,
            "truncated normal",
            "finite bounds with lower < upper, not " + format_number(lower, 6) + " and " + format_number(upper, 6));
    d.kind  = DistributionKind::truncated_normal;
    d.lower = lower;
    d.upper = upper;
    require(truncation_mass(d) >= 1e-12,
            "truncated normal",
            "bounds that hold a probability of at least 1e-12 of the normal (mean " + format_number(mean, 6) +
              ", standard deviation " + format_number(std_dev, 6) + "); [" + format_number(lower, 6) + ", " +
              format_number(upper, 6) + "] lies too far out in its tail");
    return d;
  }

  double
  InputDistribution::quantile(const double u) const
  {
    switch (kind)
      {
        case DistributionKind::normal:
          return boost::math::quantile(boost::math::normal(mean, std_dev), u);
        case DistributionKind::lognormal:
          return boost::math::quantile(boost::math::lognormal(std::log(median), log_std), u);
        case DistributionKind::uniform:
          return lower + u * (upper - lower);
        case DistributionKind::truncated_normal:
          return truncated_normal_quantile(*this, u);
      }
    return std::numeric_limits<double>::quiet_NaN();
  }

  std::string
  InputDistribution::describe() const
  {
    const auto n = [](const double v) {
      return format_number(v, 6);
    };
    switch (kind)
      {
        case DistributionKind::normal:
          return "normal(mean " + n(mean) + ", std_dev " + n(std_dev) + ")";
        case DistributionKind::lognormal:
          return "lognormal(median " + n(median) + ", log_std " + n(log_std) + ")";
        case DistributionKind::uniform:
          return "uniform(" + n(lower) + ", " + n(upper) + ")";
        case DistributionKind::truncated_normal:
          return "truncated_normal(mean " + n(mean) + ", std_dev " + n(std_dev) + ", " + n(lower) + ", " + n(upper) +
                 ")";
      }
    return "unknown";
  }

  // ---------------------------------------------------------------- Saltelli design

  SaltelliDesign::SaltelliDesign(std::vector<InputDistribution> inputs,
                                 const std::uint64_t            n_base,
                                 const std::uint64_t            skip,
                                 const std::uint64_t            shift_seed)
    : distributions(std::move(inputs))
    , base_samples(n_base)
    , sequence(static_cast<unsigned int>(2 * std::max<std::size_t>(distributions.size(), 1)), skip, shift_seed)
  {
    if (distributions.empty())
      throw InputError("A Saltelli design needs at least one uncertain input.");
    if (n_base < 1)
      throw InputError("A Saltelli design needs at least one base sample.");
  }

  std::vector<double>
  SaltelliDesign::unit_point(const std::uint64_t k) const
  {
    const unsigned int  d    = n_inputs();
    const std::uint64_t row  = k / (d + 2);
    const unsigned int  part = static_cast<unsigned int>(k % (d + 2));
    const auto          ab   = sequence.point(row);
    // A_j is the first half of the 2d coordinates, B_j the second; A_B^(i) takes
    // coordinate i from B_j.
    std::vector<double> u(ab.begin() + (part == 1 ? d : 0), ab.begin() + (part == 1 ? 2 * d : d));
    if (part >= 2)
      u[part - 2] = ab[d + part - 2];
    return u;
  }

  std::vector<double>
  SaltelliDesign::point(const std::uint64_t k) const
  {
    auto x = unit_point(k);
    for (unsigned int i = 0; i < x.size(); ++i)
      x[i] = distributions[i].quantile(x[i]);
    return x;
  }

  std::vector<std::vector<double>>
  SaltelliDesign::points() const
  {
    std::vector<std::vector<double>> out;
    out.reserve(n_points());
    for (std::uint64_t k = 0; k < n_points(); ++k)
      out.push_back(point(k));
    return out;
  }

  // ---------------------------------------------------------------- Sobol indices

  std::string
  method_name(const SensitivityMethod method)
  {
    return method == SensitivityMethod::sobol_indices ? "sobol-indices" : "rank-correlation";
  }

  namespace
  {
    /** The evaluations of a Saltelli design, by block: f_A[j], f_B[j], f_ABi[i][j]. */
    struct SaltelliOutputs
    {
      std::vector<double>              fa, fb;
      std::vector<std::vector<double>> fab;
      std::uint64_t                    dropped = 0;
    };

    /** Split @p outputs into blocks, leaving out the rows with a non-finite value. */
    SaltelliOutputs
    split_outputs(const unsigned int d, const std::vector<double> &outputs)
    {
      if (d < 1 || outputs.size() % (d + 2) != 0)
        throw InputError("A Saltelli design of " + std::to_string(d) + " inputs has a multiple of " +
                         std::to_string(d + 2) + " evaluations; given " + std::to_string(outputs.size()) + ".");
      SaltelliOutputs s;
      s.fab.resize(d);
      for (std::size_t row = 0; row < outputs.size() / (d + 2); ++row)
        {
          const auto first = outputs.begin() + row * (d + 2);
          if (!std::all_of(first, first + d + 2, [](const double v) { return std::isfinite(v); }))
            {
              ++s.dropped;
              continue;
            }
          s.fa.push_back(first[0]);
          s.fb.push_back(first[1]);
          for (unsigned int i = 0; i < d; ++i)
            s.fab[i].push_back(first[2 + i]);
        }
      return s;
    }

    /** First-order and total indices of the rows @p rows (repeats allowed), and V. */
    struct IndexValues
    {
      std::vector<double> first, total;
      double              mean = 0, variance = 0;
    };

    IndexValues
    index_values(const SaltelliOutputs &s, const std::vector<std::uint32_t> &rows)
    {
      const double n = static_cast<double>(rows.size());
      IndexValues  v;
      for (const auto j : rows)
        v.mean += (s.fa[j] + s.fb[j]) / (2 * n);
      for (const auto j : rows)
        v.variance += ((s.fa[j] - v.mean) * (s.fa[j] - v.mean) + (s.fb[j] - v.mean) * (s.fb[j] - v.mean)) / (2 * n);
      for (const auto &fab : s.fab)
        {
          double first = 0, total = 0;
          for (const auto j : rows)
            {
              first += (s.fb[j] - v.mean) * (fab[j] - s.fa[j]);
              total += (s.fa[j] - fab[j]) * (s.fa[j] - fab[j]);
            }
          // 0/0 for a constant output: NaN, as documented.
          v.first.push_back(first / n / v.variance);
          v.total.push_back(total / (2 * n) / v.variance);
        }
      return v;
    }

    /**
     * Row indices for one bootstrap resample: n draws with replacement. The top 32 bits
     * of each 64-bit output times n, shifted down by 32, is uniform on 0 … n − 1 up to a
     * bias of n / 2³² — integer arithmetic that every platform does alike (unlike
     * std::uniform_int_distribution, whose algorithm the standard leaves open).
     */
    std::vector<std::uint32_t>
    resample(std::mt19937_64 &engine, const std::uint32_t n)
    {
      std::vector<std::uint32_t> rows(n);
      for (auto &r : rows)
        r = static_cast<std::uint32_t>(((engine() >> 32) * n) >> 32);
      return rows;
    }

    /** Percentile-bootstrap 95 % intervals of every index, into @p inputs. */
    void
    bootstrap_intervals(const SaltelliOutputs         &s,
                        const SensitivitySettings     &settings,
                        std::vector<InputSensitivity> &inputs)
    {
      const auto                       n      = static_cast<std::uint32_t>(s.fa.size());
      auto                             engine = seeded_engine(settings.bootstrap_seed);
      std::vector<std::vector<double>> first(inputs.size()), total(inputs.size());
      for (unsigned int b = 0; b < settings.bootstrap_resamples; ++b)
        {
          const auto v = index_values(s, resample(engine, n));
          for (std::size_t i = 0; i < inputs.size(); ++i)
            {
              first[i].push_back(v.first[i]);
              total[i].push_back(v.total[i]);
            }
        }
      for (std::size_t i = 0; i < inputs.size(); ++i)
        {
          inputs[i].first_order.ci95_low  = percentile(first[i], 0.025);
          inputs[i].first_order.ci95_high = percentile(first[i], 0.975);
          inputs[i].total.ci95_low        = percentile(total[i], 0.025);
          inputs[i].total.ci95_high       = percentile(total[i], 0.975);
        }
    }
  } // namespace

  SensitivityResult
  sobol_indices(const unsigned int n_inputs, const std::vector<double> &outputs, const SensitivitySettings &settings)
  {
    const SaltelliOutputs s = split_outputs(n_inputs, outputs);
    if (s.fa.size() < 2)
      throw InputError("Sobol indices need at least 2 base samples with finite outputs; " +
                       std::to_string(s.fa.size()) + " of " + std::to_string(s.fa.size() + s.dropped) + " have them.");
    if (s.fa.size() >= (std::uint64_t(1) << 32))
      throw InputError("Sobol indices are estimated from fewer than 2^32 base samples.");
    std::vector<std::uint32_t> all(s.fa.size());
    std::iota(all.begin(), all.end(), 0u);
    const IndexValues v = index_values(s, all);

    SensitivityResult r;
    r.method          = SensitivityMethod::sobol_indices;
    r.samples         = s.fa.size();
    r.dropped         = s.dropped;
    r.output_mean     = v.mean;
    r.output_variance = v.variance;
    r.inputs.resize(n_inputs);
    for (unsigned int i = 0; i < n_inputs; ++i)
      {
        r.inputs[i].first_order.value = v.first[i];
        r.inputs[i].total.value       = v.total[i];
      }
    if (settings.bootstrap_resamples > 0 && v.variance > 0)
      {
        bootstrap_intervals(s, settings, r.inputs);
        r.bootstrap_resamples = settings.bootstrap_resamples;
      }
    return r;
  }

  // ---------------------------------------------------------------- rank correlations

  namespace
  {
    /** Ranks 1 … n of @p values, ties sharing their mean rank. */
    std::vector<double>
    ranks(const std::vector<double> &values)
    {
      std::vector<std::size_t> order(values.size());
      std::iota(order.begin(), order.end(), std::size_t(0));
      std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return values[a] < values[b]; });
      std::vector<double> rank(values.size());
      for (std::size_t first = 0; first < order.size();)
        {
          std::size_t last = first;
          while (last + 1 < order.size() && values[order[last + 1]] == values[order[first]])
            ++last;
          const double shared = 0.5 * static_cast<double>(first + last) + 1;
          for (std::size_t k = first; k <= last; ++k)
            rank[order[k]] = shared;
          first = last + 1;
        }
      return rank;
    }

    /** Pearson's correlation of @p x and @p y (NaN if either is constant). */
    double
    pearson(const std::vector<double> &x, const std::vector<double> &y)
    {
      const double n   = static_cast<double>(x.size());
      const double mx  = std::accumulate(x.begin(), x.end(), 0.0) / n;
      const double my  = std::accumulate(y.begin(), y.end(), 0.0) / n;
      double       sxy = 0, sxx = 0, syy = 0;
      for (std::size_t k = 0; k < x.size(); ++k)
        {
          sxy += (x[k] - mx) * (y[k] - my);
          sxx += (x[k] - mx) * (x[k] - mx);
          syy += (y[k] - my) * (y[k] - my);
        }
      if (!(sxx > 0 && syy > 0))
        return std::numeric_limits<double>::quiet_NaN();
      return std::clamp(sxy / std::sqrt(sxx * syy), -1.0, 1.0);
    }

    /** ρ with its Fisher-z 95 % interval for @p n samples (see the header). */
    IndexEstimate
    fisher_interval(const double rho, const std::size_t n)
    {
      IndexEstimate e;
      e.value = rho;
      if (!std::isfinite(rho))
        return e;
      if (std::abs(rho) >= 1)
        {
          e.ci95_low = e.ci95_high = rho; // z is infinite: no sampling spread is left
          return e;
        }
      const double z     = std::atanh(rho);
      const double se    = std::sqrt(1.06 / (static_cast<double>(n) - 3));
      const double z_975 = boost::math::quantile(boost::math::normal(), 0.975);
      e.ci95_low         = std::tanh(z - z_975 * se);
      e.ci95_high        = std::tanh(z + z_975 * se);
      return e;
    }
  } // namespace

  SensitivityResult
  rank_correlations(const std::vector<std::vector<double>> &inputs, const std::vector<double> &outputs)
  {
    if (inputs.size() != outputs.size())
      throw InputError("Rank correlations need one row of inputs per output; given " + std::to_string(inputs.size()) +
                       " rows and " + std::to_string(outputs.size()) + " outputs.");
    const std::size_t d = inputs.empty() ? 0 : inputs.front().size();
    SensitivityResult r;
    r.method = SensitivityMethod::rank_correlation;
    std::vector<std::vector<double>> columns(d);
    std::vector<double>              y;
    for (std::size_t k = 0; k < outputs.size(); ++k)
      {
        if (inputs[k].size() != d)
          throw InputError("Rank correlations need the same number of inputs in every row; row " + std::to_string(k) +
                           " has " + std::to_string(inputs[k].size()) + ", row 0 has " + std::to_string(d) + ".");
        if (!std::isfinite(outputs[k]))
          {
            ++r.dropped;
            continue;
          }
        y.push_back(outputs[k]);
        for (std::size_t i = 0; i < d; ++i)
          columns[i].push_back(inputs[k][i]);
      }
    if (y.size() < 4)
      throw InputError("Rank correlations with an interval need at least 4 evaluations with a finite output; " +
                       std::to_string(y.size()) + " have one.");
    r.samples         = y.size();
    r.output_mean     = std::accumulate(y.begin(), y.end(), 0.0) / static_cast<double>(y.size());
    r.output_variance = 0;
    for (const double v : y)
      r.output_variance += (v - r.output_mean) * (v - r.output_mean) / static_cast<double>(y.size());
    const auto ry = ranks(y);
    r.inputs.resize(d);
    for (std::size_t i = 0; i < d; ++i)
      r.inputs[i].rank_correlation = fisher_interval(pearson(ranks(columns[i]), ry), y.size());
    return r;
  }

  SensitivityResult
  analyse_sensitivity(const SaltelliDesign      &design,
                      const std::vector<double> &outputs,
                      const SensitivitySettings &settings)
  {
    if (outputs.size() != design.n_points())
      throw InputError("The Saltelli design has " + std::to_string(design.n_points()) + " points; given " +
                       std::to_string(outputs.size()) + " outputs.");
    if (design.n_base() >= settings.min_base_samples_for_indices)
      return sobol_indices(design.n_inputs(), outputs, settings);
    std::vector<std::vector<double>> x;
    std::vector<double>              y;
    const unsigned int               stride = design.n_inputs() + 2;
    for (std::uint64_t j = 0; j < design.n_base(); ++j)
      for (std::uint64_t part = 0; part < 2; ++part) // A_j, then B_j
        {
          x.push_back(design.point(j * stride + part));
          y.push_back(outputs[j * stride + part]);
        }
    return rank_correlations(x, y);
  }
} // namespace wearlink::analysis
