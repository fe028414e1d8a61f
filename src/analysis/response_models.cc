// SPDX-License-Identifier: LGPL-2.1-or-later
#include "analysis/response_models.h"

#include "analysis/ensemble_statistics.h"
#include "base/numbers.h"

#include <Eigen/Dense>

#include <algorithm>
#include <boost/math/distributions/fisher_f.hpp>
#include <boost/math/distributions/normal.hpp>
#include <cmath>

namespace wearlink::analysis
{
  namespace
  {
    using numbers::nan;
    constexpr double unbounded = std::numeric_limits<double>::infinity();

    /** Change points spread over a gap between measurements (its ends included). */
    constexpr int samples_per_gap = 9;

    /** The roots r₋ ≤ r₊ of A r² − 2 B r + C = 0 for A > 0 (NaN if there are none). */
    Interval
    positive_roots(const double a, const double b, const double c)
    {
      const double discriminant = b * b - a * c;
      if (!(a > 0) || !(discriminant >= 0))
        return {};
      const double root = std::sqrt(discriminant);
      return {(b - root) / a, (b + root) / a};
    }

    /**
     * The hull of {v in [lo, hi] : A v² − 2 B v + C ≤ 0} (hi may be +∞); NaN if empty,
     * high = +∞ where the set is unbounded above. The set's pieces end at lo, hi or a root,
     * so testing those and the middles between them finds it.
     */
    Interval
    quadratic_set(const double a, const double b, const double c, const double lo, const double hi)
    {
      const auto inside = [&](const double v) {
        return a * v * v - 2 * b * v + c <= 1e-12 * (std::abs(c) + std::abs(b * v) + std::abs(a * v * v));
      };
      std::vector<double> cuts         = {lo};
      const double        discriminant = b * b - a * c;
      if (a != 0 && discriminant >= 0)
        for (const double r : {(b - std::sqrt(discriminant)) / a, (b + std::sqrt(discriminant)) / a})
          if (r > lo && r < hi)
            cuts.push_back(r);
      if (a == 0 && b != 0 && c / (2 * b) > lo && c / (2 * b) < hi)
        cuts.push_back(c / (2 * b));
      std::sort(cuts.begin(), cuts.end());
      Interval   hull{unbounded, -unbounded};
      const auto take = [&hull](const double v) {
        hull.low  = std::min(hull.low, v);
        hull.high = std::max(hull.high, v);
      };
      for (std::size_t i = 0; i < cuts.size(); ++i)
        {
          if (inside(cuts[i]))
            take(cuts[i]);
          // No root inside the piece up to the next cut: one point of it tells the whole.
          const double next  = i + 1 < cuts.size() ? cuts[i + 1] : hi;
          const double probe = std::isfinite(next) ? 0.5 * (cuts[i] + next) : cuts[i] + 1 + 2 * std::abs(cuts[i]);
          if (next > cuts[i] && inside(probe))
            {
              take(cuts[i]);
              take(next);
            }
        }
      if (std::isfinite(hi) && inside(hi))
        take(hi);
      if (!(hull.low <= hull.high))
        return {};
      return hull;
    }

    /** The least-squares coefficients of @p y on the columns of @p design; empty if rank deficient. */
    Eigen::VectorXd
    least_squares(const Eigen::MatrixXd &design, const Eigen::VectorXd &y)
    {
      const auto qr = design.colPivHouseholderQr();
      if (qr.rank() < design.cols())
        return {};
      return qr.solve(y);
    }

    /** A model of @p family at the change points @p tau1, @p tau2 fitted to (@p x, @p y). */
    TrendModel
    model_at(const TrendFamily          family,
             const double               tau1,
             const double               tau2,
             const std::vector<double> &x,
             const std::vector<double> &y,
             const unsigned int         parameters)
    {
      TrendModel m;
      m.family     = family;
      m.tau1       = tau1;
      m.tau2       = tau2;
      m.parameters = parameters;
      std::vector<double> w(x.size());
      for (std::size_t i = 0; i < x.size(); ++i)
        w[i] = m.regressor(x[i]);
      m.fit          = fit_regressor(w, y);
      const double n = static_cast<double>(x.size());
      m.bic          = n * std::log(m.fit.rss / n) + parameters * std::log(n);
      return m;
    }

    /** RSS with NaN (no fit) as +∞, for comparisons. */
    double
    rss_of(const TrendModel &m)
    {
      return std::isfinite(m.fit.rss) ? m.fit.rss : unbounded;
    }

