#!/usr/bin/env node
// The web client's pictures in docs/img, made the way a player sees them:
//
//   node scripts/web_screenshots.mjs [--server PATH] [--out docs/img] [--only singles|doubles|replay|texts|ratings]
//
// web-aim.png: 900 x 900, a game against a server bot, the break being aimed (the pull, the
// guide, the power ring and, with the page's engine, the aim assist). web-phone.png: 390 x 844 at 2 device px per CSS px, touch, the
// board after the break against a server bot (the first-game tips skipped, the log under the
// board). web-rules.png: the same phone, How to play opened from the match (freestyle).
// web-doubles-side.png: 900 x 900, a doubles game of
// four pages (ICF rules), the right seat's view (a quarter turn: its own baseline at the
// bottom, its partner across) aiming its first shot after the break. web-replay.png: 900 x 900,
// the replay page (#/replay/ID) of a game the page played against a server bot (freestyle to
// 40 points, on a server with a match store), paused in the motion of the game's last stroke.
// The texts a newcomer reads (900 x 900, against server bots): web-foul.png, the striker sent
// into a pocket after the break (warnings, and what it cost); web-game-over-loser.png, three
// missed 1 s shot clocks; web-game-over-winner.png, the opponent left (no rematch);
// web-board-summary.png, the card after the first of two ICF boards against a hard bot.
// The ratings (900 x 900, two seeded players in a rated quick match, tests/web/lib/rated.mjs):
// web-ratings-seats.png, Asha's top bar with both ratings; web-ratings-game-over.png, her card
// after Ravi forfeits, with both changes; web-leaderboard.png, her lobby's leaderboard (ICF).

import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';

const { root, args, opt } = await import('./lib/script_options.mjs');
const out = path.resolve(opt('--out', path.join(root, 'docs/img')));
const only = opt('--only', 'all');
const wanted = (name) => only === 'all' || only === name;

const { launchBrowser, pageUrl, run, startServer, startWebServer } = await import(path.join(root, 'tests/web/lib/harness.mjs'));
const { Player } = await import(path.join(root, 'tests/web/lib/player.mjs'));
const { breakShot, playUntilOver } = await import(path.join(root, 'tests/web/lib/match.mjs'));
const { chooseShot } = await import(path.join(root, 'tests/web/lib/shot_chooser.mjs'));
const { ratedPair, startSeededServer } = await import(path.join(root, 'tests/web/lib/rated.mjs'));

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

// The texts pictures (see the top); each from a fresh page.
async function textsPictures(t) {
  const view = { viewport: { width: 900, height: 900 } };
  const open = async (server, name) => Player.open(await t.browser.newContext(view), name,
    pageUrl(await startWebServer(server), server), t.errors);
  const shot = async (p, name) => {
    await p.page.screenshot({ path: path.join(out, name) });
    console.log(`saved ${path.join(out, name)}`);
  };

  const calm = await startServer(['--shot-clock', '0', '--time-scale', '4', '--bot-think-ms', '100', '--bot-seed', '3']);
  let a = await open(calm, 'foul');
  await a.fillLobby({ name: 'Asha', ruleSet: 'icf', botLevel: 'easy' });
  await a.press('#play-bot');
  let s = await a.waitFor('our break', (st) => st.inRoom && st.myTurn && !st.animating && st.aim.phase === 'idle');
  await a.shoot(breakShot(s.aim.side));
  s = await a.waitFor('our next turn', (st, turn) => st.turn !== turn && st.myTurn && !st.animating
    && st.aim.phase === 'idle', 60000, s.turn);
  // The striker straight into a bottom pocket, from the first place on the baseline with a
  // clear way there (no piece within 32 px of the path).
  const pieces = s.board.filter((b) => !b.pocketed && b.kind !== 'striker');
  const gap = (x, px) => Math.min(...pieces.map((b) => {
    const [dx, dy] = [px - x, 543 - 520];
    const k = Math.max(0, Math.min(1, ((b.x - x) * dx + (b.y - 520) * dy) / (dx * dx + dy * dy)));
    return Math.hypot(b.x - x - k * dx, b.y - 520 - k * dy);
  }));
  let aimAt = null;
  for (let x = 113; x <= 487 && !aimAt; x += 2) {
    for (const px of [57, 543]) if (!aimAt && gap(x, px) > 32) aimAt = { x, px };
  }
  const dist = Math.hypot(aimAt.px - aimAt.x, 23);
  await a.shoot({ x: aimAt.x, angle: Math.atan2(543 - 520, aimAt.px - aimAt.x), power: Math.min(25, 5 + dist / 20) });
  // As soon as the foul is said (the server's bot plays its turn at once).
  await a.waitFor('the foul said', (st) => st.log.some((l) => l.text.startsWith('Foul by Asha: The striker')), 30000);
  await shot(a, 'web-foul.png');

  const quick = await startServer(['--shot-clock', '1', '--bot-shot-clock', '1', '--time-scale', '8', '--bot-think-ms', '50']);
  a = await open(quick, 'loser');
  await a.fillLobby({ name: 'Asha', botLevel: 'easy' });
  await a.press('#play-bot');
  await a.waitFor('the game over', (st) => st.phase === 'game_over' && !st.animating && st.gameEnd !== null, 60000);
  await shot(a, 'web-game-over-loser.png');

  const friends = await startServer(['--shot-clock', '0', '--no-bots']);
  a = await open(friends, 'winner');
  await a.fillLobby({ name: 'Asha' });
  await a.press('#create');
  const { code } = await a.waitFor('the room', (st) => st.inRoom && st.phase === 'waiting');
  const b = await open(friends, 'leaver');
  await b.fillLobby({ name: 'Ravi', code });
  await b.press('#join');
  await a.waitFor('Ravi seated', (st) => st.phase === 'aiming');
  await b.leaveAndForfeit();
  await a.waitFor('the forfeit', (st) => st.phase === 'game_over' && !st.seats[1].occupied);
  await shot(a, 'web-game-over-winner.png');

  const boards = await startServer(['--shot-clock', '0', '--time-scale', '16', '--bot-think-ms', '20', '--bot-seed', '3']);
  a = await open(boards, 'boards');
  await a.fillLobby({ name: 'Asha', ruleSet: 'icf', targetPoints: 99, boards: 2, botLevel: 'hard' });
  await a.press('#play-bot');
  let shots = 0;
  for (;;) {
    s = await a.state();
    if (s.boardSummary !== null && s.boardNumber === 2) break;
    if (s.inRoom && s.myTurn && !s.animating && s.aim.phase === 'idle') {
      await a.shoot(s.shots === 0 ? breakShot(s.aim.side) : chooseShot(s.board, s.aim.side, shots));
      shots += 1;
      await a.waitFor('the shot result', (st) => st.turn !== st.shotSentTurn || st.boardSummary !== null, 30000);
    } else {
      await new Promise((r) => { setTimeout(r, 50); });
    }
  }
  await a.waitFor('the card drawn', (st) => !st.animating && st.boardSummary !== null);
  await shot(a, 'web-board-summary.png');
}

