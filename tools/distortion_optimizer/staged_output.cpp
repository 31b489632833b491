// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The tool's staged outputs (staged_output.h): POSIX files and signals.

#include "staged_output.h"

#include "command_line.h"

#include <CGAL/Distortion_optimization/IO/write_file_atomically.h>
#include <CGAL/Distortion_optimization/errors.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>

#include <random>

#include <cerrno>
#include <fcntl.h>
#include <sys/stat.h>
#include <sys/time.h>
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
  return CGAL::Distortion_optimization::IO::write_destination(path, *special).string();
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
  // Only named here, so that no file exists before the run writes it (a run killed earlier leaves
  // nothing); the folder is checked now, so that an output that cannot be written fails first.
  if(::access(folder.empty() ? "." : folder.c_str(), W_OK | X_OK) != 0)
    throw Invalid_input(printable(path) + ": cannot write (does the folder exist, and is it writable?)");
  std::random_device device;
  const auto key = (static_cast<unsigned long long>(device()) << 32) ^ device() ^ static_cast<unsigned long long>(::getpid());
  struct stat existing;
  for(unsigned long long attempt = 0;; ++attempt) {
    path_ = folder + "." + base + "." + std::to_string(key + attempt) + suffix;
    if(::lstat(path_.c_str(), &existing) != 0 && errno == ENOENT) break;
    if(attempt == 64) throw Invalid_input(printable(path) + ": cannot write (no free temporary name beside it)");
  }
  streamed_ = special;
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
  struct stat written;
  if(::stat(path_.c_str(), &written) != 0) std::ofstream(path_, std::ios::binary);   // an output the run left empty
  if(special) {
    // Not blocking on a named pipe that no program reads: then the open fails (ENXIO).
    const int out = ::open(place.c_str(), O_WRONLY | O_NONBLOCK);
    if(out < 0)
      throw Invalid_input(printable(target) + (errno == ENXIO ? ": a pipe that no program reads" : ": cannot write"));
    ::fcntl(out, F_SETFL, ::fcntl(out, F_GETFL) & ~O_NONBLOCK);
    std::ifstream in(path_, std::ios::binary);
    bool good = static_cast<bool>(in);
    for(char buffer[1 << 16]; good && in.read(buffer, sizeof buffer).gcount() > 0;)
      for(const char *at = buffer, *end = buffer + in.gcount(); good && at < end;) {
        const ssize_t n = ::write(out, at, static_cast<std::size_t>(end - at));
        if(n < 0 && errno == EINTR) continue;
        good = n > 0;
        at += n > 0 ? n : 0;
      }
    good = ::close(out) == 0 && good;
    if(!good) throw Invalid_input(printable(target) + ": write error");
    return;   // the temporary file is removed by the destructor
  }
  // An existing output keeps its mode (a read-only file stays read-only).
  struct stat old;
  if(::stat(place.c_str(), &old) == 0) ::chmod(path_.c_str(), old.st_mode & 07777);
  if(std::rename(path_.c_str(), place.c_str()) != 0) throw Invalid_input(printable(target) + ": cannot replace the file");
  Temporary_registry::get().remove(slot_);
  slot_ = -1;
  kept_ = true;
}

// The signals that end the program by default and can be caught, sent by others (the crashes
// are handled too, but cannot be held back).
constexpr int sent_signals[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGUSR1, SIGUSR2, SIGALRM, SIGVTALRM, SIGPROF, SIGXCPU, SIGXFSZ};

void remove_temporary_files_on_signals()
{
  Temporary_registry::get();   // constructed before any handler may run
  // The files being written go first (SIGKILL cannot be caught: the files exist only while written).
  for(int signal : sent_signals) std::signal(signal, unlink_temporaries_and_reraise);
  for(int signal : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) std::signal(signal, unlink_temporaries_and_reraise);
  // A closed standard output (`... | head`) must not kill the tool after its files are written:
  // writes to it fail instead, and the exit status is the run's.
  std::signal(SIGPIPE, SIG_IGN);
}

void commit_uninterrupted(const std::function<void()>& commit)
{
  sigset_t held, before;
  sigemptyset(&held);
  for(int signal : sent_signals) sigaddset(&held, signal);
  ::sigprocmask(SIG_BLOCK, &held, &before);
  const auto release = [&] {
    for(int signal : sent_signals) std::signal(signal, SIG_IGN);   // discards those pending
    ::sigprocmask(SIG_SETMASK, &before, nullptr);
  };
  try {
    commit();
  } catch(...) {
    release();
    throw;
  }
  release();
}

namespace {

// The message of the deadline armed, in fixed storage that the handler may write.
std::array<char, 1024> deadline_message;
std::size_t deadline_message_size = 0;

void end_at_deadline(int)
{
  Temporary_registry::get().unlink_all();
  [[maybe_unused]] const ssize_t written = ::write(STDERR_FILENO, deadline_message.data(), deadline_message_size);
  ::_exit(1);
}

} // namespace

Hard_deadline::Hard_deadline(double seconds, const std::string& message)
{
  if(!(seconds > 0)) return;
  const std::string line = "distortion_optimizer: " + message + "\n";
  deadline_message_size = (std::min)(line.size(), deadline_message.size());
  std::memcpy(deadline_message.data(), line.data(), deadline_message_size);
  std::signal(SIGALRM, end_at_deadline);
  itimerval timer{};
  timer.it_value.tv_sec = static_cast<time_t>(seconds);
  timer.it_value.tv_usec = static_cast<suseconds_t>((seconds - std::floor(seconds)) * 1e6);
  armed_ = ::setitimer(ITIMER_REAL, &timer, nullptr) == 0;
}

Hard_deadline::~Hard_deadline()
{
  if(!armed_) return;
  itimerval off{};
  ::setitimer(ITIMER_REAL, &off, nullptr);
  std::signal(SIGALRM, unlink_temporaries_and_reraise);
}

} // namespace distortion_optimizer
