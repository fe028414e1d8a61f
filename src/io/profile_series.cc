// SPDX-License-Identifier: LGPL-2.1-or-later
#include "io/profile_series.h"

#include "base/atomic_file.h"
#include "base/numbers.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <sstream>

namespace wearlink::io
{
  namespace
  {
    /** One surface's samples: radius, cumulative depth, pressure, and which way it wears (+1 out, −1 in). */
    struct Curve
    {
      const Profile             *profile;
      const std::vector<double> *depth;
      const std::vector<double> *pressure;
      double                     direction;
    };

    /** A DataArray of @p components per point, from @p value(curve, k, component). */
    template <class Value>
    void
    data_array(std::ostream &os, const std::string &name, int components, const std::vector<Curve> &curves, Value value)
    {
      os << "        <DataArray type=\"Float64\" Name=\"" << name << "\" NumberOfComponents=\"" << components
         << "\" format=\"ascii\">\n";
      for (const auto &c : curves)
        for (unsigned int k = 0; k < c.profile->n_points(); ++k)
          {
            os << "         ";
            for (int d = 0; d < components; ++d)
              os << ' ' << value(c, k, d);
            os << '\n';
          }
      os << "        </DataArray>\n";
    }

    double
    at(const std::vector<double> *v, const unsigned int k)
    {
      return v && k < v->size() ? (*v)[k] : 0.0;
    }

    /** The VTU of two closed poly-lines (see the header). */
    std::string
    profile_vtu(const std::vector<Curve> &curves)
    {
      std::ostringstream os;
      os << std::setprecision(15);
      unsigned int n_points = 0;
      for (const auto &c : curves)
        n_points += c.profile->n_points();
      os << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
         << "  <UnstructuredGrid>\n    <Piece NumberOfPoints=\"" << n_points << "\" NumberOfCells=\"" << curves.size()
         << "\">\n      <Points>\n";
      const auto direction = [](const Curve &c, unsigned int k) {
        return c.profile->angle(k);
      };
      data_array(os, "position", 3, curves, [&](const Curve &c, unsigned int k, int d) {
        const double r = (*c.profile)[k], a = direction(c, k);
        return d == 0 ? r * std::cos(a) : d == 1 ? r * std::sin(a) : 0.0;
      });
      os
        << "      </Points>\n      <Cells>\n        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
      unsigned int first = 0;
      std::string  offsets;
      for (const auto &c : curves)
        {
          os << "         ";
          for (unsigned int k = 0; k < c.profile->n_points(); ++k)
            os << ' ' << first + k;
          os << ' ' << first << '\n'; // closed
          first += c.profile->n_points();
          offsets += " " + std::to_string(first + (&c - curves.data()) + 1);
        }
      os << "        </DataArray>\n        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">" << offsets
         << "</DataArray>\n        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">";
      for (std::size_t i = 0; i < curves.size(); ++i)
        os << " 4"; // VTK_POLY_LINE
      os
        << "</DataArray>\n      </Cells>\n      <PointData Scalars=\"wear_depth_m\" Vectors=\"wear_displacement_m\">\n";
      data_array(os, "wear_depth_m", 1, curves, [](const Curve &c, unsigned int k, int) { return at(c.depth, k); });
      data_array(os, "wear_displacement_m", 3, curves, [&](const Curve &c, unsigned int k, int d) {
        const double h = c.direction * at(c.depth, k), a = direction(c, k);
        return d == 0 ? h * std::cos(a) : d == 1 ? h * std::sin(a) : 0.0;
      });
      data_array(os, "radius_m", 1, curves, [](const Curve &c, unsigned int k, int) { return (*c.profile)[k]; });
      data_array(os, "contact_pressure_Pa", 1, curves, [](const Curve &c, unsigned int k, int) {
        return at(c.pressure, k);
      });
      os << "      </PointData>\n      <CellData Scalars=\"surface\">\n        <DataArray type=\"Int32\" "
            "Name=\"surface\" format=\"ascii\">";
      for (std::size_t i = 0; i < curves.size(); ++i)
        os << ' ' << i;
      os << "</DataArray>\n      </CellData>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
      return os.str();
    }

