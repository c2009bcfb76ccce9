// What a newcomer reads in the page, against a real carrom-server: a game against a server bot
// lost on three missed shot clocks (the countdown, each miss with how many more lose, the
// warning colour, the game over from the loser's side with the score), the longer default clock
// of a bot game, a friend who leaves (the forfeit line, no rematch offered), and the card
// between two boards (who won the board, the points, the new colour).

import { check, launchBrowser, pageUrl, run, sleep, startServer, startWebServer } from './lib/harness.mjs';
import { breakShot } from './lib/match.mjs';
import { Player } from './lib/player.mjs';
import { chooseShot } from './lib/shot_chooser.mjs';

const VIEW = { viewport: { width: 900, height: 900 } };
const said = (s, text) => s.log.find((l) => l.text === text);

// A bot game on the server's default clocks: the bot's room gets --bot-shot-clock, a friend's
// room --shot-clock.
async function defaultClocks(t) {
  const bots = await startServer(['--shot-clock', '20', '--bot-shot-clock', '40']);
  const web = await startWebServer(bots);
  const a = await Player.open(await t.browser.newContext(VIEW), 'Asha', pageUrl(web, bots), t.errors);
  await a.fillLobby({ name: 'Asha', botLevel: 'easy' });
  await a.press('#play-bot');
  await a.waitFor('the bot room', (s) => s.inRoom && s.phase === 'aiming');
  const b = await Player.open(await t.browser.newContext(VIEW), 'Ravi', pageUrl(web, bots), t.errors);
  await b.fillLobby({ name: 'Ravi' });
  await b.press('#create');
  await b.waitFor('the friend room', (s) => s.inRoom);
  const [botClock, friendClock] = [(await a.state()).options.shot_clock_s, (await b.state()).options.shot_clock_s];
  check(botClock === 40, `a bot game's clock: ${botClock} s`);
  check(friendClock === 20, `a friend room's clock: ${friendClock} s`);
  await a.page.context().close();
  await b.page.context().close();
}

// Never shooting against a bot with a 1 s clock: three misses lose the game.
async function clockLoss(t) {
  const server = await startServer(['--shot-clock', '1', '--bot-shot-clock', '1', '--time-scale', '8',
    '--bot-think-ms', '50']);
  const web = await startWebServer(server);
  const a = await Player.open(await t.browser.newContext(VIEW), 'Asha', pageUrl(web, server), t.errors);
  await a.fillLobby({ name: 'Asha', botLevel: 'easy' });
  await a.press('#play-bot');
  let hurry = '';
  const deadline = Date.now() + 60000;
  for (;;) {
    const s = await a.state();
    if (s.phase === 'game_over') break;
    check(Date.now() < deadline, 'three missed clocks did not end the game within 60 s');
    if (s.myTurn && !hurry) {
      const status = await a.page.textContent('#status-line');
      if (status.includes('Your turn')) hurry = status;
    }
    await sleep(50);
  }
  const end = await a.waitFor('the end on screen', (s) => s.phase === 'game_over' && !s.animating && s.gameEnd !== null);
  check(/^Your turn {2}1 s left!$/.test(hurry.trim()), `the countdown on our turn: "${hurry}"`);
  check(end.countdownTicks >= 3, `a tick in the last seconds of each of our turns: ${end.countdownTicks}`);
  const two = said(end, 'Foul by Asha: The shot clock ran out; the turn passes. 2 more missed turns in a row lose the game.');
  const one = said(end, 'Foul by Asha: The shot clock ran out; the turn passes. One more missed turn in a row loses the game.');
  const lost = said(end, 'Foul by Asha: Too many turns were missed in a row: the game is lost.');
  check(two && one && lost, `each miss says how many more lose:\n${end.log.map((l) => l.text).join('\n')}`);
  check([two, one, lost].every((l) => l.tone === 'foul'), 'the misses are warnings');
  check(!end.log.some((l) => l.tone === 'good' && l.text.startsWith('Foul')), 'no foul in the good-news colour');
  const text = async (sel) => (await a.page.textContent(sel)).trim();
  check(await text('#game-over-result') === 'You lost', `title: ${await text('#game-over-result')}`);
  check(await text('#game-over-reason') === 'You let the shot clock run out three times in a row.',
    `reason: ${await text('#game-over-reason')}`);
  const score = await text('#game-over-score');
  check(/^Final score: Asha 0, Bot \(easy\) \d+$/.test(score), `score: ${score}`);
  check(await a.page.isVisible('#rematch'), 'a rematch is offered against a bot');
  await a.page.context().close();
}

