// SPDX-License-Identifier: LGPL-2.1-or-later
#include "fe/pin_bushing_mesher.h"

#include "base/atomic_file.h"
#include "base/effect_ledger.h"
#include "base/exceptions.h"
#include "base/numbers.h"
#include "fe/boundary_ids.h"

#include <deal.II/base/config.h>
#include <gmsh.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <vector>

namespace wearlink::fe
{
  namespace
  {
    using wearlink::numbers::pi;

    std::string
    number(double v)
    {
      std::ostringstream os;
      os.precision(6);
      os << v;
      return os.str();
    }

    /**
     * A gmsh session: initialize on construction, finalize on destruction (also when
     * an exception leaves the mesher), so that the next session — or deal.II's
     * GridIn::read_msh, which opens its own — starts clean. gmsh may install signal
     * handlers of its own; the program's SIGINT/SIGTERM/SIGHUP handlers (base/interrupt.h) are
     * put back after it starts.
     */
    class GmshSession
    {
    public:
      GmshSession()
      {
        struct sigaction on_int, on_term, on_hup;
        ::sigaction(SIGINT, nullptr, &on_int);
        ::sigaction(SIGTERM, nullptr, &on_term);
        ::sigaction(SIGHUP, nullptr, &on_hup);
        gmsh::initialize(0, nullptr, false);
        ::sigaction(SIGINT, &on_int, nullptr);
        ::sigaction(SIGTERM, &on_term, nullptr);
        ::sigaction(SIGHUP, &on_hup, nullptr);
        gmsh::option::setNumber("General.Terminal", 0);
        gmsh::option::setNumber("General.Verbosity", 1);
        EffectLedger::instance().add_resource("gmsh sessions");
      }
      ~GmshSession()
      {
        gmsh::finalize();
      }
      GmshSession(const GmshSession &) = delete;
      GmshSession &
      operator=(const GmshSession &) = delete;
    };

    /**
     * True if the file @p path ends as a complete .msh file does: with the end marker of
     * its last section ("$End<Section>" and a newline; the markers are text in the
     * binary format too).
     */
    bool
    ends_with_section_end(const std::string &path)
    {
      std::ifstream in(path, std::ios::binary | std::ios::ate);
      const auto    size = static_cast<long>(in.tellg());
      if (!in || size <= 0)
        return false;
      const long tail_size = std::min(size, 64L);
      in.seekg(size - tail_size);
      std::string tail(static_cast<std::size_t>(tail_size), '\0');
      in.read(tail.data(), tail_size);
      if (!in || tail.back() != '\n')
        return false;
      tail.pop_back();
      const auto marker = tail.rfind("\n$End");
      if (marker == std::string::npos || marker + 5 == tail.size())
        return false;
      return std::all_of(tail.begin() + static_cast<long>(marker) + 5, tail.end(), [](const char c) {
        return std::isalpha(static_cast<unsigned char>(c)) != 0;
      });
    }

    /**
     * Write gmsh's current model to @p msh_path through a temporary (base/atomic_file.h).
     * gmsh does not check its own writes: on a full disk it leaves a truncated file
     * without a word, and reading that file back throws from inside the reader. A file
     * that does not end as a complete .msh file does is therefore a failed write: an
     * IoError naming the file, and the temporary removed.
     */
    void
    write_mesh_file(const std::string &msh_path)
    {
      const std::string   tmp = temporary_name_for(msh_path);
      RegisteredTemporary registration(tmp);
      std::string         problem;
      try
        {
          gmsh::write(tmp);
          if (!ends_with_section_end(tmp))
            problem = "gmsh left it incomplete, as it does when the disk is full or a write fails";
        }
      catch (const std::string &message)
        {
          problem = "gmsh: " + message;
        }
      if (!problem.empty())
        {
          std::error_code ec;
          std::filesystem::remove(tmp, ec);
          throw IoError("Writing the mesh '" + msh_path + "' failed: " + problem +
                        ". Free some space (or check the disk) and run again.");
        }
      commit_external_file(tmp, msh_path);
    }

