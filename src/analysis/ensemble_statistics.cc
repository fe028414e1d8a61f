// SPDX-License-Identifier: LGPL-2.1-or-later
#include "analysis/ensemble_statistics.h"

#include "base/numbers.h"

#include <algorithm>
#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <limits>
#include <random>

namespace wearlink::analysis
{
  double
  student_t_quantile(const double p, const double dof)
  {
    const boost::math::students_t distribution(dof);
    return boost::math::quantile(distribution, p);
  }

  EnsembleFigure
  ensemble_figure(const std::vector<double> &values)
  {
    using numbers::nan;
    EnsembleFigure f;
    double         sum = 0;
    for (const double v : values)
      if (std::isfinite(v))
        {
          sum += v;
          ++f.members;
        }
    if (f.members == 0)
      return {nan, nan, nan, nan, 0};
    f.mean = sum / f.members;
    if (f.members < 2)
      {
        f.std = f.ci95_low = f.ci95_high = nan;
        return f;
      }
    double squares = 0;
    for (const double v : values)
      if (std::isfinite(v))
        squares += (v - f.mean) * (v - f.mean);
    const double n    = static_cast<double>(f.members);
    f.std             = std::sqrt(squares / (n - 1));
    const double half = student_t_quantile(0.975, n - 1) * f.std / std::sqrt(n);
    f.ci95_low        = f.mean - half;
    f.ci95_high       = f.mean + half;
    return f;
  }

  std::map<std::string, EnsembleFigure>
  ensemble_figures(const std::vector<std::map<std::string, double>> &members)
  {
    std::map<std::string, std::vector<double>> values;
    for (const auto &m : members)
      for (const auto &[name, v] : m)
        values[name].push_back(v);
    std::map<std::string, EnsembleFigure> out;
    for (const auto &[name, v] : values)
      out[name] = ensemble_figure(v);
    return out;
  }

  double
  percentile(std::vector<double> values, const double p)
  {
    values.erase(std::remove_if(values.begin(), values.end(), [](const double v) { return !std::isfinite(v); }),
                 values.end());
    if (values.empty())
      return std::numeric_limits<double>::quiet_NaN();
    std::sort(values.begin(), values.end());
    const double      h     = (static_cast<double>(values.size()) - 1) * std::clamp(p, 0.0, 1.0);
    const std::size_t below = static_cast<std::size_t>(std::floor(h));
    if (below + 1 >= values.size())
      return values.back();
    return values[below] + (h - static_cast<double>(below)) * (values[below + 1] - values[below]);
  }

  std::vector<double>
  member_normals(const std::uint64_t seed, const unsigned int member, const unsigned int count)
  {
    std::seed_seq   sequence{static_cast<std::uint32_t>(seed & 0xffffffffu),
                           static_cast<std::uint32_t>(seed >> 32),
                           member};
    std::mt19937_64 engine(sequence);
    // Uniform on (0, 1]: the top 53 bits, shifted by one so that the logarithm is finite.
    const auto uniform = [&engine] {
      return ((engine() >> 11) + 1) * 0x1.0p-53;
    };
    std::vector<double> z;
    while (z.size() < count)
      {
        const double radius = std::sqrt(-2 * std::log(uniform()));
        const double angle  = 2 * numbers::pi * uniform();
        z.push_back(radius * std::cos(angle));
        if (z.size() < count)
          z.push_back(radius * std::sin(angle));
      }
    return z;
  }
} // namespace wearlink::analysis
