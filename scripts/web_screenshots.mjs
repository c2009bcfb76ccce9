#!/usr/bin/env node
// The web client's pictures in docs/img, made the way a player sees them:
//
//   node scripts/web_screenshots.mjs [--server PATH] [--out docs/img]
//
// web-aim.png: 900 x 900, a game against a server bot, the break being aimed (the pull, the
// guide and the power ring). web-phone.png: 390 x 844 at 2 device px per CSS px, touch, the
// board after the break against a server bot.

import { fileURLToPath } from 'node:url';
import path from 'node:path';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const args = process.argv.slice(2);
const opt = (name, fallback) => {
  const i = args.indexOf(name);
  return i >= 0 ? args[i + 1] : fallback;
};
process.env.CARROM_SERVER = path.resolve(opt('--server', process.env.CARROM_SERVER ?? path.join(root, 'build/test/server/carrom-server')));
const out = path.resolve(opt('--out', path.join(root, 'docs/img')));

const { launchBrowser, pageUrl, run, startServer, startWebServer } = await import(path.join(root, 'tests/web/lib/harness.mjs'));
const { Player } = await import(path.join(root, 'tests/web/lib/player.mjs'));
const { breakShot } = await import(path.join(root, 'tests/web/lib/match.mjs'));

run('web_screenshots', 120000, async (t) => {
  const server = await startServer(['--shot-clock', '30', '--bot-think-ms', '100']);
  const web = await startWebServer(server);
  t.browser = await launchBrowser();

  const desk = await Player.open(await t.browser.newContext({ viewport: { width: 900, height: 900 } }), 'desktop', pageUrl(web, server), t.errors);
  await desk.fillLobby({ name: 'Asha', ruleSet: 'icf', botLevel: 'easy' });
  await desk.press('#play-bot');
  let s = await desk.waitFor('our break', (st) => st.inRoom && st.myTurn && !st.animating && st.aim.phase === 'idle');
  const from = await desk.toClient(s.aim.x, s.aim.y);
  const to = await desk.toClient(s.aim.x + 40, s.aim.y + 110);
  await desk.page.mouse.move(from.x, from.y);
  await desk.page.mouse.down();
  await desk.page.mouse.move(to.x, to.y, { steps: 6 });
  await desk.page.screenshot({ path: path.join(out, 'web-aim.png') });
  await desk.page.mouse.up();

  const phone = await Player.open(await t.browser.newContext({
    viewport: { width: 390, height: 844 }, deviceScaleFactor: 2, isMobile: true, hasTouch: true,
  }), 'phone', pageUrl(web, server), t.errors);
  await phone.useTouch();
  await phone.fillLobby({ name: 'Ravi', ruleSet: 'freestyle', botLevel: 'easy' });
  await phone.press('#play-bot');
  s = await phone.waitFor('our break', (st) => st.inRoom && st.myTurn && !st.animating && st.aim.phase === 'idle');
  await phone.shoot(breakShot(s.aim.y));
  await phone.waitFor('the break over', (st, turn) => st.turn !== turn && !st.animating, 30000, s.turn);
  await phone.page.screenshot({ path: path.join(out, 'web-phone.png') });
  console.log(`saved ${path.join(out, 'web-aim.png')} and ${path.join(out, 'web-phone.png')}`);
});
