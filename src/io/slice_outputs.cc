// SPDX-License-Identifier: LGPL-2.1-or-later
#include "io/slice_outputs.h"

#include "base/atomic_file.h"
#include "base/numbers.h"
#include "io/plot.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <map>
#include <sstream>

namespace wearlink::io
{
  namespace
  {
    using numbers::pi;

    /** One sliced joint: its slices' wear states and places, in slice order. */
    struct SlicedJoint
    {
      std::string                               name;
      double                                    length = 0; ///< the joint's axial length [m]
      std::vector<const wear::JointWearState *> slices;
      std::vector<double>                       positions; ///< z_i [m]
      std::vector<double>                       radii;     ///< nominal bore, pin [m]
    };

    std::vector<SlicedJoint>
    sliced_joints(const Scene &scene, const wear::WearState &st)
    {
      std::vector<SlicedJoint>           out;
      std::map<std::string, std::size_t> where;
      for (const auto &js : st.joints)
        for (const auto *cj : scene.clearance_joints)
          {
            const auto &d = cj->get_description();
            if (d.name != js.name || d.slice.count < 2)
              continue;
            const auto it = where.emplace(d.slice.joint, out.size()).first;
            if (it->second == out.size())
              out.push_back({d.slice.joint,
                             d.geometry.axial_length * d.slice.count,
                             {},
                             {},
                             {d.slice.nominal_bore_radius, d.slice.nominal_pin_radius}});
            out[it->second].slices.push_back(&js);
            out[it->second].positions.push_back(d.slice.position);
          }
      return out;
    }

    /** The deepest of @p values over the slices, and where. */
    struct Deepest
    {
      double depth = 0, position = 0;
      int    slice = 0;
    };

    Deepest
    deepest(const SlicedJoint &j, const bool bore)
    {
      Deepest d;
      for (std::size_t i = 0; i < j.slices.size(); ++i)
        {
          const auto  &h     = j.slices[i]->history;
          const double depth = h.empty() ? 0.0 : (bore ? h.back().max_depth_bore : h.back().max_depth_pin);
          if (depth > d.depth)
            d = {depth, j.positions[i], static_cast<int>(i) + 1};
        }
      return d;
    }

    std::vector<double>
    last(const SlicedJoint &j, double wear::IterationRecord::*field)
    {
      std::vector<double> v;
      for (const auto *s : j.slices)
        v.push_back(s->history.empty() ? 0.0 : s->history.back().*field);
      return v;
    }

    void
    write_slice_table(const std::string &path, const SlicedJoint &j)
    {
      const auto force = last(j, &wear::IterationRecord::mean_normal_force);
      double     sum   = 0;
      for (const double f : force)
        sum += f;
      std::ostringstream os;
      os << std::setprecision(10)
         << "slice,z_m,mean_normal_force_N,force_share,volume_bushing_mm3,volume_pin_mm3,max_depth_bushing_um,"
            "max_depth_pin_um\n";
      for (std::size_t i = 0; i < j.slices.size(); ++i)
        {
          const auto &h = j.slices[i]->history;
          const auto  r = h.empty() ? wear::IterationRecord() : h.back();
          os << i + 1 << ',' << j.positions[i] << ',' << force[i] << ',' << (sum > 0 ? force[i] / sum : 0.0) << ','
             << r.volume_bore * 1e9 << ',' << r.volume_pin * 1e9 << ',' << r.max_depth_bore * 1e6 << ','
             << r.max_depth_pin * 1e6 << '\n';
        }
      write_file_atomically(path, os.str());
    }

    /** The depth field of iteration @p it (0-based) of one surface, per slice and area [m]. */
    std::vector<std::vector<double>>
    depth_field(const SlicedJoint &j, const bool bore, const std::size_t it)
    {
      std::vector<std::vector<double>> z;
      for (const auto *s : j.slices)
        z.push_back(bore ? s->history[it].depth_bore : s->history[it].depth_pin);
      return z;
    }

