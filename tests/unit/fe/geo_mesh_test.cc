// SPDX-License-Identifier: LGPL-2.1-or-later
// meshes/pin_bushing.geo is the documented, user-editable form of the pin–bushing mesh
// that src/fe/pin_bushing_mesher.cc builds through the gmsh API. For the same round pair
// and sizes the two must give the same mesh: the same construction (points, splines,
// transfinite counts, size field, recombination, split) in the same order makes gmsh
// produce identical counts, so node, quadrilateral and per-boundary segment counts are
// compared for equality, and the physical group names must match. deal.II reads the
// .geo mesh and the shipped fixture meshes/fixtures/pin_bushing_coarse.msh with the
// material and boundary ids of fe/boundary_ids.h, and each body's area lies between the
// analytic annulus area and the area of the polygons its boundary vertices span (the
// mesh fills polygons inscribed in the circles: each circle of radius r loses at most
// π r² (1 − sin θ / θ), θ its largest segment angle, and the hole's polygon adds as
// much at most).
#include "base/profile.h"
#include "fe/boundary_ids.h"
#include "fe/pin_bushing_mesher.h"
#include "support/test_support.h"

#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/tria.h>
#include <gmsh.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <set>

using namespace wearlink;

namespace
{
  constexpr double bore_radius = 0.012, pin_radius = 0.0115, core_radius = 0.4 * 0.0115, outer_radius = 0.024;

  /** Counts of a mesh as gmsh sees it. */
  struct GmshCounts
  {
    std::size_t                   nodes = 0, quadrilaterals = 0;
    std::map<std::string, size_t> segments; ///< line elements per named boundary group
    std::set<std::string>         names;    ///< physical group names
  };

  /** Open @p file in a fresh gmsh session (meshing it if it is a .geo) and count. */
  GmshCounts
  count(const std::string &file, const bool mesh)
  {
    gmsh::initialize(0, nullptr, false);
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::open(file);
    if (mesh)
      gmsh::model::mesh::generate(2);
    GmshCounts                            c;
    std::vector<int>                      types;
    std::vector<std::vector<std::size_t>> tags, nodes;
    gmsh::model::mesh::getElements(types, tags, nodes, 2);
    for (std::size_t t = 0; t < types.size(); ++t)
      if (types[t] == 3)
        c.quadrilaterals += tags[t].size();
    std::vector<std::size_t> node_tags;
    std::vector<double>      coords, params;
    gmsh::model::mesh::getNodes(node_tags, coords, params, -1, -1, false, false);
    c.nodes = node_tags.size();
    gmsh::vectorpair groups;
    gmsh::model::getPhysicalGroups(groups);
    for (const auto &[dim, tag] : groups)
      {
        std::string name;
        gmsh::model::getPhysicalName(dim, tag, name);
        c.names.insert(name);
        if (dim != 1)
          continue;
        std::vector<int> curves;
        gmsh::model::getEntitiesForPhysicalGroup(dim, tag, curves);
        for (const int curve : curves)
          {
            gmsh::model::mesh::getElements(types, tags, nodes, 1, curve);
            for (const auto &t : tags)
              c.segments[name] += t.size();
          }
      }
    gmsh::finalize();
    return c;
  }

  /** A .geo that sets the sizes and includes meshes/pin_bushing.geo. */
  std::string
  geo_with_sizes(const std::string &dir,
                 const double       surface_size,
                 const double       max_size,
                 const unsigned     n_points,
                 const double       layer = 0.1e-3)
  {
    const std::string path = dir + "/pin_bushing_sized.geo";
    std::ofstream(path) << "surface_size = " << surface_size << ";\nmax_size = " << max_size
                        << ";\nn_points = " << n_points << ";\nlayer = " << layer << ";\nInclude \""
                        << wearlink::testing::source_path("meshes/pin_bushing.geo") << "\";\n";
    return path;
  }

  /** The pair's mesh specification with the given sizes (growth 0.3, a 0.1 mm layer). */
  fe::MeshSpecification
  specification(const double surface_size, const double max_size)
  {
    fe::MeshSpecification spec;
    spec.core_radius          = core_radius;
    spec.outer_radius         = outer_radius;
    spec.surface_element_size = surface_size;
    spec.max_element_size     = max_size;
    spec.size_growth          = 0.3;
    spec.layer_thickness      = 0.1e-3;
    return spec;
  }

