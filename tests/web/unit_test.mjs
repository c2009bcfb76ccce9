// The web client's pure modules under node (no browser): the same cases as the desktop client's
// unit tests where the logic is shared (tests/client/playout_clock_test.cpp,
// interpolation_buffer_test.cpp, aim_controller_test.cpp), plus the decoder and the room links.
import assert from 'node:assert/strict';
import fs from 'node:fs';
import test from 'node:test';

import { AimController, checkPlacement, clampBaselineX, powerFromDrag } from '../../web/js/aim_controller.js';
import { makeBoardGeometry, nearestPocket, PHYSICS } from '../../web/js/board_geometry.js';
import { hermite } from '../../web/js/hermite.js';
import { HudLog } from '../../web/js/hud_log.js';
import { InterpolationBuffer, INTERPOLATION_DEFAULTS, travelFactor } from '../../web/js/interpolation_buffer.js';
import { applyLimits, OPTION_RANGES } from '../../web/js/lobby.js';
import { MatchModel } from '../../web/js/match_model.js';
import { gameEndSentence, pocketList } from '../../web/js/plain_words.js';
import { PlayoutClock, PLAYOUT_DEFAULTS } from '../../web/js/playout_clock.js';
import * as proto from '../../web/js/protocol.js';
import { parseRoomHash, roomHash } from '../../web/js/room_link.js';
import { PROTOCOL } from '../../web/js/physics_config.js';
import { OVERLAP_ALPHA, Renderer } from '../../web/js/renderer.js';
import { ScreenMapping } from '../../web/js/screen_mapping.js';
import { ServerClock } from '../../web/js/server_clock.js';
import { Session, SESSION_DEFAULTS } from '../../web/js/session.js';
import { synthSound } from '../../web/js/sound.js';
import { loudnessFromImpulse, SoundCueQueue } from '../../web/js/sound_cues.js';

const geometry = makeBoardGeometry();
const near = (a, b, eps, what = '') => assert.ok(Math.abs(a - b) <= eps, `${what} ${a} is not within ${eps} of ${b}`);

// ---- hermite ----

test('hermite hits the ends and is exact for uniform motion', () => {
  const p0 = { x: 10, y: 20 };
  const v = { x: 100, y: -50 };
  const p1 = { x: 20, y: 15 };
  assert.deepEqual(hermite(p0, v, p1, v, 0.1, 0), p0);
  const mid = hermite(p0, v, p1, v, 0.1, 0.3);
  near(mid.x, 13, 1e-12);
  near(mid.y, 18.5, 1e-12);
});

test('hermite is exact for uniform deceleration', () => {
  const p = (t) => ({ x: 200 * t - 150 * t * t, y: 0 });
  const v = (t) => ({ x: 200 - 300 * t, y: 0 });
  for (const s of [0.1, 0.5, 0.77]) near(hermite(p(0), v(0), p(0.2), v(0.2), 0.2, s).x, p(s * 0.2).x, 1e-12);
});

// ---- playout clock ----

test('steady snapshots give two intervals of delay', () => {
  const c = new PlayoutClock();
  for (let i = 0; i < 120; i += 1) c.onSnapshot(i / 30, 100 + i / 30 + 0.04);
  near(c.interval, 1 / 30, 1e-6);
  near(c.jitter, 0, 1e-9);
  near(c.baseTransit(), 100.04, 1e-9);
  near(c.delay(), 2 / 30, 1e-6);
  near(c.targetTime(104), 104 - 100.04 - 2 / 30, 1e-6);
});

test('jitter raises the delay and then decays', () => {
  const c = new PlayoutClock({ ...PLAYOUT_DEFAULTS, jitterDecay: 1 });
  for (let i = 0; i < 60; i += 1) c.onSnapshot(i / 60, i / 60);
  const calm = c.delay();
  c.onSnapshot(1, 1.03);
  near(c.jitter, 0.03, 1e-9);
  near(c.delay(), calm + 0.03, 1e-6);
  for (let i = 61; i < 400; i += 1) c.onSnapshot(i / 60, i / 60);
  assert.ok(c.jitter < 0.03 * 0.01);
});

test('delay is clamped', () => {
  const c = new PlayoutClock({ ...PLAYOUT_DEFAULTS, maxDelay: 0.1 });
  c.onSnapshot(0, 0);
  c.onSnapshot(0.01, 2);
  assert.equal(c.delay(), 0.1);
});

test('render time advances smoothly and never backwards', () => {
  const c = new PlayoutClock();
  let seed = 7;
  const random = () => { seed = (seed * 1103515245 + 12345) % 2147483648; return seed / 2147483648; };
  let last = null;
  let maxStep = 0;
  let next = 0;
  for (let frame = 0; frame < 600; frame += 1) {
    const local = frame / 60;
    while (next / 60 + 0.02 <= local) {
      c.onSnapshot(next / 60, next / 60 + 0.05 + 0.02 * random());
      next += 1;
    }
    if (!c.hasData) continue;
    const r = c.renderTime(local);
    if (last !== null) {
      assert.ok(r >= last);
      maxStep = Math.max(maxStep, r - last);
    }
    last = r;
  }
  assert.ok(maxStep <= 1.1 / 60 + 1e-9, `step ${maxStep}`);
});

test('large errors snap at once', () => {
  const c = new PlayoutClock();
  c.onSnapshot(0, 0);
  const r0 = c.renderTime(0);
  for (let i = 0; i < 200; i += 1) c.onSnapshot(10 + i / 60, 0.01 + i / 60);
  assert.ok(c.renderTime(0.02) - r0 > 9);
});

