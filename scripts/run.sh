#!/usr/bin/env bash
# The main job: installs what is missing, builds libubii, starts a local Ubi-Interact master in a
# private network namespace and runs a node against it (for now examples/c/hello, which fetches and
# prints the master's server configuration), then stops the master.
#
#   scripts/run.sh             build tree in ./build/run
#   UBII_BUILD_DIR=DIR ...     build tree below DIR instead
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
build="${UBII_BUILD_DIR:-$root/build}/run"

"$root/scripts/bootstrap.sh"
"$root/scripts/npm-packages.sh"
cmake -S "$root" -B "$build" -DUBII_BUILD_EXAMPLES=ON -DUBII_BUILD_TESTS=OFF >/dev/null
cmake --build "$build" -j "$(nproc 2>/dev/null || echo 2)" >/dev/null

exec "$root/scripts/private-net.sh" bash -c '
  set -euo pipefail
  state=$(mktemp -d)
  trap "\"$1/scripts/master.sh\" stop \"\$state\" >/dev/null; rm -rf \"\$state\"" EXIT
  "$1/scripts/master.sh" start "$state"
  "$2/examples/hello" tcp://127.0.0.1:8101
' run "$root" "$build"
