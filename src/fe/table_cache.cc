// SPDX-License-Identifier: LGPL-2.1-or-later
#include "fe/table_cache.h"

#include "base/atomic_file.h"
#include "fe/fe_normal_force_law.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace wearlink::fe
{
  namespace
  {
    namespace fs = std::filesystem;

    std::string
    cache_directory()
    {
      if (const char *d = std::getenv("WEARLINK_CACHE_DIR"); d != nullptr && *d != '\0')
        return d;
      if (const char *d = std::getenv("XDG_CACHE_HOME"); d != nullptr && *d != '\0')
        return std::string(d) + "/wearlink";
      if (const char *h = std::getenv("HOME"); h != nullptr && *h != '\0')
        return std::string(h) + "/.cache/wearlink";
      return (fs::temp_directory_path() / "wearlink-cache").string();
    }
  } // namespace

  std::string
  table_geometry_key(const contact::JointGeometry &g, const FeForceLawSettings &s, const contact::JointGeometry *meshed)
  {
    std::ostringstream k;
    k << std::setprecision(17);
    auto profiles = [&](const contact::JointGeometry &p, const char *prefix) {
      k << prefix << "bore";
      for (const double r : p.bore.samples())
        k << ' ' << r;
      k << '\n' << prefix << "pin";
      for (const double r : p.pin.samples())
        k << ' ' << r;
      k << '\n';
    };
    profiles(g, "");
    if (meshed != nullptr && (meshed->bore.samples() != g.bore.samples() || meshed->pin.samples() != g.pin.samples()))
      profiles(*meshed, "meshed ");
    const FeSettings &f = s.fe;
    k << "L " << g.axial_length << "\nE " << g.bushing.youngs_modulus << ' ' << g.bushing.poisson_ratio << ' '
      << g.pin_material.youngs_modulus << ' ' << g.pin_material.poisson_ratio << "\nfe " << f.surface_element_size
      << ' ' << f.max_element_size << ' ' << f.size_growth << ' ' << f.refined_layer_thickness << ' '
      << f.core_radius_fraction << ' ' << f.outer_radius << ' ' << f.outer_radius_ratio << ' ' << f.degree << ' '
      << f.refinements << ' ' << f.remesh_depth << "\ntable " << s.min_force << ' ' << s.max_force << ' ' << s.n_levels
      << ' ' << s.n_bore_directions << ' ' << s.n_pin_directions << '\n';
    return k.str();
  }

  std::string
  table_cache_file(const std::string &stem, const std::string &key)
  {
    std::ostringstream name;
    name << stem << '_' << std::hex << std::hash<std::string>()(key) << '_' << std::dec << key.size() << ".json";
    return cache_directory() + "/" + name.str();
  }

  Json
  read_table_cache(const std::string &file, const std::string &format, const int version, const std::string &key)
  {
    std::ifstream in(file);
    if (!in)
      return nullptr;
    Json j = Json::parse(in, nullptr, false);
    try
      {
        if (j.is_discarded() || !j.is_object() || j.value("format", "") != format || j.value("version", 0) != version ||
            j.value("key", "") != key)
          return nullptr;
      }
    catch (const std::exception &) // a damaged entry: rebuild (the file is overwritten)
      {
        return nullptr;
      }
    return j;
  }

  void
  write_table_cache(const std::string &file,
                    const std::string &format,
                    const int          version,
                    const std::string &key,
                    Json               entry)
  {
    Json j;
    j["format"]  = format;
    j["version"] = version;
    j["key"]     = key;
    for (auto &[name, value] : entry.items())
      j[name] = std::move(value);
    try
      {
        make_output_directory(fs::path(file).parent_path().string());
        write_file_atomically(file, j.dump());
      }
    catch (const std::exception &e) // a cache that cannot be written only costs time
      {
        std::cerr << "[wearlink] warning: cannot write the FE table cache '" << file << "': " << e.what() << '\n';
      }
  }
} // namespace wearlink::fe
