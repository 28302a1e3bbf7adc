// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The benchmark programs are one executable (build/benchmarks/archgeo_benchmarks,
// its sources compiled together as unity units); each program registers its
// main under its file's name, and build/benchmarks/<name> is a symbolic link
// to the executable that runs that program (the name it is called by picks it).
//
//   ARCHGEO_BENCHMARK_PROGRAM(pellis_fig19, ARCHGEO_UNITY_ID::Main);
#pragma once

namespace bench {

using ProgramMain = int (*)(int argc, char** argv);

// Adds `main` under `name`; called during static initialisation.
bool RegisterProgram(const char* name, ProgramMain main);

// For a program that takes no arguments: false, with "unknown argument"
// and its usage on stderr, when it was given one (the program exits 2).
bool NoArguments(int argc, char** argv);

}  // namespace bench

#define ARCHGEO_BENCHMARK_PROGRAM(name, main) \
  static const bool archgeo_benchmark_##name = bench::RegisterProgram(#name, main)
