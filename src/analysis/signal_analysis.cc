// SPDX-License-Identifier: LGPL-2.1-or-later
#include "analysis/signal_analysis.h"

#include "base/exceptions.h"
#include "base/numbers.h"
#include "base/text.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <fftw3.h>
#include <numeric>

namespace wearlink::analysis
{
  namespace
  {
    /** An FFTW array (aligned as FFTW wants it), freed with fftw_free. */
    template <typename T>
    class FftwArray
    {
    public:
      explicit FftwArray(const std::size_t n)
        : data(static_cast<T *>(fftw_malloc(sizeof(T) * std::max<std::size_t>(n, 1))))
      {
        if (data == nullptr)
          throw std::bad_alloc();
      }
      ~FftwArray()
      {
        fftw_free(data);
      }
      FftwArray(const FftwArray &) = delete;
      FftwArray    &
      operator=(const FftwArray &) = delete;
      T *data;
    };

    /** An FFTW plan, executed once and destroyed. */
    class FftwPlan
    {
    public:
      explicit FftwPlan(fftw_plan p)
        : plan(p)
      {
      }
      ~FftwPlan()
      {
        fftw_destroy_plan(plan);
      }
      FftwPlan(const FftwPlan &) = delete;
      FftwPlan &
      operator=(const FftwPlan &) = delete;
      void
      execute() const
      {
        fftw_execute(plan);
      }

    private:
      fftw_plan plan;
    };

    /** The r2c transform (n/2 + 1 complex values) of @p x, zero-padded to @p n. */
    std::vector<std::complex<double>>
    forward_fft(const std::vector<double> &x, const std::size_t n)
    {
      FftwArray<double>       in(n);
      FftwArray<fftw_complex> out(n / 2 + 1);
      const FftwPlan          plan(fftw_plan_dft_r2c_1d(static_cast<int>(n), in.data, out.data, FFTW_ESTIMATE));
      std::fill(in.data, in.data + n, 0.0);
      std::copy(x.begin(), x.begin() + static_cast<std::ptrdiff_t>(std::min(n, x.size())), in.data);
      plan.execute();
      std::vector<std::complex<double>> y(n / 2 + 1);
      for (std::size_t k = 0; k < y.size(); ++k)
        y[k] = {out.data[k][0], out.data[k][1]};
      return y;
    }

    /** The c2r inverse (unnormalized) of the half spectrum @p y of a length-@p n signal. */
    std::vector<double>
    inverse_fft(const std::vector<std::complex<double>> &y, const std::size_t n)
    {
      FftwArray<fftw_complex> in(n / 2 + 1);
      FftwArray<double>       out(n);
      const FftwPlan          plan(fftw_plan_dft_c2r_1d(static_cast<int>(n), in.data, out.data, FFTW_ESTIMATE));
      for (std::size_t k = 0; k < y.size(); ++k)
        {
          in.data[k][0] = y[k].real();
          in.data[k][1] = y[k].imag();
        }
      plan.execute();
      return std::vector<double>(out.data, out.data + n);
    }

    double
    mean_of(const std::vector<double> &v)
    {
      return v.empty() ? 0.0 : std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
    }

    std::vector<double>
    without_mean(const std::vector<double> &v)
    {
      const double        m = mean_of(v);
      std::vector<double> out(v.size());
      std::transform(v.begin(), v.end(), out.begin(), [m](double x) { return x - m; });
      return out;
    }

    /** Offset in (−1, 1) of the vertex of the parabola through (−1, a), (0, b), (1, c). */
    double
    parabola_vertex(const double a, const double b, const double c)
    {
      const double d = a - 2 * b + c;
      return d < 0 ? std::clamp(0.5 * (a - c) / d, -1.0, 1.0) : 0.0;
    }

    /** The Hann window's amplitude response at @p delta bins off its centre, relative to 1. */
    double
    hann_response(const double delta)
    {
      const double d = std::abs(delta);
      if (d < 1e-9)
        return 1.0;
      return std::sin(numbers::pi * d) / (numbers::pi * d) / (1 - d * d);
    }

