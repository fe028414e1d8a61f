// SPDX-License-Identifier: LGPL-2.1-or-later
// `wearlink study accuracy SCENE.prm`: what accuracy costs in time (workflows/study/accuracy_study.h).
// Every accuracy knob that applies to the scene is varied alone; the error of the
// quantities that matter against the knob's reference and the wall time of every run
// go into accuracy.csv, accuracy.md and accuracy_pareto.png.
// `wearlink study convergence SCENE.prm`: do the worn profiles converge
// (workflows/study/convergence_study.h)? The surfaces and the wear step refined together, an
// ensemble at every level.
#include "app/command_line.h"
#include "app/output_claim.h"
#include "base/exceptions.h"
#include "io/output_names.h"
#include "workflows/study/accuracy_study.h"
#include "workflows/study/convergence_study.h"

#include <deal.II/base/mpi.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <sstream>

namespace wearlink::app
{
  namespace
  {
    const std::string study_help =
      std::string(R"(wearlink study convergence SCENE.prm [--output DIR] [--set "Section/Entry=value" ...]
                     [--refinements 1,2,4] [--ensemble N] [--seed S] [--perturbation RAD]
                     [--overwrite] [--quiet]
mpirun -np R wearlink study convergence ...   (the same, runs spread over R MPI ranks)

Do the worn profiles of a wear scene converge? Each level refines the worn surfaces and
the wear step together by a factor r (--refinements, default 1,2,4; the scene's own
settings are 1): r × the Number of discrete areas of joints on hertz-strip or winkler,
fe Surface element size ÷ r for joints on fe; r × the wear iterations with the
extrapolation factor ÷ r (the same revolutions), or Maximum depth increment ÷ r with
adaptive extrapolation. Every level runs an ensemble of N members (--ensemble, default
4: the scene's own run and N − 1 runs whose initial crank angles are shifted by ~1e-9
rad, as `run --ensemble` does), because the clearance dynamics are chaotic and one run
is one sample. Each level's mean profile is compared with the finest level's, point by
point on the coarser grid: the relative L2 and largest pointwise differences, and the
changes of the largest depth, the envelope depth (at the contact width) and the worn
volume, beside the chaos floor (two single runs' L2 difference, the standard error of a
mean profile) and each level's roughness and wall time. With three levels of one ratio
(1,2,4), a Richardson estimate of each surface's largest and envelope depth: the
observed order, the extrapolated depth and each level's error against it (not given
where a difference is within the chaos floor or the levels do not converge). Writes
into DIR (default:
output/<scene name>_convergence; rank 0): convergence.md (the table, also printed),
convergence.csv, convergence.json, and per joint and surface convergence_<J>_<pin|
bushing>.csv (each level's mean, smallest and largest depth at each angle) and .png (the
mean profiles with the members' range as a band).

wearlink study accuracy SCENE.prm [--output DIR] [--set "Section/Entry=value" ...]
                     [--quick] [--knobs a,b,...] [--study STUDY.prm] [--overwrite] [--quiet]
                     [--ensemble N] [--seed S] [--perturbation RAD]
mpirun -np R wearlink study accuracy ...   (the same, runs spread over R MPI ranks)

Shows what accuracy costs in time. Each accuracy knob that applies to the scene
(integrator tolerance or step, Baumgarte factors, contact law, discrete areas per
profile, load sampling of the pressure model, wear step, simulated cycles per wear
iteration, pressure model, and with
Pressure model = fe: surface element size, element degree, re-mesh depth; with
Normal force law = fe in a wear scene: the direction grid of the worn tables) is set
to each of its values in turn, coarse to fine, while everything else keeps the
scene's value. Every run is timed (reading, building and running) and compared with
the knob's reference run (its finest value; for choices without a "finer" one, the
scene's own): relative error of the worn volume and largest wear depth of pin and
bushing, relative L2 difference of the worn-depth profiles, peak contact force per
clearance joint and peak acceleration of the response body.
The pressure-model knob evaluates every registered model the scene gives the
parameters of (fe, registered last, the reference) on sampled load states (50 per
cycle; fe with 0.2 mm surface elements, re-meshing beyond 2 of them) when the scene
itself evaluates every step without fe: fe at every step of a 100-cycle run takes
hours; what sampling costs in accuracy is the load-sampling knob's row.

The chaos floor: the scene's own run and N − 1 runs whose angle drivers' initial angles
are shifted by ~1e-9 rad (as the members of `wearlink run --ensemble`; N = --ensemble,
default 4, 0: none) are compared pairwise as a row is with its reference. Their spread
is what no knob can resolve: the table has it as a column ("floor", and each row's
"worst/floor"), the PNGs as a band, accuracy_floor.csv per quantity.

Runs are spread over the MPI ranks (largest predicted first, each to the least loaded
rank); one line per run with the estimated time left (on that rank). Writes into DIR
(default: output/<scene name>_accuracy; rank 0), each file atomically: accuracy.csv
(every quantity and error, the floor), accuracy.md (the table, also printed),
accuracy_floor.csv, accuracy_pareto.png (worst error vs wall time, log-log, one series
per knob, the floor as a band) and, for wear scenes, accuracy_pareto_volume.png (the
worn volume's error vs wall time).
)") + output_folder_help +
      R"(
Options:
  --quick             fewer values and, for wear scenes, Wear/Cycles per iteration = 1,
                      Wear/Number of iterations = 2 (other scenes: at most 1 s
                      simulated); --set overrides win
  --knobs a,b         only these knobs
  --study FILE        a study file (below); --knobs wins over its Knobs
  --set S/E=V         override a scene entry in every run (repeatable)
  --overwrite         replace the files of an earlier study in DIR
  --quiet             no progress lines
  --ensemble N        members of the chaos floor (default 4; 0: no floor)
  --seed S            seed of the floor's perturbations (default 1)
  --perturbation RAD  their size (default 1e-9 rad)

)" + workflows::study_file_help() +
      R"(
Exit status: 0 success (a run that fails is a row of the table), 2 bad input (nothing
is written; also: directory in use, earlier study's files), 3 numerical failure, 4 an
output that cannot be written or memory that ran out, 1 an internal error (see
`wearlink --help`).
)" + std::string("study accuracy: ") +
      io::outputs::listing(io::outputs::accuracy_study()) +
      "study convergence: " + io::outputs::listing(io::outputs::convergence_study());

