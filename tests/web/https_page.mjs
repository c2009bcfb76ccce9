// A page loaded over https from carrom-server (--tls-cert, --tls-key: certificates of a test CA
// made by tests/tls/make_test_pki.sh) plays a whole match over wss against carrom-bot, which
// connects over wss too (--ca-file). Chromium trusts the test CA through its own NSS database
// (HOME of its own, the CA added with certutil), never by turning certificate checks off: the
// page, its scripts and its WebSocket are refused without it. Checks: the page is https and its
// WebSocket wss, the same final scores on both sides, the server counted TLS handshakes, no
// console errors.

import { execFileSync } from 'node:child_process';
import { mkdirSync, mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';

import { check, env, launchBrowser, run, startChild, startServer } from './lib/harness.mjs';
import { playUntilOver } from './lib/match.mjs';
import { Player } from './lib/player.mjs';

const home = mkdtempSync(join(tmpdir(), 'carrom_https_page_'));
process.on('exit', () => rmSync(home, { recursive: true, force: true }));

run('web.https_page', 150000, async (t) => {
  check(env.bot, 'CARROM_BOT is not set');
  const pki = join(home, 'pki');
  execFileSync(fileURLToPath(new URL('../tls/make_test_pki.sh', import.meta.url)), [pki]);
  const nssdb = join(home, '.pki', 'nssdb');
  mkdirSync(nssdb, { recursive: true });
  execFileSync('certutil', ['-d', `sql:${nssdb}`, '-N', '--empty-password']);
  execFileSync('certutil', ['-d', `sql:${nssdb}`, '-A', '-t', 'C,,', '-n', 'carrom-test', '-i', join(pki, 'ca.pem')]);

  const server = await startServer(['--shot-clock', '0', '--time-scale', '8', '--no-bots',
    '--tls-cert', join(pki, 'server.pem'), '--tls-key', join(pki, 'server.key')]);
  t.browser = await launchBrowser([], { ...process.env, HOME: home });
  const url = `https://localhost:${server.port}/`;
  const page = await Player.open(await t.browser.newContext({ viewport: { width: 900, height: 900 } }), 'Asha', url, t.errors);
  const sockets = [];
  page.page.on('websocket', (ws) => sockets.push(ws.url()));
  check(await page.page.evaluate(() => window.location.protocol) === 'https:', 'the page is https');
  await page.fillLobby({ name: 'Asha', ruleSet: 'freestyle', targetPoints: 10, boards: 1, shotClock: 0 });
  await page.press('#create');
  const { code } = await page.waitFor('the room', (s) => s.inRoom && s.phase === 'waiting');
  check(sockets.length > 0 && sockets.every((u) => u === `wss://localhost:${server.port}/`), `the page's WebSockets: ${sockets}`);

  const bot = await startChild('carrom-bot', env.bot, [
    '--url', `wss://127.0.0.1:${server.port}`, '--ca-file', join(pki, 'ca.pem'), '--name', 'Greedy',
    '--join', code, '--strategy', 'greedy', '--level', 'easy', '--think-ms', '200', '--games', '1',
    '--timeout', '120', '--log-level', 'warn',
  ], new RegExp(`room ${code}`));
  await page.waitFor('the bot seated', (s) => s.seats[1] && s.seats[1].occupied && s.phase === 'aiming');
  const shots = await playUntilOver([page], { maxShots: 40, timeoutMs: 110000 });
  const end = await page.waitFor('the end on screen', (s) => s.phase === 'game_over' && !s.animating && s.gameEnd !== null, 30000);
  const exit = await bot.exited;
  const summaryLine = bot.log.filter((l) => l.startsWith('{')).pop();
  check(summaryLine, `the bot printed no summary (exit ${exit})`);
  const summary = JSON.parse(summaryLine);
  check(exit === 0 && summary.ok, `the bot finished cleanly (exit ${exit}): ${summaryLine}`);
  const scores = end.seats.map((x) => x.score);
  check(JSON.stringify(summary.scores) === JSON.stringify(scores), `scores: page ${scores}, bot ${summary.scores}`);

  const metrics = await (await fetch(`http://127.0.0.1:${server.port}/metrics`)).text();
  const handshakes = Number(/^carrom_tls_handshakes_total (\d+)$/m.exec(metrics)?.[1] ?? 0);
  check(handshakes >= 2, `TLS handshakes counted by the server: ${handshakes}`);
  console.log(`room ${code} over https/wss: page ${shots} shots, bot ${summary.shots}; ${handshakes} TLS handshakes; ${end.gameEnd.sentence}`);
});
