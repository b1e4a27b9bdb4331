// Cross-implementation round trip between our nanopb code and protobufjs, the encoder the master and
// the official nodes use (from @tum-far/ubii-msg-formats, installed by scripts/npm-packages.sh).
//
//   node protobufjs_roundtrip.js MSG_FORMATS_DIR PROTO_DIR CODEC_TOOL [MESSAGES_PER_TYPE]
//
// 1. protobufjs -> us -> protobufjs: random messages of TopicData (cycling through every
//    TopicDataRecord member), ServiceRequest and ServiceReply (every member) are encoded by
//    protobufjs, decoded and re-encoded by codec_tool, decoded by protobufjs again: same content.
// 2. us -> protobufjs: codec_tool encodes random messages and prints what it put on the wire;
//    protobufjs must decode exactly that.
// Content is compared as "what is on the wire, by field number": floats by bit pattern, int64 as
// decimal strings, bytes as hex. Any difference fails with the message and both versions.
'use strict';
const fs = require('fs');
const path = require('path');
const { execFileSync } = require('child_process');

const [packageDir, protoDir, codecTool, countText] = process.argv.slice(2);
if (!packageDir || !protoDir || !codecTool) {
  console.error('usage: protobufjs_roundtrip.js MSG_FORMATS_DIR PROTO_DIR CODEC_TOOL [COUNT]');
  process.exit(2);
}
const perType = Number(countText || 300);
const protobuf = require(require.resolve('protobufjs', { paths: [packageDir] }));
const staticRoot = require(path.join(packageDir, 'dist', 'js', 'protobuf'));

// Reflection over the official .proto files, to walk any message generically.
const reflection = new protobuf.Root();
reflection.resolvePath = (origin, target) => path.join(packageDir, 'src', target);
reflection.loadSync(['proto/topicData/topicData.proto', 'proto/services/serviceRequest.proto',
  'proto/services/serviceReply.proto'], { keepCase: true });
reflection.resolveAll();
// The static module uses camelCase property names; reflection was loaded with the proto names.
const staticName = (name) => name.replace(/_([a-zA-Z0-9])/g, (m, c) => c.toUpperCase());

// max_size of our static strings, from our .options files (counts the NUL).
const stringLimits = [];
(function readOptions(dir) {
  for (const entry of fs.readdirSync(dir, { withFileTypes: true })) {
    const full = path.join(dir, entry.name);
    if (entry.isDirectory()) readOptions(full);
    else if (entry.name.endsWith('.options')) {
      for (const line of fs.readFileSync(full, 'utf8').split('\n')) {
        const m = line.match(/^\s*(\S+)\s+.*max_size:(\d+)/);
        if (m) {
          const pattern = new RegExp('^' + m[1].replace(/\./g, '\\.').replace(/\*/g, '.*') + '$');
          stringLimits.push([pattern, Number(m[2])]);
        }
      }
    }
  }
})(protoDir);
function byteLimit(field) {
  const name = field.parent.fullName.slice(1) + '.' + field.name;
  const hit = stringLimits.find(([pattern]) => pattern.test(name));
  return hit ? hit[1] - 1 : 40;
}

// ---- deterministic random values ---------------------------------------------------------------
let seed = 12345;
function random() {
  seed ^= seed << 13; seed >>>= 0;
  seed ^= seed >>> 17;
  seed ^= seed << 5; seed >>>= 0;
  return seed / 4294967296;
}
const below = (n) => Math.floor(random() * n);
const alphabet = ['a', 'Z', '0', '/', ' ', '.', '_', 'é', '€', '🐋', '"', '\\'];

function randomString(limitBytes) {
  let text = '';
  const length = below(12);
  for (let i = 0; i < length; i++) {
    const next = text + alphabet[below(alphabet.length)];
    if (Buffer.byteLength(next) > limitBytes) break;
    text = next;
  }
  return text;
}