// ---- interpolation buffer ----

const body = (id, x, y, vx = 0, vy = 0, pocketed = false) => ({ id, kind: id === 0 ? 'queen' : 'white', x, y, vx, vy, pocketed });
const snap = (seq, time, keyframe, bodies) => ({ seq, time, keyframe, bodies });
const find = (list, id) => list.find((b) => b.id === id) ?? null;

test('a delta needs a keyframe', () => {
  const b = new InterpolationBuffer(geometry);
  assert.equal(b.push(snap(1, 0, false, [body(1, 100, 100)])), false);
  assert.ok(b.empty());
  assert.equal(b.push(snap(2, 0, true, [body(1, 100, 100)])), true);
});

test('stale and duplicate snapshots are ignored', () => {
  const b = new InterpolationBuffer(geometry);
  b.push(snap(5, 1, true, [body(1, 100, 100)]));
  assert.equal(b.push(snap(5, 1.1, false, [body(1, 200, 100)])), false);
  assert.equal(b.push(snap(4, 1.2, false, [body(1, 200, 100)])), false);
  assert.equal(b.push(snap(6, 0.9, false, [body(1, 200, 100)])), false);
  assert.equal(b.newestState()[0].x, 100);
});

test('deltas keep unlisted bodies at rest', () => {
  const b = new InterpolationBuffer(geometry);
  b.push(snap(1, 0, true, [body(1, 100, 100), body(2, 200, 200, 50, 0)]));
  b.push(snap(2, 0.1, false, [body(2, 205, 200, 40, 0)]));
  const s = b.newestState();
  assert.equal(s.length, 2);
  assert.deepEqual([s[0].x, s[1].x, s[1].vx], [100, 205, 40]);
});

// Without damping (k = 0) uniform motion is the free motion.
const undamped = { ...INTERPOLATION_DEFAULTS, dampingPerS: 0 };

test('interpolates between states with velocities', () => {
  const b = new InterpolationBuffer(geometry, undamped);
  b.push(snap(1, 0, true, [body(1, 100, 100, 100, 0)]));
  b.push(snap(2, 0.1, false, [body(1, 110, 100, 100, 0)]));
  const r = b.sample(0.05);
  near(r[0].x, 105, 1e-9);
  assert.equal(r[0].scale, 1);
  assert.equal(r[0].alpha, 1);
});

test('before the oldest and after the newest', () => {
  const b = new InterpolationBuffer(geometry, undamped);
  b.push(snap(1, 1, true, [body(1, 100, 100, 100, 0)]));
  b.push(snap(2, 1.1, false, [body(1, 110, 100, 100, 0)]));
  near(b.sample(0.5)[0].x, 100, 1e-9);
  near(b.sample(1.12)[0].x, 112, 1e-9);
  near(b.sample(5)[0].x, 115, 1e-9);
});

test('a long gap after rest holds instead of gliding', () => {
  const b = new InterpolationBuffer(geometry);
  b.push(snap(1, 0, true, [body(1, 100, 100)]));
  b.push(snap(2, 5, false, [body(1, 300, 300, 500, 0)]));
  assert.deepEqual([b.sample(4.9)[0].x, b.sample(4.9)[0].y], [100, 100]);
  assert.deepEqual([b.sample(5)[0].x, b.sample(5)[0].y], [300, 300]);
});

test('a pocketed piece falls into its pocket', () => {
  const b = new InterpolationBuffer(geometry);
  b.push(snap(1, 0, true, [body(3, 520, 520, 300, 300), body(4, 300, 300)]));
  b.push(snap(2, 1 / 60, false, [body(3, 525, 525, 0, 0, true)]));
  const a = find(b.sample(0.01), 3);
  assert.ok(a.falling && a.scale < 1 && a.alpha < 1);
  const c = find(b.sample(0.12), 3);
  assert.ok(c.scale < a.scale && c.alpha < a.alpha);
  const pocket = geometry.pockets[3];
  assert.ok(Math.hypot(c.x - pocket.x, c.y - pocket.y) < 1);
  assert.equal(find(b.sample(0.2), 3), null);
  assert.notEqual(find(b.sample(0.2), 4), null);
});

test('a piece returned to the board appears at its new place', () => {
  const b = new InterpolationBuffer(geometry);
  b.push(snap(1, 0, true, [body(0, 0, 0, 0, 0, true)]));
  assert.equal(find(b.sample(0), 0), null);
  b.push(snap(2, 0.5, true, [body(0, 300, 300)]));
  assert.equal(find(b.sample(0.25), 0), null);
  assert.equal(find(b.sample(0.5), 0).x, 300);
});

test('old states are dropped', () => {
  const b = new InterpolationBuffer(geometry, { ...INTERPOLATION_DEFAULTS, history: 1 });
  b.push(snap(1, 0, true, [body(1, 100, 100)]));
  for (let i = 2; i < 200; i += 1) b.push(snap(i, i / 60, false, [body(1, 100 + i, 100)]));
  assert.ok(b.frames[0].time >= b.newestTime() - 1 - 1 / 60);
});

// ---- aim ----

test('power from drag: dead zone, linear, capped', () => {
  assert.equal(powerFromDrag(11.9), 0);
  assert.equal(powerFromDrag(12), 0);
  near(powerFromDrag(86), 12.5, 1e-12);
  assert.equal(powerFromDrag(160), 25);
  assert.equal(powerFromDrag(1000), 25);
  assert.equal(powerFromDrag(NaN), 0);
});

