// SPDX-License-Identifier: LGPL-2.1-or-later
#include "io/output_names.h"

namespace wearlink::io::outputs
{
  RunFiles
  run()
  {
    RunFiles f;
    f.patterns       = {summary,
                        parameters,
                        time_series,
                        checkpoint,
                        "analysis_series.csv",
                        "phase_portrait_*.png",
                        "poincare_section.csv",
                        "poincare_*.png",
                        "lyapunov_*.csv",
                        "lyapunov_*.png",
                        wear_history,
                        "wear_depth_*.csv",
                        "wear_depth_*.png",
                        "profiles_*.csv",
                        "profiles_*.msh",
                        "profile_*_bore.png",
                        "profile_*_pin.png",
                        "bore_*.csv",
                        "pin_*.csv",
                        "wear_volume.png",
                        response_before,
                        response_after,
                        "response.png",
                        "before_after.md",
                        "before_after_*.png",
                        "before_after_*.csv",
                        "mesh_*.msh",
                        "fields_*.vtu",
                        "fields_*.pvd",
                        "fields_*_pressure.csv",
                        "profiles_*.pvd",
                        "profile_*.vtu",
                        "orbit_*.png",
                        "contact_forces.png",
                        "accelerations.png"};
    f.subdirectories = {"dynamics_before", "dynamics_after", "exponent_before", "exponent_after", "fe", "profiles"};
    return f;
  }

  RunFiles
  life()
  {
    RunFiles f = run();
    f.patterns.push_back(life_history);
    f.patterns.push_back(life_plot);
    return f;
  }

  RunFiles
  ensemble()
  {
    return {{summary, ensemble_table, ensemble_plot, "sensitivity.png", "life_cdf.png"}, {}};
  }

  RunFiles
  contact()
  {
    return {{summary, parameters, "pressure_*_*.csv", "fields_*.vtu", contact_mesh}, {}};
  }

  RunFiles
  accuracy_study()
  {
    return {{accuracy_table, accuracy_report, accuracy_floor, "accuracy_pareto.png", "accuracy_pareto_volume.png"}, {}};
  }

  RunFiles
  convergence_study()
  {
    return {{convergence_report, convergence_table, convergence_json, "convergence_*.csv", "convergence_*.png"}, {}};
  }

  RunFiles
  sweep()
  {
    return {{bifurcation_table, sweep_members, bifurcation_plot, sweep_json}, {}};
  }

  RunFiles
  compare_contact()
  {
    return {{force_approach_table,
             force_approach_plot,
             deviations,
             effects,
             pressure_table,
             pressure_plot,
             compare_contact_log},
            {}};
  }

  RunFiles
  compare_pressure()
  {
    return {{compare_pressure_table, "compare_depth_*.csv", "compare_depth_*.png"}, {}};
  }

  RunFiles
  compare_dynamics()
  {
    return {{"before_after_phase_*.png", before_after_table, "before_after_delay_scan.*", before_after_report}, {}};
  }

  RunFiles
  compare_signal()
  {
    return {{signal_overlay, signal_spectrum, signal_comparison}, {signal_simulated}};
  }

  RunFiles
  compare_profile()
  {
    return {{profile_comparison_plot, profile_comparison_json}, {}};
  }

  RunFiles
  calibrate()
  {
    return {{calibration_report, calibrated_scene, calibration_plot}, {}};
  }

  RunFiles
  lyapunov()
  {
    return {{"lyapunov_*_*.csv", "lyapunov_*_*.json", "lyapunov_*_*.png"}, {}};
  }

  std::string
  listing(const RunFiles &files, const bool removable)
  {
    std::vector<std::string> names = files.patterns;
    for (const auto &d : files.subdirectories)
      names.push_back(d + "/");
    std::string out  = removable ? "Files and folders this command may write (the names --overwrite removes):\n" :
                                   "Files this command may write (an earlier run's are kept or replaced):\n";
    std::string line = " ";
    for (std::size_t i = 0; i < names.size(); ++i)
      {
        const std::string item = " " + names[i] + (i + 1 < names.size() ? "," : "");
        if (line.size() + item.size() > 88)
          {
            out += line + "\n";
            line = " ";
          }
        line += item;
      }
    return out + line + "\n";
  }
} // namespace wearlink::io::outputs
