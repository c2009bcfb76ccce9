// Doubles in the browser against a real carrom-server.
//
// 1. A page creates a doubles room with three server bots through the lobby (Players: doubles,
//    Play bots (doubles)) and plays its strokes from the bottom seat while the bots play theirs,
//    for a bounded number of turns. Checks: four seats, the bots on seats 1-3, the four seat
//    panels at their sides of the board (you at the bottom, the partner across at the top, the
//    opponents left and right), the teams in the top bar, every seat has a turn and the turn
//    passes anticlockwise, partners' panels show one score, the page's shots arrive as aimed.
// 2. Four pages fill a doubles room (Create doubles, three joins by code): each sees its own
//    baseline at the bottom (quarter turns for the side seats) with its partner across, and the
//    side seats' mouse shots, aimed in their turned views, reach the server as aimed (board x
//    along the baseline, absolute angle).
// 3. Quick match doubles: a page waiting alone is seated with three server bots when the
//    server's quick-match wait (--quick-match-bot 1) runs out.

import { check, launchBrowser, pageUrl, run, sleep, startServer, startWebServer } from './lib/harness.mjs';
import { breakShot } from './lib/match.mjs';
import { Player } from './lib/player.mjs';
import { chooseShot } from './lib/shot_chooser.mjs';

const VIEW = { viewport: { width: 900, height: 900 } };
const SIDES = ['bottom', 'right', 'top', 'left'];

// What the page shows in its four frame panels: {at: {text, toPlay, score}}.
function framePanels(player) {
  return player.page.$$eval('.frame-seat:not([hidden])', (els) => Object.fromEntries(els.map((el) => [
    el.dataset.at,
    { text: el.textContent, toPlay: el.classList.contains('to-play'), score: el.querySelector('.score').textContent },
  ])));
}

async function shootAndCheck(p, shot) {
  const sent = await p.shoot(shot);
  const s = await p.waitFor('the shot result', (st, turn) => st.lastShot && st.lastShot.turn === turn, 30000,
    sent.shotSentTurn);
  check(Math.abs(s.lastShot.x - shot.x) < 1.5, `${p.label}: x ${s.lastShot.x}, aimed ${shot.x}`);
  const da = Math.abs(Math.atan2(Math.sin(s.lastShot.angle - shot.angle), Math.cos(s.lastShot.angle - shot.angle)));
  check(da < 0.03, `${p.label}: angle ${s.lastShot.angle}, aimed ${shot.angle}`);
  check(Math.abs(s.lastShot.power - shot.power) < 0.6, `${p.label}: power ${s.lastShot.power}, aimed ${shot.power}`);
  return s;
}

