#!/usr/bin/env bash
# Pub/sub benchmark: libubii over ZMQ and over WebSocket, on the Linux port (its default in-thread
# ZMTP engine or libzmq, libwebsockets) and on the embedded port (its own ZMTP and WebSocket code),
# beside the official Node.js node, each against a freshly started local master, in one run, with
# ratios.
# Prints a table; asserts nothing.
#   bench/run.sh [ROUNDS [MESSAGES [WINDOW]]]    defaults 2000 20000 100
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build="${UBII_BUILD_DIR:-$root/build}/bench"
embedded_build="${UBII_BUILD_DIR:-$root/build}/bench-embedded"
cache=${UBII_CACHE_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/libubii}
rounds=${1:-2000} messages=${2:-20000} window=${3:-100}

"$root/scripts/bootstrap.sh" >/dev/null
"$root/scripts/npm-packages.sh" >/dev/null
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DUBII_BUILD_BENCH=ON -DUBII_BUILD_TESTS=OFF \
  -DUBII_BUILD_EXAMPLES=OFF >/dev/null
cmake --build "$build" -j "$(nproc)" --target pubsub_bench >/dev/null
cmake -S "$root" -B "$embedded_build" -DCMAKE_BUILD_TYPE=Release -DUBII_PORT=embedded \
  -DUBII_BUILD_BENCH=ON -DUBII_BUILD_TESTS=OFF -DUBII_BUILD_EXAMPLES=OFF >/dev/null
cmake --build "$embedded_build" -j "$(nproc)" --target pubsub_bench >/dev/null

