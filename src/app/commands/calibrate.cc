// SPDX-License-Identifier: LGPL-2.1-or-later
// `wearlink calibrate SCENE.prm --measurements MEAS.prm`: the Archard wear coefficients
// of a scene's wearing joints from measured mass losses (workflows/wear/calibration.h).
#include "app/command_line.h"
#include "app/output_claim.h"
#include "base/exceptions.h"
#include "io/calibration_files.h"
#include "io/output_names.h"
#include "workflows/wear/calibration.h"

#include <deal.II/base/mpi.h>

#include <cmath>
#include <filesystem>
#include <iostream>

namespace wearlink::app
{
  namespace
  {
    const std::string calibrate_help =
      std::string(
        R"(wearlink calibrate SCENE.prm --measurements MEAS.prm [--ensemble N] [--seed S]
                   [--perturbation RAD] [--tolerance T] [--max-runs R] [--set "S/E=V" ...]
                   [--output DIR] [--overwrite] [--quiet]

Identifies the Archard wear coefficients ('Joint J/Clearance/archard/Pin wear
coefficient' and 'Bushing wear coefficient', m^3/(N m)) of the scene's wearing joints
from measured mass losses or worn profiles, by whole wear runs (the worn gap feeds
back on the dynamics).

MEAS.prm (deal.II parameter syntax, like a scene), per measured joint J:
  subsection Joint J
    set Revolutions                   = 50000  # of the test [-], > 0
    set Pin mass loss                 = 6.3    # [mg], > 0
    set Pin mass loss uncertainty     = 0.1    # [mg, 1 sigma], >= 0
    set Bushing mass loss             = ...    # [mg] (either surface, or both)
    set Bushing mass loss uncertainty = ...    # [mg, 1 sigma]
    set Pin profile file              = ...    # optional measured worn surfaces,
    set Bore profile file             = ...    # 'angle_rad,radius_m' as runs write
                                               # pin_<J>.csv (relative to MEAS.prm)
    set Profile uncertainty           = 2e-6   # [m, 1 sigma per point], > 0
    set Profile angle search          = 180    # [deg], 0 ... 180 (default 180)
  end
A joint cut into slices along its pin is measured as a whole, by its own name: its
slices' mass losses add up (a profile file is refused for it: its surfaces differ along
the pin).
A surface with a profile but no mass loss is fitted on the profile's worn volume: its
worn area against the scene's unworn surface x the joint's axial length x the
surface's density, as a mass loss with the 1 sigma of independent per-point errors.
After the calibration one run at the calibrated coefficients is compared with every
profile (aligned within the angle search, as `wearlink compare-profile` does): RMS
difference, RMS / Profile uncertainty, worn areas, deepest wear.
Each forward run is the scene with the coefficients set and its wear loop stretched to
the measured revolutions (fixed extrapolation: 'Wear/Extrapolation factor' = R /
(cycles per iteration x iterations); adaptive: 'Wear/Target revolutions' = R).

  1. secant: runs of the scene from its own coefficients (the first step the linear
     rescale k m_measured / m_predicted, then secant steps on log k with the
     least-squares slope d log m / d log k of the runs so far, bisection once the root
     is bracketed) until every |m_predicted / m_measured - 1| < T or R runs;
  2. ensemble: N runs at that k with the initial angles perturbed as by `run
     --ensemble` (over the MPI ranks with mpirun); N = 1: none;
  3. value = k (m_measured / mean)^(1/slope); 95 % interval value exp(+-1.96 s),
     s = sqrt((sigma_m/m)^2 + (sigma_c/mean)^2) / slope, sigma_m the measurement's
     1 sigma, sigma_c = s sqrt(1 + 1/N) with s the std of the N runs (the measured
     test is one chaotic sample, scatter s; the mean is known to s/sqrt(N)); 0 for
     N = 1, whose chaotic scatter is not estimated.

  --measurements MEAS the measured mass losses (required)
  --ensemble N        runs at the final k (1 ... 1000, default 4; 1: no ensemble)
  --seed S            seed of the perturbations (default 1)
  --perturbation RAD  sigma of the initial-angle shifts (default 1e-9 rad)
  --tolerance T       of the secant on the relative mass-loss residual (default 1e-3)
  --max-runs R        secant runs at most (default 10)
  --set S/E=V         override a scene entry in every run (repeatable)
  --output DIR        where to write (default output/<scene name>_calibration)
  --quiet             no progress lines on stderr

Written into DIR, each file atomically, only when the calibration succeeded:
  calibration.json  joints.<J>.{pin,bushing}_wear_coefficient.{value,ci95_low,
                    ci95_high,sigma_log_k,prior,secant_value,slope_dlogm_dlogk}
                    [m^3/(N m)], .{pin,bushing}_mass_loss_mg.{measured,
                    measured_uncertainty,predicted_mean,predicted_std,
                    predicted_std_of_mean,chaos_uncertainty,predicted_members,...},
                    the secant's runs
                    and residuals, iterations, forward_runs, wall_time_s; with
                    profiles .{pin,bore}_profile.{rms_difference_m,
                    rms_over_uncertainty,rotation_deg,worn_area_measured_m2,
                    worn_area_predicted_m2,max_depth_measured_m,...}
  calibrated.prm    the effective scene (includes resolved, --set applied) with the
                    calibrated coefficients; a comment on top names the measurements
                    and the intervals
  calibration.png   measured against predicted mass loss per surface
)") + output_folder_help +
      R"(  --overwrite        replace the files of an earlier calibration in DIR

Exit status: 0 success; 2 bad input (a missing or malformed measurements file, an entry
that is not a finite number, Revolutions <= 0 or fewer than the scene simulates, a
negative uncertainty, a joint that does not exist or does not wear, no measurement, a
profile file that cannot be read or has no uncertainty; a scene that does not wear or predicts
no wear of a measured surface; also: output directory in use, earlier files) - the
message names the file, the line and the entry, and nothing is written; 3 a forward
run that failed numerically; 4 an output that cannot be written; 1 an internal error.
)" + io::outputs::listing(io::outputs::calibrate());

