// SPDX-License-Identifier: LGPL-2.1-or-later
#include "base/atomic_file.h"

#include "base/exceptions.h"

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <system_error>
#include <unistd.h>

namespace wearlink
{
  namespace
  {
    constexpr const char *partial_marker = ".partial-";

    /** The system's reason for the last failure, or @p fallback if errno says nothing. */
    std::string
    reason(const int error, const std::string &fallback)
    {
      return error != 0 ? std::string(std::strerror(error)) : fallback;
    }

    /** fsync @p path (a file or a directory); IoError naming @p what on failure. */
    void
    sync_to_disk(const std::string &path, const std::string &what, const bool directory)
    {
      const int fd = ::open(path.c_str(), O_RDONLY | (directory ? O_DIRECTORY : 0));
      if (fd < 0)
        {
          if (directory)
            return; // a directory we may not open: its entry reaches the disk later
          throw IoError("Writing '" + what + "' failed: cannot reopen it to flush it to the disk (" +
                        reason(errno, "unknown reason") + ").");
        }
      const int status = ::fsync(fd);
      const int error  = errno;
      ::close(fd);
      // EINVAL: the file system has no fsync for this kind of file (nothing to wait for).
      if (status != 0 && error != EINVAL)
        throw IoError("Writing '" + what + "' failed while flushing it to the disk: " + reason(error, "fsync failed") +
                      ". Free some space (or check the disk) and run again.");
    }

    std::string
    directory_of(const std::string &path)
    {
      const std::string parent = std::filesystem::path(path).parent_path().string();
      return parent.empty() ? "." : parent;
    }

    /** The writer's pid in a temporary name, or 0. */
    long
    writer_pid(const std::string &file_name)
    {
      const auto at = file_name.find(partial_marker);
      if (file_name.empty() || file_name[0] != '.' || at == std::string::npos)
        return 0;
      long        pid = 0;
      std::size_t k   = at + std::strlen(partial_marker);
      for (; k < file_name.size() && std::isdigit(static_cast<unsigned char>(file_name[k])); ++k)
        pid = 10 * pid + (file_name[k] - '0');
      return pid > 0 && pid < (1L << 31) ? pid : 0;
    }

    bool
    process_runs(const long pid)
    {
      return ::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM;
    }
  } // namespace

  std::string
  temporary_name_for(const std::string &path)
  {
    namespace fs          = std::filesystem;
    const fs::path    p   = path;
    const auto        tn  = "." + p.filename().string() + partial_marker + std::to_string(::getpid());
    const std::string ext = p.extension().string();
    // Keep the extension last: gmsh and gnuplot choose their format from it.
    return (p.parent_path() / (tn + ext)).string();
  }

  bool
  is_temporary_name(const std::string &file_name)
  {
    return writer_pid(file_name) != 0;
  }

