// SPDX-License-Identifier: LGPL-2.1-or-later
#include "fe/elasticity_problem.h"

#include "base/atomic_file.h"
#include "base/effect_ledger.h"
#include "base/exceptions.h"
#include "base/numbers.h"
#include "fe/blas_threads.h"
#include "fe/boundary_ids.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_renumbering.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>

namespace wearlink::fe
{
  using namespace dealii;

  namespace
  {
    using wearlink::numbers::pi;

    /** Lamé constants of plane strain: λ = Eν/((1+ν)(1−2ν)), μ = E/(2(1+ν)). */
    std::pair<double, double>
    lame(const contact::Material &m)
    {
      const double E = m.youngs_modulus, nu = m.poisson_ratio;
      return {E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))};
    }

    /**
     * Plane-strain stress from the displacement gradient, for DataOut:
     * σ = λ tr(ε) I + 2 μ ε in the plane, σ_zz = λ tr(ε), and the von Mises stress.
     */
    class StressPostprocessor : public DataPostprocessor<2>
    {
    public:
      StressPostprocessor(const contact::Material &pin, const contact::Material &bushing)
        : pin(lame(pin))
        , bushing(lame(bushing))
      {
      }

      void
      evaluate_vector_field(const DataPostprocessorInputs::Vector<2> &inputs,
                            std::vector<Vector<double>>              &computed) const override
      {
        const auto cell   = inputs.template get_cell<2>();
        const auto [l, m] = cell->material_id() == material_ids::pin ? pin : bushing;
        for (unsigned int q = 0; q < computed.size(); ++q)
          {
            const auto  &g   = inputs.solution_gradients[q];
            const double exx = g[0][0], eyy = g[1][1], exy = 0.5 * (g[0][1] + g[1][0]);
            const double tr  = exx + eyy;
            const double sxx = l * tr + 2 * m * exx;
            const double syy = l * tr + 2 * m * eyy;
            const double sxy = 2 * m * exy;
            const double szz = l * tr;
            const double vm =
              std::sqrt(0.5 * ((sxx - syy) * (sxx - syy) + (syy - szz) * (syy - szz) + (szz - sxx) * (szz - sxx)) +
                        3 * sxy * sxy);
            computed[q](0) = sxx;
            computed[q](1) = syy;
            computed[q](2) = sxy;
            computed[q](3) = szz;
            computed[q](4) = vm;
          }
      }

      std::vector<std::string>
      get_names() const override
      {
        return {"stress_xx_Pa", "stress_yy_Pa", "stress_xy_Pa", "stress_zz_Pa", "von_mises_Pa"};
      }

      UpdateFlags
      get_needed_update_flags() const override
      {
        return update_gradients;
      }

    private:
      const std::pair<double, double> pin, bushing;
    };

    /** Polar angle in (−π, π]. */
    double
    polar_angle(const Point<2> &p)
    {
      return std::atan2(p[1], p[0]);
    }

    /** The point of @p profile at polar angle @p psi and the profile's outward normal there. */
    std::pair<Point<2>, Tensor<1, 2>>
    on_profile(const Profile &profile, double psi)
    {
      const double r = profile.radius(psi), dr = profile.slope(psi);
      const double c = std::cos(psi), s = std::sin(psi);
      // Tangent dX/dψ = r' e_r + r e_ψ; outward normal ∝ r e_r − r' e_ψ.
      Tensor<1, 2> n;
      n[0] = r * c + dr * s;
      n[1] = r * s - dr * c;
      return {Point<2>(r * c, r * s), n / n.norm()};
    }
  } // namespace


  ElasticityProblem::ElasticityProblem(const std::string       &msh_file,
                                       unsigned int             degree,
                                       unsigned int             refinements,
                                       const contact::Material &pin_material,
                                       const contact::Material &bushing_material,
                                       const Profile           &pin_profile,
                                       const Profile           &bore_profile,
                                       unsigned int             n_partitions)
    : fe(FE_Q<2>(degree), 2)
    , dof_handler(triangulation)
    , msh_file(msh_file)
    , refinements(refinements)
    , n_partitions(n_partitions)
    , pin_material(pin_material)
    , bushing_material(bushing_material)
    , pin_profile(pin_profile)
    , bore_profile(bore_profile)
  {
    blas_is_thread_safe(); // one BLAS thread per call from here on (fe/blas_threads.h)
  }


  void
  ElasticityProblem::run()
  {
    read_mesh(msh_file, refinements);
    setup_system();
    assemble_system();
    extract_contact_surfaces();
  }


  // The mesh comes from gmsh through deal.II's reader, which maps the named physical
  // groups "MaterialID:n" and "BoundaryID:n" onto material and boundary ids.
  void
  ElasticityProblem::read_mesh(const std::string &file, unsigned int n_refinements)
  {
    GridIn<2> grid_in(triangulation);
    try
      {
        grid_in.read_msh(file);
      }
    catch (const std::string &message)
      {
        // gmsh's reader throws its message as a string. The mesher checked the file when
        // it wrote it (fe/pin_bushing_mesher.cc), so the file was changed or damaged on
        // the disk since.
        throw IoError("Reading the mesh '" + file + "' failed: gmsh: " + message +
                      ". The file was damaged after it was written; check the disk and run again.");
      }
    EffectLedger::instance().add_resource("triangulations");
    triangulation.refine_global(n_refinements);
    if (n_partitions > 1)
      GridTools::partition_triangulation(n_partitions, triangulation, SparsityTools::Partitioner::metis);
  }


  void
  ElasticityProblem::setup_system()
  {
    dof_handler.distribute_dofs(fe);
    if (n_partitions > 1)
      DoFRenumbering::subdomain_wise(dof_handler);
    DynamicSparsityPattern dsp(dof_handler.n_dofs());
    DoFTools::make_sparsity_pattern(dof_handler, dsp);
    sparsity_pattern.copy_from(dsp);
    stiffness_matrix.reinit(sparsity_pattern);
  }


  // Plane-strain elasticity, per unit axial length: a(u, v) = ∫ λ div u div v +
  // 2 μ ε(u) : ε(v) dx, with the Lamé constants of the cell's body (material id).
  // The matrix is assembled without any boundary condition; each solver imposes its own.
  QGauss<2>
  ElasticityProblem::quadrature() const
  {
    return QGauss<2>(fe.degree + 1);
  }


  void
  ElasticityProblem::cell_stiffness(const DoFHandler<2>::active_cell_iterator &cell,
                                    FEValues<2>                               &fe_values,
                                    FullMatrix<double>                        &cell_matrix) const
  {
    const auto [l, m]                = lame(cell->material_id() == material_ids::pin ? pin_material : bushing_material);
    const unsigned int dofs_per_cell = fe.n_dofs_per_cell();
    fe_values.reinit(cell);
    cell_matrix = 0;
    for (unsigned int q = 0; q < fe_values.n_quadrature_points; ++q)
      for (unsigned int i = 0; i < dofs_per_cell; ++i)
        {
          const unsigned int ci = fe.system_to_component_index(i).first;
          const auto         gi = fe_values.shape_grad(i, q);
          for (unsigned int j = 0; j < dofs_per_cell; ++j)
            {
              const unsigned int cj = fe.system_to_component_index(j).first;
              const auto         gj = fe_values.shape_grad(j, q);
              cell_matrix(i, j) +=
                (l * gi[ci] * gj[cj] + m * gi[cj] * gj[ci] + (ci == cj ? m * (gi * gj) : 0.0)) * fe_values.JxW(q);
            }
        }
  }


  // Plane-strain elasticity, per unit axial length: a(u, v) = ∫ λ div u div v +
  // 2 μ ε(u) : ε(v) dx, with the Lamé constants of the cell's body (material id).
  // The matrix is assembled without any boundary condition; each solver imposes its own.
  void
  ElasticityProblem::assemble_system()
  {
    FEValues<2>                   fe_values(fe, quadrature(), update_gradients | update_JxW_values);
    const unsigned int            dofs_per_cell = fe.n_dofs_per_cell();
    FullMatrix<double>            cell_matrix(dofs_per_cell, dofs_per_cell);
    std::vector<global_dof_index> dof_indices(dofs_per_cell);
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell_stiffness(cell, fe_values, cell_matrix);
        cell->get_dof_indices(dof_indices);
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          for (unsigned int j = 0; j < dofs_per_cell; ++j)
            stiffness_matrix.add(dof_indices[i], dof_indices[j], cell_matrix(i, j));
      }
  }


  // Contact candidates are the support points on the two contact surfaces. Each gets
  // its x/y DoFs, its lumped weight ∫ N_i ds (the length over which its nodal contact
  // force is spread when converted to a pressure), and its position and normal on the
  // exact profile R*(ψ) at its polar angle: the contact gap is computed from the
  // profiles, not from the faceted mesh, so that gaps far below the element size (the
  // Hertz approach is ~0.1 µm) are represented exactly.
  void
  ElasticityProblem::extract_contact_surfaces()
  {
    const MappingQ<2>     mapping(1);
    std::vector<Point<2>> support(dof_handler.n_dofs());
    DoFTools::map_dofs_to_support_points(mapping, dof_handler, support);

    const QGauss<1>               face_quadrature(fe.degree + 1);
    FEFaceValues<2>               fe_face_values(mapping, fe, face_quadrature, update_values | update_JxW_values);
    const unsigned int            dofs_per_cell = fe.n_dofs_per_cell();
    std::vector<global_dof_index> dof_indices(dofs_per_cell);

    std::map<global_dof_index, SurfaceNode>      pin_map, bore_map;
    std::map<global_dof_index, global_dof_index> core_map;
    std::vector<global_dof_index>                outer;
    std::vector<std::vector<global_dof_index>>   bore_face_dofs;

    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          {
            const auto id = cell->face(f)->boundary_id();
            cell->get_dof_indices(dof_indices);
            // Pair the x and y DoFs of each support point on this face.
            std::map<unsigned int, std::array<global_dof_index, 2>> points;
            std::map<unsigned int, unsigned int>                    x_index;
            for (unsigned int i = 0; i < dofs_per_cell; ++i)
              if (fe.has_support_on_face(i, f))
                {
                  const auto [component, base] = fe.system_to_component_index(i);
                  points[base][component]      = dof_indices[i];
                  if (component == 0)
                    x_index[base] = i;
                }
            if (id == boundary_ids::pin_core)
              for (const auto &p : points)
                core_map[p.second[0]] = p.second[1];
            else if (id == boundary_ids::bushing_outer)
              for (const auto &p : points)
                {
                  outer.push_back(p.second[0]);
                  outer.push_back(p.second[1]);
                }
            else if (id == boundary_ids::pin_surface || id == boundary_ids::bore_surface)
              {
                const bool  is_pin  = id == boundary_ids::pin_surface;
                auto       &nodes   = is_pin ? pin_map : bore_map;
                const auto &profile = is_pin ? pin_profile : bore_profile;
                fe_face_values.reinit(cell, f);
                std::vector<global_dof_index> face_dofs;
                for (const auto &p : points)
                  {
                    const unsigned int i  = x_index[p.first];
                    auto               it = nodes.find(p.second[0]);
                    if (it == nodes.end())
                      {
                        SurfaceNode node;
                        node.dofs                         = p.second;
                        node.angle                        = polar_angle(support[p.second[0]]);
                        std::tie(node.point, node.normal) = on_profile(profile, node.angle);
                        it                                = nodes.emplace(p.second[0], node).first;
                      }
                    for (unsigned int q = 0; q < face_quadrature.size(); ++q)
                      it->second.weight += fe_face_values.shape_value_component(i, q, 0) * fe_face_values.JxW(q);
                    face_dofs.push_back(p.second[0]);
                  }
                if (!is_pin)
                  bore_face_dofs.push_back(face_dofs);
              }
          }

    AssertThrow(!pin_map.empty() && !bore_map.empty() && !core_map.empty() && !outer.empty(),
                ExcMessage("The mesh '" + msh_file + "' lacks one of the boundary ids of fe/boundary_ids.h."));

    auto sorted = [](const std::map<global_dof_index, SurfaceNode> &m) {
      std::vector<SurfaceNode> v;
      for (const auto &e : m)
        v.push_back(e.second);
      std::sort(v.begin(), v.end(), [](const SurfaceNode &a, const SurfaceNode &b) { return a.angle < b.angle; });
      return v;
    };
    pin_nodes         = sorted(pin_map);
    bore_nodes        = sorted(bore_map);
    pin_surface_slope = 0;
    for (unsigned int i = 0; i < pin_nodes.size(); ++i)
      {
        const auto &a = pin_nodes[i], &b = pin_nodes[(i + 1) % pin_nodes.size()];
        double      d = b.angle - a.angle;
        d -= wearlink::numbers::two_pi * std::floor(d / wearlink::numbers::two_pi);
        if (d > 0)
          pin_surface_slope = std::max(pin_surface_slope, std::abs(b.point.norm() - a.point.norm()) / d);
      }
    core_nodes.clear();
    for (const auto &c : core_map)
      core_nodes.push_back({{c.first, c.second}});
    std::sort(outer.begin(), outer.end());
    outer.erase(std::unique(outer.begin(), outer.end()), outer.end());
    outer_dofs = outer;

    build_bore_faces(bore_face_dofs);
  }


  // Bore faces: node indices ordered by angle along the face (handling the face that
  // straddles the ±π cut), sorted by their first angle.
  void
  ElasticityProblem::build_bore_faces(const std::vector<std::vector<types::global_dof_index>> &bore_face_dofs)
  {
    std::map<global_dof_index, unsigned int> bore_index;
    for (unsigned int k = 0; k < bore_nodes.size(); ++k)
      bore_index[bore_nodes[k].dofs[0]] = k;
    bore_faces.clear();
    for (const auto &dofs : bore_face_dofs)
      {
        SurfaceFace face;
        for (const auto d : dofs)
          face.nodes.push_back(bore_index[d]);
        const double ref    = bore_nodes[face.nodes[0]].angle;
        auto         unwrap = [&](unsigned int k) {
          double a = bore_nodes[k].angle - ref;
          a -= 2 * pi * std::round(a / (2 * pi));
          return a;
        };
        std::sort(face.nodes.begin(), face.nodes.end(), [&](unsigned int a, unsigned int b) {
          return unwrap(a) < unwrap(b);
        });
        face.begin = bore_nodes[face.nodes.front()].angle;
        face.span  = unwrap(face.nodes.back()) - unwrap(face.nodes.front());
        AssertThrow(face.span > 0, ExcInternalError());
        bore_faces.push_back(face);
      }
    std::sort(bore_faces.begin(), bore_faces.end(), [](const SurfaceFace &a, const SurfaceFace &b) {
      return a.begin < b.begin;
    });
  }


  void
  ElasticityProblem::output_results(const Vector<double> &displacement,
                                    const std::string    &vtu_path,
                                    const Vector<double> *traction) const
  {
    DataOut<2> data_out;
    data_out.attach_dof_handler(dof_handler);
    const std::vector<DataComponentInterpretation::DataComponentInterpretation> interpretation(
      2,
      DataComponentInterpretation::component_is_part_of_vector);
    data_out.add_data_vector(displacement,
                             std::vector<std::string>(2, "displacement_m"),
                             DataOut<2>::type_dof_data,
                             interpretation);
    if (traction)
      data_out.add_data_vector(*traction,
                               std::vector<std::string>(2, "contact_traction_Pa"),
                               DataOut<2>::type_dof_data,
                               interpretation);
    const StressPostprocessor stress(pin_material, bushing_material);
    data_out.add_data_vector(displacement, stress);
    Vector<float> material(triangulation.n_active_cells());
    for (const auto &cell : triangulation.active_cell_iterators())
      material(cell->active_cell_index()) = cell->material_id();
    data_out.add_data_vector(material, "body");
    data_out.build_patches(fe.degree);
    // zlib at its fastest level: ~9 MB per file, written in a fraction of the time that
    // the default best compression takes (measured 4.3 s of the FE scene's 87 s for
    // its four files).
    DataOutBase::VtkFlags flags;
    flags.compression_level = DataOutBase::VtkFlags::best_speed;
    data_out.set_flags(flags);
    AtomicFile out(vtu_path);
    try
      {
        data_out.write_vtu(out.stream());
      }
    catch (const dealii::StandardExceptions::ExcIO &)
      {
        out.throw_if_failed(); // a failed write (disk full): an IoError naming the file
        throw;
      }
    out.commit();
  }
} // namespace wearlink::fe
