// SPDX-License-Identifier: LGPL-2.1-or-later
#include "support/test_support.h"

#include "base/exceptions.h"

#include <algorithm>
#include <array>
#include <csignal>
#include <cstdio>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <zlib.h>

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
    /**
     * Run @p command in a shell, its output collected. With @p file_size_limit > 0 the
     * shell and what it starts inherit that RLIMIT_FSIZE (set only around popen).
     */
    ProgramResult
    run_shell(const std::string &command, const std::size_t file_size_limit = 0)
    {
      ProgramResult r;
      rlimit        own;
      ::getrlimit(RLIMIT_FSIZE, &own);
      if (file_size_limit > 0)
        {
          const rlimit limited = {file_size_limit, own.rlim_max};
          ::setrlimit(RLIMIT_FSIZE, &limited);
        }
      FILE *pipe = ::popen((command + " 2>&1").c_str(), "r");
      ::setrlimit(RLIMIT_FSIZE, &own);
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
  run_wearlink_with_file_size_limit(const std::size_t bytes, const std::vector<std::string> &args)
  {
    return run_shell(quoted_arguments(args), bytes);
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

  std::vector<std::string>
  partial_files_in(const std::string &dir)
  {
    std::vector<std::string> out;
    if (!fs::exists(dir))
      return out;
    for (const auto &e : fs::recursive_directory_iterator(dir))
      if (e.path().filename().string().find(".partial-") != std::string::npos)
        out.push_back(e.path().string());
    return out;
  }

  std::string
  file_content(const std::string &path)
  {
    std::ifstream      in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }

  std::map<std::string, std::string>
  directory_snapshot(const std::string &dir)
  {
    std::map<std::string, std::string> out;
    for (const auto &f : files_in(dir))
      out[fs::relative(f, dir).string()] = file_content(f);
    return out;
  }

  std::string
  reseal_checkpoint(const std::string &text)
  {
    const std::string key = "\n\"payload\": ";
    const auto        at  = text.find(key);
    if (at == std::string::npos || text.size() < at + key.size() + 2)
      throw std::runtime_error("not a checkpoint of format version 6");
    const std::string payload = text.substr(at + key.size(), text.size() - at - key.size() - 2);
    char              crc[16];
    std::snprintf(crc,
                  sizeof(crc),
                  "%08lx",
                  ::crc32_z(::crc32_z(0L, Z_NULL, 0), reinterpret_cast<const Bytef *>(payload.data()), payload.size()));
    Json header             = Json::parse(text.substr(0, at - 1) + "}");
    header["payload_bytes"] = payload.size();
    header["payload_crc32"] = crc;
    std::string h           = header.dump();
    h.pop_back();
    return h + "," + key + payload + "}\n";
  }

  int
  start_wearlink(const std::vector<std::string> &args, const std::string &log_file)
  {
    std::vector<std::string> all = {WEARLINK_BINARY};
    all.insert(all.end(), args.begin(), args.end());
    std::vector<char *> argv;
    for (auto &a : all)
      argv.push_back(a.data());
    argv.push_back(nullptr);
    const pid_t pid = ::fork();
    if (pid < 0)
      throw std::runtime_error("fork failed");
    if (pid == 0)
      {
        ::signal(SIGHUP, SIG_DFL); // as started from a terminal, also under nohup
        const int fd = ::open(log_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (fd >= 0)
          {
            ::dup2(fd, 1);
            ::dup2(fd, 2);
          }
        ::execv(argv[0], argv.data());
        ::_exit(127);
      }
    return pid;
  }

  int
  wait_for(const int pid)
  {
    int status = 0;
    if (::waitpid(pid, &status, 0) != pid)
      return -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : WIFSIGNALED(status) ? 128 + WTERMSIG(status) : -1;
  }

  std::vector<std::string>
  with(std::vector<std::string> a, const std::vector<std::string> &b)
  {
    a.insert(a.end(), b.begin(), b.end());
    return a;
  }

  double
  type7(std::vector<double> v, const double p)
  {
    std::sort(v.begin(), v.end());
    const double      h = (v.size() - 1) * p;
    const std::size_t k = static_cast<std::size_t>(h);
    return k + 1 < v.size() ? v[k] + (h - k) * (v[k + 1] - v[k]) : v[k];
  }
} // namespace wearlink::testing