    /** --ensemble N, --seed, --perturbation of a study: the chaos floor's ensemble. */
    workflows::FloorEnsemble
    floor_of(const ParsedArguments &a)
    {
      return workflows::floor_ensemble(a.number("--ensemble", 4),
                                       a.number("--seed", 1),
                                       a.number("--perturbation", 1e-9));
    }

    /** --refinements a,b,c: the levels' factors. */
    std::vector<double>
    refinements(const ParsedArguments &a)
    {
      if (!a.has("--refinements"))
        return {1, 2, 4};
      std::vector<double> r;
      for (const auto &part : split(a.value("--refinements"), ','))
        {
          std::size_t used = 0;
          double      v    = std::numeric_limits<double>::quiet_NaN();
          try
            {
              v = std::stod(part, &used);
            }
          catch (const std::exception &)
            {
            }
          if (part.empty() || used != part.size() || !std::isfinite(v))
            throw InputError("--refinements " + a.value("--refinements") + ": '" + part +
                             "' is not a number; give increasing factors separated by commas, e.g. 1,2,4.");
          r.push_back(v);
        }
      return r;
    }

    /** MPI for a study command only. One thread per rank: the ranks are the parallelism. */
    struct StudyMpi
    {
      int                                      argc            = 1;
      char                                     program[9]      = "wearlink";
      char                                    *argv_storage[2] = {program, nullptr};
      char                                   **argv            = argv_storage;
      dealii::Utilities::MPI::MPI_InitFinalize mpi{argc, argv, 1};
    };

