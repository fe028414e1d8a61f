// SPDX-License-Identifier: LGPL-2.1-or-later
#include "io/measurements.h"

#include "base/exceptions.h"
#include "base/parameters.h"
#include "base/text.h"
#include "io/profile_file.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>

namespace wearlink::io
{
  std::string
  wear_coefficient_entry(const std::string &joint, const std::string &surface)
  {
    return "Joint " + joint + "/Clearance/archard/" + (surface == "pin" ? "Pin" : "Bushing") + " wear coefficient";
  }

  namespace
  {
    const char *const entries[] = {"Revolutions",
                                   "Pin mass loss",
                                   "Pin mass loss uncertainty",
                                   "Bushing mass loss",
                                   "Bushing mass loss uncertainty",
                                   "Pin profile file",
                                   "Bore profile file",
                                   "Profile uncertainty",
                                   "Profile angle search"};

    /** What the pre-scan finds: the joints' subsections and the lines of their entries. */
    struct Layout
    {
      std::vector<std::pair<std::string, unsigned>> joints; ///< name, line of its subsection
      std::map<std::string, unsigned>               lines;  ///< "Joint A/Pin mass loss" → line
    };

    /** The top-level `subsection Joint X` lines and the `set` lines inside them. */
    Layout
    pre_scan(const std::string &file)
    {
      std::ifstream   in(file);
      std::error_code ec; // a name too long for the system: "no such file", not an exception
      if (!in)
        throw InputError("Cannot read the measurements file '" + file + "' (" +
                         (std::filesystem::exists(file, ec) ? "not readable" : "no such file") + ").");
      Layout                   layout;
      std::vector<std::string> path;
      std::string              line;
      for (unsigned n = 1; std::getline(in, line); ++n)
        {
          const std::string body = trim(line.substr(0, line.find('#')));
          if (body.rfind("subsection ", 0) == 0)
            {
              path.push_back(trim(body.substr(11)));
              if (path.size() == 1 && path[0].rfind("Joint ", 0) == 0)
                layout.joints.emplace_back(trim(path[0].substr(6)), n);
            }
          else if (body == "end" && !path.empty())
            path.pop_back();
          else if (body.rfind("set ", 0) == 0 && path.size() == 1 && body.find('=') != std::string::npos)
            layout.lines[path[0] + "/" + trim(body.substr(4, body.find('=') - 4))] = n;
        }
      return layout;
    }

    /** "In FILE line L: " or "In FILE: ". */
    std::string
    where(const std::string &file, const unsigned line)
    {
      return "In " + file + (line > 0 ? " line " + std::to_string(line) : std::string()) + ": ";
    }

    /** The joints of @p scene that wear, a sliced joint once by its own name. */
    std::vector<std::string>
    wearing_joints(const Scene &scene)
    {
      std::vector<std::string> wearing;
      for (const auto &w : scene.wear)
        if (const auto name = whole_joint(scene, w->joint);
            std::find(wearing.begin(), wearing.end(), name) == wearing.end())
          wearing.push_back(name);
      return wearing;
    }

    /** Each pre-scanned joint must be a joint of @p scene that wears. */
    void
    check_joints(const std::string &file, const Layout &layout, const Scene &scene)
    {
      const auto wearing = wearing_joints(scene);
      const auto all     = split(entry_value(*scene.parameters, "Mechanism/Joints"), ',');
      for (const auto &[name, line] : layout.joints)
        {
          const bool is_joint = std::find(all.begin(), all.end(), name) != all.end();
          if (std::find(wearing.begin(), wearing.end(), name) == wearing.end())
            throw InputError(where(file, line) + "'Joint " + name + "' " +
                             (is_joint ? "is a joint of " + scene.file + " that does not wear (no clearance with " +
                                           "'Wear law = archard'), so it has no wear coefficient to calibrate" :
                                         "is not a joint of " + scene.file) +
                             ". The joints that wear there: " + join(wearing, ", ") + ".");
        }
    }

    /** Entry @p entry of joint @p joint as a finite number, or NaN if it is not set. */
    double
    number(dealii::ParameterHandler &prm,
           const std::string        &file,
           const Layout             &layout,
           const std::string        &joint,
           const std::string        &entry)
    {
      const std::string path = "Joint " + joint + "/" + entry;
      const std::string text = trim(entry_value(prm, path));
      if (text.empty())
        return NAN;
      char        *end = nullptr;
      const double v   = std::strtod(text.c_str(), &end);
      if (end == text.c_str() || !trim(end).empty() || !std::isfinite(v))
        throw InputError(where(file, layout.lines.count(path) ? layout.lines.at(path) : 0) + "'" + path + "' is '" +
                         text + "'; it must be a finite number.");
      return v;
    }
  } // namespace

