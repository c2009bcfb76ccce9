// A browser page and carrom-client (the SFML desktop client, under Xvfb when DISPLAY is unset)
// play one short match against each other through a real carrom-server (freestyle, first coin
// wins): the page creates the room and plays its turns with the mouse; carrom-client joins with
// the room code and plays its own with `--autoplay easy` (the server bots' strategy, through
// the client's mouse input path). Both sides end the game; carrom-client writes the final state
// it saw (`--final-state`) and exits. Checks: the same pieces (each piece's pocketed flag and,
// on the board, its position as the server sent it), scores, winner and reason (the rule code)
// on both sides; shots from both; no console errors.

import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { check, env, launchBrowser, pageUrl, run, startChild, startServer, startWebServer } from './lib/harness.mjs';
import { playUntilOver } from './lib/match.mjs';
import { Player } from './lib/player.mjs';

run('web.client_match', 80000, async (t) => {
  check(env.client, 'CARROM_CLIENT is not set');
  const server = await startServer(['--shot-clock', '0', '--time-scale', '8', '--no-bots']);
  const web = await startWebServer(server);
  t.browser = await launchBrowser();
  const page = await Player.open(await t.browser.newContext({ viewport: { width: 900, height: 900 } }), 'Asha', pageUrl(web, server), t.errors);
  await page.fillLobby({ name: 'Asha', ruleSet: 'freestyle', targetPoints: 10, boards: 1, shotClock: 0 });
  await page.press('#create');
  const { code } = await page.waitFor('the room', (s) => s.inRoom && s.phase === 'waiting');

  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'carrom-client-match-'));
  const finalFile = path.join(dir, 'final.json');
  const clientArgs = [
    '--url', server.ws, '--name', 'Desk', '--join', code, '--mute', '--width', '700', '--height', '700',
    '--autoplay', 'easy', '--final-state', finalFile, '--timeout', '70',
  ];
  const display = process.env.DISPLAY;
  // Under AddressSanitizer the client runs without the leak check: Mesa's GL driver leaks a few
  // hundred bytes at exit (as in tests/client/network_match_test.cpp).
  const clientEnv = { ...process.env, ASAN_OPTIONS: `${process.env.ASAN_OPTIONS ?? ''}:detect_leaks=0` };
  const client = display
    ? await startChild('carrom-client', env.client, clientArgs, new RegExp(`^room ${code}$`), 20000, clientEnv)
    : await startChild('carrom-client', 'xvfb-run', ['-a', '-s', '-screen 0 1280x1024x24', env.client, ...clientArgs],
      new RegExp(`^room ${code}$`), 20000, clientEnv);
  const joined = await page.waitFor('carrom-client seated', (s) => s.seats[1] && s.seats[1].occupied && s.phase === 'aiming');
  check(joined.seats[1].name === 'Desk', `carrom-client's name on the page (${joined.seats[1].name})`);

  const shots = await playUntilOver([page], { maxShots: 30, timeoutMs: 60000 });
  const end = await page.waitFor('the end on screen', (s) => s.phase === 'game_over' && !s.animating && s.gameEnd !== null, 20000);
  const exit = await client.exited;
  check(exit === 0, `carrom-client ended the game and exited with ${exit}:\n${client.log.slice(-30).join('\n')}`);
  check(client.log.includes(`final state ${finalFile}`), 'carrom-client says it wrote the final state');
  const desk = JSON.parse(fs.readFileSync(finalFile, 'utf8'));
  fs.rmSync(dir, { recursive: true, force: true });

  check(desk.room === code && desk.you === 1, `carrom-client's room ${desk.room}, seat ${desk.you}`);
  const pageScores = end.seats.map((x) => x.score);
  check(JSON.stringify(desk.scores) === JSON.stringify(pageScores), `scores: page ${pageScores}, carrom-client ${desk.scores}`);
  check(desk.winner === end.winner && desk.winner >= 0, `winner: page ${end.winner}, carrom-client ${desk.winner}`);
  check(desk.reason === end.gameEnd.reason, `reason: page ${end.gameEnd.reason}, carrom-client ${desk.reason}`);
  // Both name the end by game_end's rule code (docs/protocol.md), as the journal does.
  const ruleCodes = ['target_points', 'boards_played', 'board_cleared', 'colour_cleared', 'coins_exhausted',
    'opponent_last_coin', 'forfeit', 'missed_turns'];
  check(ruleCodes.includes(desk.reason), `reason ${desk.reason} is a rule code`);
  const pieces = (list) => list.map((b) => ({ id: b.id, kind: b.kind, pocketed: b.pocketed, x: b.pocketed ? null : b.x, y: b.pocketed ? null : b.y }))
    .sort((a, b) => a.id - b.id);
  const a = pieces(end.board);
  const b = pieces(desk.bodies);
  check(a.length === 20 && a.length === b.length, `pieces: page ${a.length}, carrom-client ${b.length}`);
  for (let i = 0; i < a.length; i += 1) {
    check(JSON.stringify(a[i]) === JSON.stringify(b[i]), `piece ${a[i].id}: page ${JSON.stringify(a[i])}, carrom-client ${JSON.stringify(b[i])}`);
  }
  const clientShots = end.shots - shots;
  check(shots > 0 && clientShots > 0, `both shot (page ${shots}, carrom-client ${clientShots})`);
  console.log(`room ${code}: page ${shots} shots, carrom-client ${clientShots}; ${a.filter((p) => p.pocketed).length} pieces pocketed; ${end.gameEnd.sentence}`);
});