  /** Per material id: mesh area, and the analytic band [low, high] it must lie in. */
  void
  check_areas(const std::string &msh)
  {
    dealii::Triangulation<2> tria;
    dealii::GridIn<2>        in(tria);
    in.read_msh(msh);
    std::map<unsigned, double>                    area;
    std::map<unsigned, std::pair<double, double>> max_angle; // per boundary id: radius, θ
    std::set<unsigned>                            boundary_ids;
    for (const auto &cell : tria.active_cell_iterators())
      {
        area[cell->material_id()] += cell->measure();
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            {
              const auto id = cell->face(f)->boundary_id();
              boundary_ids.insert(id);
              const auto   a = cell->face(f)->vertex(0), b = cell->face(f)->vertex(1);
              const double theta = std::abs(std::remainder(std::atan2(a[1], a[0]) - std::atan2(b[1], b[0]), 2 * M_PI));
              auto        &m     = max_angle[id];
              m.first            = a.norm();
              m.second           = std::max(m.second, theta);
            }
      }
    EXPECT_EQ(area.size(), 2u);
    EXPECT_EQ(boundary_ids,
              (std::set<unsigned>{fe::boundary_ids::pin_core,
                                  fe::boundary_ids::pin_surface,
                                  fe::boundary_ids::bore_surface,
                                  fe::boundary_ids::bushing_outer}));
    auto loss = [&](const unsigned id) {
      const auto [r, theta] = max_angle.at(id);
      return M_PI * r * r * (1 - std::sin(theta) / theta);
    };
    const double pin  = M_PI * (pin_radius * pin_radius - core_radius * core_radius);
    const double ring = M_PI * (outer_radius * outer_radius - bore_radius * bore_radius);
    const double tiny = 1e-12 * ring; // round-off of the cell measures
    EXPECT_GE(area.at(fe::material_ids::pin), pin - loss(fe::boundary_ids::pin_surface) - tiny);
    EXPECT_LE(area.at(fe::material_ids::pin), pin + loss(fe::boundary_ids::pin_core) + tiny);
    EXPECT_GE(area.at(fe::material_ids::bushing), ring - loss(fe::boundary_ids::bushing_outer) - tiny);
    EXPECT_LE(area.at(fe::material_ids::bushing), ring + loss(fe::boundary_ids::bore_surface) + tiny);
  }
} // namespace

TEST(GeoMesh, GeoFileAndApiMesherGiveTheSameMesh)
{
  const std::string dir = wearlink::testing::fresh_directory("geo_mesh");
  // Coarse enough to mesh in well under a second, fine enough to exercise the size field.
  const double   surface_size = 2e-4, max_size = 3e-3;
  const unsigned n_points = 72;
  const auto     geo      = count(geo_with_sizes(dir, surface_size, max_size, n_points), true);

  fe::MeshSpecification spec = specification(surface_size, max_size);
  spec.periodic              = false; // the general construction (SectorGeoFile… covers the periodic one)
  const std::string msh      = dir + "/api.msh";
  const auto        stats =
    fe::write_pin_bushing_mesh(Profile::round(bore_radius, n_points), Profile::round(pin_radius, n_points), spec, msh);
  const auto api = count(msh, false);

  // In memory: the counts of the .geo mesh and those the C++ mesher reports.
  EXPECT_EQ(geo.nodes, stats.n_nodes);
  EXPECT_EQ(geo.quadrilaterals, stats.n_quadrilaterals);
  EXPECT_EQ(geo.names, api.names);
  EXPECT_EQ(geo.segments, api.segments);
  EXPECT_EQ(geo.names,
            (std::set<std::string>{"MaterialID:1",
                                   "MaterialID:2",
                                   "BoundaryID:1",
                                   "BoundaryID:2",
                                   "BoundaryID:3",
                                   "BoundaryID:4"}));
  // Both contact surfaces at the surface size: 2π R / surface_size segments each (the
  // split doubles the transfinite counts), to the rounding of four quarter counts.
  EXPECT_NEAR(geo.segments.at("BoundaryID:2"), 2 * M_PI * pin_radius / surface_size, 4.0);
  EXPECT_NEAR(geo.segments.at("BoundaryID:3"), 2 * M_PI * bore_radius / surface_size, 4.0);
  EXPECT_EQ(stats.n_refined_surface_segments, geo.segments.at("BoundaryID:2") + geo.segments.at("BoundaryID:3"));

  // The .geo mesh as deal.II reads it.
  const std::string geo_msh = dir + "/geo.msh";
  gmsh::initialize(0, nullptr, false);
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::open(geo_with_sizes(dir, surface_size, max_size, n_points));
  gmsh::model::mesh::generate(2);
  gmsh::write(geo_msh);
  gmsh::finalize();
  // As files (which hold only the nodes of the physical groups' elements): the same.
  const auto geo_file = count(geo_msh, false);
  EXPECT_EQ(geo_file.nodes, api.nodes);
  EXPECT_EQ(geo_file.quadrilaterals, api.quadrilaterals);
  EXPECT_EQ(geo_file.segments, api.segments);
  check_areas(geo_msh);
}

