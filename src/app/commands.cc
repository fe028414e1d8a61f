// SPDX-License-Identifier: LGPL-2.1-or-later
#include "app/commands.h"

namespace wearlink::app
{
  // Each sub-command lives in app/commands/<name>.cc and exposes its Command entry.
  extern const Command run_scene_command;
  extern const Command lyapunov_command;
  extern const Command contact_command;
  extern const Command sweep_command;
  extern const Command compare_pressure_command;
  extern const Command compare_contact_command;
  extern const Command study_command;
  extern const Command compare_dynamics_command;
  extern const Command compare_signal_command;
  extern const Command compare_profile_command;
  extern const Command life_command;
  extern const Command calibrate_command;

  const std::vector<Command> &
  commands()
  {
    static const std::vector<Command> table = {
      run_scene_command,
      life_command,
      lyapunov_command,
      contact_command,
      sweep_command,
      compare_pressure_command,
      compare_contact_command,
      study_command,
      compare_dynamics_command,
      compare_signal_command,
      compare_profile_command,
      calibrate_command,
    };
    return table;
  }
} // namespace wearlink::app
