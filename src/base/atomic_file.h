// SPDX-License-Identifier: LGPL-2.1-or-later
// Outputs are never half-written: every file wearlink writes goes to a temporary name
// in the same directory and is renamed into place only when complete (rename is atomic
// on POSIX file systems). A writer destroyed without commit() removes its temporary.
// Before the rename the file's data is flushed to the disk (fsync), after it the
// directory's entry, so that a machine that loses power keeps the old file or the new
// one, never an empty one. A failed write, close or fsync (disk full, quota, I/O error)
// is an IoError naming the file; the previous file of that name is left as it was.
// Temporary names are ".<name>.partial-<pid><ext>". After SIGINT or SIGTERM nothing new
// is moved into place (commit() removes its temporary and throws Interrupted); the
// handler of a second signal removes the temporaries at once (base/interrupt.h), and
// remove_stale_partials() removes those of a run that was killed outright.
#pragma once

#include "base/interrupt.h"

#include <fstream>
#include <string>
#include <vector>

namespace wearlink
{
  class AtomicFile
  {
  public:
    /** Open a temporary file next to @p path (the directory must exist). */
    explicit AtomicFile(std::string path);
    ~AtomicFile();
    AtomicFile(const AtomicFile &) = delete;
    AtomicFile &
    operator=(const AtomicFile &) = delete;

    std::ostream &
    stream()
    {
      return out;
    }

    /**
     * Flush, check for write errors, fsync, rename into place, fsync the directory.
     * IoError naming the file if any step fails (the temporary is removed).
     */
    void
    commit();

    /**
     * IoError naming the file (its temporary removed) if a write to stream() has failed
     * so far (disk full, quota, I/O error). A writer that streams over a long computation
     * calls it after each record, so that the command stops at the first failed write
     * instead of computing on into a file that can no longer be written.
     */
    void
    throw_if_failed();

    /** The temporary file's name (for writers that need a path, e.g. gmsh, gnuplot). */
    const std::string &
    temporary_path() const
    {
      return tmp_path;
    }

  private:
    std::string         final_path;
    std::string         tmp_path;
    RegisteredTemporary registration;
    std::ofstream       out;
    bool                committed = false;
  };

  /** Write @p content to @p path atomically. */
  void
  write_file_atomically(const std::string &path, const std::string &content);

  /**
   * Rename @p tmp (written by a third-party writer) to @p path, or remove it and throw
   * if @p tmp does not exist. After SIGINT or SIGTERM nothing is moved into place (the
   * writer may have been stopped by the same signal): @p tmp is removed and Interrupted
   * thrown.
   */
  void
  commit_external_file(const std::string &tmp, const std::string &path);

  /**
   * Copy the file @p from to @p to atomically (through a temporary next to @p to, as
   * commit_external_file()). IoError naming @p to if the copy fails (disk full, a file
   * that cannot be read); no partial copy is left.
   */
  void
  copy_file_atomically(const std::string &from, const std::string &to);

  /** A temporary name next to @p path, unique to this process. */
  std::string
  temporary_name_for(const std::string &path);

  /** True if @p file_name (no directory) is a temporary name of temporary_name_for(). */
  bool
  is_temporary_name(const std::string &file_name);

  /**
   * Remove the temporary files in @p dir and its sub-directories (one level down) whose
   * writing process no longer runs (a run killed with SIGKILL, or by a power cut);
   * those of running processes are kept. Returns the paths removed.
   */
  std::vector<std::string>
  remove_stale_partials(const std::string &dir);

  /**
   * Remove the scratch directories "wearlink-<what>-<pid>-<n>" under @p parent whose
   * process no longer runs (killed outright, or by a second signal, which leaves at
   * once); those of running processes are kept. Returns the paths removed.
   */
  std::vector<std::string>
  remove_stale_temporary_directories(const std::string &parent);

  /**
   * A new directory under the system's temporary directory, named
   * "wearlink-<what>-<pid>-<n>" (n counts within the process), removed with everything in
   * it when the object goes: scratch space for meshes and plot scripts. The first one of
   * a process removes the stale ones of processes that were killed
   * (remove_stale_temporary_directories()).
   */
  class TemporaryDirectory
  {
  public:
    explicit TemporaryDirectory(const std::string &what);
    ~TemporaryDirectory();
    TemporaryDirectory(const TemporaryDirectory &) = delete;
    TemporaryDirectory &
    operator=(const TemporaryDirectory &) = delete;

    const std::string &
    path() const
    {
      return directory;
    }

  private:
    std::string directory;
  };

  /** Create @p dir (and parents); an InputError if that is impossible. */
  void
  make_output_directory(const std::string &dir);
} // namespace wearlink