    double
    median_step(const std::vector<double> &time)
    {
      std::vector<double> steps(time.size() - 1);
      for (std::size_t i = 1; i < time.size(); ++i)
        steps[i - 1] = time[i] - time[i - 1];
      std::nth_element(steps.begin(), steps.begin() + static_cast<std::ptrdiff_t>(steps.size() / 2), steps.end());
      return steps[steps.size() / 2];
    }

    std::vector<double>
    peaks_per_cycle(const UniformSignal &s, const double period)
    {
      const std::size_t n = s.values.size();
      if (!(period > 0))
        return {std::abs(*std::max_element(s.values.begin(), s.values.end(), [](double a, double b) {
          return std::abs(a) < std::abs(b);
        }))};
      const double        span     = n * s.dt; // sample i stands for [t0 + i dt, t0 + (i+1) dt)
      const auto          n_cycles = static_cast<std::size_t>(std::floor(span / period + 1e-9));
      std::vector<double> peaks;
      for (std::size_t c = 0; c < n_cycles; ++c)
        {
          const auto first = static_cast<std::size_t>(std::ceil(c * period / s.dt - 1e-9));
          const auto last  = std::min(n, static_cast<std::size_t>(std::ceil((c + 1) * period / s.dt - 1e-9)));
          double     peak  = 0;
          for (std::size_t i = first; i < last; ++i)
            peak = std::max(peak, std::abs(s.values[i]));
          peaks.push_back(peak);
        }
      return peaks;
    }
  } // namespace

  UniformSignal
  resample_uniform(const std::vector<double> &time,
                   const std::vector<double> &values,
                   const double               t0,
                   const double               dt,
                   const std::size_t          n)
  {
    UniformSignal s{t0, dt, std::vector<double>(n)};
    std::size_t   j = 0;
    for (std::size_t i = 0; i < n; ++i)
      {
        const double t = t0 + i * dt;
        while (j + 2 < time.size() && time[j + 1] < t)
          ++j;
        const double w = std::clamp((t - time[j]) / (time[j + 1] - time[j]), 0.0, 1.0);
        s.values[i]    = (1 - w) * values[j] + w * values[j + 1];
      }
    return s;
  }

  void
  amplitude_spectrum(const UniformSignal &s, std::vector<double> &frequencies_Hz, std::vector<double> &amplitudes)
  {
    const std::size_t   n = s.values.size();
    std::vector<double> x = without_mean(s.values);
    for (std::size_t i = 0; i < n; ++i)
      x[i] *= 0.5 * (1 - std::cos(2 * numbers::pi * i / n)); // periodic Hann window, sum n/2
    const auto y = forward_fft(x, n);
    frequencies_Hz.resize(y.size());
    amplitudes.resize(y.size());
    for (std::size_t k = 0; k < y.size(); ++k)
      {
        const bool edge   = k == 0 || 2 * k == n; // no mirror image at 0 and Nyquist
        frequencies_Hz[k] = k / (n * s.dt);
        amplitudes[k]     = (edge ? 1.0 : 2.0) * std::abs(y[k]) / (0.5 * n);
      }
  }

  std::vector<SpectralPeak>
  dominant_peaks(const std::vector<double> &frequencies_Hz, const std::vector<double> &amplitudes, const unsigned int n)
  {
    std::vector<std::size_t> maxima;
    for (std::size_t k = 1; k + 1 < amplitudes.size(); ++k)
      if (amplitudes[k] > amplitudes[k - 1] && amplitudes[k] >= amplitudes[k + 1])
        maxima.push_back(k);
    std::sort(maxima.begin(), maxima.end(), [&](std::size_t a, std::size_t b) {
      return amplitudes[a] > amplitudes[b];
    });
    maxima.resize(std::min<std::size_t>(maxima.size(), n));
    const double              bin = frequencies_Hz.size() > 1 ? frequencies_Hz[1] : 0.0;
    std::vector<SpectralPeak> peaks;
    for (const auto k : maxima)
      {
        const double tiny  = 1e-300; // log of an exact zero
        const double delta = parabola_vertex(std::log(amplitudes[k - 1] + tiny),
                                             std::log(amplitudes[k] + tiny),
                                             std::log(amplitudes[k + 1] + tiny));
        peaks.push_back({frequencies_Hz[k] + delta * bin, amplitudes[k] / hann_response(delta)});
      }
    return peaks;
  }

