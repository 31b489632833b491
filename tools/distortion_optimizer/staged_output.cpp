// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The tool's staged outputs (staged_output.h): POSIX files and signals.

#include "staged_output.h"

#include "command_line.h"

#include <CGAL/Distortion_optimization/IO/write_file_atomically.h>
#include <CGAL/Distortion_optimization/errors.h>

#include <array>
#include <atomic>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>

#include <sys/stat.h>
#include <unistd.h>

namespace distortion_optimizer {

namespace {

using CGAL::Distortion_optimization::Invalid_input;

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

void unlink_temporaries_and_reraise(int signal)
{
  Temporary_registry::get().unlink_all();
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

// Where the bytes for `path` go: the file a symbolic link names, and whether that is a device or a
// pipe rather than a file to replace; the library's writers decide it the same way.
std::string destination(const std::string& path, bool* special)
{
  return CGAL::Distortion_optimization::IO::internal::destination(path, *special).string();
}

} // namespace

Temporary_file::Temporary_file(const std::string& path, const std::string& suffix)
{
  bool special = false;
  const std::string place = destination(path, &special);
  const std::size_t slash = place.find_last_of('/');
  std::string folder = slash == std::string::npos ? "" : place.substr(0, slash + 1);
  const std::string base = slash == std::string::npos ? place : place.substr(slash + 1);
  if(base.empty()) throw Invalid_input(printable(path) + ": not a file name");
  if(special) {
    const char* tmp = std::getenv("TMPDIR");
    folder = std::string(tmp != nullptr && *tmp != 0 ? tmp : "/tmp") + "/";
  }
  std::string name = folder + "." + base + ".XXXXXX" + suffix;
  const int fd = ::mkstemps(&name[0], static_cast<int>(suffix.size()));
  if(fd < 0) throw Invalid_input(printable(path) + ": cannot write (does the folder exist, and is it writable?)");
  streamed_ = special;
  // mkstemp makes the file private (0600); give it the mode a new file of the user would have.
  const mode_t mask = ::umask(0);
  ::umask(mask);
  ::fchmod(fd, 0666 & ~mask);
  ::close(fd);
  path_ = name;
  slot_ = Temporary_registry::get().add(path_);
}

Temporary_file::~Temporary_file()
{
  Temporary_registry::get().remove(slot_);
  if(!kept_) ::unlink(path_.c_str());
}

void Temporary_file::rename_to(const std::string& target)
{
  bool special = false;
  const std::string place = destination(target, &special);
  if(special) {
    {
      std::ifstream in(path_, std::ios::binary);
      std::ofstream out(place, std::ios::binary);
      if(!in || !out || !(out << in.rdbuf()) || !out.flush()) throw Invalid_input(printable(target) + ": write error");
    }
    return;   // the temporary file is removed by the destructor
  }
  if(std::rename(path_.c_str(), place.c_str()) != 0) throw Invalid_input(printable(target) + ": cannot replace the file");
  Temporary_registry::get().remove(slot_);
  slot_ = -1;
  kept_ = true;
}

void remove_temporary_files_on_signals()
{
  Temporary_registry::get();   // constructed before any handler may run
  for(int signal : {SIGINT, SIGTERM, SIGHUP}) std::signal(signal, unlink_temporaries_and_reraise);
  // A closed standard output (`... | head`) must not kill the tool after its files are written:
  // writes to it fail instead, and the exit status is the run's.
  std::signal(SIGPIPE, SIG_IGN);
}

} // namespace distortion_optimizer