test('baseline x is clamped to the legal range', () => {
  assert.equal(clampBaselineX(0), 113);
  assert.equal(clampBaselineX(1000), 487);
  assert.equal(clampBaselineX(NaN), 300);
  assert.equal(clampBaselineX(250.5), 250.5);
});

test('placement overlapping a coin is illegal', () => {
  const pieces = [{ id: 4, kind: 'black', x: 300, y: 500, pocketed: false }];
  assert.deepEqual(checkPlacement({ x: 300, y: 520 }, pieces), { legal: false, blockingId: 4 });
  assert.equal(checkPlacement({ x: 333, y: 520 }, pieces).legal, true);
});

test('pulling back from the striker shoots away from the pointer', () => {
  const aim = new AimController();
  aim.beginTurn('bottom', 300);
  aim.pointerDown({ x: 300, y: 520 }, []);
  assert.equal(aim.phase, 'pulling');
  aim.pointerMove({ x: 300, y: 606 }, []);
  const shot = aim.pointerUp({ x: 300, y: 606 }, []);
  near(shot.angle, -Math.PI / 2, 1e-12);
  near(shot.power, 12.5, 1e-9);
  assert.equal(shot.x, 300);
});

test('a short pull shoots nothing, and cancel drops the pull', () => {
  const aim = new AimController();
  aim.beginTurn('top', 200);
  aim.pointerDown({ x: 200, y: 80 }, []);
  assert.equal(aim.pointerUp({ x: 205, y: 75 }, []), null);
  aim.pointerDown({ x: 200, y: 80 }, []);
  aim.pointerMove({ x: 200, y: 0 }, []);
  aim.cancel();
  assert.equal(aim.phase, 'idle');
  assert.equal(aim.pointerUp({ x: 200, y: 0 }, []), null);
});

test('a press on the baseline slides the striker, clamped', () => {
  const aim = new AimController();
  aim.beginTurn('bottom', 300);
  aim.pointerDown({ x: 150, y: 530 }, []);
  assert.equal(aim.phase, 'sliding');
  aim.pointerMove({ x: 20, y: 560 }, []);
  assert.equal(aim.x, 113);
  assert.equal(aim.pointerUp({ x: 20, y: 560 }, []), null);
  assert.equal(aim.takeMoved(), true);
  assert.equal(aim.takeMoved(), false);
});

test('a finger grabs the striker from further away', () => {
  const aim = new AimController();
  aim.beginTurn('bottom', 300);
  aim.pointerDown({ x: 340, y: 520 }, [], 46);
  assert.equal(aim.phase, 'pulling');
});

// ---- mapping, geometry ----

test('a turned view maps the top baseline to the bottom', () => {
  const m = new ScreenMapping(10, 20, 1.5, 600, true);
  assert.deepEqual(m.toScreen({ x: 300, y: 80 }), { x: 10 + 300 * 1.5, y: 20 + 520 * 1.5 });
  const back = m.toBoard(m.toScreen({ x: 123, y: 456 }));
  near(back.x, 123, 1e-9);
  near(back.y, 456, 1e-9);
});

test('pockets and the nearest one', () => {
  assert.deepEqual(geometry.pockets[0], { x: 57, y: 57 });
  assert.deepEqual(geometry.pockets[3], { x: 543, y: 543 });
  assert.equal(nearestPocket(geometry, { x: 560, y: 30 }), 1);
});

// ---- clocks, sounds ----

test('server clock: the pong with the smallest round trip wins', () => {
  const c = new ServerClock();
  c.oneWay(5000, 1);
  assert.equal(c.serverNowMs(1), 5000);
  c.roundTrip(10000, 2, 2.2); // rtt 200 ms, offset 10000 - 2100
  c.roundTrip(10100, 3, 3.02); // rtt 20 ms, offset 10100 - 3010
  near(c.offsetMs, 7090, 1e-9);
  c.oneWay(0, 4); // ignored once pongs arrived
  near(c.offsetMs, 7090, 1e-9);
  assert.equal(c.secondsUntil(7090 + 5000, 4), 1);
});

test('loudness from impulse and sound cues', () => {
  assert.equal(loudnessFromImpulse(5), 0);
  assert.equal(loudnessFromImpulse(2000), 1);
  near(loudnessFromImpulse(100), Math.log(20) / Math.log(400), 1e-12);
  const q = new SoundCueQueue();
  q.push({ time: 2, kind: 'click', volume: 1 });
  q.push({ time: 1, kind: 'pocket', volume: 1 });
  q.push({ time: 0.5, kind: 'cushion', volume: 1 });
  assert.deepEqual(q.takeDue(1.1).map((c) => c.kind), ['pocket']); // 0.5 s late: dropped
  assert.deepEqual(q.takeDue(2).map((c) => c.kind), ['click']);
});

test('synthesised sounds have their lengths and a 0.9 peak', () => {
  for (const [kind, seconds] of [['click', 0.045], ['cushion', 0.12], ['pocket', 0.3]]) {
    const wave = synthSound(kind, 44100);
    assert.equal(wave.length, Math.floor(seconds * 44100));
    near(Math.max(...wave.map(Math.abs)), 0.9, 1e-6, kind);
  }
});

// ---- protocol ----