    /** Arc length of the polar curve r(ψ) between samples i0 and i1 (i1 may wrap). */
    double
    arc_length(const Profile &p, unsigned int i0, unsigned int i1)
    {
      const unsigned int n = p.n_points();
      double             s = 0;
      for (unsigned int i = i0; i < i1; ++i)
        {
          const double a0 = p.angle(i % n), r0 = p[i % n];
          const double a1 = a0 + 2 * pi / n, r1 = p[(i + 1) % n];
          const double dx = r1 * std::cos(a1) - r0 * std::cos(a0);
          const double dy = r1 * std::sin(a1) - r0 * std::sin(a0);
          s += std::sqrt(dx * dx + dy * dy);
        }
      return s;
    }

    /**
     * The closed surface curve of @p profile. If @p half_angle ≥ π: four splines
     * (quarter turns), each with a uniform transfinite node spacing ≈ @p h. Otherwise a
     * refined spline over the samples spanning [centre − half_angle, centre +
     * half_angle] with that spacing, and one spline for the rest, meshed by the size
     * field. Returns all curve tags in counter-clockwise order; @p refined receives the
     * uniformly spaced ones and @p n_segments their segment count.
     */
    std::vector<int>
    add_profile_curve(const Profile    &profile,
                      double            h,
                      double            centre,
                      double            half_angle,
                      std::vector<int> &refined,
                      unsigned long    &n_segments)
    {
      const int        n = static_cast<int>(profile.n_points());
      std::vector<int> points(n);
      for (int k = 0; k < n; ++k)
        points[k] = gmsh::model::geo::addPoint(profile[k] * std::cos(profile.angle(k)),
                                               profile[k] * std::sin(profile.angle(k)),
                                               0,
                                               h);
      // Pieces as ranges of sample indices [i0, i1] (i1 may exceed n: wrap).
      std::vector<std::pair<int, int>> pieces;
      std::vector<bool>                uniform;
      const double                     step = 2 * pi / n;
      int                              i0   = static_cast<int>(std::floor((centre - half_angle) / step));
      int                              i1   = static_cast<int>(std::ceil((centre + half_angle) / step));
      if (half_angle >= pi || i1 - i0 + 2 > n)
        for (int q = 0; q < 4; ++q)
          {
            pieces.emplace_back((q * n) / 4, ((q + 1) * n) / 4);
            uniform.push_back(true);
          }
      else
        {
          i0 = ((i0 % n) + n) % n;
          i1 = i0 + std::max(i1 - static_cast<int>(std::floor((centre - half_angle) / step)), 2);
          pieces.emplace_back(i0, i1);
          uniform.push_back(true);
          pieces.emplace_back(i1, i0 + n);
          uniform.push_back(false);
        }
      std::vector<int> curves;
      n_segments = 0;
      for (std::size_t p = 0; p < pieces.size(); ++p)
        {
          std::vector<int> piece;
          for (int i = pieces[p].first; i <= pieces[p].second; ++i)
            piece.push_back(points[i % n]);
          const int c = gmsh::model::geo::addSpline(piece);
          if (uniform[p])
            {
              const int segments =
                std::max(2, static_cast<int>(std::lround(arc_length(profile, pieces[p].first, pieces[p].second) / h)));
              gmsh::model::geo::mesh::setTransfiniteCurve(c, segments + 1);
              n_segments += segments;
              refined.push_back(c);
            }
          curves.push_back(c);
        }
      return curves;
    }

    /** A circle of radius @p r about the origin as four arcs (counter-clockwise). */
    std::vector<int>
    add_circle(double r, double h)
    {
      const int        centre = gmsh::model::geo::addPoint(0, 0, 0, h);
      std::vector<int> p;
      for (unsigned int q = 0; q < 4; ++q)
        p.push_back(gmsh::model::geo::addPoint(r * std::cos(q * pi / 2), r * std::sin(q * pi / 2), 0, h));
      std::vector<int> arcs;
      for (unsigned int q = 0; q < 4; ++q)
        arcs.push_back(gmsh::model::geo::addCircleArc(p[q], centre, p[(q + 1) % 4]));
      return arcs;
    }

