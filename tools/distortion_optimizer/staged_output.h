// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The tool's outputs, all or none (POSIX): each output is first a unique temporary file beside it
// (never a name a user's file may have), renamed over it only once every output was written, and
// removed on every failure, also when the program is interrupted (remove_temporary_files_on_signals).

#ifndef DISTORTION_OPTIMIZER_STAGED_OUTPUT_H
#define DISTORTION_OPTIMIZER_STAGED_OUTPUT_H

#include <functional>
#include <string>

namespace distortion_optimizer {

// A unique name beside `path` (in its folder, hidden, ending in `suffix`) that the run writes, not
// yet a file; the file is removed when this object is destroyed unless it was renamed, and also if
// the program is ended by a signal after remove_temporary_files_on_signals(). Where `path` is a
// symbolic link, the file it names is replaced and the link kept; where it is a device or a pipe
// (/dev/null, /dev/stdout), the temporary file is made in the temporary folder (TMPDIR, else /tmp)
// and its bytes are written into `path` at the end, which is never replaced.
class Temporary_file
{
public:
  // Throws Invalid_input if the folder of `path` does not exist or is not writable, if `path` is
  // a folder, or a symbolic link to nothing.
  explicit Temporary_file(const std::string& path, const std::string& suffix = "");
  Temporary_file(const Temporary_file&) = delete;
  Temporary_file& operator=(const Temporary_file&) = delete;
  ~Temporary_file();

  const std::string& path() const { return path_; }
  // Whether the bytes go into a device or a pipe at rename_to() (a write that may fail, such as
  // /dev/full) rather than by renaming the file.
  bool is_streamed() const { return streamed_; }
  // Renames the file to `target` (the file a symbolic link names, whose mode it takes if it
  // exists; into a device or a pipe, its bytes are written), after which it is no longer
  // temporary. Throws Invalid_input if the rename or the write fails, or if `target` is a named
  // pipe that no program reads (the temporary file is then removed).
  void rename_to(const std::string& target);

private:
  std::string path_;
  int slot_ = -1;
  bool kept_ = false, streamed_ = false;
};

// Installs handlers of the signals that end the program (SIGINT, SIGTERM, SIGHUP, SIGQUIT, the
// user, timer and limit signals, and the crashes) that remove the temporary files being written
// and then end the program as the signal would have; ignores SIGPIPE (a write into a closed pipe
// fails instead).
void remove_temporary_files_on_signals();

// Runs `commit` (the renames that put the outputs in place) with the signals of
// remove_temporary_files_on_signals() held back, then ignores those that came meanwhile: a
// signal cannot end the program between two renames, and the exit status is the run's, as the
// files say (a run whose outputs are all in place does not end with 143).
void commit_uninterrupted(const std::function<void()>& commit);

// Ends the program if `seconds` (> 0; 0 for never) pass before it is destroyed: `message` on
// standard error, the temporary files removed, exit status 1. For a stage that its own time limit
// cannot always stop (Mesh_3's protection of sharp edges runs long steps that check none).
class Hard_deadline
{
public:
  Hard_deadline(double seconds, const std::string& message);
  Hard_deadline(const Hard_deadline&) = delete;
  Hard_deadline& operator=(const Hard_deadline&) = delete;
  ~Hard_deadline();

private:
  bool armed_ = false;
};

} // namespace distortion_optimizer

#endif // DISTORTION_OPTIMIZER_STAGED_OUTPUT_H
