// SPDX-License-Identifier: LGPL-2.1-or-later
// The FE contact model of one shaft–bushing pair, as seen from outside src/fe: no
// deal.II type appears here (pimpl). It meshes the pair with gmsh, assembles
// plane-strain elasticity with deal.II, and solves frictionless contact for load states
// with either solver (see fe/contact_solver.h for the discretization):
//   - condensed (production): per-body factorization once per mesh, compliance columns
//     on the contact candidates (computed on demand, cached), a small active-set QP per
//     load state;
//   - reference: the same discrete problem solved on the full FE system with an
//     active-set (semismooth Newton) iteration that re-factors the constrained system.
//
// Load introduction (documented choice): the pin is loaded through a rigid core of
// radius 'Pin core radius fraction' × min R2*. Under force control the core translates
// by the unknown pin displacement U (no rotation: the pin's link holds its angle) and
// the contact resultant balances the load; under displacement control the core sits at
// the given eccentricity. The bushing ring is fixed on its outer edge.
//
// Frames: loads and eccentricities are global; the bore lives in the bushing frame
// (angle θ_bushing) and the pin in the pin frame (θ_pin); a worn pin is placed at the
// relative angle θ_pin − θ_bushing. Forces are in N for the whole axial length L; the FE
// model is per unit length (plane strain), so P = F / L.
#pragma once

