// What a first game shows around the board (issue 39's layout points), on a 390 x 844 phone and
// a 1000 x 800 desktop page against a real server and its bot: the lobby's room code placeholder
// fits and "Match options" carries a disclosure marker; How to play opens from the lobby and the
// match at the rule set in use; the settings survive a reload; in a match the message log sits
// under the board (phone) or beside it (desktop), never over it, without a line twice, and on
// the phone it fills the room under the board; Cancel shot covers no pocket; the first-game tips
// show and can be skipped; Leave asks first and Stay keeps the match; the reconnecting card dims
// the board, says how long the seat is held and leaves the bottom bar whole.

import { check, launchBrowser, pageUrl, run, sleep, startServer, startWebServer } from './lib/harness.mjs';
import { Player } from './lib/player.mjs';
import { relay } from './lib/relay.mjs';

const PHONE = { viewport: { width: 390, height: 844 }, deviceScaleFactor: 3, isMobile: true, hasTouch: true };
const DESK = { viewport: { width: 1000, height: 800 } };

// Rects (client px) of what the layout checks look at.
function layoutRects(page) {
  return page.evaluate(() => {
    const r = (el) => { const b = el.getBoundingClientRect(); return { l: b.left, t: b.top, r: b.right, b: b.bottom, w: b.width, h: b.height }; };
    const $ = (id) => document.getElementById(id);
    const shown = (el) => !el.hidden && el.getClientRects().length > 0;
    return {
      board: r($('board')), side: r($('side')), bottom: r($('bottom-bar')), cancel: shown($('cancel-aim')) ? r($('cancel-aim')) : null,
      messages: [...document.querySelectorAll('#messages .message')].map((m) => ({ text: m.textContent, ...r(m) })),
      coach: shown($('coach')) ? $('coach-text').textContent : null,
    };
  });
}

// Two frames: what the page's loop writes (tips, panels) shows by then.
const frames = (page) => page.evaluate(() => new Promise((r) => { requestAnimationFrame(() => requestAnimationFrame(r)); }));

const overlaps = (a, b) => a.l < b.r - 0.5 && b.l < a.r - 0.5 && a.t < b.b - 0.5 && b.t < a.b - 0.5;

function checkMessages(rects, where) {
  for (const m of rects.messages) check(!overlaps(m, rects.board), `${where}: "${m.text}" lies over the board`);
  const texts = rects.messages.map((m) => m.text);
  check(new Set(texts).size === texts.length, `${where}: a line shown twice: ${texts.join(' | ')}`);
}

// The pockets' squares on the screen (client px), from the page's own mapping.
async function pocketRects(player) {
  const rects = [];
  for (const [x, y] of [[0, 0], [600, 0], [0, 600], [600, 600]]) {
    const c = await player.toClient(Math.min(Math.max(x, 40), 560), Math.min(Math.max(y, 40), 560));
    rects.push({ l: c.x - 25, r: c.x + 25, t: c.y - 25, b: c.y + 25 });
  }
  return rects;
}