test('client messages as the protocol spells them', () => {
  assert.deepEqual(proto.hello('Asha'), { type: 'hello', version: 1, name: 'Asha' });
  assert.deepEqual(proto.createRoom('freestyle', { target_points: 10, boards: '', shot_clock_s: 0 }, 'easy'),
    { type: 'create_room', rule_set: 'freestyle', options: { target_points: 10, shot_clock_s: 0 }, bot: { level: 'easy' } });
  assert.deepEqual(proto.createRoom('icf'), { type: 'create_room', rule_set: 'icf' });
  assert.deepEqual(proto.joinRoom('K7M2QX', true), { type: 'join_room', code: 'K7M2QX', as: 'spectator' });
  assert.deepEqual(proto.shoot(3, 301.5, -1.5, 20), { type: 'shoot', turn: 3, x: 301.5, angle: -1.5, power: 20 });
});

test('names and codes', () => {
  assert.ok(proto.isPlayerName('Asha'));
  assert.ok(!proto.isPlayerName('   '));
  assert.ok(!proto.isPlayerName('a\tb'));
  assert.ok(!proto.isPlayerName('x'.repeat(25)));
  assert.ok(proto.isPlayerName('é'.repeat(12)));
  assert.ok(!proto.isPlayerName('é'.repeat(13)));
  assert.equal(proto.clipName('é'.repeat(13)), 'é'.repeat(12));
  assert.ok(proto.isRoomCode('K7M2QX'));
  assert.ok(!proto.isRoomCode('K7M2Q0'));
  assert.equal(proto.normaliseRoomCode('k7-m2 qx!'), 'K7M2QX');
});

test('the decoder accepts the protocol examples', () => {
  const lines = [
    '{"type":"welcome","version":1,"player_id":7,"resume_token":"5f0c1e0e8a7b4c2d9e3f1a2b3c4d5e6f","server_time_ms":1700000000000}',
    '{"type":"snapshot","seq":12,"turn":3,"t":0.2,"keyframe":false,"bodies":[[19,300.12,401.5,-12.5,-600.0]],"pocketed":[]}',
    '{"type":"event","kind":"collision","turn":3,"t":0.125,"a":19,"b":4,"impulse":1234.5}',
    '{"type":"event","kind":"turn","turn":4,"seat":1,"deadline_ms":1700000020000,"server_time_ms":1700000000000}',
    '{"type":"error","code":"not_your_turn","message":"It is seat 1\'s turn."}',
    '{"type":"pong","nonce":42,"server_time_ms":1700000000005}',
  ];
  for (const line of lines) assert.ok(proto.decodeServer(line).message, line);
});

test('the decoder refuses bad frames with a reason', () => {
  assert.equal(proto.decodeServer('{').error, 'not JSON');
  assert.equal(proto.decodeServer('[1]').error, 'not an object');
  assert.equal(proto.decodeServer('{"x":1}').error, "no string 'type'");
  assert.equal(proto.decodeServer('{"type":"nope"}').error, "unknown type 'nope'");
  assert.equal(proto.decodeServer('{"type":"snapshot","seq":1,"turn":1,"t":0,"keyframe":false,"bodies":[[1,2,3]],"pocketed":[]}').error,
    "snapshot: field 'bodies[0]' must be [id, x, y, vx, vy]");
  assert.equal(proto.decodeServer('{"type":"pong","nonce":1.5,"server_time_ms":1}').error,
    "pong: field 'nonce' must be an integer");
  assert.equal(proto.decodeServer('{"type":"event","kind":"boom"}').error,
    "event: field 'kind' must be a known event kind");
});

test('the lobby gives its inputs the protocol limits, which index.html does not spell', () => {
  const inputs = { name: {}, code: {}, targetPoints: {}, boards: {}, shotClock: {} };
  applyLimits(inputs);
  assert.deepEqual(inputs, {
    name: { maxLength: PROTOCOL.maxNameBytes },
    code: { maxLength: PROTOCOL.roomCodeLength },
    targetPoints: { min: '1', max: String(PROTOCOL.maxTargetPoints) },
    boards: { min: '1', max: String(PROTOCOL.maxBoards) },
    shotClock: { min: '0', max: String(PROTOCOL.maxShotClockS) },
  });
  assert.deepEqual(OPTION_RANGES.boards, [1, PROTOCOL.maxBoards]);
  const html = fs.readFileSync(new URL('../../web/index.html', import.meta.url), 'utf8');
  for (const id of ['name', 'room-code', 'target-points', 'boards', 'shot-clock']) {
    const tag = html.match(new RegExp(`<input id="${id}"[^>]*>`));
    assert.ok(tag, id);
    assert.doesNotMatch(tag[0], /\b(maxlength|min|max)=/, id);
  }
});

// ---- words, links, model ----

test('plain words', () => {
  assert.equal(pocketList(['white', 'black', 'white', 'queen']), '2 white coins, 1 black coin and the queen');
  assert.equal(pocketList([]), 'nothing');
  assert.equal(gameEndSentence(1, false, 'Ravi', 'left'), 'Ravi wins the game (the opponent left)');
  assert.equal(gameEndSentence(0, true, 'Asha', 'score'), 'You win the game (target score reached)');
  assert.equal(gameEndSentence(-1, false, '', 'boards'), 'The game is drawn (all boards played)');
});

test('room links', () => {
  assert.deepEqual(parseRoomHash('#/room/K7M2QX'), { kind: 'room', code: 'K7M2QX' });
  assert.deepEqual(parseRoomHash('#/watch/k7m2qx'), { kind: 'watch', code: 'K7M2QX' });
  assert.equal(parseRoomHash('#/room/K7M2'), null);
  assert.equal(parseRoomHash('#/room/K7M2QX/extra'), null);
  assert.equal(parseRoomHash(''), null);
  assert.equal(roomHash('K7M2QX', true), '#/watch/K7M2QX');
});

