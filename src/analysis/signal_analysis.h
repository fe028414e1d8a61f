// SPDX-License-Identifier: LGPL-2.1-or-later
// Comparing a simulated signal with a measured one (`wearlink compare-signal`): both
// are resampled onto one uniform grid, then each gets its RMS, its peak in every
// driving cycle, its amplitude spectrum and dominant frequencies; the two together their
// cross-correlation lag. Pure functions on vectors; the FFTs are FFTW3's.
//
// The common grid: the time interval both signals cover, [max(t0), min(t1)], sampled at
// the finer of the two median sample intervals (linear interpolation between samples).
//
// The spectrum: the mean is removed, a Hann window applied, the one-sided amplitude
// spectrum scaled so that a sine of amplitude A at a bin's frequency reads A. A
// dominant frequency is a local maximum of the spectrum, refined between bins by a
// parabola through the logarithms of the three amplitudes around it (exact for a
// Gaussian peak, within a few hundredths of a bin for the Hann window's); its amplitude
// is corrected for the Hann window's response at that offset from the bin.
//
// The lag: the cross-correlation r(k) = Σ s[n] m[n+k] of the mean-free signals (by
// FFT, zero-padded so nothing wraps), its largest value within ±max_lag, refined by a
// parabola. A positive lag means the measured signal m comes later than the simulated s:
// m(t) ≈ s(t − lag).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace wearlink::analysis
{
  /** A signal sampled uniformly: values[i] at t0 + i dt. */
  struct UniformSignal
  {
    double              t0 = 0, dt = 0;
    std::vector<double> values;
  };

  /** One peak of an amplitude spectrum. */
  struct SpectralPeak
  {
    double frequency_Hz = 0;
    double amplitude    = 0; ///< in the signal's unit
  };

  /** What one signal shows on the common grid. */
  struct SignalFeatures
  {
    double mean = 0;
    /** Root mean square of the signal (with its mean). */
    double rms = 0;
    /** Largest |value| in each whole driving cycle from the grid's start (none if shorter). */
    std::vector<double> peak_per_cycle;
    /** The strongest spectral peaks, strongest first. */
    std::vector<SpectralPeak> dominant;
    /** The one-sided amplitude spectrum: frequencies [Hz] and amplitudes. */
    std::vector<double> frequencies_Hz, amplitudes;
  };

  struct SignalComparisonSettings
  {
    /** Driving cycle [s] for the peaks per cycle; 0: the whole interval is one cycle. */
    double cycle_period = 0;
    /** How many dominant frequencies to report. */
    unsigned int n_dominant = 3;
    /** Largest lag searched [s]; 0: half the cycle period, or a quarter of the interval. */
    double max_lag = 0;
  };

  struct SignalComparison
  {
    UniformSignal  measured, simulated; ///< on the common grid
    SignalFeatures measured_features, simulated_features;
    /** Lag of the measured signal behind the simulated one [s]. */
    double lag = 0;
    /** Normalized cross-correlation at that lag (1: identical shapes). */
    double correlation = 0;
  };

  /**
   * Resample (@p time, @p values) onto t0 + i dt, i < n, by linear interpolation. The
   * time must increase strictly and cover [t0, t0 + (n−1) dt].
   */
  UniformSignal
  resample_uniform(const std::vector<double> &time,
                   const std::vector<double> &values,
                   double                     t0,
                   double                     dt,
                   std::size_t                n);

  /** The one-sided amplitude spectrum of @p s (mean removed, Hann window). */
  void
  amplitude_spectrum(const UniformSignal &s, std::vector<double> &frequencies_Hz, std::vector<double> &amplitudes);

  /** The @p n strongest local maxima of a spectrum, refined between bins. */
  std::vector<SpectralPeak>
  dominant_peaks(const std::vector<double> &frequencies_Hz, const std::vector<double> &amplitudes, unsigned int n);

  /** RMS, peaks per cycle, spectrum and dominant frequencies of @p s. */
  SignalFeatures
  signal_features(const UniformSignal &s, const SignalComparisonSettings &settings);

  /**
   * The lag [s] of @p measured behind @p simulated (same grid), searched within
   * ±@p max_lag; @p correlation receives the normalized cross-correlation there.
   */
  double
  cross_correlation_lag(const UniformSignal &simulated,
                        const UniformSignal &measured,
                        double               max_lag,
                        double              &correlation);

  /**
   * Both signals on their common grid, their features and the lag. Throws
   * EstimationError if they overlap in fewer than 16 grid samples.
   */
  SignalComparison
  compare_signals(const std::vector<double>      &simulated_time,
                  const std::vector<double>      &simulated_values,
                  const std::vector<double>      &measured_time,
                  const std::vector<double>      &measured_values,
                  const SignalComparisonSettings &settings);

  /** Fewest samples of the common grid a comparison accepts. */
  inline constexpr std::size_t min_comparison_samples = 16;
} // namespace wearlink::analysis
