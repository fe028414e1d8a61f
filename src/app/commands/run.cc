// SPDX-License-Identifier: LGPL-2.1-or-later
// `wearlink run SCENE.prm`: read and validate a scene, assemble it, integrate it and
// write summary.json, time_series.csv and parameters.prm into the output directory.
// `--validate` stops after reading, building and assembling (no output is written);
// `--print-parameters` prints every entry a scene can have. The output directory is held
// for the run (base/output_directory.h): locked, and refused if it holds an earlier
// run's files unless --overwrite (replace them) or --resume (continue that wear run).
#include "workflows/run/run.h"

#include "app/command_line.h"
#include "app/ensemble_command.h"
#include "app/output_claim.h"
#include "base/exceptions.h"
#include "base/output_directory.h"
#include "io/output_names.h"
#include "io/scene.h"
#include "workflows/ensemble/ensemble.h"
#include "workflows/run/first_look.h"
#include "workflows/wear/wear_run.h"

#include <filesystem>
#include <iostream>
#include <memory>

namespace wearlink::app
{


  namespace
  {
    const std::string run_help =
      std::string(R"(wearlink run SCENE.prm [--output DIR] [--overwrite] [--set "Section/Entry=value" ...] [--quiet]
wearlink run SCENE.prm --resume DIR [--set ...] [--quiet]
wearlink run SCENE.prm --ensemble N [--seed S] [--perturbation RAD] [--sensitivity saltelli] [--output DIR] [...]
wearlink run --validate SCENE.prm [--set ...]
wearlink run --print-parameters [SCENE.prm]

Runs the multibody simulation of a scene (a deal.II .prm file; see params/ for
examples) and writes into DIR (default: output/<scene name>):
  summary.json      run statistics: steps, constraint violation, energy balance,
                    per-body extremes of position, velocity and acceleration,
                    per-clearance-joint forces, penetration, contact fraction, impacts,
                    and the effect ledger (what was constructed and called)
  time_series.csv   sampled every 'Output/Time series interval' seconds
  parameters.prm    the effective scene (with --set overrides applied)
  orbit_<J>.png     the journal-centre orbit of clearance joint J (eccentricity in
                    the bushing frame) inside its clearance circle
  contact_forces.png  normal and friction force of each clearance joint vs time
  accelerations.png the acceleration of the 'Output/Plot bodies' (default: the
                    sliders, else the body with the largest peak acceleration)
                    (the PNGs unless 'Output/Plots = false'; drawn from
                    time_series.csv by gnuplot: without either, a note, no failure)
and prints a short summary (contact fraction, peak forces and impacts per clearance
joint, peak acceleration per plot body; the numbers of summary.json) and the files
written.
For the analyses listed in 'Analyses/List of analyses' (phase-portrait, poincare,
lyapunov; see --print-parameters): analysis_series.csv and phase_portrait_*.png,
poincare_section.csv and poincare_*.png, lyapunov_<channel>_<method>.csv/.png, with
their results (Poincaré spread, exponents in 1/s, natural log) in summary.json
Every file is written under a temporary name and renamed when complete.

A scene in which some clearance joint has 'Wear law = archard' runs the wear loop
instead (section Wear; one progress line per iteration) and writes, besides
summary.json (with per-joint wear volumes, depths, mass loss and revolutions) and
parameters.prm: checkpoint.json, wear_history.csv, wear_depth_<J>.csv/.png,
profiles_<J>.csv/.msh, profile_<J>_bore.png, profile_<J>_pin.png, wear_volume.png,
response_before.csv, response_after.csv, response.png, and the worn profiles of every
iteration as a ParaView series, profiles_<J>.pvd with profiles/profile_<J>_<k>.vtu
(depth, radius, the pressure at the iteration's largest load; "Warp By Vector" on
wear_displacement_m magnifies the wear); joints on the fe pressure model also fe/
(meshes, and the FE fields at each iteration's largest load with fields_<J>.pvd).
If a wear scene lists analyses, they do not run during the wear iterations; instead
the dynamics is run from Start to End time once with the fresh and once with the worn
profiles (dynamics_before/, dynamics_after/) and compared (before_after.md, printed;
before_after_phase_*.png, before_after_lyapunov.csv, before_after_delay_scan.*; see
'Analyses/Before-after wear' and `wearlink compare-dynamics --help`).
  --resume DIR        continue the wear run whose output directory is DIR from its
                      last finished iteration (same scene; Wear/Number of iterations
                      and Wear/Target revolutions may be raised with --set, Output/*,
                      Wear/FE output and Wear/Profile magnification changed; a
                      checkpoint of another scene, of another format version, truncated
                      or damaged (checksum) is refused with what differs). The summary's
                      effect ledger and wear_timing_s cover the whole run.

The output directory (the default one too) is locked while the run lasts: a second run
into it is refused with the first one's pid. A directory that holds the files of an
earlier run (summary.json, checkpoint.json, time_series.csv, ...) is refused unless
  --overwrite         the earlier run's files are removed first (only the names a run
                      writes, listed above, and its sub-folders; other files are kept)
or --resume continues it. Temporary files (".NAME.partial-PID") of a run that was
killed are removed at the next start. SIGINT/SIGTERM/SIGHUP stop a run: its temporary files
are removed, finished files and the last checkpoint are kept (exit status 128 + signal;
a second signal stops at once).

Ensembles (mpirun -np R wearlink run SCENE --ensemble N: members over R MPI ranks;
default folder output/<scene name>_ensemble; --resume DIR reads finished members back
and resumes the others):
)") + workflows::ensemble_help() +
      R"(
Options:
  --output DIR        output directory
  --set S/E=V         override entry E of subsection S (repeatable), e.g.
                      --set "Joint A/Clearance/Radial clearance=2e-4"
  --validate          check the scene (parse, cross-checks, assembly) and stop
  --print-parameters  print every scene entry with its unit, default and meaning
  --quiet             no progress lines

Exit status: 0 success, 2 bad input (also: directory in use, earlier run's files),
3 numerical failure, 4 an output that cannot be written (disk full, I/O error) or
memory that ran out, 130 / 143 / 129 stopped by SIGINT / SIGTERM / SIGHUP, 1 an internal error
(see `wearlink --help`).
)" + io::outputs::listing(io::outputs::run());

    /** Take @p dir for this run (see the help text): lock, stale temporaries, earlier runs. */
    std::unique_ptr<OutputDirectory>
    claim_output_directory(const std::string &dir, const ParsedArguments &a, const bool wear)
    {
      if (a.has("--overwrite") && a.has("--resume"))
        throw InputError("--overwrite and --resume exclude each other: --resume continues the run in " +
                         a.value("--resume") + ", --overwrite removes its files.");
      OutputClaim claim = output_claim(dir, io::outputs::run(), a);
      if (a.has("--resume"))
        claim.earlier = EarlierRun::resume;
      if (wear)
        claim.advice = "Add --overwrite to replace them, --resume " + dir +
                       " (instead of --output) to continue that wear run, or choose another --output directory.";
      return app::claim_output_directory(claim);
    }

    /** `wearlink run` of a wear scene (or --resume): the wear loop and its outputs. */
    int
    run_wear_scene(io::Scene &scene, const std::string &file, const ParsedArguments &a)
    {
      if (!workflows::has_wear(scene))
        throw InputError("--resume continues a wear run, but no clearance joint of " + file + " has a Wear law.");
      workflows::WearRunOptions w;
      w.resume           = a.has("--resume");
      w.output_directory = a.has("--resume") ?
                             a.value("--resume") :
                             a.value("--output", "output/" + std::filesystem::path(file).stem().string());
      w.progress         = !a.has("--quiet");
      const auto claimed = claim_output_directory(w.output_directory, a, true);
      const auto r       = workflows::run_wear(scene, w);
      if (!r.before_after_report.empty())
        std::cout << r.before_after_report << "\n";
      std::cout << "wrote " << w.output_directory << "/summary.json (" << r.state.iterations_done
                << " wear iterations, " << r.state.revolutions << " revolutions, " << r.timings.total << " s wall)\n";
      return 0;
    }

    /** The short summary and the files of a run (workflows/run/first_look.h). */
    void
    print_first_look(const workflows::FirstLook &look)
    {
      for (const auto &note : look.notes)
        std::cerr << "[wearlink] " << note << "\n";
      std::cout << "summary (summary.json; peaks over every integrator step, the time series and its plots "
                   "sample them):\n"
                << look.summary << "files written:\n";
      for (const auto &f : look.written)
        std::cout << "  " << f << "\n";
    }

    /** `wearlink run` of a scene without wear: one simulation and its analyses. */
    int
    run_plain_scene(io::Scene &scene, const std::string &file, const ParsedArguments &a)
    {
      const std::string     out     = a.value("--output", "output/" + std::filesystem::path(file).stem().string());
      const auto            claimed = claim_output_directory(out, a, false);
      workflows::RunOptions options;
      options.output_directory = out;
      options.progress         = !a.has("--quiet");
      const auto  run          = workflows::run_with_first_look(scene, options);
      const Json &summary      = run.summary;
      std::cout << "wrote " << out << "/summary.json (" << json_number(summary.at("steps")) << " steps, "
                << json_number(summary.at("wall_time_s")) << " s wall)\n";
      if (summary.contains("analyses") && summary.at("analyses").contains("lyapunov"))
        {
          const Json &l = summary.at("analyses").at("lyapunov");
          for (std::size_t k = 0; k < l.size(); ++k)
            {
              std::cout << "  largest Lyapunov exponent of " << l[k].at("channel").get<std::string>() << " ("
                        << l[k].at("method").get<std::string>() << "): " << json_number(l[k].at("exponent_per_s"))
                        << " 1/s (natural log)";
              if (l[k].contains("exponent_per_sample"))
                std::cout << " = " << json_number(l[k].at("exponent_per_sample")) << " per sample of "
                          << json_number(l[k].at("sample_interval_s")) << " s";
              std::cout << "\n";
            }
        }
      print_first_look(run.look);
      return 0;
    }

    /**
     * `wearlink run --ensemble N`: every member a wear run (or a plain run) of the scene
     * perturbed, in DIR/member_<k>/ (app/ensemble_command.h).
     */
    int
    run_ensemble_scene(const std::string &file, const ParsedArguments &a, const bool wear)
    {
      const bool progress = !a.has("--quiet");
      if (wear)
        return run_ensemble_command(
          "run",
          file,
          a,
          [progress](io::Scene &scene, const std::string &dir, const std::string &prefix, const bool resume) {
            workflows::WearRunOptions w;
            w.output_directory = dir;
            w.resume           = resume;
            w.progress         = progress;
            w.progress_prefix  = prefix;
            return workflows::run_wear(scene, w).summary;
          },
          io::outputs::run());
      if (a.has("--resume"))
        throw InputError("--resume continues a wear run, but no clearance joint of " + file + " has a Wear law.");
      return run_ensemble_command(
        "run",
        file,
        a,
        [](io::Scene &scene, const std::string &dir, const std::string &, const bool) {
          workflows::RunOptions ro;
          ro.output_directory = dir;
          return workflows::run_scene(scene, ro);
        },
        io::outputs::run());
    }

    int
    run_run(const std::vector<std::string> &args)
    {
      std::vector<OptionSpec> spec = {{"--output", true},
                                      {"--set", true, true},
                                      {"--validate", false},
                                      {"--print-parameters", false},
                                      {"--quiet", false},
                                      {"--overwrite", false},
                                      {"--resume", true}};
      for (const auto &o : ensemble_options())
        spec.push_back(o);
      const auto a = parse_arguments(args, spec, "run");
      if (a.has("--print-parameters"))
        {
          io::print_scene_parameters(std::cout, a.positional.empty() ? "" : a.positional[0]);
          return 0;
        }
      if (a.positional.size() != 1)
        throw InputError("`wearlink run` needs exactly one scene file (given " + std::to_string(a.positional.size()) +
                         "). See `wearlink run --help`.");
      const std::string file  = a.positional[0];
      io::Scene         scene = io::read_scene(file, a.all("--set"));

      if (a.has("--validate"))
        {
          Eigen::VectorXd q, v;
          workflows::assemble_scene(scene, q, v);
          std::cout << "OK: " << file << " — " << scene.mechanism->n_bodies() << " bodies, "
                    << scene.mechanism->n_constraint_equations() << " constraint equations, "
                    << scene.clearance_joints.size() << " clearance joints; assembles at t = " << scene.start_time
                    << " s.\n";
          scene.warnings.print(std::cerr);
          return 0;
        }

      if (a.has("--ensemble") || a.has("--seed") || a.has("--perturbation") || a.has("--sensitivity"))
        {
          ensemble_request(a); // a bad value is refused before anything runs
          return run_ensemble_scene(file, a, workflows::has_wear(scene));
        }
      refuse_several_ranks("run` without `--ensemble",
                           "add --ensemble N to run N perturbed members of the scene over the ranks");
      if (workflows::has_wear(scene) || a.has("--resume"))
        return run_wear_scene(scene, file, a);
      return run_plain_scene(scene, file, a);
    }
  } // namespace

  extern const Command run_scene_command;
  const Command        run_scene_command = {"run",
                                            "run SCENE.prm [--output DIR] [--set S/E=V ...]  "
                                                   "simulate a mechanism scene",
                                            run_help.c_str(),
                                            run_run};
} // namespace wearlink::app
