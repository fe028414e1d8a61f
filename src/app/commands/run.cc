// SPDX-License-Identifier: LGPL-2.1-or-later
// `wearlink run SCENE.prm`: read and validate a scene, assemble it, integrate it and
// write summary.json, time_series.csv and parameters.prm into the output directory.
// `--validate` stops after reading, building and assembling (no output is written);
// `--print-parameters` prints every entry a scene can have.
#include "workflows/run.h"

#include "app/command_line.h"
#include "base/exceptions.h"
#include "io/scene.h"
#include "workflows/wear_run.h"

#include <filesystem>
#include <iostream>

namespace wearlink::app
{
  namespace
  {
    const char *help_text =
      R"(wearlink run SCENE.prm [--output DIR] [--set "Section/Entry=value" ...] [--quiet]
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
and, for the analyses listed in 'Analyses/List of analyses' (phase-portrait, poincare,
lyapunov; see --print-parameters): analysis_series.csv and phase_portrait_*.png,
poincare_section.csv and poincare_*.png, lyapunov_<channel>_<method>.csv/.png, with
their results (Poincaré spread, exponents in 1/s, natural log) in summary.json
Every file is written under a temporary name and renamed when complete.

A scene in which some clearance joint has 'Wear law = archard' runs the wear loop
instead (section Wear; one progress line per iteration) and writes, besides
summary.json (with per-joint wear volumes, depths, mass loss and revolutions) and
parameters.prm: checkpoint.json, wear_history.csv, wear_depth_<J>.csv/.png,
profiles_<J>.csv/.msh, profile_<J>_bore.png, profile_<J>_pin.png, wear_volume.png,
response_before.csv, response_after.csv, response.png.
If a wear scene lists analyses, they do not run during the wear iterations; instead
the dynamics is run from Start to End time once with the fresh and once with the worn
profiles (dynamics_before/, dynamics_after/) and compared (before_after.md, printed;
before_after_phase_*.png, before_after_lyapunov.csv, before_after_delay_scan.*; see
'Analyses/Before-after wear' and `wearlink compare-dynamics --help`).
  --resume DIR        continue the wear run whose output directory is DIR from its
                      last finished iteration (same scene; Wear/Number of iterations
                      and Wear/Target revolutions may be raised with --set)

Options:
  --output DIR        output directory
  --set S/E=V         override entry E of subsection S (repeatable), e.g.
                      --set "Joint A/Clearance/Radial clearance=2e-4"
  --validate          check the scene (parse, cross-checks, assembly) and stop
  --print-parameters  print every scene entry with its unit, default and meaning
  --quiet             no progress lines

Exit status: 0 success, 2 bad input, 3 numerical failure, 4 an output that cannot
be written or memory that ran out, 1 an internal error (see `wearlink --help`).
)";

    int
    run(const std::vector<std::string> &args)
    {
      const auto a = parse_arguments(args,
                                     {{"--output", true},
                                      {"--set", true, true},
                                      {"--validate", false},
                                      {"--print-parameters", false},
                                      {"--quiet", false},
                                      {"--resume", true}},
                                     "run");
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
          return 0;
        }

      if (workflows::has_wear(scene) || a.has("--resume"))
        {
          if (!workflows::has_wear(scene))
            throw InputError("--resume continues a wear run, but no clearance joint of " + file + " has a Wear law.");
          workflows::WearRunOptions w;
          w.resume           = a.has("--resume");
          w.output_directory = a.has("--resume") ?
                                 a.value("--resume") :
                                 a.value("--output", "output/" + std::filesystem::path(file).stem().string());
          w.progress         = !a.has("--quiet");
          const auto r       = workflows::run_wear(scene, w);
          if (!r.before_after_report.empty())
            std::cout << r.before_after_report << "\n";
          std::cout << "wrote " << w.output_directory << "/summary.json (" << r.state.iterations_done
                    << " wear iterations, " << r.state.revolutions << " revolutions, " << r.timings.total
                    << " s wall)\n";
          return 0;
        }
      const std::string     out = a.value("--output", "output/" + std::filesystem::path(file).stem().string());
      workflows::RunOptions options;
      options.output_directory = out;
      options.progress         = !a.has("--quiet");
      const Json summary       = workflows::run_scene(scene, options);
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
      return 0;
    }
  } // namespace

  extern const Command run_scene_command;
  const Command        run_scene_command = {"run",
                                            "run SCENE.prm [--output DIR] [--set S/E=V ...]  "
                                                   "simulate a mechanism scene",
                                            help_text,
                                            run};
} // namespace wearlink::app