    int
    run_convergence(const std::vector<std::string> &rest)
    {
      const auto a = parse_arguments(rest,
                                     {{"--output", true},
                                      {"--set", true, true},
                                      {"--refinements", true},
                                      {"--quiet", false},
                                      {"--overwrite", false},
                                      {"--ensemble", true},
                                      {"--seed", true},
                                      {"--perturbation", true}},
                                     "study convergence");
      if (a.positional.size() != 1)
        throw InputError("`wearlink study convergence` needs exactly one scene file (given " +
                         std::to_string(a.positional.size()) + "). See `wearlink study --help`.");
      const std::string             file = a.positional[0];
      workflows::ConvergenceRequest request;
      request.overrides    = a.all("--set");
      request.progress     = !a.has("--quiet");
      request.refinements  = refinements(a);
      const auto floor     = floor_of(a);
      request.members      = floor.members;
      request.seed         = floor.seed;
      request.perturbation = floor.perturbation;
      const std::string out =
        a.value("--output", "output/" + std::filesystem::path(file).stem().string() + "_convergence");
      StudyMpi   mpi;
      const auto claimed = claim_output_directory_on_root(output_claim(out, io::outputs::convergence_study(), a));
      const auto study   = workflows::run_convergence_study(file, request);
      if (!study.root)
        return 0;
      workflows::write_convergence_study(out, study);
      std::cout << study.markdown() << "\nwrote " << out
                << "/convergence.md, convergence.csv, convergence.json, convergence_<J>_<surface>.csv/.png\n";
      return 0;
    }

    int
    run_accuracy(const std::vector<std::string> &rest)
    {
      const auto a = parse_arguments(rest,
                                     {{"--output", true},
                                      {"--set", true, true},
                                      {"--quick", false},
                                      {"--knobs", true},
                                      {"--study", true},
                                      {"--quiet", false},
                                      {"--overwrite", false},
                                      {"--ensemble", true},
                                      {"--seed", true},
                                      {"--perturbation", true}},
                                     "study accuracy");
      if (a.positional.size() != 1)
        throw InputError("`wearlink study accuracy` needs exactly one scene file (given " +
                         std::to_string(a.positional.size()) + "). See `wearlink study --help`.");
      const std::string       file = a.positional[0];
      workflows::StudyRequest request;
      request.overrides = a.all("--set");
      request.quick     = a.has("--quick");
      request.progress  = !a.has("--quiet");
      if (a.has("--study"))
        workflows::read_study_file(a.value("--study"), request);
      const auto floor      = floor_of(a);
      request.floor_members = floor.members;
      request.seed          = floor.seed;
      request.perturbation  = floor.perturbation;
      if (a.has("--knobs"))
        {
          request.knobs.clear();
          std::stringstream ks(a.value("--knobs"));
          for (std::string k; std::getline(ks, k, ',');)
            if (!k.empty())
              request.knobs.push_back(k);
        }
      const std::string out =
        a.value("--output", "output/" + std::filesystem::path(file).stem().string() + "_accuracy");
      StudyMpi   mpi;
      const auto claimed = claim_output_directory_on_root(output_claim(out, io::outputs::accuracy_study(), a));
      const auto study   = workflows::run_accuracy_study(file, request);
      if (!study.root)
        return 0;
      workflows::write_accuracy_study(out, study);
      std::cout << study.markdown() << "\nwrote " << out
                << "/accuracy.csv, accuracy.md, accuracy_floor.csv, accuracy_pareto.png\n";
      return 0;
    }

    int
    run_study(const std::vector<std::string> &args)
    {
      const std::vector<std::string> rest(args.empty() ? args.end() : args.begin() + 1, args.end());
      if (!args.empty() && args[0] == "accuracy")
        return run_accuracy(rest);
      if (!args.empty() && args[0] == "convergence")
        return run_convergence(rest);
      throw InputError("`wearlink study` needs a study kind, `accuracy` or `convergence`: wearlink study accuracy "
                       "SCENE.prm, wearlink study convergence SCENE.prm. See `wearlink study --help`.");
    }
  } // namespace

  extern const Command study_command;
  const Command        study_command = {"study",
                                        "study accuracy|convergence SCENE.prm  what accuracy costs in time "
                                               "(every knob in turn); do the worn profiles converge",
                                        study_help.c_str(),
                                        run_study};
} // namespace wearlink::app
