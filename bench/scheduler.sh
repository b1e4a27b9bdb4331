#!/usr/bin/env bash
# Processing-module timing: bench/scheduler_bench.cpp against a freshly started local master in a
# private network namespace. Prints a table beside the thesis's Table 3.1; asserts nothing.
#   bench/scheduler.sh [SECONDS_PER_RATE [LOAD_MSG_PER_S]]    defaults 10 2000
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build="${UBII_BUILD_DIR:-$root/build}/bench"
seconds=${1:-10} load=${2:-2000}

"$root/scripts/bootstrap.sh" >/dev/null
"$root/scripts/npm-packages.sh" >/dev/null
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DUBII_BUILD_BENCH=ON -DUBII_BUILD_TESTS=OFF \
  -DUBII_BUILD_EXAMPLES=OFF -DUBII_WITH_CPP=ON >/dev/null
cmake --build "$build" -j "$(nproc)" --target scheduler_bench >/dev/null

exec "$root/scripts/private-net.sh" bash -c '
  set -euo pipefail
  root=$1 build=$2 seconds=$3 load=$4
  state=$(mktemp -d)
  trap "\"$root/scripts/master.sh\" stop \"\$state\" >/dev/null 2>&1; rm -rf \"\$state\"" EXIT
  "$root/scripts/master.sh" start "$state" >/dev/null
  "$build/bench/scheduler_bench" tcp://127.0.0.1:8101 tcp://127.0.0.1:8103 "$seconds" "$load"
' _ "$root" "$build" "$seconds" "$load"
