#!/usr/bin/env bash
# Starts and stops a real Ubi-Interact master node (npm @tum-far/ubii-nodejs-backend@0.4.0) for tests
# and demos. The master binds every interface; run it inside scripts/private-net.sh.
#
#   master.sh start STATE_DIR [PORT_BASE]  start in the background, return once it is ready
#                                          (ports PORT_BASE..PORT_BASE+3, default 8101..8104)
#   master.sh stop STATE_DIR               stop the master started in STATE_DIR
#   master.sh run STATE_DIR [PORT_BASE]    run in the foreground until interrupted
#
# The package comes from scripts/npm-packages.sh (UBII_CACHE_DIR). A master that does not report
# ready within UBII_MASTER_START_TIMEOUT seconds (default 20) is killed and its log printed.
# UBII_MASTER_TLS=1 serves WebSocket and HTTP over TLS (wss://, https://) with a self-signed
# certificate made in STATE_DIR. UBII_MASTER_SOURCE=DIR runs the current master from a checkout
# that scripts/current-master.sh prepared, instead of the npm package.
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
cache=${UBII_CACHE_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/libubii}
install_dir=${UBII_MASTER_SOURCE:-$cache/npm/master}
start_timeout=${UBII_MASTER_START_TIMEOUT:-20}
bind_errors='Address already in use|EADDRINUSE|EACCES'

usage() { sed -n '2,14p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; }

prepare() {
  local state=$1 base=$2
  if [ ! -f "$install_dir/.ubii-stamp" ]; then
    echo "master.sh: the master is not installed in $install_dir; run scripts/npm-packages.sh (or" \
      "scripts/current-master.sh for UBII_MASTER_SOURCE) first" >&2
    exit 1
  fi
  mkdir -p "$state/home"
  local https='"enabled": false'
  if [ "${UBII_MASTER_TLS:-0}" = 1 ]; then
    # A client checks an IP address against the subjectAltName only (never the CN).
    openssl req -x509 -newkey rsa:2048 -nodes -days 2 -subj /CN=127.0.0.1 \
      -addext "subjectAltName=IP:127.0.0.1,DNS:localhost" \
      -keyout "$state/key.pem" -out "$state/cert.pem" >/dev/null 2>&1
    openssl rsa -in "$state/key.pem" -pubout -out "$state/public.pem" >/dev/null 2>&1
    https="\"enabled\": true, \"pathCert\": \"$state/cert.pem\", \"pathPrivateKey\": \"$state/key.pem\", \"pathPublicKey\": \"$state/public.pem\""
  fi
  # https.enabled must be given: the master treats a missing key as true. allowedHosts and
  # profiling are the current master's (the npm one ignores them).
  cat > "$state/config.json" <<JSON
{ "ports": { "serviceZMQ": $base, "serviceREST": $((base + 1)),
             "topicdataZMQ": $((base + 2)), "topicdataWS": $((base + 3)) },
  "ipc": { "ipcEndpointTopicData": "/ubii-ipc-topicdata" },
  "https": { $https, "allowedOrigins": [] },
  "allowedHosts": [".*"], "profiling": { "enabled": false } }
JSON
}

# The master writes its database under $HOME and an IPC socket into its working directory.
launch() {
  local state=$1
  # The current master reads config.json beside its node_modules, not in its working directory:
  # one master at a time per checkout.
  [ -z "${UBII_MASTER_SOURCE:-}" ] || cp "$state/config.json" "$install_dir/config.json"
  cd "$state"
  HOME="$state/home" PWD="$state" exec node --no-warnings "$here/master/launch-master.js" "$install_dir"
}

# True if PID is a master this script launched (not a reused process id).
is_master() {
  grep -q launch-master "/proc/$1/cmdline" 2>/dev/null
}

stop_pid() {
  local pid=$1
  kill -TERM "$pid" 2>/dev/null || return 0
  for _ in $(seq 50); do
    kill -0 "$pid" 2>/dev/null || return 0
    sleep 0.1
  done
  echo "master.sh: master $pid ignored SIGTERM for 5 s; killing it" >&2
  kill -KILL "$pid" 2>/dev/null || true
}

case "${1:-}" in
  start)
    state=$(mkdir -p "${2:?$(usage)}" && cd "$2" && pwd)
    base=${3:-8101}
    if [ -f "$state/master.pid" ] && is_master "$(cat "$state/master.pid")"; then
      echo "master.sh: a master is already running from $state (pid $(cat "$state/master.pid"))" >&2
      exit 1
    fi
    prepare "$state" "$base"
    (launch "$state") </dev/null >"$state/master.log" 2>&1 &
    pid=$!
    echo "$pid" > "$state/master.pid"
    deadline=$((SECONDS + start_timeout))
    while [ $SECONDS -lt $deadline ]; do
      if grep -q 'status=ready' "$state/master.log" 2>/dev/null; then
        # The master reports ready even when a ZMQ bind failed, and the HTTP server's EADDRINUSE
        # arrives a moment later: give both time to show before calling it ready.
        sleep 0.5
        if kill -0 "$pid" 2>/dev/null && ! grep -qE "$bind_errors" "$state/master.log"; then
          echo "master.sh: master ready (pid $pid, ports $base-$((base + 3)))"
          exit 0
        fi
        break
      fi
      if ! kill -0 "$pid" 2>/dev/null || grep -q 'status=failed' "$state/master.log"; then
        break
      fi
      sleep 0.1
    done
    echo "master.sh: the master did not start cleanly on ports $base-$((base + 3)) (limit ${start_timeout} s); its log:" >&2
    tail -n 40 "$state/master.log" >&2
    stop_pid "$pid"
    rm -f "$state/master.pid"
    exit 1
    ;;
  stop)
    state=${2:?$(usage)}
    if [ -f "$state/master.pid" ] && is_master "$(cat "$state/master.pid")"; then
      stop_pid "$(cat "$state/master.pid")"
      rm -f "$state/master.pid"
      echo "master.sh: master stopped"
    fi
    ;;
  run)
    state=$(mkdir -p "${2:?$(usage)}" && cd "$2" && pwd)
    prepare "$state" "${3:-8101}"
    launch "$state"
    ;;
  *) usage ;;
esac
