// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The main of build/benchmarks/archgeo_benchmarks: runs the program named by
// the link it was called through (build/benchmarks/<name>), or by its first
// argument (`archgeo_benchmarks <name> ...`); without one, lists the programs.
#include <cstdio>
#include <cstring>
#include <map>
#include <string>

#include "benchmarks/program.h"
#include "core/solver_options.h"

namespace bench {
namespace {

std::map<std::string, ProgramMain>& Programs() {
  static std::map<std::string, ProgramMain> programs;
  return programs;
}

std::string BaseName(const char* path) {
  const char* slash = std::strrchr(path, '/');
  return slash ? slash + 1 : path;
}

}  // namespace

bool RegisterProgram(const char* name, ProgramMain main) {
  Programs()[name] = main;
  return true;
}

bool NoArguments(int argc, char** argv) {
  if (argc <= 1) return true;
  std::fprintf(stderr, "%s: unknown argument '%s'\nusage: %s (no arguments)\n", argv[0], argv[1],
               argv[0]);
  return false;
}

}  // namespace bench

int main(int argc, char** argv) {
  archgeo::StartWithPassiveOpenMpWaits(argv);
  const auto& programs = bench::Programs();
  auto it = programs.find(bench::BaseName(argv[0]));
  if (it != programs.end()) return it->second(argc, argv);
  if (argc > 1 && (it = programs.find(argv[1])) != programs.end()) {
    return it->second(argc - 1, argv + 1);
  }
  std::fprintf(stderr, "usage: %s PROGRAM [ARGS...]  (or build/benchmarks/PROGRAM [ARGS...])\n"
                       "programs:\n", argv[0]);
  for (const auto& [name, main] : programs) std::fprintf(stderr, "  %s\n", name.c_str());
  return argc > 1 ? 2 : 0;
}