// Ravi leaves a finished-or-not friend game: Asha reads who left and that she wins, and no
// rematch is offered.
async function friendLeaves(t) {
  const server = await startServer(['--shot-clock', '0', '--no-bots']);
  const web = await startWebServer(server);
  const a = await Player.open(await t.browser.newContext(VIEW), 'Asha', pageUrl(web, server), t.errors);
  await a.fillLobby({ name: 'Asha' });
  await a.press('#create');
  const { code } = await a.waitFor('the room', (s) => s.inRoom && s.phase === 'waiting');
  const b = await Player.open(await t.browser.newContext(VIEW), 'Ravi', pageUrl(web, server), t.errors);
  await b.fillLobby({ name: 'Ravi', code });
  await b.press('#join');
  await a.waitFor('Ravi seated', (s) => s.phase === 'aiming' && s.seats[1].occupied);
  await b.leaveAndForfeit();
  const end = await a.waitFor('the forfeit', (s) => s.phase === 'game_over' && !s.seats[1].occupied);
  const line = said(end, 'Ravi left the match: you win by forfeit');
  check(line && line.tone === 'good', `the forfeit line: ${JSON.stringify(end.log)}`);
  check(!end.log.some((l) => l.text.includes('A player forfeited')), 'no bare "A player forfeited"');
  check((await a.page.textContent('#game-over-result')).trim() === 'You won!', 'the winner reads "You won!"');
  check((await a.page.textContent('#game-over-reason')).trim() === 'Ravi left the game.', 'why');
  check(!(await a.page.isVisible('#rematch')), 'no rematch offered once the opponent left');
  check((await a.page.textContent('#game-over-waiting')).trim() === 'Your opponent left the room: no rematch',
    'the panel says why');
  await a.page.context().close();
  await b.page.context().close();
}

// ICF, two boards, against a hard server bot: the page plays until the first board ends.
async function boardSummary(t) {
  const server = await startServer(['--shot-clock', '0', '--time-scale', '16', '--bot-think-ms', '20', '--bot-seed', '3']);
  const web = await startWebServer(server);
  const a = await Player.open(await t.browser.newContext(VIEW), 'Asha', pageUrl(web, server), t.errors);
  await a.fillLobby({ name: 'Asha', ruleSet: 'icf', targetPoints: 99, boards: 2, botLevel: 'hard' });
  await a.press('#play-bot');
  await a.waitFor('the bot room', (s) => s.inRoom && s.phase !== 'waiting');
  const deadline = Date.now() + 120000;
  let shots = 0;
  let s;
  for (;;) {
    s = await a.state();
    if (s.boardSummary !== null || s.phase === 'game_over') break;
    check(Date.now() < deadline, `no board ended within 120 s (${shots} shots by the page)`);
    if (s.myTurn && !s.animating && s.aim.phase === 'idle') {
      await a.shoot(s.shots === 0 ? breakShot(s.aim.side) : chooseShot(s.board, s.aim.side, shots));
      shots += 1;
      await a.waitFor('the shot result', (st) => st.turn !== st.shotSentTurn || st.boardSummary !== null, 30000);
    } else {
      await sleep(50);
    }
  }
  check(s.phase !== 'game_over', 'the first board did not end the game');
  s = await a.waitFor('the next board', (st) => st.boardNumber === 2 && st.boardSummary !== null);
  check(await a.page.isVisible('#board-summary'), 'the card between boards is shown');
  const title = (await a.page.textContent('#board-summary-title')).trim();
  const points = (await a.page.textContent('#board-summary-points')).trim();
  const colours = (await a.page.textContent('#board-summary-colours')).trim();
  check(/^(You|Bot \(hard\)) won board 1$/.test(title), `title: ${title}`);
  check(/^\+\d+ points?\. Score: you \d+, Bot \(hard\) \d+$/.test(points), `points: ${points}`);
  const me = s.seats[s.you];
  check(colours === `Board 2: you play ${me.colour}`, `colours: ${colours} (seat colour ${me.colour})`);
  await a.page.click('#board-summary');
  await a.waitFor('the card dismissed', (st) => st.boardSummary === null, 5000);
  check(!(await a.page.isVisible('#board-summary')), 'a click dismisses the card');
  console.log(`board 1 after ${shots} page shots: ${title}; ${points}; ${colours}`);
}

run('web.texts_pages', 190000, async (t) => {
  t.browser = await launchBrowser();
  await defaultClocks(t);
  await clockLoss(t);
  await friendLeaves(t);
  await boardSummary(t);
});
