// The official Node.js client node (@tum-far/ubii-node-nodejs) as the other party of a libubii
// processing module: it publishes pairs on /pm/<run>/a and /pm/<run>/b (0 and 0 first, a value the
// Node.js node's own modules would drop) and waits for their sum on /pm/<run>/sum, then the next
// pair. Each pair is published again every 100 ms until its sum arrives. Lines for the test start
// with "PEER ".
//   node nodejs_sum_peer.js CLIENT_PACKAGE_DIR SERVICE_URL TOPIC_URL RUN_ID PAIRS
'use strict';
const [packageDir, serviceUrl, topicUrl, run, pairs] = process.argv.slice(2);
const path = require('path');
const clientDir = path.resolve(packageDir);
require(path.join(__dirname, '../../support', 'nodejs_scratch_dir.js')).enter(); // before the client loads
const { UbiiClientNode } = require(clientDir);

const say = (line) => process.stdout.write('PEER ' + line + '\n');

(async () => {
  const node = new UbiiClientNode('nodejs-pm-peer', { address: serviceUrl }, { address: topicUrl });
  await node.initialize();
  let pair = 0;
  await node.subscribeTopic(`/pm/${run}/sum`, (record) => {
    const sum = record.double;
    say(`sum ${sum}`);
    if (record.type === 'double' && sum === pair * 11)
      pair += 1;
    if (pair >= Number(pairs)) {
      say('done');
      setTimeout(() => process.exit(0), 200);
    }
  });
  say(`ready ${node.id}`);
  setInterval(() => {
    node.publishRecordImmediately({ topic: `/pm/${run}/a`, double: pair });
    node.publishRecordImmediately({ topic: `/pm/${run}/b`, double: pair * 10 });
  }, 100);
})().catch((error) => { say('error ' + error); process.exit(1); });
process.on('SIGTERM', () => process.exit(0));