function roomState(extra = {}) {
  return {
    type: 'room_state', code: 'K7M2QX', you: 1, rule_set: 'icf',
    options: { target_points: 25, boards: 8, shot_clock_s: 20 },
    seats: [
      { occupied: true, name: 'Asha', connected: true, bot: false, colour: 'white', baseline: 'bottom' },
      { occupied: true, name: 'Ravi', connected: true, bot: false, colour: 'black', baseline: 'top' },
    ],
    spectators: 0, scores: [3, 1], dues: [0, 1], board_number: 2, turn: 7, to_play: 1,
    shot_clock_deadline_ms: 1000020000, server_time_ms: 1000000000, phase: 'aiming',
    queen: { state: 'on_board', seat: -1 }, winner: -1,
    bodies: [{ id: 0, kind: 'queen', x: 300, y: 300, vx: 0, vy: 0, pocketed: false },
      { id: 1, kind: 'black', x: 300, y: 265, vx: 0, vy: 0, pocketed: true }],
    ...extra,
  };
}

test('the model from a room state: seats, turn, turned view, shot clock', () => {
  const m = new MatchModel();
  m.handle(roomState(), 10);
  assert.equal(m.view.code, 'K7M2QX');
  assert.ok(m.myTurn());
  assert.ok(m.flipped());
  assert.equal(m.view.seats[1].dues, 1);
  assert.equal(m.shotClockLeft(10), 20);
  assert.equal(m.shotClockLeft(15), 15);
  assert.deepEqual(m.coinsLeft(), { black: 0, white: 0, queen: 1 });
});

test('the model places each shot on one timeline and ends the game with its reason', () => {
  const m = new MatchModel();
  m.handle(roomState({ you: 0 }), 10);
  m.handle({ type: 'snapshot', seq: 1, turn: 7, t: 0, keyframe: false, bodies: [[0, 300, 300, 10, 0]], pocketed: [] }, 10.1);
  assert.equal(m.view.phase, 'moving');
  m.handle({ type: 'snapshot', seq: 2, turn: 7, t: 0.5, keyframe: false, bodies: [[0, 305, 300, 0, 0]], pocketed: [] }, 10.6);
  near(m.buffer.newestTime() - m.buffer.frames[m.buffer.frames.length - 2].time, 0.5, 1e-9);
  m.handle({ type: 'event', kind: 'game_end', winner: 1, reason: 'left', scores: [0, 5] }, 11);
  assert.equal(m.view.phase, 'game_over');
  assert.equal(m.view.gameEnd.sentence, 'Ravi wins the game (the opponent left)');
});

test('the game end is named by its rule code, as the journal and carrom-client name it', () => {
  const m = new MatchModel();
  m.handle(roomState({ you: 0 }), 10);
  const end = proto.decodeServer('{"type":"event","kind":"game_end","winner":1,"reason":"left","scores":[0,5],"rule":"forfeit"}');
  m.handle(end.message, 11);
  assert.deepEqual({ winner: m.view.gameEnd.winner, reason: m.view.gameEnd.reason }, { winner: 1, reason: 'forfeit' });
  assert.equal(m.view.gameEnd.sentence, 'Ravi wins the game (the opponent left)');
  const older = new MatchModel(); // a server that sends no rule: game_end's reason
  older.handle(roomState({ you: 0 }), 10);
  older.handle({ type: 'event', kind: 'game_end', winner: 0, reason: 'score', scores: [25, 5] }, 11);
  assert.equal(older.view.gameEnd.reason, 'score');
  assert.equal(proto.decodeServer('{"type":"event","kind":"game_end","winner":1,"reason":"score","scores":[0,5],"rule":7}').error,
    "event: field 'rule' must be a string");
});

test('a match paused while the server cannot save its stroke says so, then that it goes on', () => {
  const m = new MatchModel();
  m.handle(roomState({ you: 0 }), 10);
  const message = 'The server cannot save the last stroke because its database does not answer; '
    + 'the match goes on when it is back.';
  const paused = proto.decodeServer(JSON.stringify({ type: 'event', kind: 'paused', reason: 'store', message }));
  assert.equal(paused.error, undefined);
  m.handle(paused.message, 11);
  const resumed = proto.decodeServer('{"type":"event","kind":"resumed"}');
  assert.equal(resumed.error, undefined);
  m.handle(resumed.message, 12);
  assert.deepEqual(m.log.lines.slice(-2).map((l) => [l.text, l.tone]),
    [[message, 'error'], ['The match goes on', 'info']]);
  assert.equal(proto.decodeServer('{"type":"event","kind":"paused","reason":"store"}').error,
    "event: field 'message' must be a string");
});