    /**
     * Sizes from the background field only; Frontal-Delaunay, Blossom recombination,
     * and every element split into quadrilaterals; MSH 4.1 for deal.II.
     */
    void
    set_meshing_options()
    {
      gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
      gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
      gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
      gmsh::option::setNumber("Mesh.Algorithm",
                              6); // Frontal-Delaunay (algorithm 8 crashes in gmsh 4.8 with a background field)
      gmsh::option::setNumber("Mesh.RecombineAll", 1);
      gmsh::option::setNumber("Mesh.RecombinationAlgorithm", 1); // Blossom
      // Blossom recombination can leave a few triangles; splitting every element
      // (triangle → 3 quads, quad → 4 quads) guarantees an all-quadrilateral mesh. The
      // split halves all sizes, so the geometry is meshed at twice the target sizes.
      gmsh::option::setNumber("Mesh.SubdivisionAlgorithm", 1);
      gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
#ifdef DEAL_II_GMSH_WITH_API
      // Binary: a 25 µm mesh's text file took 0.14–0.2 s to write and ~0.25 s more to
      // read. deal.II reads it through the gmsh API (GridIn::read_msh of a file name);
      // its own text parser, the fallback without that API, reads text only.
      gmsh::option::setNumber("Mesh.Binary", 1);
#endif
    }

    void
    name_group(int dim, const std::vector<int> &tags, const std::string &name)
    {
      const int g = gmsh::model::addPhysicalGroup(dim, tags);
      gmsh::model::setPhysicalName(dim, g, name);
    }

    /**
     * Element size h within the layer of thickness t below the given (contact) curves,
     * then growing linearly with the distance d from them, h(d) = min(h + growth (d − t),
     * H) — gmsh Distance + Threshold fields, @p samples points per curve.
     */
    void
    set_size_field(const std::vector<int> &curves, const double samples, const MeshSpecification &spec)
    {
      const double              h = 2 * spec.surface_element_size, H = 2 * spec.max_element_size;
      const std::vector<double> list(curves.begin(), curves.end());
      const int                 distance = gmsh::model::mesh::field::add("Distance");
      gmsh::model::mesh::field::setNumbers(distance, "CurvesList", list);
      gmsh::model::mesh::field::setNumber(distance, "NumPointsPerCurve", samples);
      const int threshold = gmsh::model::mesh::field::add("Threshold");
      gmsh::model::mesh::field::setNumber(threshold, "IField", distance);
      gmsh::model::mesh::field::setNumber(threshold, "LcMin", h);
      gmsh::model::mesh::field::setNumber(threshold, "LcMax", H);
      gmsh::model::mesh::field::setNumber(threshold, "DistMin", spec.layer_thickness);
      gmsh::model::mesh::field::setNumber(threshold,
                                          "DistMax",
                                          spec.layer_thickness + std::max((H - h) / (2 * spec.size_growth), h));
      gmsh::model::mesh::field::setAsBackgroundMesh(threshold);
    }

    /**
     * Mesh the current model (set_meshing_options()) and refuse a result that is not all
     * quadrilaterals; returns their number.
     */
    unsigned long
    generate_quadrilaterals()
    {
      set_meshing_options();
      try
        {
          gmsh::model::mesh::generate(2);
        }
      catch (const std::string &message)
        {
          throw NumericalError("gmsh could not mesh the pin–bushing pair: " + message);
        }
      // deal.II needs quadrilaterals only: refuse a mixed mesh rather than pass it on.
      std::vector<int>                      types;
      std::vector<std::vector<std::size_t>> element_tags, node_tags;
      gmsh::model::mesh::getElements(types, element_tags, node_tags, 2);
      unsigned long n = 0;
      for (std::size_t t = 0; t < types.size(); ++t)
        {
          if (types[t] == 3)
            n += element_tags[t].size();
          else if (!element_tags[t].empty())
            throw NumericalError("gmsh left " + std::to_string(element_tags[t].size()) +
                                 " non-quadrilateral elements (type " + std::to_string(types[t]) +
                                 ") in the pin–bushing mesh; change 'Surface element size' or "
                                 "'Size growth' slightly.");
        }
      return n;
    }

    /** One meshed sector of a body: its nodes, elements, and how its radial edges join. */
    struct SectorMesh
    {
      std::vector<std::array<double, 2>>      points;
      std::vector<std::array<std::size_t, 4>> quads;        ///< local node indices
      std::vector<std::array<std::size_t, 2>> contact, far; ///< boundary segments on the two arcs
      /** Per node: −1, or (on the edge at angle α) the node of the edge at 0 it is after a rotation by α. */
      std::vector<long> master;
    };

