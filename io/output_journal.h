// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the commit journal of StagedOutputs and the recovery of what a
// killed process left (protocol in io/output_files.h).
//
// Before the first backup and rename, Commit() writes a journal into every
// folder it writes to: `.archgeo-commit-<pid>-<token>`, each copy listing
// every output (target, temporary, backup) with absolute paths. The copy in
// the first output's folder is the primary; removing it is the commit point.
// RecoverOutputs(folder), run by Stage() on each folder it stages into,
// finishes what a dead process (SIGKILL, power loss) left there:
//  - a journal whose primary still exists: the commit did not end; every
//    output returns to its old content (backups renamed back, outputs that
//    had none removed), then every copy of the journal goes;
//  - a journal whose primary is gone: the commit ended; its backups go;
//  - temporaries and backups of a dead process with no journal left: they go.
// Only regular files owned by the running user whose names carry a pid that
// is no live process are touched.
#pragma once

#include <sys/types.h>

#include <cstdint>
#include <string>
#include <vector>

namespace archgeo {

struct JournalEntry {
  std::string target, temporary, backup;  // absolute; backup empty for a new output
  std::uint64_t device = 0, inode = 0;    // of the temporary, as Stage() created it
};

class CommitJournal {
 public:
  // Writes the copies (the primary last), each flushed to disk; false with
  // errno set if one cannot be written (the copies written are removed).
  bool Write(const std::vector<JournalEntry>& entries, const std::string& token);
  // The commit point: removes the primary.
  void Committed();
  // Removes every copy that is left, the primary last.
  void Remove();

 private:
  std::vector<std::string> copies_;  // the primary last
};

// 12 random characters [a-z0-9] (getrandom).
std::string RandomToken();

// `.tmp-<pid>-<token>` / `.bak-<pid>-<token>` / `.archgeo-commit-<pid>-<token>`.
std::string TemporaryMark(const std::string& token);
std::string BackupMark(const std::string& token);

// Returns every output of `entries` to its old content: a target replaced
// gets its backup back, a target that had none and holds the temporary's
// inode is removed, a backup of a target never replaced and the temporaries
// left go. Idempotent.
void RollBackOutputs(const std::vector<JournalEntry>& entries);

// Cleans what dead processes left in `folder` (see above).
void RecoverOutputs(const std::string& folder);

}  // namespace archgeo
