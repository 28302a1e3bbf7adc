#!/usr/bin/env bash
# SPDX-FileCopyrightText: The archgeo authors
# SPDX-License-Identifier: GPL-3.0-or-later
# Fuzz smoke run (CI): builds the libFuzzer harnesses of fuzz/ with clang,
# ASan and UBSan in build-fuzz/, then runs each for a few seconds starting
# from its committed corpus fuzz/corpus/<name>/ (every committed input, the
# regression inputs of past findings included, is replayed first). New inputs
# go to a scratch folder, never into the repository.
# Exit 0: no finding. Non-zero: a harness crashed, leaked, timed out or ran
# out of memory; its reproducer (crash-*, leak-*, timeout-*, oom-*) is kept in
# the folder printed at the end and fuzz/README.md says how to replay it.
#
#   tools/fuzz_smoke.sh                 # 10 s per harness (4 harnesses)
#   tools/fuzz_smoke.sh obj off ply     # the mesh readers only (tools/test.sh)
#   ARCHGEO_FUZZ_SECONDS=600 tools/fuzz_smoke.sh obj   # a longer run of one
set -euo pipefail
cd "$(dirname "$0")/.."

build=${ARCHGEO_FUZZ_BUILD:-build-fuzz}
seconds=${ARCHGEO_FUZZ_SECONDS:-10}
harnesses=("$@")
if [ "${#harnesses[@]}" -eq 0 ]; then harnesses=(obj off ply spec); fi

launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
# -O1 with line tables: the sanitizers' reports keep file and line, and the
# instrumented build takes a fraction of -O2 -g's time.
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only -DNDEBUG" \
  -DCMAKE_CXX_COMPILER=clang++ -DARCHGEO_FUZZ=ON "${launcher[@]}" >/dev/null
targets=()
for name in "${harnesses[@]}"; do targets+=("fuzz_$name"); done
cmake --build "$build" -j "$(nproc)" --target "${targets[@]}"

artifacts=$(mktemp -d "${TMPDIR:-/tmp}/archgeo_fuzz_smoke.XXXXXX")
# One harness: ${seconds} s from its corpus; exit non-zero on a finding.
fuzz() {
  local name=$1 work="$artifacts/$1-corpus"
  mkdir -p "$work"
  # -timeout: one input may take at most 10 s; -rss_limit_mb: 2 GB (also the
  # largest single allocation allowed).
  ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=0 \
    UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 \
    "$build/fuzz/fuzz_$name" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
      -print_final_stats=1 -artifact_prefix="$artifacts/$name-" \
      "$work" "fuzz/corpus/$name" 2>"$artifacts/$name.log"
  local status=$?
  rm -rf "$work"
  return "$status"
}
# The harnesses run nproc at a time (each is one process on one core).
declare -A pid
for name in "${harnesses[@]}"; do
  while [ "$(jobs -rp | wc -l)" -ge "$(nproc)" ]; do wait -n || true; done
  fuzz "$name" &
  pid[$name]=$!
done
status=0
for name in "${harnesses[@]}"; do
  echo "== fuzz_$name: ${seconds} s on fuzz/corpus/$name"
  if ! wait "${pid[$name]}"; then
    status=1
    tail -n 60 "$artifacts/$name.log"
    echo "fuzz_$name: FINDING (reproducer and log in $artifacts)"
  else
    grep -E "^stat::(number_of_executed_units|peak_rss_mb)|cov: .* ft: .* corp:" \
      "$artifacts/$name.log" | tail -n 3
  fi
done
if [ "$status" -eq 0 ]; then
  rm -rf "$artifacts"
  echo "fuzz smoke: no finding"
fi
exit "$status"