    /** The better of @p a and @p b (the smaller RSS). */
    const TrendModel &
    better_fit(const TrendModel &a, const TrendModel &b)
    {
      return rss_of(b) < rss_of(a) ? b : a;
    }

    /**
     * The ramp with its rise starting at @p tau1 and ending in the gap [x_k, x_k+1] that
     * fits best: the linear model a (before), a + c (N − τ₁) (rise), d (plateau) with
     * τ₂ = τ₁ + (d − a)/c, if that lies in the gap, else an end of the gap.
     */
    TrendModel
    ramp_with_start(const std::vector<double> &x, const std::vector<double> &y, const double tau1, const std::size_t k)
    {
      const auto      n      = static_cast<Eigen::Index>(x.size());
      Eigen::MatrixXd design = Eigen::MatrixXd::Zero(n, 3);
      for (Eigen::Index i = 0; i < n; ++i)
        if (static_cast<std::size_t>(i) > k)
          design(i, 2) = 1;
        else
          {
            design(i, 0) = 1;
            design(i, 1) = std::max(x[i] - tau1, 0.0);
          }
      TrendModel best         = better_fit(model_at(TrendFamily::ramp, tau1, x[k], x, y, 4),
                                   model_at(TrendFamily::ramp, tau1, x[k + 1], x, y, 4));
      const auto coefficients = least_squares(design, Eigen::Map<const Eigen::VectorXd>(y.data(), n));
      if (coefficients.size() == 3 && coefficients[1] != 0)
        {
          const double tau2 = tau1 + (coefficients[2] - coefficients[0]) / coefficients[1];
          if (tau2 > x[k] && tau2 < x[k + 1])
            best = better_fit(best, model_at(TrendFamily::ramp, tau1, tau2, x, y, 4));
        }
      return best;
    }

    /**
     * The ramp with its rise ending at @p tau2 and starting in the gap [x_j, x_j+1] that
     * fits best: a (before), e + c N (rise), e + c τ₂ (plateau), τ₁ = (a − e)/c.
     */
    TrendModel
    ramp_with_end(const std::vector<double> &x, const std::vector<double> &y, const double tau2, const std::size_t j)
    {
      const auto      n      = static_cast<Eigen::Index>(x.size());
      Eigen::MatrixXd design = Eigen::MatrixXd::Zero(n, 3);
      for (Eigen::Index i = 0; i < n; ++i)
        if (static_cast<std::size_t>(i) <= j)
          design(i, 0) = 1;
        else
          {
            design(i, 1) = 1;
            design(i, 2) = std::min(x[i], tau2);
          }
      TrendModel best         = better_fit(model_at(TrendFamily::ramp, x[j], tau2, x, y, 4),
                                   model_at(TrendFamily::ramp, x[j + 1], tau2, x, y, 4));
      const auto coefficients = least_squares(design, Eigen::Map<const Eigen::VectorXd>(y.data(), n));
      if (coefficients.size() == 3 && coefficients[2] != 0)
        {
          const double tau1 = (coefficients[0] - coefficients[1]) / coefficients[2];
          if (tau1 > x[j] && tau1 < x[j + 1])
            best = better_fit(best, model_at(TrendFamily::ramp, tau1, tau2, x, y, 4));
        }
      return best;
    }

    /**
     * The best ramp with τ₁ in the gap [x_j, x_j+1] and τ₂ in [x_k, x_k+1], j < k: the
     * unconstrained fit (the mean before, a line on the rise, the mean after) if its change
     * points lie in their gaps, else the best on a face of the gaps (see the file comment).
     */
    TrendModel
    best_ramp_in(const std::vector<double> &x, const std::vector<double> &y, const std::size_t j, const std::size_t k)
    {
      TrendModel best = better_fit(better_fit(ramp_with_start(x, y, x[j], k), ramp_with_start(x, y, x[j + 1], k)),
                                   better_fit(ramp_with_end(x, y, x[k], j), ramp_with_end(x, y, x[k + 1], j)));
      if (k - j < 2)
        return best; // one measurement on the rise: no line of its own
      double before = 0, after = 0;
      for (std::size_t i = 0; i <= j; ++i)
        before += y[i] / static_cast<double>(j + 1);
      for (std::size_t i = k + 1; i < x.size(); ++i)
        after += y[i] / static_cast<double>(x.size() - k - 1);
      const std::vector<double> x_rise(x.begin() + j + 1, x.begin() + k + 1),
        y_rise(y.begin() + j + 1, y.begin() + k + 1);
      const auto rise = fit_regressor(x_rise, y_rise);
      if (!std::isfinite(rise.beta) || rise.beta == 0)
        return best;
      const double tau1 = (before - rise.a) / rise.beta, tau2 = (after - rise.a) / rise.beta;
      if (tau1 > x[j] && tau1 < x[j + 1] && tau2 > x[k] && tau2 < x[k + 1])
        best = better_fit(best, model_at(TrendFamily::ramp, tau1, tau2, x, y, 4));
      return best;
    }

