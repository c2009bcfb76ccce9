// The page's aim assist (web/js/aim_assist.js) on the real WebAssembly engine under node: the
// closed-form cases of tests/common/first_contact_test.cpp (head-on, cut shot, nearer of two, a
// soft shot that stops short), the standard break (carrom-engine-cases, native) naming the
// piece, contact and direction of the engine's first_contact and of the stroke's first
// collision, the cache (a repeated question runs nothing), when it is off, and its cost per run.
//
//   CARROM_ENGINE_CASES=... CARROM_ENGINE_WASM=... node tests/wasm/aim_assist_test.mjs
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { AimAssist, aimAssistAllowed } from '../../web/js/aim_assist.js';
import { AimController } from '../../web/js/aim_controller.js';
import { loadEngine } from '../../web/js/engine.js';
import { MatchModel } from '../../web/js/match_model.js';
import { PHYSICS } from '../../web/js/physics_config.js';

const KINDS = ['black', 'white', 'queen', 'striker'];
const layout = JSON.parse(execFileSync(process.env.CARROM_ENGINE_CASES, ['0']).toString()).bodies
  .map(([id, kind, x, y]) => ({ id, kind: KINDS[kind], x, y, vx: 0, vy: 0, pocketed: false }));
const engine = await loadEngine(readFileSync(process.env.CARROM_ENGINE_WASM));
const reference = await loadEngine(readFileSync(process.env.CARROM_ENGINE_WASM));
const UP = -Math.PI / 2;
const BASELINE_Y = PHYSICS.boardSize - PHYSICS.baselineOffset; // the bottom striker's centre y
const SUM_OF_RADII = PHYSICS.coinRadius + PHYSICS.strikerRadius;
const TOL_PX = 1e-9;
let passed = 0;

function test(name, body) {
  body();
  passed += 1;
  console.log(`ok ${name}`);
}

function assistant() {
  const a = new AimAssist();
  a.setEngine(engine);
  return a;
}

const coin = (id, x, y) => ({ id, kind: 'white', x, y, vx: 0, vy: 0, pocketed: false });

// The coin's speed after a head-on hit by the striker launched at v0 that travelled s px:
// damping dv/ds = -k, then the two-disc impulse (striker mass 2, coin 1).
function headOnCoinSpeed(v0, s) {
  const u = v0 - PHYSICS.dampingPerS * s;
  return ((1 + PHYSICS.discRestitution) * PHYSICS.strikerMass) / (PHYSICS.strikerMass + PHYSICS.coinMass) * u;
}

test('head-on: the coin on the line, touched at the sum of radii, sent straight on', () => {
  const g = assistant().guide([coin(1, 300, 300)], 'bottom', { x: 300, angle: UP, power: 5 });
  assert.equal(g.id, 1);
  assert.ok(Math.abs(g.striker.x - 300) < TOL_PX && Math.abs(g.striker.y - (300 + SUM_OF_RADII)) < TOL_PX,
    `striker at ${JSON.stringify(g.striker)}`);
  assert.deepEqual(g.piece, { x: 300, y: 300 });
  assert.ok(Math.abs(g.direction.x) < 1e-12 && Math.abs(g.direction.y + 1) < 1e-12, `direction ${JSON.stringify(g.direction)}`);
  const speed = headOnCoinSpeed(5 * PHYSICS.powerToSpeed, BASELINE_Y - 300 - SUM_OF_RADII);
  assert.ok(Math.abs(g.speed - speed) < 1e-3, `speed ${g.speed}, closed form ${speed}`);
  assert.ok(Math.abs(g.rollPx - speed / PHYSICS.dampingPerS) < 1e-3 && g.rollPx < 200, `roll ${g.rollPx}`);
});

test('a hard head-on hit: the roll is capped at 200 px', () => {
  const g = assistant().guide([coin(1, 300, 300)], 'bottom', { x: 300, angle: UP, power: 25 });
  assert.equal(g.id, 1);
  assert.equal(g.rollPx, 200);
});

