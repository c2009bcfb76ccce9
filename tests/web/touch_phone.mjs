// A phone-sized page (390 x 844, touch, 3 device px per CSS px) plays a server bot from the
// lobby and aims only by touch. Checks: the board fills the width; every control is at least
// 44 x 44 CSS px; while a finger aims the page neither scrolls nor zooms; a second finger
// cancels a pull and nothing is shot; the shots the server plays are the ones aimed; the
// screenshot shows every piece; the game ends with its reason on screen; no console errors.

import { check, launchBrowser, pageUrl, run, sleep, startServer, startWebServer } from './lib/harness.mjs';
import { breakShot, playUntilOver } from './lib/match.mjs';
import { checkPicture } from './lib/picture.mjs';
import { Player } from './lib/player.mjs';

const PHONE = {
  viewport: { width: 390, height: 844 }, deviceScaleFactor: 3, isMobile: true, hasTouch: true,
};

// Controls narrower or lower than 44 CSS px, among the visible ones.
function smallControls(page) {
  return page.evaluate(() => [...document.querySelectorAll('button, input, select, summary')]
    .filter((e) => e.getClientRects().length > 0 && getComputedStyle(e).visibility !== 'hidden')
    .map((e) => ({ id: e.id || e.textContent.trim(), r: e.getBoundingClientRect() }))
    .filter(({ r }) => r.width < 44 || r.height < 44)
    .map(({ id, r }) => `${id} ${r.width.toFixed(0)}x${r.height.toFixed(0)}`));
}

function viewportState(page) {
  return page.evaluate(() => ({
    scrollX: window.scrollX,
    scrollY: window.scrollY,
    zoom: window.visualViewport ? window.visualViewport.scale : 1,
    scrollHeight: document.documentElement.scrollHeight,
    innerHeight: window.innerHeight,
    aiming: document.body.classList.contains('aiming'),
    cancelShown: !document.getElementById('cancel-aim').hidden,
  }));
}

run('web.touch_phone', 150000, async (t) => {
  const server = await startServer(['--shot-clock', '0', '--time-scale', '8', '--bot-think-ms', '50']);
  const web = await startWebServer(server);
  t.browser = await launchBrowser();
  const phone = await Player.open(await t.browser.newContext(PHONE), 'Phone', pageUrl(web, server), t.errors);
  await phone.useTouch();

  let small = await smallControls(phone.page);
  check(small.length === 0, `lobby controls under 44 px: ${small.join(', ')}`);
  await phone.fillLobby({ name: 'Phone', ruleSet: 'freestyle', targetPoints: 10, boards: 1, shotClock: 0, botLevel: 'random' });
  await phone.press('#play-bot');
  let s = await phone.waitFor('our turn against the bot', (st) => st.inRoom && st.myTurn && !st.animating && st.aim.phase === 'idle');
  check(s.seats[1].bot && s.seats[1].name.length > 0, 'the other seat is a bot');
  check(s.canvas.side === 390 && s.canvas.dpr === 3, `the board fills the width (${s.canvas.side} CSS px at ${s.canvas.dpr}x)`);
  small = await smallControls(phone.page);
  check(small.length === 0, `match controls under 44 px: ${small.join(', ')}`);

  // A pull cancelled by a second finger shoots nothing.
  const cdp = phone.touch;
  const striker = await phone.toClient(s.aim.x, s.aim.y);
  const below = await phone.toClient(s.aim.x, s.aim.y + 60);
  const finger = (points) => points.map((p, i) => ({ x: p.x, y: p.y, id: i + 1, radiusX: 8, radiusY: 8, force: 1 }));
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: finger([striker]) });
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: finger([below]) });
  let v = await viewportState(phone.page);
  check(v.aiming && v.cancelShown, 'a pull shows the aim and the Cancel button');
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: finger([below, { x: 40, y: 400 }]) });
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
  await sleep(200);
  s = await phone.state();
  check(s.shotSentTurn === -1 && s.aim.phase === 'idle', `a second finger cancels (sent ${s.shotSentTurn}, ${s.aim.phase})`);

  // The break by touch, with the viewport checked in the middle of the pull.
  const brk = breakShot(s.aim.y);
  await phone.drag([{ x: 113, y: s.aim.y }, { x: brk.x, y: s.aim.y }]);
  s = await phone.state();
  const from = await phone.toClient(s.aim.x, s.aim.y);
  const to = await phone.toClient(s.aim.x, s.aim.y + 160);
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: finger([from]) });
  for (const k of [0.25, 0.5, 0.75, 1]) {
    await cdp.send('Input.dispatchTouchEvent', {
      type: 'touchMove', touchPoints: finger([{ x: from.x + (to.x - from.x) * k, y: from.y + (to.y - from.y) * k }]),
    });
  }
  v = await viewportState(phone.page);
  check(v.scrollX === 0 && v.scrollY === 0 && v.zoom === 1, `no scroll or zoom while aiming (${JSON.stringify(v)})`);
  check(v.scrollHeight <= v.innerHeight, `the page does not scroll (${v.scrollHeight} > ${v.innerHeight})`);
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
  s = await phone.waitFor('the break played', (st) => st.lastShot !== null && st.lastShot.seat === st.you);
  check(Math.abs(s.lastShot.angle + Math.PI / 2) < 0.03 && s.lastShot.power === 25 && Math.abs(s.lastShot.x - 300) < 1.5,
    `the break as aimed (${JSON.stringify(s.lastShot)})`);
  await phone.waitFor('rest after the break', (st) => !st.animating && st.phase !== 'moving');
  await checkPicture(phone, { minPieces: 6 });

  const shots = await playUntilOver([phone], {
    maxShots: 40,
    timeoutMs: 100000,
    onShot: async (p, shot) => {
      const st = await p.waitFor('the shot result', (x) => x.lastShot && x.lastShot.turn === x.shotSentTurn, 30000);
      check(Math.abs(st.lastShot.angle - shot.angle) < 0.03 && Math.abs(st.lastShot.power - shot.power) < 0.4,
        `touch shot as aimed: ${JSON.stringify(st.lastShot)} vs ${JSON.stringify(shot)}`);
    },
  });
  s = await phone.waitFor('the end on screen', (st) => st.phase === 'game_over' && !st.animating && st.gameEnd !== null, 30000);
  check(await phone.page.isVisible('#game-over-result'), 'the result is shown');
  small = await smallControls(phone.page);
  check(small.length === 0, `game over controls under 44 px: ${small.join(', ')}`);
  console.log(`${shots + 1} touch shots; ${s.gameEnd.sentence}`);
});
