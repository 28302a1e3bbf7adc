// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — `archgeo bench`: solver-setting sweeps on the user's meshes.
//
//   archgeo bench SPEC --mesh A.obj --mesh B.off
//       --vary 'solver.linear_solver_type=[sparse_normal_cholesky,cgnr]'
//       --vary 'solver.num_threads=[1,2]' --repeat 3 --out results.csv
//
// Runs the cross product of the --vary values (settings) × the meshes, each
// `repeat` times, every run `archgeo solve SPEC --set …` in its own process
// (this very binary), its outputs redirected into a scratch folder. Per run
// a record (JSON) with the exit code and first error line, wall time, peak
// memory (wait4's ru_maxrss), Ceres' time split (evaluation = residuals and
// Jacobians, linear solver), iterations, and the problem's own figures
// (tolerances met, each tolerance's measure after the solve, the objective)
// from its report. Records of one (settings, mesh) are merged into a row:
// wall time median, min and max over the repeats. Rows go to the table
// printed, to OUT (CSV; the name must end in .csv) and to OUT with .json. A
// run that fails is a row with its exit code and message; the sweep goes on.
//
// Outputs (OUT and its .json, the job file, a record) are written as `solve`
// writes its own (io/output_files.h): staged before any run, refused if they
// name an input (the spec, a mesh, a file the spec reads, a record being
// collected, the job file) or exist and are not regular files, and put in
// place all together, so a failure leaves the previous files as they were.
// A signal stops the running child and removes the scratch folder
// (bench/child.h).
//
// Beyond one machine: --emit-jobs JOBS writes one job per line, as data
// (bench/jobs.h); `archgeo bench --run-jobs JOBS --job K` runs job K and
// writes its record into the records folder (--records, default JOBS
// without extension + "_runs"); runners pass only K (docs/bench.md), and
// `archgeo bench --collect DIR` merges the records into the same rows.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/progress.h"

namespace archgeo {

struct BenchRequest {
  std::string spec;                     // the spec every run solves
  std::vector<std::string> meshes;      // --mesh, in order
  std::vector<std::string> vary;        // --vary 'key=[a,b]' (or 'key=a')
  std::vector<std::string> sets;        // --set key=value (one run: --record)
  int repeat = 1;
  std::string out;                      // CSV path ("" = none); JSON beside it
  std::string emit_jobs;                // write jobs instead of running
  std::string records;                  // folder of the emitted jobs' records
  std::string collect;                  // merge the records of this folder
  std::string record;                   // run once (settings from `sets`) into this record
  std::string run_jobs;                 // a job file of --emit-jobs ...
  int job = 0;                          // ... and the job of it to run (from 1)
  std::string self;                     // the archgeo binary
  ProgressSink progress;                // a note before and after each run ("run i of N ...")
};

// Does what the request asks and returns the text to print (the table, or
// what was written). Throws InputError for bad arguments, an unreadable
// spec, a --vary key the spec's problem does not have, a missing mesh, or
// an output that cannot be written.
std::string RunBench(const BenchRequest& request);

// One run's record (the JSON written per run); exposed for tests.
nlohmann::json RunOnce(const std::string& self, const std::string& spec, const std::string& mesh,
                       const std::vector<std::pair<std::string, std::string>>& settings,
                       int repeat);

// Records merged into rows (grouped by settings and mesh, first-seen order).
nlohmann::json MergeRecords(const std::vector<nlohmann::json>& records);

// The median of `values` (0 if there are none).
double Median(std::vector<double> values);

}  // namespace archgeo
