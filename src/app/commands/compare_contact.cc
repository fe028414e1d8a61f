// SPDX-License-Identifier: LGPL-2.1-or-later
// `wearlink compare-contact SCENE.prm`: the simplified contact laws against the FE model
// (workflows/compare/contact_comparison.h); prints the deviations and the effects, writes the
// curves, tables and the plot.
#include "app/command_line.h"
#include "app/output_claim.h"
#include "base/exceptions.h"
#include "base/text.h"
#include "io/output_names.h"
#include "workflows/compare/contact_comparison.h"

#include <filesystem>
#include <iostream>

namespace wearlink::app
{
  namespace
  {
    const std::string compare_contact_help =
      std::string(R"(wearlink compare-contact SCENE.prm [--output DIR] [--worn DIR] [--cycles N] [--no-effects]
                                  [--overwrite] [--set "Section/Entry=value" ...]

The validation of simplified contact against the FE model, for every clearance joint
of the scene:
  1. force–approach curves: the sphere law the dynamics use by default (K δ^1.5,
     seed eq. 10), the cylindrical laws with the axial length (Johnson 1985; ESDU-78035),
     a linear Winkler layer (if the scene sets winkler/Layer thickness), and the FE model
     of the joint ('fe' subsection numerics). The approach δ is the overlap of the rigid
     profiles at the pin position the FE equilibrium finds (the bushing held on its outer
     edge, the pin loaded through its rigid core): the δ the clearance joint computes.
     With --worn DIR (a wear run's output: bore_<J>.csv, pin_<J>.csv) also the FE curve
     of the worn profiles, in the direction of the deepest bore wear.
  2. each law's force at the approach where FE carries 100 N, 1 kN, 10 kN, 100 kN,
     relative to that load (printed; deviations.csv);
  3. the effect on the dynamics: the scene run for N driving cycles (default 100) with
     every clearance joint on lankarani-nikravesh, johnson, esdu-78035 and fe (the
     scene's restitution): contact fraction, peak and mean normal force, impacts, peak
     body acceleration, steps, wall time (effects.csv). In a wear scene also one wear
     iteration per law (Wear/Cycles per iteration from assembly, the scene's pressure
     model, no extrapolation): the volumes worn off pin and bushing and Archard's
     k_D ∫ F|v| dt per wearing joint. --no-effects skips these runs.
  4. pressure distributions on the bore at four loads per joint, from the mean to the
     peak normal force in contact of the lankarani-nikravesh run (the effect run; with
     --no-effects a 10-cycle run), spaced geometrically, the pin pushed into the bore at
     the bushing's −y (with --worn: at the deepest bore wear): hertz-strip, winkler (if
     given) and fe, fresh and worn; peak pressure and contact half-angle of each and
     their ratio to fe (printed; pressure.csv, pressure.png).
Writes into DIR (default: output/<scene name>_contact): force_approach.csv (approach_m,
then force_N_<law>_<state>_<joint>), force_approach.png, deviations.csv, effects.csv,
pressure.csv (bore_angle_rad, then pressure_Pa_<model>_<state>_<joint>_<load>N),
pressure.png, compare_contact.txt. The FE tables are cached like the fe law's (see
--help of run).
)") + output_folder_help +
      R"(
Exit status: 0 success, 2 bad input (also: directory in use, earlier run's files),
3 numerical failure, 4 an output that cannot be written or memory that ran out, 1 an
internal error (see `wearlink --help`).
)" + io::outputs::listing(io::outputs::compare_contact());

    int
    run_compare_contact(const std::vector<std::string> &args)
    {
      const auto a = parse_arguments(args,
                                     {{"--output", true},
                                      {"--set", true, true},
                                      {"--worn", true},
                                      {"--cycles", true},
                                      {"--no-effects", false},
                                      {"--overwrite", false}},
                                     "compare-contact");
      if (a.positional.size() != 1)
        throw InputError("`wearlink compare-contact` needs exactly one scene file. See --help.");
      workflows::ContactComparisonRequest r;
      r.scene_file     = a.positional[0];
      r.overrides      = ParameterOverrides(a.all("--set"));
      r.worn_directory = a.value("--worn", "");
      r.cycles         = a.number("--cycles", 100);
      r.effects        = !a.has("--no-effects");
      const std::string out =
        a.value("--output", "output/" + std::filesystem::path(r.scene_file).stem().string() + "_contact");
      const auto claimed = claim_output_directory(output_claim(out, io::outputs::compare_contact(), a));
      const auto c       = workflows::compare_contact(r);
      std::cout << c.table();
      workflows::write_contact_comparison(out, c);
      std::cout << "\nwrote " << out
                << "/force_approach.csv, force_approach.png, deviations.csv, effects.csv, pressure.csv, pressure.png, "
                   "compare_contact.txt\n";
      return 0;
    }
  } // namespace

  extern const Command compare_contact_command;
  const Command        compare_contact_command = {"compare-contact",
                                                  "compare-contact SCENE.prm [--worn DIR]  simplified contact laws "
                                                         "against the FE model: curves, deviations, effects, pressures",
                                                  compare_contact_help.c_str(),
                                                  run_compare_contact};
} // namespace wearlink::app
