// The official Node.js client node (@tum-far/ubii-node-nodejs) as an echo for the C++ layer's
// cross-language test: every record it receives under /cpp-echo/<run>/out/ it decodes (with its
// own protobufjs schema) and publishes again, same member, under /cpp-echo/<run>/back/. Lines for
// the test start with "PEER ".
//   node nodejs_echo.js CLIENT_PACKAGE_DIR SERVICE_URL TOPIC_URL RUN_ID
'use strict';
const [packageDir, serviceUrl, topicUrl, run] = process.argv.slice(2);
const path = require('path');
const clientDir = path.resolve(packageDir);
require(path.join(__dirname, '../../support', 'nodejs_scratch_dir.js')).enter(); // before the client loads
const { UbiiClientNode } = require(clientDir);

const say = (line) => process.stdout.write('PEER ' + line + '\n');

(async () => {
  const node = new UbiiClientNode('nodejs-cpp-echo', { address: serviceUrl }, { address: topicUrl });
  await node.initialize();
  const prefix = `/cpp-echo/${run}/out/`;
  await node.subscribeRegex('^' + prefix, (record) => {
    const member = record.type; // protobufjs: the name of the oneof member that is set
    const echo = { topic: `/cpp-echo/${run}/back/` + record.topic.slice(prefix.length) };
    echo[member] = record[member];
    node.publishRecordImmediately(echo);
  });
  say(`ready ${node.id}`);
})().catch((error) => { say('error ' + error); process.exit(1); });
process.on('SIGTERM', () => process.exit(0));
