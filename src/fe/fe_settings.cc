// SPDX-License-Identifier: LGPL-2.1-or-later
#include "fe/fe_settings.h"

#include "base/exceptions.h"

namespace wearlink::fe
{
  void
  FeSettings::check(const std::string &where) const
  {
    auto fail = [&](const std::string &what) {
      throw InputError("In " + where + ": " + what);
    };
    if (!(surface_element_size > 0))
      fail("'Surface element size' must be > 0 m.");
    if (!(max_element_size >= surface_element_size))
      fail("'Maximum element size' must be ≥ 'Surface element size' (both in m).");
    if (!(refined_layer_thickness >= 0))
      fail("'Refined layer thickness' must be ≥ 0 m.");
    if (!(size_growth > 0))
      fail("'Size growth' must be > 0.");
    if (!(core_radius_fraction > 0 && core_radius_fraction < 0.95))
      fail("'Pin core radius fraction' must lie in (0, 0.95).");
    if (outer_radius < 0)
      fail("the bushing outer radius must be > 0 m.");
    if (!(outer_radius_ratio > 1))
      fail("'Bushing outer radius ratio' must be > 1.");
    if (degree < 1 || degree > 2)
      fail("'Element degree' must be 1 or 2.");
    if (!(remesh_depth >= 0 && remesh_depth <= 100))
      fail("'Remesh depth' must lie in [0, 100] (a fraction of the surface element size).");
  }


  void
  declare_fe_settings(dealii::ParameterHandler &prm)
  {
    using namespace dealii::Patterns;
    declare(prm,
            "Surface element size",
            "25e-6",
            Double(1e-7, 1),
            "Element size along both contact surfaces (pin and bore). It must resolve "
            "the contact half-width: a Hertz half-width b needs about b/10 or finer. At least "
            "0.1 µm: a 10-mm pin then has 6e5 surface elements, the most a mesh can hold in memory.",
            "m");
    declare(prm,
            "Maximum element size",
            "1.5e-3",
            Double(1e-7, 1),
            "Largest element size, reached far from the contact surfaces.",
            "m");
    declare(prm,
            "Refined layer thickness",
            "0.1e-3",
            Double(0, 1),
            "Depth below both contact surfaces over which the element size stays at "
            "'Surface element size' before growing: the contact stresses decay over about "
            "one contact half-width, which must be resolved too.",
            "m");
    declare(prm,
            "Size growth",
            "0.3",
            Double(0, 100),
            "Growth rate of the element size with the distance d from the nearest "
            "contact surface: h(d) = min(h_surface + growth d, h_max).",
            "none");
    declare(prm,
            "Pin core radius fraction",
            "0.4",
            Double(0, 0.95),
            "The pin is loaded through a rigid core (its centre region, radius = this "
            "fraction of the smallest pin radius): the core translates rigidly by the pin "
            "displacement and does not rotate (the pin's link holds its angle).",
            "none");
    declare(prm,
            "Bushing outer radius ratio",
            "2",
            Double(1, 100),
            "Outer radius of the bushing ring / mean bore radius (at most 100); the outer edge is "
            "fixed. Used by the `fe` pressure model (the `contact` command takes the "
            "outer radius from its geometry section).",
            "none");
    declare(prm,
            "Element degree",
            "1",
            Integer(1, 2),
            "Polynomial degree of the FE_Q elements (plane-strain elasticity).",
            "none");
    declare(prm,
            "Global refinements",
            "0",
            Integer(0, 6),
            "Uniform refinements of the gmsh mesh (each halves every element size).",
            "none");
    declare(prm,
            "Maximum active-set iterations",
            "100",
            Integer(1, 100000),
            "Iteration limit of the active-set contact solvers; exceeding it is a "
            "numerical error. The condensed solver's primal–dual iteration hands over to its "
            "monotone (Lawson–Hanson) method after 30 iterations or when it cycles; that "
            "method ends in finitely many steps and is allowed 10 × this limit.",
            "none");
    declare(prm,
            "Remesh depth",
            "0",
            Double(0, 100),
            "Re-mesh a worn pair only when a profile has moved by more than this fraction of "
            "the (refined) surface element size since its mesh was made. Below it the mesh, "
            "its factorization and its compliance columns are kept, and the worn profiles "
            "enter the contact gaps exactly (the bore as the surface the pin's rays meet, the "
            "pin as a radial offset of each contact node); what is approximated is the "
            "elastic compliance of the worn surface layer. 0: re-mesh at every profile "
            "change (the exact path; costly at fine element sizes). The error of a value is "
            "a row of `wearlink study accuracy` (knob remesh-depth).",
            "none");
    declare(prm,
            "Mesh directory",
            "",
            Anything(),
            "Directory for the generated gmsh .msh files; empty: a temporary directory "
            "(the `contact` command always uses its output directory).",
            "none");
  }


  FeSettings
  read_fe_settings(const ParameterReader &reader)
  {
    FeSettings s;
    s.surface_element_size      = reader.get_positive("Surface element size");
    s.max_element_size          = reader.get_positive("Maximum element size");
    s.size_growth               = reader.get_positive("Size growth");
    s.refined_layer_thickness   = reader.get_double("Refined layer thickness");
    s.core_radius_fraction      = reader.get_positive("Pin core radius fraction");
    s.outer_radius_ratio        = reader.get_double("Bushing outer radius ratio");
    s.degree                    = static_cast<unsigned int>(reader.get_integer("Element degree"));
    s.refinements               = static_cast<unsigned int>(reader.get_integer("Global refinements"));
    s.max_active_set_iterations = static_cast<unsigned int>(reader.get_integer("Maximum active-set iterations"));
    s.mesh_directory            = reader.get("Mesh directory");
    s.remesh_depth              = reader.get_double("Remesh depth");
    if (s.max_element_size < s.surface_element_size)
      reader.fail("Maximum element size", "it must be ≥ 'Surface element size'");
    if (!(s.outer_radius_ratio > 1))
      reader.fail("Bushing outer radius ratio", "it must be > 1");
    return s;
  }
} // namespace wearlink::fe
