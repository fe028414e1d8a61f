// SPDX-License-Identifier: LGPL-2.1-or-later
// The entries of "Joint <name>/Clearance" that the contact layer reads, declared here once
// with their bounds, defaults, documentation and units (doc/contributing.md §4): which
// body holds the bore, bore radius, radial clearance, axial length, materials, the
// effective-radius convention, the normal force and friction laws (every registered law
// declares its own subsection), the initial eccentricity, the profile files and the
// number of discrete areas. The wear layer adds its own entries to the same subsection
// (wear/wear_settings.h); the scene reader (io/scene_reader.cc) reads the profile files
// and assembles the joint.
#pragma once

#include "base/parameters.h"
#include "base/validity_warnings.h"
#include "contact/clearance_joint.h"

namespace wearlink::contact
{
  /** Upper bound of 'Slices/Axial slices'. */
  inline constexpr int max_axial_slices = 200;

  /** Upper bound of 'Number of discrete areas' (see its documentation). */
  inline constexpr int max_discrete_areas = 100000;

  /** The entries of "Joint <name>/Clearance" (without the wear layer's). */
  void
  declare_clearance(dealii::ParameterHandler &prm);

  /** Nominal size of a clearance joint, checked: 0 < c ≤ R1 / 2. */
  struct ClearanceSize
  {
    double       bore_radius      = 0; ///< R1 [m]
    double       radial_clearance = 0; ///< c = R1 − R2 [m]
    unsigned int n_areas          = 0; ///< samples of each profile
  };

  /** Bore radius, radial clearance and number of discrete areas (@p r inside "Clearance"). */
  ClearanceSize
  read_clearance_size(ParameterReader &r);

  /** Axial length, materials and the effective-radius convention into @p d. */
  void
  read_clearance_materials(ParameterReader &r, ClearanceJointDescription &d);

  /**
   * The "Slices" subsection (@p r inside "Clearance"), checked against the joint @p d
   * (its axial length, normal force law and persistent-contact mode, read before).
   */
  SliceLayout
  read_slice_layout(ParameterReader &r, const ClearanceJointDescription &d);

  /**
   * Warn (into @p warnings) when joint @p joint's friction coefficient @p mu is above 1:
   * valid, since clean metals in vacuum and elastomers exceed 1, but far above the 0.1 …
   * 0.8 of the dry metal pairs of pin joints (lubricated: 0.05 … 0.15), so most likely
   * a mistake.
   */
  void
  check_friction_coefficient(const std::string &joint, double mu, ValidityWarnings &warnings);
} // namespace wearlink::contact
