#!/usr/bin/env bash
# Runs a command in a private network namespace that has only a loopback interface, so that the
# master (which binds every interface) is reachable from nowhere else. Where namespaces are not
# permitted, runs the command as it is and says so; everything then talks to 127.0.0.1 only.
#
#   private-net.sh COMMAND [ARGS...]
set -euo pipefail
[ $# -gt 0 ] || { echo "usage: private-net.sh COMMAND [ARGS...]" >&2; exit 2; }

if [ "${UBII_IN_PRIVATE_NET:-}" = 1 ]; then
  exec "$@"
fi

unshare_flags=(-n)
[ "$(id -u)" -eq 0 ] || unshare_flags=(-r -n)
if unshare "${unshare_flags[@]}" true 2>/dev/null; then
  export UBII_IN_PRIVATE_NET=1
  exec unshare "${unshare_flags[@]}" bash -c 'ip link set lo up && exec "$@"' private-net "$@"
fi
echo "private-net.sh: network namespaces are not permitted here; running on the host's loopback" >&2
exec "$@"
