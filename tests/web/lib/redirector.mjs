// An instance of a cluster that runs no room, for tests of redirects (docs/protocol.md,
// "Redirects"): a minimal WebSocket server on an ephemeral 127.0.0.1 port. A hello with a
// resume token gets `redirect` (seat) to `target`; one without gets welcome, and the next
// message gets `redirect` (room, with the code a join_room named). Then close 4005. `hellos`
// records every hello.

import { createHash } from 'node:crypto';
import http from 'node:http';

const GUID = '258EAFA5-E914-47DA-95CA-C5AB0DC85B11';

// A server-to-client frame: FIN, the opcode, the payload unmasked.
function frame(opcode, payload) {
  const head = payload.length < 126 ? Buffer.from([0x80 | opcode, payload.length])
    : Buffer.from([0x80 | opcode, 126, payload.length >> 8, payload.length & 0xff]);
  return Buffer.concat([head, payload]);
}

// The client's text frames in `buffer` (masked, unfragmented); returns [texts, bytes used].
function readFrames(buffer) {
  const texts = [];
  let at = 0;
  for (;;) {
    if (buffer.length - at < 2) break;
    const opcode = buffer[at] & 0x0f;
    let length = buffer[at + 1] & 0x7f;
    let head = 2;
    if (length === 126) {
      if (buffer.length - at < 4) break;
      length = buffer.readUInt16BE(at + 2);
      head = 4;
    } else if (length === 127) {
      if (buffer.length - at < 10) break;
      length = Number(buffer.readBigUInt64BE(at + 2));
      head = 10;
    }
    if (buffer.length - at < head + 4 + length) break;
    const mask = buffer.subarray(at + head, at + head + 4);
    const payload = Buffer.from(buffer.subarray(at + head + 4, at + head + 4 + length));
    for (let i = 0; i < payload.length; i += 1) payload[i] ^= mask[i % 4];
    if (opcode === 0x1) texts.push(payload.toString('utf8'));
    at += head + 4 + length;
  }
  return [texts, at];
}

export async function redirector(target) {
  const hellos = [];
  const sockets = new Set();
  const server = http.createServer((req, res) => { res.writeHead(404); res.end(); });
  server.on('upgrade', (req, socket) => {
    sockets.add(socket);
    socket.on('close', () => sockets.delete(socket));
    socket.on('error', () => socket.destroy());
    const accept = createHash('sha1').update(req.headers['sec-websocket-key'] + GUID).digest('base64');
    socket.write(`HTTP/1.1 101 Switching Protocols\r\nUpgrade: websocket\r\nConnection: Upgrade\r\nSec-WebSocket-Accept: ${accept}\r\n\r\n`);
    const send = (m) => socket.write(frame(0x1, Buffer.from(JSON.stringify(m))));
    const redirect = (m) => {
      send({ type: 'redirect', url: target, ...m });
      const code = Buffer.alloc(2);
      code.writeUInt16BE(4005);
      socket.write(frame(0x8, code));
      socket.end();
    };
    let pending = Buffer.alloc(0);
    let said = null;
    socket.on('data', (data) => {
      const [texts, used] = readFrames(Buffer.concat([pending, data]));
      pending = Buffer.concat([pending, data]).subarray(used);
      for (const text of texts) {
        const m = JSON.parse(text);
        if (said === null) {
          said = m;
          hellos.push(m);
          if (m.resume_token) {
            redirect({ reason: 'seat' });
            return;
          }
          send({ type: 'welcome', version: m.version, player_id: 7, resume_token: 'e'.repeat(32), server_time_ms: Date.now() });
        } else if (m.type !== 'ping') {
          redirect(m.type === 'join_room' ? { reason: 'room', code: m.code, as: m.as ?? 'player' } : { reason: 'room' });
          return;
        }
      }
    });
  });
  await new Promise((r) => { server.listen(0, '127.0.0.1', r); });
  return {
    ws: `ws://127.0.0.1:${server.address().port}/`,
    hellos,
    close: () => { for (const s of sockets) s.destroy(); server.close(); },
  };
}
