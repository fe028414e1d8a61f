// SPDX-License-Identifier: LGPL-2.1-or-later
// `wearlink life SCENE.prm`: the wear loop until the scene's Life criteria are reached
// (workflows/wear/life.h), in an output folder held as `run` holds it.
#include "workflows/wear/life.h"

#include "app/command_line.h"
#include "app/ensemble_command.h"
#include "app/output_claim.h"
#include "base/exceptions.h"
#include "io/output_names.h"
#include "workflows/ensemble/ensemble.h"

#include <filesystem>
#include <iostream>

namespace wearlink::app
{
  namespace
  {
    const std::string life_help =
      std::string(R"(wearlink life SCENE.prm [--output DIR] [--overwrite] [--set "Section/Entry=value" ...] [--quiet]
wearlink life SCENE.prm --resume DIR [--set ...] [--quiet]
[mpirun -np R] wearlink life SCENE.prm --ensemble N [--seed S] [--perturbation RAD] [--sensitivity saltelli] [...]

When is the joint worn out? Runs the wear loop of a wear scene (section Wear: the
iterations, their extrapolation, the pressure models; see `wearlink run --help`) until
the stop criteria of the scene's section Life are decided, and reports the revolutions
(and the hours at the scene's driving speed) to each:
  Life/Maximum wear depth       m   the deepest envelope depth of any pin or bore
  Life/Radial clearance growth  m   a joint's bore envelope depth + pin envelope depth
  Life/Pin mass loss            mg  the mass worn off a joint's pin
  Life/Bushing mass loss        mg  the mass worn off a joint's bushing
  Life/Response rise            %   the rise of the trend of the mean per-cycle peak
                                    acceleration of Life/Response body (Life/Response
                                    cycles cycles from the initial assembly with the
                                    current profiles, after every iteration) over its
                                    value when fresh
A limit of 0 (the default) switches a criterion off; at least one must be on.

The envelope depth is the largest running median of a surface's depth over the joint's
contact width (2b of the Hertz strip of the unworn radii at the first iteration's peak
force): a spike of one discrete area does not reach a depth limit, a pocket as wide as
the contact does.

The wear criteria (depth, clearance growth, mass losses) are deterministic: each
iteration's extrapolation is limited so that the iteration that crosses one represents
at most Life/Tolerance (default 0.02) of the revolutions at its end, so each is located
within that fraction (the bracket) and is decided when reached.

The response measure scatters (the impacts of a chaotic mechanism), so Response rise is
decided on its trend, never on one sample: the least-squares line through all
measurements, rise = line(N)/line(0) - 1, with its 95 % confidence band (Student t,
n - 2 degrees of freedom). It is reached when the band's lower bound of the rise at the
last measurement is at the limit, not reached when its upper bound is below; located
where the line crosses the limit, with the 95 % interval of the revolutions where the
band's bounds cross it. It is decided when reached with that interval at most
Life/Response tolerance (default 0.5) of the crossing wide, else undecided (reported
with the line's crossing, the interval if bounded, and why). It counts from the 4th
measurement. An undecided criterion is never the life: the life (summary.json
life.headline, first_criterion, life_revolutions) is the decided criterion with the
fewest revolutions.

The run ends when every criterion is settled (a wear criterion reached; the response
criterion decided, or unable to come before the wear lives once they are all reached:
the upper 95 % bound of its rise at the earliest of them below its limit), or at
Life/Maximum revolutions or Life/Maximum iterations (which replaces Wear/Number of
iterations; with adaptive extrapolation Life/Maximum revolutions replaces Wear/Target
revolutions). `wearlink --print-parameters` documents each entry.

Writes into DIR (default: output/<scene name>_life) the files of a wear run
(summary.json, checkpoint.json, wear_history.csv, wear_depth_<J>.csv/.png, profiles,
response_before.csv, response_after.csv, response.png, ...; see `wearlink run --help`)
and
  life_history.csv  per iteration: revolutions, factor, each criterion's value and the
                    joint that has it, the response measure [m/s²]
  life.png          each criterion's value / its limit against revolutions; the
                    response trend with its 95 % band and the interval of its crossing
summary.json has a block "life": per criterion its limit, status ("decided",
"undecided", "not reached"), decided, reached, the revolutions and hours to it, the
joint; a wear criterion its bracket and whether it is within the tolerance; the
response criterion interval_revolutions [low, high], its line's crossing and, if
undecided, the reason; "headline" (criterion, revolutions, hours, reason). The table
is printed.
  --resume DIR        continue the life run in DIR from its last finished iteration
                      (same scene; Life/Maximum revolutions and Life/Maximum iterations
                      may be raised, Life/Response tolerance changed)

)"
                  R"(The output directory is locked while the command runs; one that holds an earlier run's
files is refused unless --overwrite (remove them) or --resume (continue it).

Ensembles (default folder output/<scene name>_life_ensemble; each member a life run in
DIR/member_<k>/): summary.json's "ensemble_life" gives per criterion how many members
decided it and, over those, its revolutions and hours as mean, standard deviation, 95 %
interval of the mean and P10 / P50 / P90 (linear interpolation between the order
statistics, type 7); the ensemble's life is the smallest P10 of the criteria every
member decided. DIR/life.png draws the band (smallest to largest) and the median of the
members' criteria against revolutions. The table is printed.
)") + workflows::ensemble_help() +
      R"(
Options:
  --output DIR        output directory
  --set S/E=V         override entry E of subsection S (repeatable), e.g.
                      --set "Life/Maximum wear depth=5e-5"
  --overwrite         replace the files of an earlier run in DIR
  --quiet             no progress lines

Exit status: 0 success (also when a criterion is not reached within the bounds: the
summary says so), 2 bad input (no wear law, no criterion, a limit out of range, NaN;
nothing is written; also: directory in use, earlier run's files), 3 numerical
failure, 4 an output that cannot be written or memory that ran out, 128 + N stopped by
signal N (the last checkpoint kept), 1 an internal error (see `wearlink --help`).
)" + io::outputs::listing(io::outputs::life());

    /** The file names `wearlink life` writes, for --overwrite. */
    /** Every member a life run (workflows/wear/life.h) in DIR/member_<k>/. */
    int
    run_life_ensemble(const std::string &file, const ParsedArguments &a)
    {
      const bool progress = !a.has("--quiet");
      return run_ensemble_command(
        "life",
        file,
        a,
        [progress](io::Scene &scene, const std::string &dir, const std::string &prefix, const bool resume) {
          workflows::LifeRunOptions o;
          o.output_directory = dir;
          o.resume           = resume;
          o.progress         = progress;
          o.progress_prefix  = prefix;
          return workflows::run_life(scene, o).wear.summary;
        },
        io::outputs::life());
    }

    int
    run_life(const std::vector<std::string> &args)
    {
      std::vector<OptionSpec> spec = {{"--output", true},
                                      {"--set", true, true},
                                      {"--quiet", false},
                                      {"--overwrite", false},
                                      {"--resume", true}};
      for (const auto &o : ensemble_options())
        spec.push_back(o);
      const auto a = parse_arguments(args, spec, "life");
      if (a.positional.size() != 1)
        throw InputError("`wearlink life` needs exactly one scene file (given " + std::to_string(a.positional.size()) +
                         "). See `wearlink life --help`.");
      if (a.has("--overwrite") && a.has("--resume"))
        throw InputError("--overwrite and --resume exclude each other: --resume continues the run in " +
                         a.value("--resume") + ", --overwrite removes its files.");
      const std::string file  = a.positional[0];
      io::Scene         scene = io::read_scene(file, a.all("--set"));
      workflows::check_life_criteria(scene); // before the folder is claimed: a bad input writes nothing
      if (a.has("--ensemble") || a.has("--seed") || a.has("--perturbation") || a.has("--sensitivity"))
        {
          ensemble_request(a); // a bad value is refused before anything runs
          return run_life_ensemble(file, a);
        }
      refuse_several_ranks("life` without `--ensemble",
                           "add --ensemble N to run N perturbed members of the scene over the ranks");

      workflows::LifeRunOptions o;
      o.resume           = a.has("--resume");
      o.output_directory = o.resume ?
                             a.value("--resume") :
                             a.value("--output", "output/" + std::filesystem::path(file).stem().string() + "_life");
      o.progress         = !a.has("--quiet");
      OutputClaim claim  = output_claim(o.output_directory, io::outputs::life(), a);
      if (o.resume)
        claim.earlier = EarlierRun::resume;
      claim.advice = "Add --overwrite to replace them, --resume " + o.output_directory +
                     " (instead of --output) to continue that life run, or choose another --output directory.";
      const auto claimed = claim_output_directory(claim);
      const auto r       = workflows::run_life(scene, o);
      std::cout << workflows::life_table(r.life) << "wrote " << o.output_directory
                << "/summary.json, life_history.csv, life.png and the wear run's files ("
                << r.wear.state.iterations_done << " wear iterations, " << r.wear.state.revolutions << " revolutions, "
                << r.wear.timings.total << " s wall)\n";
      return 0;
    }
  } // namespace

  extern const Command life_command;
  const Command        life_command = {"life",
                                       "life SCENE.prm [--output DIR] [--set S/E=V ...]  "
                                              "wear until the scene's Life criteria: revolutions to each",
                                       life_help.c_str(),
                                       run_life};
} // namespace wearlink::app