    /** Sectors of a body whose contact surface has radius @p r (surface size @p h). */
    unsigned int
    sector_count(const double r, const double h)
    {
      return std::max(4L, std::lround(2 * pi * r / (periodic_sector_elements * h)));
    }

    /** Node and element data of the current gmsh model's entity (@p dim, @p tag) by type. */
    std::vector<std::size_t>
    element_nodes(const int type, const int tag)
    {
      std::vector<std::size_t> elements, nodes;
      gmsh::model::mesh::getElementsByType(type, elements, nodes, tag);
      return nodes;
    }

    /**
     * Mesh the annular sector inner ≤ r ≤ outer, 0 ≤ θ ≤ 2π/K, whose contact arc (inner
     * or outer) is transfinite at the surface size, the other sizes from the distance to
     * it (as in the full mesh), the radial edge at 2π/K a rotated copy of the one at 0.
     */
    SectorMesh
    mesh_sector(const double             inner,
                const double             outer,
                const bool               contact_outside,
                const unsigned int       K,
                const MeshSpecification &spec)
    {
      const double h = 2 * spec.surface_element_size, H = 2 * spec.max_element_size, alpha = 2 * pi / K;
      gmsh::model::add(contact_outside ? "pin_sector" : "ring_sector");
      namespace geo   = gmsh::model::geo;
      const double hi = contact_outside ? H : h, ho = contact_outside ? h : H;
      const int    centre = geo::addPoint(0, 0, 0, H);
      const int    i0     = geo::addPoint(inner, 0, 0, hi),
                i1        = geo::addPoint(inner * std::cos(alpha), inner * std::sin(alpha), 0, hi);
      const int o0        = geo::addPoint(outer, 0, 0, ho),
                o1        = geo::addPoint(outer * std::cos(alpha), outer * std::sin(alpha), 0, ho);
      const int left = geo::addLine(i0, o0), right = geo::addLine(i1, o1);
      const int inner_arc = geo::addCircleArc(i0, centre, i1), outer_arc = geo::addCircleArc(o0, centre, o1);
      const int loop    = geo::addCurveLoop({left, outer_arc, -right, -inner_arc}); // counter-clockwise
      const int surface = geo::addPlaneSurface({loop});
      const int contact = contact_outside ? outer_arc : inner_arc;
      geo::mesh::setTransfiniteCurve(contact, periodic_sector_elements / 2 + 1);
      geo::synchronize();
      const double c = std::cos(alpha), s = std::sin(alpha);
      gmsh::model::mesh::setPeriodic(1, {right}, {left}, {c, -s, 0, 0, s, c, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1});
      set_size_field({contact}, 4 * periodic_sector_elements, spec);
      generate_quadrilaterals();

      SectorMesh               m;
      std::vector<std::size_t> tags;
      std::vector<double>      coords, params;
      gmsh::model::mesh::getNodes(tags, coords, params, -1, -1, false, false);
      // The nodes of the sector's quadrilaterals (not, e.g., the centre point's).
      std::set<std::size_t> used;
      for (const auto t : element_nodes(3, surface))
        used.insert(t);
      std::map<std::size_t, std::size_t> index;
      for (std::size_t i = 0; i < tags.size(); ++i)
        if (used.count(tags[i]) != 0)
          {
            index[tags[i]] = m.points.size();
            m.points.push_back({{coords[3 * i], coords[3 * i + 1]}});
          }
      // Quadrilaterals counter-clockwise (deal.II needs a positive Jacobian; gmsh's
      // orientation follows the surface's, which it may choose either way).
      const auto quads = element_nodes(3, surface);
      for (std::size_t e = 0; e + 3 < quads.size(); e += 4)
        {
          std::array<std::size_t, 4> q = {
            {index.at(quads[e]), index.at(quads[e + 1]), index.at(quads[e + 2]), index.at(quads[e + 3])}};
          double area2 = 0; // twice the signed area (shoelace)
          for (unsigned v = 0; v < 4; ++v)
            {
              const auto &a = m.points[q[v]], &b = m.points[q[(v + 1) % 4]];
              area2 += a[0] * b[1] - a[1] * b[0];
            }
          if (area2 < 0)
            std::swap(q[1], q[3]);
          m.quads.push_back(q);
        }
      auto segments = [&](const int curve, std::vector<std::array<std::size_t, 2>> &out) {
        const auto lines = element_nodes(1, curve);
        for (std::size_t e = 0; e + 1 < lines.size(); e += 2)
          out.push_back({{index.at(lines[e]), index.at(lines[e + 1])}});
      };
      segments(contact, m.contact);
      segments(contact_outside ? inner_arc : outer_arc, m.far);
      int                      tag_master = 0;
      std::vector<std::size_t> slaves, masters;
      std::vector<double>      affine;
      gmsh::model::mesh::getPeriodicNodes(1, right, tag_master, slaves, masters, affine);
      m.master.assign(m.points.size(), -1);
      for (std::size_t k = 0; k < slaves.size(); ++k)
        m.master[index.at(slaves[k])] = static_cast<long>(index.at(masters[k]));
      return m;
    }

