// Publishes an Image2D through the official Node.js client node: the raw pixels of PIXEL_FILE
// (rows top to bottom, no padding) as WIDTH x HEIGHT in FORMAT (0 GRAY8, 1 RGB8, 2 RGBA8),
// BURST copies at a time every 500 ms until stopped. With GOOD_AFTER_FILE, the frames are
// malformed (one row of pixels short) until that file exists.
//   node nodejs_publish_image.js CLIENT_PACKAGE_DIR SERVICE_URL TOPIC_URL TOPIC PIXEL_FILE WIDTH
//        HEIGHT FORMAT BURST [GOOD_AFTER_FILE]
'use strict';
const fs = require('fs');
const [packageDir, serviceUrl, topicUrl, topic, pixelFile, widthText, heightText, formatText,
  burstText, goodAfterFile] = process.argv.slice(2);
const path = require('path');
const clientDir = path.resolve(packageDir);
const pixelPath = path.resolve(pixelFile);
const goodAfterPath = goodAfterFile ? path.resolve(goodAfterFile) : undefined;
require(path.join(__dirname, '../support', 'nodejs_scratch_dir.js')).enter(); // before the client loads
const { UbiiClientNode } = require(clientDir);

(async () => {
  const width = Number(widthText);
  const height = Number(heightText);
  const data = fs.readFileSync(pixelPath);
  const oneRowShort = data.subarray(0, data.length - data.length / height);
  const node = new UbiiClientNode('nodejs-image-publisher', { address: serviceUrl }, { address: topicUrl });
  await node.initialize();
  process.stdout.write('PUBLISHER ready\n');
  setInterval(() => {
    const good = !goodAfterPath || fs.existsSync(goodAfterPath);
    const image2D = { width, height, dataFormat: Number(formatText), data: good ? data : oneRowShort };
    for (let i = 0; i < Number(burstText); ++i) node.publishRecordImmediately({ topic, image2D });
  }, 500);
})().catch((error) => { process.stdout.write('PUBLISHER error ' + error + '\n'); process.exit(1); });
process.on('SIGTERM', () => process.exit(0));
