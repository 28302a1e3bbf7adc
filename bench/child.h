// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — `archgeo bench`'s child processes and their scratch folders,
// taken down with the bench when it is interrupted.
//
// After InstallBenchSignalHandling(), a SIGINT, SIGTERM or SIGHUP to the
// bench process
//  1. is forwarded to the running child (`archgeo solve`), which removes its
//     own staged temporaries and ends; the bench waits for it (5 s, then
//     SIGKILL), so no child outlives the bench;
//  2. removes the live scratch folder (every file in it, then the folder);
//  3. is passed on to the handler installed before (the output cleanup of
//     io/output_files.h: staged temporaries removed, the process ended by
//     the signal).
#pragma once

#include <string>
#include <vector>

namespace archgeo {

// A private folder (mkdtemp, mode 0700) named archgeo_bench.XXXXXX in the
// temporary folder ($TMPDIR, else /tmp). Removed with its content by the
// destructor or by a signal (see above). One at a time.
class ScratchFolder {
 public:
  ScratchFolder();
  ~ScratchFolder();
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

struct ChildOutcome {
  int exit_code = 0;           // its exit status, or 128 + the signal that ended it
  double wall_s = 0;           // around the child, spawn to exit
  double peak_memory_mb = 0;   // wait4's ru_maxrss
};

// Runs argv (argv[0] is the program's path; no shell) with its standard
// output and error written to the given files, and waits for it. Throws
// InputError if it cannot be started.
ChildOutcome RunChild(const std::vector<std::string>& argv, const std::string& stdout_path,
                      const std::string& stderr_path);

// Installs the handlers described above, chained to the ones in place (call
// after InstallOutputSignalCleanup()). For programs, not libraries. Idempotent.
void InstallBenchSignalHandling();

}  // namespace archgeo
