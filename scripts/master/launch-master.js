// Starts a master node without its own start script: the npm package
// (@tum-far/ubii-nodejs-backend@0.4.0), whose script loads TensorFlow that nothing the master runs
// needs, or a checkout of the current master (scripts/current-master.sh). Run with the working
// directory holding config.json. Usage: node launch-master.js <npm install folder | checkout>
'use strict';
const fs = require('fs');
const path = require('path');

const installDir = process.argv[2];
if (!installDir) {
  console.error('usage: launch-master.js <install folder | checkout>');
  process.exit(2);
}
const checkout = fs.existsSync(path.join(installDir, 'src', 'index.js'));
let backend;
if (checkout) {
  // The current master keeps its external libraries in the Node.js node's service.
  backend = path.join(installDir, 'src');
  const nodejsNode = path.join(installDir, 'node_modules', '@tum-far', 'ubii-node-nodejs', 'src', 'index');
  require(nodejsNode).ExternalLibrariesService.instance.addExternalLibrary('fs', fs);
} else {
  backend = path.join(installDir, 'node_modules', '@tum-far', 'ubii-nodejs-backend', 'src');
  require(path.join(backend, 'sessions', 'externalLibrariesService')).addExternalLibrary('fs', fs);
}

const { MasterNode } = require(path.join(backend, 'index.js'));
const master = new MasterNode();

function shutdown() {
  console.log('launch-master: stopping');
  process.exit(0);
}
process.on('SIGTERM', shutdown);
process.on('SIGINT', shutdown);
module.exports = master;
