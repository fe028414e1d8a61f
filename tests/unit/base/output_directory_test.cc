// SPDX-License-Identifier: LGPL-2.1-or-later
// Files and folders of a run (base/atomic_file.h, base/output_directory.h,
// base/interrupt.h):
//  - a write that fails (here: the file-size limit, as a full disk would) is an IoError
//    naming the file, and the previous file and the directory are left as they were; a
//    file streamed over a long computation stops at its first failed write, and a copy
//    that fails leaves no partial copy;
//  - temporaries of dead writers are removed, those of running ones kept; so are the
//    scratch folders of dead processes;
//  - a locked directory is refused naming the holder's pid, and free again after it;
//  - an earlier run's files are refused, or removed with overwrite (the user's own files
//    are kept), or kept with resume;
//  - SIGTERM is recorded and thrown at the next check; a second SIGTERM removes the
//    registered temporaries and exits with 143 at once; SIGHUP stops as SIGTERM does,
//    unless it was ignored when the handlers were installed (nohup).
// Signals and resource limits are tried in a forked child, never in the test process.
#include "base/atomic_file.h"
#include "base/exceptions.h"
#include "base/interrupt.h"
#include "base/output_directory.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

using namespace wearlink;
namespace fs = std::filesystem;

namespace
{
  /** Run @p f in a forked child; its exit status (or 128 + signal). */
  template <typename F>
  int
  in_child(F f)
  {
    const pid_t pid = ::fork();
    if (pid == 0)
      ::_exit(f());
    int status = 0;
    ::waitpid(pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  }

  /** The pid of a process that has ended (forked, exited, reaped). */
  pid_t
  dead_pid()
  {
    const pid_t pid = ::fork();
    if (pid == 0)
      ::_exit(0);
    ::waitpid(pid, nullptr, 0);
    return pid;
  }

  RunFiles
  run_files()
  {
    RunFiles f;
    f.patterns       = {"summary.json", "time_series.csv", "wear_depth_*.csv"};
    f.subdirectories = {"dynamics_before"};
    return f;
  }
} // namespace

TEST(AtomicFile, FailedWriteIsAnIoErrorNamingTheFile)
{
  const std::string dir  = wearlink::testing::fresh_directory("atomic_full");
  const std::string path = dir + "/summary.json";
  write_file_atomically(path, "previous\n");
  const int status = in_child([&] {
    ::signal(SIGXFSZ, SIG_IGN);
    const rlimit limit = {4096, 4096}; // as a full disk: writing beyond fails (EFBIG)
    ::setrlimit(RLIMIT_FSIZE, &limit);
    try
      {
        write_file_atomically(path, std::string(1 << 20, 'x'));
      }
    catch (const IoError &e)
      {
        return e.message().find("Writing '" + path + "' failed") != std::string::npos ? 0 : 2;
      }
    catch (...)
      {
        return 3;
      }
    return 1;
  });
  EXPECT_EQ(status, 0) << "1: no error, 2: the message does not name the file, 3: not an IoError";
  EXPECT_EQ(wearlink::testing::file_content(path), "previous\n");
  EXPECT_TRUE(wearlink::testing::partial_files_in(dir).empty());
}

TEST(AtomicFile, StreamedFileStopsAtTheFirstFailedWrite)
{
  const std::string dir    = wearlink::testing::fresh_directory("atomic_streamed");
  const std::string path   = dir + "/time_series.csv";
  const int         status = in_child([&] {
    const rlimit limit = {4096, 4096}; // as a full disk: writing beyond fails (EFBIG)
    ::setrlimit(RLIMIT_FSIZE, &limit);
    install_interrupt_handlers(); // SIGXFSZ ignored, as in the program
    AtomicFile  f(path);
    std::size_t rows = 0;
    try
      {
        for (; rows < 1000000; ++rows)
          {
            f.stream() << rows << ",0.123456789,0.987654321\n";
            f.throw_if_failed();
          }
      }
    catch (const IoError &e)
      {
        if (e.message().find("Writing '" + path + "' failed: File too large") == std::string::npos)
          return 2;
        // 4096 bytes hold ~170 rows of 24 bytes; the stream's buffer (a few KiB) is
        // written when full, so the failure shows within one more buffer of rows.
        return rows < 2000 ? 0 : 4;
      }
    return 1;
  });
  EXPECT_EQ(status, 0) << "1: no error, 2: the message does not name the file and the reason, 4: not at the first "
                          "failed write";
  EXPECT_TRUE(wearlink::testing::files_in(dir).empty()) << "the temporary is removed";
}

TEST(AtomicFile, FailedCopyIsAnIoErrorAndLeavesNoPartialCopy)
{
  const std::string dir  = wearlink::testing::fresh_directory("atomic_copy");
  const std::string from = dir + "/source.msh";
  const std::string to   = dir + "/fe_mesh.msh";
  std::ofstream(from) << std::string(1 << 20, 'x');
  const int status = in_child([&] {
    const rlimit limit = {4096, 4096};
    ::setrlimit(RLIMIT_FSIZE, &limit);
    install_interrupt_handlers();
    try
      {
        copy_file_atomically(from, to);
      }
    catch (const IoError &e)
      {
        return e.message().find("Writing '" + to + "' failed") != std::string::npos ? 0 : 2;
      }
    catch (...)
      {
        return 3; // std::filesystem::filesystem_error: an "internal error" of the program
      }
    return 1;
  });
  EXPECT_EQ(status, 0) << "1: no error, 2: the message does not name the copy, 3: not an IoError";
  EXPECT_FALSE(fs::exists(to));
  EXPECT_TRUE(wearlink::testing::partial_files_in(dir).empty());
  copy_file_atomically(from, to); // without the limit the same copy succeeds
  EXPECT_EQ(fs::file_size(to), fs::file_size(from));
}

TEST(AtomicFile, StaleTemporariesOfDeadWritersAreRemoved)
{
  const std::string dir = wearlink::testing::fresh_directory("atomic_stale");
  fs::create_directories(dir + "/fe");
  const std::string dead = std::to_string(dead_pid());
  const std::string mine = std::to_string(::getpid());
  for (const std::string &f : {"/.summary.json.partial-" + dead + ".json",
                               "/fe/.mesh_A_1.msh.partial-" + dead + ".msh",
                               "/.time_series.csv.partial-" + mine + ".csv",
                               "/notes.partial-" + dead + ".txt", // not a name wearlink makes
                               std::string("/summary.json")})
    std::ofstream(dir + f) << "x";
  const auto removed = remove_stale_partials(dir);
  EXPECT_EQ(removed.size(), 2u);
  EXPECT_FALSE(fs::exists(dir + "/.summary.json.partial-" + dead + ".json"));
  EXPECT_FALSE(fs::exists(dir + "/fe/.mesh_A_1.msh.partial-" + dead + ".msh"));
  EXPECT_TRUE(fs::exists(dir + "/.time_series.csv.partial-" + mine + ".csv")) << "a running writer's";
  EXPECT_TRUE(fs::exists(dir + "/notes.partial-" + dead + ".txt"));
  EXPECT_TRUE(fs::exists(dir + "/summary.json"));
}

// The scratch folder of a process killed while it plotted (or meshed) is removed by the
// next one; a running process's and folders of other names are kept.
TEST(TemporaryDirectory, StaleScratchOfKilledProcessesIsRemoved)
{
  const std::string parent = wearlink::testing::fresh_directory("scratch_parent");
  const std::string dead   = std::to_string(dead_pid());
  const std::string mine   = std::to_string(::getpid());
  for (const std::string &d : {"wearlink-plot-" + dead + "-0",
                               "wearlink-fe-" + mine + "-3",
                               std::string("wearlink-notes"),
                               "wearlink-plot-" + dead + "-x-y",
                               "other-plot-" + dead + "-0"})
    {
      fs::create_directories(parent + "/" + d);
      std::ofstream(parent + "/" + d + "/plot.gp") << "x";
    }
  const auto removed = remove_stale_temporary_directories(parent);
  ASSERT_EQ(removed.size(), 1u);
  EXPECT_FALSE(fs::exists(parent + "/wearlink-plot-" + dead + "-0"));
  EXPECT_TRUE(fs::exists(parent + "/wearlink-fe-" + mine + "-3")) << "a running process's";
  EXPECT_TRUE(fs::exists(parent + "/wearlink-notes"));
  EXPECT_TRUE(fs::exists(parent + "/wearlink-plot-" + dead + "-x-y")) << "not a name wearlink makes";
  EXPECT_TRUE(fs::exists(parent + "/other-plot-" + dead + "-0"));
}

TEST(OutputDirectory, LockedDirectoryIsRefusedNamingTheHolder)
{
  const std::string dir = wearlink::testing::fresh_directory("output_lock") + "/run";
  {
    OutputDirectory   first(dir, EarlierRun::refuse, run_files(), "");
    const std::string m =
      wearlink::testing::input_error_message([&] { OutputDirectory second(dir, EarlierRun::resume, run_files(), ""); });
    EXPECT_NE(m.find("is in use by another wearlink run (pid " + std::to_string(::getpid()) + ";"), std::string::npos)
      << m;
    EXPECT_TRUE(fs::exists(dir + "/" + OutputDirectory::lock_file_name));
  }
  EXPECT_FALSE(fs::exists(dir + "/" + OutputDirectory::lock_file_name)) << "removed on release";
  EXPECT_NO_THROW(OutputDirectory(dir, EarlierRun::refuse, run_files(), ""));
}

TEST(OutputDirectory, EarlierRunIsRefusedOverwrittenOrKept)
{
  const std::string dir = wearlink::testing::fresh_directory("output_earlier");
  fs::create_directories(dir + "/dynamics_before/deeper");
  for (const char *f : {"/summary.json",
                        "/wear_depth_A.csv",
                        "/notes.txt",
                        "/dynamics_before/summary.json",
                        "/dynamics_before/deeper/time_series.csv"})
    std::ofstream(dir + f) << "x";
  const std::string m = wearlink::testing::input_error_message(
    [&] { OutputDirectory d(dir, EarlierRun::refuse, run_files(), "Add --overwrite."); });
  EXPECT_NE(m.find("holds the files of an earlier run (dynamics_before/deeper/time_series.csv, "
                   "dynamics_before/summary.json, summary.json, wear_depth_A.csv). Add --overwrite."),
            std::string::npos)
    << m;
  EXPECT_TRUE(fs::exists(dir + "/summary.json")) << "nothing removed when refused";
  EXPECT_FALSE(fs::exists(dir + "/" + OutputDirectory::lock_file_name)) << "a refused claim lets go";
  {
    OutputDirectory kept(dir, EarlierRun::resume, run_files(), "");
    EXPECT_TRUE(kept.removed_files().empty());
    EXPECT_TRUE(fs::exists(dir + "/summary.json"));
  }
  OutputDirectory cleared(dir, EarlierRun::overwrite, run_files(), "");
  EXPECT_EQ(cleared.removed_files().size(), 4u);
  EXPECT_FALSE(fs::exists(dir + "/summary.json"));
  EXPECT_FALSE(fs::exists(dir + "/dynamics_before")) << "the run's emptied folder";
  EXPECT_TRUE(fs::exists(dir + "/notes.txt")) << "the user's own file is kept";
}

TEST(Interrupt, SignalIsThrownAtTheNextCheckAndASecondOneExitsAtOnce)
{
  const int first = in_child([] {
    install_interrupt_handlers();
    if (interrupt_signal() != 0)
      return 1;
    ::raise(SIGTERM);
    try
      {
        throw_if_interrupted();
      }
    catch (const Interrupted &e)
      {
        return e.signal_number() == SIGTERM && e.message().find("SIGTERM") != std::string::npos ? 0 : 2;
      }
    return 3;
  });
  EXPECT_EQ(first, 0);

  const std::string dir    = wearlink::testing::fresh_directory("interrupt_second");
  const std::string path   = dir + "/.summary.json.partial-1.json";
  const int         second = in_child([&] {
    install_interrupt_handlers();
    std::ofstream(path) << "x";
    RegisteredTemporary registered(path);
    ::raise(SIGTERM);
    ::raise(SIGTERM); // does not return
    return 1;
  });
  EXPECT_EQ(second, 128 + SIGTERM);
  EXPECT_FALSE(fs::exists(path)) << "removed by the handler of the second signal";
}

TEST(Interrupt, SighupStopsAsSigtermUnlessIgnoredAtTheStart)
{
  const int stopped = in_child([] {
    install_interrupt_handlers();
    ::raise(SIGHUP);
    try
      {
        throw_if_interrupted();
      }
    catch (const Interrupted &e)
      {
        return e.signal_number() == SIGHUP && e.message().find("Stopped by SIGHUP") != std::string::npos ? 0 : 2;
      }
    return 3;
  });
  EXPECT_EQ(stopped, 0) << "2: another signal or message, 3: not recorded";
  const int ignored = in_child([] {
    ::signal(SIGHUP, SIG_IGN); // nohup
    install_interrupt_handlers();
    ::raise(SIGHUP);
    return interrupt_signal();
  });
  EXPECT_EQ(ignored, 0) << "a SIGHUP ignored at the start stays ignored";
}
