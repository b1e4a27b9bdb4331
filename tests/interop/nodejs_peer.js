// The official Node.js client node (@tum-far/ubii-node-nodejs) as the other side of the
// cross-language test. It subscribes to what the C node publishes under /interop/<run>/c/, checks
// each record's value against the table below, and publishes the same table under
// /interop/<run>/js/ for the C node to check. Lines for the test start with "PEER ".
//   node nodejs_peer.js CLIENT_PACKAGE_DIR SERVICE_URL TOPIC_URL RUN_ID
'use strict';
const [packageDir, serviceUrl, topicUrl, run] = process.argv.slice(2);
const path = require('path');
const clientDir = path.resolve(packageDir);
require(path.join(__dirname, '../support', 'nodejs_scratch_dir.js')).enter(); // before the client loads
const { UbiiClientNode } = require(clientDir);

// The values both sides use; the C++ test has the same table (interop_test.cpp).
const table = {
  double: { double: 3.141592653589793 },
  float: { float: 0.15625 },
  int32: { int32: -123456 },
  bool: { bool: true },
  string: { string: 'Grüße aus C und JS 🐋' },
  vector3: { vector3: { x: 1.5, y: -2.5, z: 3.25 } },
  quaternion: { quaternion: { x: 0, y: 0, z: 0.7071067811865476, w: 0.7071067811865476 } },
  pose3D: { pose3D: { position: { x: 1, y: 2, z: 3 }, euler: { x: 0.5, y: 0, z: -0.5 } } },
  doubleList: { doubleList: { elements: [1.5, -2.25, 1e-300] } },
  int32List: { int32List: { elements: [1, -2, 2147483647] } },
  stringList: { stringList: { elements: ['eins', 'zwei', ''] } },
  image2D: { image2D: { width: 2, height: 1, dataFormat: 1, data: Buffer.from([255, 0, 0, 0, 255, 0]) } },
};

const say = (line) => process.stdout.write('PEER ' + line + '\n');

// The decoded record against the table entry: field by field, numbers exactly, bytes by content.
function same(expected, actual) {
  if (Buffer.isBuffer(expected)) return Buffer.from(actual || []).equals(expected);
  if (Array.isArray(expected)) {
    return Array.isArray(actual) && actual.length === expected.length && expected.every((e, i) => same(e, actual[i]));
  }
  if (expected !== null && typeof expected === 'object') {
    return actual !== null && typeof actual === 'object' && Object.keys(expected).every((k) => same(expected[k], actual[k]));
  }
  if (typeof expected === 'number' && typeof actual === 'object' && actual !== null) return Number(actual) === expected;
  return Object.is(expected, actual) || (expected === 0 && actual === undefined);
}

(async () => {
  const node = new UbiiClientNode('nodejs-interop-peer', { address: serviceUrl }, { address: topicUrl });
  await node.initialize();
  await node.subscribeRegex(`^/interop/${run}/c/`, (record) => {
    const type = record.topic.split('/').pop();
    const expected = table[type];
    if (!expected) return say(`unknown ${type}`);
    const member = Object.keys(expected)[0];
    say((same(expected[member], record[member]) ? 'ok ' : 'mismatch ') + type +
        (same(expected[member], record[member]) ? '' : ' ' + JSON.stringify(record[member])));
  });
  say(`ready ${node.id}`);
  // Publish the table until stopped, so the C node finds it whenever its subscription is in place.
  setInterval(() => {
    for (const [type, value] of Object.entries(table)) {
      node.publishRecordImmediately(Object.assign({ topic: `/interop/${run}/js/${type}` }, value));
    }
  }, 100);
})().catch((error) => { say('error ' + error); process.exit(1); });
process.on('SIGTERM', () => process.exit(0));
