// Starts the npm master node (@tum-far/ubii-nodejs-backend@0.4.0) without its own start script, which
// loads TensorFlow; nothing the master itself runs needs it. Run with the working directory holding
// config.json. Usage: node launch-master.js <folder with node_modules>
'use strict';
const path = require('path');

const installDir = process.argv[2];
if (!installDir) {
  console.error('usage: launch-master.js <install folder>');
  process.exit(2);
}
const backend = path.join(installDir, 'node_modules', '@tum-far', 'ubii-nodejs-backend', 'src');
const externalLibraries = require(path.join(backend, 'sessions', 'externalLibrariesService'));
externalLibraries.addExternalLibrary('fs', require('fs'));

const { MasterNode } = require(path.join(backend, 'index.js'));
const master = new MasterNode();

function shutdown() {
  console.log('launch-master: stopping');
  process.exit(0);
}
process.on('SIGTERM', shutdown);
process.on('SIGINT', shutdown);
module.exports = master;