  namespace
  {
    /**
     * The mass loss [mg] of @p surface ("pin" | "bushing") that the measured profile @p p
     * shows against the scene's unworn surface (see the top of measurements.h).
     */
    SurfaceMeasurement
    profile_mass_loss(const ProfileMeasurement &p,
                      const std::string        &surface,
                      const Scene              &scene,
                      const std::string        &file,
                      const Layout             &layout)
    {
      const contact::ClearanceJoint *joint = nullptr;
      for (const auto *j : scene.clearance_joints)
        if (j->name() == p.joint)
          joint = j;
      const wear::JointWear *wear = nullptr;
      for (const auto &w : scene.wear)
        if (w->joint == p.joint)
          wear = w.get();
      const bool   pin     = surface == "pin";
      const auto  &g       = joint->get_description().geometry;
      const auto   unworn  = analysis::PolarTrace::of_profile(pin ? g.pin : g.bore);
      const auto   area    = analysis::measured_worn_area(p.trace, unworn, !pin, p.uncertainty);
      const double density = pin ? wear->archard.pin_density : wear->archard.bushing_density;
      const double to_mg   = 1e6 * density * g.axial_length; // m² → mg
      if (!(area.area > 0))
        {
          const std::string path = "Joint " + p.joint + (pin ? "/Pin profile file" : "/Bore profile file");
          throw InputError(where(file, layout.lines.count(path) ? layout.lines.at(path) : 0u) + "'" + path + "' (" +
                           p.file + ") shows a worn area of " + format_number(area.area, 4) + " m² against the " +
                           "scene's unworn " + p.surface +
                           ": nothing worn to fit. Check the file's units (m) and "
                           "surface, or give a mass loss instead.");
        }
      return {p.joint, surface, p.revolutions, to_mg * area.area, to_mg * area.sigma, p.file};
    }
  } // namespace

  namespace
  {
    /** The measured surfaces of joint @p joint (checked). */
    std::vector<SurfaceMeasurement>
    joint_measurements(dealii::ParameterHandler              &prm,
                       const std::string                     &file,
                       const Layout                          &layout,
                       const std::string                     &joint,
                       const std::vector<ProfileMeasurement> &profiles,
                       const Scene                           &scene)
    {
      const auto line_of = [&](const std::string &entry) {
        const std::string path = "Joint " + joint + "/" + entry;
        return layout.lines.count(path) ? layout.lines.at(path) : 0u;
      };
      const auto fail = [&](const std::string &entry, const std::string &what) {
        throw InputError(where(file, line_of(entry)) + "'Joint " + joint + "/" + entry + "' " + what);
      };
      const double                    revolutions = number(prm, file, layout, joint, "Revolutions");
      std::vector<SurfaceMeasurement> out;
      for (const std::string surface : {"pin", "bushing"})
        {
          const std::string name        = surface == "pin" ? "Pin mass loss" : "Bushing mass loss";
          const double      loss        = number(prm, file, layout, joint, name);
          const double      uncertainty = number(prm, file, layout, joint, name + " uncertainty");
          if (std::isnan(loss))
            {
              if (!std::isnan(uncertainty))
                fail(name + " uncertainty", "is given without '" + name + "'.");
              for (const auto &p : profiles)
                if ((p.surface == "pin") == (surface == "pin"))
                  out.push_back(profile_mass_loss(p, surface, scene, file, layout));
              continue;
            }
          if (!(loss > 0))
            fail(name, "is " + format_number(loss, 6) + "; a measured mass loss must be > 0 [mg].");
          if (std::isnan(uncertainty))
            fail(name + " uncertainty",
                 "is not set; give the 1σ uncertainty of '" + name + "' [mg, ≥ 0] (0: exact, the interval then " +
                   "comes from the chaos of the dynamics alone).");
          if (!(uncertainty >= 0))
            fail(name + " uncertainty", "is " + format_number(uncertainty, 6) + "; it must be ≥ 0 [mg, 1σ].");
          out.push_back({joint, surface, revolutions, loss, uncertainty, ""});
        }
      if (out.empty())
        throw InputError(where(file, layout.lines.empty() ? 0u : line_of("Revolutions")) + "'Joint " + joint +
                         "' has no measurement; set 'Pin mass loss' or 'Bushing mass loss' [mg] with its "
                         "uncertainty, or a profile file, or remove the subsection.");
      if (std::isnan(revolutions))
        fail("Revolutions", "is not set; give the mechanism revolutions of the test (> 0).");
      if (!(revolutions > 0))
        fail("Revolutions", "is " + format_number(revolutions, 6) + "; it must be > 0 (the test's revolutions).");
      return out;
    }
  } // namespace

