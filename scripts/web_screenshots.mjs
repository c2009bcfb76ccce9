#!/usr/bin/env node
// The web client's pictures in docs/img, made the way a player sees them:
//
//   node scripts/web_screenshots.mjs [--server PATH] [--out docs/img] [--only singles|doubles|replay]
//
// web-aim.png: 900 x 900, a game against a server bot, the break being aimed (the pull, the
// guide and the power ring). web-phone.png: 390 x 844 at 2 device px per CSS px, touch, the
// board after the break against a server bot. web-doubles-side.png: 900 x 900, a doubles game of
// four pages (ICF rules), the right seat's view (a quarter turn: its own baseline at the
// bottom, its partner across) aiming its first shot after the break. web-replay.png: 900 x 900,
// the replay page (#/replay/ID) of a game the page played against a server bot (freestyle to
// 40 points, on a server with a match store), paused in the motion of the game's last stroke.

import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';

const { root, args, opt } = await import('./lib/script_options.mjs');
const out = path.resolve(opt('--out', path.join(root, 'docs/img')));
const only = opt('--only', 'all');
const wanted = (name) => only === 'all' || only === name;

const { launchBrowser, pageUrl, run, startServer, startWebServer } = await import(path.join(root, 'tests/web/lib/harness.mjs'));
const { Player } = await import(path.join(root, 'tests/web/lib/player.mjs'));
const { breakShot } = await import(path.join(root, 'tests/web/lib/match.mjs'));
const { chooseShot } = await import(path.join(root, 'tests/web/lib/shot_chooser.mjs'));
const { playUntilOver } = await import(path.join(root, 'tests/web/lib/match.mjs'));

// A game against a server bot on a server with a match store, then its replay page paused in
// the last stroke's motion.
async function replayPicture(t, file) {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'carrom-shots-'));
  try {
    const server = await startServer(['--shot-clock', '0', '--time-scale', '8', '--data', path.join(dir, 'm.sqlite')]);
    const web = await startWebServer(server);
    const context = await t.browser.newContext({ viewport: { width: 900, height: 900 } });
    const p = await Player.open(context, 'replay', pageUrl(web, server), t.errors);
    await p.fillLobby({ name: 'Asha', ruleSet: 'freestyle', targetPoints: 40, boards: 1, botLevel: 'easy' });
    await p.press('#play-bot');
    await p.waitFor('the game', (st) => st.inRoom && st.phase === 'aiming');
    await playUntilOver([p], { maxShots: 40, timeoutMs: 110000 });
    const base = `http://127.0.0.1:${server.port}`;
    let listed = null;
    for (let i = 0; i < 50 && !listed?.finished_ms; i += 1) {
      listed = (await (await fetch(`${base}/matches?player=Asha`)).json()).matches[0];
      await new Promise((r) => { setTimeout(r, 100); });
    }
    const r = await context.newPage();
    await r.goto(`${base}${listed.replay}`);
    await r.waitForFunction(() => window.carrom?.replay?.().loaded);
    const last = await r.evaluate(() => window.carrom.replay().inputs);
    for (let i = 1; i < last; i += 1) await r.keyboard.press('ArrowRight');
    await r.waitForFunction(() => window.carrom.replay().stroke === window.carrom.replay().strokes);
    await new Promise((res) => { setTimeout(res, 400); });
    await r.click('#replay-play');
    await r.screenshot({ path: file });
  } finally {
    fs.rmSync(dir, { recursive: true, force: true });
  }
}

// Four pages in a doubles room; once the right seat (seat 1) is to aim, its view mid-pull.
async function doublesPicture(t, web, server, file) {
  const view = { viewport: { width: 900, height: 900 } };
  const names = ['Asha', 'Ravi', 'Chitra', 'Dev'];
  const pages = [];
  for (const [i, name] of names.entries()) {
    pages.push(await Player.open(await t.browser.newContext(view), name, pageUrl(web, server), t.errors));
    if (i === 0) {
      await pages[0].fillLobby({ name, ruleSet: 'icf', shotClock: 0 });
      await pages[0].page.selectOption('#seat-count', '4');
      await pages[0].press('#create');
    } else {
      const { code } = await pages[0].waitFor('the room', (st) => st.inRoom);
      await pages[i].fillLobby({ name, code });
      await pages[i].press('#join');
    }
    await pages[i].waitFor(`seat ${i}`, (st, seat) => st.inRoom && st.you === seat, 20000, i);
  }
  const ravi = pages[1];
  let shots = 0;
  for (;;) {
    let mover = null;
    for (const p of pages) {
      const st = await p.waitFor('at rest', (x) => !x.animating && x.phase === 'aiming');
      if (st.myTurn && st.aim.phase === 'idle') mover = { p, st };
    }
    if (!mover) continue;
    if (mover.p === ravi && shots > 0) break;
    const { p, st } = mover;
    await p.shoot(shots === 0 ? breakShot(st.aim.side) : chooseShot(st.board, st.aim.side, shots));
    await p.waitFor('the shot played', (x, turn) => x.turn !== turn && !x.animating, 30000, st.turn);
    shots += 1;
  }
  const s = await ravi.state();
  const shot = chooseShot(s.board, s.aim.side, 1);
  const from = await ravi.toClient(s.aim.striker.x, s.aim.striker.y);
  const pull = { x: s.aim.striker.x - Math.cos(shot.angle) * 110, y: s.aim.striker.y - Math.sin(shot.angle) * 110 };
  const to = await ravi.toClient(pull.x, pull.y);
  await ravi.page.mouse.move(from.x, from.y);
  await ravi.page.mouse.down();
  await ravi.page.mouse.move(to.x, to.y, { steps: 6 });
  await ravi.page.screenshot({ path: file });
  await ravi.page.keyboard.press('Escape');
  await ravi.page.mouse.up();
}

run('web_screenshots', 300000, async (t) => {
  const server = await startServer(['--shot-clock', '30', '--bot-think-ms', '100']);
  const web = await startWebServer(server);
  t.browser = await launchBrowser();

  if (wanted('doubles')) {
    const file = path.join(out, 'web-doubles-side.png');
    await doublesPicture(t, web, server, file);
    console.log(`saved ${file}`);
  }
  if (wanted('replay')) {
    const file = path.join(out, 'web-replay.png');
    await replayPicture(t, file);
    console.log(`saved ${file}`);
  }
  if (!wanted('singles')) return;
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
