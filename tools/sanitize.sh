#!/usr/bin/env bash
# SPDX-FileCopyrightText: The archgeo authors
# SPDX-License-Identifier: GPL-3.0-or-later
# Sanitizer run: builds the libraries, the archgeo tool and every test with
# AddressSanitizer and UndefinedBehaviorSanitizer in build-asan/ (gcc,
# RelWithDebInfo without NDEBUG, so CGAL and Eigen keep their assertions as in
# the Release build) and runs the whole ctest suite with any sanitizer report
# fatal: ASan halts on the first error, UBSan too (-fno-sanitize-recover),
# LeakSanitizer reports every leak at exit except the suppressions in
# tools/lsan.supp (each one explained there). A report makes its test fail.
#
#   tools/sanitize.sh            # configure, build, run ctest (-j2)
#   tools/sanitize.sh -R test_io # extra arguments go to ctest
#
# EIGEN_MALLOC_ALREADY_ALIGNED=1: with -fsanitize=address Eigen switches to
# its hand-made aligned allocator, which Debian's libceres does not use; see
# ../shared/STYLE.md, "Sanitizer builds".
set -euo pipefail
cd "$(dirname "$0")/.."

build=${ARCHGEO_ASAN_BUILD:-build-asan}
flags="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
flags+=" -DEIGEN_MALLOC_ALREADY_ALIGNED=1"
launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
# Without the Python module: the interpreter is not instrumented, so the
# module cannot load an ASan runtime (its tests run in the Release build).
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DARCHGEO_PYTHON=OFF \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g" -DCMAKE_CXX_FLAGS="$flags" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" "${launcher[@]}" >/dev/null

# The tool and the tests only (not the benchmarks).
targets=(archgeo tests_energies tests_mesh tests_fields tests_problems tests_cli)
jobs=${ARCHGEO_JOBS:-$(nproc)}
cmake --build "$build" -j "$jobs" --target "${targets[@]}"

export ASAN_OPTIONS="halt_on_error=1:abort_on_error=1:detect_leaks=1:detect_stack_use_after_return=0:strict_init_order=1"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
export LSAN_OPTIONS="suppressions=$PWD/tools/lsan.supp:print_suppressions=1"
# EngineBaselines pins the Release build's objectives to 1e-6; this build
# (-O2, assertions on, instrumented) takes another floating-point path, and
# the long principal_symmetric run ends 4e-4 apart: not a memory error.
ctest --test-dir "$build" --output-on-failure -j "$jobs" -E 'EngineBaselines' "$@"
