// The golden cases of tests/golden/ (written by carrom-golden from the desktop client's logic,
// tests/golden/README.md) replayed through the web client's modules: the same inputs must give
// the same outputs, numbers within the files' tolerance. tests/client/golden_cases_test.cpp
// replays them through the C++ side.
import assert from 'node:assert/strict';
import { readdirSync, readFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import test from 'node:test';
import { fileURLToPath } from 'node:url';

import { AimController } from '../../web/js/aim_controller.js';
import { makeBoardGeometry, PHYSICS } from '../../web/js/board_geometry.js';
import { HudLog } from '../../web/js/hud_log.js';
import { InterpolationBuffer } from '../../web/js/interpolation_buffer.js';
import { MatchModel } from '../../web/js/match_model.js';
import {
  coinsLeftText, countWords, duesSentence, errorSentence, forfeitSentence, foulCost, foulSentence, pocketList,
  queenSentence, ruleSetName, strokePoints, targetWords,
} from '../../web/js/plain_words.js';
import { controlsHelp, howToPlay, walkthroughSteps } from '../../web/js/how_to_play.js';
import { PLAYOUT_DEFAULTS, PlayoutClock } from '../../web/js/playout_clock.js';
import { decodeServer } from '../../web/js/protocol.js';
import { ScreenMapping } from '../../web/js/screen_mapping.js';

const golden = join(dirname(fileURLToPath(import.meta.url)), '..', 'golden');
const TOLERANCE = 2e-6; // the files keep six decimals (tests/golden/README.md)
const rounded = (x) => Math.round(x * 1e6) / 1e6 || 0;

const readCase = (folder, file) => JSON.parse(readFileSync(join(golden, folder, file), 'utf8'));
const casesIn = (folder) => readdirSync(join(golden, folder)).filter((f) => f.endsWith('.json')).sort();

// The first difference between expected and actual: numbers within TOLERANCE, the rest equal.
// null when they agree (golden_json.cpp first_difference).
function firstDifference(expected, actual, path = '$') {
  const show = (v) => JSON.stringify(v);
  if (typeof expected === 'number' && typeof actual === 'number') {
    return Math.abs(expected - actual) <= TOLERANCE ? null
      : `${path}: expected ${show(expected)}, got ${show(actual)}`;
  }
  const kind = (v) => (v === null ? 'null' : Array.isArray(v) ? 'array' : typeof v);
  if (kind(expected) !== kind(actual)) return `${path}: expected ${show(expected)}, got ${show(actual)}`;
  if (Array.isArray(expected)) {
    if (expected.length !== actual.length) {
      return `${path}: expected ${expected.length} items, got ${actual.length} (${show(actual)})`;
    }
    for (let i = 0; i < expected.length; i += 1) {
      const d = firstDifference(expected[i], actual[i], `${path}[${i}]`);
      if (d) return d;
    }
    return null;
  }
  if (kind(expected) === 'object') {
    for (const key of Object.keys(expected)) {
      if (!(key in actual)) return `${path}.${key}: missing`;
      const d = firstDifference(expected[key], actual[key], `${path}.${key}`);
      if (d) return d;
    }
    for (const key of Object.keys(actual)) {
      if (!(key in expected)) return `${path}.${key}: not expected (${show(actual[key])})`;
    }
    return null;
  }
  return expected === actual ? null : `${path}: expected ${show(expected)}, got ${show(actual)}`;
}

function assertSame(expected, actual, what) {
  const d = firstDifference(expected, actual);
  assert.equal(d, null, `${what}: ${d}`);
}

test('the comparison of the replays fails on a difference', () => {
  assert.equal(firstDifference({ a: [1, 'x'] }, { a: [1 + 1e-7, 'x'] }), null);
  assert.match(firstDifference({ a: [1, 'x'] }, { a: [1.001, 'x'] }), /\$\.a\[0\]/);
  assert.match(firstDifference({ a: 1 }, { a: 1, b: 2 }), /not expected/);
  assert.match(firstDifference({ a: null }, { a: 0 }), /expected null/);
});

// ---- the match model ----

// The HUD's view as the case files keep it (model_cases.cpp view_json).
function viewJson(model) {
  const v = model.view;
  if (!v.inRoom) return { in_room: false }; // the rest is the defaults of each client's own
  return {
    in_room: v.inRoom,
    code: v.code,
    you: v.you,
    rule_set: v.ruleSet,
    options: {
      target_points: v.options.target_points, boards: v.options.boards,
      shot_clock_s: v.options.shot_clock_s,
    },
    seats: v.seats.map((s) => ({
      occupied: s.occupied, name: s.name, connected: s.connected, bot: s.bot, colour: s.colour,
      side: s.baseline, score: s.score, dues: s.dues,
    })),
    spectators: v.spectators,
    board_number: v.boardNumber,
    turn: v.turn,
    to_play: v.toPlay,
    phase: v.phase,
    queen: { state: v.queen.state, seat: v.queen.seat },
    winner: v.winner,
    deadline_ms: v.deadlineMs,
    aim_x: v.aimX === null ? null : rounded(v.aimX),
    result: v.gameEnd ? { winner: v.gameEnd.winner, reason: v.gameEnd.reason } : null,
  };
}

for (const file of casesIn('model')) {
  test(`model: ${file}`, () => {
    const c = readCase('model', file);
    const stream = readFileSync(join(golden, 'model', c.stream), 'utf8').split('\n')
      .filter((l) => l !== '').map((l) => JSON.parse(l));
    assert.equal(stream.length, c.expected.length, 'one expected step per message');
    const model = new MatchModel(PHYSICS);
    let expectedView = null; // a step without "view" keeps the one before
    stream.forEach((line, i) => {
      const { view, ...expected } = c.expected[i];
      if (view !== undefined) expectedView = view;
      const what = `${file} message ${i + 1} (${line.line.slice(0, 80)})`;
      const step = {};
      const decoded = decodeServer(line.line);
      if (decoded.message) model.handle(decoded.message, line.at);
      else step.refused = decoded.error;
      assertSame(expectedView, viewJson(model), `${what}: view`);
      const log = model.log.lines.map((l) => [l.text, l.tone]);
      model.log = new HudLog(); // the next step shows only its own lines
      if (log.length > 0) step.log = log;
      model.render(line.at);
      step.render_s = rounded(model.lastRender);
      const sounds = model.takeSounds().map((s) => [s.kind, rounded(s.time), rounded(s.volume)]);
      if (sounds.length > 0) step.sounds = sounds;
      assertSame(expected, step, what);
    });
  });
}

// ---- the board between snapshots ----

function replayInterpolation(input) {
  const buffer = new InterpolationBuffer(makeBoardGeometry(PHYSICS));
  buffer.setMotion(input.motion.damping_per_s, input.motion.every_change_sent);
  return input.ops.map((op) => {
    if (op.push) {
      const p = op.push;
      return buffer.push({
        seq: p.seq, time: p.time, keyframe: p.keyframe,
        bodies: p.bodies.map(([id, kind, x, y, vx, vy, pocketed]) => ({ id, kind, x, y, vx, vy, pocketed })),
      });
    }
    return buffer.sample(op.sample).map((b) => [
      b.id, rounded(b.x), rounded(b.y), rounded(b.scale), rounded(b.alpha), b.falling,
    ]);
  });
}

function replayPlayout(input) {
  const clock = new PlayoutClock({ ...PLAYOUT_DEFAULTS, intervalFactor: input.interval_factor });
  return input.ops.map((op) => {
    if (op.snapshot) {
      clock.onSnapshot(op.snapshot[0], op.snapshot[1]);
      return null;
    }
    return rounded(clock.renderTime(op.render));
  });
}

for (const file of casesIn('interpolation')) {
  test(`interpolation: ${file}`, () => {
    const c = readCase('interpolation', file);
    const replay = file === 'playout.json' ? replayPlayout : replayInterpolation;
    const actual = replay(c.input);
    c.expected.forEach((e, i) => assertSame(e, actual[i], `${file} op ${i} ${JSON.stringify(c.input.ops[i]).slice(0, 60)}`));
    assert.equal(actual.length, c.expected.length);
  });
}

// ---- aiming on a turned view ----

function replayAim(input) {
  const v = input.view;
  const mapping = new ScreenMapping(v.origin_x, v.origin_y, v.scale, v.board_size, v.turns);
  const toBoard = ([x, y]) => mapping.toBoard({ x, y });
  return input.gestures.map((g) => {
    const pieces = g.pieces.map(([id, kind, x, y, pocketed]) => ({ id, kind, x, y, vx: 0, vy: 0, pocketed }));
    const aim = new AimController(PHYSICS);
    aim.beginTurn(input.side, g.start_x);
    const steps = g.events.map((e) => {
      let shot = null;
      if (e.down) aim.pointerDown(toBoard(e.down), pieces);
      else if (e.move) aim.pointerMove(toBoard(e.move), pieces);
      else if (e.up) {
        const s = aim.pointerUp(toBoard(e.up), pieces);
        if (s) shot = [rounded(s.x), rounded(s.angle), rounded(s.power)];
      } else if (e.nudge) aim.nudge(e.nudge[0], e.nudge[1], pieces);
      else aim.cancel();
      const step = {
        phase: aim.phase, x: rounded(aim.x), legal: aim.placement.legal,
        blocking: aim.placement.blockingId, moved: aim.takeMoved(),
      };
      if (e.up) step.shot = shot;
      return step;
    });
    return { name: g.name, steps };
  });
}

for (const file of casesIn('aim')) {
  test(`aim: ${file}`, () => {
    const c = readCase('aim', file);
    assertSame(c.expected, replayAim(c.input), file);
  });
}

// ---- plain words ----

test('words: words.json', () => {
  const { input, expected } = readCase('words', 'words.json');
  assertSame(expected, {
    count: input.count.map(([n, one, many]) => countWords(n, one, many)),
    pockets: input.pockets.map((kinds) => pocketList(kinds)),
    queen: input.queen.map(([state, seat, name]) => queenSentence({ state, seat }, name)),
    errors: input.errors.map(([code, message]) => errorSentence({ code, message })),
    rule_sets: input.rule_sets.map((r) => ruleSetName(r)),
    how_to_play: input.rule_sets.map((r) => ({ ...howToPlay(r), walkthrough: walkthroughSteps(r) })),
    controls: controlsHelp(),
    targets: input.targets.map(([ruleSet, points]) => targetWords(ruleSet, points)),
    coins_left: input.coins_left.map(([white, black, queen, ruleSet, colour]) => coinsLeftText(
      { white, black, queen: queen ? 1 : 0 }, ruleSet, colour)),
    fouls: input.fouls.map(([name, message]) => foulSentence(name, message)),
    costs: input.costs.map(([kinds, points]) => foulCost(kinds, points)),
    stroke_points: input.stroke_points.map((p) => strokePoints(p)),
    dues: input.dues.map(([who, plural, owed]) => duesSentence(who, plural, owed)),
    forfeits: input.forfeits.map(([leaver, reason, winner, plural]) => forfeitSentence(
      leaver, reason, winner, plural)),
  }, 'words.json');
});
