// SPDX-License-Identifier: LGPL-2.1-or-later
// `wearlink compare-signal SCENE.prm MEASURED.csv --channel NAME`: a simulated signal
// against a measured one (workflows/compare/signal_comparison.h): a printed table, an overlay
// and a spectrum PNG, signal_comparison.json.
#include "app/command_line.h"
#include "app/output_claim.h"
#include "base/exceptions.h"
#include "io/output_names.h"
#include "workflows/compare/signal_comparison.h"

#include <filesystem>
#include <iostream>

namespace wearlink::app
{
  namespace
  {
    const std::string compare_signal_help =
      std::string(
        R"(wearlink compare-signal SCENE.prm MEASURED.csv --channel NAME [--column NAME]
                        [--simulated RUN_DIR] [--output DIR] [--set S/E=V ...] [--quiet]

Compares a simulated signal with a measured one. MEASURED.csv has a header row with a
column 'time_s' (seconds, in the scene's time, strictly increasing) and a value column
(at least 16 rows, every field a finite number).
  --channel NAME      the simulated signal: a column of the time_series.csv a run of
                      the scene writes (e.g. slider9_ax_m_s2, A_normal_force_N; a wrong
                      name is refused with the list of columns)
  --column NAME       the measured file's value column, if it has more than one
  --simulated RUN_DIR read the simulated signal from RUN_DIR/time_series.csv of a
                      finished `wearlink run` of the same scene; without it, the scene
                      is run now into DIR/simulated/
  --output DIR        where to write (default: output/<scene name>_signal)
  --overwrite         replace the files of an earlier comparison in DIR
  --set S/E=V         scene overrides, as for `wearlink run`
  --quiet             no progress lines of the simulation

Both signals are resampled by linear interpolation onto one uniform grid: the time
interval both cover, at the finer of their median sample intervals. Then, for each:
the RMS and mean; the largest |value| in each whole driving cycle (the cycle is the
period of the scene's angle drivers; without one, the whole interval is one cycle);
the amplitude spectrum (FFTW; mean removed, Hann window, scaled so that a sine of
amplitude A reads A) and its three strongest peaks, refined between bins. For both:
the lag of the measured signal behind the simulated one from their cross-correlation
(FFTW, zero-padded, searched within half a cycle, refined between samples; a positive
lag means measured(t) = simulated(t - lag)).

Prints a table (simulated, measured, difference) and writes into DIR, atomically:
  signal_overlay.png      both signals on the grid, and the measured one shifted by -lag
  signal_spectrum.png     both amplitude spectra
  signal_comparison.json  'measured' and 'simulated' blocks: dominant_frequency_Hz,
                          dominant_frequencies_Hz, dominant_amplitudes, peak_per_cycle,
                          peak_per_cycle_mean, rms, mean, source, column; and lag_s,
                          correlation_at_lag, cycle_period_s, grid
Bad input (a missing file or column, a time that does not increase, a field that is
not a number, too few samples, no overlap with the simulated interval) is refused with
exit status 2 before anything is run or written.
)") + output_folder_help +
      io::outputs::listing(io::outputs::compare_signal());

    int
    compare_signal(const std::vector<std::string> &args)
    {
      const auto a = parse_arguments(args,
                                     {{"--channel", true},
                                      {"--column", true},
                                      {"--simulated", true},
                                      {"--output", true},
                                      {"--set", true, true},
                                      {"--quiet", false},
                                      {"--overwrite", false}},
                                     "compare-signal");
      if (a.positional.size() != 2)
        throw InputError("`wearlink compare-signal` needs a scene and a measured CSV file (given " +
                         std::to_string(a.positional.size()) + "). See `wearlink compare-signal --help`.");
      workflows::SignalComparisonOptions o;
      o.scene_file          = a.positional[0];
      o.measured_file       = a.positional[1];
      o.overrides           = a.all("--set");
      o.channel             = a.value("--channel");
      o.measured_column     = a.value("--column");
      o.simulated_directory = a.value("--simulated");
      o.output_directory =
        a.value("--output", "output/" + std::filesystem::path(o.scene_file).stem().string() + "_signal");
      o.progress         = !a.has("--quiet");
      const auto claimed = claim_output_directory(output_claim(o.output_directory, io::outputs::compare_signal(), a));
      const auto r       = workflows::compare_signal(o);
      std::cout << r.table << "files written:\n";
      for (const auto &f : r.files)
        std::cout << "  " << f << "\n";
      return 0;
    }
  } // namespace

  extern const Command compare_signal_command;
  const Command        compare_signal_command = {"compare-signal",
                                                 "compare-signal SCENE.prm MEASURED.csv --channel NAME  "
                                                        "simulated against measured signal: peaks, RMS, spectra, lag",
                                                 compare_signal_help.c_str(),
                                                 compare_signal};
} // namespace wearlink::app
