// Our regex search must decide like the master, which runs `new RegExp(pattern).test(topic)`.
// Fixed cases for each supported feature and for JavaScript's quirks, then random patterns from a
// small grammar against random topics. Patterns using what the dialect documents as unsupported
// are expected to be refused; every other difference fails.
//   node regex_agrees_with_javascript.js REGEX_TOOL [RANDOM_CASES]
'use strict';
const { execFileSync } = require('child_process');
const tool = process.argv[2];
const randomCases = Number(process.argv[3] || 20000);

const topics = ['', '/', '/a', '/a/b', '/info/session/start', '/x/info', 'abc', 'ABC', 'a1_b',
  'aaa', 'ab', 'abab', 'a-b', 'a.b', 'a\\b', 'x{2}', 'p{L}', 'cat dog', 'line\nbreak', '12345',
  '/devices/7f3e/touch', '/éa/ü', 'k', 'a]b', '[x]', 'tab\there'];

const fixed = [
  'a', '^a', 'a$', '^/a$', '/info/*', '^/info/session/(start|stop)$', '.*', '^$', '', 'a|b|', '|',
  'a*', 'a+', 'a?', 'a{2}', 'a{2,}', 'a{1,2}', 'a{0}', '^a{0,2}$', '^(ab){2}$', '^(?:ab)+$',
  'a*?', 'a+?', '[abc]', '[^abc]', '[a-c]+', '[]', '[^]', '^[^]$', '[a-]', '[-a]', '[\\d-x]',
  '\\d+', '\\D', '\\w+', '\\W', '\\s', '\\S+', '\\bdog', 'a\\B', '\\.', 'a\\.b', '\\/a', '\\\\',
  '\\x41', '\\u0041', '\\p{L}', '\\k', '\\cJ', '\\c', 'x{2}', 'x{', '{', '}', ']', 'a]', '\\]',
  '[\\]]', '(a)', '((a)|b)+', '(?:)', '()', 'a{2,1}', '*', '+a', '(', ')', '(?=a)', '(?!a)',
  '(?<n>a)', '\\1', '(a)\\1', '[z-a]', '^.$', '.', 'é', '^/éa', 'é+', '[é]', '\\n', 'line.break',
  '^(a|ab)(c|bcd)(d*)$', '(a*)*', '(a*)+$', '(a|a)*b', '^(\\w+\\s?)*$', 'a{100}', 'a{101}',
  '\\t', 'k$', '^\\d{3,}$', '(?:a|b)*c', '[\\s\\S]', '[\\w.]+', '\\b', '\\B', '^\\b', '$\\b',
];

function jsVerdict(pattern, topic) {
  let re;
  try { re = new RegExp(pattern); } catch (e) { return 'invalid'; }
  return re.test(topic) ? 'match' : 'nomatch';
}

// What the dialect refuses on purpose (see topic.h): lookaround, named groups, back-references,
// non-ASCII in classes or \x/\u escapes, and over-long repetitions.
function refusedByDesign(pattern) {
  return /\(\?[=!<]/.test(pattern) || /\\[1-9]/.test(pattern) ||
    /\[[^\]]*[^\x00-\x7f]/.test(pattern) || /\{(\d{3,}|10[1-9])/.test(pattern);
}

let seed = 7;
const random = () => { seed = (seed * 1103515245 + 12345) & 0x7fffffff; return seed / 0x7fffffff; };
const pick = (list) => list[Math.floor(random() * list.length)];
const atoms = ['a', 'b', '/', '.', '\\d', '\\w', '\\s', '[ab]', '[^a]', '[a-c/]', 'x', '\\.', '^', '$', '\\b'];
function randomPattern(depth) {
  let out = '';
  const parts = 1 + Math.floor(random() * 4);
  for (let i = 0; i < parts; i++) {
    let atom = depth < 2 && random() < 0.2 ? '(' + randomPattern(depth + 1) + (random() < 0.3 ? '|' + randomPattern(depth + 1) : '') + ')' : pick(atoms);
    if (random() < 0.4 && atom !== '^' && atom !== '$' && atom !== '\\b') atom += pick(['*', '+', '?', '{2}', '{1,3}', '{0,}', '*?']);
    out += atom;
  }
  return out;
}
function randomTopic() {
  const chars = 'ab/x.1 _c';
  let out = '';
  const length = Math.floor(random() * 8);
  for (let i = 0; i < length; i++) out += pick(chars);
  return out;
}

const cases = [];
for (const pattern of fixed) for (const topic of topics) cases.push([pattern, topic]);
for (let i = 0; i < randomCases; i++) cases.push([randomPattern(0), randomTopic()]);
// C strings end at NUL, so neither side may contain one.
const usable = cases.filter(([p, t]) => !p.includes('\0') && !t.includes('\0'));
const hex = (text) => Buffer.from(text, 'utf8').toString('hex');
const output = execFileSync(tool, { input: usable.map(([p, t]) => hex(p) + '\t' + hex(t)).join('\n') + '\n', maxBuffer: 1 << 26 })
  .toString().trim().split('\n');
let differences = 0, refused = 0;
const verdicts = {};
usable.forEach(([pattern, topic], i) => {
  const ours = output[i];
  verdicts[ours] = (verdicts[ours] || 0) + 1;
  const expected = jsVerdict(pattern, topic);
  if ((ours === 'unsupported' || ours === 'toolarge') && refusedByDesign(pattern)) { refused++; return; }
  if (ours !== expected) {
    differences++;
    if (differences <= 10) console.error(`DIFFERENT /${pattern}/ on ${JSON.stringify(topic)}: JavaScript ${expected}, libubii ${ours}`);
  }
});
console.log(`regex: ${usable.length} cases (${Object.entries(verdicts).map(([k, v]) => v + ' ' + k).join(', ')}), ` +
  `${refused} refused by design, ${differences} different from JavaScript`);
process.exit(differences ? 1 : 0);
