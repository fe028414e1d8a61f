// SPDX-License-Identifier: LGPL-2.1-or-later
// `wearlink life SCENE.prm`: the wear loop until the scene's Life criteria are reached
// (workflows/life.h), in an output folder held as `run` holds it.
#include "workflows/life.h"

#include "app/command_line.h"
#include "app/ensemble_command.h"
#include "app/output_claim.h"
#include "app/run_files.h"
#include "base/exceptions.h"
#include "io/life_parameters.h"
#include "workflows/ensemble.h"

#include <filesystem>
#include <iostream>

namespace wearlink::app
{
  namespace
  {
    const std::string help_text =
      std::string(R"(wearlink life SCENE.prm [--output DIR] [--overwrite] [--set "Section/Entry=value" ...] [--quiet]
wearlink life SCENE.prm --resume DIR [--set ...] [--quiet]
[mpirun -np R] wearlink life SCENE.prm --ensemble N [--seed S] [--perturbation RAD] [...]

When is the joint worn out? Runs the wear loop of a wear scene (section Wear: the
iterations, their extrapolation, the pressure models; see `wearlink run --help`) until
the stop criteria of the scene's section Life are reached, and reports the revolutions
(and the hours at the scene's driving speed) to each:
  Life/Maximum wear depth       m   the deepest wear of any pin or bore
  Life/Radial clearance growth  m   a joint's deepest bore wear + deepest pin wear
  Life/Pin mass loss            mg  the mass worn off a joint's pin
  Life/Bushing mass loss        mg  the mass worn off a joint's bushing
  Life/Response rise            %   the rise of the mean per-cycle peak acceleration of
                                    Life/Response body (Life/Response cycles cycles from
                                    the initial assembly with the current profiles, after
                                    every iteration) over its value when fresh
A limit of 0 (the default) switches a criterion off; at least one must be on. Each
iteration's extrapolation is limited so that the iteration that crosses a criterion
represents at most Life/Tolerance (default 0.02) of the revolutions at its end: each
life is located within that fraction (the bracket in summary.json). The run ends when
every criterion is reached, or at Life/Maximum revolutions or Life/Maximum iterations
(which replaces Wear/Number of iterations; with adaptive extrapolation Life/Maximum
revolutions replaces Wear/Target revolutions). `wearlink --print-parameters` documents
each entry.

Writes into DIR (default: output/<scene name>_life) the files of a wear run
(summary.json, checkpoint.json, wear_history.csv, wear_depth_<J>.csv/.png, profiles,
response_before.csv, response_after.csv, response.png, ...; see `wearlink run --help`)
and
  life_history.csv  per iteration: revolutions, factor, each criterion's value and the
                    joint that has it, the response measure [m/s²]
  life.png          each criterion's value / its limit against revolutions
summary.json has a block "life": per criterion its limit, whether it was reached, the
revolutions and hours to it, the joint, the bracket of revolutions and whether it is
within the tolerance; the first criterion reached and its life. The table is printed.
  --resume DIR        continue the life run in DIR from its last finished iteration
                      (same scene; Life/Maximum revolutions and Life/Maximum iterations
                      may be raised)

)"
                  R"(The output directory is locked while the command runs; one that holds an earlier run's
files is refused unless --overwrite (remove them) or --resume (continue it).

Ensembles (default folder output/<scene name>_life_ensemble; each member a life run in
DIR/member_<k>/; the revolutions to each criterion get a mean, a standard deviation and
a 95 % interval, over the members that reached it):
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
)";

    /** The file names `wearlink life` writes, for --overwrite. */
    RunFiles
    life_files()
    {
      RunFiles f = run_files();
      f.patterns.push_back("life_history.csv");
      f.patterns.push_back("life.png");
      return f;
    }

    /** Every member a life run (workflows/life.h) in DIR/member_<k>/. */
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
        life_files());
    }

    int
    run(const std::vector<std::string> &args)
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
      io::check_life_criteria(scene); // before the folder is claimed: a bad input writes nothing
      if (a.has("--ensemble") || a.has("--seed") || a.has("--perturbation"))
        {
          ensemble_request(a); // a bad value is refused before anything runs
          return run_life_ensemble(file, a);
        }

      workflows::LifeRunOptions o;
      o.resume           = a.has("--resume");
      o.output_directory = o.resume ?
                             a.value("--resume") :
                             a.value("--output", "output/" + std::filesystem::path(file).stem().string() + "_life");
      o.progress         = !a.has("--quiet");
      OutputClaim claim  = output_claim(o.output_directory, life_files(), a);
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
                                       help_text.c_str(),
                                       run};
} // namespace wearlink::app
