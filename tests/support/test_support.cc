// SPDX-License-Identifier: LGPL-2.1-or-later
#include "support/test_support.h"

#include "base/exceptions.h"

#include <array>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <sys/wait.h>
#include <unistd.h>

namespace wearlink::testing
{
  namespace fs = std::filesystem;

  std::string
  source_path(const std::string &relative)
  {
    return (fs::path(WEARLINK_SOURCE_DIR) / relative).string();
  }

  std::string
  fresh_directory(const std::string &name)
  {
    // Per process: CTest runs the cases of one executable in parallel processes, and a
    // shared fixture (e.g. RoundPair's mesh) would otherwise be deleted under another.
    const fs::path dir = fs::current_path() / "test-output" / (name + "-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir.string();
  }

  namespace
  {
    std::string
    shell_quote(const std::string &s)
    {
      std::string out = "'";
      for (const char c : s)
        {
          if (c == '\'')
            out += "'\\''";
          else
            out += c;
        }
      return out + "'";
    }
  } // namespace

  namespace
  {
    ProgramResult
    run_shell(const std::string &command)
    {
      ProgramResult r;
      FILE         *pipe = ::popen((command + " 2>&1").c_str(), "r");
      if (pipe == nullptr)
        throw std::runtime_error("cannot start " + command);
      std::array<char, 4096> buf;
      std::size_t            n;
      while ((n = std::fread(buf.data(), 1, buf.size(), pipe)) > 0)
        r.output.append(buf.data(), n);
      const int status = ::pclose(pipe);
      r.exit_status    = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
      return r;
    }

    std::string
    quoted_arguments(const std::vector<std::string> &args)
    {
      std::string s = shell_quote(WEARLINK_BINARY);
      for (const auto &a : args)
        s += " " + shell_quote(a);
      return s;
    }
  } // namespace

  ProgramResult
  run_wearlink(const std::vector<std::string> &args)
  {
    return run_shell(quoted_arguments(args));
  }

  ProgramResult
  run_wearlink_mpi(unsigned int n_ranks, const std::vector<std::string> &args)
  {
    return run_shell(shell_quote(WEARLINK_MPIEXEC) + " -np " + std::to_string(n_ranks) + " --oversubscribe " +
                     quoted_arguments(args));
  }

  std::vector<std::string>
  files_in(const std::string &dir)
  {
    std::vector<std::string> out;
    if (!fs::exists(dir))
      return out;
    for (const auto &e : fs::recursive_directory_iterator(dir))
      if (e.is_regular_file())
        out.push_back(e.path().string());
    return out;
  }
  std::string
  input_error_message(const std::function<void()> &f)
  {
    try
      {
        f();
      }
    catch (const InputError &e)
      {
        return e.message();
      }
    return "(no InputError)";
  }
} // namespace wearlink::testing
