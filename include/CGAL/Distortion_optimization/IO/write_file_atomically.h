// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The atomic writer every IO header uses, and which programs may use for their own files (the
// command-line tool writes its JSON report with it): a unique temporary file beside the target
// (never a name a user's file may have), renamed over it only when everything was written, and
// removed on every failure, also when the program is interrupted (remove_temporary_files_on_signals).

#ifndef CGAL_DISTORTION_OPTIMIZATION_IO_WRITE_FILE_ATOMICALLY_H
#define CGAL_DISTORTION_OPTIMIZATION_IO_WRITE_FILE_ATOMICALLY_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/IO/internal/line_reader.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <charconv>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <locale>
#include <ostream>
#include <string>

#include <sys/stat.h>
#include <unistd.h>

namespace CGAL {
namespace Distortion_optimization {
namespace IO {
namespace internal {

// The temporary files in flight, in fixed storage that a signal handler may read: unlink() is
// async-signal-safe, and a slot is published (flag set) only once its name is complete.
struct Temporary_registry
{
  static constexpr std::size_t slots = 16, length = 4096;
  std::array<std::array<char, length>, slots> names{};
  std::array<std::atomic<bool>, slots> used{};

  static Temporary_registry& get()
  {
    static Temporary_registry registry;
    return registry;
  }
  int add(const std::string& name)
  {
    if(name.size() >= length) return -1;
    for(std::size_t i = 0; i < slots; ++i) {
      bool expected = false;
      if(used[i].load() || !used[i].compare_exchange_strong(expected, true)) continue;
      used[i] = false;   // unpublished while the name is written
      std::memcpy(names[i].data(), name.c_str(), name.size() + 1);
      used[i] = true;
      return static_cast<int>(i);
    }
    return -1;   // full: the file is still removed on failures, only not on signals
  }
  void remove(int slot)
  {
    if(slot >= 0) used[static_cast<std::size_t>(slot)] = false;
  }
  void unlink_all()   // from a signal handler
  {
    for(std::size_t i = 0; i < slots; ++i)
      if(used[i].load()) ::unlink(names[i].data());
  }
};

inline void unlink_temporaries_and_reraise(int signal)
{
  Temporary_registry::get().unlink_all();
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

} // namespace internal

/// \ingroup PkgDistortionOptimizationIO
/// A new, empty file with a unique name beside `path` (in its folder, hidden, ending in `suffix`),
/// removed when this object is destroyed unless it was renamed; while it exists it is also
/// removed if the program is interrupted after `remove_temporary_files_on_signals()`. A program
/// writes there and renames the file to `path` once everything was written. Where `path` is a
/// symbolic link, the file it names is replaced and the link kept; where it is a device or a pipe
/// (`/dev/null`, `/dev/stdout`), the temporary file is made in the temporary folder (`TMPDIR`,
/// else `/tmp`) and its bytes are written into `path` at the end, which is never replaced.
class Temporary_file
{
public:
  /// \throws Invalid_input if the folder of `path` does not exist or is not writable, if `path`
  /// is a folder, or a symbolic link to nothing.
  explicit Temporary_file(const std::string& path, const std::string& suffix = "")
  {
    bool special = false;
    const std::string place = destination(path, &special);
    const std::size_t slash = place.find_last_of('/');
    std::string folder = slash == std::string::npos ? "" : place.substr(0, slash + 1);
    const std::string base = slash == std::string::npos ? place : place.substr(slash + 1);
    if(base.empty()) throw Invalid_input(internal::printable(path) + ": not a file name");
    if(special) {
      const char* tmp = std::getenv("TMPDIR");
      folder = std::string(tmp != nullptr && *tmp != 0 ? tmp : "/tmp") + "/";
    }
    std::string name = folder + "." + base + ".XXXXXX" + suffix;
    const int fd = ::mkstemps(&name[0], static_cast<int>(suffix.size()));
    if(fd < 0) throw Invalid_input(internal::printable(path) + ": cannot write (does the folder exist, and is it writable?)");
    streamed_ = special;
    // mkstemp makes the file private (0600); give it the mode a new file of the user would have.
    const mode_t mask = ::umask(0);
    ::umask(mask);
    ::fchmod(fd, 0666 & ~mask);
    ::close(fd);
    path_ = name;
    slot_ = internal::Temporary_registry::get().add(path_);
  }
  Temporary_file(const Temporary_file&) = delete;
  Temporary_file& operator=(const Temporary_file&) = delete;
  ~Temporary_file()
  {
    internal::Temporary_registry::get().remove(slot_);
    if(!kept_) ::unlink(path_.c_str());
  }

