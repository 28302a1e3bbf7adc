// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer harness: the YAML spec reader, archgeo::ReadSpec(path, overrides)
// of problems/spec/spec.h, on arbitrary bytes written to a temporary file (ReadSpec
// reads a path; it opens no other file).
//
// Contract checked: every input either gives a spec or throws
// archgeo::InputError; anything else (yaml-cpp's own exceptions such as
// "bad conversion", std::bad_alloc, a CHECK, a sanitizer report, a timeout)
// is a finding.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "core/input_error.h"
#include "problems/spec/spec.h"

namespace {

// One file per fuzzing process, removed at exit.
const std::string& SpecPath() {
  static const std::string path = [] {
    const char* dir = std::getenv("TMPDIR");
    std::string p = std::string(dir != nullptr && *dir != '\0' ? dir : "/tmp") +
                    "/archgeo_fuzz_spec_" + std::to_string(::getpid()) + ".yaml";
    std::atexit([] { std::remove(SpecPath().c_str()); });
    return p;
  }();
  return path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string& path = SpecPath();
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (file == nullptr) __builtin_trap();
  if (size > 0 && std::fwrite(data, 1, size, file) != size) __builtin_trap();
  std::fclose(file);
  try {
    archgeo::ReadSpec(path);
  } catch (const archgeo::InputError&) {
    // Bad input, reported as such.
  }
  return 0;
}
