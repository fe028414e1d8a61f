// SPDX-License-Identifier: LGPL-2.1-or-later
#include "fe/model_pool.h"

#include "base/atomic_file.h"

#include <algorithm>
#include <mutex>
#include <string>
#include <vector>

namespace wearlink::fe
{
  namespace
  {
    /** A model and the temporary directory of its mesh file (if it has one). */
    struct Holder
    {
      std::unique_ptr<TemporaryDirectory> directory;
      std::unique_ptr<PinBushingModel>    model;
    };

    struct Entry
    {
      FeSettings                     settings;
      std::weak_ptr<PinBushingModel> model;
    };

    bool
    same_materials(const contact::Material &a, const contact::Material &b)
    {
      return a.youngs_modulus == b.youngs_modulus && a.poisson_ratio == b.poisson_ratio;
    }

    /** Everything that shapes the mesh, the matrix or the solver, except the profiles. */
    bool
    same_setup(const FeSettings &a, const FeSettings &b)
    {
      return a.surface_element_size == b.surface_element_size && a.max_element_size == b.max_element_size &&
             a.size_growth == b.size_growth && a.refined_layer_thickness == b.refined_layer_thickness &&
             a.core_radius_fraction == b.core_radius_fraction && a.outer_radius == b.outer_radius &&
             a.outer_radius_ratio == b.outer_radius_ratio && a.degree == b.degree && a.refinements == b.refinements &&
             a.max_active_set_iterations == b.max_active_set_iterations &&
             a.primal_dual_iterations == b.primal_dual_iterations &&
             a.refined_arc_half_angle == b.refined_arc_half_angle &&
             a.refined_arc_bore_centre == b.refined_arc_bore_centre &&
             a.refined_arc_pin_centre == b.refined_arc_pin_centre && a.distribute_reference == b.distribute_reference &&
             a.remesh_depth == b.remesh_depth && a.mesh_directory == b.mesh_directory;
    }

    std::mutex         pool_mutex;
    std::vector<Entry> pool;
    unsigned long      n_meshes = 0;
  } // namespace

  bool
  within_reach(const PinBushingModel &model, const contact::JointGeometry &g, const FeSettings &s)
  {
    const auto &m = model.meshed_geometry();
    if (m.axial_length != g.axial_length || !same_materials(m.bushing, g.bushing) ||
        !same_materials(m.pin_material, g.pin_material))
      return false;
    const double drift = model.profile_drift(g.bore, g.pin);
    return drift == 0 || drift <= s.remesh_depth * s.effective_surface_element_size();
  }

  namespace
  {
    /** The live model within reach (pool_mutex held), or nullptr. */
    std::shared_ptr<PinBushingModel>
    live_model(const contact::JointGeometry &geometry, const FeSettings &settings)
    {
      pool.erase(std::remove_if(pool.begin(), pool.end(), [](const Entry &e) { return e.model.expired(); }),
                 pool.end());
      for (const auto &e : pool)
        if (same_setup(e.settings, settings))
          if (auto model = e.model.lock(); model && within_reach(*model, geometry, settings))
            return model;
      return nullptr;
    }
  } // namespace

  std::shared_ptr<PinBushingModel>
  find_shared_model(const contact::JointGeometry &geometry, const FeSettings &settings)
  {
    const std::lock_guard<std::mutex> lock(pool_mutex);
    return live_model(geometry, settings);
  }

  std::shared_ptr<PinBushingModel>
  shared_model(const contact::JointGeometry &geometry, const FeSettings &settings, bool *reused)
  {
    const std::lock_guard<std::mutex> lock(pool_mutex);
    if (auto model = live_model(geometry, settings))
      {
        use_profiles(*model, geometry);
        if (reused != nullptr)
          *reused = true;
        return model;
      }
    auto        holder = std::make_shared<Holder>();
    std::string directory;
    if (settings.mesh_directory.empty())
      {
        holder->directory = std::make_unique<TemporaryDirectory>("fe");
        directory         = holder->directory->path();
      }
    else
      {
        directory = settings.mesh_directory;
        make_output_directory(directory);
      }
    const std::string msh = directory + "/pin_bushing_" + std::to_string(n_meshes++) + ".msh";
    holder->model         = std::make_unique<PinBushingModel>(geometry, settings, msh);
    holder->model->prepare_condensed();
    std::shared_ptr<PinBushingModel> model(holder, holder->model.get());
    pool.push_back({settings, model});
    if (reused != nullptr)
      *reused = false;
    return model;
  }

  void
  use_profiles(PinBushingModel &model, const contact::JointGeometry &geometry)
  {
    model.update_profiles(geometry.bore, geometry.pin);
  }
} // namespace wearlink::fe