    /** @p count points spread over [lo, hi], its ends included. */
    std::vector<double>
    spread_over_gap(const double lo, const double hi, const int count)
    {
      std::vector<double> v(count);
      for (int i = 0; i < count; ++i)
        v[i] = lo + (hi - lo) * i / (count - 1.0);
      return v;
    }
  } // namespace

  bool
  Interval::bounded() const
  {
    return std::isfinite(low) && std::isfinite(high);
  }

  Interval
  RegressorFit::excess(const double w, const double l, const double k) const
  {
    if (!(k >= 0) || !(sww > 0))
      return {};
    const double g    = beta * w - l * a;
    const double half = std::sqrt(k * (l * l / static_cast<double>(n) + std::pow(w + l * w_mean, 2) / sww));
    return {g - half, g + half};
  }

  // Fieller: the ρ with (β w − ρ a)² ≤ k (ρ²/n + (w + ρ w̄)²/Sww) lie between the roots of
  // A ρ² − 2 B ρ + C with A = a² − k (1/n + w̄²/Sww), B = w (a β + k w̄/Sww),
  // C = w² (β² − k/Sww) — bounded if A > 0 (a significant).
  Interval
  RegressorFit::ratio(const double w, const double k) const
  {
    if (!(k >= 0) || !(sww > 0))
      return {};
    const double nn = static_cast<double>(n);
    return positive_roots(a * a - k * (1 / nn + w_mean * w_mean / sww),
                          w * (a * beta + k * w_mean / sww),
                          w * w * (beta * beta - k / sww));
  }

  // The w with (β w − ℓ a)² ≤ k (ℓ²/n + (w + ℓ w̄)²/Sww): A w² − 2 B w + C ≤ 0 with
  // A = β² − k/Sww, B = ℓ (a β + k w̄/Sww), C = ℓ² (a² − k (1/n + w̄²/Sww)).
  Interval
  RegressorFit::crossing(const double l, const double k, const double w_low, const double w_high) const
  {
    if (!(k >= 0) || !(sww > 0))
      return {};
    const double nn = static_cast<double>(n);
    return quadratic_set(beta * beta - k / sww,
                         l * (a * beta + k * w_mean / sww),
                         l * l * (a * a - k * (1 / nn + w_mean * w_mean / sww)),
                         w_low,
                         w_high);
  }

  RegressorFit
  fit_regressor(const std::vector<double> &w, const std::vector<double> &y)
  {
    RegressorFit f;
    f.n = std::min(w.size(), y.size());
    if (f.n == 0)
      return f;
    const double n      = static_cast<double>(f.n);
    double       w_mean = 0, y_mean = 0, swy = 0, sww = 0;
    for (std::size_t i = 0; i < f.n; ++i)
      {
        w_mean += w[i] / n;
        y_mean += y[i] / n;
      }
    for (std::size_t i = 0; i < f.n; ++i)
      {
        sww += (w[i] - w_mean) * (w[i] - w_mean);
        swy += (w[i] - w_mean) * (y[i] - y_mean);
      }
    f.w_mean = w_mean;
    f.sww    = sww;
    f.beta   = f.n >= 2 && sww > 0 ? swy / sww : 0.0;
    f.a      = y_mean - f.beta * w_mean;
    if (!(sww > 0))
      return f;
    f.rss = 0;
    for (std::size_t i = 0; i < f.n; ++i)
      f.rss += std::pow(y[i] - f.a - f.beta * w[i], 2);
    return f;
  }

  std::string
  family_name(const TrendFamily family)
  {
    switch (family)
      {
        case TrendFamily::line:
          return "line";
        case TrendFamily::step:
          return "step";
        case TrendFamily::ramp:
          return "ramp";
      }
    return "";
  }

  double
  TrendModel::regressor(const double revolutions) const
  {
    switch (family)
      {
        case TrendFamily::line:
          return revolutions;
        case TrendFamily::step:
          return revolutions > 0.5 * (tau1 + tau2) ? 1.0 : 0.0;
        case TrendFamily::ramp:
          return std::clamp(revolutions - tau1, 0.0, tau2 - tau1);
      }
    return nan;
  }

  double
  TrendModel::value(const double revolutions) const
  {
    return fit.a + fit.beta * regressor(revolutions);
  }

