// SPDX-License-Identifier: LGPL-2.1-or-later
#include "app/command_line.h"
#include "base/exceptions.h"

namespace wearlink::app
{
  namespace
  {
    int
    run(const std::vector<std::string> &)
    {
      throw InputError("run: under construction");
    }
  } // namespace

  extern const Command run_scene_command;
  const Command run_scene_command = {"run", "run SCENE.prm [--output DIR] [--set S/E=V ...]", "", run};
} // namespace wearlink::app