async function threeBots(t, web, server) {
  const asha = await Player.open(await t.browser.newContext(VIEW), 'Asha', pageUrl(web, server), t.errors);
  await asha.fillLobby({ name: 'Asha', ruleSet: 'icf', shotClock: 0, botLevel: 'easy' });
  await asha.page.selectOption('#seat-count', '4');
  check((await asha.page.textContent('#play-bot')) === 'Play bots (doubles)', 'the lobby offers bots for doubles');
  await asha.press('#play-bot');
  let s = await asha.waitFor('the doubles room', (st) => st.inRoom && st.seats.length === 4 && st.phase === 'aiming');
  check(s.you === 0 && s.turns === 0, `the creator sits at the bottom, seat 0 (turns ${s.turns})`);
  check(s.seats.slice(1).every((x) => x.bot && x.occupied), 'server bots on seats 1, 2 and 3');
  check(JSON.stringify(s.seats.map((x) => [x.baseline, x.team])) === '[["bottom",0],["right",1],["top",0],["left",1]]',
    `baselines and teams: ${JSON.stringify(s.seats.map((x) => [x.baseline, x.team]))}`);
  let panels = await framePanels(asha);
  check(SIDES.every((at) => panels[at]), `four seat panels: ${Object.keys(panels)}`);
  check(panels.bottom.text.includes('Asha') && panels.bottom.text.includes('you'), `bottom panel: ${panels.bottom.text}`);
  check(panels.top.text.includes(s.seats[2].name) && panels.top.text.includes('partner'), `top panel: ${panels.top.text}`);
  check(panels.right.text.includes(s.seats[1].name) && panels.right.text.includes('opponent'), `right panel: ${panels.right.text}`);
  check(panels.left.text.includes(s.seats[3].name) && panels.left.text.includes('opponent'), `left panel: ${panels.left.text}`);
  const ourTeam = await asha.page.textContent('#seat-left .name');
  check(ourTeam === `You & ${s.seats[2].name}`, `the top bar shows our team first: ${ourTeam}`);
  const ourSub = await asha.page.textContent('#seat-left .sub');
  check(ourSub.startsWith('your team'), `our team is named plainly: ${ourSub}`);
  const theirSub = await asha.page.textContent('#seat-right .sub');
  check(theirSub.startsWith('opponents'), `the opponents are named plainly: ${theirSub}`);
  check(new Set(s.seats.slice(1).map((x) => x.name)).size === 3, `three distinct bot names: ${s.seats.map((x) => x.name)}`);
  check(s.seats.slice(1).every((x) => /^Bot [A-Z][a-z]+ \(easy\)$/.test(x.name)), `bots named with their level: ${s.seats.map((x) => x.name)}`);
  for (const at of SIDES) check(!panels[at].text.includes('(bot)'), `no "(bot)" after a bot's name: ${panels[at].text}`);

  const firstTurn = s.turn;
  const order = []; // seats to play, turn by turn
  let shots = 0;
  const deadline = Date.now() + 100000;
  for (;;) {
    check(Date.now() < deadline, `12 turns did not pass in time (turn ${s.turn})`);
    s = await asha.state();
    if (s.phase === 'game_over') break;
    if (order.length === 0 || order[order.length - 1].turn !== s.turn) order.push({ turn: s.turn, seat: s.toPlay });
    const turns = s.turn - firstTurn;
    if (turns >= 12) break;
    if (s.phase !== 'aiming' || s.animating) {
      await sleep(30);
      continue;
    }
    if (s.toPlay === 0) {
      if (!s.myTurn || s.aim.phase !== 'idle') {
        await sleep(30);
        continue;
      }
      const shot = shots === 0 ? breakShot('bottom') : chooseShot(s.board, 'bottom', shots);
      await shootAndCheck(asha, shot);
      shots += 1;
      continue;
    }
    await sleep(30);
  }
  check(shots >= 1, 'the page played');
  // The turn passes anticlockwise: a seat's next turn is its own (an extra turn) or the next seat's.
  for (let i = 1; i < order.length; i += 1) {
    if (order[i].turn !== order[i - 1].turn + 1) continue; // a turn the polling did not see
    const a = order[i - 1].seat;
    const b = order[i].seat;
    check(b === a || b === (a + 1) % 4, `turn order: seat ${a} then seat ${b} (${JSON.stringify(order)})`);
  }
  // Every seat had a turn (server bots shoot within a poll or two of their turn, so whether the
  // page was caught drawing each bot's striker at its side is not asserted; web.doubles_unit
  // checks where each seat's striker is drawn).
  check(new Set(order.map((o) => o.seat)).size === 4 || s.phase === 'game_over',
    `every seat had a turn: ${JSON.stringify(order)}`);
  // The panels against the state read right after them (a bot may pocket in between: look again).
  let end = null;
  for (let look = 0; look < 5; look += 1) {
    await asha.waitFor('at rest', (st) => !st.animating, 20000);
    panels = await framePanels(asha);
    end = await asha.state();
    if (Number(panels.bottom.score) === end.seats[0].score && Number(panels.right.score) === end.seats[1].score) break;
  }
  check(panels.bottom.score === panels.top.score && panels.left.score === panels.right.score,
    `partners share a score: ${JSON.stringify(panels)}`);
  check(Number(panels.bottom.score) === end.seats[0].score && Number(panels.right.score) === end.seats[1].score,
    `the panels show the scores: ${JSON.stringify(panels)}, seats ${end.seats.map((x) => x.score)}`);
  return { shots, turns: end.turn - firstTurn, order: order.map((o) => o.seat).join('') };
}

