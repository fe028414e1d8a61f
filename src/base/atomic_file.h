// SPDX-License-Identifier: LGPL-2.1-or-later
// Outputs are never half-written: every file wearlink writes goes to a temporary name
// in the same directory and is renamed into place only when complete (rename is atomic
// on POSIX file systems). A writer destroyed without commit() removes its temporary.
#pragma once

#include <fstream>
#include <string>

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

    /** Flush, check for write errors, rename into place. */
    void
    commit();

    /** The temporary file's name (for writers that need a path, e.g. gmsh, gnuplot). */
    const std::string &
    temporary_path() const
    {
      return tmp_path;
    }

  private:
    std::string   final_path;
    std::string   tmp_path;
    std::ofstream out;
    bool          committed = false;
  };

  /** Write @p content to @p path atomically. */
  void
  write_file_atomically(const std::string &path, const std::string &content);

  /**
   * Rename @p tmp (written by a third-party writer) to @p path, or remove it and throw
   * if @p tmp does not exist.
   */
  void
  commit_external_file(const std::string &tmp, const std::string &path);

  /** A temporary name next to @p path, unique to this process. */
  std::string
  temporary_name_for(const std::string &path);

  /**
   * A new directory under the system's temporary directory, named
   * "wearlink-<what>-<pid>-<n>" (n counts within the process), removed with everything in
   * it when the object goes: scratch space for meshes and plot scripts.
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