  const std::string& path() const { return path_; }
  /// Whether the bytes go into a device or a pipe at `rename_to()` (a write that may fail, such as
  /// `/dev/full`) rather than by renaming the file.
  bool is_streamed() const { return streamed_; }
  /// Renames the file to `target` (the file a symbolic link names; into a device or a pipe, its
  /// bytes are written), after which it is no longer temporary.
  /// \throws Invalid_input if the rename or the write fails (the temporary file is then removed).
  void rename_to(const std::string& target)
  {
    bool special = false;
    const std::string place = destination(target, &special);
    if(special) {
      {
        std::ifstream in(path_, std::ios::binary);
        std::ofstream out(place, std::ios::binary);
        if(!in || !out || !(out << in.rdbuf()) || !out.flush()) throw Invalid_input(internal::printable(target) + ": write error");
      }
      return;   // the temporary file is removed by the destructor
    }
    if(std::rename(path_.c_str(), place.c_str()) != 0) throw Invalid_input(internal::printable(target) + ": cannot replace the file");
    internal::Temporary_registry::get().remove(slot_);
    slot_ = -1;
    kept_ = true;
  }

private:
  // Where the bytes for `path` go: the file a symbolic link names, and whether that is a device
  // or a pipe rather than a file to replace.
  static std::string destination(const std::string& path, bool* special)
  {
    struct stat s;
    *special = false;
    if(::lstat(path.c_str(), &s) != 0) return path;   // a new file
    const bool link = S_ISLNK(s.st_mode);
    if(link && ::stat(path.c_str(), &s) != 0) throw Invalid_input(internal::printable(path) + ": a symbolic link to nothing");
    if(S_ISDIR(s.st_mode)) throw Invalid_input(internal::printable(path) + ": a folder, not a file name");
    *special = !S_ISREG(s.st_mode);
    if(!link || *special) return path;   // a device is written through its name (/dev/stdout too)
    char* resolved = ::realpath(path.c_str(), nullptr);
    if(resolved == nullptr) throw Invalid_input(internal::printable(path) + ": cannot resolve the symbolic link");
    const std::string place = resolved;
    std::free(resolved);
    return place;
  }

  std::string path_;
  int slot_ = -1;
  bool kept_ = false, streamed_ = false;
};

/// \ingroup PkgDistortionOptimizationIO
/// Installs handlers of SIGINT, SIGTERM, SIGHUP and SIGPIPE that remove the temporary files being written
/// (`Temporary_file`, `write_file_atomically()`) and then end the program as the signal would
/// have. For programs; a library does not install signal handlers.
inline void remove_temporary_files_on_signals()
{
  internal::Temporary_registry::get();   // constructed before any handler may run
  for(int signal : {SIGINT, SIGTERM, SIGHUP, SIGPIPE}) std::signal(signal, internal::unlink_temporaries_and_reraise);
}

namespace internal {

// Formats each double inserted into a stream as the shortest decimal that reads back to the
// same value (std::to_chars): several times faster than the 17 significant digits of printf-style
// formatting, and shorter. Stream precision and flags do not apply.
class Shortest_double_put : public std::num_put<char>
{
protected:
  iter_type do_put(iter_type out, std::ios_base&, char, double x) const override
  {
    char buffer[32];
    const char* end = std::to_chars(buffer, buffer + sizeof buffer, x).ptr;
    return std::copy(static_cast<const char*>(buffer), end, out);
  }
};

} // namespace internal

/// \ingroup PkgDistortionOptimizationIO
/// Writes a file whole or not at all: `write(stream)` fills a `Temporary_file` beside `path`,
/// which is renamed to `path` only when everything was written. No other file is touched. The
/// stream writes each `double` as the shortest decimal that reads back to the same value.
/// \throws Invalid_input if the file cannot be written (the temporary file is removed).
inline void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write)
{
  Temporary_file temporary(path);
  {
    std::ofstream out(temporary.path(), std::ios::binary | std::ios::trunc);
    if(!out) throw Invalid_input(internal::printable(path) + ": cannot write (is the folder writable?)");
    out.imbue(std::locale(std::locale::classic(), new internal::Shortest_double_put));
    write(out);
    out.flush();
    if(!out) throw Invalid_input(internal::printable(path) + ": write error");
  }
  temporary.rename_to(path);
}

} // namespace IO
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_IO_WRITE_FILE_ATOMICALLY_H