  double
  TrendModel::rise(const double revolutions) const
  {
    if (fit.n < 2)
      return 0;
    return 100 * fit.beta * regressor(revolutions) / fit.a;
  }

  double
  TrendModel::crossing(const double limit) const
  {
    const double l = limit / 100;
    if (!(fit.beta > 0) || !(fit.a > 0))
      return nan;
    switch (family)
      {
        case TrendFamily::line:
          return l * fit.a / fit.beta;
        case TrendFamily::step:
          return fit.beta >= l * fit.a ? 0.5 * (tau1 + tau2) : nan;
        case TrendFamily::ramp:
          return l * fit.a / fit.beta <= tau2 - tau1 ? tau1 + l * fit.a / fit.beta : nan;
      }
    return nan;
  }
} // namespace wearlink::analysis

namespace wearlink::analysis
{
  namespace
  {
    /** The 95 % point of χ²₁ (= z(0.975)²). */
    double
    chi_squared_95()
    {
      const double z = boost::math::quantile(boost::math::normal(), 0.975);
      return z * z;
    }

    /**
     * The 95 % point c of the likelihood ratio of a small jump's position: twice the
     * largest value of a two-sided random walk with drift, P(≤ c) = (1 − e^(−c/2))² (see
     * the file comment): 7.35.
     */
    double
    jump_position_95()
    {
      return -2 * std::log(1 - std::sqrt(0.95));
    }

    /** The best ramp with its change points in the gaps after measurements j and k. */
    struct RampPair
    {
      std::size_t j = 0, k = 0;
      TrendModel  best;
    };

    /**
     * The best ramp of each pair of gaps whose best leaves room (RSS − @p rss_min ≤ @p room)
     * and the ramps at samples_per_gap² change points spread over the pair.
     */
    std::vector<TrendModel>
    sampled_ramps(const std::vector<double>   &x,
                  const std::vector<double>   &y,
                  const std::vector<RampPair> &pairs,
                  const double                 rss_min,
                  const double                 room)
    {
      std::vector<TrendModel> out;
      for (const auto &p : pairs)
        {
          if (!(rss_of(p.best) - rss_min <= room))
            continue;
          out.push_back(p.best);
          for (const double tau1 : spread_over_gap(x[p.j], x[p.j + 1], samples_per_gap))
            for (const double tau2 : spread_over_gap(x[p.k], x[p.k + 1], samples_per_gap))
              if (tau2 > tau1)
                out.push_back(model_at(TrendFamily::ramp, tau1, tau2, x, y, 4));
        }
      return out;
    }

    /** The position of @p family in ResponseModels' lists. */
    std::size_t
    index_of(const TrendFamily family)
    {
      return static_cast<std::size_t>(family);
    }
  } // namespace

  ResponseModels::ResponseModels(const std::vector<double> &revolutions,
                                 const std::vector<double> &measures,
                                 const std::size_t          count)
  {
    std::vector<std::pair<double, double>> rows;
    for (std::size_t k = 0; k < count && k < measures.size() && k < revolutions.size(); ++k)
      if (std::isfinite(measures[k]) &&
          std::none_of(rows.begin(), rows.end(), [&](const auto &r) { return r.first == revolutions[k]; }))
        rows.emplace_back(revolutions[k], measures[k]);
    std::stable_sort(rows.begin(), rows.end(), [](const auto &a, const auto &b) { return a.first < b.first; });
    for (const auto &[revs, measure] : rows)
      {
        x.push_back(revs);
        y.push_back(measure);
      }
    const std::size_t n = x.size();
    fitted.push_back(model_at(TrendFamily::line, nan, nan, x, y, 2));
    candidates.push_back({fitted.back()});
    if (n < 5)
      return;
    candidates.emplace_back();
    for (std::size_t k = 0; k + 3 <= n; ++k) // at least two measurements after the jump
      candidates.back().push_back(model_at(TrendFamily::step, x[k], x[k + 1], x, y, 3));
    fitted.push_back(candidates.back().front());
    for (const auto &m : candidates.back())
      fitted.back() = better_fit(fitted.back(), m);
    if (n < 6)
      return;
    std::vector<RampPair> pairs;
    for (std::size_t j = 0; j + 4 <= n; ++j)
      for (std::size_t k = j + 1; k + 3 <= n; ++k)
        pairs.push_back({j, k, best_ramp_in(x, y, j, k)});
    fitted.push_back(pairs.front().best);
    for (const auto &p : pairs)
      fitted.back() = better_fit(fitted.back(), p.best);
    candidates.push_back(sampled_ramps(x, y, pairs, fitted.back().fit.rss, crossing_critical(TrendFamily::ramp)));
  }

