// SPDX-License-Identifier: LGPL-2.1-or-later
// `wearlink compare-pressure SCENE.prm`: the same load history of every wearing joint
// through several pressure models (workflows/compare/pressure_comparison.h); prints the table and
// writes compare_pressure.csv, compare_depth_<J>.csv/.png.
#include "app/command_line.h"
#include "app/output_claim.h"
#include "base/exceptions.h"
#include "base/text.h"
#include "io/output_names.h"
#include "io/scene.h"
#include "workflows/compare/pressure_comparison.h"

#include <filesystem>
#include <iostream>

namespace wearlink::app
{
  namespace
  {
    const std::string compare_pressure_help =
      std::string(
        R"(wearlink compare-pressure SCENE.prm [--models a,b,c] [--cycles N] [--output DIR]
                                   [--overwrite] [--set "Section/Entry=value" ...]

Simulates N cycles (default: Wear/Cycles per iteration) of a wear scene once, records
the load history of every joint with a Wear law, and feeds that same history through
each pressure model (default: every registered one whose parameters the scene gives for
those joints, in the order `wearlink --print-parameters` lists them under Pressure model,
fe last; the last one listed is the reference of the L2 column), each with the joint's
own parameters from the scene, into Archard's law on both surfaces. Prints per joint and model: worn volume of pin and bushing, the
global Archard volume k_D ∫F|v|dt, largest depth and its body-frame angle, the
relative L2 difference of the depth profiles against the reference, the number of
pressure evaluations and the wall time. The load sampling follows Wear/Pressure
evaluation (with fe, 'samples per cycle' keeps it affordable).
Writes into DIR (default: output/<scene name>_compare): compare_pressure.csv,
compare_depth_<J>.csv and compare_depth_<J>.png.
)") + output_folder_help +
      R"(
Exit status: 0 success, 2 bad input (also: directory in use, earlier run's files),
3 numerical failure, 4 an output that cannot be written or memory that ran out, 1 an
internal error (see `wearlink --help`).
)" + io::outputs::listing(io::outputs::compare_pressure());

    int
    run_compare_pressure(const std::vector<std::string> &args)
    {
      const auto a = parse_arguments(
        args,
        {{"--output", true}, {"--set", true, true}, {"--models", true}, {"--cycles", true}, {"--overwrite", false}},
        "compare-pressure");
      if (a.positional.size() != 1)
        throw InputError("`wearlink compare-pressure` needs exactly one scene file. See --help.");
      const std::string              file   = a.positional[0];
      io::Scene                      scene  = io::read_scene(file, a.all("--set"));
      const std::vector<std::string> models = a.list("--models"); // empty: the workflow's default
      const double                   cycles = a.number("--cycles", scene.wear_loop.cycles_per_iteration);
      if (!(cycles > 0 && cycles <= 1e4))
        throw InputError("--cycles is " + format_number(cycles) +
                         "; it must be > 0 and at most 1e4 (the load history of the cycles is kept in memory).");
      const std::string out = a.value("--output", "output/" + std::filesystem::path(file).stem().string() + "_compare");
      const auto        claimed = claim_output_directory(output_claim(out, io::outputs::compare_pressure(), a));
      const auto        c       = workflows::compare_pressure_models(scene, models, cycles);
      std::cout << c.table();
      workflows::write_pressure_comparison(out, c);
      std::cout << "\nwrote " << out << "/compare_pressure.csv\n";
      return 0;
    }
  } // namespace

  extern const Command compare_pressure_command;
  const Command        compare_pressure_command = {"compare-pressure",
                                                   "compare-pressure SCENE.prm [--models a,b,c]  same load history "
                                                          "through several pressure models (wear volumes and profiles)",
                                                   compare_pressure_help.c_str(),
                                                   run_compare_pressure};
} // namespace wearlink::app
