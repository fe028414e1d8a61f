// SPDX-License-Identifier: LGPL-2.1-or-later
// What `wearlink contact` does: the FE contact model of one shaft–bushing pair for every
// load state of a case, solved with the condensed (production) and the reference
// solver, with the Hertz line-contact numbers of doc/models.md §5.1 beside them. Writes
// into the output directory: summary.json, pressure_<k>_<solver>.csv per load state,
// fields_<k>.vtu (displacement and stress for ParaView), the gmsh mesh and the
// effective case (parameters.prm). Under MPI every rank solves; rank 0 writes.
#pragma once

#include "base/json.h"
#include "io/contact_case.h"

#include <deal.II/base/parameter_handler.h>

#include <ostream>
#include <string>

namespace wearlink::workflows
{
  /** Where a contact case runs and reports. */
  struct ContactCaseRun
  {
    std::string   output_directory;
    std::ostream *log     = nullptr; ///< the table and progress (rank 0), or nothing
    bool          root    = true;    ///< this rank writes the files
    unsigned int  n_ranks = 1;       ///< MPI ranks (> 1: distributed reference solver)
  };

  /**
   * Solve @p contact_case (read from @p prm, echoed to parameters.prm) and write its
   * outputs. Returns the summary.
   */
  Json
  run_contact_case(const io::ContactCase &contact_case, const dealii::ParameterHandler &prm, const ContactCaseRun &run);
} // namespace wearlink::workflows
