// SPDX-License-Identifier: LGPL-2.1-or-later
// The output directory of a run, held while the run lasts:
//  - an advisory lock (flock on DIR/.wearlink.lock, which holds the holder's pid): a
//    second run into the same directory is refused with the first one's pid, instead of
//    both writing the same files;
//  - the temporary files of a run that was killed outright (SIGKILL, power cut) are
//    removed (base/atomic_file.h);
//  - the files of an earlier run are refused, replaced or kept (EarlierRun), so that a
//    run never silently mixes its files with another's. Only the file names a run
//    writes (glob patterns given by the caller) are ever removed, never other files.
// The lock file is removed when the directory is released (after the lock is
// released a new holder checks that it locked the file that is still there), and so is
// the directory itself if it was created by this claim and is left empty (a command
// refused for bad input leaves no trace).
#pragma once

#include <string>
#include <vector>

namespace wearlink
{
  /** What to do with the files of an earlier run found in the directory. */
  enum class EarlierRun
  {
    refuse,    ///< InputError naming the files and @p advice
    overwrite, ///< remove them first
    resume     ///< keep them (the run continues the earlier one)
  };

  /** The file names a run writes, and the sub-directories it writes them into. */
  struct RunFiles
  {
    std::vector<std::string> patterns;       ///< glob patterns of file names (fnmatch)
    std::vector<std::string> subdirectories; ///< cleared of those patterns recursively
  };

  class OutputDirectory
  {
  public:
    /**
     * Create @p dir if needed, lock it, remove stale temporaries, then apply @p earlier.
     * InputError if another process holds the lock (naming its pid) or if the directory
     * holds an earlier run's files and @p earlier is refuse (the message ends with
     * @p advice, e.g. which option to add).
     */
    OutputDirectory(const std::string &dir, EarlierRun earlier, const RunFiles &files, const std::string &advice);
    ~OutputDirectory();
    OutputDirectory(const OutputDirectory &) = delete;
    OutputDirectory &
    operator=(const OutputDirectory &) = delete;

    /** Temporary files of killed runs that were removed. */
    const std::vector<std::string> &
    removed_partials() const
    {
      return partials;
    }

    /** Files of the earlier run removed (EarlierRun::overwrite). */
    const std::vector<std::string> &
    removed_files() const
    {
      return removed;
    }

    /** The name of the lock file inside a run's directory. */
    static constexpr const char *lock_file_name = ".wearlink.lock";

  private:
    void
    lock();
    void
    release();
    void
    remove_earlier_run(const std::vector<std::string> &earlier_runs, const RunFiles &files);

    std::string              directory;
    std::string              lock_path;
    int                      fd      = -1;
    bool                     created = false; ///< the directory did not exist before
    std::vector<std::string> partials, removed;
  };

  /** The files of @p dir (top level, and the sub-directories of @p files) that match. */
  std::vector<std::string>
  files_of_earlier_run(const std::string &dir, const RunFiles &files);
} // namespace wearlink