test('a cut shot sends the piece along the line of centres (30 degrees off the path)', () => {
  const half = SUM_OF_RADII / 2;
  const g = assistant().guide([coin(1, 300 + half, 300)], 'bottom', { x: 300, angle: UP, power: 5 });
  assert.equal(g.id, 1);
  assert.ok(Math.abs(g.striker.x - 300) < TOL_PX, `striker x ${g.striker.x}`);
  assert.ok(Math.abs(g.striker.y - (300 + Math.sqrt(SUM_OF_RADII ** 2 - half ** 2))) < TOL_PX, `striker y ${g.striker.y}`);
  assert.ok(Math.abs(g.direction.x - 0.5) < 1e-9 && Math.abs(g.direction.y + Math.sqrt(3) / 2) < 1e-9,
    `direction ${JSON.stringify(g.direction)}`);
});

test('the nearer of two coins in line is touched; one beside the path is not', () => {
  const a = assistant();
  assert.equal(a.guide([coin(1, 300, 200), coin(2, 300, 300)], 'bottom', { x: 300, angle: UP, power: 5 }).id, 2);
  const beside = [coin(1, 300 + SUM_OF_RADII + 1, 300), coin(2, 300, 200)];
  assert.equal(a.guide(beside, 'bottom', { x: 300, angle: UP, power: 10 }).id, 2);
});

test('a striker that stops short or is not struck touches nothing', () => {
  const a = assistant();
  assert.equal(a.guide([coin(1, 300, 200)], 'bottom', { x: 300, angle: UP, power: 1 }), null);
  assert.equal(a.guide([coin(1, 300, 200)], 'bottom', { x: 300, angle: UP, power: 0 }), null);
});

test("the standard break: the engine's first contact and the stroke's first collision", () => {
  for (const [x, angle] of [[300, UP], [250, UP + 0.15], [360, UP - 0.1]]) {
    const shot = { x, angle, power: 25 };
    const g = assistant().guide(layout, 'bottom', shot);
    const hit = reference.firstContact(layout, 'bottom', shot);
    assert.ok(g && hit, `the break at x ${x}, angle ${angle} touches a piece`);
    assert.equal(g.id, hit.id);
    assert.equal(g.t, hit.t);
    assert.deepEqual(g.striker, hit.striker);
    assert.deepEqual(g.direction, hit.direction);
    assert.deepEqual(g.piece, (({ x: px, y: py }) => ({ x: px, y: py }))(layout.find((b) => b.id === hit.id)));
    const stroke = reference.simulate(layout, 'bottom', shot);
    const first = stroke.events.find((e) => e.kind === 'collision' && (e.a === 19 || e.b === 19));
    assert.equal(g.id, first.a === 19 ? first.b : first.a, 'the first piece the stroke touches');
    assert.ok(g.speed > 0 && g.rollPx > 0 && g.rollPx <= 200, `roll ${g.rollPx}`);
  }
  // Straight up the middle: coins 10 and 9 (mirrored about x = 300, 16.3 px off the path) are
  // struck at the same instant; the first event names 10, sent up and left along the line of
  // centres (no other piece touches it).
  const straight = assistant().guide(layout, 'bottom', { x: 300, angle: UP, power: 25 });
  const ten = layout.find((b) => b.id === 10);
  assert.equal(straight.id, 10);
  const off = ten.x - 300;
  const rise = Math.sqrt(SUM_OF_RADII ** 2 - off ** 2);
  assert.ok(Math.abs(straight.striker.x - 300) < TOL_PX && Math.abs(straight.striker.y - (ten.y + rise)) < 1e-6,
    `striker at ${JSON.stringify(straight.striker)}`);
  assert.ok(Math.abs(straight.direction.x - off / SUM_OF_RADII) < 1e-9
    && Math.abs(straight.direction.y + rise / SUM_OF_RADII) < 1e-9, `direction ${JSON.stringify(straight.direction)}`);
  assert.equal(straight.rollPx, 200, 'a full-power break sends it further than the cap');
});

test('a side seat: the same contact as the engine from the right', () => {
  const shot = { x: 300, angle: Math.PI, power: 25 };
  const g = assistant().guide(layout, 'right', shot);
  const hit = reference.firstContact(layout, 'right', shot);
  assert.equal(g.id, hit.id);
  assert.deepEqual(g.direction, hit.direction);
  assert.ok(g.direction.x < 0, 'the piece goes left, away from the right baseline');
});

