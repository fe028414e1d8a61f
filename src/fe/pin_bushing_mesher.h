// SPDX-License-Identifier: LGPL-2.1-or-later
// Geometry and mesh of one shaft–bushing pair with the gmsh C++ API.
//
// From the two discrete profiles (bore R1*(ψ) in the bushing frame, pin R2*(ψ) in the
// pin frame) this builds, each body in its own frame and centred at its joint centre:
//   - the pin annulus between a rigid core circle (radius r_core) and the pin surface;
//   - the bushing ring between the bore and a fixed outer circle (radius r_out).
// At zero eccentricity and zero relative rotation the two bodies do not overlap (the pin
// must lie inside the bore), so one mesh holds both; the eccentricity and relative angle
// of a load state enter only through the contact kinematics (non-matching meshes).
//
// The contact surfaces are splines through the profile samples, each split into four
// quarter arcs with a uniform (transfinite) node spacing equal to the surface element
// size, so that a round pair gets a mirror-symmetric surface discretization (or, for a
// fixed load direction, one uniformly spaced refined arc centred on it and a graded
// rest). Away from
// the surfaces the size grows linearly with the distance (gmsh Distance + Threshold
// fields). Quadrilaterals (Frontal-Delaunay for quads + Blossom recombination) for
// deal.II; physical groups are named "MaterialID:n" / "BoundaryID:n" with the ids of
// fe/boundary_ids.h, which GridIn::read_msh understands.
#pragma once

#include "base/profile.h"

#include <string>

namespace wearlink::fe
{
  /** What the mesher needs besides the two profiles (all lengths in m). */
  struct MeshSpecification
  {
    double core_radius          = 0; ///< rigid core of the pin
    double outer_radius         = 0; ///< fixed outer edge of the bushing
    double surface_element_size = 0; ///< along both contact surfaces
    double max_element_size     = 0; ///< far from the surfaces
    double size_growth          = 0; ///< dh/dd away from the surfaces [-]
    double layer_thickness      = 0; ///< depth kept at the surface size [m]
    /**
     * Half-angle of the arc of each contact surface meshed at the surface element size
     * [rad]; ≥ π (the default) refines the whole circumference, as a wear loop with a
     * rotating load needs. A smaller arc (for a fixed load direction, as in the
     * `contact` command) is centred on the angles below, and the size grows with the
     * distance from the arc elsewhere.
     */
    double refined_half_angle  = 4;
    double bore_refined_centre = 0; ///< centre of the refined arc, bushing frame [rad]
    double pin_refined_centre  = 0; ///< centre of the refined arc, pin frame [rad]
    /**
     * Round profiles refined all around are meshed as identical sectors (see
     * write_pin_bushing_mesh()), so that each body's compliance is invariant under the
     * rotation by one sector; false: the general construction (as for worn profiles).
     */
    bool periodic = true;
  };

  /** Contact-surface elements per sector of a periodic mesh (after the final split). */
  constexpr unsigned int periodic_sector_elements = 32;

  /** Counts of the generated mesh. */
  struct MeshStatistics
  {
    unsigned long n_nodes                    = 0;
    unsigned long n_quadrilaterals           = 0;
    unsigned long n_refined_surface_segments = 0; ///< both surfaces, at the surface size
    /** Sectors of a periodic mesh per body (0: not periodic); periodic_sector_elements surface elements each. */
    unsigned int pin_sectors = 0, bore_sectors = 0;
  };

  /**
   * Check that the two profiles and the specification describe a valid pair: every
   * size positive and finite, the pin strictly inside the bore for any relative
   * rotation (max R2* < min R1*), the core inside the pin, the outer edge outside the
   * bore. An InputError says what is wrong and how to fix it.
   */
  void
  check_pin_bushing_geometry(const Profile &bore, const Profile &pin, const MeshSpecification &spec);

  /**
   * Mesh the pair and write it as a gmsh .msh file to @p msh_path (atomically). Each
   * call is one gmsh session (counted in the EffectLedger as "gmsh sessions").
   *
   * Round profiles refined all around (the wear loop's fresh joints, the fe law's round
   * tables) with spec.periodic: each body is K identical sectors. gmsh meshes one
   * sector (its contact arc transfinite with periodic_sector_elements / 2 segments
   * before the split, its two radial edges periodic, sizes from the same fields), and
   * the mesher writes K copies of it rotated by 2π k/K, merging the shared edges'
   * nodes (gmsh's own periodic surfaces need its ANN search, which Debian's gmsh
   * lacks). K = 2πR / (periodic_sector_elements × surface size), rounded, per body.
   * The compliance of such a body is the same for every sector (BoundaryCompliance
   * computes one sector's columns); meshes/pin_bushing_sector.geo is the sector as a
   * .geo.
   */
  MeshStatistics
  write_pin_bushing_mesh(const Profile           &bore,
                         const Profile           &pin,
                         const MeshSpecification &spec,
                         const std::string       &msh_path);
} // namespace wearlink::fe
