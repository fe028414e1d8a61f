// SPDX-License-Identifier: LGPL-2.1-or-later
// `wearlink contact CASE.prm`: the FE contact model of one shaft–bushing pair for a list
// of load states, solved with both the condensed (production) and the reference solver,
// with the Hertz line-contact numbers of REFERENCE.md §5 for comparison. Writes into
// the output directory: summary.json, pressure_<k>_<solver>.csv per load state,
// fields_<k>.vtu (displacement and stress for ParaView) and the gmsh mesh.
#include "app/command_line.h"
#include "base/atomic_file.h"
#include "base/effect_ledger.h"
#include "base/exceptions.h"
#include "base/json.h"
#include "base/parameters.h"
#include "base/profile.h"
#include "base/text.h"
#include "fe/fe_settings.h"
#include "fe/pin_bushing_model.h"

#include <deal.II/base/mpi.h>

#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace wearlink::app
{
  namespace
  {
    constexpr double pi = 3.14159265358979323846;

    const char *help_text =
      R"(wearlink contact CASE.prm [--output DIR] [--set "Section/Entry=value" ...]
wearlink contact --print-parameters

Solves the 2D plane-strain frictionless contact of one pin in its bushing (gmsh mesh of
the actual, possibly worn, profiles; deal.II elasticity) for every load state of the
case, with the condensed production solver and the uncondensed reference solver (see
'FE model/Solvers'), and compares with Hertz line contact (REFERENCE.md §5).
Example: params/pin_bushing.prm. Writes into DIR (default: output/<case name>):
  summary.json               per solver: setup time, mean time per load state, and per
                             load state load_N, half_angle_deg, half_width_m,
                             peak_pressure_Pa, pin_displacement_m,
                             equilibrium_relative_residual; n_dofs,
                             n_contact_candidates; Hertz numbers; the effect ledger
  pressure_<k>_<solver>.csv  nodal pressure per pin contact candidate: pin-frame angle,
                             bushing-frame angle of its contact point, pressure (Pa)
  fields_<k>.vtu             displacement and stress of both bodies (ParaView)
  pin_bushing.msh            the gmsh mesh
  parameters.prm             the effective case (with --set overrides applied)

Options:
  --output DIR        output directory
  --set S/E=V         override an entry, e.g. --set "FE model/Surface element size=2e-5"
  --print-parameters  print every entry with its unit, default and meaning

MPI: `mpirun -np N wearlink contact CASE.prm` distributes the reference solver over N
ranks (METIS partitions of the mesh, a PETSc matrix factored by MUMPS); the condensed
solver runs on every rank (it is small and serial) and rank 0 writes all outputs. The
answer is the serial one.

Exit status: 0 success, 2 bad input, 3 numerical failure.
)";

    void
    declare_case(dealii::ParameterHandler &prm)
    {
      using namespace dealii::Patterns;
      prm.enter_subsection("Geometry");
      declare_required(
        prm,
        "Bore radius",
        Double(0),
        "Nominal bore radius R1 (used when no bore profile file is given, and for the Hertz comparison).",
        "m");
      declare_required(prm,
                       "Pin radius",
                       Double(0),
                       "Nominal pin radius R2 (used when no pin profile file is given, and for the Hertz comparison).",
                       "m");
      declare_required(prm,
                       "Bushing outer radius",
                       Double(0),
                       "Outer radius of the bushing ring; its outer edge is fixed.",
                       "m");
      declare_required(prm,
                       "Axial length",
                       Double(0),
                       "Contact length along the pin axis; loads are spread over it (plane strain).",
                       "m");
      declare(prm,
              "Number of profile points",
              "360",
              Integer(8),
              "Discrete areas N of each profile (samples at ψ_k = 2πk/N).",
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
          declare_required(prm, "Youngs modulus", Double(0), "Young's modulus E.", "Pa");
          declare_required(prm, "Poisson ratio", Double(-1, 0.5), "Poisson's ratio ν.", "none");
          prm.leave_subsection();
        }
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
              List(Double(0), 1),
              "Magnitudes of the force on the pin, one load state each (force control).",
              "N");
      declare(
        prm,
        "Eccentricities",
        "0.5e-3",
        List(Double(0), 1),
        "Pin-centre offsets from the bore centre along 'Load direction', one load state each (displacement control).",
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

    Json
    vec(const std::array<double, 2> &v)
    {
      Json a = Json::array();
      a.push_back(v[0]);
      a.push_back(v[1]);
      return a;
    }

    void
    write_pressure_csv(const std::string &path, const fe::ContactResult &r)
    {
      AtomicFile f(path);
      auto      &os = f.stream();
      os << "# nodal contact pressure per pin contact candidate\n"
         << "pin_angle_deg_pin_frame,bore_angle_deg_bushing_frame,pressure_Pa\n"
         << std::setprecision(12);
      for (std::size_t i = 0; i < r.pressure.size(); ++i)
        os << r.pin_angle[i] * 180 / pi << ',' << r.bore_angle[i] * 180 / pi << ',' << r.pressure[i] << '\n';
      f.commit();
    }

    int
    run(const std::vector<std::string> &args)
    {
      // MPI (and PETSc) for the distributed reference solver; a plain run is one rank.
      int                                      mpi_argc   = 1;
      char                                     program[]  = "wearlink";
      char                                    *mpi_argv[] = {program, nullptr};
      char                                   **argv_ptr   = mpi_argv;
      dealii::Utilities::MPI::MPI_InitFinalize mpi(mpi_argc, argv_ptr, 1);
      const unsigned int                       n_ranks = dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
      const bool                               root    = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
      std::ostream                             muted(nullptr);
      std::ostream                            &log = root ? std::cout : muted;

      const auto a =
        parse_arguments(args, {{"--output", true}, {"--set", true, true}, {"--print-parameters", false}}, "contact");
      dealii::ParameterHandler prm;
      declare_case(prm);
      if (a.has("--print-parameters"))
        {
          if (root)
            prm.print_parameters(std::cout, dealii::ParameterHandler::Text);
          return 0;
        }
      if (a.positional.size() != 1)
        throw InputError("`wearlink contact` needs exactly one case file (given " +
                         std::to_string(a.positional.size()) + "). See `wearlink contact --help`.");
      const std::string file = a.positional[0];
      read_prm_file(prm, file);
      apply_overrides(prm, a.all("--set"));
      check_required_entries(prm, file);
      ParameterReader reader(prm, file);
      const auto      base = std::filesystem::path(file).parent_path();

      // Geometry and materials.
      contact::JointGeometry geometry;
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
        Profile    p    = Profile::read_csv(path.string(), n_points);
        p.check(what + " profile '" + path.string() + "'");
        return p;
      };
      geometry.bore = profile("Bore profile file", R1, "bore");
      geometry.pin  = profile("Pin profile file", R2, "pin");
      if (!(R2 < R1))
        reader.fail("Pin radius",
                    "the pin must be smaller than the bore ('Bore radius' = " + format_number(R1, 4) + " m)",
                    "Set a pin radius below the bore radius (the radial clearance is their difference).");
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
      reader.enter("Loads");
      const bool   force_control = reader.get("Control") == "force";
      const auto   direction     = reader.get_point("Load direction");
      const double norm          = std::hypot(direction[0], direction[1]);
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
          const std::array<double, 2> value = {magnitude * direction[0] / norm, magnitude * direction[1] / norm};
          (force_control ? lc.load : lc.eccentricity) = value;
          loads.push_back(lc);
        }
      reader.leave();

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
      const bool run_condensed = std::find(solvers.begin(), solvers.end(), "condensed") != solvers.end();
      const bool run_reference = std::find(solvers.begin(), solvers.end(), "reference") != solvers.end();

      const std::string out = a.value("--output", "output/" + std::filesystem::path(file).stem().string());
      if (root)
        make_output_directory(out);
      settings.distribute_reference = n_ranks > 1;
      if (n_ranks > 1)
        log << "Reference solver distributed over " << n_ranks << " MPI ranks (METIS partitions, MUMPS).\n";

      // Set-up (mesh + assembly, then the condensed factorization).
      log << "Meshing and assembling the pin–bushing pair (surface element size " << settings.surface_element_size * 1e3
          << " mm)...\n";
      fe::PinBushingModel model(geometry, settings, out + "/pin_bushing.msh");
      {
        std::ostringstream os;
        prm.print_parameters(os, dealii::ParameterHandler::ShortText);
        if (root)
          write_file_atomically(out + "/parameters.prm", os.str());
      }
      const auto &st = model.statistics();
      log << "  " << st.mesh.n_quadrilaterals << " quadrilaterals, " << st.n_dofs << " DoFs, " << st.n_pin_candidates
          << " pin + " << st.n_bore_candidates << " bore contact candidates; mesh " << format_number(st.mesh_time, 3)
          << " s, assembly " << format_number(st.assembly_time, 3) << " s\n";

      // Hertz line contact (REFERENCE.md §5): internal contact R* = R1 R2/(R1 − R2).
      const double E_star = contact::effective_modulus(geometry.bushing, geometry.pin_material);
      const double R_star = R1 * R2 / (R1 - R2);

      Json summary                         = Json::object();
      summary["case"]                      = file;
      summary["control"]                   = force_control ? "force" : "displacement";
      summary["n_dofs"]                    = st.n_dofs;
      summary["n_contact_candidates"]      = st.n_pin_candidates + st.n_bore_candidates;
      summary["n_pin_contact_candidates"]  = st.n_pin_candidates;
      summary["n_bore_contact_candidates"] = st.n_bore_candidates;
      summary["n_quadrilaterals"]          = st.mesh.n_quadrilaterals;
      summary["surface_element_size_m"]    = settings.surface_element_size;
      summary["element_degree"]            = settings.degree;
      summary["effective_modulus_Pa"]      = E_star;
      summary["relative_radius_m"]         = R_star;
      summary["mesh_time_s"]               = st.mesh_time;
      summary["assembly_time_s"]           = st.assembly_time;

      std::vector<fe::ContactResult> condensed, reference;
      Json                           solvers_json = Json::object();
      if (run_condensed)
        {
          model.prepare_condensed();
          // Pass 1 computes the compliance columns the load states need (part of the
          // set-up: the influence matrix of the touched candidates); pass 2 is the
          // per-load-state cost the wear loop pays.
          std::vector<double> first(loads.size());
          for (std::size_t k = 0; k < loads.size(); ++k)
            first[k] = model.solve(loads[k], fe::SolverKind::condensed).solve_time;
          for (const auto &lc : loads)
            condensed.push_back(model.solve(lc, fe::SolverKind::condensed));
          double mean = 0, mean_first = 0;
          for (std::size_t k = 0; k < loads.size(); ++k)
            {
              mean += condensed[k].solve_time / loads.size();
              mean_first += first[k] / loads.size();
            }
          Json s                    = Json::object();
          s["setup_time_s"]         = st.mesh_time + st.assembly_time + st.factorization_time + model.compliance_time();
          s["factorization_time_s"] = st.factorization_time;
          s["influence_columns_time_s"] = model.compliance_time();
          s["n_influence_columns"]      = model.n_compliance_solves();
          s["mean_solve_time_s"]        = mean;
          s["mean_first_solve_time_s"]  = mean_first;
          solvers_json["condensed"]     = s;
        }
      if (run_reference)
        {
          double mean = 0;
          for (const auto &lc : loads)
            {
              reference.push_back(model.solve(lc, fe::SolverKind::reference));
              mean += reference.back().solve_time / loads.size();
            }
          Json s                    = Json::object();
          s["setup_time_s"]         = st.mesh_time + st.assembly_time;
          s["mean_solve_time_s"]    = mean;
          solvers_json["reference"] = s;
        }

      auto case_json = [&](const fe::ContactResult &r, const fe::LoadCase &lc) {
        Json         c                     = Json::object();
        const double F                     = std::hypot(r.resultant[0], r.resultant[1]);
        c["load_N"]                        = force_control ? std::hypot(lc.load[0], lc.load[1]) : F;
        c["resultant_N"]                   = vec(r.resultant);
        c["half_angle_deg"]                = r.half_angle * 180 / pi;
        c["half_width_m"]                  = r.half_width;
        c["peak_pressure_Pa"]              = r.peak_pressure;
        c["pin_displacement_m"]            = vec(r.pin_displacement);
        c["equilibrium_relative_residual"] = r.equilibrium_relative_residual;
        c["n_active_candidates"]           = r.n_active;
        c["active_set_iterations"]         = r.iterations;
        c["solve_time_s"]                  = r.solve_time;
        return c;
      };
      for (auto [name, results] : {std::pair{"condensed", &condensed}, std::pair{"reference", &reference}})
        if (!results->empty())
          {
            Json cases = Json::array();
            for (std::size_t k = 0; k < results->size(); ++k)
              {
                cases.push_back(case_json((*results)[k], loads[k]));
                if (root)
                  write_pressure_csv(out + "/pressure_" + std::to_string(k) + "_" + name + ".csv", (*results)[k]);
              }
            solvers_json[name]["load_cases"] = cases;
          }
      summary["solvers"] = solvers_json;

      // Hertz numbers and the comparison table.
      Json hertz = Json::array();
      log << "\n  load [N]   solver     half-angle [deg]  half-width [mm]  peak p [MPa]  "
             "equilibrium res.  time [ms]\n";
      double max_difference = 0;
      for (std::size_t k = 0; k < loads.size(); ++k)
        {
          const auto  &primary  = !condensed.empty() ? condensed[k] : reference[k];
          const double F        = force_control ? std::hypot(loads[k].load[0], loads[k].load[1]) :
                                                  std::hypot(primary.resultant[0], primary.resultant[1]);
          const double P        = F / geometry.axial_length;
          const double b        = std::sqrt(4 * P * R_star / (pi * E_star));
          const double p0       = 2 * P / (pi * b);
          Json         h        = Json::object();
          h["load_N"]           = F;
          h["half_width_m"]     = b;
          h["half_angle_deg"]   = b / R2 * 180 / pi;
          h["peak_pressure_Pa"] = p0;
          hertz.push_back(h);
          log << "  " << std::setw(9) << format_number(F, 6) << "  Hertz      " << std::setw(16)
              << format_number(b / R2 * 180 / pi, 4) << "  " << std::setw(15) << format_number(b * 1e3, 4) << "  "
              << std::setw(12) << format_number(p0 / 1e6, 4) << '\n';
          for (auto [name, results] : {std::pair{"condensed", &condensed}, std::pair{"reference", &reference}})
            if (!results->empty())
              {
                const auto &r = (*results)[k];
                log << "  " << std::setw(9) << ""
                    << "  " << std::setw(9) << std::left << name << std::right << "  " << std::setw(16)
                    << format_number(r.half_angle * 180 / pi, 4) << "  " << std::setw(15)
                    << format_number(r.half_width * 1e3, 4) << "  " << std::setw(12)
                    << format_number(r.peak_pressure / 1e6, 4) << "  " << std::setw(16)
                    << format_number(r.equilibrium_relative_residual, 2) << "  " << std::setw(9)
                    << format_number(r.solve_time * 1e3, 3) << '\n';
              }
          if (!condensed.empty() && !reference.empty())
            {
              double diff = 0;
              for (std::size_t i = 0; i < condensed[k].pressure.size(); ++i)
                diff = std::max(diff, std::abs(condensed[k].pressure[i] - reference[k].pressure[i]));
              max_difference = std::max(max_difference, diff / reference[k].peak_pressure);
            }
        }
      summary["hertz"] = hertz;
      if (!condensed.empty() && !reference.empty())
        {
          summary["condensed_vs_reference_max_relative_pressure_difference"] = max_difference;
          const double ratio = json_number(solvers_json["reference"]["mean_solve_time_s"]) /
                               json_number(solvers_json["condensed"]["mean_solve_time_s"]);
          summary["reference_to_condensed_time_ratio"] = ratio;
          log << "\n  condensed vs reference: max |Δp| / p_peak = " << format_number(max_difference, 3)
              << "; time per load state "
              << format_number(json_number(solvers_json["condensed"]["mean_solve_time_s"]) * 1e3, 3) << " ms vs "
              << format_number(json_number(solvers_json["reference"]["mean_solve_time_s"]) * 1e3, 4) << " ms (ratio "
              << format_number(ratio, 4) << ")\n";
        }

      if (write_vtu)
        for (std::size_t k = 0; k < loads.size(); ++k)
          model.solve(loads[k],
                      run_condensed ? fe::SolverKind::condensed : fe::SolverKind::reference,
                      root ? out + "/fields_" + std::to_string(k) + ".vtu" : std::string());

      Json ledger = Json::object();
      for (const auto &[category, entries] : EffectLedger::instance().snapshot())
        {
          Json c = Json::object();
          for (const auto &[key, count] : entries)
            c[key] = count;
          ledger[category] = c;
        }
      summary["ledger"]    = ledger;
      summary["mpi_ranks"] = n_ranks;
      if (root)
        write_file_atomically(out + "/summary.json", summary.dump(2) + "\n");
      log << "\nWrote " << out << "/summary.json\n";
      return 0;
    }
  } // namespace

  extern const Command contact_command;
  const Command contact_command = {"contact", "contact CASE.prm [--output DIR] [--set S/E=V ...]", help_text, run};
} // namespace wearlink::app
