// A TCP relay from an ephemeral 127.0.0.1 port to the server's, for tests that cut a page's
// connection: cut() closes every relayed connection; refuse(true) makes it close new ones at
// once (a server out of reach) until refuse(false).

import net from 'node:net';

export async function relay(target) {
  const sockets = new Set();
  let refusing = false;
  const server = net.createServer((client) => {
    if (refusing) {
      client.destroy();
      return;
    }
    const upstream = net.connect(target, '127.0.0.1');
    for (const [a, b] of [[client, upstream], [upstream, client]]) {
      sockets.add(a);
      a.on('close', () => { sockets.delete(a); b.destroy(); });
      a.on('error', () => b.destroy());
      a.pipe(b);
    }
  });
  await new Promise((r) => { server.listen(0, '127.0.0.1', r); });
  return {
    ws: `ws://127.0.0.1:${server.address().port}/`,
    cut: () => { for (const s of sockets) s.destroy(); },
    refuse: (on) => { refusing = on; },
    close: () => server.close(),
  };
}