  namespace
  {
    /** The measured profiles of joint @p joint (files read; checked). */
    std::vector<ProfileMeasurement>
    joint_profiles(dealii::ParameterHandler &prm,
                   const std::string        &file,
                   const Layout             &layout,
                   const std::string        &joint,
                   const double              revolutions)
    {
      const auto fail = [&](const std::string &entry, const std::string &what) {
        const std::string path = "Joint " + joint + "/" + entry;
        throw InputError(where(file, layout.lines.count(path) ? layout.lines.at(path) : 0u) + "'" + path + "' " + what);
      };
      const double                    sigma  = number(prm, file, layout, joint, "Profile uncertainty");
      const double                    search = number(prm, file, layout, joint, "Profile angle search");
      std::vector<ProfileMeasurement> out;
      for (const std::string surface : {"pin", "bore"})
        {
          const std::string entry = surface == "pin" ? "Pin profile file" : "Bore profile file";
          const std::string name  = trim(entry_value(prm, "Joint " + joint + "/" + entry));
          if (name.empty())
            continue;
          if (!(sigma > 0))
            fail("Profile uncertainty", "must be set > 0 [m, 1σ per point] with a profile file.");
          if (!std::isnan(search) && !(search >= 0 && search <= 180))
            fail("Profile angle search", "is " + format_number(search, 6) + "; it must lie in [0, 180] [deg].");
          const auto path = std::filesystem::path(name).is_absolute() ?
                              std::filesystem::path(name) :
                              std::filesystem::path(file).parent_path() / name;
          out.push_back({joint,
                         surface,
                         path.string(),
                         revolutions,
                         sigma,
                         std::isnan(search) ? 180. : search,
                         read_measured_profile_csv(path.string())});
        }
      if (out.empty() && !(std::isnan(sigma) && std::isnan(search)))
        fail(std::isnan(sigma) ? "Profile angle search" : "Profile uncertainty",
             "is given without a profile file ('Pin profile file' or 'Bore profile file').");
      return out;
    }
  } // namespace

  Measurements
  read_measurements(const std::string &file, const Scene &scene)
  {
    const Layout layout = pre_scan(file);
    check_joints(file, layout, scene);
    dealii::ParameterHandler prm;
    for (const auto &joint : wearing_joints(scene))
      {
        prm.enter_subsection("Joint " + joint);
        for (const char *e : entries)
          prm.declare_entry(e, "", dealii::Patterns::Anything());
        prm.leave_subsection();
      }
    read_prm_file(prm, file);
    Measurements m;
    m.file = file;
    for (std::size_t i = 0; i < layout.joints.size(); ++i)
      for (std::size_t j = 0; j < i; ++j)
        if (layout.joints[i].first == layout.joints[j].first)
          throw InputError(where(file, layout.joints[i].second) + "'Joint " + layout.joints[i].first +
                           "' appears a second time (first in line " + std::to_string(layout.joints[j].second) +
                           "); give each joint's measurements in one subsection.");
    for (const auto &[joint, line] : layout.joints)
      {
        const double revolutions = number(prm, file, layout, joint, "Revolutions");
        const auto   profiles    = joint_profiles(prm, file, layout, joint, revolutions);
        if (!profiles.empty() && std::none_of(scene.clearance_joints.begin(),
                                              scene.clearance_joints.end(),
                                              [&](const auto *j) { return j->name() == joint; }))
          throw InputError(where(file, line) + "'Joint " + joint + "' has a profile file, and joint " + joint +
                           " is cut into slices along its pin, whose worn surfaces differ with the axial position: "
                           "one trace is not the joint's. Give its measured mass losses (the whole surfaces') and "
                           "compare traces with `wearlink compare-profile --axial-position`.");
        for (auto &s : joint_measurements(prm, file, layout, joint, profiles, scene))
          m.surfaces.push_back(std::move(s));
        m.profiles.insert(m.profiles.end(), profiles.begin(), profiles.end());
      }
    if (m.surfaces.empty())
      throw InputError("In " + file + ": no measurement. Give, per wearing joint J of " + scene.file +
                       ", 'subsection Joint J' with 'Revolutions' and 'Pin mass loss' and/or 'Bushing mass loss' [mg] "
                       "with their uncertainties (`wearlink calibrate --help`).");
    return m;
  }
} // namespace wearlink::io