test('a shot played long after the join keyframe sounds every cue once, when rendered', () => {
  const m = new MatchModel();
  m.handle(roomState({ you: 0, to_play: 0 }), 10);
  // The join keyframe: turn 7 at rest, t = 0.
  m.handle({ type: 'snapshot', seq: 1, turn: 7, t: 0, keyframe: true, bodies: [[0, 300, 300, 0, 0], [19, 300, 500, 0, 0]], pocketed: [1] }, 10.01);
  for (let local = 10; local < 15; local += 1 / 60) m.render(local);
  // The break, 5 s later: its events come just before the snapshot that covers them; the
  // two coins of a straight break are hit at the same time.
  const events = [
    { kind: 'collision', t: 0.09, a: 19, b: 9, impulse: 1300 },
    { kind: 'collision', t: 0.09, a: 19, b: 10, impulse: 1200 },
    { kind: 'collision', t: 0.2, a: 9, b: 4, impulse: 600 },
    { kind: 'cushion', t: 0.5, a: 4, b: 2, impulse: 300 },
    { kind: 'pocket', t: 0.8, a: 4, b: 1 },
  ];
  const played = [];
  let seq = 2;
  let sent = 0;
  for (let k = 0; k <= 60; k += 1) {
    const t = k / 60;
    const local = 15 + t + 0.02;
    while (sent < events.length && events[sent].t <= t) {
      m.handle({ type: 'event', turn: 7, ...events[sent++] }, local);
    }
    m.handle({ type: 'snapshot', seq: seq++, turn: 7, t, keyframe: false, bodies: [[19, 300, 500 - 600 * t, 0, -600]], pocketed: [] }, local);
    const rendered = m.render(local + 0.005) && m.lastRender;
    for (const c of m.takeSounds()) played.push({ ...c, rendered });
  }
  for (let k = 1; k <= 30; k += 1) {
    m.render(16.02 + k / 60);
    for (const c of m.takeSounds()) played.push({ ...c, rendered: m.lastRender });
  }
  assert.equal(m.cuesHeard, 5);
  assert.equal(m.cues.late, 0);
  assert.equal(m.cuesMerged, 1); // the two clicks at 0.09 s are one sound, the louder
  assert.deepEqual(played.map((c) => c.kind), ['click', 'click', 'cushion', 'pocket']);
  const start = m.turnOffsets.get(7);
  played.forEach((c, i) => {
    const t = [0.09, 0.2, 0.5, 0.8][i];
    near(c.time - start, t, 1e-9); // on the shot's own timeline
    assert.ok(c.rendered >= c.time && c.rendered - c.time < 0.05, `cue at ${t} s played ${c.rendered - c.time} s after`);
  });
  near(played[0].volume, loudnessFromImpulse(1300), 1e-12);
});

// ---- session: a silent link ----

// A connection that opens at once, records what is sent and never answers anything.
class MuteConnection {
  static made = [];
  constructor(url, hooks) {
    this.hooks = hooks;
    this.sent = [];
    this.closed = false;
    MuteConnection.made.push(this);
    setTimeout(() => hooks.onOpen(), 0);
  }
  send(m) { this.sent.push(m); }
  close() { this.closed = true; }
}

test('a link on which nothing arrives is taken for lost and reopened', async () => {
  assert.equal(SESSION_DEFAULTS.silenceTimeout, 10.0);
  assert.equal(SESSION_DEFAULTS.giveUpAfter, 130.0);
  MuteConnection.made = [];
  const statuses = [];
  const config = { ...SESSION_DEFAULTS, pingInterval: 0.05, firstRetry: 0.05, silenceTimeout: 0.3 };
  const session = new Session('ws://127.0.0.1:1', null, { onMessage() {}, onChange() { statuses.push(session.status); } },
    config, MuteConnection);
  session.start('ann');
  await new Promise((resolve) => setTimeout(resolve, 200));
  assert.equal(MuteConnection.made.length, 1, 'not before the silence timeout');
  await new Promise((resolve) => setTimeout(resolve, 400));
  assert.ok(MuteConnection.made[0].closed, 'the silent link is closed');
  assert.ok(MuteConnection.made.length >= 2, 'a new link is opened');
  assert.ok(statuses.some((s) => s.includes('the link is silent, taken for lost')), statuses.join(' | '));
  session.stopLink();
});

// ---- free motion between snapshots (docs/interpolation.md, "Sampling a time") ----

const K = 60 * Math.log(1 / 0.985); // the server's default damping, 1/s
// A body's state dt after (x, y, vx, vy) along the damped free motion.
const freeAt = (s, dt, k = K) => {
  const f = k === 0 ? dt : -Math.expm1(-k * dt) / k;
  const decay = Math.exp(-k * dt);
  return { x: s.x + s.vx * f, y: s.y + s.vy * f, vx: s.vx * decay, vy: s.vy * decay };
};
const stateBody = (id, s, pocketed = false) => body(id, s.x, s.y, s.vx, s.vy, pocketed);

test('the travel factor is -expm1(-k dt) / k, and dt for k = 0', () => {
  near(travelFactor(K, 0.1), (1 - Math.exp(-K * 0.1)) / K, 1e-15);
  near(travelFactor(K, -0.1), (1 - Math.exp(K * 0.1)) / K, 1e-15);
  assert.equal(travelFactor(0, 0.37), 0.37);
  assert.equal(INTERPOLATION_DEFAULTS.dampingPerS, K);
  assert.equal(PHYSICS.dampingPerS, K);
});

test('free motion between two states with no change of motion is drawn exactly', () => {
  const b = new InterpolationBuffer(geometry);
  const a = { x: 100, y: 200, vx: 300, vy: -150 };
  b.push(snap(1, 1, true, [stateBody(1, a)]));
  b.push(snap(2, 1.1, false, [stateBody(1, freeAt(a, 0.1))]));
  for (const dt of [0, 0.001, 0.025, 0.05, 0.0777, 0.099]) {
    const r = b.sample(1 + dt)[0];
    near(r.x, freeAt(a, dt).x, 1e-9, `x at ${dt}`);
    near(r.y, freeAt(a, dt).y, 1e-9, `y at ${dt}`);
  }
});