exec "$root/scripts/private-net.sh" bash -c '
  set -euo pipefail
  root=$1 build=$2 embedded_build=$3 cache=$4 rounds=$5 messages=$6 window=$7
  state=$(mktemp -d)
  trap "\"$root/scripts/master.sh\" stop \"\$state\" >/dev/null 2>&1; rm -rf \"\$state\"" EXIT
  client="$cache/npm/node-client/node_modules/@tum-far/ubii-node-nodejs"
  # Each client gets a master of its own, freshly started: a master that has served earlier
  # clients can be slower (the npm 0.4.0 master kept forwarding to every client that left
  # subscribed), which would favour whichever client runs first.
  run() {
    "$root/scripts/master.sh" start "$state" >/dev/null
    echo "$1 $(eval "$2")"
    "$root/scripts/master.sh" stop "$state" >/dev/null
  }
  {
    run "libubii-zmq" "\"$build/bench/pubsub_bench\" tcp://127.0.0.1:8101 tcp://127.0.0.1:8103 $rounds $messages $window"
    run "libubii-websocket" "\"$build/bench/pubsub_bench\" tcp://127.0.0.1:8101 ws://127.0.0.1:8104 $rounds $messages $window"
    run "libubii-zmq-libzmq" "UBII_BENCH_ZMQ_ENGINE=libzmq \"$build/bench/pubsub_bench\" tcp://127.0.0.1:8101 tcp://127.0.0.1:8103 $rounds $messages $window"
    run "embedded-zmtp" "\"$embedded_build/bench/pubsub_bench\" tcp://127.0.0.1:8101 tcp://127.0.0.1:8103 $rounds $messages $window"
    run "embedded-websocket" "\"$embedded_build/bench/pubsub_bench\" tcp://127.0.0.1:8101 ws://127.0.0.1:8104 $rounds $messages $window"
    # The same clients polled once per 60 Hz frame, as a game engine pumps them (the Node.js
    # node has no such mode: its event loop reacts to every arrival).
    frame=16667 frame_window=$((window * 10))
    run "libubii-zmq@60Hz" "\"$build/bench/pubsub_bench\" tcp://127.0.0.1:8101 tcp://127.0.0.1:8103 10 $messages $frame_window $frame"
    run "libubii-websocket@60Hz" "\"$build/bench/pubsub_bench\" tcp://127.0.0.1:8101 ws://127.0.0.1:8104 10 $messages $frame_window $frame"
    run "libubii-zmq-libzmq@60Hz" "UBII_BENCH_ZMQ_ENGINE=libzmq \"$build/bench/pubsub_bench\" tcp://127.0.0.1:8101 tcp://127.0.0.1:8103 10 $messages $frame_window $frame"
    run "embedded-zmtp@60Hz" "\"$embedded_build/bench/pubsub_bench\" tcp://127.0.0.1:8101 tcp://127.0.0.1:8103 10 $messages $frame_window $frame"
    run "embedded-websocket@60Hz" "\"$embedded_build/bench/pubsub_bench\" tcp://127.0.0.1:8101 ws://127.0.0.1:8104 10 $messages $frame_window $frame"
    run "nodejs-zmq" "node \"$root/bench/nodejs_bench.js\" \"$client\" tcp://127.0.0.1:8101 tcp://127.0.0.1:8103 $rounds $messages $window | sed -n \"s/^RESULT //p\""
    run "nodejs-websocket" "node \"$root/bench/nodejs_bench.js\" \"$client\" tcp://127.0.0.1:8101 ws://127.0.0.1:8104 $rounds $messages $window | sed -n \"s/^RESULT //p\""
  } | awk -v rounds="$rounds" -v messages="$messages" -v window="$window" "
    { name[NR] = \$1; row[\$1] = NR; for (i = 2; i <= NF; i++) { split(\$i, kv, \"=\"); v[NR, kv[1]] = kv[2] } }
    function ratio(mine, theirs,   c, n, user) {
      c = row[mine]; n = row[theirs]
      if (!c || !n || v[c, \"cpu_us_per_message\"] <= 0) return
      # getrusage counts in clock ticks: a client that barely runs may show 0 user time.
      user = v[c, \"user_us_per_message\"] > 0 ? sprintf(\"%.1fx\", v[n, \"user_us_per_message\"] / v[c, \"user_us_per_message\"]) : \"n/a, 0 measured\"
      printf \"  %-27s vs %-16s cpu/msg %.1fx (user %s)   rtt p50 %.2fx   rtt p99 %.2fx   throughput %.2fx\n\", mine, theirs,
        v[n, \"cpu_us_per_message\"] / v[c, \"cpu_us_per_message\"], user,
        v[n, \"rtt_p50_us\"] / v[c, \"rtt_p50_us\"], v[n, \"rtt_p99_us\"] / v[c, \"rtt_p99_us\"],
        v[c, \"messages_per_s\"] / v[n, \"messages_per_s\"]
    }
    END {
      printf \"pub/sub through a local npm 0.4.0 master (a fresh one per client): %d round trips, %d messages (window %d)\n\", rounds, messages, window
      printf \"%-27s %10s %10s %10s %10s %10s %10s %10s\n\", \"client\", \"rtt p50 us\", \"rtt p99 us\", \"msgs/s\", \"cpu us/msg\", \"user us\", \"kernel us\", \"switch/msg\"
      for (r = 1; r <= NR; r++)
        printf \"%-27s %10s %10s %10s %10s %10s %10s %10s\n\", name[r], v[r, \"rtt_p50_us\"], v[r, \"rtt_p99_us\"], v[r, \"messages_per_s\"], v[r, \"cpu_us_per_message\"], v[r, \"user_us_per_message\"], v[r, \"system_us_per_message\"], v[r, \"switches_per_message\"]
      printf \"ratios, Node.js / libubii on the same transport (higher is better for libubii; throughput libubii / Node.js):\n\"
      ratio(\"libubii-zmq\", \"nodejs-zmq\"); ratio(\"libubii-zmq-libzmq\", \"nodejs-zmq\")
      ratio(\"libubii-websocket\", \"nodejs-websocket\")
      ratio(\"embedded-zmtp\", \"nodejs-zmq\"); ratio(\"embedded-websocket\", \"nodejs-websocket\")
      printf \"polled once per 60 Hz frame, window %d (latency columns of these rows are meaningless: they measure 10 round trips only):\n\", window * 10
      ratio(\"libubii-zmq@60Hz\", \"nodejs-zmq\"); ratio(\"libubii-zmq-libzmq@60Hz\", \"nodejs-zmq\")
      ratio(\"libubii-websocket@60Hz\", \"nodejs-websocket\")
      ratio(\"embedded-zmtp@60Hz\", \"nodejs-zmq\"); ratio(\"embedded-websocket@60Hz\", \"nodejs-websocket\")
      printf \"kernel time is loopback TCP to and from the master and thread wake-ups (switch/msg: context switches per message)\n\"
    }"
' bench "$root" "$build" "$embedded_build" "$cache" "$rounds" "$messages" "$window"
