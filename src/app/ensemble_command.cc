// SPDX-License-Identifier: LGPL-2.1-or-later
#include "app/ensemble_command.h"

#include "app/output_claim.h"
#include "base/exceptions.h"
#include "io/output_names.h"
#include "io/scene.h"
#include "workflows/ensemble/uncertain_inputs.h"

#include <deal.II/base/mpi.h>

#include <cmath>
#include <filesystem>
#include <iostream>

namespace wearlink::app
{
  namespace
  {
    /**
     * InputError unless @p dir holds an ensemble that --resume can continue (at least one
     * member_* folder): a mistyped directory must not start a fresh ensemble.
     */
    void
    check_resumable_ensemble(const std::string &dir)
    {
      namespace fs = std::filesystem;
      std::error_code error;
      bool            members = false;
      if (fs::is_directory(dir, error))
        for (const auto &entry : fs::directory_iterator(dir, error))
          members = members || (entry.is_directory() && entry.path().filename().string().rfind("member_", 0) == 0);
      if (!members)
        throw InputError("Cannot resume the ensemble in '" + dir + "': " +
                         (fs::exists(dir, error) ? "it holds no member_* folder" : "the directory does not exist") +
                         ". Check the path, or start the ensemble with --output " + dir + " instead of --resume.");
    }
  } // namespace

  std::vector<OptionSpec>
  ensemble_options()
  {
    return {{"--ensemble", true}, {"--seed", true}, {"--perturbation", true}, {"--sensitivity", true}};
  }

  workflows::EnsembleRequest
  ensemble_request(const ParsedArguments &a)
  {
    workflows::EnsembleRequest r;
    if (!a.has("--ensemble"))
      {
        if (a.has("--seed") || a.has("--perturbation") || a.has("--sensitivity"))
          throw InputError(
            "--seed, --perturbation and --sensitivity belong to an ensemble: add --ensemble N (2 … 1000).");
        return r;
      }
    if (a.has("--sensitivity") && a.value("--sensitivity") != "saltelli")
      throw InputError("--sensitivity " + a.value("--sensitivity") +
                       ": the only layout is 'saltelli' (a Saltelli design for Sobol indices); leave the option "
                       "out for rank correlations over Sobol points.");
    // A value that is no number is named by a.number(); its range by the workflow.
    return workflows::ensemble_request(a.number("--ensemble", 0),
                                       a.number("--seed", 1),
                                       a.number("--perturbation", 1e-9),
                                       a.has("--sensitivity"));
  }


  int
  run_ensemble_command(const std::string          &command,
                       const std::string          &file,
                       const ParsedArguments      &a,
                       const workflows::MemberRun &run,
                       const RunFiles             &member_files)
  {
    // MPI for this command only. One thread per rank: the ranks are the parallelism.
    int                                      argc           = 1;
    char                                     program[]      = "wearlink";
    char                                    *argv_storage[] = {program, nullptr};
    char                                   **argv           = argv_storage;
    dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
    workflows::EnsembleOptions               o;
    o.scene_file           = file;
    o.overrides            = ParameterOverrides(a.all("--set"));
    o.request              = ensemble_request(a);
    o.command              = command;
    o.resume               = a.has("--resume");
    o.progress             = !a.has("--quiet");
    const std::string stem = std::filesystem::path(file).stem().string();
    o.output_directory     = o.resume ?
                               a.value("--resume") :
                               a.value("--output", "output/" + stem + (command == "life" ? "_life" : "") + "_ensemble");
    if (o.resume)
      check_resumable_ensemble(o.output_directory);
    // Every member's uncertain inputs are checked before the folder is claimed: a bad input writes nothing.
    workflows::check_uncertain_members(o, io::read_scene(file, o.overrides));
    OutputClaim claim = output_claim(o.output_directory,
                                     workflows::ensemble_files(o.output_directory, o.request.members, member_files),
                                     a);
    if (o.resume)
      claim.earlier = EarlierRun::resume;
    claim.advice = "Add --overwrite to replace them, --resume " + o.output_directory +
                   " (instead of --output) to continue that ensemble, or choose another --output directory.";
    const auto claimed    = claim_output_directory_on_root(claim);
    bool       all_failed = false;
    const Json summary    = workflows::run_ensemble(o, run, all_failed);
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::cout << workflows::ensemble_table(summary) << "wrote " << o.output_directory
                << "/summary.json, ensemble.csv, ensemble.png"
                << (summary.contains("sensitivity") ? ", sensitivity.png" : "")
                << (command == "life" ? ", life.png, life_cdf.png" : "") << " and member_*/\n";
    return all_failed ? 3 : 0;
  }
} // namespace wearlink::app
