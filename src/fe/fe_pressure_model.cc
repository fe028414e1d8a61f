// SPDX-License-Identifier: LGPL-2.1-or-later
#include "fe/fe_pressure_model.h"

#include "base/atomic_file.h"
#include "base/exceptions.h"
#include "base/text.h"
#include "fe/model_pool.h"
#include "fe/pin_bushing_model.h"

#include <filesystem>
#include <iomanip>
#include <sstream>

namespace wearlink::fe
{
  FePressureModel::FePressureModel(const FeSettings &settings)
    : settings(settings)
  {
  }

  FePressureModel::~FePressureModel() = default;

  // A new mesh only when the profiles left the reach of the current one ('Remesh
  // depth'); the pool decides, and may hand out the model the joint's fe force law
  // made for the same geometry.
  void
  FePressureModel::geometry_changed()
  {
    const auto &g = geometry();
    if (model && within_reach(*model, g, settings))
      {
        use_profiles(*model, g);
        return;
      }
    bool reused = false;
    auto next   = shared_model(g, settings, &reused);
    if (next == model)
      return;
    if (model && created_model)
      {
        const auto &st = model->statistics();
        past_mesh_time += st.mesh_time;
        past_setup_time += st.assembly_time + st.factorization_time;
        past_compliance_time += model->compliance_time();
      }
    model         = std::move(next);
    created_model = !reused;
    ++mesh_counter;
  }

  const contact::JointGeometry *
  FePressureModel::meshed_geometry() const
  {
    return model ? &model->meshed_geometry() : nullptr;
  }

  void
  FePressureModel::restore_geometry(const contact::JointGeometry &meshed, const contact::JointGeometry &current)
  {
    update_geometry(meshed);
    update_geometry(current);
  }

  PhaseTimings
  FePressureModel::timings() const
  {
    double mesh = past_mesh_time, setup = past_setup_time, compliance = past_compliance_time;
    if (model && created_model)
      {
        const auto &st = model->statistics();
        mesh += st.mesh_time;
        setup += st.assembly_time + st.factorization_time;
        compliance += model->compliance_time();
      }
    PhaseTimings t;
    t.meshing       = mesh;
    t.fe_setup      = setup;
    t.fe_compliance = compliance;
    return t;
  }

  namespace
  {
    /** The FE load case of a multibody load: the pin pushed by −(bushing's force on it). */
    LoadCase
    load_case(const contact::ContactLoad &load)
    {
      LoadCase lc;
      lc.control       = Control::force;
      lc.bushing_angle = load.bushing_angle;
      lc.pin_angle     = load.pin_angle;
      lc.load          = {{-load.force[0], -load.force[1]}};
      return lc;
    }
  } // namespace

  // A load state the solver fails on is named in full (the force in both components, the
  // body angles to 17 digits), so that `wearlink contact` with the worn profiles of the
  // run's checkpoint reproduces it.
  ContactResult
  FePressureModel::solve_or_explain(const contact::ContactLoad &load, const double wear_compliance)
  {
    try
      {
        auto lc            = load_case(load);
        lc.wear_compliance = wear_compliance;
        return model->solve(lc, SolverKind::condensed);
      }
    catch (const NumericalError &e)
      {
        const auto lc = load_case(load); // + 0.0: no "-0" for a zero component
        throw NumericalError(std::string(e.what()) + " The load state: force on the pin (" +
                             format_number(lc.load[0] + 0.0) + ", " + format_number(lc.load[1] + 0.0) +
                             ") N (global), bushing angle " + format_number(lc.bushing_angle) + " rad, pin angle " +
                             format_number(lc.pin_angle) + " rad.");
      }
  }

  bool
  FePressureModel::write_fields(const contact::ContactLoad &load, const std::string &stem)
  {
    if (model == nullptr || (load.force[0] == 0 && load.force[1] == 0))
      return false;
    use_profiles(*model, geometry());
    const ContactResult r = model->solve(load_case(load), SolverKind::condensed, stem + ".vtu");
    std::ostringstream  csv;
    csv << std::setprecision(12) << "pin_angle_rad,bore_angle_rad,pressure_Pa,force_N\n";
    for (std::size_t i = 0; i < r.pressure.size(); ++i)
      csv << r.pin_angle[i] << ',' << r.bore_angle[i] << ',' << r.pressure[i] << ',' << r.force[i] << '\n';
    write_file_atomically(stem + "_pressure.csv", csv.str());
    return true;
  }

  std::string
  FePressureModel::mesh_file() const
  {
    return model ? model->mesh_path() : std::string();
  }

  void
  FePressureModel::evaluate(const contact::ContactLoad &load, contact::SurfacePressure &out)
  {
    AssertThrow(model != nullptr, dealii::ExcMessage("The fe pressure model was evaluated before update_geometry()."));
    out.pin.assign(geometry().pin.n_points(), 0.0);
    out.bore.assign(geometry().bore.n_points(), 0.0);
    if (load.force[0] == 0 && load.force[1] == 0)
      return;
    use_profiles(*model, geometry());
    out = model->surface_pressure(solve_or_explain(load));
  }

  void
  FePressureModel::evaluate_wearing(const contact::ContactLoad    &load,
                                    const contact::WearCompliance &c,
                                    contact::SurfacePressure      &out)
  {
    AssertThrow(model != nullptr, dealii::ExcMessage("The fe pressure model was evaluated before update_geometry()."));
    out.pin.assign(geometry().pin.n_points(), 0.0);
    out.bore.assign(geometry().bore.n_points(), 0.0);
    if (load.force[0] == 0 && load.force[1] == 0)
      return;
    use_profiles(*model, geometry());
    out = model->surface_pressure(solve_or_explain(load, c.total()));
  }
} // namespace wearlink::fe
