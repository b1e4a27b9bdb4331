// The Node.js node doing what pubsub_bench does (same topic pattern, same counts), measured the
// same way: round trips through the master, then a windowed stream, with process CPU per message.
//   node nodejs_bench.js CLIENT_PACKAGE_DIR SERVICE_URL TOPIC_URL [ROUNDS [MESSAGES [WINDOW]]]
'use strict';
const [packageDir, serviceUrl, topicUrl, roundsText, messagesText, windowText] = process.argv.slice(2);
const path = require('path');
const clientDir = path.resolve(packageDir);
require(path.join(__dirname, '../tests/support', 'nodejs_scratch_dir.js')).enter(); // before the client loads
const { UbiiClientNode } = require(clientDir);
const rounds = Number(roundsText || 2000);
const messages = Number(messagesText || 20000);
const windowSize = Number(windowText || 100);
const topic = '/libubii/bench/echo-nodejs';

(async () => {
  const node = new UbiiClientNode('nodejs-bench', { address: serviceUrl }, { address: topicUrl });
  await node.initialize();
  let received = 0;
  let waiter = null;
  await node.subscribeTopic(topic, () => {
    received++;
    if (waiter && waiter.until <= received) {
      const resolve = waiter.resolve;
      waiter = null;
      resolve();
    }
  });
  const until = (target, timeoutMs) => new Promise((resolve, reject) => {
    if (received >= target) return resolve();
    const timer = setTimeout(() => reject(new Error(`timeout at ${received} of ${target}`)), timeoutMs);
    waiter = { until: target, resolve: () => { clearTimeout(timer); resolve(); } };
  });
  const publish = (value) => node.publishRecordImmediately({ topic, double: value });

  // Warm up until the subscription is served.
  for (let i = 0; received === 0 && i < 100; i++) {
    publish(0);
    await new Promise((r) => setTimeout(r, 20));
  }
  if (received === 0) throw new Error('no echo from the master');
  await new Promise((r) => setTimeout(r, 200));

  const rtt = [];
  for (let i = 0; i < rounds; i++) {
    const target = received + 1;
    const start = process.hrtime.bigint();
    publish(i);
    await until(target, 5000);
    rtt.push(Number(process.hrtime.bigint() - start) / 1000);
  }
  rtt.sort((a, b) => a - b);

  const base = received;
  const cpuStart = process.cpuUsage();
  const switches = () => {
    const usage = process.resourceUsage();
    return usage.voluntaryContextSwitches + usage.involuntaryContextSwitches;
  };
  const switchesStart = switches();
  const start = process.hrtime.bigint();
  let sent = 0;
  while (sent < messages) {
    while (sent < messages && sent - (received - base) < windowSize) publish(sent++);
    await until(Math.min(base + sent, received + 1), 30000);
  }
  await until(base + messages, 30000);
  const elapsed = Number(process.hrtime.bigint() - start) / 1e9;
  const cpu = process.cpuUsage(cpuStart);
  const switchCount = switches() - switchesStart;
  console.log(`RESULT rtt_p50_us=${rtt[Math.floor(rounds / 2)].toFixed(1)} ` +
    `rtt_p99_us=${rtt[Math.floor(rounds * 99 / 100)].toFixed(1)} ` +
    `messages_per_s=${(messages / elapsed).toFixed(0)} ` +
    `cpu_us_per_message=${((cpu.user + cpu.system) / messages).toFixed(2)} ` +
    `user_us_per_message=${(cpu.user / messages).toFixed(2)} ` +
    `system_us_per_message=${(cpu.system / messages).toFixed(2)} ` +
    `switches_per_message=${(switchCount / messages).toFixed(2)}`);
  process.exit(0);
})().catch((error) => { console.error('nodejs_bench:', error.message); process.exit(1); });