  bool
  ResponseModels::has(const TrendFamily family) const
  {
    return index_of(family) < fitted.size();
  }

  const TrendModel &
  ResponseModels::model(const TrendFamily family) const
  {
    return fitted.at(index_of(family));
  }

  TrendFamily
  ResponseModels::chosen() const
  {
    TrendFamily best = TrendFamily::line;
    for (const auto &m : fitted)
      if (m.bic < model(best).bic)
        best = m.family;
    return best;
  }

  double
  ResponseModels::weight(const TrendFamily family) const
  {
    if (!has(family))
      return 0;
    const double best = model(chosen()).bic;
    double       sum  = 0;
    for (const auto &m : fitted)
      sum += std::exp(-0.5 * (m.bic - best));
    return std::exp(-0.5 * (model(family).bic - best)) / sum;
  }

  double
  ResponseModels::residual_std(const TrendFamily family) const
  {
    const auto  &m   = model(family);
    const double dof = static_cast<double>(m.fit.n) - m.parameters;
    return dof > 0 ? std::sqrt(m.fit.rss / dof) : nan;
  }

  double
  ResponseModels::critical(const TrendFamily family) const
  {
    const auto  &m   = model(family);
    const double dof = static_cast<double>(m.fit.n) - m.parameters;
    if (!(dof >= 1))
      return nan;
    const double t = student_t_quantile(0.975, dof);
    return t * t * m.fit.rss / dof;
  }

  double
  ResponseModels::crossing_critical(const TrendFamily family) const
  {
    const auto  &m   = model(family);
    const double dof = static_cast<double>(m.fit.n) - m.parameters;
    if (family == TrendFamily::step)
      return critical(family) * jump_position_95() / chi_squared_95();
    if (family == TrendFamily::ramp && dof >= 1)
      return 2 * boost::math::quantile(boost::math::fisher_f(2, dof), 0.95) * m.fit.rss / dof;
    return critical(family);
  }

  std::vector<ResponseModels::Admitted>
  ResponseModels::admitted(const TrendFamily family, const double critical) const
  {
    std::vector<Admitted> out;
    if (!has(family) || !std::isfinite(critical))
      return out;
    const double rss_min = model(family).fit.rss;
    for (const auto &m : candidates[index_of(family)])
      {
        const double room = critical - (m.fit.rss - rss_min);
        if (room >= 0)
          out.push_back({m, room});
      }
    return out;
  }

  Interval
  ResponseModels::rise_interval(const TrendFamily family, const double revolutions) const
  {
    Interval hull{unbounded, -unbounded};
    for (const auto &[m, room] : admitted(family, critical(family)))
      {
        const auto r = m.fit.ratio(m.regressor(revolutions), room);
        if (!r.bounded())
          return {};
        hull = {std::min(hull.low, 100 * r.low), std::max(hull.high, 100 * r.high)};
      }
    return hull.low <= hull.high ? hull : Interval();
  }

  Interval
  ResponseModels::excess_band(const TrendFamily family, const double revolutions, const double limit) const
  {
    Interval band{unbounded, -unbounded};
    for (const auto &[m, room] : admitted(family, critical(family)))
      {
        const auto g = m.fit.excess(m.regressor(revolutions), limit / 100, room);
        if (!g.bounded())
          return {};
        band = {std::min(band.low, g.low), std::max(band.high, g.high)};
      }
    return band.low <= band.high ? band : Interval();
  }

  Interval
  ResponseModels::crossing_interval(const TrendFamily family, const double limit) const
  {
    const double l = limit / 100;
    Interval     hull{unbounded, -unbounded};
    const auto   take = [&hull](const double low, const double high) {
      hull = {std::min(hull.low, low), std::max(hull.high, high)};
    };
    for (const auto &[m, room] : admitted(family, crossing_critical(family)))
      if (family == TrendFamily::step)
        {
          if (m.fit.excess(1, l, room).high >= 0) // its jump can reach the limit
            take(m.tau1, m.tau2);
        }
      else
        {
          const double start = family == TrendFamily::ramp ? m.tau1 : 0.0;
          const double width = family == TrendFamily::ramp ? m.tau2 - m.tau1 : unbounded;
          const auto   w     = m.fit.crossing(l, room, 0, width);
          if (std::isfinite(w.low))
            take(start + w.low, start + w.high);
        }
    if (!(hull.low <= hull.high) || !std::isfinite(hull.high))
      return {};
    return hull;
  }
} // namespace wearlink::analysis
