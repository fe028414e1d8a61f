// SPDX-License-Identifier: LGPL-2.1-or-later
// `wearlink compare-dynamics BEFORE_DIR AFTER_DIR`: the before/after-wear comparison of
// workflows/compare/dynamics_comparison.h for two runs recorded earlier (each a `wearlink run` output
// directory with analyses), e.g. a clearance scene run once with fresh and once with
// worn profile files. A wear scene with analyses does the same by itself.
#include "analysis/analyses_parameters.h"
#include "app/command_line.h"
#include "app/output_claim.h"
#include "base/exceptions.h"
#include "base/text.h"
#include "io/json_file.h"
#include "io/output_names.h"
#include "io/recorded_run_files.h"
#include "workflows/compare/dynamics_comparison.h"
#include "workflows/run/analyses.h"

#include <algorithm>
#include <iostream>

namespace wearlink::app
{
  namespace
  {
    const std::string compare_dynamics_help =
      std::string(
        R"(wearlink compare-dynamics BEFORE_DIR AFTER_DIR [--output DIR] [--overwrite] [--delay S] [--embedding M]
        [--methods wolf,rosenstein] [--directions x,y] [--scan S1,S2,...] [--bodies B1,B2]
        [--published "A_ex_m: 0.041 0.076, ..."] [--published-note TEXT]

Compares two runs of the same mechanism recorded by `wearlink run` with analyses
(Analyses/List of analyses with lyapunov and/or phase-portrait, poincare), typically
before and after wear. A wear scene that lists analyses does this by itself at the end
of the wear loop; this command serves runs made separately (doc/tutorials/nonlinear_dynamics.md).

Writes into DIR (default output/compare_dynamics), each file atomically:
  before_after_phase_<J>_<x|y>.png  phase portraits before | after on the same axes,
                                    Poincaré points in red
  before_after_lyapunov.csv         largest Lyapunov exponents (1/s, natural log) of
                                    <J>_e<x|y>_m at ONE embedding for both runs
  before_after_delay_scan.csv/.png  the same at the delays of --scan
  before_after.md                   the tables, also printed: impacts per period,
                                    contact fraction, peak force, Poincaré spread,
                                    peak accelerations of --bodies, exponents
)") + output_folder_help +
      R"(
  --overwrite        replace the files of an earlier comparison in DIR
  --delay S          common embedding delay [s] (default 0.005; 0: the before run's
                     mutual-information choice). Exponents of these series fall
                     roughly like 1/delay, so only equal delays are comparable.
  --embedding M      common embedding dimension (default 0: false nearest neighbours
                     on the before run)
  --methods LIST     wolf, rosenstein (default both)
  --directions LIST  x, y (default x, the seed's)
  --scan LIST        delays of the scan [s] (default 0.002,0.005,0.01,0.02,0.05;
                     "none": no scan)
  --bodies LIST      bodies whose peak accelerations are compared (from summary.json)
  --published TEXT   published exponents printed next to ours, "CHANNEL: BEFORE AFTER, ..."
  --published-note TEXT   their source and units

Exit status: 0 success, 2 bad input (missing directory, a run without analyses, runs
of different mechanisms, a body not in the runs, a channel not recorded in both, a
delay below the sample interval; also: output directory
in use, earlier comparison's files), 4 an output that cannot be written or memory that
ran out, 1 an internal error (see `wearlink --help`).
)" + io::outputs::listing(io::outputs::compare_dynamics());

    workflows::ComparedRun
    read_run(const std::string &dir, const std::string &label)
    {
      workflows::ComparedRun r;
      r.run     = io::read_recorded_run(dir, label);
      r.summary = io::read_json_file(dir + "/" + io::outputs::summary);
      return r;
    }

    /** The names of the moving bodies of a run's summary.json ("bodies"), sorted. */
    std::vector<std::string>
    body_names(const Json &summary)
    {
      std::vector<std::string> names;
      if (summary.is_object() && summary.contains("bodies") && summary.at("bodies").is_object())
        for (const auto &[name, value] : summary.at("bodies").items())
          names.push_back(name);
      std::sort(names.begin(), names.end());
      return names;
    }

    /**
     * The two runs must be of one mechanism: the same moving bodies. Runs of two
     * mechanisms share at most a joint's name ("B"), and their "before/after" figures
     * would compare unrelated motions.
     */
    void
    check_same_mechanism(const workflows::ComparedRun   &before,
                         const workflows::ComparedRun   &after,
                         const std::vector<std::string> &dirs)
    {
      const auto b = body_names(before.summary), a = body_names(after.summary);
      if (b != a)
        throw InputError("The runs in '" + dirs[0] + "' and '" + dirs[1] +
                         "' are of different mechanisms: the bodies of the first are " + join(b, ", ") +
                         ", those of the second " + join(a, ", ") +
                         ". compare-dynamics compares one mechanism before and after wear; give two runs of "
                         "the same scene (fresh and worn profiles).");
    }

    /** Every name of --bodies must be a body of the runs (InputError naming those there are). */
    void
    check_bodies(const std::vector<std::string> &asked, const Json &summary)
    {
      const auto names = body_names(summary);
      for (const auto &b : asked)
        if (std::find(names.begin(), names.end(), b) == names.end())
          throw InputError("--bodies: '" + b + "' is not a body of the runs; their bodies are " + join(names, ", ") +
                           ".");
    }

    int
    run_compare_dynamics(const std::vector<std::string> &args)
    {
      const auto a = parse_arguments(args,
                                     {{"--output", true},
                                      {"--delay", true},
                                      {"--embedding", true},
                                      {"--methods", true},
                                      {"--directions", true},
                                      {"--scan", true},
                                      {"--bodies", true},
                                      {"--published", true},
                                      {"--published-note", true},
                                      {"--overwrite", false}},
                                     "compare-dynamics");
      if (a.positional.size() != 2)
        throw InputError("`wearlink compare-dynamics` needs two run directories, BEFORE and AFTER (given " +
                         std::to_string(a.positional.size()) + "). See --help.");
      const std::string      out     = a.value("--output", "output/compare_dynamics");
      const auto             claimed = claim_output_directory(output_claim(out, io::outputs::compare_dynamics(), a));
      workflows::ComparedRun before  = read_run(a.positional[0], "before: " + a.positional[0]);
      workflows::ComparedRun after   = read_run(a.positional[1], "after: " + a.positional[1]);
      check_same_mechanism(before, after, a.positional);

      workflows::DynamicsComparisonSettings s;
      // Joints: the clearance joints whose journal-centre channels both runs recorded.
      if (before.summary.contains("clearance_joints"))
        for (const auto &[name, value] : before.summary.at("clearance_joints").items())
          if (before.run.series.has(name + "_ex_m") && after.run.series.has(name + "_ex_m"))
            s.joints.push_back(name);
      if (s.joints.empty())
        throw InputError("The runs in '" + a.positional[0] + "' and '" + a.positional[1] +
                         "' have no clearance-joint series in common (list phase-portrait or "
                         "lyapunov in 'Analyses/List of analyses' and analyse the same joints).");
      s.directions = a.list("--directions", "x");
      for (const auto &d : s.directions)
        if (d != "x" && d != "y")
          throw InputError("--directions: '" + d + "' is not a direction; allowed: x, y.");
      for (const auto &m : a.list("--methods", "wolf,rosenstein"))
        if (const auto method = analysis::parse_method(m))
          s.methods.push_back(*method);
        else
          throw InputError("--methods: '" + m + "' is not a method; allowed: wolf, rosenstein.");
      s.delay = a.number("--delay", 0.005);
      if (!(s.delay >= 0.0))
        throw InputError("--delay must be >= 0 s (0: automatic), given " + a.value("--delay") + ".");
      const double m = a.number("--embedding", 0);
      if (!(m >= 0 && m <= 64 && m == std::floor(m)))
        throw InputError("--embedding must be an integer in [0, 64] (0: automatic), given " + a.value("--embedding") +
                         ".");
      s.dimension            = static_cast<unsigned int>(m);
      const std::string scan = a.value("--scan", "0.002,0.005,0.01,0.02,0.05");
      if (scan != "none")
        for (const auto &v : a.list("--scan", scan))
          {
            double tau = 0;
            try
              {
                std::size_t used = 0;
                tau              = std::stod(v, &used);
                if (used != v.size())
                  throw std::invalid_argument(v);
              }
            catch (const std::exception &)
              {
                throw InputError("--scan: '" + v + "' is not a number of seconds.");
              }
            if (!(tau > 0.0) || !std::isfinite(tau))
              throw InputError("--scan: delays must be > 0 s, given '" + v + "'.");
            s.delay_scan.push_back(tau);
          }
      s.bodies = a.list("--bodies");
      check_bodies(s.bodies, before.summary);
      s.published      = analysis::parse_published_exponents(a.value("--published", ""), "--published");
      s.published_note = a.value("--published-note", "");

      const auto c = workflows::compare_dynamics(before, after, s, out);
      std::cout << c.report << "\nwrote " << out << "/" << io::outputs::before_after_report << "\n";
      return 0;
    }
  } // namespace

  extern const Command compare_dynamics_command;
  const Command        compare_dynamics_command = {"compare-dynamics",
                                                   "compare-dynamics BEFORE_DIR AFTER_DIR [--output DIR]  "
                                                          "dynamics before vs after wear",
                                                   compare_dynamics_help.c_str(),
                                                   run_compare_dynamics};
} // namespace wearlink::app
