// The current master's binary HTTP service endpoint, as docs/PROTOCOL.md §1.3 states it, in front
// of the npm 0.4.0 master (which lacks it): POST /services/binary with Content-Type
// application/octet-stream carries a serialized ServiceRequest; the answer is HTTP 200,
// application/octet-stream, a serialized ServiceReply (service errors too). Requests are handed to
// the master's ZMQ REP socket, one at a time as REQ/REP demands. A request that breaks the contract
// (other path or method: 404; wrong Content-Type, no Host, wrong Content-Length: 400) makes the
// node's test fail, since no ServiceReply comes back. POST /services/binary?reply=chunked answers
// the same with Transfer-Encoding: chunked (small chunks and a trailer), as an HTTP server may.
// With CERT_PEM and KEY_PEM it serves HTTPS instead, on every loopback address (the TLS tests
// reach it as 127.0.0.2 too, a host its certificate does not name).
//   node http_services_bridge.js LISTEN_PORT MASTER_SERVICE_PORT ZEROMQ_MODULE_DIR [CERT_PEM KEY_PEM]
'use strict';
const fs = require('fs');
const http = require('http');
const https = require('https');
const [listenPort, masterPort, zeromqDir, certFile, keyFile] = process.argv.slice(2);
const zmq = require(zeromqDir);

const socket = zmq.socket('req');
socket.connect(`tcp://127.0.0.1:${masterPort}`);
const waiting = [];
socket.on('message', (reply) => {
  const { response, chunked } = waiting.shift();
  if (chunked) {
    // Without a Content-Length, Node's http sends every write() as a chunk of its own.
    response.writeHead(200, { 'Content-Type': 'application/octet-stream', Trailer: 'X-Reply-Length' });
    for (let at = 0; at < reply.length; at += 7) response.write(reply.subarray(at, at + 7));
    response.addTrailers({ 'X-Reply-Length': String(reply.length) });
    response.end();
  } else {
    // Express's res.send(Buffer), as the master answers, states the length.
    response.writeHead(200, { 'Content-Type': 'application/octet-stream', 'Content-Length': reply.length });
    response.end(reply);
  }
  if (waiting.length > 0) socket.send(waiting[0].body);
});

const handle = (request, response) => {
  const chunks = [];
  request.on('data', (chunk) => chunks.push(chunk));
  request.on('end', () => {
    const body = Buffer.concat(chunks);
    const chunked = request.url === '/services/binary?reply=chunked';
    if (request.method !== 'POST' || (request.url !== '/services/binary' && !chunked)) {
      response.writeHead(404);
      return response.end();
    }
    if (request.headers['content-type'] !== 'application/octet-stream' || !request.headers.host ||
        Number(request.headers['content-length']) !== body.length) {
      response.writeHead(400);
      return response.end();
    }
    waiting.push({ body, response, chunked });
    if (waiting.length === 1) socket.send(body);
  });
};
const server = certFile
  ? https.createServer({ cert: fs.readFileSync(certFile), key: fs.readFileSync(keyFile) }, handle)
  : http.createServer(handle);
server.listen(Number(listenPort), certFile ? '0.0.0.0' : '127.0.0.1',
  () => console.log(`bridge ready on ${listenPort}`));
process.on('SIGTERM', () => process.exit(0));
