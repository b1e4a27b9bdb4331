#!/usr/bin/env bash
# Starts or stops http_services_bridge.js in the background (CTest fixture).
#   http_services_bridge.sh start STATE_DIR LISTEN_PORT MASTER_SERVICE_PORT ZEROMQ_MODULE_DIR
#                                 [CERT_PEM KEY_PEM]   (HTTPS)
#   http_services_bridge.sh stop STATE_DIR
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
state=${2:?}
mkdir -p "$state"
case "$1" in
  start)
    node "$here/http_services_bridge.js" "$3" "$4" "$5" "${@:6}" </dev/null >"$state/bridge.log" 2>&1 &
    echo $! >"$state/bridge.pid"
    for _ in $(seq 100); do
      grep -q 'bridge ready' "$state/bridge.log" && exit 0
      kill -0 "$(cat "$state/bridge.pid")" 2>/dev/null || break
      sleep 0.1
    done
    echo "http_services_bridge: did not start; its log:" >&2
    cat "$state/bridge.log" >&2
    exit 1
    ;;
  stop)
    [ -f "$state/bridge.pid" ] && kill "$(cat "$state/bridge.pid")" 2>/dev/null || true
    rm -f "$state/bridge.pid"
    ;;
esac
