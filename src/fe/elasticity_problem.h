// SPDX-License-Identifier: LGPL-2.1-or-later
// Plane-strain linear elasticity of the pin annulus and the bushing ring (one
// triangulation read from the gmsh mesh, two material ids, each body in its own frame),
// in the shape of a deal.II tutorial: setup_system(), assemble_system(),
// extract_contact_surfaces(), output_results(), run().
//
// The class owns the *unconstrained* stiffness matrix K of both bodies. The two contact
// solvers build their own constrained systems from it:
//   - the condensed solver clamps the rigid pin core and the bushing's outer edge and
//     factors once (boundary_compliance.h);
//   - the reference solver ties the core to the unknown pin translation and adds the
//     active contact constraints at every active-set iteration (contact_solver.h).
// It also provides the contact candidates: the support points of the pin surface
// (slaves) and of the bore (masters) with their DoFs, their lumped weights ∫ N_i ds and
// their exact positions and normals on the profiles R*(ψ).
#pragma once

#include "base/profile.h"
#include "contact/pressure_model.h"

#include <deal.II/base/point.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <string>
#include <vector>

namespace wearlink::fe
{
  using dealii::types::global_dof_index;

  /** One support point of a contact surface (a contact candidate). */
  struct SurfaceNode
  {
    double                          angle = 0;  ///< polar angle in the body's frame [rad], in (−π, π]
    dealii::Point<2>                point;      ///< R*(angle) (cos, sin): on the profile [m]
    dealii::Tensor<1, 2>            normal;     ///< unit normal of the profile, pointing away from the centre
    double                          weight = 0; ///< lumped length ∫ N_i ds on the surface [m]
    std::array<global_dof_index, 2> dofs{};     ///< x and y DoF (body-frame components)
  };

  /** One boundary face of a contact surface, for interpolating along it. */
  struct SurfaceFace
  {
    double begin = 0; ///< polar angle of its first vertex [rad] in (−π, π]
    double span  = 0; ///< angular extent, > 0 [rad]
    /** Surface-node indices ordered along the face (degree + 1 of them). */
    std::vector<unsigned int> nodes;
  };

  class ElasticityProblem
  {
  public:
    /**
     * @param msh_file gmsh mesh written by write_pin_bushing_mesh()
     * @param degree FE_Q degree (1 or 2)
     * @param refinements global refinements of the mesh
     */
    ElasticityProblem(const std::string       &msh_file,
                      unsigned int             degree,
                      unsigned int             refinements,
                      const contact::Material &pin_material,
                      const contact::Material &bushing_material,
                      const Profile           &pin_profile,
                      const Profile           &bore_profile,
                      unsigned int             n_partitions = 1);

    /**
     * Read the mesh (and, for n_partitions > 1, partition it with METIS and number the
     * DoFs subdomain by subdomain), set up DoFs, assemble K, extract the contact
     * candidates.
     */
    void
    run();

    /**
     * Write displacement, stress (plane strain, incl. σ_zz and von Mises) and the
     * material id of both bodies in their own frames as VTU. The pin's displacement
     * includes its rigid translation. With @p traction (a DoF vector like the
     * displacement), also `contact_traction_Pa`: the contact pressure × the surface's
     * outward normal at the contact nodes (its magnitude is the pressure).
     */
    void
    output_results(const dealii::Vector<double> &displacement,
                   const std::string            &vtu_path,
                   const dealii::Vector<double> *traction = nullptr) const;

    /**
     * The stiffness matrix of one cell: plane-strain elasticity with the Lamé constants
     * of the cell's body. @p fe_values must use quadrature() and update gradients and
     * JxW values.
     */
    void
    cell_stiffness(const dealii::DoFHandler<2>::active_cell_iterator &cell,
                   dealii::FEValues<2>                               &fe_values,
                   dealii::FullMatrix<double>                        &matrix) const;

    /** 1/E* = Σ (1 − ν²)/E of the two bodies [Pa] (doc/models.md §5.1). */
    double
    effective_modulus() const
    {
      return contact::effective_modulus(pin_material, bushing_material);
    }

    /** The cell quadrature of cell_stiffness(). */
    dealii::QGauss<2>
    quadrature() const;

    dealii::Triangulation<2>     triangulation;
    dealii::FESystem<2>          fe;
    dealii::DoFHandler<2>        dof_handler;
    dealii::SparsityPattern      sparsity_pattern;
    dealii::SparseMatrix<double> stiffness_matrix;

    std::vector<SurfaceNode> pin_nodes; ///< sorted by angle
    /** max |Δr / Δψ| between neighbouring pin nodes [m/rad] (the contact window's bound). */
    double                   pin_surface_slope = 0;
    std::vector<SurfaceNode> bore_nodes; ///< sorted by angle
    std::vector<SurfaceFace> bore_faces; ///< sorted by begin
    /** (x, y) DoF pairs of the rigid pin core's support points. */
    std::vector<std::array<global_dof_index, 2>> core_nodes;
    /** DoFs on the fixed outer edge of the bushing. */
    std::vector<global_dof_index> outer_dofs;

  private:
    void
    read_mesh(const std::string &msh_file, unsigned int refinements);
    void
    setup_system();
    void
    assemble_system();
    void
    extract_contact_surfaces();
    /** The bore faces of extract_contact_surfaces(), ordered by angle. */
    void
    build_bore_faces(const std::vector<std::vector<dealii::types::global_dof_index>> &bore_face_dofs);

    const std::string       msh_file;
    const unsigned int      refinements;
    const unsigned int      n_partitions;
    const contact::Material pin_material;
    const contact::Material bushing_material;
    const Profile           pin_profile;
    const Profile           bore_profile;
  };
} // namespace wearlink::fe