test('an unchanged question runs nothing; a changed shot or board runs once', () => {
  const a = assistant();
  const shot = { x: 300, angle: UP, power: 20 };
  const first = a.guide(layout, 'bottom', shot);
  assert.equal(a.guide(layout.map((b) => ({ ...b })), 'bottom', { ...shot }), first);
  assert.equal(a.stats.runs, 1);
  assert.equal(a.stats.asked, 2);
  a.guide(layout, 'bottom', { ...shot, power: 21 });
  assert.equal(a.stats.runs, 2);
  const moved = layout.map((b) => (b.id === first.id ? { ...b, pocketed: true } : b));
  assert.notEqual(a.guide(moved, 'bottom', { ...shot, power: 21 })?.id, first.id, 'a pocketed piece is not touched');
  assert.equal(a.stats.runs, 3);
});

function roomState(aimAssist, you) {
  return {
    type: 'room_state', code: 'ABCDEF', you, rule_set: 'icf',
    options: { target_points: 25, boards: 8, shot_clock_s: 0 }, spectators: 0, board_number: 1,
    turn: 0, to_play: 0, phase: 'aiming', queen: { state: 'on_board', seat: -1 }, winner: -1,
    seats: [
      { occupied: true, name: 'Asha', connected: true, bot: false, colour: 'white', baseline: 'bottom' },
      { occupied: true, name: 'Ravi', connected: true, bot: false, colour: 'black', baseline: 'top' },
    ],
    scores: [0, 0], dues: [0, 0], bodies: layout, server_time_ms: 0,
    motion: { damping_per_s: 1.2, contact_snapshots: true },
    ...(aimAssist === undefined ? {} : { aim_assist: aimAssist }),
  };
}

// The page's question while the seat at the bottom pulls straight up at full power.
function pull(aimAssist, you = 0, withEngine = true) {
  const model = new MatchModel();
  if (withEngine) model.setEngine(engine);
  model.handle(roomState(aimAssist, you), 0);
  const aim = new AimController();
  aim.beginTurn('bottom', 300);
  const a = new AimAssist();
  if (withEngine) a.setEngine(engine);
  return { guide: a.forPull(model, aim, { x: 300, angle: UP, power: 25 }), runs: a.stats.runs };
}

test('on in a room with aim_assist true or absent; off when false, for a spectator, without engine', () => {
  assert.equal(pull(true).guide.id, assistant().guide(layout, 'bottom', { x: 300, angle: UP, power: 25 }).id);
  assert.ok(pull(undefined).guide, 'absent reads as on');
  assert.deepEqual(pull(false), { guide: null, runs: 0 });
  assert.deepEqual(pull(true, -1), { guide: null, runs: 0 });
  assert.deepEqual(pull(true, 0, false), { guide: null, runs: 0 });
  assert.equal(aimAssistAllowed({ aimAssist: true, you: 0, engineLoaded: true, predicting: true }), false,
    'not while the own stroke is predicted on the same engine');
  assert.equal(aimAssistAllowed({ aimAssist: undefined, you: 1, engineLoaded: true, predicting: false }), true);
});

test('an illegal placement (the striker over a piece) shows nothing', () => {
  const model = new MatchModel();
  model.setEngine(engine);
  const onBaseline = layout.concat([coin(30, 300, BASELINE_Y)]);
  model.handle({ ...roomState(true, 0), bodies: onBaseline }, 0);
  const aim = new AimController();
  aim.beginTurn('bottom', 300);
  aim.setX(300, model.boardNow());
  assert.equal(aim.placement.legal, false);
  const a = new AimAssist();
  a.setEngine(engine);
  assert.equal(a.forPull(model, aim, { x: 300, angle: UP, power: 25 }), null);
  assert.equal(a.stats.runs, 0);
});

// The cost of a run (a new question each time: every frame of a pull that moves): 200 shots
// across the break.
const timed = assistant();
const costs = [];
for (let i = 0; i < 200; i += 1) {
  timed.guide(layout, 'bottom', { x: 200 + i / 2, angle: UP + (i % 20) * 0.02 - 0.2, power: 5 + (i % 21) });
  costs.push(timed.stats.lastMs);
}
assert.equal(timed.stats.runs, 200);
costs.sort((a, b) => a - b);
const at = (q) => costs[Math.min(costs.length - 1, Math.floor(q * costs.length))].toFixed(2);
console.log(`aim assist: ${passed} passed; the break, 200 runs (powers 5-25): p50 ${at(0.5)} ms, p99 ${at(0.99)} ms, max ${at(1)} ms (the first run compiles)`);