  SignalFeatures
  signal_features(const UniformSignal &s, const SignalComparisonSettings &settings)
  {
    SignalFeatures f;
    f.mean           = mean_of(s.values);
    f.rms            = std::sqrt(std::inner_product(s.values.begin(), s.values.end(), s.values.begin(), 0.0) /
                      static_cast<double>(s.values.size()));
    f.peak_per_cycle = peaks_per_cycle(s, settings.cycle_period);
    amplitude_spectrum(s, f.frequencies_Hz, f.amplitudes);
    f.dominant = dominant_peaks(f.frequencies_Hz, f.amplitudes, settings.n_dominant);
    return f;
  }

  double
  cross_correlation_lag(const UniformSignal &simulated,
                        const UniformSignal &measured,
                        const double         max_lag,
                        double              &correlation)
  {
    const std::size_t n = std::min(simulated.values.size(), measured.values.size());
    const auto        a = without_mean(simulated.values);
    const auto        b = without_mean(measured.values);
    const std::size_t m = 2 * n; // zero padding: no circular wrap-around
    auto              A = forward_fft(a, m);
    const auto        B = forward_fft(b, m);
    for (std::size_t k = 0; k < A.size(); ++k)
      A[k] = std::conj(A[k]) * B[k];
    const auto r  = inverse_fft(A, m); // r[k] = m × Σ a[i] b[i+k], negative k at m − |k|
    const auto at = [&](long k) {
      return r[static_cast<std::size_t>(k >= 0 ? k : static_cast<long>(m) + k)];
    };
    const long limit  = std::min(static_cast<long>(n) - 1, static_cast<long>(std::floor(max_lag / simulated.dt)));
    long       best_k = 0;
    for (long k = -limit; k <= limit; ++k)
      if (at(k) > at(best_k))
        best_k = k;
    double delta = 0;
    if (best_k > -limit && best_k < limit)
      delta = parabola_vertex(at(best_k - 1), at(best_k), at(best_k + 1));
    const double energy = std::sqrt(std::inner_product(a.begin(), a.end(), a.begin(), 0.0) *
                                    std::inner_product(b.begin(), b.end(), b.begin(), 0.0));
    correlation         = energy > 0 ? at(best_k) / static_cast<double>(m) / energy : 0.0;
    return (static_cast<double>(best_k) + delta) * simulated.dt;
  }

  SignalComparison
  compare_signals(const std::vector<double>      &simulated_time,
                  const std::vector<double>      &simulated_values,
                  const std::vector<double>      &measured_time,
                  const std::vector<double>      &measured_values,
                  const SignalComparisonSettings &settings)
  {
    const double t0           = std::max(simulated_time.front(), measured_time.front());
    const double t1           = std::min(simulated_time.back(), measured_time.back());
    const double dt           = std::min(median_step(simulated_time), median_step(measured_time));
    const double span_samples = (t1 - t0) / dt;
    if (!(span_samples + 1 >= static_cast<double>(min_comparison_samples)))
      throw EstimationError("The simulated signal (" + format_number(simulated_time.front(), 6) + " to " +
                            format_number(simulated_time.back(), 6) + " s) and the measured one (" +
                            format_number(measured_time.front(), 6) + " to " + format_number(measured_time.back(), 6) +
                            " s) overlap in fewer than " + std::to_string(min_comparison_samples) + " samples of " +
                            format_number(dt, 6) + " s: give a measured file that covers the simulated interval.");
    const auto       n = static_cast<std::size_t>(std::floor(span_samples + 1e-9)) + 1;
    SignalComparison c;
    c.simulated          = resample_uniform(simulated_time, simulated_values, t0, dt, n);
    c.measured           = resample_uniform(measured_time, measured_values, t0, dt, n);
    c.simulated_features = signal_features(c.simulated, settings);
    c.measured_features  = signal_features(c.measured, settings);
    const double max_lag = settings.max_lag > 0      ? settings.max_lag :
                           settings.cycle_period > 0 ? 0.5 * settings.cycle_period :
                                                       0.25 * (n - 1) * dt;
    c.lag                = cross_correlation_lag(c.simulated, c.measured, max_lag, c.correlation);
    return c;
  }
} // namespace wearlink::analysis
