#!/usr/bin/env bash
# The test command: installs what is missing (Debian packages, npm packages), builds libubii four
# times and runs the suite on each, inside a private network namespace where a real master is
# started and stopped by the tests: the Linux port plain (build/test) and with AddressSanitizer +
# UndefinedBehaviorSanitizer (build/asan), both with the OCR pipelines; the embedded port with both
# sanitizers (build/embedded), whose suite also builds and tests the reduced "topics" schema
# (tests/schema); and the C++ layer's threaded parts under ThreadSanitizer (build/tsan).
#
#   scripts/test.sh            build trees in ./build/{test,asan,embedded,tsan}
#   UBII_BUILD_DIR=DIR ...     build trees below DIR instead
#   UBII_CACHE_DIR=DIR ...     fetched sources and npm packages in DIR (default ~/.cache/libubii)
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
build_root=${UBII_BUILD_DIR:-$root/build}
jobs=$(nproc 2>/dev/null || echo 2)
started=$SECONDS

"$root/scripts/bootstrap.sh"

# run_configuration NAME CMAKE_ARGS...; with TARGETS and TESTS set, builds only those targets and
# runs only the tests matching that regex (and the fixtures they need).
run_configuration() {
  local name=$1; shift
  local dir="$build_root/$name"
  echo "=== $name: configure and build in $dir"
  cmake -S "$root" -B "$dir" -DUBII_BUILD_TESTS=ON -DUBII_BUILD_EXAMPLES=ON "$@" >"$dir.configure.log" 2>&1 ||
    { cat "$dir.configure.log"; return 1; }
  local targets=() selection=()
  for target in ${TARGETS:-}; do targets+=(--target "$target"); done
  [ -n "${TESTS:-}" ] && selection=(-R "$TESTS")
  cmake --build "$dir" -j "$jobs" "${targets[@]}"
  echo "=== $name: tests"
  "$root/scripts/private-net.sh" ctest --test-dir "$dir" --output-on-failure -j "$jobs" --timeout 300 \
    "${selection[@]}"
}

mkdir -p "$build_root"
run_configuration test -DCMAKE_BUILD_TYPE=RelWithDebInfo -DUBII_WITH_OCR=ON
run_configuration asan -DCMAKE_BUILD_TYPE=Debug -DUBII_SANITIZE=ON -DUBII_WITH_OCR=ON
# The integration suite's largest message (an image) needs more than the 2 KB default.
run_configuration embedded -DCMAKE_BUILD_TYPE=Debug -DUBII_SANITIZE=ON -DUBII_PORT=embedded \
  -DUBII_EMBEDDED_MAX_MESSAGE=16384
# ThreadSanitizer for what runs threads: the processing modules' worker executor (C++ layer).
TARGETS="ubii_npm_packages cpp_scheduler_test cpp_processing_module_test" \
TESTS="SchedulerTest|StandaloneModule|ProcessingModule|TimingMetric" \
  run_configuration tsan -DCMAKE_BUILD_TYPE=Debug -DUBII_SANITIZE_THREAD=ON
echo "=== all configurations passed in $((SECONDS - started)) s"