// A rated game of the seeded players (see the top): the seats, the game over, the leaderboard.
async function ratingsPictures(t) {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'carrom-shots-'));
  try {
    const { server, web } = await startSeededServer(dir, ['--shot-clock', '0', '--quick-match-bot', '0']);
    const [asha, ravi] = await ratedPair(t.browser, server, web, t.errors);
    await asha.waitFor('both ratings read', (st) => st.ratings.seats.every((x) => x !== ''));
    const saved = [];
    const shot = async (file, target = asha.page) => {
      await target.screenshot({ path: path.join(out, file) });
      saved.push(path.join(out, file));
    };
    await shot('web-ratings-seats.png');
    await ravi.leaveAndForfeit();
    await asha.waitFor('the changes', (st) => st.phase === 'game_over' && st.ratings.gameOver.startsWith('Ratings: Asha'), 15000);
    await shot('web-ratings-game-over.png');
    await asha.press('#to-lobby');
    await asha.waitFor('the lobby', (st) => !st.inRoom && st.session.phase === 'lobby');
    await asha.page.click('#leaderboard summary');
    await asha.page.waitForSelector('#leaderboard-rows tr:nth-child(3)');
    await asha.page.locator('#leaderboard').scrollIntoViewIfNeeded();
    await shot('web-leaderboard.png');
    console.log(`saved ${saved.join(', ')}`);
  } finally {
    fs.rmSync(dir, { recursive: true, force: true });
  }
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
  if (wanted('texts')) await textsPictures(t);
  if (wanted('ratings')) await ratingsPictures(t);
  if (!wanted('singles')) return;
  const desk = await Player.open(await t.browser.newContext({ viewport: { width: 900, height: 900 } }), 'desktop', pageUrl(web, server), t.errors);
  await desk.fillLobby({ name: 'Asha', ruleSet: 'icf', botLevel: 'easy' });
  await desk.press('#play-bot');
  let s = await desk.waitFor('our break', (st) => st.inRoom && st.myTurn && !st.animating && st.aim.phase === 'idle'
    && (st.engine.loaded || st.engine.error !== null));
  const from = await desk.toClient(s.aim.x, s.aim.y);
  const to = await desk.toClient(s.aim.x + 40, s.aim.y + 110);
  await desk.page.mouse.move(from.x, from.y);
  await desk.page.mouse.down();
  await desk.page.mouse.move(to.x, to.y, { steps: 6 });
  await desk.waitFor('the aim assist', (st) => st.assist.shown || !st.engine.loaded);
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
  await phone.press('#coach-skip');
  await phone.page.screenshot({ path: path.join(out, 'web-phone.png') });
  await phone.press('#help');
  await phone.page.screenshot({ path: path.join(out, 'web-rules.png') });
  console.log(`saved ${['web-aim.png', 'web-phone.png', 'web-rules.png'].map((f) => path.join(out, f)).join(', ')}`);
});
