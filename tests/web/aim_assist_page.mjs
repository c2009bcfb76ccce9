// The aim assist on the page (web/js/aim_assist.js) in a game against a server bot: while the
// player pulls, the page shows the first-contact guide computed by its engine: the same piece,
// contact and direction as the engine the server serves (js/carrom_engine.wasm, loaded here under
// node) gives for the page's board and pending shot, and the gold line is on the canvas; holding
// still runs no new simulation; a pull that moves runs one per new shot, whose cost the page
// measures; a cancel hides it. Needs the page's engine (registered when it is built).

import { AimAssist } from '../../web/js/aim_assist.js';
import { loadEngine } from '../../web/js/engine.js';
import { check, launchBrowser, pageUrl, run, sleep, startServer, startWebServer } from './lib/harness.mjs';
import { Player } from './lib/player.mjs';

const VIEW = { viewport: { width: 900, height: 900 } };
const PULL_PX = 90; // board px behind the striker: a strong shot towards the centre

// The canvas pixel (RGBA) under board point p, as the page maps it.
function pixelAt(player, p) {
  return player.page.evaluate(([x, y]) => {
    const c = document.getElementById('board');
    const at = window.carrom.toClient(x, y);
    const r = c.getBoundingClientRect();
    const k = c.width / r.width;
    return Array.from(c.getContext('2d').getImageData(Math.round((at.x - r.left) * k), Math.round((at.y - r.top) * k), 1, 1).data);
  }, [p.x, p.y]);
}

const frames = (player, n) => player.page.evaluate((count) => new Promise((resolve) => {
  let left = count;
  const step = () => { left -= 1; if (left <= 0) resolve(); else requestAnimationFrame(step); };
  requestAnimationFrame(step);
}), n);

run('web.aim_assist_page', 120000, async (t) => {
  const server = await startServer(['--shot-clock', '0', '--time-scale', '8', '--bot-think-ms', '50']);
  const web = await startWebServer(server);
  const wasm = await fetch(`http://127.0.0.1:${web.port}/js/carrom_engine.wasm`);
  check(wasm.ok, `GET /js/carrom_engine.wasm: ${wasm.status}`);
  const reference = new AimAssist();
  reference.setEngine(await loadEngine(new Uint8Array(await wasm.arrayBuffer())));
  t.browser = await launchBrowser();

  const asha = await Player.open(await t.browser.newContext(VIEW), 'Asha', pageUrl(web, server), t.errors);
  await asha.fillLobby({ name: 'Asha', ruleSet: 'freestyle', targetPoints: 10, boards: 1, shotClock: 0 });
  await asha.press('#play-bot');
  let s = await asha.waitFor('our turn against the bot, the engine loaded',
    (st) => st.inRoom && st.myTurn && !st.animating && st.aim.phase === 'idle' && st.engine.loaded, 40000);
  check(s.aimAssist !== false, 'a game against a bot allows the aim assist');
  check(!s.assist.shown && s.assist.stats.runs === 0, 'nothing is computed before a pull');

  // Grab the striker and pull away from the centre; hold the button.
  const from = s.aim.striker;
  const away = { x: from.x - 300, y: from.y - 300 };
  const len = Math.hypot(away.x, away.y);
  const pullAt = (d) => ({ x: from.x + (away.x / len) * d, y: from.y + (away.y / len) * d });
  const mouse = asha.page.mouse;
  const grab = await asha.toClient(from.x, from.y);
  await mouse.move(grab.x, grab.y);
  await mouse.down();
  for (const d of [20, 45, 70, PULL_PX]) {
    const c = await asha.toClient(pullAt(d).x, pullAt(d).y);
    await mouse.move(c.x, c.y, { steps: 4 });
  }
  s = await asha.waitFor('the guide', (st) => st.aim.phase === 'pulling' && st.assist.shown);
  const g = s.assist.guide;
  check(g.side === s.aim.side && g.shot.x === s.aim.x && g.shot.power > 0, `the guide's shot ${JSON.stringify(g.shot)}`);
  const expected = reference.guide(s.board, g.side, g.shot);
  check(expected, 'the served engine finds a contact for the page\'s shot');
  check(g.id === expected.id, `the page names piece ${g.id}, the engine ${expected.id}`);
  check(Math.abs(g.direction.x - expected.direction.x) < 1e-9 && Math.abs(g.direction.y - expected.direction.y) < 1e-9,
    `direction: page ${JSON.stringify(g.direction)}, engine ${JSON.stringify(expected.direction)}`);
  check(Math.abs(g.striker.x - expected.striker.x) < 1e-6 && Math.abs(g.striker.y - expected.striker.y) < 1e-6,
    'the contact point');
  check(g.rollPx > 0 && g.rollPx <= 200, `roll ${g.rollPx} px`);

  // The gold line is on the canvas, three quarters of the way along it.
  const along = Math.min(g.rollPx, 120) * 0.75;
  const [r, gr, b] = await pixelAt(asha, { x: g.piece.x + g.direction.x * along, y: g.piece.y + g.direction.y * along });
  check(r > 200 && gr > 150 && b < 140, `gold under the piece's line: rgb(${r},${gr},${b})`);

  // Holding still: asked every frame, no new simulation.
  const held = (await asha.state()).assist.stats;
  await frames(asha, 20);
  const still = (await asha.state()).assist.stats;
  check(still.runs === held.runs && still.asked > held.asked, `holding still ran ${still.runs - held.runs} simulations in ${still.asked - held.asked} frames`);

  // A pull that moves: one run per new shot; the page's cost per run and its work per frame.
  await asha.page.evaluate(() => window.carrom.clearFrameTimes());
  for (let i = 0; i < 30; i += 1) {
    const p = pullAt(PULL_PX - i);
    const side = { x: p.x + (away.y / len) * i * 0.5, y: p.y - (away.x / len) * i * 0.5 };
    const c = await asha.toClient(side.x, side.y);
    await mouse.move(c.x, c.y);
    await frames(asha, 1);
  }
  const moving = (await asha.state()).assist.stats;
  const work = (await asha.page.evaluate(() => window.carrom.frameTimes())).map((f) => f.work).sort((x, y) => x - y);
  const workP99 = work[Math.min(work.length - 1, Math.floor(0.99 * work.length))];
  check(moving.runs > still.runs + 10, `a moving pull ran ${moving.runs - still.runs} simulations`);
  check(moving.maxMs < 50, `the slowest run ${moving.maxMs.toFixed(2)} ms`);

  // A cancel (Escape) hides it; nothing was sent.
  await asha.page.keyboard.press('Escape');
  await mouse.up();
  s = await asha.waitFor('the guide hidden', (st) => st.aim.phase === 'idle' && !st.assist.shown);
  check(s.shotSentTurn !== s.turn, 'a cancelled pull shoots nothing');
  await sleep(50);
  console.log(`aim assist on the page: piece ${g.id}, roll ${g.rollPx.toFixed(1)} px; ${moving.runs} runs, mean ${(moving.totalMs / moving.runs).toFixed(3)} ms, max ${moving.maxMs.toFixed(3)} ms; the page's work per frame while pulling p99 ${workP99.toFixed(2)} ms over ${work.length} frames`);
});