  AtomicFile::AtomicFile(std::string path)
    : final_path(std::move(path))
    , tmp_path(temporary_name_for(final_path))
    , registration(tmp_path)
  {
    errno = 0;
    out.open(tmp_path);
    if (!out)
      throw IoError("Cannot write '" + final_path +
                    "': " + reason(errno, "the directory does not exist or is not writable") +
                    ". Check its permissions, or choose another --output directory.");
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

  namespace
  {
    /** The IoError of a failed write of @p path, for the system's @p error (0: unknown). */
    IoError
    write_failure(const std::string &path, const int error)
    {
      return IoError("Writing '" + path + "' failed: " + reason(error, "the data could not be written") +
                     ". Free some space (or check the disk) and run again; the previous file of that name, if "
                     "any, is unchanged.");
    }
  } // namespace

  void
  AtomicFile::commit()
  {
    errno = 0;
    out.flush();
    const bool written = static_cast<bool>(out);
    int        error   = errno;
    out.close();
    if (written && out.fail())
      error = errno;
    if (!written || out.fail())
      {
        std::error_code ec;
        std::filesystem::remove(tmp_path, ec);
        throw write_failure(final_path, error);
      }
    commit_external_file(tmp_path, final_path);
    committed = true;
  }

  void
  AtomicFile::throw_if_failed()
  {
    if (out)
      return;
    // The failed write(2) set errno; formatting into the stream's buffer since then
    // made no system call that would have changed it.
    const int error = errno;
    out.close();
    std::error_code ec;
    std::filesystem::remove(tmp_path, ec);
    committed = true; // nothing left to remove
    throw write_failure(final_path, error);
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
    if (interrupt_signal() != 0)
      {
        std::filesystem::remove(tmp, ec);
        throw_if_interrupted();
      }
    if (!std::filesystem::exists(tmp, ec))
      throw InputError("Writing '" + path + "' failed: the writer produced no file.");
    try
      {
        sync_to_disk(tmp, path, false);
      }
    catch (const IoError &)
      {
        std::filesystem::remove(tmp, ec);
        throw;
      }
    std::filesystem::rename(tmp, path, ec);
    if (ec)
      {
        const std::string why = ec.message();
        std::filesystem::remove(tmp, ec);
        throw IoError("Cannot move the finished file into place at '" + path + "': " + why +
                      ". Check the permissions of that directory.");
      }
    sync_to_disk(directory_of(path), path, true);
  }

  void
  copy_file_atomically(const std::string &from, const std::string &to)
  {
    const std::string   tmp = temporary_name_for(to);
    RegisteredTemporary registration(tmp);
    std::error_code     ec;
    std::filesystem::copy_file(from, tmp, std::filesystem::copy_options::overwrite_existing, ec);
    if (ec)
      {
        const int error = ec.value();
        std::filesystem::remove(tmp, ec);
        throw write_failure(to, error);
      }
    commit_external_file(tmp, to);
  }

  std::vector<std::string>
  remove_stale_partials(const std::string &dir)
  {
    namespace fs = std::filesystem;
    std::vector<std::string> removed;
    std::error_code          ec;
    std::vector<fs::path>    folders = {dir};
    for (const auto &e : fs::directory_iterator(dir, ec))
      if (e.is_directory(ec) && !e.is_symlink(ec))
        folders.push_back(e.path());
    for (const auto &folder : folders)
      for (const auto &e : fs::directory_iterator(folder, ec))
        {
          const long pid = writer_pid(e.path().filename().string());
          if (pid != 0 && e.is_regular_file(ec) && !process_runs(pid) && fs::remove(e.path(), ec))
            removed.push_back(e.path().string());
        }
    return removed;
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
  std::vector<std::string>
  remove_stale_temporary_directories(const std::string &parent)
  {
    namespace fs = std::filesystem;
    std::vector<std::string> removed;
    std::error_code          ec;
    for (const auto &e : fs::directory_iterator(parent, ec))
      {
        // "wearlink-<what>-<pid>-<n>": the pid is the next-to-last field.
        const std::string name = e.path().filename().string();
        const auto        last = name.rfind('-');
        const auto        pid0 = last == std::string::npos || last == 0 ? std::string::npos : name.rfind('-', last - 1);
        if (name.rfind("wearlink-", 0) != 0 || pid0 == std::string::npos || pid0 + 1 >= last)
          continue;
        const std::string digits = name.substr(pid0 + 1, last - pid0 - 1);
        if (digits.size() > 9 || !std::all_of(digits.begin(), digits.end(), [](const char c) {
              return std::isdigit(static_cast<unsigned char>(c)) != 0;
            }))
          continue;
        const long pid = std::stol(digits);
        if (pid > 0 && e.is_directory(ec) && !e.is_symlink(ec) && !process_runs(pid) &&
            fs::remove_all(e.path(), ec) > 0)
          removed.push_back(e.path().string());
      }
    return removed;
  }

  TemporaryDirectory::TemporaryDirectory(const std::string &what)
  {
    static std::atomic<unsigned long> counter{0};
    namespace fs = std::filesystem;
    if (counter == 0)
      {
        std::error_code ec;
        remove_stale_temporary_directories(fs::temp_directory_path(ec).string());
      }
    directory = (fs::temp_directory_path() /
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
