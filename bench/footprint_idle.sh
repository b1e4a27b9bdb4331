#!/usr/bin/env bash
# Idle footprint: a connected, subscribed, idle node's memory, read from /proc/PID/smaps after it
# has idled IDLE seconds, for libubii (Linux port: in-thread ZMTP, libzmq, WebSocket; embedded
# port: ZMTP) and the official Node.js node, each against a freshly started local master. Prints RSS, PSS and private memory per node,
# then where libubii's in-thread node's resident memory lies (its own binary, each library, heap,
# stacks, other anonymous memory). Asserts nothing.
#   bench/footprint_idle.sh [IDLE]    default 3 s
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build="${UBII_BUILD_DIR:-$root/build}/bench"
embedded_build="${UBII_BUILD_DIR:-$root/build}/bench-embedded"
cache=${UBII_CACHE_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/libubii}
idle=${1:-3}

"$root/scripts/bootstrap.sh" >/dev/null
"$root/scripts/npm-packages.sh" >/dev/null
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DUBII_BUILD_BENCH=ON -DUBII_BUILD_TESTS=OFF \
  -DUBII_BUILD_EXAMPLES=OFF >/dev/null
cmake --build "$build" -j "$(nproc)" --target idle_node >/dev/null
cmake -S "$root" -B "$embedded_build" -DCMAKE_BUILD_TYPE=Release -DUBII_PORT=embedded \
  -DUBII_BUILD_BENCH=ON -DUBII_BUILD_TESTS=OFF -DUBII_BUILD_EXAMPLES=OFF >/dev/null
cmake --build "$embedded_build" -j "$(nproc)" --target idle_node >/dev/null

exec "$root/scripts/private-net.sh" bash -c '
  set -euo pipefail
  root=$1 build=$2 cache=$3 idle=$4 embedded_build=$5
  state=$(mktemp -d)
  trap "\"$root/scripts/master.sh\" stop \"\$state\" >/dev/null 2>&1; rm -rf \"\$state\"" EXIT
  client="$cache/npm/node-client/node_modules/@tum-far/ubii-node-nodejs"
  # kB summed over every mapping of PID: Rss, Pss, Private_Clean + Private_Dirty
  totals() {
    awk "/^Rss:/ {r += \$2} /^Pss:/ {p += \$2} /^Private_(Clean|Dirty):/ {v += \$2}
         END {printf \"%.1f %.1f %.1f\", r / 1024, p / 1024, v / 1024}" "/proc/$1/smaps"
  }
  # Resident kB per mapping: the file it maps, or [heap], [stack], anonymous
  by_mapping() {
    awk "/^[0-9a-f]+-[0-9a-f]+ / { name = (NF >= 6) ? \$6 : \"anonymous\" }
         /^Rss:/ { rss[name] += \$2 } /^Private_(Clean|Dirty):/ { own[name] += \$2 }
         END { for (n in rss) if (rss[n] > 0) printf \"%8d %8d  %s\n\", rss[n], own[n], n }" \
      "/proc/$1/smaps" | sort -rn
  }
  measure() { # NAME COMMAND...
    local name=$1; shift
    "$root/scripts/master.sh" start "$state" >/dev/null
    local out; out=$(mktemp)
    "$@" >"$out" 2>&1 &
    local pid=$!
    for _ in $(seq 100); do grep -q ": ready" "$out" && break; sleep 0.1; done
    grep -q ": ready" "$out" || { echo "$name did not connect:"; cat "$out"; kill $pid; exit 1; }
    sleep "$idle"
    read -r rss pss private <<<"$(totals $pid)"
    printf "| %s | %s | %s | %s |\n" "$name" "$rss" "$pss" "$private"
    [ "$name" = "libubii-zmq" ] && by_mapping $pid >"$state/by_mapping"
    kill $pid; wait $pid 2>/dev/null || true
    rm -f "$out"
    "$root/scripts/master.sh" stop "$state" >/dev/null
  }
  echo "idle ${idle} s after connecting and subscribing; MiB"
  echo
  echo "| node | RSS | PSS | private |"
  echo "|---|---|---|---|"
  measure libubii-zmq "$build/bench/idle_node" tcp://127.0.0.1:8101 tcp://127.0.0.1:8103
  measure libubii-zmq-libzmq "$build/bench/idle_node" tcp://127.0.0.1:8101 tcp://127.0.0.1:8103 libzmq
  measure libubii-websocket "$build/bench/idle_node" tcp://127.0.0.1:8101 ws://127.0.0.1:8104
  measure libubii-embedded-zmtp "$embedded_build/bench/idle_node" tcp://127.0.0.1:8101 tcp://127.0.0.1:8103
  measure nodejs-zmq node "$root/bench/idle_nodejs.js" "$client" tcp://127.0.0.1:8101 tcp://127.0.0.1:8103
  echo
  echo "libubii-zmq by mapping (kB resident, kB private):"
  cat "$state/by_mapping"
' footprint "$root" "$build" "$cache" "$idle" "$embedded_build"
