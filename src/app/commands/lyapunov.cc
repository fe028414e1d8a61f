// SPDX-License-Identifier: LGPL-2.1-or-later
// `wearlink lyapunov SERIES.csv --column NAME ...`: the largest Lyapunov exponent of one
// column of a CSV file by Wolf et al. 1985 or Rosenstein et al. 1993 (doc/models.md §6.4,
// analysis/lyapunov.h), with the delay and embedding dimension given or chosen by
// mutual information and false nearest neighbours (analysis/embedding.h). Prints the
// exponent with its units and the embedding used, and writes a convergence plot (PNG)
// with the plotted data (CSV) and a JSON summary, all atomically.
#include "analysis/lyapunov.h"

#include "app/command_line.h"
#include "app/output_claim.h"
#include "base/exceptions.h"
#include "io/output_names.h"
#include "workflows/run/lyapunov_series.h"

#include <iostream>
#include <optional>
#include <string>

namespace wearlink::app
{
  namespace
  {
    using namespace wearlink::analysis;


    const std::string lyapunov_help = R"(wearlink lyapunov SERIES.csv --column NAME [options]

Largest Lyapunov exponent (LLE) of one column of a CSV file (first row: column names,
comma-separated; lines starting with # are ignored).

Methods (--method):
  rosenstein  (default) Rosenstein, Collins & De Luca 1993: every reference point
              gets its nearest neighbour once; the mean over pairs of ln(separation
              after k samples) grows linearly with slope LLE until it saturates. The
              slope is fitted over a linear region chosen automatically ("straightest
              rise": the window where the local slope of the curve, smoothed over one
              orbit = 4 delays, varies by less than 20 % and the curve rises most); the
              region is printed and drawn. If the curve rises less than e-fold there is
              no exponential divergence and the fit spans the whole curve (LLE ~ 0).
              Neighbours of a sampled flow are followed between samples by linear
              interpolation (automatic; off for map-like series).
  wolf        Wolf, Swift, Swinney & Vastano 1985, fixed evolution time: follow one
              neighbour for E samples, add ln(d_E/d_0), replace it by a nearby point
              whose separation keeps the old orientation (smallest angle among the 64
              nearest points within 5 % of the attractor extent; angle limit 0.3 rad,
              widened if needed), repeat. LLE = sum / total evolution time. Needs dense
              data: about 1e5 samples for 10 % on the Lorenz attractor.

Options:
  --column NAME      the column to analyse (required)
  --method M         rosenstein | wolf (default rosenstein)
  --dt S             sample interval [s]. Without it, a column named t or time_s gives
                     dt (it must be uniformly sampled); with neither, the exponent is
                     per sample (= per iteration of a map).
  --delay K          delay tau [samples]; default: first minimum of the average mutual
                     information (averaged shifted histograms, 16 bins); if the mutual
                     information decays below 5 % of I(0) without a minimum (a map), 1.
  --embedding M      embedding dimension; default: false nearest neighbours (Kennel et
                     al. 1992, R_tol 15, A_tol 2): the first dimension with < 1 % false.
  --theiler W        Theiler window [samples]: neighbours must be more than W samples
                     apart in time; default m * tau.
  --evolution E      Wolf evolution time [samples]; default 6 tau.
  --horizon K        Rosenstein divergence horizon [samples]; default: until the curve
                     saturates (at most 256 tau).
  --output DIR       output directory (default: the current directory)

Output: the exponent in natural-log units, per second when dt is known (also per sample
and in bits), the delay, dimension and Theiler window with how they were chosen, and in
DIR: lyapunov_<column>_<method>.png (Wolf: running estimate vs evolution time;
Rosenstein: mean log divergence vs time with the fitted line), .csv (the plotted data)
and .json (the summary).
DIR is locked while the command runs (a second command into it is refused with the
first one's pid). Files of an earlier analysis are kept, and those of the same column
and method replaced (each name says what it holds, and DIR is often a run's folder).

Exit status: 0 success, 2 bad input (missing file, unknown column, NaN or too short
series, bad option value, DIR in use), 4 an output that cannot be written or memory
that ran out, 1 an internal error (see `wearlink --help`).
)" + io::outputs::listing(io::outputs::lyapunov(), false);

    /** A non-negative integer option (at least @p min), or unset. */
    template <class T>
    std::optional<T>
    integer_option(const ParsedArguments &args, const std::string &option, const long min)
    {
      if (!args.has(option))
        return std::nullopt;
      const std::string text = args.value(option);
      std::size_t       used = 0;
      long              v    = 0;
      try
        {
          v = std::stol(text, &used);
        }
      catch (const std::exception &)
        {
          used = 0;
        }
      if (text.empty() || used != text.size() || v < min)
        throw InputError("The option " + option + " needs a whole number >= " + std::to_string(min) + ", not '" + text +
                         "'.");
      return static_cast<T>(v);
    }

    int
    run_lyapunov(const std::vector<std::string> &argv)
    {
      const ParsedArguments args = parse_arguments(argv,
                                                   {{"--column", true},
                                                    {"--method", true},
                                                    {"--dt", true},
                                                    {"--delay", true},
                                                    {"--embedding", true},
                                                    {"--theiler", true},
                                                    {"--evolution", true},
                                                    {"--horizon", true},
                                                    {"--output", true}},
                                                   "lyapunov");
      if (args.positional.size() != 1)
        throw InputError("`wearlink lyapunov` needs exactly one series file (CSV), got " +
                         std::to_string(args.positional.size()) +
                         ". Usage: wearlink lyapunov SERIES.csv --column NAME (see --help).");
      const std::string file = args.positional[0];
      if (!args.has("--column"))
        throw InputError("`wearlink lyapunov` needs --column NAME: the column of '" + file + "' to analyse.");
      const std::string column = args.value("--column");

      LyapunovSettings  settings;
      const std::string method = args.value("--method", "rosenstein");
      if (const auto m = parse_method(method))
        settings.method = *m;
      else
        throw InputError("Unknown --method '" + method + "'. The methods are: rosenstein, wolf.");
      settings.embedding.delay          = integer_option<std::size_t>(args, "--delay", 1);
      settings.embedding.dimension      = integer_option<unsigned int>(args, "--embedding", 1);
      settings.embedding.theiler_window = integer_option<std::size_t>(args, "--theiler", 0);
      settings.wolf.evolution_steps     = integer_option<std::size_t>(args, "--evolution", 1);
      settings.rosenstein.horizon       = integer_option<std::size_t>(args, "--horizon", 2);
      if (settings.embedding.dimension && *settings.embedding.dimension > 64)
        throw InputError("The option --embedding must be at most 64.");
      if (args.has("--dt"))
        {
          const double dt = args.number("--dt", 0.0);
          if (!(dt > 0.0))
            throw InputError("The option --dt is the sample interval in seconds and must be > 0, not " +
                             args.value("--dt") + ".");
          settings.sample_interval = dt;
        }

      workflows::LyapunovSeriesRequest request;
      request.file             = file;
      request.column           = column;
      request.settings         = settings;
      request.output_directory = args.value("--output", ".");
      OutputClaim claim        = output_claim(request.output_directory, io::outputs::lyapunov(), args);
      claim.earlier            = EarlierRun::resume; // see the help: earlier files are kept
      const auto claimed       = claim_output_directory(claim);
      std::cout << workflows::analyse_lyapunov_series(request);
      return 0;
    }
  } // namespace

  extern const Command lyapunov_command;
  const Command        lyapunov_command = {
           "lyapunov",
           "lyapunov SERIES.csv --column NAME [--method wolf|rosenstein] [--dt S] [--embedding M] "
                  "[--delay K] [--output DIR]",
           lyapunov_help.c_str(),
           run_lyapunov};
} // namespace wearlink::app