test('one change of motion between two states is drawn exactly before and after its instant', () => {
  // Moving right and down, the body bounces off a cushion at c = 0.063 s (vx reversed at 0.8).
  const a = { x: 100, y: 300, vx: 400, vy: 50 };
  const c = 0.063;
  const hit = freeAt(a, c);
  const after = { ...hit, vx: -0.8 * hit.vx };
  const truth = (t) => (t <= c ? freeAt(a, t) : freeAt(after, t - c));
  const b = new InterpolationBuffer(geometry);
  b.push(snap(1, 0, true, [stateBody(1, a)]));
  b.push(snap(2, 0.1, false, [stateBody(1, truth(0.1))]));
  let furthestFromHermite = 0;
  for (const t of [0.001, 0.02, 0.05, 0.062, 0.0629, 0.0631, 0.064, 0.08, 0.0999]) {
    const r = b.sample(t)[0];
    near(r.x, truth(t).x, 1e-9, `x at ${t}`);
    near(r.y, truth(t).y, 1e-9, `y at ${t}`);
    const h = hermite(a, { x: a.vx, y: a.vy }, truth(0.1), { x: truth(0.1).vx, y: truth(0.1).vy }, 0.1, t / 0.1);
    furthestFromHermite = Math.max(furthestFromHermite, Math.hypot(h.x - r.x, h.y - r.y));
  }
  assert.ok(furthestFromHermite > 1, `the Hermite curve is ${furthestFromHermite} px away at most`);
});

test('two changes of motion between two states fall back to the Hermite curve', () => {
  // A bounce off a side cushion at 0.03 s, then off the bottom one at 0.07 s.
  const a = { x: 520, y: 500, vx: 600, vy: 500 };
  const one = freeAt(a, 0.03);
  const two = freeAt({ ...one, vx: -0.8 * one.vx }, 0.04);
  const end = freeAt({ ...two, vy: -0.8 * two.vy }, 0.03);
  const b = new InterpolationBuffer(geometry);
  b.push(snap(1, 0, true, [stateBody(1, a)]));
  b.push(snap(2, 0.1, false, [stateBody(1, end)]));
  for (const t of [0.01, 0.03, 0.05, 0.09]) {
    const h = hermite(a, { x: a.vx, y: a.vy }, end, { x: end.vx, y: end.vy }, 0.1, t / 0.1);
    const r = b.sample(t)[0];
    near(r.x, h.x, 1e-9, `x at ${t}`);
    near(r.y, h.y, 1e-9, `y at ${t}`);
  }
});

test('past the newest state: free motion for 0.25 s with contact snapshots, 50 ms without', () => {
  const a = { x: 100, y: 300, vx: 400, vy: -100 };
  for (const [every, cap] of [[true, 0.25], [false, 0.05]]) {
    const b = new InterpolationBuffer(geometry);
    b.setMotion(K, every);
    b.push(snap(1, 2, true, [stateBody(1, a)]));
    for (const ahead of [0.01, 0.04, 0.2, 0.25, 0.3, 1]) {
      const r = b.sample(2 + ahead)[0];
      const want = freeAt(a, Math.min(ahead, cap));
      near(r.x, want.x, 1e-9, `x ${ahead} s ahead, contact snapshots ${every}`);
      near(r.y, want.y, 1e-9, `y ${ahead} s ahead, contact snapshots ${every}`);
    }
  }
});

test('with contact snapshots a pocket fall starts at the newer state, where the free motion brings the body', () => {
  const a = { x: 500, y: 500, vx: 300, vy: 300 };
  const b = new InterpolationBuffer(geometry);
  b.setMotion(K, true);
  b.push(snap(1, 0, true, [stateBody(3, a), body(4, 300, 300)]));
  b.push(snap(2, 0.08, false, [body(3, 0, 0, 0, 0, true)]));
  assert.equal(b.falls.length, 1);
  const fall = b.falls[0];
  assert.equal(fall.start, 0.08);
  const at = freeAt(a, 0.08);
  near(fall.fromX, at.x, 1e-9);
  near(fall.fromY, at.y, 1e-9);
  near(fall.fromVx, at.vx, 1e-9);
  assert.equal(fall.pocket, geometry.pockets[3]);
  const r = find(b.sample(0.09), 3);
  assert.ok(r.falling && r.scale < 1);
  // Until its pocketing instant it moves on along the free motion.
  for (const t of [0.01, 0.04, 0.079]) {
    const drawn = find(b.sample(t), 3);
    assert.ok(drawn && !drawn.falling, `drawn at ${t}`);
    near(drawn.x, freeAt(a, t).x, 1e-9);
    near(drawn.y, freeAt(a, t).y, 1e-9);
  }
  // Without contact snapshots it starts at the older state, from its position.
  const old = new InterpolationBuffer(geometry);
  old.push(snap(1, 0, true, [stateBody(3, a)]));
  old.push(snap(2, 0.08, false, [body(3, 0, 0, 0, 0, true)]));
  assert.deepEqual([old.falls[0].start, old.falls[0].fromX], [0, 500]);
});

test('with interval factor 0 the playout delay is clamp(jitter, 10 ms, 300 ms)', () => {
  for (const [late, want] of [[0, 0.010], [0.004, 0.010], [0.03, 0.03], [0.12, 0.12], [0.5, 0.3]]) {
    const c = new PlayoutClock();
    c.setIntervalFactor(0);
    for (let i = 0; i < 30; i += 1) c.onSnapshot(i / 10, 50 + i / 10);
    c.onSnapshot(3, 53 + late);
    near(c.interval, 0.1, 0.01, 'interval');
    near(c.delay(), want, 1e-9, `delay with ${late} s late`);
  }
  assert.equal(PLAYOUT_DEFAULTS.intervalFactor, 2);
});