function randomScalar(field) {
  switch (field.type) {
    case 'double': {
      const special = [Infinity, -Infinity, 5e-324, -1.7976931348623157e308];
      return below(10) === 0 ? special[below(4)] : (random() - 0.5) * 10 ** (below(30) - 10);
    }
    case 'float': return Math.fround((random() - 0.5) * 10 ** (below(16) - 6));
    case 'int32': return (below(2 ** 32) | 0);
    case 'int64': return Math.floor((random() - 0.5) * 2 ** 53);
    case 'bool': return random() < 0.5;
    case 'string': return randomString(byteLimit(field));
    case 'bytes': return Buffer.from(Array.from({ length: below(24) }, () => below(256)));
    default: {
      if (field.resolvedType instanceof protobuf.Enum) {
        const values = Object.values(field.resolvedType.values);
        return values[below(values.length)];
      }
      throw new Error('no generator for ' + field.type);
    }
  }
}

const isDefault = (v) => v === 0 && !Object.is(v, -0) || v === false || v === '' ||
  (Buffer.isBuffer(v) && v.length === 0);

function randomValue(field, depth, forced) {
  return field.resolvedType instanceof protobuf.Type
    ? randomMessage(field.resolvedType, depth + 1, forced) : randomScalar(field);
}

// `forced` maps a message's full name to the oneof member to use (to cover every member).
function randomMessage(type, depth, forced) {
  const object = {};
  for (const field of type.fieldsArray) {
    if (field.partOf) continue;
    if (field.repeated) {
      const count = depth > 5 ? 0 : below(4);
      object[field.name] = Array.from({ length: count }, () => randomValue(field, depth, forced));
    } else if (field.resolvedType instanceof protobuf.Type) {
      if (depth <= 5 && random() < 0.6) object[field.name] = randomValue(field, depth, forced);
    } else {
      const value = randomScalar(field);
      if (!isDefault(value)) object[field.name] = value;
    }
  }
  for (const oneof of type.oneofsArray) {
    const wanted = forced[type.fullName];
    const members = oneof.fieldsArray;
    const member = wanted ? members.find((f) => f.name === wanted)
      : (depth > 5 || below(members.length + 1) === members.length ? null : members[below(members.length)]);
    if (member) object[member.name] = randomValue(member, depth, forced);
  }
  return object;
}

// Plain object with proto field names -> static-module message.
function toStatic(type, object) {
  const converted = {};
  for (const [name, value] of Object.entries(object)) {
    const field = type.fields[name];
    const convert = (v) => field.resolvedType instanceof protobuf.Type ? toStatic(field.resolvedType, v) : v;
    converted[staticName(name)] = Array.isArray(value) ? value.map(convert) : convert(value);
  }
  return staticType(type).fromObject(converted);
}

function staticType(type) {
  return type.fullName.slice(1).split('.').reduce((node, part) => node[part], staticRoot);
}

// ---- canonical "on the wire" form ------------------------------------------------------------------
function canonicalScalar(field, value) {
  if (field.resolvedType instanceof protobuf.Type) return canonical(field.resolvedType, value);
  switch (field.type) {
    case 'float': return new Uint32Array(new Float32Array([value]).buffer)[0];
    case 'double': {
      const view = new DataView(new ArrayBuffer(8));
      view.setFloat64(0, value);
      return view.getBigUint64(0).toString(16).padStart(16, '0');
    }
    case 'int64': return String(value);
    case 'bytes': return Buffer.from(value).toString('hex');
    default: return value;
  }
}

// protobufjs's static decoder sets own properties exactly for the fields found on the wire.
function canonical(type, message) {
  const out = {};
  for (const field of type.fieldsArray) {
    const name = staticName(field.name);
    if (!Object.prototype.hasOwnProperty.call(message, name)) continue;
    const value = message[name];
    if (field.repeated) {
      if (value.length) out[field.id] = value.map((v) => canonicalScalar(field, v));
    } else {
      out[field.id] = canonicalScalar(field, value);
    }
  }
  return out;
}

function stable(value) {
  if (Array.isArray(value)) return '[' + value.map(stable).join(',') + ']';
  if (value && typeof value === 'object') {
    return '{' + Object.keys(value).sort((a, b) => a - b).map((k) => JSON.stringify(k) + ':' + stable(value[k])).join(',') + '}';
  }
  return JSON.stringify(value);
}

