// SPDX-License-Identifier: LGPL-2.1-or-later
#include "io/contact_case.h"

#include "base/exceptions.h"
#include "base/numbers.h"
#include "base/parameters.h"
#include "base/profile.h"
#include "base/text.h"
#include "fe/fe_settings.h"
#include "io/profile_file.h"
#include "io/scene.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace wearlink::io
{
  using numbers::pi;

  namespace
  {
    /** Geometry and materials of the pair. */
    void
    declare_pair(dealii::ParameterHandler &prm)
    {
      using namespace dealii::Patterns;
      prm.enter_subsection("Geometry");
      declare_required(
        prm,
        "Bore radius",
        Double(1e-6, 1),
        "Nominal bore radius R1 (used when no bore profile file is given, and for the Hertz comparison), 1 µm … 1 m.",
        "m");
      declare_required(prm,
                       "Pin radius",
                       Double(1e-6, 1),
                       "Nominal pin radius R2 (used when no pin profile file is given, and for the Hertz comparison), "
                       "1 µm … 1 m.",
                       "m");
      declare_required(prm,
                       "Bushing outer radius",
                       Double(1e-6, 10),
                       "Outer radius of the bushing ring; its outer edge is fixed. At most 10 m.",
                       "m");
      declare_required(prm,
                       "Axial length",
                       Double(1e-6, 1),
                       "Contact length along the pin axis; loads are spread over it (plane strain), 1 µm … 1 m.",
                       "m");
      declare(prm,
              "Number of profile points",
              "360",
              Integer(8, 100000),
              "Discrete areas N of each profile (samples at ψ_k = 2πk/N), 8 … 100000 (finer than any mesh "
              "of the surface can follow).",
              "none");
      declare(
        prm,
        "Bore profile file",
        "",
        Anything(),
        "CSV 'angle_rad, radius_m' of the worn bore in the bushing frame; empty: round bore of radius 'Bore radius'. Relative to the case file.",
        "none");
      declare(
        prm,
        "Pin profile file",
        "",
        Anything(),
        "CSV 'angle_rad, radius_m' of the worn pin in the pin frame; empty: round pin of radius 'Pin radius'. Relative to the case file.",
        "none");
      prm.leave_subsection();
      for (const char *body : {"Bushing material", "Pin material"})
        {
          prm.enter_subsection(body);
          declare_required(prm,
                           "Youngs modulus",
                           Double(1e6, 1e13),
                           "Young's modulus E, 1e6 … 1e13 Pa: from soft rubber to beyond diamond.",
                           "Pa");
          declare_required(prm, "Poisson ratio", Double(-1, 0.5), "Poisson's ratio ν.", "none");
          prm.leave_subsection();
        }
    }

    /**
     * The load states of subsection Loads (force or eccentricity control, one state per
     * magnitude along the load direction) for a bore of radius @p R1 and a pin of @p R2.
     */
    /**
     * Warn about an eccentricity @p e (load state @p k) that does not exceed the radial
     * clearance @p c: the pin then does not touch the bore and every force is 0.
     */
    void
    check_eccentricity_touches(const std::size_t k, const double e, const double c, ValidityWarnings &warnings)
    {
      const double same = 1e-12 * c; // the clearance is R1 − R2, rounded
      warnings.check(
        {"load state " + std::to_string(k) + " (eccentricity " + format_number(e, 6) + " m): radial clearance left",
         std::abs(c - e) <= same ? 0.0 : c - e,
         -same,
         "m",
         "the pin touches the bore only when its eccentricity exceeds the radial clearance " + format_number(c, 6) +
           " m",
         "the pin does not touch the bore: the contact force is 0. Under Control = displacement the "
         "load states are Loads/Eccentricities, the clearance plus the approach"});
    }

    std::vector<fe::LoadCase>
    read_load_states(ParameterReader       &reader,
                     const double           R1,
                     const double           R2,
                     bool                  &force_control,
                     std::array<double, 2> &direction,
                     ValidityWarnings      &warnings)
    {
      reader.enter("Loads");
      force_control     = reader.get("Control") == "force";
      direction         = reader.get_point("Load direction");
      const double norm = std::hypot(direction[0], direction[1]);
      if (!(norm > 0))
        reader.fail("Load direction", "it must be a non-zero vector");
      std::vector<fe::LoadCase> loads;
      for (const auto &v : reader.get_list(force_control ? "Load magnitudes" : "Eccentricities"))
        {
          fe::LoadCase lc;
          lc.control             = force_control ? fe::Control::force : fe::Control::displacement;
          lc.bushing_angle       = reader.get_double("Bushing angle") * pi / 180;
          lc.pin_angle           = reader.get_double("Pin angle") * pi / 180;
          const double magnitude = std::stod(v);
          if (!(magnitude > 0))
            reader.fail(force_control ? "Load magnitudes" : "Eccentricities", "every value must be > 0");
          // The FE model is small-strain linear elasticity: strains of order approach / R2
          // beyond a few per cent describe no real material (steel yields near 0.2 %).
          const double max_approach = 0.05 * R2;
          if (!force_control && magnitude - (R1 - R2) > max_approach)
            reader.fail("Eccentricities",
                        "the eccentricity " + format_number(magnitude, 4) + " m pushes the pin " +
                          format_number(magnitude - (R1 - R2), 4) + " m into the bore, beyond 5 % of the pin radius (" +
                          format_number(max_approach, 4) +
                          " m), where small-strain linear elasticity (the FE model) no "
                          "longer describes any material",
                        "Give eccentricities up to the radial clearance + 5 % of the pin radius (" +
                          format_number(R1 - R2 + max_approach, 4) + " m); realistic approaches are micrometres.");
          if (!force_control)
            check_eccentricity_touches(loads.size(), magnitude, R1 - R2, warnings);
          const std::array<double, 2> value = {{magnitude * direction[0] / norm, magnitude * direction[1] / norm}};
          (force_control ? lc.load : lc.eccentricity) = value;
          loads.push_back(lc);
        }
      reader.leave();
      return loads;
    }
  } // namespace

  void
  declare_contact_case(dealii::ParameterHandler &prm)
  {
    using namespace dealii::Patterns;
    declare_pair(prm);
    prm.enter_subsection("Loads");
    declare(
      prm,
      "Control",
      "force",
      Selection("force|displacement"),
      "force: the load magnitudes are given and the pin's displacement follows; displacement: the eccentricities are given and the contact force follows.",
      "none");
    declare(prm,
            "Load magnitudes",
            "100",
            List(Double(0, 1e9), 1),
            "Magnitudes of the force on the pin, one load state each (force control), at most 1e9 N.",
            "N");
    declare(
      prm,
      "Eccentricities",
      "0.5e-3",
      List(Double(0, 1), 1),
      "Pin-centre offsets from the bore centre along 'Load direction', one load state each (displacement control). "
      "Each may exceed the radial clearance by at most 5 % of the pin radius: the FE model is small-strain linear "
      "elasticity.",
      "m");
    declare(prm,
            "Load direction",
            "0, -1",
            point_pattern(),
            "Direction of the force on the pin (pushing it into the bore), or of the eccentricity; global frame.",
            "none");
    declare(prm, "Bushing angle", "0", Double(), "Angle θ of the body holding the bore.", "deg");
    declare(prm, "Pin angle", "0", Double(), "Angle θ of the body holding the pin.", "deg");
    prm.leave_subsection();
    prm.enter_subsection("FE model");
    fe::declare_fe_settings(prm);
    declare(
      prm,
      "Refined arc half-angle",
      "180",
      Double(0, 180),
      "Half-angle of the arc of each contact surface, centred on the load direction, that is meshed at 'Surface element size'; elsewhere the size grows with the distance from it. 180: the whole circumference.",
      "deg");
    declare(prm,
            "Solvers",
            "condensed, reference",
            MultipleSelection("condensed|reference"),
            "Which contact solvers to run (both: their pressures are compared).",
            "none");
    prm.leave_subsection();
    prm.enter_subsection("Output");
    declare(prm, "Write VTU", "true", Bool(), "Write fields_<k>.vtu (displacement, stress) per load state.", "none");
    prm.leave_subsection();
  }


  ContactCase
  read_contact_case(dealii::ParameterHandler &prm, const std::string &file)
  {
    ContactCase     c;
    ParameterReader reader(prm, file);
    const auto      base = std::filesystem::path(file).parent_path();
    c.file               = file;
    // Geometry and materials.
    auto &geometry = c.geometry;
    reader.enter("Geometry");
    const double R1           = reader.get_positive("Bore radius");
    const double R2           = reader.get_positive("Pin radius");
    const double outer_radius = reader.get_positive("Bushing outer radius");
    geometry.axial_length     = reader.get_positive("Axial length");
    const auto n_points       = static_cast<unsigned int>(reader.get_integer("Number of profile points"));
    auto       profile        = [&](const std::string &entry, double radius, const std::string &what) {
      const std::string f = reader.get(entry);
      if (f.empty())
        return Profile::round(radius, n_points);
      const auto path = std::filesystem::path(f).is_relative() ? base / f : std::filesystem::path(f);
      Profile    p    = io::read_profile_csv(path.string(), n_points);
      p.check(what + " profile '" + path.string() + "'");
      return p;
    };
    geometry.bore = profile("Bore profile file", R1, "bore");
    geometry.pin  = profile("Pin profile file", R2, "pin");
    io::check_profile_radius(reader, "Bore profile file", geometry.bore, R1, "Bore radius");
    io::check_profile_radius(reader, "Pin profile file", geometry.pin, R2, "Pin radius");
    if (!(R2 < R1))
      reader.fail("Pin radius",
                  "the pin must be smaller than the bore ('Bore radius' = " + format_number(R1, 4) + " m)",
                  "Set a pin radius below the bore radius (the radial clearance is their difference).");
    io::check_pin_inside_bore(reader, geometry.bore, geometry.pin);
    if (!(outer_radius > R1))
      reader.fail("Bushing outer radius", "it must exceed the bore radius (" + format_number(R1, 4) + " m)");
    reader.leave();
    for (auto [section, material] :
         {std::pair{"Bushing material", &geometry.bushing}, std::pair{"Pin material", &geometry.pin_material}})
      {
        reader.enter(section);
        material->youngs_modulus = reader.get_positive("Youngs modulus");
        material->poisson_ratio  = reader.get_double("Poisson ratio");
        reader.leave();
      }

    // Load states.
    bool                  force_control = true;
    std::array<double, 2> direction{};
    const auto            loads = read_load_states(reader, R1, R2, force_control, direction, c.warnings);

    reader.enter("FE model");
    fe::FeSettings settings         = fe::read_fe_settings(reader);
    settings.outer_radius           = outer_radius;
    settings.refined_arc_half_angle = reader.get_double("Refined arc half-angle") * pi / 180;
    if (settings.refined_arc_half_angle >= pi)
      settings.refined_arc_half_angle = 4; // whole circumference
    if (!loads.empty())
      {
        const double direction_angle     = std::atan2(direction[1], direction[0]);
        settings.refined_arc_bore_centre = direction_angle - loads[0].bushing_angle;
        settings.refined_arc_pin_centre  = direction_angle - loads[0].pin_angle;
      }
    const auto solvers = reader.get_list("Solvers");
    reader.leave();
    reader.enter("Output");
    const bool write_vtu = reader.get_bool("Write VTU");
    reader.leave();

    c.bore_radius   = R1;
    c.pin_radius    = R2;
    c.force_control = force_control;
    c.loads         = loads;
    c.settings      = settings;
    c.run_condensed = std::find(solvers.begin(), solvers.end(), "condensed") != solvers.end();
    c.run_reference = std::find(solvers.begin(), solvers.end(), "reference") != solvers.end();
    c.write_vtu     = write_vtu;
    return c;
  }
  namespace
  {
    /**
     * Parse @p file as a contact case into @p prm. A file that fails to parse but reads
     * as a mechanism scene was given to the wrong command: say so, instead of deal.II's
     * "No entry <Scene format>" at its first line.
     */
    void
    read_contact_case_file(dealii::ParameterHandler &prm, const std::string &file)
    {
      try
        {
          read_prm_file(prm, file);
        }
      catch (const InputError &)
        {
          bool scene = false;
          try
            {
              io::read_scene(file);
              scene = true;
            }
          catch (const Error &)
            {
              // not a scene either: the contact case's own message says what is wrong
            }
          if (scene)
            throw InputError("'" + file +
                             "' is a mechanism scene (for `wearlink run`), not a contact case. `wearlink contact` "
                             "reads one pin–bushing pair under given loads (subsections Geometry, Bushing material, "
                             "Pin material, Loads, FE model; see params/pin_bushing.prm). To compare the contact "
                             "laws of a scene's joints against the FE model, use `wearlink compare-contact " +
                             file + "`.");
          throw;
        }
    }

    /**
     * A --set of the load list that the chosen Loads/Control does not read (magnitudes
     * under displacement control, eccentricities under force control) is a mistake:
     * the run would use the file's other list and say nothing.
     */
    void
    refuse_unused_load_override(dealii::ParameterHandler &prm, const std::vector<std::string> &overrides)
    {
      prm.enter_subsection("Loads");
      const std::string control = prm.get("Control");
      prm.leave_subsection();
      const std::string unused = control == "force" ? "Eccentricities" : "Load magnitudes";
      const std::string used   = control == "force" ? "Load magnitudes" : "Eccentricities";
      for (const auto &o : overrides)
        if (trim(o.substr(0, o.find('='))) == "Loads/" + unused)
          throw InputError("--set \"" + o + "\" has no effect: under Loads/Control = " + control +
                           " the load states are Loads/" + used +
                           (control == "force" ? " (forces on the pin, N)" :
                                                 " (pin-centre offsets, m, each beyond the radial clearance)") +
                           ". Set Loads/" + used +
                           ", or Loads/Control = " + (control == "force" ? "displacement" : "force") + ".");
    }

  } // namespace

  ContactCase
  load_contact_case(dealii::ParameterHandler &prm, const std::string &file, const std::vector<std::string> &overrides)
  {
    read_contact_case_file(prm, file);
    apply_overrides(prm, ParameterOverrides(overrides));
    refuse_unused_load_override(prm, overrides);
    check_required_entries(prm, file);
    return read_contact_case(prm, file);
  }
} // namespace wearlink::io
