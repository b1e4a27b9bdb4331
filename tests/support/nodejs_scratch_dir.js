// The official Node.js node writes a module database (database/processing) into its working
// directory when it starts: a peer that required it from the test's or the repository's directory
// would leave that folder behind. enter() moves the process into a directory of its own under the
// system's temporary directory, removed when the process exits; call it after resolving every
// path given on the command line.
'use strict';
const fs = require('fs');
const os = require('os');
const path = require('path');

function enter() {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'ubii-nodejs-'));
  process.chdir(dir);
  process.on('exit', () => fs.rmSync(dir, { recursive: true, force: true }));
  return dir;
}

module.exports = { enter };