    /**
     * The worn depth of one surface over angle × axial position at iteration @p it
     * (0-based), on a colour scale up to @p z_max [µm] (0: its own largest depth).
     */
    void
    plot_wear_map(const std::string &path, const SlicedJoint &j, const bool bore, const std::size_t it, double z_max)
    {
      HeatMap m;
      m.title = "joint " + j.name + ", worn " + (bore ? "bushing (bushing frame)" : "pin (pin frame)") + ", " +
                std::to_string(j.slices.size()) + " slices, iteration " + std::to_string(it + 1);
      m.z_max   = z_max;
      m.x_label = "angle [deg]";
      m.y_label = "axial position z [mm]";
      m.z_label = "worn depth [µm]";
      const std::size_t n =
        (bore ? j.slices[0]->history.back().depth_bore : j.slices[0]->history.back().depth_pin).size();
      for (std::size_t k = 0; k < n; ++k)
        m.x.push_back(360.0 * static_cast<double>(k) / static_cast<double>(n));
      for (const double z : j.positions)
        m.y.push_back(z * 1e3);
      m.z = depth_field(j, bore, it);
      for (auto &row : m.z)
        for (auto &v : row)
          v *= 1e6;
      plot_heat_map_png(m, path);
    }

    /**
     * One surface at iteration @p it as a VTU cylinder of radius @p radius: points at
     * the areas' angles × the slices' positions, quads between them (closed around),
     * the depth [µm] as point data.
     */
    std::string
    surface_vtu(const SlicedJoint &j, const bool bore, const std::size_t it, const double radius)
    {
      const auto         depth = depth_field(j, bore, it);
      const std::size_t  nz = depth.size(), na = depth[0].size();
      std::ostringstream os;
      os << std::setprecision(7)
         << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\">\n<UnstructuredGrid>\n"
         << "<Piece NumberOfPoints=\"" << nz * na << "\" NumberOfCells=\"" << (nz - 1) * na << "\">\n"
         << "<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
      for (std::size_t i = 0; i < nz; ++i)
        for (std::size_t k = 0; k < na; ++k)
          {
            const double psi = 2 * pi * static_cast<double>(k) / static_cast<double>(na);
            os << radius * std::cos(psi) << ' ' << radius * std::sin(psi) << ' ' << j.positions[i] << '\n';
          }
      os << "</DataArray></Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
      for (std::size_t i = 0; i + 1 < nz; ++i)
        for (std::size_t k = 0; k < na; ++k)
          {
            const std::size_t k1 = (k + 1) % na;
            os << i * na + k << ' ' << i * na + k1 << ' ' << (i + 1) * na + k1 << ' ' << (i + 1) * na + k << '\n';
          }
      os << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
      for (std::size_t c = 1; c <= (nz - 1) * na; ++c)
        os << 4 * c << '\n';
      os << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
      for (std::size_t c = 0; c < (nz - 1) * na; ++c)
        os << "9\n";
      os << "</DataArray>\n</Cells>\n<PointData Scalars=\"depth_um\">\n"
         << "<DataArray type=\"Float64\" Name=\"depth_um\" format=\"ascii\">\n";
      for (const auto &row : depth)
        for (const double h : row)
          os << h * 1e6 << '\n';
      os << "</DataArray>\n</PointData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
      return os.str();
    }

    /** The frames of the .pvd series: every iteration, or at most ten spread over them. */
    std::vector<std::size_t>
    frames(const std::size_t iterations, const bool every)
    {
      std::vector<std::size_t> f;
      const std::size_t        most = every ? iterations : std::min<std::size_t>(iterations, 10);
      for (std::size_t k = 1; k <= most; ++k)
        {
          const std::size_t it = (k * iterations + most - 1) / most - 1; // the last one is the last iteration
          if (f.empty() || it != f.back())
            f.push_back(it);
        }
      return f;
    }

