// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — all-or-nothing output files.
//
// A run's outputs are staged: each is written to a temporary file beside its
// target (same folder, so the same file system), named
// <stem>.tmp-<pid>-<token><extension> with a random 12-character token, and
// only Commit() puts them in place.
//
// What the protocol promises (README, "Exit codes and guarantees"):
//  - Outputs are regular files. A target that exists and is not a regular
//    file is refused by Stage(): a device such as /dev/null, a FIFO, a
//    socket, a folder, and a symbolic link (also one to a regular file, such
//    as /dev/stdout with the output redirected): a link is neither followed
//    nor replaced. So is a target that names an input (`protected_paths`,
//    also through "..", "." or a symbolic link) or another output.
//  - Stage() creates the temporary itself, exclusively and without following
//    a link (O_CREAT|O_EXCL|O_NOFOLLOW; a name taken is drawn again), and
//    the writers open it without following a link (io/output_stream.h).
//    Commit() checks that every temporary is still the regular file Stage()
//    created (same device and inode; Stage() keeps it open, so its inode
//    number cannot pass to a file put in its place) and every target still
//    one Stage() accepts; else it throws InputError naming the target,
//    nothing replaced.
//  - Nothing is replaced before every output has been written completely:
//    Commit() first flushes every temporary to disk (fsync).
//  - Commit() then writes a journal into each folder it writes to
//    (.archgeo-commit-<pid>-<token>, io/output_journal.h), keeps a
//    hard-linked backup <target>.bak-<pid>-<token> of every existing target,
//    and replaces the targets by rename(2), each atomically. If a rename
//    fails, the targets already replaced get their backups back and the new
//    ones that had none are removed: the outputs are all old. Else removing
//    the journal of the first output's folder is the commit point; the
//    backups and the other journals go after it.
//  - SIGINT, SIGTERM and SIGHUP are held back during Commit(). One that
//    arrives before the commit point rolls the commit back as a failed
//    rename would (all old outputs) and then ends the process by the signal
//    (exit status 128 + signal); one that arrives after it ends the process
//    the same way with every output new.
//  - After InstallOutputSignalCleanup(), a SIGINT, SIGTERM or SIGHUP at any
//    other time before the commit removes every staged temporary and every
//    folder Stage() created (if empty), leaves the existing outputs untouched
//    and ends the process with the signal's default action (exit status
//    128 + signal).
//  - A SIGKILL (or a power loss) cannot be handled. Before Commit() it
//    leaves the old outputs and the temporaries; during the commit it can
//    leave some targets new and others old, the backups and the journals.
//    The next Stage() into the same folder recovers (RecoverOutputs): a
//    commit that did not reach its commit point is rolled back, so every
//    output it listed is old again, in every folder; the backups of one that
//    did go; the temporaries of dead processes go.
//  - Without Commit() (an error, an exception) the destructor removes the
//    temporaries and the folders Stage() created (if still empty).
#pragma once

#include <cstdint>
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

  // Creates the temporary to write `target` to and returns its path,
  // creating the target's folder if needed and first recovering what a killed
  // run left in that folder. `key` names the output in messages (e.g.
  // "output.report"). Throws InputError(target, 0, key, ...) for a protected
  // path, a target given twice, a target that exists and is not a regular
  // file (a symbolic link included), or a folder or temporary that cannot be
  // created.
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
    std::uint64_t device = 0, inode = 0;  // the temporary as created
    int fd = -1;                          // open on it from Stage() to the end
  };
  Staged CreateTemporary(const std::string& target, const std::string& key);
  void CheckAndSync() const;

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
