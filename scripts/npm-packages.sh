#!/usr/bin/env bash
# Installs the npm packages the tests and the demo use into CACHE/npm (default: $UBII_CACHE_DIR or
# ~/.cache/libubii), each in a folder of its own, and builds their ZeroMQ addons against Debian's
# libzmq. Idempotent: a folder whose stamp matches is left alone. Needs the npm registry, so run it
# before entering a private network namespace.
#
#   master       @tum-far/ubii-nodejs-backend@0.4.0 (the master node)
#   node-client  @tum-far/ubii-node-nodejs@0.4.2    (the official Node.js client node)
#   msg-formats  @tum-far/ubii-msg-formats@0.16.6   (reference schema and protobufjs code)
set -euo pipefail

cache=${1:-${UBII_CACHE_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/libubii}}
root="$cache/npm"
mkdir -p "$root"

# Install scripts of these packages download prebuilt binaries (TensorFlow, ZeroMQ) from the internet,
# which is not reachable here and not needed: the one native addon needed is rebuilt below.
install_package() {
  local folder=$1 package=$2 overrides=$3 stamp
  stamp="$package $overrides v2"
  if [ "$(cat "$root/$folder/.ubii-stamp" 2>/dev/null)" = "$stamp" ]; then
    return 0
  fi
  echo "npm-packages: installing $package into $root/$folder"
  rm -rf "$root/$folder"
  mkdir -p "$root/$folder"
  local name=${package%@*} version=${package##*@}
  cat > "$root/$folder/package.json" <<JSON
{ "name": "ubii-test-$folder", "private": true,
  "dependencies": { "$name": "$version" }, "overrides": { $overrides } }
JSON
  (cd "$root/$folder" &&
    npm install --ignore-scripts --no-audit --no-fund --loglevel=error >install.log 2>&1 ||
    { cat install.log >&2; exit 1; })
  if [ -d "$root/$folder/node_modules/zeromq" ]; then
    (cd "$root/$folder" &&
      npm_config_zmq_external=true npm_config_nodedir=/usr npm rebuild zeromq >rebuild.log 2>&1 ||
      { cat rebuild.log >&2; exit 1; })
  fi
  echo "$stamp" > "$root/$folder/.ubii-stamp"
}

install_package master @tum-far/ubii-nodejs-backend@0.4.0 ''
# The client's ZeroMQ addon only compiles on Node 20 with a newer nan.
install_package node-client @tum-far/ubii-node-nodejs@0.4.2 '"nan": "2.30.0"'
install_package msg-formats @tum-far/ubii-msg-formats@0.16.6 ''
echo "npm-packages: ready in $root"
