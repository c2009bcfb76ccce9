// A page keeps its player key across a reload, and shows its rating after a rated game
// (docs/ratings.md): its quick match meets carrom-bot --identity (a rated room); the page leaves
// at once (Leave, then the question's Leave), a forfeit, so the bot wins; back in the lobby the
// page reads "Rating: ICF 1338? (-162)".

import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';

import { check, env, launchBrowser, pageUrl, run, startChild, startServer, startWebServer } from './lib/harness.mjs';
import { Player } from './lib/player.mjs';

run('web.identity_page', 90000, async (t) => {
  check(env.bot, 'CARROM_BOT is not set');
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'carrom_identity_page_'));
  const server = await startServer(['--shot-clock', '0', '--quick-match-bot', '0', '--data', path.join(dir, 'c.db')]);
  const web = await startWebServer(server);
  t.browser = await launchBrowser();
  const page = await Player.open(await t.browser.newContext({ viewport: { width: 900, height: 900 } }), 'Asha', pageUrl(web, server), t.errors);
  const key = await page.page.evaluate(() => localStorage.getItem('carrom.identity'));
  check(/^[0-9a-f]{64}$/.test(key ?? ''), `the page made a player key (${key})`);
  await page.page.reload();
  await page.page.waitForFunction(() => window.carrom !== undefined);
  check(await page.page.evaluate(() => localStorage.getItem('carrom.identity')) === key, 'the key survives a reload');
  check(await page.page.inputValue('#identity-key') === key, 'the lobby shows the key');

  await page.fillLobby({ name: 'Asha', ruleSet: 'icf' });
  await page.press('#quick');
  await page.waitFor('waiting', (s) => s.session.phase === 'joining');
  const bot = await startChild('carrom-bot', env.bot, [
    '--url', server.ws, '--name', 'Ravi', '--identity', path.join(dir, 'ravi.key'), '--quick',
    '--strategy', 'random', '--games', '1', '--timeout', '60', '--log-level', 'warn',
  ], /room [A-Z0-9]{6}/);
  await page.waitFor('paired with the bot', (s) => s.inRoom && s.seats.every((x) => x.occupied));
  await page.leaveAndForfeit(); // Leave asks first while the game runs
  await page.waitFor('the lobby', (s) => !s.inRoom && s.session.phase === 'lobby');
  await page.page.waitForFunction(() => document.getElementById('my-rating').textContent.includes('('), null, { timeout: 10000 });
  const line = await page.page.textContent('#my-rating');
  check(line === 'Rating: ICF 1338? (-162)', `the lobby shows the rating and its change (${line})`);
  const answer = await (await fetch(`http://127.0.0.1:${server.port}/players/Ravi`)).json();
  check(answer.ratings[0].label === '1662?', `the bot's rating rose (${JSON.stringify(answer.ratings)})`);
  await bot.exited;
  fs.rmSync(dir, { recursive: true, force: true });
});
