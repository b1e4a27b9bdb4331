#!/usr/bin/env bash
# The main job: installs what is missing, builds libubii, starts a local Ubi-Interact master in a
# private network namespace and runs nodes against it, then stops the master. First OCR:
#   ocr          `ubii-node run` serves the OCR plugin's TesseractOCR_PURE and TextDetection_DB;
#                ocr_session_cpp publishes generated scenes and prints the words that come back,
#                with each module's time per frame. With the current master
#                (UBII_CURRENT_MASTER_SOURCE=DIR) the modules run in a session the master assigns;
#                the npm master assigns none, so there `ubii-node run --wire` runs them itself.
# Then the shorter examples:
#   hello        the master's server configuration
#   pubsub       two nodes exchanging records over ZMQ, then over WebSocket
#   engine_tick  a 60 Hz frame loop driving a node through its file descriptors
#   services     the master's services, topics and clients
#   pubsub_cpp, services_cpp   the same two in C++ (the C++ layer, cpp/)
#   processing_module_cpp      a processing module wired to topics, with its timing metric
#   session_cpp  a session: the master assigns a module to a node (only with the current master,
#                which is not on npm: UBII_CURRENT_MASTER_SOURCE=DIR, a checkout of ubii-node-master;
#                scripts/current-master.sh prepares it)
#
#   scripts/run.sh             build tree in ./build/run
#   UBII_BUILD_DIR=DIR ...     build tree below DIR instead
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
build="${UBII_BUILD_DIR:-$root/build}/run"

"$root/scripts/bootstrap.sh"
"$root/scripts/npm-packages.sh"
"$root/scripts/ocr-models.sh" >/dev/null
cmake -S "$root" -B "$build" -DUBII_BUILD_EXAMPLES=ON -DUBII_BUILD_TESTS=OFF -DUBII_WITH_OCR=ON \
  >/dev/null
cmake --build "$build" -j "$(nproc 2>/dev/null || echo 2)" >/dev/null

exec "$root/scripts/private-net.sh" bash -c '
  set -euo pipefail
  root=$1 build=$2 source=$3 state=$(mktemp -d) current=""
  cleanup() {
    "$root/scripts/master.sh" stop "$state" >/dev/null
    [ -z "$current" ] || UBII_MASTER_SOURCE="$source" "$root/scripts/master.sh" stop "$current" >/dev/null
    rm -rf "$state" $current
  }
  trap cleanup EXIT
  # ocr SERVICE_URL TOPIC_URL [--session]: the OCR modules served by ubii-node run, fed by
  # ocr_session_cpp; the node is stopped with SIGINT (it deregisters) afterwards.
  ocr() {
    local wires=() log="$state/ubii-node-run.log"
    if [ "${3:-}" != "--session" ]; then
      for module in TesseractOCR_PURE TextDetection_DB; do
        wires+=(--wire "$module:image=/demo/ocr/image" --wire "$module:objects=/demo/ocr/words/$module"
                --wire "$module:error=/demo/ocr/errors")
      done
    fi
    OMP_THREAD_LIMIT=1 "$build/cpp/cli/ubii-node" --service-url "$1" --topic-url "$2" run \
      TesseractOCR_PURE TextDetection_DB "${wires[@]}" >"$log" 2>&1 &
    local node=$! waited=0
    until grep -q "connected as client" "$log"; do
      sleep 0.2; waited=$((waited + 1))
      if [ $waited -gt 100 ] || ! kill -0 $node 2>/dev/null; then cat "$log"; return 1; fi
    done
    local status=0
    "$build"/examples/ocr_session_cpp "$1" "$2" ${3:+"$3"} || status=$?
    kill -INT $node; wait $node || status=$?
    [ $status -eq 0 ] || cat "$log"
    return $status
  }
  "$1/scripts/master.sh" start "$state"
  echo "=== ocr: TesseractOCR_PURE and TextDetection_DB served by ubii-node run (npm master: --wire)"
  ocr tcp://127.0.0.1:8101 tcp://127.0.0.1:8103
  for step in "hello tcp://127.0.0.1:8101" \
              "pubsub tcp://127.0.0.1:8101 tcp://127.0.0.1:8103 2" \
              "pubsub tcp://127.0.0.1:8101 ws://127.0.0.1:8104 2" \
              "engine_tick tcp://127.0.0.1:8101 tcp://127.0.0.1:8103 3" \
              "services tcp://127.0.0.1:8101 tcp://127.0.0.1:8103" \
              "pubsub_cpp tcp://127.0.0.1:8101 ws://127.0.0.1:8104 2" \
              "services_cpp tcp://127.0.0.1:8101 tcp://127.0.0.1:8103" \
              "processing_module_cpp tcp://127.0.0.1:8101 tcp://127.0.0.1:8103 3"; do
    echo "=== $step"
    "$2"/examples/$step
  done
  if [ -n "$3" ]; then
    "$1/scripts/current-master.sh" "$3"
    current=$(mktemp -d)
    UBII_MASTER_SOURCE="$3" "$1/scripts/master.sh" start "$current" 8401
    echo "=== ocr in a session the current master assigns to ubii-node run"
    ocr tcp://127.0.0.1:8401 tcp://127.0.0.1:8403 --session
    echo "=== session_cpp tcp://127.0.0.1:8401 tcp://127.0.0.1:8403"
    "$2"/examples/session_cpp tcp://127.0.0.1:8401 tcp://127.0.0.1:8403
  else
    echo "=== session_cpp: skipped (sessions need the current master: UBII_CURRENT_MASTER_SOURCE=DIR)"
  fi
' run "$root" "$build" "${UBII_CURRENT_MASTER_SOURCE:-}"
