// SPDX-License-Identifier: LGPL-2.1-or-later
// `wearlink contact CASE.prm`: the FE contact model of one shaft–bushing pair for a list
// of load states, solved with both the condensed (production) and the reference solver,
// with the Hertz line-contact numbers of doc/models.md §5.1 for comparison. Writes into
// the output directory: summary.json, pressure_<k>_<solver>.csv per load state,
// fields_<k>.vtu (displacement and stress for ParaView) and the gmsh mesh.
#include "app/command_line.h"
#include "app/output_claim.h"
#include "base/exceptions.h"
#include "io/contact_case.h"
#include "io/output_names.h"
#include "workflows/run/contact_case.h"

#include <deal.II/base/mpi.h>

#include <filesystem>
#include <iostream>

namespace wearlink::app
{
  namespace
  {
    const std::string contact_help =
      std::string(R"(wearlink contact CASE.prm [--output DIR] [--overwrite] [--set "Section/Entry=value" ...]
wearlink contact --print-parameters

Solves the 2D plane-strain frictionless contact of one pin in its bushing (gmsh mesh of
the actual, possibly worn, profiles; deal.II elasticity) for every load state of the
case, with the condensed production solver and the uncondensed reference solver (see
'FE model/Solvers'), and compares with Hertz line contact (doc/models.md §5.1).
Example: params/pin_bushing.prm. Writes into DIR (default: output/<case name>):
  summary.json               per solver: setup time, mean time per load state, and per
                             load state load_N, half_angle_deg, half_width_m,
                             peak_pressure_Pa, pin_displacement_m,
                             equilibrium_relative_residual; n_dofs,
                             n_contact_candidates; Hertz numbers; the effect ledger
  pressure_<k>_<solver>.csv  nodal pressure per pin contact candidate: pin-frame angle,
                             bushing-frame angle of its contact point, pressure (Pa)
  fields_<k>.vtu             displacement and stress of both bodies (ParaView)
  pin_bushing.msh            the gmsh mesh
  parameters.prm             the effective case (with --set overrides applied)
)") + output_folder_help +
      R"(
Options:
  --output DIR        output directory
  --overwrite         replace the files of an earlier contact run in DIR
  --set S/E=V         override an entry, e.g. --set "FE model/Surface element size=2e-5"
  --print-parameters  print every entry with its unit, default and meaning

MPI: `mpirun -np N wearlink contact CASE.prm` distributes the reference solver over N
ranks (METIS partitions of the mesh, a PETSc matrix factored by MUMPS); the condensed
solver runs on every rank (it is small and serial) and rank 0 writes all outputs. The
answer is the serial one.

Exit status: 0 success, 2 bad input (also: directory in use, earlier run's files),
3 numerical failure, 4 an output that cannot be written or memory that ran out, 1 an
internal error (see `wearlink --help`).
)" + io::outputs::listing(io::outputs::contact());

    int
    run_contact(const std::vector<std::string> &args)
    {
      // MPI (and PETSc) for the distributed reference solver; a plain run is one rank.
      int                                      mpi_argc   = 1;
      char                                     program[]  = "wearlink";
      char                                    *mpi_argv[] = {program, nullptr};
      char                                   **argv_ptr   = mpi_argv;
      dealii::Utilities::MPI::MPI_InitFinalize mpi(mpi_argc, argv_ptr, 1);
      const unsigned int                       n_ranks = dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
      const bool                               root    = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;

      const auto a = parse_arguments(
        args,
        {{"--output", true}, {"--set", true, true}, {"--print-parameters", false}, {"--overwrite", false}},
        "contact");
      dealii::ParameterHandler prm;
      io::declare_contact_case(prm);
      if (a.has("--print-parameters"))
        {
          if (root)
            prm.print_parameters(std::cout, dealii::ParameterHandler::Text);
          return 0;
        }
      if (a.positional.size() != 1)
        throw InputError("`wearlink contact` needs exactly one case file (given " +
                         std::to_string(a.positional.size()) + "). See `wearlink contact --help`.");
      const std::string         file         = a.positional[0];
      const auto                contact_case = io::load_contact_case(prm, file, a.all("--set"));
      workflows::ContactCaseRun run;
      run.output_directory = a.value("--output", "output/" + std::filesystem::path(file).stem().string());
      run.log              = root ? &std::cout : nullptr;
      run.root             = root;
      run.n_ranks          = n_ranks;
      const auto claimed =
        claim_output_directory_on_root(output_claim(run.output_directory, io::outputs::contact(), a));
      workflows::run_contact_case(contact_case, prm, run);
      return 0;
    }
  } // namespace

  extern const Command contact_command;
  const Command        contact_command = {"contact",
                                          "contact CASE.prm [--output DIR] [--set S/E=V ...]",
                                          contact_help.c_str(),
                                          run_contact};
} // namespace wearlink::app
