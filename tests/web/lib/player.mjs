// A page playing as one player, through what a person would use: the lobby's controls, the
// mouse or a finger (Chrome DevTools touch events) on the canvas. Board positions are mapped to
// page coordinates by the page's own mapping (window.carrom.toClient), so a turned view is
// handled as the player sees it.

import { check } from './harness.mjs';

const FULL_POWER_DRAG = 160;
const DEAD_ZONE = 12;
const MAX_POWER = 25;

export class Player {
  constructor(page, label, errors) {
    this.page = page;
    this.label = label;
    page.on('console', (m) => {
      if (m.type() === 'error') errors.push(`${label}: ${m.text()}`);
    });
    page.on('pageerror', (e) => errors.push(`${label}: ${e.message}`));
    page.on('requestfailed', (r) => errors.push(`${label}: request failed ${r.url()} ${r.failure()?.errorText}`));
    this.touch = null;
  }

  static async open(context, label, url, errors) {
    const page = await context.newPage();
    const player = new Player(page, label, errors);
    await page.goto(url);
    await page.waitForFunction(() => window.carrom !== undefined, null, { timeout: 10000 });
    return player;
  }

  state() {
    return this.page.evaluate(() => window.carrom.state());
  }

  // Waits until fn(state, arg) is true of the page's state, polled every 50 ms; returns the
  // state. fn runs here on a copy of that state (it sees only its arguments): the page's
  // Content-Security-Policy forbids evaluating a function's source in the page.
  async waitFor(what, fn, timeoutMs = 20000, arg = null) {
    const deadline = Date.now() + timeoutMs;
    for (;;) {
      const s = await this.state().catch(() => null); // null while the page (re)loads
      if (s && fn(s, arg)) break;
      if (Date.now() >= deadline) {
        throw new Error(`${this.label}: ${what} did not happen within ${timeoutMs} ms (phase ${s?.phase}, session ${s?.session.phase}: ${s?.session.status})`);
      }
      await new Promise((r) => { setTimeout(r, 50); });
    }
    // Two more frames, so that what the page draws and writes (canvas, HUD) shows it too.
    await this.page.evaluate(() => new Promise((r) => { requestAnimationFrame(() => requestAnimationFrame(r)); }));
    return this.state();
  }

  async fillLobby({ name, ruleSet, targetPoints, boards, shotClock, botLevel, code }) {
    const p = this.page;
    if (name !== undefined) await p.fill('#name', name);
    if (ruleSet) await p.selectOption('#rule-set', ruleSet);
    if (targetPoints !== undefined || boards !== undefined || shotClock !== undefined) {
      await p.click('#lobby details summary');
      if (targetPoints !== undefined) await p.fill('#target-points', String(targetPoints));
      if (boards !== undefined) await p.fill('#boards', String(boards));
      if (shotClock !== undefined) await p.fill('#shot-clock', String(shotClock));
    }
    if (botLevel) await p.selectOption('#bot-level', botLevel);
    if (code) await p.fill('#room-code', code);
  }

  async press(selector) {
    if (this.touch) await this.page.tap(selector);
    else await this.page.click(selector);
  }

  // Leave a running game: Leave, then the question's Leave ("Leave and forfeit?").
  async leaveAndForfeit() {
    await this.press('#leave');
    await this.page.waitForSelector('#leave-ask', { state: 'visible', timeout: 5000 });
    await this.press('#leave-yes');
  }

  async toClient(x, y) {
    return this.page.evaluate(([bx, by]) => window.carrom.toClient(bx, by), [x, y]);
  }

  // A drag along board points, by mouse or by one finger.
  async drag(points) {
    const client = [];
    for (const p of points) client.push(await this.toClient(p.x, p.y));
    if (this.touch) {
      const cdp = this.touch;
      const at = (c) => [{ x: c.x, y: c.y, id: 1, radiusX: 8, radiusY: 8, force: 1 }];
      await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: at(client[0]) });
      for (const c of client.slice(1)) {
        await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: at(c) });
      }
      await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
      return;
    }
    const m = this.page.mouse;
    await m.move(client[0].x, client[0].y);
    await m.down();
    for (const c of client.slice(1)) await m.move(c.x, c.y, { steps: 3 });
    await m.up();
  }

  async useTouch() {
    this.touch = await this.page.context().newCDPSession(this.page);
  }

  // Waits for our turn (or the end of the game); returns the state.
  waitTurnOrEnd(timeoutMs = 30000) {
    return this.waitFor('our turn or the end',
      (s) => s.phase === 'game_over' || (s.myTurn && !s.animating && s.aim.phase === 'idle'), timeoutMs);
  }

  // Places the striker at x (a slide along the baseline, any side) and shoots at `angle` (the
  // board's absolute angle) with `power` (a pull back from the striker). Checks that the page
  // sent it.
  async shoot({ x, angle, power }) {
    let s = await this.state();
    check(s.aim.phase === 'idle', `${this.label}: not ready to aim (${s.aim.phase})`);
    const turn = s.turn;
    // Board points on our baseline (x along it: board x, or board y for a side seat).
    const sideways = s.aim.side === 'left' || s.aim.side === 'right';
    const on = (along) => (sideways ? { x: s.aim.striker.x, y: along } : { x: along, y: s.aim.striker.y });
    const far = s.aim.x > 300 ? 113 : 487; // away from the striker: a press there slides
    await this.drag([on(far), on((far + x) / 2), on(x)]);
    s = await this.state();
    check(Math.abs(s.aim.x - x) < 1.5, `${this.label}: striker at ${s.aim.x}, wanted ${x}`);
    const drag = DEAD_ZONE + (power / MAX_POWER) * (FULL_POWER_DRAG - DEAD_ZONE);
    const from = s.aim.striker;
    const path = [0, 0.25, 0.5, 0.75, 1].map((k) => ({
      x: from.x - Math.cos(angle) * drag * k,
      y: from.y - Math.sin(angle) * drag * k,
    }));
    await this.drag(path);
    s = await this.state();
    check(s.shotSentTurn === turn, `${this.label}: the shot was not sent (aim ${s.aim.phase}, legal ${s.aim.legal})`);
    return s;
  }
}
