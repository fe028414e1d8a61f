// SPDX-License-Identifier: LGPL-2.1-or-later
// The one place where the ids of the pin–bushing mesh are defined. The gmsh builder
// (pin_bushing_mesher.cc) writes them into the names of its physical groups
// ("BoundaryID:2", "MaterialID:1"), which deal.II's GridIn::read_msh maps onto
// boundary and material ids; the elasticity problem reads them back from here.
// Never use bare literals for these (doc/contributing.md §3; deal.II's step-49 does).
#pragma once

#include <deal.II/base/types.h>

namespace wearlink::fe
{
  namespace boundary_ids
  {
    /** Inner edge of the pin annulus: the rigid core through which the pin is loaded. */
    constexpr dealii::types::boundary_id pin_core = 1;
    /** Outer edge of the pin: its (worn) contact surface R2*(ψ). */
    constexpr dealii::types::boundary_id pin_surface = 2;
    /** Inner edge of the bushing: the (worn) bore R1*(ψ). */
    constexpr dealii::types::boundary_id bore_surface = 3;
    /** Outer edge of the bushing ring: fixed (u = 0). */
    constexpr dealii::types::boundary_id bushing_outer = 4;
  } // namespace boundary_ids

  namespace material_ids
  {
    constexpr dealii::types::material_id pin     = 1;
    constexpr dealii::types::material_id bushing = 2;
  } // namespace material_ids
} // namespace wearlink::fe
