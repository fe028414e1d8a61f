// SPDX-License-Identifier: LGPL-2.1-or-later
// The pressure-model family: given the (worn) geometry of one shaft–bushing pair and
// the contact load that the multibody model computed, return the contact pressure on
// each discrete area of both surfaces. Members (chosen per joint by name):
//   hertz-strip : the normal force over a Hertz line-contact strip at the contact direction, its
//                 width from the worn surfaces (or, as the seed, from the local radii)
//   winkler     : elastic foundation from the local overlap of the profiles
//   fe          : 2D plane-strain contact FE of the actual pin and bushing (src/fe)
// The wear layer integrates Archard's law with these pressures (doc/models.md §4, §5).
//
// Frames: the bore profile and its pressure live in the bushing body's frame, the pin
// profile and its pressure in the pin body's frame (ψ measured from each body's x-axis).
#pragma once

#include "base/profile.h"
#include "base/registry.h"
#include "base/timings.h"
#include "base/validity_warnings.h"

#include <array>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace wearlink::contact
{
  /** Isotropic linear-elastic material. */
  struct Material
  {
    double youngs_modulus = 0; ///< E [Pa]
    double poisson_ratio  = 0; ///< ν [-]

    /** (1 − ν²)/E [1/Pa], the σ of seed eq. 10. */
    double
    compliance() const
    {
      return (1 - poisson_ratio * poisson_ratio) / youngs_modulus;
    }
  };

  /** 1/E* = (1 − ν1²)/E1 + (1 − ν2²)/E2 [Pa] (doc/models.md §5.1). */
  inline double
  effective_modulus(const Material &a, const Material &b)
  {
    return 1.0 / (a.compliance() + b.compliance());
  }

  /**
   * Modulus of a Winkler layer of the two surfaces in series, 1/(1/E_f,a + 1/E_f,b) [Pa],
   * with E_f = E(1 − ν)/((1 + ν)(1 − 2ν)) the constrained modulus of each layer.
   */
  inline double
  series_foundation_modulus(const Material &a, const Material &b)
  {
    const auto layer = [](const Material &m) {
      const double nu = m.poisson_ratio;
      return m.youngs_modulus * (1 - nu) / ((1 + nu) * (1 - 2 * nu));
    };
    return 1.0 / (1.0 / layer(a) + 1.0 / layer(b));
  }

  /** Geometry and materials of one shaft–bushing pair. */
  struct JointGeometry
  {
    Profile  bore;             ///< R1*(ψ) [m], bushing frame
    Profile  pin;              ///< R2*(ψ) [m], pin frame
    double   axial_length = 0; ///< contact length along the pin axis [m]
    Material bushing;
    Material pin_material;
  };

  /**
   * One load state of the joint, as the multibody model saw it. The pressure models are
   * frictionless, so the wear layer passes the normal part of the contact force only:
   * force = −normal_force · (cos φ*, sin φ*).
   */
  struct ContactLoad
  {
    double                bushing_angle = 0; ///< θ of the body holding the bore [rad]
    double                pin_angle     = 0; ///< θ of the body holding the pin [rad]
    std::array<double, 2> eccentricity{};    ///< pin centre − bore centre, global [m]
    std::array<double, 2> force{};           ///< force of the bushing on the pin, global [N]
    double                penetration   = 0; ///< δ of the rigid-body contact model [m]
    double                normal_force  = 0; ///< F_n ≥ 0 [N]
    double                contact_angle = 0; ///< φ*, global direction from bore centre to contact [rad]
  };

  /** Contact pressure per discrete area of each surface. */
  struct SurfacePressure
  {
    std::vector<double> bore; ///< [Pa] at the bore profile's sample angles
    std::vector<double> pin;  ///< [Pa] at the pin profile's sample angles
  };

  /**
   * How deep each surface wears per unit contact pressure during one load state of a
   * wear iteration: c = f k_D |v_t| Δt [m/Pa], with f the iteration's extrapolation
   * factor (wear/archard.h, the sequential wear update).
   */
  struct WearCompliance
  {
    double bore = 0; ///< [m/Pa]
    double pin  = 0; ///< [m/Pa]

    double
    total() const
    {
      return bore + pin;
    }
  };

  /**
   * Material removed from the discrete areas of both surfaces by one load state: area
   * bore_areas[i] of the bore deepens by bore_depth[i] (its radius grows), area
   * pin_areas[i] of the pin by pin_depth[i] (its radius shrinks) [m].
   */
  struct SurfaceWear
  {
    std::vector<unsigned int> bore_areas, pin_areas;
    std::vector<double>       bore_depth, pin_depth;

    void
    clear()
    {
      bore_areas.clear();
      pin_areas.clear();
      bore_depth.clear();
      pin_depth.clear();
    }
  };

  /**
   * What only a model that meshes and solves the actual bodies (gmsh + deal.II: the `fe`
   * model) has beyond the pressure: its mesh and fields as files, the geometry of the mesh
   * it keeps across small wear (a checkpoint stores it so that a resumed run meshes the
   * same), and the wall time of its heavy phases. PressureModel::fe_hooks() returns it,
   * nullptr for a model that does not mesh; callers ask there, the other models carry
   * none of it.
   */
  class FeGeometryHooks
  {
  public:
    virtual ~FeGeometryHooks() = default;

    /** Wall time spent so far in the heavy phases (meshing, FE set-up, compliance) [s]. */
    virtual PhaseTimings
    timings() const = 0;

    /**
     * Write the fields for @p load next to @p stem: stem.vtu (displacement, stresses,
     * von Mises) and stem_pressure.csv (contact pressure per node, both body frames);
     * false if there is nothing to write (no mesh yet, or no load).
     */
    virtual bool
    write_fields(const ContactLoad &load, const std::string &stem) = 0;

    /** The gmsh file of the current mesh ("" before the first). */
    virtual std::string
    mesh_file() const = 0;

    /** The geometry of the mesh in use ('Remesh depth' keeps it across small updates); nullptr before the first. */
    virtual const JointGeometry *
    meshed_geometry() const = 0;

    /** Resume: as if the model had seen @p meshed and then @p current. */
    virtual void
    restore_geometry(const JointGeometry &meshed, const JointGeometry &current) = 0;
  };

  /**
   * A pressure model. The base class holds the joint's current geometry and writes the
   * wear update once (remove_material()); a model derives from it what it needs in
   * geometry_changed() and, for the cheap local update of the sequential wear, in
   * material_removed().
   */
  class PressureModel
  {
  public:
    virtual ~PressureModel() = default;

    /**
     * Take @p geometry as the current one and (re)build whatever the model needs for it
     * (for `fe`: mesh, factorization, compliance). Called before the first evaluate()
     * and after every wear update of the profiles.
     */
    void
    update_geometry(const JointGeometry &geometry);

    /**
     * Remove @p wear from the current profiles (the sequential wear update, after each
     * load state): bore area k deepens, its radius grows; pin area k's radius shrinks.
     * A cheap local update (material_removed()); update_geometry() with the iteration's
     * end profiles follows at the end of the iteration.
     */
    void
    remove_material(const SurfaceWear &wear);

    /** The current geometry: the last one given to update_geometry(), less the material removed since. */
    const JointGeometry &
    geometry() const
    {
      return current;
    }

    /**
     * Pressure for one load state. @p out's vectors are resized to the profiles'
     * sample counts. The pressure carries the load it is given: on each surface
     * Σ_k p_k A_k u(ψ_k + θ) (A_k = L R_k Δψ, u the outward radial direction in global
     * axes, θ the surface's body angle) is F_n u(φ*), the force with which the pin
     * presses on the bore (−load.force), to the direction quantization of the areas —
     * the contract every registered model passes
     * (tests/unit/contact/pressure_contract_test.cc). Σ_k p_k A_k itself exceeds F_n
     * on a wide arc (wear/archard.h).
     */
    virtual void
    evaluate(const ContactLoad &load, SurfacePressure &out) = 0;

    /**
     * The pressure of a load state during which the surfaces wear by @p c × p: the
     * sequential wear update (wear/archard.h) removes c × p after the state, so that the
     * next state meets the worn surfaces. A model that solves the contact with the wear
     * in series with its own compliance returns the pressure at the state's end (the
     * backward-Euler step, stable for any c: winkler, fe); the default returns
     * evaluate()'s pressure, which is a stable step while c.total() ≤
     * stable_compliance(load) (the caller splits a state that exceeds it).
     */
    virtual void
    evaluate_wearing(const ContactLoad &load, const WearCompliance & /*c*/, SurfacePressure &out)
    {
      evaluate(load, out);
    }

    /**
     * The largest wear compliance c.total() [m/Pa] for which evaluate_wearing() of
     * @p load is a stable explicit step: about the reciprocal of the contact's stiffness
     * against a change of shape of the worn surfaces at the contact width. +∞ for models
     * whose evaluate_wearing() is implicit. Call after evaluate_wearing() of the same
     * load (models may keep what they computed there).
     */
    virtual double
    stable_compliance(const ContactLoad & /*load*/) const
    {
      return std::numeric_limits<double>::infinity();
    }

    /**
     * Warnings, under joint @p joint's name, about the evaluations so far that left the
     * model's validity, into @p w (which keeps the worst value of each: one warning per
     * joint and kind). hertz-strip: a Hertz half-angle past 90°. Default: none.
     */
    virtual void
    check_validity(const std::string & /*joint*/, ValidityWarnings & /*w*/) const
    {
    }

    /** The hooks of a model that meshes and solves the actual bodies (FeGeometryHooks); nullptr for the others. */
    virtual FeGeometryHooks *
    fe_hooks()
    {
      return nullptr;
    }

  protected:
    /** Rebuild what the model derives from geometry(): called by update_geometry(). */
    virtual void
    geometry_changed() = 0;

    /**
     * Refresh what the model derives from the areas @p wear touched, after
     * remove_material() changed geometry() there. Default: nothing (the model reads
     * geometry() at each evaluation).
     */
    virtual void
    material_removed(const SurfaceWear & /*wear*/)
    {
    }

  private:
    JointGeometry current;
  };

  /** The registry of pressure models (filled by register_contact_effects / register_fe_effects). */
  Registry<PressureModel> &
  pressure_models();
} // namespace wearlink::contact
