#!/usr/bin/env bash
# The C++ layer's cost over the C core: pubsub_bench (C) and cpp_pubsub_bench (C++), alternately,
# each against a freshly started local master, REPEATS times per mode and transport (reacting to
# every message; pumped once per 60 Hz frame), over the in-thread ZMQ engine and WebSocket.
# Prints every run's CPU µs per message and the medians' ratio C++/C. Asserts nothing.
#   bench/cpp_overhead.sh [REPEATS [MESSAGES]]    defaults 5 20000
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build="${UBII_BUILD_DIR:-$root/build}/bench"
repeats=${1:-5} messages=${2:-20000}

"$root/scripts/bootstrap.sh" >/dev/null
"$root/scripts/npm-packages.sh" >/dev/null
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DUBII_BUILD_BENCH=ON -DUBII_BUILD_TESTS=OFF \
  -DUBII_BUILD_EXAMPLES=OFF -DUBII_WITH_CPP=ON >/dev/null
cmake --build "$build" -j "$(nproc)" --target pubsub_bench cpp_pubsub_bench >/dev/null

exec "$root/scripts/private-net.sh" bash -c '
  set -euo pipefail
  root=$1 build=$2 repeats=$3 messages=$4
  state=$(mktemp -d)
  trap "\"$root/scripts/master.sh\" stop \"\$state\" >/dev/null 2>&1; rm -rf \"\$state\"" EXIT
  run() { # NAME BINARY TOPIC_URL ROUNDS WINDOW [FRAME_US]
    "$root/scripts/master.sh" start "$state" >/dev/null
    echo "$1 $("$build/bench/$2" tcp://127.0.0.1:8101 "$3" "$4" "$messages" "$5" ${6:-})"
    "$root/scripts/master.sh" stop "$state" >/dev/null
  }
  {
    for i in $(seq "$repeats"); do
      for transport in zmq=tcp://127.0.0.1:8103 websocket=ws://127.0.0.1:8104; do
        name=${transport%%=*} url=${transport#*=}
        run "c-$name-reactive" pubsub_bench "$url" 200 100
        run "cpp-$name-reactive" cpp_pubsub_bench "$url" 200 100
        run "c-$name-60Hz" pubsub_bench "$url" 10 1000 16667
        run "cpp-$name-60Hz" cpp_pubsub_bench "$url" 10 1000 16667
      done
    done
  } | awk "
    { split(\$1, part, \"-\"); key = part[2] \" \" part[3]; lang = part[1]
      for (i = 2; i <= NF; i++) { split(\$i, kv, \"=\"); if (kv[1] == \"cpu_us_per_message\") cpu = kv[2]
        if (kv[1] == \"messages_per_s\") rate = kv[2] }
      n[lang, key]++; runs[lang, key, n[lang, key]] = cpu; keys[key] = 1
      printf \"%-4s %-20s cpu_us_per_message=%s messages_per_s=%s\\n\", lang, key, cpu, rate }
    function median(lang, key,   i, j, t, m, a) {
      m = n[lang, key]; for (i = 1; i <= m; i++) a[i] = runs[lang, key, i]
      for (i = 1; i <= m; i++) for (j = i + 1; j <= m; j++) if (a[j] < a[i]) { t = a[i]; a[i] = a[j]; a[j] = t }
      return m % 2 ? a[(m + 1) / 2] : (a[m / 2] + a[m / 2 + 1]) / 2 }
    END { print \"\"; print \"median CPU µs per message (whole process), C++ / C:\"
      for (key in keys) printf \"  %-20s C %.2f  C++ %.2f  ratio %.3f\\n\", key, median(\"c\", key), median(\"cpp\", key), median(\"cpp\", key) / median(\"c\", key) }"
' overhead "$root" "$build" "$repeats" "$messages"
