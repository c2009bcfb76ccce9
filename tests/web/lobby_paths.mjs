// The lobby's other ways in and out, through the page's controls: a name is required; quick
// match pairs two pages; a wrong code is refused in plain words; Leave goes back to the lobby and
// the opponent wins (the reason on screen); a room link opened with a name already known joins
// at once, and watches when the room is full; no console errors.

import { check, launchBrowser, pageUrl, run, startServer, startWebServer } from './lib/harness.mjs';
import { Player } from './lib/player.mjs';

const VIEW = { viewport: { width: 900, height: 900 } };

run('web.lobby_paths', 120000, async (t) => {
  const server = await startServer(['--shot-clock', '0', '--quick-match-bot', '0']);
  const web = await startWebServer(server);
  t.browser = await launchBrowser();
  const a = await Player.open(await t.browser.newContext(VIEW), 'Asha', pageUrl(web, server), t.errors);
  const b = await Player.open(await t.browser.newContext(VIEW), 'Ravi', pageUrl(web, server), t.errors);

  await a.press('#quick');
  check((await a.page.textContent('#lobby-error'))
    === 'Type your name first: 1 to 24 letters (accented letters count twice).', 'a name is required, in plain words');
  check((await a.state()).session.phase === 'idle', 'nothing was sent without a name');

  // Quick match: the two pages are paired.
  await a.fillLobby({ name: 'Asha', ruleSet: 'freestyle' });
  await a.press('#quick');
  await a.waitFor('waiting for an opponent', (s) => s.session.phase === 'joining');
  check((await a.page.textContent('#lobby-status')) === 'Waiting for an opponent...', 'the lobby says it waits');
  check(await a.page.isEnabled('#lobby-cancel'), 'waiting can be cancelled');
  await a.press('#lobby-cancel');
  await a.waitFor('back in the lobby', (s) => s.session.phase === 'lobby');
  check(!(await a.page.isVisible('#lobby-cancel')), 'nothing left to cancel');
  await a.press('#quick');
  await a.waitFor('waiting again', (s) => s.session.phase === 'joining');
  await b.fillLobby({ name: 'Ravi', ruleSet: 'freestyle' });
  await b.press('#quick');
  const qa = await a.waitFor('paired', (s) => s.inRoom && s.phase === 'aiming');
  const qb = await b.waitFor('paired', (s) => s.inRoom && s.phase === 'aiming');
  check(qa.code === qb.code && qa.ruleSet === 'freestyle', 'both in one freestyle room');
  check(qa.you + qb.you === 1, 'two different seats');

  // Leave asks first (the game would be forfeited); Leave again: back to the lobby; the opponent
  // wins because the other left.
  await a.leaveAndForfeit();
  await a.waitFor('the lobby', (s) => !s.inRoom && s.session.phase === 'lobby');
  check(await a.page.isVisible('#lobby'), 'the lobby is shown again');
  check((await a.state()).hash === '', 'the address no longer names the room');
  const over = await b.waitFor('the game over', (s) => s.phase === 'game_over' && s.gameEnd !== null);
  check(over.gameEnd.sentence === 'You win the game (the opponent left)', over.gameEnd.sentence);
  check((await b.page.textContent('#game-over-result')) === 'You won!', 'the winner reads it from their side');
  check((await b.page.textContent('#game-over-reason')) === 'Asha left the game.', 'the reason is on screen');
  check(!(await b.page.isVisible('#rematch')), 'no rematch once the opponent left');
  await b.press('#to-lobby');
  await b.waitFor('the lobby', (s) => !s.inRoom);

  // A wrong code.
  await a.fillLobby({ code: 'ZZZZZZ' });
  await a.press('#join');
  await a.page.waitForFunction(() => document.getElementById('lobby-error').textContent !== '', null, { timeout: 10000 });
  check((await a.page.textContent('#lobby-error')) === 'There is no room with that code. Check the code and try again.', 'wrong code in plain words');

  // A full room's link, opened with a known name: the page joins at once and, the room being
  // full, watches.
  await a.press('#create');
  const { code } = await a.waitFor('the room', (s) => s.inRoom && s.phase === 'waiting');
  await b.fillLobby({ code });
  await b.press('#join');
  await b.waitFor('seated', (s) => s.inRoom && s.you >= 0);
  const zoeContext = await t.browser.newContext(VIEW);
  await zoeContext.addInitScript(() => window.localStorage.setItem('carrom.name', 'Zoe'));
  const zoe = await Player.open(zoeContext, 'Zoe', pageUrl(web, server, `#/room/${code}`), t.errors);
  const z = await zoe.waitFor('watching the full room', (s) => s.inRoom && s.you === -1);
  check(z.code === code && z.hash === `#/watch/${code}`, `watching ${z.code} at ${z.hash}`);
  const seen = await a.waitFor('the match under way', (s) => s.phase === 'aiming');
  check(seen.seats[0].name === 'Asha' && seen.seats[1].name === 'Ravi', 'the seats are unchanged');
  // A spectator's arrival sends the players nothing (docs/protocol.md, room_state.spectators):
  // the spectator's own room_state, built after the arrival, counts it.
  check((await zoe.page.textContent('#room-info')).includes('1 spectator'), "the spectator's HUD counts the spectator");
});
