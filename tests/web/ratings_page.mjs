// The ratings on the page after a rated game (docs/web.md, "Ratings in a match", "Leaderboard"):
// Asha (ICF 1600) and Ravi (ICF 1520), established players in the store, take their keys in the
// lobby and meet in a rated quick match. Both top bars show both ratings beside the names; the
// room has no aim assist (a pull shows no guide); Ravi leaves and forfeits, and Asha's game-over
// card shows both new ratings with their changes, as GET /players gives them. In the lobby the
// leaderboard lists Asha first and Ravi second with those ratings and 21 games, another rule set
// says it has nobody yet, and My matches lists the game from Asha's side with its replay link.
// A server without a store: the leaderboard says so in one sentence.

import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';

import { check, launchBrowser, pageUrl, run, startServer, startWebServer } from './lib/harness.mjs';
import { Player } from './lib/player.mjs';
import { ratedPair, SEEDED, startSeededServer } from './lib/rated.mjs';

const signed = (n) => `${n >= 0 ? '+' : ''}${n}`;

run('web.ratings_page', 120000, async (t) => {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'carrom_ratings_page_'));
  const { server, web } = await startSeededServer(dir, ['--shot-clock', '0', '--quick-match-bot', '0']);
  t.browser = await launchBrowser();
  const [asha, ravi] = await ratedPair(t.browser, server, web, t.errors);

  // Beside each name, on both pages: the own seat on the left.
  for (const [page, left, right] of [[asha, '1600', '1520'], [ravi, '1520', '1600']]) {
    const s = await page.waitFor('both ratings read', (st) => st.ratings.seats.every((x) => x !== ''));
    check(s.aimAssist === false && s.ratings.rated, `${page.label}: a rated room without aim assist`);
    await page.page.waitForFunction(([l, r]) => document.querySelector('#seat-left .rating').textContent === l
      && document.querySelector('#seat-right .rating').textContent === r, [left, right], { timeout: 5000 });
  }
  const shown = await asha.page.textContent('#seat-right');
  check(shown.includes('Ravi') && shown.includes('1520'), `Asha's top bar shows Ravi's rating (${shown})`);

  // The seat to play pulls back: no guide in a rated room, also with the engine loaded.
  const engine = process.env.CARROM_WEB_ENGINE === '1';
  const players = [asha, ravi];
  let turn = null;
  for (const p of players) if ((await p.state()).myTurn) turn = p;
  check(turn !== null, 'one page is to play');
  let s = await turn.waitFor('ready to aim', (st) => st.aim.phase === 'idle' && (!engine || st.engine.loaded));
  const from = s.aim.striker;
  const mouse = turn.page.mouse;
  const grab = await turn.toClient(from.x, from.y);
  await mouse.move(grab.x, grab.y);
  await mouse.down();
  const pulled = await turn.toClient(from.x, from.y + (s.aim.side === 'top' ? -100 : 100));
  await mouse.move(pulled.x, pulled.y, { steps: 6 });
  s = await turn.waitFor('pulling', (st) => st.aim.phase === 'pulling');
  check(!s.assist.shown && s.assist.stats.runs === 0, `no aim assist in a rated room (${JSON.stringify(s.assist)})`);
  await turn.page.keyboard.press('Escape');
  await mouse.up();

  // Ravi forfeits: Asha's card names both changes as the store wrote them.
  await ravi.leaveAndForfeit();
  s = await asha.waitFor('the game over with the ratings', (st) => st.phase === 'game_over' && st.ratings.gameOver.startsWith('Ratings: Asha'), 15000);
  const after = {};
  for (const p of SEEDED) {
    const answer = await (await fetch(`http://127.0.0.1:${server.port}/players/${p.name}`)).json();
    const r = answer.ratings.find((x) => x.rule_set === 'icf');
    check(r.games === p.games + 1, `${p.name} has one more game (${JSON.stringify(r)})`);
    after[p.name] = { ...r, change: Math.round(r.rating) - p.rating };
  }
  check(after.Asha.change > 0 && after.Ravi.change < 0, `the winner rose, the loser fell (${JSON.stringify(after)})`);
  // A rating and its change are kept on one line by a no-break space.
  const expected = `Ratings: Asha ${after.Asha.label}\u00a0(${signed(after.Asha.change)}), Ravi ${after.Ravi.label}\u00a0(${signed(after.Ravi.change)})`;
  await asha.page.waitForFunction((text) => document.getElementById('game-over-ratings').textContent === text, expected, { timeout: 5000 });
  check(await asha.page.isVisible('#game-over-ratings'), 'the card shows the ratings line');
  check(await asha.page.textContent('#seat-left .rating') === after.Asha.label, 'Asha\'s seat shows her new rating');

  // The lobby: the leaderboard in rating order, the own row marked; another rule set has nobody.
  await asha.press('#to-lobby');
  await asha.waitFor('the lobby', (st) => !st.inRoom && st.session.phase === 'lobby');
  await asha.page.click('#leaderboard summary');
  await asha.page.waitForFunction(() => document.querySelectorAll('#leaderboard-rows tr').length === 3, null, { timeout: 5000 });
  const rows = await asha.page.$$eval('#leaderboard-rows tr', (trs) => trs.map((tr) => [...tr.children].map((c) => c.textContent).join('|')));
  const want = ['#|Player|Rating|Games', `1|Asha|${after.Asha.label}|21`, `2|Ravi|${after.Ravi.label}|21`];
  check(JSON.stringify(rows) === JSON.stringify(want), `the leaderboard: ${JSON.stringify(rows)}, wanted ${JSON.stringify(want)}`);
  check(await asha.page.getAttribute('#leaderboard-rows tr:nth-child(2)', 'class') === 'you', 'Asha\'s own row is marked');
  check(await asha.page.textContent('#leaderboard-note') === '', 'no sentence beside rows');
  await asha.page.selectOption('#leaderboard-rule-set', 'seed');
  await asha.page.waitForFunction(() => document.getElementById('leaderboard-rows').hidden, null, { timeout: 5000 });
  const note = await asha.page.textContent('#leaderboard-note');
  check(note === 'Nobody has an established classic rating yet (it takes about 10 rated games).', `another rule set: ${note}`);
  await asha.page.selectOption('#leaderboard-rule-set', 'icf');
  await asha.page.waitForFunction(() => !document.getElementById('leaderboard-rows').hidden, null, { timeout: 5000 });

  // My matches: the game from Asha's side, a link to its replay.
  await asha.page.click('#my-matches summary');
  await asha.page.waitForSelector('#my-matches a', { timeout: 5000 });
  const match = await asha.page.$eval('#my-matches a', (a) => ({ text: a.textContent, href: a.getAttribute('href') }));
  check(match.text.startsWith('vs Ravi · won 0 : 0 · ICF · '), `My matches: ${match.text}`); // a forfeit before any point
  check(/^#\/replay\/[0-9a-z]{16}$/.test(match.href), `the replay link ${match.href}`);
  check((await asha.page.textContent('#my-rating')).startsWith(`Rating: ICF ${after.Asha.label}`), 'the lobby\'s rating line');

  // A server that keeps no ratings: one sentence, no table.
  const bare = await startServer();
  const other = await Player.open(await t.browser.newContext(), 'Guest', pageUrl(await startWebServer(bare), bare), t.errors);
  await other.page.click('#leaderboard summary');
  await other.page.waitForFunction(() => document.getElementById('leaderboard-note').textContent.startsWith('This server'), null, { timeout: 5000 });
  check(await other.page.textContent('#leaderboard-note') === 'This server keeps no ratings, so it has no leaderboard.', 'no store');
  check(await other.page.isHidden('#leaderboard-rows'), 'no table without rows');
  // Chromium logs every answer of status 400 or more; the store's 503 is the expected one here.
  const expectedLog = /^Guest: Failed to load resource: the server responded with a status of 503/;
  t.errors.splice(0, t.errors.length, ...t.errors.filter((e) => !expectedLog.test(e)));
  console.log(`after the rated game: "${expected}"; My matches: "${match.text}"`);
  fs.rmSync(dir, { recursive: true, force: true });
});
