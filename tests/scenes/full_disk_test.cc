// SPDX-License-Identifier: LGPL-2.1-or-later
// A full disk, as the commands meet it: the first write that fails stops the command
// with exit status 4 and a message naming the file, never an abort (134) or an
// "internal error" (1), and nothing is left but the files it had finished: no
// temporary file, no lock, no truncated mesh. Two ways to make the writes fail:
//  - a small tmpfs (ENOSPC), as a user's nearly full disk, where this machine lets the
//    test mount one (root with CAP_SYS_ADMIN); skipped with a message otherwise;
//  - the file-size limit (RLIMIT_FSIZE, EFBIG), which every machine has: always run.
// The cases: `contact`, whose gmsh mesh is cut short (gmsh does not check its own
// writes, and reading the cut file back threw through deal.II's reader and aborted); a
// run streaming time_series.csv, which must stop at the failed write instead of
// integrating on (the scene asks for 1e8 rows: minutes of work); an FE wear run, which
// writes meshes, copies them into fe/ and writes VTU fields.
#include "base/output_directory.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace
{
  namespace fs = std::filesystem;
  using wearlink::testing::ProgramResult;
  using wearlink::testing::source_path;

  /** A tmpfs of a given size mounted while the object lives (if the machine allows it). */
  class SmallTmpfs
  {
  public:
    SmallTmpfs(const std::string &name, const std::string &size)
      : directory(wearlink::testing::fresh_directory(name) + "/disk")
    {
      fs::create_directories(directory);
      mounted = std::system(("mount -t tmpfs -o size=" + size + " tmpfs '" + directory + "' 2>/dev/null").c_str()) == 0;
    }
    ~SmallTmpfs()
    {
      if (mounted)
        {
          const int status = std::system(("umount -l '" + directory + "'").c_str());
          (void)status; // nothing to do about a mount that stays: the test has its result
        }
    }
    SmallTmpfs(const SmallTmpfs &) = delete;
    SmallTmpfs &
    operator=(const SmallTmpfs &) = delete;

    std::string directory;
    bool        mounted = false;
  };

  const char *const no_tmpfs = "cannot mount a tmpfs here (needs root with CAP_SYS_ADMIN); the file-size-limit "
                               "tests of this file cover the same writes";

  std::vector<std::string>
  contact_args(const std::string &out)
  {
    return {"contact",
            source_path("params/pin_bushing.prm"),
            "--output",
            out,
            "--set",
            "FE model/Surface element size=1e-4",
            "--set",
            "Loads/Load magnitudes=1000",
            "--set",
            "FE model/Solvers=condensed"};
  }

  std::vector<std::string>
  streaming_run_args(const std::string &out)
  {
    return {"run",
            source_path("params/nine_bar_clearance.prm"),
            "--output",
            out,
            "--quiet",
            "--set",
            "Simulation/End time=0.5",
            "--set",
            "Output/Time series interval=5e-9"};
  }

  /** An FE wear run of one short iteration on coarse meshes (a few seconds). */
  std::vector<std::string>
  fe_wear_args(const std::string &out)
  {
    std::vector<std::string> a = {"run", source_path("params/nine_bar_wear_fe.prm"), "--output", out, "--quiet"};
    for (const char *s : {"Wear/Number of iterations=1",
                          "Wear/Cycles per iteration=1",
                          "Wear/Response cycles=1",
                          "Wear/Cycle period=0.03",
                          "Joint A/Clearance/fe/Surface element size=2e-4",
                          "Joint B/Clearance/fe/Surface element size=2e-4",
                          "Joint A/Clearance/fe/Table load levels=4",
                          "Joint B/Clearance/fe/Table load levels=4",
                          "Output/Plots=false"})
      {
        a.push_back("--set");
        a.push_back(s);
      }
    return a;
  }

  /**
   * @p r stopped at a failed write: exit 4, a message that names a file and says to free
   * space, no abort and no internal error; @p out holds no temporary file and no lock.
   */
  void
  expect_stopped_cleanly(const ProgramResult &r, const std::string &out, const std::string &file)
  {
    EXPECT_EQ(r.exit_status, 4) << r.output;
    EXPECT_NE(r.output.find("Free some space"), std::string::npos) << r.output;
    if (!file.empty())
      {
        EXPECT_NE(r.output.find(file + "' failed"), std::string::npos) << "names " << file << ":\n" << r.output;
      }
    EXPECT_EQ(r.output.find("internal error"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("terminate called"), std::string::npos) << r.output;
    EXPECT_TRUE(wearlink::testing::partial_files_in(out).empty());
    EXPECT_FALSE(fs::exists(out + "/" + wearlink::OutputDirectory::lock_file_name));
  }

  double
  seconds_since(const std::chrono::steady_clock::time_point start)
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  /** 64 KiB: the mesh (~330 kB) and the time series do not fit, the lock file does. */
  constexpr std::size_t small_file = 64 * 1024;
} // namespace

TEST(FullDisk, ContactStopsWhenTheMeshCannotBeWritten)
{
  const SmallTmpfs disk("full_disk_contact", "64k");
  if (!disk.mounted)
    GTEST_SKIP() << no_tmpfs;
  const std::string out = disk.directory + "/c";
  const auto        r   = wearlink::testing::run_wearlink(contact_args(out));
  expect_stopped_cleanly(r, out, "pin_bushing.msh");
  EXPECT_FALSE(fs::exists(out + "/pin_bushing.msh")) << "no truncated mesh";
}

TEST(FullDisk, RunStopsAtTheFirstFailedWriteOfItsTimeSeries)
{
  const SmallTmpfs disk("full_disk_run", "64k");
  if (!disk.mounted)
    GTEST_SKIP() << no_tmpfs;
  const std::string out   = disk.directory + "/r";
  const auto        start = std::chrono::steady_clock::now();
  const auto        r     = wearlink::testing::run_wearlink(streaming_run_args(out));
  expect_stopped_cleanly(r, out, "time_series.csv");
  EXPECT_NE(r.output.find("No space left on device"), std::string::npos) << r.output;
  // 64 KiB of rows are a few milliseconds of simulated time; the whole 0.5 s took
  // minutes. 60 s leaves room for a loaded machine.
  EXPECT_LT(seconds_since(start), 60.0) << "stopped at the failed write, not at the end";
}

TEST(FullDisk, FeWearRunStopsCleanlyWhereverTheDiskFills)
{
  // The disk fills at different writes as it grows: the profiles, the copied mesh in
  // fe/, the VTU fields. Each must stop the run in the same clean way.
  for (const std::string size : {"400k", "640k", "1m"})
    {
      const SmallTmpfs disk("full_disk_fe_" + size, size);
      if (!disk.mounted)
        GTEST_SKIP() << no_tmpfs;
      const std::string out = disk.directory + "/w";
      SCOPED_TRACE("tmpfs of " + size);
      expect_stopped_cleanly(wearlink::testing::run_wearlink(fe_wear_args(out)), out, "");
    }
}

TEST(WriteFailure, ContactStopsWhenTheMeshCannotBeWritten)
{
  // `contact` starts MPI; Open MPI's PMIx keeps its store in shared-memory files, which
  // would fall under the limit too (MPI_Init aborts), while a full output disk leaves
  // them alone. In memory they are not files.
  ::setenv("PMIX_MCA_gds", "hash", 1);
  const std::string out = wearlink::testing::fresh_directory("write_failure_contact") + "/c";
  const auto        r   = wearlink::testing::run_wearlink_with_file_size_limit(small_file, contact_args(out));
  expect_stopped_cleanly(r, out, "pin_bushing.msh");
  EXPECT_FALSE(fs::exists(out + "/pin_bushing.msh")) << "no truncated mesh";
}

TEST(WriteFailure, RunStopsAtTheFirstFailedWriteOfItsTimeSeries)
{
  const std::string out   = wearlink::testing::fresh_directory("write_failure_run") + "/r";
  const auto        start = std::chrono::steady_clock::now();
  const auto        r     = wearlink::testing::run_wearlink_with_file_size_limit(small_file, streaming_run_args(out));
  expect_stopped_cleanly(r, out, "time_series.csv");
  EXPECT_NE(r.output.find("File too large"), std::string::npos) << r.output;
  EXPECT_LT(seconds_since(start), 60.0) << "stopped at the failed write, not at the end (see above)";
}

TEST(WriteFailure, FeWearRunStopsWhenItsMeshCannotBeWritten)
{
  // 200 kB: the profiles and the response fit; the meshes (~420 kB, written by gmsh into
  // the scratch folder) do not.
  const std::string out = wearlink::testing::fresh_directory("write_failure_fe") + "/w";
  const auto        r   = wearlink::testing::run_wearlink_with_file_size_limit(200 * 1024, fe_wear_args(out));
  expect_stopped_cleanly(r, out, ".msh");
  EXPECT_NE(r.output.find("Writing the mesh"), std::string::npos) << r.output;
}
