// SPDX-License-Identifier: LGPL-2.1-or-later
// The wearlink program: dispatch to a sub-command and the one place where errors are
// caught. A user error (InputError) prints its message and exits with status 2; a
// numerical failure of a valid scene (NumericalError) exits with 3; a fault of the
// environment (IoError: a file that cannot be written, a full disk; std::bad_alloc:
// memory ran out) exits with 4; anything else is a bug and exits with 1 after printing
// what deal.II knows about it.
#include "app/commands.h"
#include "base/exceptions.h"
#include "base/interrupt.h"
#include "base/text.h"
#include "register_all.h"

#include <deal.II/base/exceptions.h>

#include <iostream>
#include <new>
#include <string>
#include <vector>

namespace
{
  void
  print_usage(std::ostream &out)
  {
    out << "wearlink — finite-element wear refinement for planar mechanisms with revolute\n"
           "clearance joints.\n\n"
           "Usage:\n";
    for (const auto &c : wearlink::app::commands())
      out << "  wearlink " << c.synopsis << "\n";
    out << "  wearlink --validate SCENE.prm        check a scene without running it\n"
           "  wearlink --print-parameters [SCENE]  every declared entry with its unit and "
           "default\n"
           "  wearlink --help | COMMAND --help\n\n"
           "Exit status:\n"
           "  0  success\n"
           "  1  internal error (a bug: please report it with the scene)\n"
           "  2  bad input: scene, file or command line (the message says what to fix); also\n"
           "     an output directory in use by another wearlink command (its pid is named) or\n"
           "     holding an earlier run's files (add --overwrite)\n"
           "  3  numerical failure in a valid scene (the message names time, joint, residual)\n"
           "  4  the environment failed: an output that cannot be written (permission, disk\n"
           "     full) or memory that ran out\n"
           "  128 + N  stopped by signal N (130 SIGINT, 143 SIGTERM, 129 SIGHUP): temporary files\n"
           "     removed, the last checkpoint kept\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  std::vector<std::string> args(argv + 1, argv + argc);
  const std::string        command = args.empty() ? "" : (args[0] == "--validate" ? "run --validate" : args[0]);
  try
    {
      dealii::deal_II_exceptions::disable_abort_on_exception();
      wearlink::install_interrupt_handlers(); // SIGINT/SIGTERM: exit 128 + signal, temporaries removed
      wearlink::register_all();

      if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help")
        {
          print_usage(std::cout);
          return args.empty() ? 2 : 0;
        }
      // Global spellings that map onto the run command.
      if (args[0] == "--validate" || args[0] == "--print-parameters")
        {
          args.insert(args.begin(), "run");
        }
      for (const auto &c : wearlink::app::commands())
        if (args[0] == c.name)
          {
            const std::vector<std::string> rest(args.begin() + 1, args.end());
            for (const auto &a : rest)
              if (a == "--help" || a == "-h")
                {
                  std::cout << c.help;
                  return 0;
                }
            return c.run(rest);
          }
      std::cerr << "error: unknown command '" << args[0] << "'.\n\n";
      print_usage(std::cerr);
      return 2;
    }
  catch (const wearlink::InputError &e)
    {
      std::cerr << "error: " << wearlink::shorten_long_words(e.message()) << '\n';
      return 2;
    }
  catch (const wearlink::EstimationError &e)
    {
      std::cerr << "error: " << wearlink::shorten_long_words(e.message()) << '\n';
      return 2;
    }
  catch (const wearlink::NumericalError &e)
    {
      std::cerr << "numerical failure: " << wearlink::shorten_long_words(e.message()) << '\n';
      return 3;
    }
  catch (const wearlink::IoError &e)
    {
      std::cerr << "error: " << wearlink::shorten_long_words(e.message()) << '\n';
      return 4;
    }
  catch (const wearlink::Interrupted &e)
    {
      std::cerr << "interrupted: " << e.message() << '\n';
      return 128 + e.signal_number();
    }
  catch (const std::bad_alloc &)
    {
      std::cerr << "error: memory ran out during `wearlink " << command
                << "`. Some size in the scene or the options (discrete areas, mesh elements, table "
                   "sizes, samples, iterations) asks for more memory than this machine has; lower "
                   "it, or run on a machine with more memory.\n";
      return 4;
    }
  catch (const dealii::ExceptionBase &e)
    {
      std::cerr << "internal error:\n" << e.what() << '\n';
      return 1;
    }
  catch (const std::exception &e)
    {
      std::cerr << "internal error: " << e.what() << '\n';
      return 1;
    }
  catch (...)
    {
      // A library that throws something else (gmsh throws its messages as strings):
      // still our bug, and still an exit through the destructors (outputs unlocked,
      // temporaries removed), never an abort.
      std::cerr << "internal error: an exception of unknown type left `wearlink " << command << "`\n";
      return 1;
    }
}