    /**
     * K rotated copies of @p sector as the nodes and elements of the discrete entities
     * @p surface, @p contact_curve and @p far_curve of the current model; node and
     * element tags continue from @p next_node and @p next_element.
     */
    void
    add_rotated_copies(const SectorMesh &sector,
                       const unsigned    K,
                       const int         surface,
                       const int         contact_curve,
                       const int         far_curve,
                       std::size_t      &next_node,
                       std::size_t      &next_element)
    {
      const std::size_t        n = sector.points.size();
      std::vector<std::size_t> own(n);
      std::size_t              n_own = 0;
      for (std::size_t i = 0; i < n; ++i)
        if (sector.master[i] < 0)
          own[i] = n_own++;
      const std::size_t first = next_node;
      auto              tag   = [&](const unsigned k, const std::size_t i) {
        if (sector.master[i] >= 0)
          return first + ((k + 1) % K) * n_own + own[sector.master[i]];
        return first + k * n_own + own[i];
      };
      std::vector<std::size_t> node_tags;
      std::vector<double>      coords;
      for (unsigned k = 0; k < K; ++k)
        {
          const double c = std::cos(2 * pi * k / K), s = std::sin(2 * pi * k / K);
          for (std::size_t i = 0; i < n; ++i)
            if (sector.master[i] < 0)
              {
                const auto &p = sector.points[i];
                node_tags.push_back(tag(k, i));
                coords.insert(coords.end(), {c * p[0] - s * p[1], s * p[0] + c * p[1], 0.0});
              }
        }
      gmsh::model::mesh::addNodes(2, surface, node_tags, coords);
      next_node += K * n_own;
      auto add = [&](const int dim_tag, const int type, const auto &elements) {
        std::vector<std::size_t> element_tags, nodes;
        for (unsigned k = 0; k < K; ++k)
          for (const auto &e : elements)
            {
              element_tags.push_back(next_element++);
              for (const auto i : e)
                nodes.push_back(tag(k, i));
            }
        gmsh::model::mesh::addElementsByType(dim_tag, type, element_tags, nodes);
      };
      add(surface, 3, sector.quads);
      add(contact_curve, 1, sector.contact);
      add(far_curve, 1, sector.far);
    }
  } // namespace


