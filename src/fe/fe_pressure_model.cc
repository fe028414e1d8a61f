// SPDX-License-Identifier: LGPL-2.1-or-later
#include "fe/fe_pressure_model.h"

#include "base/atomic_file.h"
#include "base/exceptions.h"
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

  // A temporary mesh directory is the model's own: it goes with the model (the meshes
  // a user wants to keep are written where 'Mesh directory' says, and the wear layer
  // writes the worn geometry's .msh into the run's output directory itself).
  FePressureModel::~FePressureModel()
  {
    model.reset(); // before its temporary mesh directory goes
  }

  // A new mesh per geometry: worn profiles change the domain, so the mesh, the
  // stiffness, its factorization and the cached compliance are all rebuilt.
  void
  FePressureModel::update_geometry(const contact::JointGeometry &g)
  {
    if (mesh_directory.empty())
      {
        if (settings.mesh_directory.empty())
          {
            temporary_meshes = std::make_unique<TemporaryDirectory>("fe");
            mesh_directory   = temporary_meshes->path();
          }
        else
          {
            mesh_directory = settings.mesh_directory;
            make_output_directory(mesh_directory);
          }
      }
    if (model)
      {
        const auto &st = model->statistics();
        past_mesh_time += st.mesh_time;
        past_setup_time += st.assembly_time + st.factorization_time;
        past_compliance_time += model->compliance_time();
      }
    model.reset();
    geometry              = g;
    const std::string msh = mesh_directory + "/pin_bushing_" + std::to_string(mesh_counter++) + ".msh";
    model                 = std::make_unique<PinBushingModel>(geometry, settings, msh);
    model->prepare_condensed();
  }

  PhaseTimings
  FePressureModel::timings() const
  {
    double mesh = past_mesh_time, setup = past_setup_time, compliance = past_compliance_time;
    if (model)
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
      lc.load          = {-load.force[0], -load.force[1]};
      return lc;
    }
  } // namespace

  bool
  FePressureModel::write_fields(const contact::ContactLoad &load, const std::string &stem)
  {
    if (model == nullptr || (load.force[0] == 0 && load.force[1] == 0))
      return false;
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
    return mesh_counter == 0 ? std::string() :
                               mesh_directory + "/pin_bushing_" + std::to_string(mesh_counter - 1) + ".msh";
  }

  void
  FePressureModel::evaluate(const contact::ContactLoad &load, contact::SurfacePressure &out)
  {
    AssertThrow(model != nullptr, dealii::ExcMessage("The fe pressure model was evaluated before update_geometry()."));
    out.pin.assign(geometry.pin.n_points(), 0.0);
    out.bore.assign(geometry.bore.n_points(), 0.0);
    if (load.force[0] == 0 && load.force[1] == 0)
      return;
    const ContactResult r = model->solve(load_case(load), SolverKind::condensed);
    out                   = model->surface_pressure(r);
  }
} // namespace wearlink::fe
