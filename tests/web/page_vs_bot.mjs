// A page plays a whole match against carrom-bot (a separate process joining with the room code
// the page shows). Checks: the bot's seat and name on the page, the same final scores and reason
// on both sides, the bot's result matching the page's winner, the page's strokes predicted by the
// engine without corrections, no console errors.

import { check, env, launchBrowser, pageUrl, run, startChild, startServer, startWebServer } from './lib/harness.mjs';
import { playUntilOver } from './lib/match.mjs';
import { Player } from './lib/player.mjs';

run('web.page_vs_bot', 150000, async (t) => {
  check(env.bot, 'CARROM_BOT is not set');
  const server = await startServer(['--shot-clock', '0', '--time-scale', '8', '--no-bots']);
  const web = await startWebServer(server);
  t.browser = await launchBrowser();
  const page = await Player.open(await t.browser.newContext({ viewport: { width: 900, height: 900 } }), 'Asha', pageUrl(web, server), t.errors);
  await page.fillLobby({ name: 'Asha', ruleSet: 'freestyle', targetPoints: 10, boards: 1, shotClock: 0 });
  await page.press('#create');
  const { code } = await page.waitFor('the room', (s) => s.inRoom && s.phase === 'waiting');
  check(await page.page.isVisible('#waiting'), 'the room code is shown while waiting');
  check((await page.page.textContent('#waiting-code')) === code, 'the shown code is the room code');

  const bot = await startChild('carrom-bot', env.bot, [
    '--url', server.ws, '--name', 'Greedy', '--join', code, '--strategy', 'greedy', '--level', 'easy',
    '--think-ms', '200', '--games', '1', '--timeout', '120', '--log-level', 'warn',
  ], new RegExp(`room ${code}`));
  const joined = await page.waitFor('the bot seated', (s) => s.seats[1] && s.seats[1].occupied && s.phase === 'aiming');
  check(joined.seats[1].name === 'Greedy', `the bot's name on the page (${joined.seats[1].name})`);

  const shots = await playUntilOver([page], { maxShots: 40, timeoutMs: 110000 });
  const end = await page.waitFor('the end on screen', (s) => s.phase === 'game_over' && !s.animating && s.gameEnd !== null, 30000);
  const code1 = await bot.exited;
  const summaryLine = bot.log.filter((l) => l.startsWith('{')).pop();
  check(summaryLine, `the bot printed no summary (exit ${code1})`);
  const summary = JSON.parse(summaryLine);
  check(code1 === 0 && summary.ok, `the bot finished cleanly (exit ${code1}): ${summaryLine}`);
  const scores = end.seats.map((x) => x.score);
  check(JSON.stringify(summary.scores) === JSON.stringify(scores), `scores: page ${scores}, bot ${summary.scores}`);
  check(summary.reason === end.gameEnd.reason, `reason: page ${end.gameEnd.reason}, bot ${summary.reason}`);
  const botResult = end.winner === 1 ? 'won' : end.winner === 0 ? 'lost' : 'drawn';
  check(summary.result === botResult, `the bot ${summary.result}, the page says it ${botResult}`);
  // The page's own strokes were predicted by the engine (docs/web.md, "Shot prediction"), when
  // the build has it (CARROM_WEB_ENGINE=1); without it nothing is predicted.
  const withEngine = process.env.CARROM_WEB_ENGINE !== '0';
  check(end.engine.loaded === withEngine, `the engine loaded: ${end.engine.loaded} (${end.engine.error})`);
  check(withEngine ? end.prediction.strokes >= 1 && end.prediction.corrections === 0 : end.prediction === null,
    `strokes predicted ${end.prediction?.strokes}, corrected ${end.prediction?.corrections}`);
  console.log(`room ${code}: page ${shots} shots, bot ${summary.shots}; ${end.prediction?.strokes ?? 0} predicted, largest difference ${end.prediction?.maxDifferencePx.toFixed(4) ?? '-'} px, engine ${end.engine.ms?.toFixed(1) ?? '-'} ms; ${end.gameEnd.sentence}`);
});