async function fourPages(t, web, server) {
  // Not 'Asha': threeBots' page holds that name with its own player key (docs/ratings.md, "Names").
  const names = ['Anu', 'Ravi', 'Chitra', 'Dev'];
  const pages = [];
  pages.push(await Player.open(await t.browser.newContext(VIEW), names[0], pageUrl(web, server), t.errors));
  await pages[0].fillLobby({ name: names[0], ruleSet: 'icf', shotClock: 0 });
  await pages[0].page.selectOption('#seat-count', '4');
  await pages[0].press('#create');
  const created = await pages[0].waitFor('the room', (st) => st.inRoom && st.phase === 'waiting');
  const share = await pages[0].page.textContent('#waiting-share');
  check(share.includes('partner') && share.includes('opponents'), `waiting for three: ${share}`);
  check((await pages[0].page.textContent('#status-line')) === 'Waiting for 3 players', 'three seats to fill');
  for (let i = 1; i < 4; i += 1) {
    pages.push(await Player.open(await t.browser.newContext(VIEW), names[i], pageUrl(web, server), t.errors));
    await pages[i].fillLobby({ name: names[i], code: created.code });
    await pages[i].press('#join');
    await pages[i].waitFor(`seat ${i}`, (st, seat) => st.inRoom && st.you === seat, 20000, i);
  }
  for (let i = 0; i < 4; i += 1) {
    const s = await pages[i].waitFor('the game', (st) => st.phase === 'aiming' && st.seats.every((x) => x.occupied));
    check(s.turns === i, `${names[i]} (seat ${i}) sees the board turned ${s.turns} quarter turns`);
    const panels = await framePanels(pages[i]);
    check(panels.bottom.text.includes(names[i]) && panels.bottom.text.includes('you'), `${names[i]}: bottom ${panels.bottom.text}`);
    check(panels.top.text.includes(names[(i + 2) % 4]) && panels.top.text.includes('partner'), `${names[i]}: top ${panels.top.text}`);
    check(panels.right.text.includes(names[(i + 1) % 4]), `${names[i]}: right ${panels.right.text}`);
    check(panels.left.text.includes(names[(i + 3) % 4]), `${names[i]}: left ${panels.left.text}`);
  }
  // Play until both side seats shot from their turned views (and their shots arrived as aimed).
  const sideShots = { 1: 0, 3: 0 };
  let shots = 0;
  const deadline = Date.now() + 90000;
  while (sideShots[1] === 0 || sideShots[3] === 0) {
    check(Date.now() < deadline && shots < 24, `the side seats did not both shoot (${shots} shots, ${JSON.stringify(sideShots)})`);
    let mover = null;
    for (const p of pages) {
      const s = await p.state();
      check(s.phase !== 'game_over', 'the game ended before both side seats shot');
      if (s.myTurn && !s.animating && s.aim.phase === 'idle') mover = { p, s };
    }
    if (!mover) {
      await sleep(50);
      continue;
    }
    const { p, s } = mover;
    const shot = shots === 0 ? breakShot(s.aim.side) : chooseShot(s.board, s.aim.side, shots);
    await shootAndCheck(p, shot);
    shots += 1;
    if (s.you in sideShots) sideShots[s.you] += 1;
  }
  return { shots, sideShots };
}

async function quickDoubles(t, web, server) {
  const mira = await Player.open(await t.browser.newContext(VIEW), 'Mira', pageUrl(web, server), t.errors);
  await mira.fillLobby({ name: 'Mira', ruleSet: 'seed' });
  await mira.page.selectOption('#seat-count', '4');
  check((await mira.page.textContent('#quick')) === 'Quick match doubles', 'the lobby offers quick match doubles');
  await mira.press('#quick');
  const s = await mira.waitFor('seated with bots', (st) => st.inRoom && st.phase === 'aiming', 20000);
  check(s.ruleSet === 'seed' && s.seats.length === 4, `a doubles room of the rule set (${s.ruleSet}, ${s.seats.length} seats)`);
  const bots = s.seats.filter((x, i) => i !== s.you && x.bot).length;
  check(bots === 3, `three bots seated with the lone player (${bots})`);
  const panels = await framePanels(mira);
  check(panels.bottom.text.includes('Mira') && panels.top.text.includes('partner'), `Mira's panels: ${JSON.stringify(panels)}`);
}

run('web.doubles_pages', 190000, async (t) => {
  const server = await startServer(['--shot-clock', '0', '--time-scale', '8', '--bot-think-ms', '400',
    '--quick-match-bot', '1']);
  const web = await startWebServer(server);
  t.browser = await launchBrowser();
  const bots = await threeBots(t, web, server);
  console.log(`three bots: the page shot ${bots.shots} times in ${bots.turns} turns; seats to play ${bots.order}`);
  const four = await fourPages(t, web, server);
  console.log(`four pages: ${four.shots} shots, right seat ${four.sideShots[1]}, left seat ${four.sideShots[3]}`);
  await quickDoubles(t, web, server);
  console.log('quick match doubles: seated with three bots');
});