run('web.first_game_ui', 150000, async (t) => {
  const server = await startServer(['--shot-clock', '0', '--bot-think-ms', '3000']);
  const web = await startWebServer(server);
  t.browser = await launchBrowser();

  // ---- the phone ----
  const phone = await Player.open(await t.browser.newContext(PHONE), 'Phone', pageUrl(web, server), t.errors);
  const p = phone.page;
  const placeholder = await p.evaluate(() => {
    const input = document.getElementById('room-code');
    const style = getComputedStyle(input, '::placeholder');
    const probe = document.createElement('span');
    probe.textContent = input.placeholder;
    probe.style.cssText = `font: ${style.font}; letter-spacing: ${style.letterSpacing}; position: absolute; white-space: pre`;
    document.body.append(probe);
    const need = probe.getBoundingClientRect().width;
    probe.remove();
    const cs = getComputedStyle(input);
    return { need, room: input.clientWidth - parseFloat(cs.paddingLeft) - parseFloat(cs.paddingRight) };
  });
  check(placeholder.need <= placeholder.room, `"ROOM CODE" needs ${placeholder.need.toFixed(0)} px, the field has ${placeholder.room.toFixed(0)}`);
  const marker = () => p.evaluate(() => getComputedStyle(document.querySelector('#lobby summary'), '::before').content);
  check((await marker()) === '"\u25B8"', `Match options shows a closed marker (${await marker()})`);
  await p.click('#lobby summary');
  check((await marker()) === '"\u25BE"', `an open marker once opened (${await marker()})`);

  // How to play from the lobby, at the rule set chosen there.
  await phone.fillLobby({ name: 'Phone', ruleSet: 'freestyle' });
  await phone.press('#lobby-help');
  check(await p.isVisible('#rules'), 'How to play opens from the lobby');
  check((await p.inputValue('#rules-set')) === 'freestyle', 'at the lobby\'s rule set');
  const rules = await p.$$eval('#rules-text li', (li) => li.map((x) => x.textContent));
  check(rules[0] === 'Anyone may pocket any coin: white scores 20, black 10.', `the freestyle rules: ${rules[0]}`);
  await p.selectOption('#rules-set', 'icf');
  const icf = await p.$$eval('#rules-text li', (li) => li.map((x) => x.textContent));
  check(icf.length === 7 && icf[0].startsWith('Pocket your own colour'), `the ICF rules: ${icf[0]}`);
  await phone.press('#rules-close');
  check(!(await p.isVisible('#rules')), 'Close closes it');

  // Settings: changed, then still there after a reload.
  await phone.press('#lobby-settings');
  await p.fill('#volume', '40');
  await p.check('#reduced-motion');
  await p.check('#left-handed');
  await phone.press('#settings-close');
  await p.reload();
  await p.waitForFunction(() => window.carrom !== undefined);
  let s = await phone.state();
  check(s.settings.volume === 40 && s.settings.reducedMotion && s.settings.leftHanded && !s.settings.muted,
    `settings after a reload: ${JSON.stringify(s.settings)}`);
  check(await p.evaluate(() => document.body.classList.contains('left-handed')), 'left-handed applies at once');

  await phone.useTouch();
  await phone.fillLobby({ name: 'Phone', ruleSet: 'freestyle', botLevel: 'random' });
  await phone.press('#play-bot');
  s = await phone.waitFor('our turn against the bot', (st) => st.inRoom && st.myTurn && !st.animating && st.aim.phase === 'idle');
  check(s.logPlace === 'under', `the log is under the board on a phone (${s.logPlace})`);
  let rects = await layoutRects(p);
  check(rects.side.t >= rects.board.b - 0.5, 'the side area starts under the board');
  check(rects.bottom.t - rects.side.b <= 12, `no empty room under the board (${(rects.bottom.t - rects.side.b).toFixed(0)} px left)`);
  check(rects.board.w === 390, `the board keeps the full width (${rects.board.w})`);
  check(rects.coach?.startsWith('1/4 Place:'), `the first tip shows: ${rects.coach}`);
  checkMessages(rects, 'phone');

  // A pull shows Cancel shot under the board, on no pocket.
  const cdp = phone.touch;
  const finger = (pt) => [{ x: pt.x, y: pt.y, id: 1, radiusX: 8, radiusY: 8, force: 1 }];
  const from = await phone.toClient(s.aim.x, s.aim.y);
  const to = await phone.toClient(s.aim.x, s.aim.y + 60);
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: finger(from) });
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: finger(to) });
  rects = await layoutRects(p);
  check(rects.cancel !== null, 'a pull shows Cancel shot');
  for (const pocket of await pocketRects(phone)) check(!overlaps(rects.cancel, pocket), 'Cancel shot covers a pocket');
  check(!overlaps(rects.cancel, rects.board), 'Cancel shot is off the board');
  check(rects.cancel.l < 195, 'left-handed: Cancel shot on the left');
  await phone.press('#cancel-aim');
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
  s = await phone.state();
  check(s.shotSentTurn === -1, 'nothing was shot');

  // The tips: Next, then Skip for good.
  await phone.press('#coach-next');
  await frames(p);
  check((await layoutRects(p)).coach.startsWith('2/4 Aim:'), 'Next shows the aim tip');
  await phone.press('#coach-skip');
  await frames(p);
  check((await layoutRects(p)).coach === null, 'Skip hides the tips');

  // How to play from the match, at the room's rule set.
  await phone.press('#help');
  check(await p.isVisible('#rules') && (await p.inputValue('#rules-set')) === 'freestyle', 'the rules of the room');
  await phone.press('#rules-close');

  // Leave asks; Stay keeps the match.
  await phone.press('#leave');
  check(await p.isVisible('#leave-ask'), 'Leave asks first');
  const ask = await p.textContent('#leave-ask');
  check(ask.includes('Leave and forfeit?') && ask.includes('wins it by forfeit'), `the question and its cost: ${ask}`);
  await phone.press('#leave-stay');
  await sleep(300);
  s = await phone.state();
  check(s.inRoom && s.phase !== 'game_over' && !(await p.isVisible('#leave-ask')), 'Stay keeps the match');
  checkMessages(await layoutRects(p), 'phone, later');
  await phone.press('#leave');
  await phone.press('#leave-yes');
  s = await phone.waitFor('the lobby', (st) => !st.inRoom);
  await frames(p);
  check((await p.evaluate(() => localStorage.getItem('carrom.coached'))) === '1', 'skipped tips stay skipped');

  // ---- a desktop page at 1000 x 800, through a relay the test cuts ----
  const cut = await relay(server.port);
  const desk = await Player.open(await t.browser.newContext(DESK), 'Desk', pageUrl(web, cut), t.errors);
  const d = desk.page;
  await desk.fillLobby({ name: 'Desk', ruleSet: 'icf', botLevel: 'random' });
  await desk.press('#play-bot');
  s = await desk.waitFor('our turn against the bot', (st) => st.inRoom && st.myTurn && !st.animating);
  check(s.logPlace === 'beside', `the log is beside the board on a desktop page (${s.logPlace})`);
  rects = await layoutRects(d);
  check(rects.side.l >= rects.board.r - 0.5, 'the side area is right of the board');
  check(rects.board.w >= 600, `the board stays large (${rects.board.w})`);
  checkMessages(rects, 'desktop');

  cut.refuse(true);
  cut.cut();
  await desk.waitFor('reconnecting', (st) => st.session.phase !== 'in_room', 15000);
  await d.waitForFunction(() => !document.getElementById('notice').hidden, null, { timeout: 15000 });
  const card = await d.evaluate(() => {
    const bar = document.getElementById('bottom-bar');
    const cut = [...bar.children].filter((el) => el.getClientRects().length > 0 && el.scrollWidth > el.clientWidth + 1).map((el) => el.id);
    return {
      text: document.getElementById('notice-text').textContent,
      dimmed: getComputedStyle(document.getElementById('board')).filter,
      barH: bar.getBoundingClientRect().height,
      cut,
    };
  });
  check(/Your seat is held; giving up in \d+ s\./.test(card.text), `the card says how long the seat is held: ${card.text}`);
  check(card.dimmed.startsWith('brightness'), `the board is dimmed (${card.dimmed})`);
  check(card.cut.length === 0, `bottom bar items cut: ${card.cut.join(', ')}`);
  check(card.barH < 60, `the bottom bar keeps one line (${card.barH} px)`);
  cut.refuse(false);
  await desk.waitFor('back in the room', (st) => st.session.phase === 'in_room', 20000);
  check(!(await d.isVisible('#notice')), 'the card goes once the seat is back');
  cut.close();
  // The cut link's failed tries are the test's doing.
  t.errors = t.errors.filter((e) => !/WebSocket connection to .* failed/.test(e));
});
