// The page's shot prediction (web/js/prediction.js through match_model.js) on the real
// WebAssembly engine under node, fed the server's messages as the page decodes them: the stroke
// is drawn from the frame after the shot, an exact server is followed without corrections and
// its sounds are not played twice, a server 5 px off is reached within the blend and counted
// once, a refused shot returns to the board at rest; the aim assist's first contact. The board
// is the standard break's (carrom-engine-cases, native).
//
//   CARROM_ENGINE_CASES=... CARROM_ENGINE_WASM=... node tests/wasm/prediction_test.mjs
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { loadEngine } from '../../web/js/engine.js';
import { MatchModel } from '../../web/js/match_model.js';

const KINDS = ['black', 'white', 'queen', 'striker'];
const layout = JSON.parse(execFileSync(process.env.CARROM_ENGINE_CASES, ['0']).toString()).bodies
  .map(([id, kind, x, y]) => ({ id, kind: KINDS[kind], x, y, vx: 0, vy: 0, pocketed: false }));
const engine = await loadEngine(readFileSync(process.env.CARROM_ENGINE_WASM));
// The server's engine: a second instance, so the page's keeps its own stroke.
const server = await loadEngine(readFileSync(process.env.CARROM_ENGINE_WASM));
const SHOT = { turn: 3, x: 300, angle: -Math.PI / 2, power: 25 };
let passed = 0;

function roomState(turn) {
  return {
    type: 'room_state', code: 'ABCDEF', you: 0, rule_set: 'icf',
    options: { target_points: 25, boards: 8, shot_clock_s: 0 }, spectators: 0, board_number: 1,
    turn, to_play: 0, phase: 'aiming', queen: { state: 'on_board', seat: -1 }, winner: -1,
    seats: [
      { occupied: true, name: 'Asha', connected: true, bot: false, colour: 'white', baseline: 'bottom' },
      { occupied: true, name: 'Ravi', connected: true, bot: false, colour: 'black', baseline: 'top' },
    ],
    scores: [0, 0], dues: [0, 0], bodies: layout, server_time_ms: 0,
    motion: { damping_per_s: 1.2, contact_snapshots: true },
  };
}

function model() {
  const m = new MatchModel();
  m.setEngine(engine);
  m.handle(roomState(SHOT.turn), 0);
  return m;
}

// The server's delta at shot time t: every body on the board, the pocketed ids.
let seq = 100;
function snapshot(t, shiftPx = 0, keyframe = false) {
  const bodies = server.stateAt(t);
  return {
    type: 'snapshot', seq: seq++, turn: SHOT.turn, t, keyframe,
    bodies: bodies.filter((b) => !b.pocketed).map((b) => [b.id, b.x + (b.id === 1 ? shiftPx : 0), b.y, 0, 0]),
    pocketed: bodies.filter((b) => b.pocketed).map((b) => b.id),
  };
}

function test(name, body) {
  body();
  passed += 1;
  console.log(`ok ${name}`);
}

const stroke = server.simulate(layout, 'bottom', SHOT);
assert.equal(stroke.error, null);

test('the stroke is drawn from the next frame', () => {
  const m = model();
  const at = 1.0;
  assert.equal(m.predict(SHOT, at), true);
  assert.equal(m.view.phase, 'moving');
  const start = m.prediction.offset;
  const striker = (bodies) => bodies.find((b) => b.id === 19);
  const next = striker(m.render(at + 1 / 60));
  assert.ok(next, 'the striker is drawn');
  const expected = server.stateAt(m.lastRender - start).find((b) => b.id === 19);
  assert.ok(Math.abs(next.y - expected.y) < 1e-9, `striker y ${next.y}, engine ${expected.y}`);
  assert.ok(next.y < server.stateAt(0).find((b) => b.id === 19).y, 'the striker moved up');
  assert.equal(m.predict(SHOT, at), false, 'one prediction at a time');
});

