// SPDX-License-Identifier: LGPL-2.1-or-later
// The `fe` pressure model: contact pressure on both surfaces of a shaft–bushing pair from
// the 2D plane-strain contact FE model of the actual (worn) pin and bushing
// (doc/models.md §5; doc/architecture.md §3). It is constructed only when a scene selects
// it; nothing is meshed or factored before update_geometry(), which re-meshes only when
// the profiles have moved beyond 'Remesh depth' (otherwise the worn profiles enter the
// gaps of the kept mesh), and shares the model with the joint's `fe` force law
// (fe/model_pool.h). The set-up of a shared model is reported by the holder that made it. Each load state is solved
// under force control with the condensed solver: the pin is pushed into the bore by
// −ContactLoad::force (the bushing's force on the pin), and the resulting pressure is
// returned per discrete area of each profile, each in its own body frame. The
// eccentricity of the rigid-body model is not used: the FE model finds the elastic
// equilibrium position itself. No deal.II type leaks out (pimpl in PinBushingModel).
#pragma once

#include "contact/pressure_model.h"
#include "fe/fe_settings.h"

#include <memory>

namespace wearlink::fe
{
  class PinBushingModel;
  struct ContactResult;

  class FePressureModel
    : public contact::PressureModel
    , public contact::FeGeometryHooks
  {
  public:
    explicit FePressureModel(const FeSettings &settings);
    ~FePressureModel() override;

    void
    evaluate(const contact::ContactLoad &load, contact::SurfacePressure &out) override;

    /**
     * The condensed solve with the state's wear in series with the FE compliance (the
     * gap at each pin node opens by c × its pressure): the pressure at the end of the
     * state's wear, a backward-Euler step stable for any c.
     */
    void
    evaluate_wearing(const contact::ContactLoad    &load,
                     const contact::WearCompliance &c,
                     contact::SurfacePressure      &out) override;

    contact::FeGeometryHooks *
    fe_hooks() override
    {
      return this;
    }

    PhaseTimings
    timings() const override;

    bool
    write_fields(const contact::ContactLoad &load, const std::string &stem) override;

    std::string
    mesh_file() const override;

    /** Number of meshes in use so far (a new one whenever the profiles moved beyond 'Remesh depth'). */
    unsigned int
    n_meshes() const
    {
      return mesh_counter;
    }

    /** The geometry the current mesh was made of (resume: re-mesh it, then update). */
    const contact::JointGeometry *
    meshed_geometry() const override;

    void
    restore_geometry(const contact::JointGeometry &meshed, const contact::JointGeometry &current) override;

  protected:
    /**
     * A new mesh only when the profiles left the reach of the current one ('Remesh
     * depth'); otherwise the current profiles enter the kept mesh's gaps. The worn areas
     * of remove_material() enter them at the next solve.
     */
    void
    geometry_changed() override;

  private:
    /** The condensed solve of @p load; NumericalError naming the load state if it fails. */
    ContactResult
    solve_or_explain(const contact::ContactLoad &load, double wear_compliance = 0);

    const FeSettings                 settings;
    unsigned int                     mesh_counter = 0;
    std::shared_ptr<PinBushingModel> model; ///< shared (fe/model_pool.h)
    /** Set-up times of the models this one created and already let go [s]. */
    double past_mesh_time = 0, past_setup_time = 0, past_compliance_time = 0;
    bool   created_model = false; ///< the current model was meshed for this one (its set-up is reported here)
  };
} // namespace wearlink::fe