  void
  check_pin_bushing_geometry(const Profile &bore, const Profile &pin, const MeshSpecification &spec)
  {
    bore.check("bore profile");
    pin.check("pin profile");
    const auto positive = [](double v) {
      return std::isfinite(v) && v > 0;
    };
    if (!positive(spec.surface_element_size) || !positive(spec.max_element_size) || !positive(spec.size_growth) ||
        !(spec.layer_thickness >= 0))
      throw InputError("The FE mesh sizes must be finite and > 0 (surface element size " +
                       number(spec.surface_element_size) + " m, maximum element size " + number(spec.max_element_size) +
                       " m, size growth " + number(spec.size_growth) + ").");
    if (!(pin.max_radius() < bore.min_radius()))
      throw InputError("The pin is not inside the bore: the largest pin radius (" + number(pin.max_radius()) +
                       " m) must be smaller than the smallest bore "
                       "radius (" +
                       number(bore.min_radius()) +
                       " m) so that the pin fits at any relative rotation. Check the radii "
                       "(bore radius > pin radius) and the profile files.");
    if (!(positive(spec.core_radius) && spec.core_radius < pin.min_radius()))
      throw InputError("The rigid core of the pin (radius " + number(spec.core_radius) +
                       " m) must have a positive radius smaller than the smallest pin radius (" +
                       number(pin.min_radius()) + " m).");
    if (!(positive(spec.outer_radius) && spec.outer_radius > bore.max_radius()))
      throw InputError("The bushing outer radius (" + number(spec.outer_radius) +
                       " m) must be larger than the largest bore radius (" + number(bore.max_radius()) + " m).");
    // Each ring must hold a few elements across: an element wider than a quarter of the
    // thinner ring gives a mesh of a few degenerate elements, and the solver then fails
    // on its singular stiffness with a message that names no entry.
    const double ring = std::min(pin.min_radius() - spec.core_radius, spec.outer_radius - bore.max_radius());
    if (!(spec.surface_element_size <= ring / 4))
      throw InputError("The FE surface element size (" + number(spec.surface_element_size) +
                       " m) is larger than a quarter of the thinner ring of the pin–bushing pair (" + number(ring) +
                       " m: the pin between its rigid core and its surface, or the bushing between its bore and its "
                       "outer edge), so no mesh can resolve the rings. Choose 'Surface element size' well below it; "
                       "contact half-widths call for micrometres.");
  }


  namespace
  {
    /** The periodic construction (see write_pin_bushing_mesh()) of a round pair. */
    MeshStatistics
    write_periodic_mesh(const double R1, const double R2, const MeshSpecification &spec, const std::string &msh_path)
    {
      GmshSession    session;
      MeshStatistics stats;
      const double   h      = spec.surface_element_size;
      stats.pin_sectors     = sector_count(R2, h);
      stats.bore_sectors    = sector_count(R1, h);
      const SectorMesh pin  = mesh_sector(spec.core_radius, R2, true, stats.pin_sectors, spec);
      const SectorMesh ring = mesh_sector(R1, spec.outer_radius, false, stats.bore_sectors, spec);

      gmsh::model::add("pin_bushing");
      enum : int
      {
        pin_area = 1,
        ring_area,
        core_curve = 1,
        pin_curve,
        bore_curve,
        outer_curve
      };
      for (const int t : {pin_area, ring_area})
        gmsh::model::addDiscreteEntity(2, t);
      for (const int t : {core_curve, pin_curve, bore_curve, outer_curve})
        gmsh::model::addDiscreteEntity(1, t);
      std::size_t next_node = 1, next_element = 1;
      add_rotated_copies(pin, stats.pin_sectors, pin_area, pin_curve, core_curve, next_node, next_element);
      add_rotated_copies(ring, stats.bore_sectors, ring_area, bore_curve, outer_curve, next_node, next_element);
      name_group(2, {pin_area}, "MaterialID:" + std::to_string(material_ids::pin));
      name_group(2, {ring_area}, "MaterialID:" + std::to_string(material_ids::bushing));
      name_group(1, {core_curve}, "BoundaryID:" + std::to_string(boundary_ids::pin_core));
      name_group(1, {pin_curve}, "BoundaryID:" + std::to_string(boundary_ids::pin_surface));
      name_group(1, {bore_curve}, "BoundaryID:" + std::to_string(boundary_ids::bore_surface));
      name_group(1, {outer_curve}, "BoundaryID:" + std::to_string(boundary_ids::bushing_outer));

      stats.n_nodes          = next_node - 1;
      stats.n_quadrilaterals = stats.pin_sectors * pin.quads.size() + stats.bore_sectors * ring.quads.size();
      stats.n_refined_surface_segments =
        stats.pin_sectors * pin.contact.size() + stats.bore_sectors * ring.contact.size();
      write_mesh_file(msh_path);
      return stats;
    }
  } // namespace


  namespace
  {
    MeshStatistics
    write_general_mesh(const Profile           &bore,
                       const Profile           &pin,
                       const MeshSpecification &spec,
                       const std::string       &msh_path);
  } // namespace

