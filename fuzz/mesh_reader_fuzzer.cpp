// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer harness: one mesh reader (OBJ, OFF or PLY, chosen at compile
// time by ARCHGEO_FUZZ_NAME's extension) on arbitrary bytes, through
// ReadMeshFromMemory, the code path of ReadMesh after the file is read.
//
// Contract checked: every input either gives a mesh or throws
// archgeo::InputError. Anything else is a finding: another exception
// (std::bad_alloc, std::length_error, a CGAL assertion: libFuzzer reports an
// uncaught exception), a glog CHECK failure (abort), a sanitizer report, an
// allocation beyond -malloc_limit_mb (default: -rss_limit_mb, 2 GB), a
// timeout (-timeout, default 1200 s; fuzz_smoke.sh uses 10 s).
// The default ReadLimits are used, as in a run.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/input_error.h"
#include "io/io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  try {
    const archgeo::Mesh mesh = archgeo::ReadMeshFromMemory(ARCHGEO_FUZZ_NAME, bytes);
    // A mesh was read: it is valid and has faces.
    if (!mesh.is_valid(false) || mesh.number_of_faces() == 0) __builtin_trap();
  } catch (const archgeo::InputError&) {
    // Bad input, reported as such: the expected outcome for most inputs.
  }
  return 0;
}
