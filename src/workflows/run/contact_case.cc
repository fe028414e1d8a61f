// SPDX-License-Identifier: LGPL-2.1-or-later
#include "workflows/run/contact_case.h"

#include "base/atomic_file.h"
#include "base/effect_ledger.h"
#include "base/numbers.h"
#include "base/text.h"
#include "base/validity_warnings.h"
#include "contact/hertz.h"
#include "io/output_names.h"

#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace wearlink::workflows
{
  namespace
  {
    using numbers::pi;

    Json
    vec(const std::array<double, 2> &v)
    {
      Json a = Json::array();
      a.push_back(v[0]);
      a.push_back(v[1]);
      return a;
    }

    /** pressure_<k>_<solver>.csv: the nodal pressure per pin contact candidate. */
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

    /** The results of one solver over all load states, and its timing summary. */
    struct SolverRun
    {
      std::vector<fe::ContactResult> results;
      Json                           json = Json::object();
    };

    /**
     * The condensed solver: pass 1 computes the compliance columns the load states need
     * (part of the set-up: the influence matrix of the touched candidates); pass 2 is the
     * per-load-state cost the wear loop pays.
     */
    SolverRun
    solve_condensed(fe::PinBushingModel &model, const std::vector<fe::LoadCase> &loads)
    {
      const auto &st = model.statistics();
      SolverRun   out;
      model.prepare_condensed();
      std::vector<double> first(loads.size());
      for (std::size_t k = 0; k < loads.size(); ++k)
        first[k] = model.solve(loads[k], fe::SolverKind::condensed).solve_time;
      double mean = 0, mean_first = 0;
      for (std::size_t k = 0; k < loads.size(); ++k)
        {
          const double timed = model.solve(loads[k], fe::SolverKind::condensed).solve_time;
          // The result written out has every candidate's bore angle (not timed).
          out.results.push_back(model.solve(loads[k], fe::SolverKind::condensed, "", true));
          out.results.back().solve_time = timed;
          mean += timed / loads.size();
          mean_first += first[k] / loads.size();
        }
      auto &s                       = out.json;
      s["setup_time_s"]             = st.mesh_time + st.assembly_time + st.factorization_time + model.compliance_time();
      s["factorization_time_s"]     = st.factorization_time;
      s["influence_columns_time_s"] = model.compliance_time();
      s["n_influence_columns"]      = model.n_compliance_solves();
      s["mean_solve_time_s"]        = mean;
      s["mean_first_solve_time_s"]  = mean_first;
      return out;
    }

    /** The uncondensed reference solver on every load state. */
    SolverRun
    solve_reference(fe::PinBushingModel &model, const std::vector<fe::LoadCase> &loads)
    {
      const auto &st = model.statistics();
      SolverRun   out;
      double      mean = 0;
      for (const auto &lc : loads)
        {
          out.results.push_back(model.solve(lc, fe::SolverKind::reference));
          mean += out.results.back().solve_time / loads.size();
        }
      out.json["setup_time_s"]      = st.mesh_time + st.assembly_time;
      out.json["mean_solve_time_s"] = mean;
      return out;
    }

    /** One load state's result in summary.json. */
    Json
    case_json(const fe::ContactResult &r, const fe::LoadCase &lc, const bool force_control)
    {
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
    }

    /** The case's set-up figures in summary.json. */
    Json
    setup_summary(const io::ContactCase &c, const fe::PinBushingModel &model, const double E_star, const double R_star)
    {
      const auto &st                       = model.statistics();
      Json        summary                  = Json::object();
      summary["case"]                      = c.file;
      summary["control"]                   = c.force_control ? "force" : "displacement";
      summary["n_dofs"]                    = st.n_dofs;
      summary["n_contact_candidates"]      = st.n_pin_candidates + st.n_bore_candidates;
      summary["n_pin_contact_candidates"]  = st.n_pin_candidates;
      summary["n_bore_contact_candidates"] = st.n_bore_candidates;
      summary["n_quadrilaterals"]          = st.mesh.n_quadrilaterals;
      summary["surface_element_size_m"]    = c.settings.surface_element_size;
      summary["element_degree"]            = c.settings.degree;
      summary["effective_modulus_Pa"]      = E_star;
      summary["relative_radius_m"]         = R_star;
      summary["mesh_time_s"]               = st.mesh_time;
      summary["assembly_time_s"]           = st.assembly_time;
      return summary;
    }

    /** Print one solver's row of the comparison table. */
    void
    print_row(std::ostream &log, const std::string &name, const fe::ContactResult &r)
    {
      log << "  " << std::setw(9) << ""
          << "  " << std::setw(9) << std::left << name << std::right << "  " << std::setw(16)
          << format_number(r.half_angle * 180 / pi, 4) << "  " << std::setw(15) << format_number(r.half_width * 1e3, 4)
          << "  " << std::setw(12) << format_number(r.peak_pressure / 1e6, 4) << "  " << std::setw(16)
          << format_number(r.equilibrium_relative_residual, 2) << "  " << std::setw(9)
          << format_number(r.solve_time * 1e3, 3) << '\n';
    }

    /**
     * Hertz numbers per load state (doc/models.md §5.1; internal contact R* = R1 R2/(R1 −
     * R2)), the printed table of every solver against them, and the largest
     * condensed-vs-reference pressure difference relative to the peak (0 if only one
     * solver ran).
     */
    Json
    hertz_comparison(const io::ContactCase &c,
                     const SolverRun       &condensed,
                     const SolverRun       &reference,
                     const double           E_star,
                     const double           R_star,
                     std::ostream          &log,
                     double                &max_difference)
    {
      Json hertz = Json::array();
      log << "\n  load [N]   solver     half-angle [deg]  half-width [mm]  peak p [MPa]  "
             "equilibrium res.  time [ms]\n";
      max_difference = 0;
      for (std::size_t k = 0; k < c.loads.size(); ++k)
        {
          const auto  &primary = !condensed.results.empty() ? condensed.results[k] : reference.results[k];
          const double F       = c.force_control ? std::hypot(c.loads[k].load[0], c.loads[k].load[1]) :
                                                   std::hypot(primary.resultant[0], primary.resultant[1]);
          const auto   h       = contact::hertz_line_contact(F / c.geometry.axial_length, R_star, E_star);
          const double b = h.half_width, p0 = h.peak_pressure;
          Json         row        = Json::object();
          row["load_N"]           = F;
          row["half_width_m"]     = b;
          row["half_angle_deg"]   = b / c.pin_radius * 180 / pi;
          row["peak_pressure_Pa"] = p0;
          hertz.push_back(row);
          log << "  " << std::setw(9) << format_number(F, 6) << "  Hertz      " << std::setw(16)
              << format_number(b / c.pin_radius * 180 / pi, 4) << "  " << std::setw(15) << format_number(b * 1e3, 4)
              << "  " << std::setw(12) << format_number(p0 / 1e6, 4) << '\n';
          if (!condensed.results.empty())
            print_row(log, "condensed", condensed.results[k]);
          if (!reference.results.empty())
            print_row(log, "reference", reference.results[k]);
          if (!condensed.results.empty() && !reference.results.empty())
            {
              double diff = 0;
              for (std::size_t i = 0; i < condensed.results[k].pressure.size(); ++i)
                diff = std::max(diff, std::abs(condensed.results[k].pressure[i] - reference.results[k].pressure[i]));
              max_difference = std::max(max_difference, diff / reference.results[k].peak_pressure);
            }
        }
      return hertz;
    }

    /**
     * Hertz's line contact assumes a contact narrow against the radii: a half-angle past
     * 90° (a contact wider than half the pin) is far outside it, and so is the comparison.
     */
    ValidityWarnings
    contact_case_warnings(const Json &hertz)
    {
      ValidityWarnings w;
      for (const auto &row : hertz)
        w.check({"Hertz contact half-angle at " + format_number(json_number(row.at("load_N")), 4) + " N",
                 json_number(row.at("half_angle_deg")),
                 90,
                 "deg",
                 "a contact wider than half the pin",
                 "Hertz's theory assumes a contact narrow against the radii, so its row of the comparison does "
                 "not apply (the FE solution does not rest on that assumption)"});
      return w;
    }

    /** The effect ledger as JSON. */
    Json
    ledger_json()
    {
      Json ledger = Json::object();
      for (const auto &[category, entries] : EffectLedger::instance().snapshot())
        {
          Json c = Json::object();
          for (const auto &[key, count] : entries)
            c[key] = count;
          ledger[category] = c;
        }
      return ledger;
    }
  } // namespace

  Json
  run_contact_case(const io::ContactCase &c, const dealii::ParameterHandler &prm, const ContactCaseRun &run)
  {
    std::ostream       muted(nullptr);
    std::ostream      &log = run.log ? *run.log : muted;
    const std::string &out = run.output_directory;
    if (run.root)
      make_output_directory(out);
    fe::FeSettings settings       = c.settings;
    settings.distribute_reference = run.n_ranks > 1;
    if (run.n_ranks > 1)
      log << "Reference solver distributed over " << run.n_ranks << " MPI ranks (METIS partitions, MUMPS).\n";

    // Set-up (mesh + assembly, then the condensed factorization).
    log << "Meshing and assembling the pin–bushing pair (surface element size " << settings.surface_element_size * 1e3
        << " mm)...\n";
    fe::PinBushingModel model(c.geometry, settings, out + "/" + io::outputs::contact_mesh);
    std::ostringstream  effective;
    prm.print_parameters(effective, dealii::ParameterHandler::ShortText);
    if (run.root)
      write_file_atomically(out + "/" + io::outputs::parameters, effective.str());
    const auto &st = model.statistics();
    log << "  " << st.mesh.n_quadrilaterals << " quadrilaterals, " << st.n_dofs << " DoFs, " << st.n_pin_candidates
        << " pin + " << st.n_bore_candidates << " bore contact candidates; mesh " << format_number(st.mesh_time, 3)
        << " s, assembly " << format_number(st.assembly_time, 3) << " s\n";

    const double E_star  = contact::effective_modulus(c.geometry.bushing, c.geometry.pin_material);
    const double R_star  = c.bore_radius * c.pin_radius / (c.bore_radius - c.pin_radius);
    Json         summary = setup_summary(c, model, E_star, R_star);

    const SolverRun condensed = c.run_condensed ? solve_condensed(model, c.loads) : SolverRun();
    const SolverRun reference = c.run_reference ? solve_reference(model, c.loads) : SolverRun();
    Json            solvers   = Json::object();
    for (const auto &[name, s] : {std::pair{"condensed", &condensed}, std::pair{"reference", &reference}})
      if (!s->results.empty())
        {
          solvers[name] = s->json;
          Json cases    = Json::array();
          for (std::size_t k = 0; k < s->results.size(); ++k)
            {
              cases.push_back(case_json(s->results[k], c.loads[k], c.force_control));
              if (run.root)
                write_pressure_csv(out + "/pressure_" + std::to_string(k) + "_" + name + ".csv", s->results[k]);
            }
          solvers[name]["load_cases"] = cases;
        }
    summary["solvers"] = solvers;

    double max_difference = 0;
    summary["hertz"]      = hertz_comparison(c, condensed, reference, E_star, R_star, log, max_difference);
    if (!condensed.results.empty() && !reference.results.empty())
      {
        summary["condensed_vs_reference_max_relative_pressure_difference"] = max_difference;
        const double t_condensed                     = json_number(solvers["condensed"]["mean_solve_time_s"]);
        const double t_reference                     = json_number(solvers["reference"]["mean_solve_time_s"]);
        const double ratio                           = t_reference / t_condensed;
        summary["reference_to_condensed_time_ratio"] = ratio;
        log << "\n  condensed vs reference: max |Δp| / p_peak = " << format_number(max_difference, 3)
            << "; time per load state " << format_number(t_condensed * 1e3, 3) << " ms vs "
            << format_number(t_reference * 1e3, 4) << " ms (ratio " << format_number(ratio, 4) << ")\n";
      }

    if (c.write_vtu)
      for (std::size_t k = 0; k < c.loads.size(); ++k)
        model.solve(c.loads[k],
                    c.run_condensed ? fe::SolverKind::condensed : fe::SolverKind::reference,
                    run.root ? out + "/fields_" + std::to_string(k) + ".vtu" : std::string());

    summary["ledger"]         = ledger_json();
    summary["mpi_ranks"]      = run.n_ranks;
    ValidityWarnings warnings = c.warnings; // the implausible load states first
    warnings.merge(contact_case_warnings(summary["hertz"]));
    summary["warnings"] = warnings.json();
    if (run.root)
      {
        write_file_atomically(out + "/" + io::outputs::summary, summary.dump(2) + "\n");
        warnings.print(std::cerr);
      }
    log << "\nWrote " << out << "/summary.json\n";
    return summary;
  }
} // namespace wearlink::workflows