    /** The options of @p a (InputError for a bad value). */
    workflows::CalibrationOptions
    calibration_options(const ParsedArguments &a)
    {
      workflows::CalibrationOptions o;
      o.scene_file        = a.positional[0];
      o.measurements_file = a.value("--measurements");
      o.overrides         = ParameterOverrides(a.all("--set"));
      o.progress          = !a.has("--quiet");
      o                   = workflows::calibration_options(o,
                                         a.number("--ensemble", 4),
                                         a.number("--seed", 1),
                                         a.number("--perturbation", 1e-9),
                                         a.number("--tolerance", 1e-3),
                                         a.number("--max-runs", 10));
      o.output_directory =
        a.value("--output", "output/" + std::filesystem::path(o.scene_file).stem().string() + "_calibration");
      return o;
    }

    int
    calibrate(const std::vector<std::string> &args)
    {
      std::vector<OptionSpec> spec = {{"--measurements", true},
                                      {"--ensemble", true},
                                      {"--seed", true},
                                      {"--perturbation", true},
                                      {"--tolerance", true},
                                      {"--max-runs", true},
                                      {"--set", true, true},
                                      {"--output", true},
                                      {"--overwrite", false},
                                      {"--quiet", false}};
      const auto              a    = parse_arguments(args, spec, "calibrate");
      if (a.positional.size() != 1 || !a.has("--measurements"))
        throw InputError("`wearlink calibrate` needs one scene file and --measurements MEAS.prm. See `wearlink "
                         "calibrate --help`.");
      const auto options        = calibration_options(a);
      auto       problem        = workflows::load_calibration(options); // bad input: before anything is claimed
      int        argc           = 1;
      char       program[]      = "wearlink";
      char      *argv_storage[] = {program, nullptr};
      char     **argv           = argv_storage;
      dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
      const auto                               claimed =
        claim_output_directory_on_root(output_claim(options.output_directory, io::outputs::calibrate(), a));
      const Json report = workflows::calibrate(problem, options);
      if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
        std::cout << workflows::calibration_table(report) << "wrote " << options.output_directory
                  << "/calibration.json, calibrated.prm, calibration.png\n";
      return 0;
    }
  } // namespace

  extern const Command calibrate_command;
  const Command        calibrate_command = {"calibrate",
                                            "calibrate SCENE.prm --measurements MEAS.prm  wear coefficients from "
                                                   "measured mass losses",
                                            calibrate_help.c_str(),
                                            calibrate};
} // namespace wearlink::app
