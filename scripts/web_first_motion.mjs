#!/usr/bin/env node
// The web page's first motion for the shooter (docs/network.md, "The browser"): how long after
// the release the page draws its own stroke moving, with the engine's prediction and without it
// (the engine's file refused, as on a page without WebAssembly), on the LAN and at 100 ms RTT.
//
//   node scripts/web_first_motion.mjs [--server PATH] [--strokes N] [--profiles lan,rtt100] [--json]
//
// carrom-server (default build/test/server/carrom-server) serves the page; the page's WebSocket
// goes through tests/support/fault_proxy.py, which delays every chunk by RTT/2 +- jitter/2 each
// way (rtt100: 50 +- 10 ms, as network_report.py's profile "100 ms RTT, 20 ms jitter"; lan: no
// delay). Headless Chromium (the tests' flags, 900 x 900) plays against a server bot (random
// level, ICF) with the mouse, N strokes of its own per mode (default 6), the break first. For each
// stroke: from the release (the page's pointerup, performance.now()) to the end of the first
// frame that draws the striker away from where it was placed, ms, and the frames from the one in
// progress at the release to that one (1 is the best possible), from window.carrom.frameTimes().

import { spawn } from 'node:child_process';
import { once } from 'node:events';
import { createInterface } from 'node:readline';
import path from 'node:path';

const { root, args, opt } = await import('./lib/script_options.mjs');
const strokes = Number(opt('--strokes', '6'));
const profiles = opt('--profiles', 'lan,rtt100').split(',');
const DELAYS = { lan: [0, 0], rtt100: [50, 10] };

const { launchBrowser, run, startServer, startWebServer, check, sleep } = await import(path.join(root, 'tests/web/lib/harness.mjs'));
const { Player } = await import(path.join(root, 'tests/web/lib/player.mjs'));
const { breakShot } = await import(path.join(root, 'tests/web/lib/match.mjs'));
const { chooseShot } = await import(path.join(root, 'tests/web/lib/shot_chooser.mjs'));

// fault_proxy.py in front of the server: {port, child}.
async function startProxy(server, delayMs, jitterMs) {
  const child = spawn('python3', [path.join(root, 'tests/support/fault_proxy.py'), '--target', `127.0.0.1:${server.port}`,
    '--control', `/tmp/web-first-motion-${process.pid}`, '--delay-ms', String(delayMs), '--jitter-ms', String(jitterMs)]);
  const lines = createInterface({ input: child.stdout });
  const [line] = await once(lines, 'line');
  const m = /listening on [\d.]+:(\d+)/.exec(line);
  check(m, `fault_proxy.py: ${line}`);
  return { port: Number(m[1]), child };
}

const median = (v) => [...v].sort((a, b) => a - b)[Math.floor((v.length - 1) / 2)];
const round = (x) => Math.round(x * 10) / 10;

// One own stroke: shoot, wait for its end, find its first moving frame.
async function measureStroke(p, shot) {
  const before = await p.state();
  const placed = { x: shot.x, y: before.aim.striker.y };
  await p.page.evaluate(() => window.carrom.clearFrameTimes());
  await p.shoot(shot);
  await p.waitFor('the stroke over', (s) => s.turn !== before.turn && !s.animating, 60000);
  const after = await p.state();
  const frames = await p.page.evaluate(() => window.carrom.frameTimes());
  const release = after.releaseMs;
  const atRelease = frames.findLastIndex((f) => f.ts <= release);
  const first = frames.findIndex((f, i) => i > atRelease && f.sx !== undefined
    && Math.hypot(f.sx - placed.x, f.sy - placed.y) > 0.01);
  check(atRelease >= 0 && first > atRelease, 'the stroke was drawn moving');
  const f = frames[first];
  return { ms: f.ts + f.ms - release, frames: first - atRelease, predicted: after.prediction?.strokes ?? 0 };
}

run('web_first_motion', 900000, async (t) => {
  const server = await startServer(['--shot-clock', '0', '--bot-think-ms', '100']);
  const web = await startWebServer(server);
  t.browser = await launchBrowser();
  const results = [];
  for (const profile of profiles) {
    const [delay, jitter] = DELAYS[profile];
    const proxy = await startProxy(server, delay, jitter);
    try {
      for (const engine of [true, false]) {
        const context = await t.browser.newContext({ viewport: { width: 900, height: 900 } });
        if (!engine) await context.route('**/*.wasm', (route) => route.fulfill({ status: 404, body: '' }));
        const url = `http://127.0.0.1:${web.port}/index.html?ws=${encodeURIComponent(`ws://127.0.0.1:${proxy.port}/`)}`;
        const p = await Player.open(context, `${profile} ${engine ? 'engine' : 'no engine'}`, url, []);
        await p.waitFor('the engine settled', (s) => s.engine.loaded || s.engine.error !== null, 10000);
        await p.fillLobby({ name: 'Shooter', ruleSet: 'icf', botLevel: 'random' });
        await p.press('#play-bot');
        const measured = [];
        while (measured.length < strokes) {
          const s = await p.waitFor('our turn', (st) => (st.myTurn && !st.animating && st.aim.phase === 'idle') || st.phase === 'game_over', 60000);
          if (s.phase === 'game_over') break;
          const shot = measured.length === 0 ? breakShot(s.aim.side) : chooseShot(s.board, s.aim.side, measured.length);
          measured.push(await measureStroke(p, shot));
          await sleep(200);
        }
        const ms = measured.map((m) => m.ms);
        const row = {
          profile, engine, strokes: measured.length, predicted: measured[measured.length - 1]?.predicted ?? 0,
          median_ms: round(median(ms)), max_ms: round(Math.max(...ms)), max_frames: Math.max(...measured.map((m) => m.frames)),
          ms: ms.map(round),
        };
        results.push(row);
        console.log(`${profile} ${engine ? 'with the engine' : 'without the engine'}: ${row.strokes} strokes (${row.predicted} predicted), `
          + `first motion median ${row.median_ms} ms, max ${row.max_ms} ms, max ${row.max_frames} frames (${row.ms.join(', ')})`);
        await context.close();
      }
    } finally {
      proxy.child.kill();
    }
  }
  if (args.includes('--json')) console.log(JSON.stringify(results));
});
