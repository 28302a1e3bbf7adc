// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the job file of `archgeo bench --emit-jobs`: one run per line,
// as data, never as a shell command.
//
// Each line is a JSON object
//   {"spec": S, "mesh": M, "settings": [[KEY, VALUE], ...], "repeat": R, "record": F}
// with absolute paths (JSON escapes every character a path may hold, a line
// break included). `archgeo bench --run-jobs FILE --job K` reads line K
// (from 1) and runs it itself: a runner (xargs, a Slurm array) passes only
// the number K, so no shell ever parses a file name.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace archgeo {

struct BenchJob {
  std::string spec, mesh;
  std::vector<std::pair<std::string, std::string>> settings;
  int repeat = 1;        // the repeat's number (1, 2, ...)
  std::string record;    // where the run's record goes
};

// The job as one line, '\n' included.
std::string JobLine(const BenchJob& job);

// Line `k` of the job file `path`. Throws InputError(path, k, "--job", ...)
// if the file cannot be read, has no line k, or line k is not a job.
BenchJob ReadJob(const std::string& path, int k);

}  // namespace archgeo