  MeshStatistics
  write_pin_bushing_mesh(const Profile           &bore,
                         const Profile           &pin,
                         const MeshSpecification &spec,
                         const std::string       &msh_path)
  {
    // gmsh throws its messages as strings, from its geometry kernel too (a rigid core of
    // 1e-300 of the pin radius): a pair it cannot build is a numerical failure of the
    // mesher, named as such, never an exception of unknown type.
    try
      {
        return write_general_mesh(bore, pin, spec, msh_path);
      }
    catch (const std::string &message)
      {
        throw NumericalError("gmsh could not build the pin–bushing mesh (bore radius " + number(bore.mean_radius()) +
                             " m, pin radius " + number(pin.mean_radius()) + " m, rigid core radius " +
                             number(spec.core_radius) + " m, surface element size " +
                             number(spec.surface_element_size) + " m): " + message);
      }
  }

  namespace
  {
    MeshStatistics
    write_general_mesh(const Profile           &bore,
                       const Profile           &pin,
                       const MeshSpecification &spec,
                       const std::string       &msh_path)
    {
      check_pin_bushing_geometry(bore, pin, spec);
      if (spec.periodic && spec.refined_half_angle >= pi && bore.is_round() && pin.is_round())
        return write_periodic_mesh(bore.mean_radius(), pin.mean_radius(), spec, msh_path);
      // Sizes before the final split of every element into quadrilaterals (see below).
      const double h = 2 * spec.surface_element_size;
      const double H = 2 * spec.max_element_size;

      GmshSession session;
      gmsh::model::add("pin_bushing");
      MeshStatistics stats;

      // Pin annulus: surface (outer) loop and rigid-core hole.
      std::vector<int> refined;
      unsigned long    pin_segments = 0, bore_segments = 0;
      const auto       pin_curves =
        add_profile_curve(pin, h, spec.pin_refined_centre, spec.refined_half_angle, refined, pin_segments);
      const auto core_curves = add_circle(spec.core_radius, H);
      const int  pin_loop    = gmsh::model::geo::addCurveLoop(pin_curves);
      const int  core_loop   = gmsh::model::geo::addCurveLoop(core_curves);
      const int  pin_area    = gmsh::model::geo::addPlaneSurface({pin_loop, core_loop});

      // Bushing ring: fixed outer circle and the bore as its hole.
      const auto bore_curves =
        add_profile_curve(bore, h, spec.bore_refined_centre, spec.refined_half_angle, refined, bore_segments);
      stats.n_refined_surface_segments = 2 * (pin_segments + bore_segments);
      const auto outer_curves          = add_circle(spec.outer_radius, H);
      const int  outer_loop            = gmsh::model::geo::addCurveLoop(outer_curves);
      const int  bore_loop             = gmsh::model::geo::addCurveLoop(bore_curves);
      const int  ring_area             = gmsh::model::geo::addPlaneSurface({outer_loop, bore_loop});
      gmsh::model::geo::synchronize();

      name_group(2, {pin_area}, "MaterialID:" + std::to_string(material_ids::pin));
      name_group(2, {ring_area}, "MaterialID:" + std::to_string(material_ids::bushing));
      name_group(1, core_curves, "BoundaryID:" + std::to_string(boundary_ids::pin_core));
      name_group(1, pin_curves, "BoundaryID:" + std::to_string(boundary_ids::pin_surface));
      name_group(1, bore_curves, "BoundaryID:" + std::to_string(boundary_ids::bore_surface));
      name_group(1, outer_curves, "BoundaryID:" + std::to_string(boundary_ids::bushing_outer));

      // Element size from the distance to the refined, uniformly spaced arcs of both surfaces.
      set_size_field(refined, static_cast<double>(std::max(pin_segments, bore_segments)) + 10, spec);
      stats.n_quadrilaterals = generate_quadrilaterals();
      std::vector<std::size_t> all_nodes;
      std::vector<double>      coords, params;
      gmsh::model::mesh::getNodes(all_nodes, coords, params, -1, -1, false, false);
      stats.n_nodes = all_nodes.size();

      write_mesh_file(msh_path);
      return stats;
    }
  } // namespace
} // namespace wearlink::fe