    void
    write_surfaces(const std::string &dir, const SlicedJoint &j, const bool every, const double revolutions_per_it)
    {
      namespace fs = std::filesystem;
      fs::create_directories(dir + "/slices");
      for (const bool bore : {true, false})
        {
          const std::string  surface = bore ? "bushing" : "pin";
          std::ostringstream pvd;
          pvd << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
          for (const auto it : frames(j.slices[0]->history.size(), every))
            {
              const std::string name = j.name + "_" + surface + "_it" + std::to_string(it + 1) + ".vtu";
              write_file_atomically(dir + "/slices/" + name, surface_vtu(j, bore, it, j.radii[bore ? 0 : 1]));
              const double revolutions = j.slices[0]->history[it].relative_revolutions;
              pvd << "<DataSet timestep=\"" << (revolutions > 0 ? revolutions : revolutions_per_it * (it + 1))
                  << "\" file=\"" << name << "\"/>\n";
            }
          pvd << "</Collection>\n</VTKFile>\n";
          write_file_atomically(dir + "/slices/" + j.name + "_" + surface + ".pvd", pvd.str());
        }
    }
  } // namespace

  bool
  has_sliced_joints(const Scene &scene)
  {
    return std::any_of(scene.clearance_joints.begin(), scene.clearance_joints.end(), [](const auto *j) {
      return j->get_description().slice.count > 1;
    });
  }

  Json
  sliced_wear_summary(const Scene &scene, const wear::WearState &st)
  {
    Json out = Json::object();
    for (const auto &j : sliced_joints(scene, st))
      {
        const auto force = last(j, &wear::IterationRecord::mean_normal_force);
        double     sum = 0, largest = 0;
        for (const double f : force)
          {
            sum += f;
            largest = std::max(largest, f);
          }
        const double mean = sum / static_cast<double>(force.size());
        const auto   bore = deepest(j, true), pin = deepest(j, false);
        Json         o                    = Json::object();
        o["slices"]                       = j.slices.size();
        o["positions_m"]                  = j.positions;
        o["mean_normal_force_N"]          = force;
        o["edge_to_mean_force"]           = mean > 0 ? std::max(force.front(), force.back()) / mean : 0.0;
        o["largest_to_mean_force"]        = mean > 0 ? largest / mean : 0.0;
        o["max_depth_bushing_m"]          = bore.depth;
        o["max_depth_bushing_position_m"] = bore.position;
        o["max_depth_pin_m"]              = pin.depth;
        o["max_depth_pin_position_m"]     = pin.position;
        o["volume_bushing_m3"]            = last(j, &wear::IterationRecord::volume_bore);
        o["volume_pin_m3"]                = last(j, &wear::IterationRecord::volume_pin);
        out[j.name]                       = o;
      }
    return out;
  }

  void
  write_sliced_wear_outputs(const std::string &dir, const Scene &scene, const wear::WearState &st)
  {
    for (const auto &j : sliced_joints(scene, st))
      {
        if (j.slices[0]->history.empty())
          continue;
        write_slice_table(dir + "/slices_" + j.name + ".csv", j);
        const bool every = scene.wear_loop.every_iteration_output;
        write_surfaces(dir, j, every, 0);
        if (!scene.plots)
          continue;
        // The last iteration beside the run's files; the frames of the VTU series (at
        // most ten unless every iteration's outputs are asked for) in slices/, on the
        // last iteration's colour scale, so that the maps of a series compare.
        const std::size_t last = j.slices[0]->history.size() - 1;
        for (const bool bore : {true, false})
          {
            const std::string surface = bore ? "bushing" : "pin";
            plot_wear_map(dir + "/wear_map_" + j.name + "_" + surface + ".png", j, bore, last, 0);
            double top = 0;
            for (const auto &row : depth_field(j, bore, last))
              for (const double v : row)
                top = std::max(top, v * 1e6);
            for (const auto it : frames(last + 1, every))
              plot_wear_map(dir + "/slices/" + j.name + "_" + surface + "_it" + std::to_string(it + 1) + ".png",
                            j,
                            bore,
                            it,
                            top);
          }
      }
  }
} // namespace wearlink::io
