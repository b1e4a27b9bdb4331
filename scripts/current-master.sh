#!/usr/bin/env bash
# Prepares the current Ubi-Interact master (ubii-node-master, develop) from a source checkout you
# provide, so that scripts/master.sh and the session tests can run it (UBII_MASTER_SOURCE=DIR).
# It is not on npm; this project never fetches, ships or runs it in CI. Its npm dependencies are
# installed into the checkout (TensorFlow's install scripts skipped, the ZeroMQ addon built
# against Debian's libzmq, as for the npm master). Idempotent.
#
#   current-master.sh SOURCE_DIR
set -euo pipefail
src=$(cd "${1:?usage: current-master.sh SOURCE_DIR}" && pwd)
[ -f "$src/src/index.js" ] && [ -f "$src/package.json" ] ||
  { echo "current-master.sh: $src is not a ubii-node-master checkout" >&2; exit 1; }
cd "$src"
# nan 2.30 builds the ZeroMQ addon on Node 20; devDependencies (ava, ...) are not needed to run it.
node -e '
  const fs = require("fs"); const p = JSON.parse(fs.readFileSync("package.json"));
  p.overrides = Object.assign({}, p.overrides, { nan: "2.30.0" }); delete p.devDependencies;
  fs.writeFileSync("package.json", JSON.stringify(p, null, 2) + "\n");'
stamp="current-master $(sha256sum package.json | cut -c1-16) v1"
[ "$(cat .ubii-stamp 2>/dev/null)" = "$stamp" ] && exit 0
rm -f package-lock.json
npm install --ignore-scripts --no-audit --no-fund >install.log 2>&1 || { cat install.log >&2; exit 1; }
npm_config_zmq_external=true npm_config_nodedir=/usr npm rebuild zeromq >rebuild.log 2>&1 ||
  { cat rebuild.log >&2; exit 1; }
echo "$stamp" > .ubii-stamp
echo "current-master.sh: $src is ready (UBII_MASTER_SOURCE=$src scripts/master.sh start STATE_DIR)"
