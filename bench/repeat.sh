#!/usr/bin/env bash
# bench/run.sh RUNS times, then per client the median and range of CPU per message, and of the
# Node.js node's CPU per message over libubii's on the same transport, run by run (the ratio moves
# with the machine's load, the loopback's cost and how the Node.js node's event loop batches; one
# run's figure is no claim). Prints a table; asserts nothing.
#   bench/repeat.sh [RUNS [ROUNDS [MESSAGES [WINDOW]]]]    defaults 5 2000 20000 100
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
runs=${1:-5}
shift || true
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for run in $(seq "$runs"); do
  "$root/bench/run.sh" "$@" >"$out/run$run.txt"
  echo "bench/repeat.sh: run $run of $runs done" >&2
done
# Table rows: client, rtt p50, rtt p99, msgs/s, cpu us/msg, user, kernel, switches.
cat "$out"/run*.txt | awk -v runs="$runs" '
  NF == 8 && $1 ~ /^(libubii|embedded|nodejs)/ && $5 ~ /^[0-9.]+$/ {
    n[$1]++; cpu[$1, n[$1]] = $5
    if (!($1 in order)) { order[$1] = ++clients; name[clients] = $1 }
  }
  function sort(a, k,   i, j, t) { for (i = 2; i <= k; i++) for (j = i; j > 1 && a[j - 1] > a[j]; j--) { t = a[j]; a[j] = a[j - 1]; a[j - 1] = t } }
  function median(a, k) { return k % 2 ? a[(k + 1) / 2] : (a[k / 2] + a[k / 2 + 1]) / 2 }
  END {
    printf "%d runs of bench/run.sh; CPU us per message (median, min-max) and Node.js / libubii on the same transport, run by run\n\n", runs
    printf "| client | CPU us/msg median | range | Node.js / this, median | range |\n|---|---|---|---|---|\n"
    for (c = 1; c <= clients; c++) {
      m = name[c]; k = n[m]
      for (i = 1; i <= k; i++) own[i] = cpu[m, i]
      sort(own, k)
      node = (m ~ /websocket/) ? "nodejs-websocket" : "nodejs-zmq"
      line = sprintf("| %s | %.2f | %.2f-%.2f |", m, median(own, k), own[1], own[k])
      if (m !~ /^nodejs/ && n[node] == k) {
        for (i = 1; i <= k; i++) ratio[i] = cpu[node, i] / cpu[m, i]
        sort(ratio, k)
        line = line sprintf(" %.1fx | %.1f-%.1fx |", median(ratio, k), ratio[1], ratio[k])
      } else line = line " | |"
      print line
    }
  }'
