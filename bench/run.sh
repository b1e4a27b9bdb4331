#!/usr/bin/env bash
# Pub/sub benchmark: libubii over ZMQ and over WebSocket beside the official Node.js node, all
# against the same local master in one run, with ratios. Prints a table; asserts nothing.
#   bench/run.sh [ROUNDS [MESSAGES [WINDOW]]]    defaults 2000 20000 100
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build="${UBII_BUILD_DIR:-$root/build}/bench"
cache=${UBII_CACHE_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/libubii}
rounds=${1:-2000} messages=${2:-20000} window=${3:-100}

"$root/scripts/bootstrap.sh" >/dev/null
"$root/scripts/npm-packages.sh" >/dev/null
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DUBII_BUILD_BENCH=ON -DUBII_BUILD_TESTS=OFF \
  -DUBII_BUILD_EXAMPLES=OFF >/dev/null
cmake --build "$build" -j "$(nproc)" --target pubsub_bench >/dev/null

exec "$root/scripts/private-net.sh" bash -c '
  set -euo pipefail
  root=$1 build=$2 cache=$3 rounds=$4 messages=$5 window=$6
  state=$(mktemp -d)
  trap "\"$root/scripts/master.sh\" stop \"\$state\" >/dev/null; rm -rf \"\$state\"" EXIT
  "$root/scripts/master.sh" start "$state" >/dev/null
  client="$cache/npm/node-client/node_modules/@tum-far/ubii-node-nodejs"
  run() { echo "$1 $(eval "$2")"; }
  {
    run "libubii-zmq" "\"$build/bench/pubsub_bench\" tcp://127.0.0.1:8101 tcp://127.0.0.1:8103 $rounds $messages $window"
    run "libubii-websocket" "\"$build/bench/pubsub_bench\" tcp://127.0.0.1:8101 ws://127.0.0.1:8104 $rounds $messages $window"
    run "nodejs-zmq" "node \"$root/bench/nodejs_bench.js\" \"$client\" tcp://127.0.0.1:8101 tcp://127.0.0.1:8103 $rounds $messages $window | sed -n \"s/^RESULT //p\""
    run "nodejs-websocket" "node \"$root/bench/nodejs_bench.js\" \"$client\" tcp://127.0.0.1:8101 ws://127.0.0.1:8104 $rounds $messages $window | sed -n \"s/^RESULT //p\""
  } | awk -v rounds="$rounds" -v messages="$messages" -v window="$window" "
    { name[NR] = \$1; for (i = 2; i <= NF; i++) { split(\$i, kv, \"=\"); v[NR, kv[1]] = kv[2] } }
    END {
      printf \"pub/sub through one local npm 0.4.0 master: %d round trips, %d messages (window %d)\n\", rounds, messages, window
      printf \"%-18s %11s %11s %11s %12s %12s %12s\n\", \"client\", \"rtt p50 us\", \"rtt p99 us\", \"messages/s\", \"cpu us/msg\", \"user us/msg\", \"kernel us/msg\"
      for (r = 1; r <= NR; r++)
        printf \"%-18s %11s %11s %11s %12s %12s %12s\n\", name[r], v[r, \"rtt_p50_us\"], v[r, \"rtt_p99_us\"], v[r, \"messages_per_s\"], v[r, \"cpu_us_per_message\"], v[r, \"user_us_per_message\"], v[r, \"system_us_per_message\"]
      printf \"ratios, Node.js / libubii (same transport):\n\"
      for (t = 1; t <= 2; t++) {
        c = t; n = t + 2
        if (v[c, \"cpu_us_per_message\"] > 0 && v[n, \"cpu_us_per_message\"] > 0 && v[c, \"user_us_per_message\"] > 0)
          printf \"  %-10s cpu/msg %.1fx (user %.1fx)   rtt p50 %.2fx   rtt p99 %.2fx   throughput libubii/Node.js %.2fx\n\", (t == 1 ? \"zmq\" : \"websocket\"),
            v[n, \"cpu_us_per_message\"] / v[c, \"cpu_us_per_message\"], v[n, \"user_us_per_message\"] / v[c, \"user_us_per_message\"],
            v[n, \"rtt_p50_us\"] / v[c, \"rtt_p50_us\"], v[n, \"rtt_p99_us\"] / v[c, \"rtt_p99_us\"],
            v[c, \"messages_per_s\"] / v[n, \"messages_per_s\"]
      }
      printf \"kernel time is loopback TCP to and from the master (and thread wake-ups), paid by both clients alike\n\"
    }"
' bench "$root" "$build" "$cache" "$rounds" "$messages" "$window"
