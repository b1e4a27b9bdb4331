// Publishes, every 100 ms until stopped, a string record of SIZE bytes on TOPIC and then the
// string "after" on TOPIC/after, through the official Node.js client node.
//   node nodejs_publish.js CLIENT_PACKAGE_DIR SERVICE_URL TOPIC_URL TOPIC SIZE
'use strict';
const [packageDir, serviceUrl, topicUrl, topic, sizeText] = process.argv.slice(2);
const path = require('path');
const clientDir = path.resolve(packageDir);
require(path.join(__dirname, '../support', 'nodejs_scratch_dir.js')).enter(); // before the client loads
const { UbiiClientNode } = require(clientDir);
(async () => {
  const node = new UbiiClientNode('nodejs-publisher', { address: serviceUrl }, { address: topicUrl });
  await node.initialize();
  const big = 'x'.repeat(Number(sizeText));
  process.stdout.write('PUBLISHER ready\n');
  setInterval(() => {
    node.publishRecordImmediately({ topic, string: big });
    node.publishRecordImmediately({ topic: topic + '/after', string: 'after' });
  }, 100);
})().catch((error) => { process.stdout.write('PUBLISHER error ' + error + '\n'); process.exit(1); });
process.on('SIGTERM', () => process.exit(0));
