// The official Node.js client node (@tum-far/ubii-node-nodejs) in a session beside libubii nodes.
// It publishes 1, 2, 3, ... on IN_TOPIC every 100 ms and prints what arrives on OUT_TOPIC; with
// MODULES "js_negate" it is also a dedicated processing node offering one JavaScript module,
// js_negate (y = -x on every x), from a class file in its local database (WORK_DIR/database), as
// the Node.js node loads modules. It deregisters on SIGTERM. Lines for the test start with "PEER ".
//   node nodejs_session_peer.js CLIENT_PACKAGE_DIR SERVICE_URL TOPIC_URL WORK_DIR MODULES
//        IN_TOPIC OUT_TOPIC
'use strict';
const fs = require('fs');
const path = require('path');
const [packageDir, serviceUrl, topicUrl, workDir, modules, inTopic, outTopic] = process.argv.slice(2);

const say = (line) => process.stdout.write('PEER ' + line + '\n');

// The Node.js node reads its modules from ./database/processing when first asked for them.
fs.rmSync(path.join(workDir, 'database'), { recursive: true, force: true });
fs.mkdirSync(path.join(workDir, 'database', 'processing'), { recursive: true });
// A module class file, as the Node.js node's own modules are written (its .pm JSON files are not
// offered at registration: their specs are not found).
const moduleBase = JSON.stringify(path.join(packageDir, 'src', 'processing', 'processingModule.js'));
if (modules === 'js_negate') fs.writeFileSync(path.join(workDir, 'database', 'processing', 'js_negate.js'), `
const { ProcessingModule } = require(${moduleBase});
class JsNegate extends ProcessingModule {
  constructor(specs) {
    super(specs);
    Object.assign(this, JsNegate.specs);
  }
  onProcessing(deltaTime, inputs, state) {
    return { outputs: { y: { double: -inputs.x.double } }, state };
  }
}
JsNegate.specs = {
  name: 'js_negate',
  processingMode: { triggerOnInput: { minDelayMs: 0, allInputsNeedUpdate: false } },
  inputs: [{ internalName: 'x', messageFormat: 'double' }],
  outputs: [{ internalName: 'y', messageFormat: 'double' }]
};
module.exports = JsNegate;
`);
process.chdir(workDir);
const { UbiiClientNode } = require(packageDir);

let node;
(async () => {
  node = new UbiiClientNode('nodejs-session-peer', { address: serviceUrl }, { address: topicUrl });
  await node.initialize();
  await node.subscribeTopic(outTopic, (record) => say(`got ${record.double}`));
  say(`ready ${node.id}`);
  let value = 0;
  setInterval(() => node.publishRecordImmediately({ topic: inTopic, double: ++value }), 100);
})().catch((error) => { say('error ' + error); process.exit(1); });
process.on('SIGTERM', () => {
  // A node that vanishes stays assignable at the master for a while: leave properly.
  const leaving = node ? node.deinitialize() : Promise.resolve();
  Promise.race([leaving, new Promise((resolve) => setTimeout(resolve, 2000))]).then(() => process.exit(0));
});