// meshes/pin_bushing_sector.geo holds the two sectors that the periodic mesher meshes
// and copies around (round profiles refined all around): meshed by gmsh from the file,
// each sector must have the quadrilaterals whose K copies the C++ mesher reports, its
// contact arc periodic_sector_elements segments, and K = 2πR / (32 × surface size).
TEST(GeoMesh, SectorGeoFileIsWhatThePeriodicMesherCopies)
{
  const std::string dir          = wearlink::testing::fresh_directory("geo_sector");
  const double      surface_size = 1e-4, max_size = 2e-3;
  const std::string geo = dir + "/sector_sized.geo";
  std::ofstream(geo) << "surface_size = " << surface_size << ";\nmax_size = " << max_size << ";\nInclude \""
                     << wearlink::testing::source_path("meshes/pin_bushing_sector.geo") << "\";\n";
  std::map<std::string, std::size_t> quads; // per material group
  gmsh::initialize(0, nullptr, false);
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::open(geo);
  gmsh::model::mesh::generate(2);
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups, 2);
  for (const auto &[dim, tag] : groups)
    {
      std::string name;
      gmsh::model::getPhysicalName(dim, tag, name);
      std::vector<int> surfaces;
      gmsh::model::getEntitiesForPhysicalGroup(dim, tag, surfaces);
      for (const int surface : surfaces)
        {
          std::vector<int>                      types;
          std::vector<std::vector<std::size_t>> tags, nodes;
          gmsh::model::mesh::getElements(types, tags, nodes, 2, surface);
          for (std::size_t t = 0; t < types.size(); ++t)
            quads[name] += types[t] == 3 ? tags[t].size() : 0;
        }
    }
  gmsh::finalize();

  fe::MeshSpecification spec = specification(surface_size, max_size);
  const std::string     msh  = dir + "/periodic.msh";
  const auto            stats =
    fe::write_pin_bushing_mesh(Profile::round(bore_radius, 360), Profile::round(pin_radius, 360), spec, msh);
  const auto sectors = [&](const double R) {
    return std::lround(2 * M_PI * R / (fe::periodic_sector_elements * surface_size));
  };
  EXPECT_EQ(stats.pin_sectors, sectors(pin_radius));
  EXPECT_EQ(stats.bore_sectors, sectors(bore_radius));
  EXPECT_EQ(stats.n_quadrilaterals,
            stats.pin_sectors * quads.at("MaterialID:1") + stats.bore_sectors * quads.at("MaterialID:2"));
  const auto api = count(msh, false);
  EXPECT_EQ(api.segments.at("BoundaryID:2"), stats.pin_sectors * fe::periodic_sector_elements);
  EXPECT_EQ(api.segments.at("BoundaryID:3"), stats.bore_sectors * fe::periodic_sector_elements);
  EXPECT_EQ(api.quadrilaterals, stats.n_quadrilaterals);
  EXPECT_EQ(api.nodes, stats.n_nodes);
  check_areas(msh);
}

TEST(GeoMesh, ShippedFixtureIsTheGeoMeshAndReadsWithItsIdsAndAreas)
{
  // meshes/fixtures/pin_bushing_coarse.msh is the .geo meshed with the parameters of
  // meshes/README.md; meshing them again must give the same counts, and deal.II must
  // read it with the ids and areas of the pair.
  const std::string fixture = wearlink::testing::source_path("meshes/fixtures/pin_bushing_coarse.msh");
  const std::string dir     = wearlink::testing::fresh_directory("geo_fixture");
  gmsh::initialize(0, nullptr, false);
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::open(geo_with_sizes(dir, 8e-4, 4e-3, 72, 0.0));
  gmsh::model::mesh::generate(2);
  gmsh::write(dir + "/again.msh");
  gmsh::finalize();
  const auto shipped = count(fixture, false);
  const auto again   = count(dir + "/again.msh", false);
  EXPECT_EQ(shipped.nodes, again.nodes);
  EXPECT_EQ(shipped.quadrilaterals, again.quadrilaterals);
  EXPECT_EQ(shipped.segments, again.segments);
  EXPECT_EQ(shipped.names, again.names);
  EXPECT_GT(shipped.quadrilaterals, 100u);
  check_areas(fixture);
}