    std::string
    frame_name(const std::string &joint, const unsigned int k)
    {
      return "profiles/profile_" + joint + "_" + std::to_string(k) + ".vtu";
    }
  } // namespace

  void
  write_pvd(const std::string &path, const std::vector<double> &times, const std::vector<std::string> &files)
  {
    std::ostringstream os;
    os << std::setprecision(15) << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n"
       << "  <Collection>\n";
    for (std::size_t i = 0; i < files.size() && i < times.size(); ++i)
      os << "    <DataSet timestep=\"" << times[i] << "\" part=\"0\" file=\"" << files[i] << "\"/>\n";
    os << "  </Collection>\n</VTKFile>\n";
    write_file_atomically(path, os.str());
  }

  void
  remove_series_files(const std::string               &dir,
                      const std::string               &prefix,
                      const std::string               &suffix,
                      const std::vector<unsigned int> &keep)
  {
    if (!std::filesystem::is_directory(dir))
      return;
    std::vector<std::filesystem::path> old;
    for (const auto &entry : std::filesystem::directory_iterator(dir))
      {
        const std::string name = entry.path().filename().string();
        if (name.size() <= prefix.size() + suffix.size() || name.compare(0, prefix.size(), prefix) != 0 ||
            name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0)
          continue;
        const std::string number = name.substr(prefix.size(), name.size() - prefix.size() - suffix.size());
        if (number.size() > 9 ||
            !std::all_of(number.begin(), number.end(), [](unsigned char c) { return std::isdigit(c); }))
          continue;
        if (std::find(keep.begin(), keep.end(), static_cast<unsigned int>(std::stoul(number))) == keep.end())
          old.push_back(entry.path());
      }
    for (const auto &path : old)
      std::filesystem::remove(path);
  }

  void
  write_profile_frame(const std::string              &dir,
                      const wear::WearState          &state,
                      const unsigned int              joint,
                      const contact::SurfacePressure &pressure,
                      const double                    cycles_per_iteration,
                      const bool                      every_iteration)
  {
    const auto &js = state.joints.at(joint);
    std::filesystem::create_directories(dir + "/profiles");
    const unsigned int k = state.iterations_done;
    if (k > 0 && !std::filesystem::exists(dir + "/" + frame_name(js.name, 0)))
      write_file_atomically(dir + "/" + frame_name(js.name, 0),
                            profile_vtu(
                              {{&js.initial_bore, nullptr, nullptr, 1}, {&js.initial_pin, nullptr, nullptr, -1}}));
    const wear::IterationRecord none;
    const auto                 &r = js.history.empty() ? none : js.history.back();
    write_file_atomically(dir + "/" + frame_name(js.name, k),
                          profile_vtu({{&js.bore, &r.depth_bore, &pressure.bore, 1},
                                       {&js.pin, &r.depth_pin, &pressure.pin, -1}}));
    if (!every_iteration)
      remove_series_files(dir + "/profiles", "profile_" + js.name + "_", ".vtu", {0, k});
    std::vector<double>      times{0};
    std::vector<std::string> files{frame_name(js.name, 0)};
    double                   revolutions = 0;
    for (unsigned int i = 0; i < k && i < state.factors.size(); ++i)
      {
        revolutions += state.factors[i] * cycles_per_iteration;
        if (std::filesystem::exists(dir + "/" + frame_name(js.name, i + 1)))
          {
            times.push_back(revolutions);
            files.push_back(frame_name(js.name, i + 1));
          }
      }
    write_pvd(dir + "/profiles_" + js.name + ".pvd", times, files);
  }
} // namespace wearlink::io