test('an exact server: no correction, the sounds once', () => {
  const m = model();
  m.predict(SHOT, 1.0);
  let local = 1.0;
  let played = 0;
  const heard = [];
  for (let t = 0; t <= stroke.endTime + 0.2; t += 0.05) {
    local += 0.05;
    m.handle(snapshot(Math.min(t, stroke.endTime)), local);
    m.render(local);
    played += m.takeSounds().length;
  }
  for (const e of stroke.events.filter((x) => x.kind === 'collision')) {
    m.handle({ type: 'event', kind: 'collision', turn: SHOT.turn, t: e.t, impulse: e.impulse }, local);
    heard.push(e);
  }
  // The server's cues of predicted events are claimed: none is queued to play again.
  assert.equal(m.cues.cues.length, 0, 'no server cue of a predicted event waits');
  m.handle(snapshot(stroke.endTime, 0, true), local);
  for (let i = 0; i < 40; i += 1) {
    local += 0.05;
    m.render(local);
    assert.equal(m.takeSounds().length, 0, 'no sound after the stroke');
  }
  assert.ok(played > 0, 'the predicted sounds played');
  assert.equal(m.prediction.stats.corrections, 0);
  assert.equal(m.prediction.active, false, 'the prediction ended on the last keyframe');
  assert.ok(heard.length > 0);
});

test('a server 5 px off is reached within the blend and counted once', () => {
  const m = model();
  m.predict(SHOT, 1.0);
  const t = 0.05;
  m.handle(snapshot(t, 5), 1.2);
  m.handle(snapshot(t + 0.01, 5), 1.21);
  assert.equal(m.prediction.stats.corrections, 1);
  const drawn = (local, shot) => m.prediction.draw(m.prediction.offset + shot, local, null).find((b) => b.id === 1);
  const exact = server.stateAt(t + 0.01).find((b) => b.id === 1);
  const early = drawn(1.2, t + 0.01);
  const late = drawn(1.2 + 0.1, t + 0.01);
  assert.ok(Math.abs(early.x - exact.x) < 0.01, `at the first difference the prediction is drawn (${early.x - exact.x})`);
  assert.ok(Math.abs(late.x - (exact.x + 5)) < 1e-9, `after 100 ms the server's (${late.x - exact.x})`);
});

test('a refused shot returns to the board at rest', () => {
  const m = model();
  m.predict(SHOT, 1.0);
  m.render(1.1);
  m.handle({ type: 'error', code: 'stale_turn', message: 'That turn is over.' }, 1.15);
  assert.equal(m.prediction.active, false);
  assert.equal(m.view.phase, 'aiming');
  assert.equal(m.turnOffsets.has(SHOT.turn), false, 'the turn waits for its own start');
  const drawn = m.render(1.2);
  for (const b of layout) {
    const d = drawn.find((x) => x.id === b.id);
    assert.ok(d && d.x === b.x && d.y === b.y, `piece ${b.id} at rest where it was`);
  }
  assert.equal(m.predictedCues.length, 0, 'no predicted sound plays');
});

test('no engine: nothing is predicted', () => {
  const m = new MatchModel();
  m.handle(roomState(SHOT.turn), 0);
  assert.equal(m.predict(SHOT, 1.0), false);
});
test("the aim assist's first contact", () => {
  const hit = server.firstContact(layout, 'bottom', SHOT);
  assert.ok(hit, 'the break touches a piece');
  const first = stroke.events.find((e) => e.kind === 'collision' && (e.a === 19 || e.b === 19));
  assert.equal(hit.id, first.a === 19 ? first.b : first.a, 'the first piece the stroke touches');
  assert.equal(hit.t, first.t);
  assert.ok(Math.abs(Math.hypot(hit.direction.x, hit.direction.y) - 1) < 1e-12, 'a unit direction');
  assert.ok(hit.direction.y < 0, 'the piece moves up the board');
  assert.ok(Math.abs(hit.striker.x - 300) < 1e-9 && hit.striker.y < 600, 'the striker where it touches');
  assert.equal(server.firstContact(layout, 'bottom', { x: 300, angle: Math.PI / 2, power: 1 }), null,
    'a soft shot at the own cushion touches nothing');
});
console.log(`prediction: ${passed} passed`);
