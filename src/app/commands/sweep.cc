// SPDX-License-Identifier: LGPL-2.1-or-later
// `wearlink sweep SCENE.prm --parameter "Section/Entry" --values FROM:TO:COUNT`: the
// arguments, MPI for this command only, and the sweep of workflows/study/sweep.h.
#include "workflows/study/sweep.h"

#include "app/command_line.h"
#include "app/output_claim.h"
#include "base/exceptions.h"
#include "io/output_names.h"

#include <deal.II/base/mpi.h>

#include <cmath>
#include <filesystem>
#include <sstream>

namespace wearlink::app
{
  namespace
  {
    const std::string sweep_help = std::string(
                                     R"(wearlink sweep SCENE.prm --parameter "Section/Entry" --values FROM:TO:COUNT
               [--channel NAME] [--output DIR] [--set "Section/Entry=value" ...]
mpirun -np N wearlink sweep ...   (the same, members spread over N MPI ranks)

Runs SCENE once per value of one scene entry, COUNT values evenly spaced from FROM to TO
(inclusive), and draws the bifurcation diagram: the Poincaré points of one channel
(one point per driving period, from the integrator's dense output at the exact section
time) against the parameter.

The section follows the scene's 'Analyses' entries: Driving period (default 2π/|ω| of
the angle drivers), Section phase, Transient (points before Start time + Transient are
not used). Set them with --set, e.g. --set "Analyses/Transient=1". The scene's own
analyses (phase portraits, Lyapunov exponents) are not run for sweep members, and no
time series is written for them.

Options:
  --parameter PATH   the swept entry, e.g. "Joint A/Clearance/Radial clearance"
  --values F:T:N     N values from F to T (N >= 1; N = 1 gives F)
  --channel NAME     the channel drawn (default: <first clearance joint>_ex_m, the
                     journal-centre x relative to the bushing). Channels: for a body B
                     B_x_m, B_y_m, B_theta_rad, B_vx_m_s, B_vy_m_s, B_omega_rad_s; for a
                     clearance joint J J_ex_m, J_ey_m, J_vex_m_s, J_vey_m_s.
  --output DIR       output directory (default output/<scene name>_sweep)
  --set S/E=V        override another entry for every member (repeatable)
  --overwrite        replace the files of an earlier sweep in DIR
  --quiet            no per-member lines

A member whose value is invalid or whose run fails (e.g. a mechanism that cannot be
assembled) is reported in members.csv, sweep.json and on the screen; the other members
still run. Exit status: 0 if the sweep ran (even with failed members), 2 bad input
(scene, option or channel; also: directory in use, earlier sweep's files), 3 if every
member failed, 4 an output that cannot be written or memory that ran out, 1 an internal
error (see `wearlink --help`).

Outputs in DIR (written by rank 0 only, each atomically): bifurcation.csv,
members.csv, bifurcation.png, sweep.json.
)") + output_folder_help + io::outputs::listing(io::outputs::sweep());

    /** The swept values FROM:TO:COUNT. */
    std::vector<double>
    parse_values(const std::string &text)
    {
      const auto fail = [&](const std::string &why) {
        throw InputError("--values '" + text + "': " + why +
                         ". Give FROM:TO:COUNT, e.g. --values 1e-4:5e-4:8 (COUNT values from FROM "
                         "to TO inclusive).");
      };
      const auto parts = dealii::Utilities::split_string_list(text, ':');
      if (parts.size() != 3)
        fail("it needs three fields separated by ':'");
      double bounds[2];
      for (int k = 0; k < 2; ++k)
        {
          std::size_t used = 0;
          try
            {
              bounds[k] = std::stod(parts[k], &used);
            }
          catch (const std::exception &)
            {
              used = 0;
            }
          if (used == 0 || used != parts[k].size() || !std::isfinite(bounds[k]))
            fail("'" + parts[k] + "' is not a finite number");
        }
      long        count = 0;
      std::size_t used  = 0;
      try
        {
          count = std::stol(parts[2], &used);
        }
      catch (const std::exception &)
        {
          used = 0;
        }
      if (used == 0 || used != parts[2].size() || count < 1 || count > 100000)
        fail("COUNT '" + parts[2] + "' must be a whole number from 1 to 100000");
      // Evenly spaced, the ends exact. A value that is zero up to the rounding of the
      // spacing (-1e-4 + 4e-4 / 4 = -1.4e-20) is set to zero, the value the user meant.
      std::vector<double> values(count);
      const double        scale = std::max(std::abs(bounds[0]), std::abs(bounds[1]));
      for (long i = 0; i < count; ++i)
        {
          values[i] = count == 1 ? bounds[0] : bounds[0] + (bounds[1] - bounds[0]) * i / (count - 1);
          if (std::abs(values[i]) < 1e-12 * scale)
            values[i] = 0.0;
        }
      values.back() = count == 1 ? bounds[0] : bounds[1];
      return values;
    }

    int
    run_sweep(const std::vector<std::string> &args)
    {
      const auto a = parse_arguments(args,
                                     {{"--parameter", true},
                                      {"--values", true},
                                      {"--channel", true},
                                      {"--output", true},
                                      {"--set", true, true},
                                      {"--quiet", false},
                                      {"--overwrite", false}},
                                     "sweep");
      // MPI for this command only. One thread per rank: the ranks are the parallelism.
      int                                      argc           = 1;
      char                                     program[]      = "wearlink";
      char                                    *argv_storage[] = {program, nullptr};
      char                                   **argv           = argv_storage;
      dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
      if (a.positional.size() != 1)
        throw InputError("`wearlink sweep` needs exactly one scene file (given " + std::to_string(a.positional.size()) +
                         "). See `wearlink sweep --help`.");
      if (!a.has("--parameter") || !a.has("--values"))
        throw InputError("`wearlink sweep` needs --parameter \"Section/Entry\" and --values "
                         "FROM:TO:COUNT. See `wearlink sweep --help`.");
      workflows::SweepRequest r;
      r.file             = a.positional[0];
      r.parameter        = a.value("--parameter");
      r.values           = parse_values(a.value("--values"));
      r.channel          = a.value("--channel", "");
      r.overrides        = a.all("--set");
      r.output_directory = a.value("--output", "output/" + std::filesystem::path(r.file).stem().string() + "_sweep");
      r.quiet            = a.has("--quiet");
      const auto claimed = claim_output_directory_on_root(output_claim(r.output_directory, io::outputs::sweep(), a));
      return workflows::run_sweep(r);
    }
  } // namespace

  extern const Command sweep_command;
  const Command        sweep_command = {"sweep",
                                        "sweep SCENE.prm --parameter \"S/E\" --values FROM:TO:COUNT [--channel NAME] "
                                               "[--output DIR]  bifurcation diagram (MPI: mpirun -np N wearlink sweep ...)",
                                        sweep_help.c_str(),
                                        run_sweep};
} // namespace wearlink::app
