// The official Node.js node connected, subscribed to one topic and idle: bench/footprint_idle.sh
// measures it beside bench/idle_node.c.
//   node idle_nodejs.js CLIENT_PACKAGE_DIR SERVICE_URL TOPIC_URL
'use strict';
const [packageDir, serviceUrl, topicUrl] = process.argv.slice(2);
const path = require('path');
const clientDir = path.resolve(packageDir);
require(path.join(__dirname, '../tests/support', 'nodejs_scratch_dir.js')).enter();
const { UbiiClientNode } = require(clientDir);
(async () => {
  const node = new UbiiClientNode('nodejs-idle', { address: serviceUrl }, { address: topicUrl });
  await node.initialize();
  await node.subscribeTopic('/libubii/idle', () => {});
  process.stdout.write('idle_nodejs: ready\n');
})().catch((error) => { process.stdout.write('idle_nodejs: error ' + error + '\n'); process.exit(1); });
process.on('SIGTERM', () => process.exit(0));