// ---- framing and the C tool -------------------------------------------------------------------------
function frame(buffers) {
  return Buffer.concat(buffers.flatMap((b) => {
    const header = Buffer.alloc(4);
    header.writeUInt32LE(b.length);
    return [header, Buffer.from(b)];
  }));
}
function unframe(buffer) {
  const out = [];
  for (let offset = 0; offset < buffer.length;) {
    const size = buffer.readUInt32LE(offset);
    out.push(buffer.subarray(offset + 4, offset + 4 + size));
    offset += 4 + size;
  }
  return out;
}

const tool = (args, input) => execFileSync(codecTool, args, { input, maxBuffer: 1 << 28, stdio: ['pipe', 'pipe', 'pipe'] });

let failures = 0;
function report(what, expected, actual) {
  failures++;
  if (failures <= 5) console.error(`MISMATCH ${what}\n  expected ${expected}\n  actual   ${actual}`);
}

const cases = [
  ['TopicData', 'ubii.topicData.TopicData', 'ubii.topicData.TopicDataRecord', 'topic_data_record'],
  ['ServiceRequest', 'ubii.services.ServiceRequest', 'ubii.services.ServiceRequest', null],
  ['ServiceReply', 'ubii.services.ServiceReply', 'ubii.services.ServiceReply', null],
];
let checked = 0;
for (const [toolName, typeName, cycledName, envelopeMember] of cases) {
  const type = reflection.lookupType(typeName);
  const cycled = reflection.lookupType(cycledName).oneofs.type.fieldsArray.map((f) => f.name);
  // 1. protobufjs -> us -> protobufjs
  const originals = [];
  for (let i = 0; i < perType; i++) {
    const forced = { ['.' + cycledName]: cycled[i % cycled.length] };
    if (envelopeMember) forced['.' + typeName] = envelopeMember;
    originals.push(staticType(type).encode(toStatic(type, randomMessage(type, 0, forced))).finish());
  }
  const reencoded = unframe(tool(['reencode', toolName], frame(originals)));
  if (reencoded.length !== originals.length) throw new Error(`${toolName}: ${reencoded.length} of ${originals.length} came back`);
  originals.forEach((bytes, i) => {
    const expected = stable(canonical(type, staticType(type).decode(bytes)));
    const actual = stable(canonical(type, staticType(type).decode(reencoded[i])));
    if (expected !== actual) report(`${toolName} #${i} protobufjs->nanopb->protobufjs`, expected, actual);
    checked++;
  });
  // 2. us -> protobufjs
  const result = require('child_process').spawnSync(codecTool, ['generate', toolName, '7', String(perType)], { maxBuffer: 1 << 28 });
  if (result.status !== 0) throw new Error(`codec_tool generate failed: ${result.stderr}`);
  const messages = unframe(result.stdout);
  const lines = result.stderr.toString().trim().split('\n');
  messages.forEach((bytes, i) => {
    const expected = stable(JSON.parse(lines[i]));
    const actual = stable(canonical(type, staticType(type).decode(bytes)));
    if (expected !== actual) report(`${toolName} #${i} nanopb->protobufjs`, expected, actual);
    checked++;
  });
  console.log(`${toolName}: ${perType} protobufjs->nanopb->protobufjs, ${messages.length} nanopb->protobufjs`);
}

// A string longer than its static size is refused by our decoder, not cut.
const record = reflection.lookupType('ubii.topicData.TopicData');
const tooLong = staticType(record).encode(staticType(record).fromObject({ topicDataRecord: { topic: 'x'.repeat(300) } })).finish();
let refused = false;
try { tool(['reencode', 'TopicData'], frame([tooLong])); } catch (e) { refused = /string overflow|decode failed/.test(String(e.stderr)); }
if (!refused) report('oversized topic', 'decode refused', 'accepted');

if (failures) {
  console.error(`protobufjs round trip: ${failures} of ${checked} messages differ`);
  process.exit(1);
}
console.log(`protobufjs round trip: ${checked} messages identical in both directions; oversized string refused`);