#include "contact/pressure_model.h"
#include "fe/fe_settings.h"
#include "fe/pin_bushing_mesher.h"

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace wearlink::fe
{
  struct CondensedTimings; // fe/contact_solver.h

  enum class SolverKind
  {
    condensed,
    reference
  };

  enum class Control
  {
    force,       ///< the load on the pin is given; its displacement is unknown
    displacement ///< the eccentricity is given; the contact force follows
  };

  /** One load state. */
  struct LoadCase
  {
    Control control       = Control::force;
    double  bushing_angle = 0; ///< θ of the body holding the bore [rad]
    double  pin_angle     = 0; ///< θ of the body holding the pin [rad]
    /** Force control: force on the pin from its link, pushing it into the bore, global [N]. */
    std::array<double, 2> load{};
    /** Displacement control: pin centre − bore centre, global [m]. */
    std::array<double, 2> eccentricity{};
    /**
     * Depth both surfaces together wear per unit pressure during the state [m/Pa]
     * (the sequential wear update; condensed solver only): the state is solved at the
     * end of its own wear, the gap at each pin node opened by this × its pressure.
     */
    double wear_compliance = 0;
  };

  /** Result of one load state. */
  struct ContactResult
  {
    /** L ∫ p n ds over the pin surface (n outward), global [N]: the load carried. */
    std::array<double, 2> resultant{};
    /** Pin centre − bore centre at equilibrium, global [m]. */
    std::array<double, 2> pin_displacement{};
    /** |resultant − load| / |load| (force control; 0 for displacement control). */
    double       equilibrium_relative_residual = 0;
    double       peak_pressure                 = 0; ///< [Pa]
    double       half_angle                    = 0; ///< half the contact arc seen from the bore centre [rad]
    double       half_width                    = 0; ///< half the contact arc length along the pin surface [m]
    unsigned int n_active                      = 0;
    unsigned int iterations                    = 0; ///< active-set iterations (summed over kinematic updates)
    bool         monotone   = false; ///< the condensed solver needed its monotone phase (last kinematic update)
    double       solve_time = 0;     ///< wall time of this load state [s]
    /** Per pin contact candidate (sorted by pin-frame angle): */
    std::vector<double> pin_angle;  ///< pin-frame angle [rad]
    std::vector<double> bore_angle; ///< bushing-frame angle of its contact point [rad] (see solve())
    std::vector<double> pressure;   ///< nodal contact pressure [Pa]
    std::vector<double> force;      ///< nodal contact force over the length L [N]
  };

  /** Sizes and timings of the model's set-up. */
  struct SetupStatistics
  {
    MeshStatistics mesh;
    unsigned long  n_dofs             = 0;
    unsigned long  n_pin_candidates   = 0;
    unsigned long  n_bore_candidates  = 0;
    double         mesh_time          = 0; ///< gmsh [s]
    double         assembly_time      = 0; ///< read mesh, DoFs, assemble K [s]
    double         factorization_time = 0; ///< clamped factorization (condensed) [s]
  };

  class PinBushingModel
  {
  public:
    /**
     * Mesh and assemble the pair; @p msh_path receives the gmsh mesh. The
     * factorization of the condensed solver is built on its first use (or by
     * prepare_condensed()). InputError for an invalid geometry.
     */
    PinBushingModel(const contact::JointGeometry &geometry, const FeSettings &settings, const std::string &msh_path);
    ~PinBushingModel();
    PinBushingModel(const PinBushingModel &) = delete;
    PinBushingModel &
    operator=(const PinBushingModel &) = delete;

    /**
     * Solve one load state; if @p vtu_path is not empty, write the fields there. The
     * condensed solver sees only the contact window (contact_solver.h): outside it the
     * result's bore angles are NaN unless @p all_angles (or a VTU) asks for every
     * candidate's.
     */
    ContactResult
    solve(const LoadCase &load, SolverKind solver, const std::string &vtu_path = "", bool all_angles = false);

    /** Factor the clamped system now (otherwise on the first condensed solve). */
    void
    prepare_condensed();

    /** Compute every compliance column (the full influence matrices). */
    void
    precompute_compliance();

    /**
     * True when both bodies' compliance columns are rotations of one sector's
     * (BoundaryCompliance; a periodic mesh that passed its symmetry check), so that
     * precompute_compliance() computes only that sector.
     */
    bool
    compliance_is_periodic();

    /** Time spent computing compliance columns so far [s]. */
    double
    compliance_time() const;

    /** Number of compliance columns computed so far (back substitutions). */
    unsigned long
    n_compliance_solves() const;

    /** The condensed solver's time by phase so far (fe/contact_solver.h; zero before its first solve). */
    const CondensedTimings &
    condensed_timings() const;

    const SetupStatistics &
    statistics() const;

    /**
     * Keep the mesh, its factorization and the compliance columns, and solve from now
     * on with these (worn) profiles: the bore's enters the gaps exactly, the pin's as a
     * radial offset of each contact candidate from the meshed surface. What is kept is
     * the elastic compliance of the meshed bodies, an approximation of order
     * (profile drift / element size) in the surface layer; profile_drift() measures
     * the drift so that the caller can re-mesh when it grows (FeSettings::remesh_depth).
     * InputError unless the sample counts equal the meshed profiles'.
     */
    void
    update_profiles(const Profile &bore, const Profile &pin);

    /** max |r − r_meshed| over both profiles' samples [m] (∞ for other sample counts). */
    double
    profile_drift(const Profile &bore, const Profile &pin) const;

    /** The geometry the mesh was made of, and the one in use (update_profiles). */
    const contact::JointGeometry &
    meshed_geometry() const;
    const contact::JointGeometry &
    current_geometry() const;

    /** The gmsh file of the mesh. */
    const std::string &
    mesh_path() const;

    /**
     * Pressure per discrete area of both profiles [Pa]: the nodal forces are spread
     * over their tributary arcs and collected on the areas [ψ_k ± π/N] of each
     * profile (pin: pin frame; bore: bushing frame). Σ_k p_k A_k is the sum of the
     * nodal force magnitudes, each placed at its contact point, so the areas' radial
     * resultant Σ_k p_k A_k u_k is the nodal forces' resultant (the load) to the
     * areas' direction quantization and to the lean of the nodal forces, which act
     * along the pin's normals, from the radii: (e/R) sin α on a round pair, the
     * profile's slope on a worn one (tests/unit/contact/pressure_contract_test.cc).
     */
    contact::SurfacePressure
    surface_pressure(const ContactResult &result) const;

  private:
    class Impl;
    std::unique_ptr<Impl> impl;
  };
} // namespace wearlink::fe
