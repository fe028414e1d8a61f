// SPDX-License-Identifier: LGPL-2.1-or-later
#include "base/output_directory.h"

#include "base/atomic_file.h"
#include "base/exceptions.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fnmatch.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

namespace wearlink
{
  namespace
  {
    namespace fs = std::filesystem;

    bool
    matches(const std::string &name, const RunFiles &files)
    {
      return std::any_of(files.patterns.begin(), files.patterns.end(), [&](const std::string &p) {
        return ::fnmatch(p.c_str(), name.c_str(), 0) == 0;
      });
    }

    /** The pid written into the lock file by its holder ("unknown" while it writes it). */
    std::string
    holder_of(const int fd)
    {
      char          text[32] = {0};
      const ssize_t n        = ::pread(fd, text, sizeof(text) - 1, 0);
      std::string   pid;
      for (ssize_t k = 0; k < n && std::isdigit(static_cast<unsigned char>(text[k])); ++k)
        pid += text[k];
      return pid.empty() ? "unknown" : pid;
    }

    /** Whether @p fd is still the file at @p path (a releasing holder removes it). */
    bool
    same_file(const int fd, const std::string &path)
    {
      struct stat open_file, named_file;
      return ::fstat(fd, &open_file) == 0 && ::stat(path.c_str(), &named_file) == 0 &&
             open_file.st_ino == named_file.st_ino && open_file.st_dev == named_file.st_dev;
    }
  } // namespace

  std::vector<std::string>
  files_of_earlier_run(const std::string &dir, const RunFiles &files)
  {
    std::vector<std::string> out;
    std::error_code          ec;
    for (const auto &e : fs::directory_iterator(dir, ec))
      if (e.is_regular_file(ec) && matches(e.path().filename().string(), files))
        out.push_back(e.path().string());
    for (const auto &sub : files.subdirectories)
      {
        const fs::path folder = fs::path(dir) / sub;
        if (!fs::is_directory(folder, ec) || fs::is_symlink(folder, ec))
          continue;
        for (const auto &e : fs::recursive_directory_iterator(folder, ec))
          if (e.is_regular_file(ec) && matches(e.path().filename().string(), files))
            out.push_back(e.path().string());
      }
    std::sort(out.begin(), out.end());
    return out;
  }

  OutputDirectory::OutputDirectory(const std::string &dir,
                                   const EarlierRun   earlier,
                                   const RunFiles    &files,
                                   const std::string &advice)
    : directory(dir)
    , lock_path((fs::path(dir) / lock_file_name).string())
  {
    std::error_code ec;
    created = !fs::exists(dir, ec);
    make_output_directory(dir);
    lock();
    try
      {
        partials                = remove_stale_partials(dir);
        const auto earlier_runs = files_of_earlier_run(dir, files);
        if (earlier_runs.empty() || earlier == EarlierRun::resume)
          return;
        if (earlier == EarlierRun::refuse)
          {
            std::string names;
            for (std::size_t k = 0; k < earlier_runs.size() && k < 4; ++k)
              names += (k > 0 ? ", " : "") + fs::relative(earlier_runs[k], dir).string();
            if (earlier_runs.size() > 4)
              names += ", … (" + std::to_string(earlier_runs.size()) + " files)";
            throw InputError("The output directory '" + dir + "' holds the files of an earlier run (" + names + "). " +
                             advice);
          }
        remove_earlier_run(earlier_runs, files);
      }
    catch (...)
      {
        release();
        throw;
      }
  }

  void
  OutputDirectory::remove_earlier_run(const std::vector<std::string> &earlier_runs, const RunFiles &files)
  {
    std::error_code ec;
    for (const auto &f : earlier_runs)
      if (fs::remove(f, ec))
        removed.push_back(f);
    // The run's sub-directories, deepest first, where they are now empty.
    for (const auto &sub : files.subdirectories)
      {
        const fs::path        top = fs::path(directory) / sub;
        std::vector<fs::path> folders;
        if (fs::is_directory(top, ec) && !fs::is_symlink(top, ec))
          for (const auto &e : fs::recursive_directory_iterator(top, ec))
            if (e.is_directory(ec))
              folders.push_back(e.path());
        std::sort(folders.begin(), folders.end(), [](const fs::path &a, const fs::path &b) {
          return a.string().size() > b.string().size();
        });
        folders.push_back(top);
        for (const auto &f : folders)
          if (fs::is_directory(f, ec) && fs::is_empty(f, ec))
            fs::remove(f, ec);
      }
  }

  void
  OutputDirectory::lock()
  {
    for (int attempt = 0; attempt < 10; ++attempt)
      {
        fd = ::open(lock_path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
        if (fd < 0 && errno == ENOENT) // an empty directory removed by its releasing holder
          {
            make_output_directory(directory);
            continue;
          }
        if (fd < 0)
          throw IoError("Cannot create the lock file '" + lock_path + "': " + std::strerror(errno) +
                        ". Choose another --output directory.");
        if (::flock(fd, LOCK_EX | LOCK_NB) != 0)
          {
            const int         error  = errno;
            const std::string holder = holder_of(fd);
            ::close(fd);
            fd = -1;
            if (error == EWOULDBLOCK)
              throw InputError("The output directory '" + directory + "' is in use by another wearlink run (pid " +
                               holder + "; lock file " + lock_path +
                               "). Wait until it has finished (or stop it), or choose another --output directory.");
            throw IoError("Cannot lock the output directory '" + directory + "' (" + lock_path +
                          "): " + std::strerror(error) + ".");
          }
        if (same_file(fd, lock_path))
          {
            const std::string pid = std::to_string(::getpid()) + "\n";
            if (::ftruncate(fd, 0) != 0 || ::pwrite(fd, pid.data(), pid.size(), 0) != static_cast<ssize_t>(pid.size()))
              throw IoError("Cannot write the lock file '" + lock_path + "': " + std::strerror(errno) + ".");
            return;
          }
        ::close(fd); // the holder removed it as we opened it: lock the new one
        fd = -1;
      }
    throw IoError("Cannot lock the output directory '" + directory + "': its lock file keeps changing.");
  }

  void
  OutputDirectory::release()
  {
    if (fd < 0)
      return;
    if (same_file(fd, lock_path))
      ::unlink(lock_path.c_str());
    ::close(fd);
    fd = -1;
    std::error_code ec;
    if (created && fs::is_empty(directory, ec))
      fs::remove(directory, ec);
  }

  OutputDirectory::~OutputDirectory()
  {
    release();
  }
} // namespace wearlink
