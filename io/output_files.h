// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — all-or-nothing output files.
//
// A run's outputs are staged: each is written to a temporary file beside its
// target (same folder, so the same file system), named
// <stem>.tmp-<pid>-<n><extension>, and only Commit() puts them in place.
//
// What the protocol promises (README, "Exit codes and guarantees"):
//  - Outputs are regular files. A target that exists and is not a regular
//    file (a device such as /dev/null, a FIFO, a socket, a folder) is refused
//    by Stage(), as is a target that names an input (`protected_paths`, also
//    through "..", "." or a symbolic link) or another output.
//  - Nothing is replaced before every output has been written completely:
//    Commit() first checks and flushes every temporary to disk (fsync).
//  - Commit() replaces the targets by rename(2), each atomically. Before the
//    first rename every existing target gets a hard-linked backup
//    <target>.bak-<pid>; if a later rename fails, the targets already
//    replaced are restored from their backups (or removed if they are new),
//    so the outputs are either all old or all new. The backups are removed
//    when the commit ends.
//  - SIGINT, SIGTERM and SIGHUP are blocked during Commit(): a signal that
//    arrives then is delivered when the commit is complete (all new files).
//  - After InstallOutputSignalCleanup(), a SIGINT, SIGTERM or SIGHUP at any
//    other time removes every staged temporary and every folder Stage()
//    created (if empty), leaves the existing outputs untouched and ends the
//    process with the signal's default action (exit status 128 + signal).
//  - A SIGKILL cannot be handled: before Commit() it leaves the old outputs
//    untouched and the temporaries in place (recognisable by their
//    `.tmp-<pid>-` names); during the renames of Commit() (microseconds) it
//    can leave some targets new and others old, with the old ones still
//    present as <target>.bak-<pid> — a detectable state.
//  - Without Commit() (an error, an exception) the destructor removes the
//    temporaries and the folders Stage() created (if still empty).
#pragma once

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace archgeo {

class StagedOutputs {
 public:
  explicit StagedOutputs(std::vector<std::string> protected_paths = {});
  ~StagedOutputs();
  StagedOutputs(const StagedOutputs&) = delete;
  StagedOutputs& operator=(const StagedOutputs&) = delete;

  // Returns the temporary path to write `target` to, creating the target's
  // folder if needed. `key` names the output in messages (e.g.
  // "output.report"). Throws InputError(target, 0, key, ...) for a protected
  // path, a target given twice, a target that exists and is not a regular
  // file, or a folder that cannot be created.
  std::string Stage(const std::string& target, const std::string& key = "");

  // Stages `target` and calls `writer(temporary)`; an InputError the writer
  // throws about the temporary is rethrown naming `target` and `key`, so
  // messages name the path the user asked for.
  void Write(const std::string& target, const std::string& key,
             const std::function<void(const std::string& temporary)>& writer);

  // Puts every staged output in place (see above). Throws InputError naming
  // the target that could not be committed; the old outputs are then intact.
  void Commit();

  // For tests of the commit protocol: called after the k-th rename (k = 0,
  // 1, ...) with the target just replaced.
  void SetRenameHookForTesting(std::function<void(int k, const std::string& target)> hook) {
    rename_hook_ = std::move(hook);
  }

 private:
  struct Staged {
    std::string temporary, target, key;
  };
  std::vector<std::string> protected_paths_;
  std::vector<Staged> staged_;
  std::vector<std::string> created_;  // folders created by Stage(), outermost first
  std::vector<int> slots_;            // their entries for the signal cleanup
  bool committed_ = false;
  std::function<void(int, const std::string&)> rename_hook_;
};

// Writes `text` to `path` and checks every step (write, flush, fsync,
// close): a full disk is an InputError(path, 0, key, ...), never an empty or
// truncated file reported as written.
void WriteTextFile(const std::string& path, const std::string& text, const std::string& key = "");

// Installs handlers for SIGINT, SIGTERM and SIGHUP that remove the staged
// temporaries and created folders of every live StagedOutputs and then end
// the process by the signal (see above). For programs (the CLI), not for
// libraries embedded elsewhere. Idempotent.
void InstallOutputSignalCleanup();

}  // namespace archgeo
