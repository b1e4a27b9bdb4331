#!/usr/bin/env bash
# Builds the libFuzzer targets with clang and runs each for SECONDS (default 10), or until it has
# executed RUNS inputs when that comes first. The long form (10 million inputs per target):
#   tests/fuzz/run_fuzz.sh . build/fuzz 3600 10000000
# Exit 77 (skipped) if clang is missing; a crash, leak or sanitizer finding fails.
#   run_fuzz.sh SOURCE_DIR WORK_DIR [SECONDS [RUNS]]
set -euo pipefail
source=$(cd "${1:?}" && pwd) work=${2:?} seconds=${3:-10} runs=${4:--1}
command -v clang >/dev/null || { echo "run_fuzz: clang missing (scripts/bootstrap.sh installs it): skipped"; exit 77; }
CC=clang cmake -S "$source" -B "$work" -DUBII_PORT=embedded -DUBII_BUILD_FUZZ=ON -DUBII_BUILD_TESTS=OFF \
  -DUBII_BUILD_EXAMPLES=OFF -DCMAKE_BUILD_TYPE=RelWithDebInfo >"$work.configure.log" 2>&1 ||
  { cat "$work.configure.log"; exit 1; }
cmake --build "$work" -j 2 >"$work.build.log" 2>&1 || { cat "$work.build.log"; exit 1; }
for target in fuzz_port_parsers fuzz_zmtp_stream fuzz_url fuzz_topic_data fuzz_service_reply; do
  corpus="$work/corpus/$target"
  mkdir -p "$corpus"
  # New inputs go to the work corpus; the seeds in the tree are read only.
  "$work/tests/fuzz/$target" -max_total_time="$seconds" -runs="$runs" -print_final_stats=1 -artifact_prefix="$work/" "$corpus" \
    "$source/tests/fuzz/seeds/$target" >"$work/$target.log" 2>&1 || { tail -n 40 "$work/$target.log"; exit 1; }
  executed=$(sed -n 's/^stat::number_of_executed_units: *//p' "$work/$target.log")
  took=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$work/$target.log")
  coverage=$(grep -E '^#[0-9]+' "$work/$target.log" | tail -n 1 | sed -n 's/.* cov: \([0-9]*\) ft: \([0-9]*\).*/\1 edges, \2 features/p')
  echo "run_fuzz: $target: $executed inputs ($took/s), coverage ${coverage:-unknown}, no finding"
done
