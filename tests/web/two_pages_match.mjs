// Two browser pages play a whole short match against each other through a real carrom-server
// (freestyle, first coin wins), the second joining through the shareable room link; a third page
// watches through the watch link. Checks: the second player's view is turned (own baseline at
// the bottom) and its mouse shots reach the server as aimed; after the break both screenshots
// show the board and every piece in its colour; at the end all three pages show the same final
// board and scores and the same reason; no console errors.

import { check, launchBrowser, pageUrl, run, startServer, startWebServer } from './lib/harness.mjs';
import { playUntilOver } from './lib/match.mjs';
import { checkPicture } from './lib/picture.mjs';
import { Player } from './lib/player.mjs';

const VIEW = { viewport: { width: 900, height: 900 } };

run('web.two_pages_match', 170000, async (t) => {
  const server = await startServer(['--shot-clock', '0', '--time-scale', '8', '--no-bots']);
  const web = await startWebServer(server);
  t.browser = await launchBrowser();

  const asha = await Player.open(await t.browser.newContext(VIEW), 'Asha', pageUrl(web, server), t.errors);
  await asha.fillLobby({ name: 'Asha', ruleSet: 'freestyle', targetPoints: 10, boards: 1, shotClock: 0 });
  await asha.press('#create');
  const created = await asha.waitFor('the room', (s) => s.inRoom && s.phase === 'waiting');
  const code = created.code;
  check(created.you === 0 && !created.flipped, 'the creator sits at the bottom, seat 0');
  check(created.hash === `#/room/${code}`, `the address shows the room link (${created.hash})`);
  const link = await asha.page.textContent('#waiting-link');
  check(link === pageUrl(web, server, `#/room/${code}`), `shareable link ${link}`);

  // The friend opens the link: the lobby offers that room; a name and Join.
  const ravi = await Player.open(await t.browser.newContext(VIEW), 'Ravi', link, t.errors);
  check((await ravi.page.textContent('#lobby-title')) === `Join room ${code}`, 'the lobby offers the linked room');
  await ravi.fillLobby({ name: 'Ravi' });
  await ravi.press('#join');
  const joined = await ravi.waitFor('seat 1', (s) => s.inRoom && s.you === 1 && s.phase === 'aiming');
  check(joined.flipped, 'seat 1 (top baseline) sees the board turned');
  check(joined.seats[0].name === 'Asha' && joined.seats[1].name === 'Ravi', 'both names in the room');

  const watcher = await Player.open(await t.browser.newContext(VIEW), 'Mira', pageUrl(web, server, `#/watch/${code}`), t.errors);
  await watcher.fillLobby({ name: 'Mira' });
  await watcher.press('#watch');
  await watcher.waitFor('watching', (s) => s.inRoom && s.you === -1);

  // The opponent's live aim: Asha slides her striker, Ravi sees it move there.
  const aiming = await asha.waitFor('our break', (st) => st.myTurn && !st.animating && st.aim.phase === 'idle');
  await asha.drag([{ x: 487, y: aiming.aim.y }, { x: 200, y: aiming.aim.y }]);
  const placed = (await asha.state()).aim.x;
  check(Math.abs(placed - 200) < 1.5, `Asha's striker at ${placed}`);
  await ravi.waitFor('the opponent striker where Asha put it', (st, x) => st.aimX === x
    && st.drawn.some((d) => d.id === -1 && d.x === x && d.y === 520), 5000, placed);

  let pictures = 0;
  let seat1Shots = 0;
  const shots = await playUntilOver([asha, ravi], {
    maxShots: 60,
    timeoutMs: 130000,
    onShot: async (p, shot) => {
      const s = await p.waitFor('the shot result', (st) => st.lastShot && st.lastShot.turn === st.shotSentTurn, 30000);
      // What the server played is what the page aimed (through a turned view for seat 1).
      check(Math.abs(s.lastShot.x - shot.x) < 1.5, `${p.label}: x ${s.lastShot.x}, aimed ${shot.x}`);
      check(Math.abs(s.lastShot.angle - shot.angle) < 0.03, `${p.label}: angle ${s.lastShot.angle}, aimed ${shot.angle}`);
      check(Math.abs(s.lastShot.power - shot.power) < 0.4, `${p.label}: power ${s.lastShot.power}, aimed ${shot.power}`);
      if (s.you === 1) seat1Shots += 1;
      if (pictures === 0 && s.phase !== 'game_over') {
        for (const q of [asha, ravi, watcher]) {
          await q.waitFor('rest after the shot', (st) => !st.animating && st.phase !== 'moving', 20000);
          await checkPicture(q, { minPieces: 6 });
        }
        pictures += 1;
      }
    },
  });
  check(shots > 0, 'the pages shot');
  check((await asha.state()).sounds > 0, 'collision sounds were cued as the break played');

  const finals = [];
  for (const p of [asha, ravi, watcher]) {
    finals.push(await p.waitFor('the end on screen', (s) => s.phase === 'game_over' && !s.animating && s.gameEnd !== null, 30000));
  }
  const [a, r, w] = finals;
  const board = (s) => JSON.stringify(s.board.filter((b) => !b.pocketed).map((b) => [b.id, b.x, b.y]));
  check(board(a) === board(r), 'both players show the same final board');
  check(board(a) === board(w), 'the spectator shows the same final board');
  const scores = (s) => s.seats.map((x) => x.score).join(',');
  check(scores(a) === scores(r) && scores(a) === scores(w), `same scores ${scores(a)} / ${scores(r)} / ${scores(w)}`);
  check(a.gameEnd.reason === r.gameEnd.reason && a.gameEnd.reason === w.gameEnd.reason, 'same reason');
  check(a.winner >= 0 && a.winner === r.winner, `a winner (${a.winner})`);
  const result = await asha.page.textContent('#game-over-result');
  check(result === (a.winner === a.you ? 'You won!' : 'You lost'), `game over panel: ${result}`);
  const why = await asha.page.textContent('#game-over-reason');
  check(/^(You|Ravi) reached \d+ points\.$/.test(why), `why, from Asha's side: ${why}`);
  check(/^Final score: Asha \d+, Ravi \d+$/.test(await asha.page.textContent('#game-over-score')), 'the final score');
  check(await asha.page.isVisible('#rematch'), 'a player is offered a rematch');
  check(!(await watcher.page.isVisible('#rematch')), 'a spectator is not offered a rematch');

  // Rematch: asked by one, it waits; asked by both, a new game starts for all three pages.
  await asha.press('#rematch');
  await asha.page.waitForFunction(() => document.getElementById('rematch').disabled, null, { timeout: 5000 });
  check((await asha.state()).phase === 'game_over', 'one rematch request alone starts nothing');
  await ravi.press('#rematch');
  for (const p of [asha, ravi, watcher]) {
    const s = await p.waitFor('the new game', (st) => st.phase === 'aiming' && st.gameEnd === null && st.seats.every((x) => x.score === 0));
    check(s.board.filter((b) => !b.pocketed && b.kind !== 'striker').length === 19, `${p.label}: a fresh board`);
    check(!(await p.page.isVisible('#game-over')), `${p.label}: the result panel is gone`);
  }
  console.log(`room ${code}: ${shots} shots by the pages (${seat1Shots} from the turned view), ${a.seats[0].score}-${a.seats[1].score}, ${a.gameEnd.sentence}`);
});
