// SPDX-License-Identifier: LGPL-2.1-or-later
#include "base/atomic_file.h"

#include "base/exceptions.h"

#include <atomic>
#include <filesystem>
#include <system_error>
#include <unistd.h>

namespace wearlink
{
  std::string
  temporary_name_for(const std::string &path)
  {
    namespace fs          = std::filesystem;
    const fs::path    p   = path;
    const auto        tn  = "." + p.filename().string() + ".partial-" + std::to_string(::getpid());
    const std::string ext = p.extension().string();
    // Keep the extension last: gmsh and gnuplot choose their format from it.
    return (p.parent_path() / (tn + ext)).string();
  }

  AtomicFile::AtomicFile(std::string path)
    : final_path(std::move(path))
    , tmp_path(temporary_name_for(final_path))
    , out(tmp_path)
  {
    if (!out)
      throw IoError("Cannot write '" + final_path +
                    "': the directory does not exist or is not writable. Check its permissions, or "
                    "choose another --output directory.");
  }

  AtomicFile::~AtomicFile()
  {
    if (!committed)
      {
        out.close();
        std::error_code ec;
        std::filesystem::remove(tmp_path, ec);
      }
  }

  void
  AtomicFile::commit()
  {
    out.flush();
    const bool ok = static_cast<bool>(out);
    out.close();
    if (!ok)
      throw IoError("Writing '" + final_path +
                    "' failed (disk full?). Free some space or choose another --output directory.");
    commit_external_file(tmp_path, final_path);
    committed = true;
  }

  void
  write_file_atomically(const std::string &path, const std::string &content)
  {
    AtomicFile f(path);
    f.stream() << content;
    f.commit();
  }

  void
  commit_external_file(const std::string &tmp, const std::string &path)
  {
    std::error_code ec;
    if (!std::filesystem::exists(tmp, ec))
      throw InputError("Writing '" + path + "' failed: the writer produced no file.");
    std::filesystem::rename(tmp, path, ec);
    if (ec)
      {
        const std::string why = ec.message();
        std::filesystem::remove(tmp, ec);
        throw IoError("Cannot move the finished file into place at '" + path + "': " + why +
                      ". Check the permissions of that directory.");
      }
  }

  void
  make_output_directory(const std::string &dir)
  {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec || !std::filesystem::is_directory(dir))
      throw IoError("Cannot create the output directory '" + dir + "': " + ec.message() +
                    ". Choose another --output directory.");
  }
  TemporaryDirectory::TemporaryDirectory(const std::string &what)
  {
    static std::atomic<unsigned long> counter{0};
    namespace fs = std::filesystem;
    directory    = (fs::temp_directory_path() /
                 ("wearlink-" + what + "-" + std::to_string(::getpid()) + "-" + std::to_string(counter++)))
                  .string();
    make_output_directory(directory);
  }

  TemporaryDirectory::~TemporaryDirectory()
  {
    std::error_code ignored;
    std::filesystem::remove_all(directory, ignored);
  }

} // namespace wearlink
