#!/usr/bin/env bash
# Soak run: bench/soak.c through a freshly started local master, over ZMQ and then over WebSocket,
# in a private network namespace. Prints soak's progress lines and its summary per transport;
# the exit status says whether anything was lost, duplicated or reordered.
#   bench/soak.sh [SECONDS [RATE [TRANSPORTS]]]    defaults 3600 s, 1000 Hz, "zmq websocket"
# (CI runs 30 s over ZMQ: the soak_short test)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build="${UBII_BUILD_DIR:-$root/build}/bench"
seconds=${1:-3600} rate=${2:-1000} transports=${3:-zmq websocket}

"$root/scripts/bootstrap.sh" >/dev/null
"$root/scripts/npm-packages.sh" >/dev/null
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DUBII_BUILD_BENCH=ON -DUBII_BUILD_TESTS=OFF \
  -DUBII_BUILD_EXAMPLES=OFF >/dev/null
cmake --build "$build" -j "$(nproc)" --target soak >/dev/null

exec "$root/scripts/private-net.sh" bash -c '
  set -euo pipefail
  root=$1 build=$2 seconds=$3 rate=$4 transports=$5
  state=$(mktemp -d)
  trap "\"$root/scripts/master.sh\" stop \"\$state\" >/dev/null 2>&1; rm -rf \"\$state\"" EXIT
  status=0
  for transport in $transports; do
    case $transport in
      zmq) topic_url=tcp://127.0.0.1:8103 ;;
      websocket) topic_url=ws://127.0.0.1:8104 ;;
      *) echo "soak.sh: unknown transport $transport (zmq, websocket)" >&2; exit 2 ;;
    esac
    "$root/scripts/master.sh" start "$state" >/dev/null
    echo "== $topic_url, $seconds s at $rate Hz"
    "$build/bench/soak" tcp://127.0.0.1:8101 "$topic_url" "$seconds" "$rate" 60 300 || status=1
    "$root/scripts/master.sh" stop "$state" >/dev/null
  done
  exit $status
' soak "$root" "$build" "$seconds" "$rate" "$transports"
