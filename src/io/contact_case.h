// SPDX-License-Identifier: LGPL-2.1-or-later
// The case file of `wearlink contact` (e.g. params/pin_bushing.prm): one shaft–bushing
// pair (geometry, materials, possibly worn profiles), a list of load states and the FE
// model's settings. Declared with units and read with the same checks as a scene
// (InputError naming the file, the entry and the allowed range).
#pragma once

#include "base/validity_warnings.h"
#include "contact/pressure_model.h"
#include "fe/pin_bushing_model.h"

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace wearlink::io
{
  /** A contact case as read from its file. */
  struct ContactCase
  {
    std::string               file;
    contact::JointGeometry    geometry;
    double                    bore_radius   = 0; ///< nominal R1 [m]
    double                    pin_radius    = 0; ///< nominal R2 [m]
    bool                      force_control = true;
    std::vector<fe::LoadCase> loads;
    fe::FeSettings            settings;
    bool                      run_condensed = true;
    bool                      run_reference = true;
    bool                      write_vtu     = true;
    /** Load states that are valid but implausible (an eccentricity within the clearance). */
    ValidityWarnings warnings;
  };

  /** Declare every entry of a contact case. */
  void
  declare_contact_case(dealii::ParameterHandler &prm);

  /**
   * Read the case from @p prm (parsed from @p file, overrides applied): profiles relative
   * to the case file's folder, load states along the load direction, the refined arc
   * centred on it.
   */
  ContactCase
  read_contact_case(dealii::ParameterHandler &prm, const std::string &file);

  /**
   * Parse @p file into @p prm (declared by declare_contact_case()), apply @p overrides
   * ("Section/Entry=value"), check the required entries and read the case. InputError for
   * a mechanism scene given instead (saying which command reads it), and for an override
   * of the load list that Loads/Control does not read (it would have no effect).
   */
  ContactCase
  load_contact_case(dealii::ParameterHandler &prm, const std::string &file, const std::vector<std::string> &overrides);
} // namespace wearlink::io
