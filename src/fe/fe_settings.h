// SPDX-License-Identifier: LGPL-2.1-or-later
// The numerical knobs of the FE contact model of one shaft–bushing pair (mesh sizes,
// element degree, refinement, rigid pin core, contact-solver limits), declared once
// with their units. The same declarations serve the `fe` pressure-model plugin
// ("…/Pressure model/fe/…") and the `wearlink contact` command ("FE model/…").
// No deal.II types beyond the ParameterHandler appear here, so app/ may include it.
#pragma once

#include "base/parameters.h"

#include <cmath>
#include <string>

namespace wearlink::fe
{
  /** Numerical settings of the pin–bushing FE model (all lengths in m). */
  struct FeSettings
  {
    /** Element size along both contact surfaces [m]. */
    double surface_element_size = 25e-6;
    /** Largest element size away from the contact surfaces [m]. */
    double max_element_size = 1.5e-3;
    /**
     * Growth of the element size with the distance d from the nearest contact surface:
     * h(d) = min(h_surface + growth · d, h_max) [-].
     */
    double size_growth = 0.3;
    /**
     * Depth below both contact surfaces over which the element size stays at the
     * surface size before it starts to grow [m]: the contact stresses decay over a
     * depth of about the contact half-width, which must be resolved as well.
     */
    double refined_layer_thickness = 0.1e-3;
    /** Radius of the rigid core of the pin as a fraction of its smallest radius [-]. */
    double core_radius_fraction = 0.4;
    /**
     * Outer radius of the bushing ring [m]; 0 means "outer radius ratio × mean bore
     * radius" (the plugin's case, where the ring is part of a link).
     */
    double outer_radius = 0;
    /** Outer radius / mean bore radius, used when outer_radius = 0 [-]. */
    double outer_radius_ratio = 2;
    /** Polynomial degree of the FE_Q elements (1 or 2). */
    unsigned int degree = 1;
    /** Global refinements of the gmsh mesh (each halves every element size). */
    unsigned int refinements = 0;
    /**
     * Re-mesh when a profile has moved by more than this fraction of the surface
     * element size (after refinements) since its mesh was made; below it the mesh, its
     * factorization and the compliance columns are kept and the worn profiles enter
     * through the gaps only (PinBushingModel::update_profiles). 0: re-mesh at every
     * profile change (the exact path) [-].
     */
    double remesh_depth = 0;
    /** Iteration limit of the active-set contact solvers. */
    unsigned int max_active_set_iterations = 100;
    /**
     * Half-angle of the refined arc of each contact surface [rad] (≥ π: the whole
     * circumference, needed when the load direction changes, as in a wear loop). Set
     * by the `contact` command for its fixed load direction; not a plugin parameter.
     */
    double refined_arc_half_angle  = 4;
    double refined_arc_bore_centre = 0; ///< bushing-frame centre of the refined arc [rad]
    double refined_arc_pin_centre  = 0; ///< pin-frame centre of the refined arc [rad]
    /**
     * Primal–dual active-set iterations of the condensed solver before its monotone
     * method takes over (see CondensedContactSolver::solve); 0: the monotone method
     * alone. Not a scene parameter (tests compare the two).
     */
    unsigned int primal_dual_iterations = 30;
    /**
     * Distribute the reference solver over the MPI ranks of MPI_COMM_WORLD (METIS
     * partitions; MPI must be initialized by the program). Not a scene parameter.
     */
    bool distribute_reference = false;
    /** Directory for the generated .msh files ("" = a temporary directory). */
    std::string mesh_directory;

    /** Element size along the contact surfaces after the global refinements [m]. */
    double
    effective_surface_element_size() const
    {
      return std::ldexp(surface_element_size, -static_cast<int>(refinements));
    }

    /** InputError if a size is not positive or the fractions are out of range. */
    void
    check(const std::string &where) const;
  };

  /** Declare the FE numerics in the current subsection of @p prm. */
  void
  declare_fe_settings(dealii::ParameterHandler &prm);

  /** Read what declare_fe_settings() declared; @p reader is in the same subsection. */
  FeSettings
  read_fe_settings(const ParameterReader &reader);
} // namespace wearlink::fe