test('room_state motion: present, absent (the defaults) and invalid', () => {
  const decode = (extra) => proto.decodeServer(JSON.stringify(roomState(extra)));
  assert.deepEqual(decode({ motion: { damping_per_s: 2.5, contact_snapshots: true } }).message.motion,
    { damping_per_s: 2.5, contact_snapshots: true });
  assert.deepEqual(decode({ motion: { damping_per_s: 0, contact_snapshots: false } }).message.motion,
    { damping_per_s: 0, contact_snapshots: false });
  assert.deepEqual(decode({}).message.motion, { damping_per_s: K, contact_snapshots: false });
  const refused = [
    [5, "room_state: field 'motion' must be an object"],
    [null, "room_state: field 'motion' must be an object"],
    [{ contact_snapshots: true }, "room_state: field 'motion.damping_per_s' must be a number in [0, 100]"],
    [{ damping_per_s: -0.1, contact_snapshots: true }, "room_state: field 'motion.damping_per_s' must be a number in [0, 100]"],
    [{ damping_per_s: 100.5, contact_snapshots: true }, "room_state: field 'motion.damping_per_s' must be a number in [0, 100]"],
    [{ damping_per_s: '1', contact_snapshots: true }, "room_state: field 'motion.damping_per_s' must be a number in [0, 100]"],
    [{ damping_per_s: 1 }, "room_state: field 'motion.contact_snapshots' must be a boolean"],
    [{ damping_per_s: 1, contact_snapshots: 1 }, "room_state: field 'motion.contact_snapshots' must be a boolean"],
  ];
  for (const [motion, error] of refused) assert.equal(decode({ motion }).error, error, JSON.stringify(motion));
});

test('the model gives room_state motion to the buffer and the playout clock', () => {
  const m = new MatchModel();
  m.handle(proto.decodeServer(JSON.stringify(roomState({ motion: { damping_per_s: 2.5, contact_snapshots: true } }))).message, 10);
  assert.equal(m.buffer.config.dampingPerS, 2.5);
  assert.equal(m.buffer.everyChangeSent, true);
  assert.equal(m.playout.config.intervalFactor, 0);
  m.handle(roomState(), 11); // no motion: an older server
  assert.equal(m.buffer.config.dampingPerS, K);
  assert.equal(m.buffer.everyChangeSent, false);
  assert.equal(m.playout.config.intervalFactor, 2);
});

test('the HUD log never shows one line twice (client/src/hud_log.cpp)', () => {
  const log = new HudLog(5, 6);
  log.post('Your turn', 'info', 0);
  log.post('Asha pocketed 1 white coin', 'good', 1);
  log.post('Your turn', 'info', 2);
  assert.deepEqual(log.visible(2).map((l) => l.text), ['Asha pocketed 1 white coin', 'Your turn']);
  assert.deepEqual(log.visible(8).map((l) => l.text), ['Your turn']);
  const later = new HudLog(5, 6);
  later.post('Your turn', 'info', 0);
  later.post('Your turn', 'info', 7);
  assert.equal(later.lines.length, 2);
});

test('a striker placed over a piece is drawn see-through, the piece outlined on top', () => {
  // The renderer's placing step on a context that records what it draws (no browser needed).
  const calls = [];
  const ctx = new Proxy({ globalAlpha: 1 }, {
    get(target, key) {
      if (key in target) return target[key];
      return (...args) => { calls.push({ op: key, args, alpha: target.globalAlpha, dash: target.dash }); };
    },
    set(target, key, value) {
      target[key] = value;
      return true;
    },
  });
  ctx.setLineDash = (d) => { ctx.dash = d.length > 0; };
  const r = Object.assign(Object.create(Renderer.prototype), {
    ctx, geometry: { strikerR: 18 }, dpr: 1, dirty: [], drawn: [],
  });
  const m = new ScreenMapping(0, 0, 1, 600, 0);
  const placing = { striker: { x: 300, y: 520 }, alpha: 1, warning: true, blocking: { x: 320, y: 515, r: 14 } };
  r.drawPlacing(m, { byKind: { striker: 'striker-sprite' } }, 40, placing, false);
  const image = calls.find((c) => c.op === 'drawImage');
  assert.equal(image.alpha, OVERLAP_ALPHA);
  assert.equal(r.drawn[0].alpha, OVERLAP_ALPHA);
  const imageAt = calls.indexOf(image);
  const outline = calls.findIndex((c, i) => i > imageAt && c.op === 'arc' && c.args[0] === 320 && c.args[1] === 515);
  assert.ok(outline > imageAt, 'the blocking piece is outlined after (over) the striker');
  assert.equal(calls[outline].args[2], 16); // its radius plus 2 px
  assert.ok(calls.slice(outline).some((c) => c.op === 'stroke' && c.dash), 'a dashed outline');
  // A legal placement: opaque, nothing outlined.
  calls.length = 0;
  r.drawn = [];
  r.drawPlacing(m, { byKind: { striker: 'striker-sprite' } }, 40, { ...placing, warning: false, blocking: null }, false);
  assert.equal(calls.find((c) => c.op === 'drawImage').alpha, 1);
  assert.ok(!calls.some((c) => c.op === 'arc'));
});
