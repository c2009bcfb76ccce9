// Doubles in the web client's pure modules under node: the view turned for each of the four
// seats (own baseline at the bottom, the seats in anticlockwise order on every screen), aiming
// and the arrow keys along a side baseline in the turned frame with board coordinates on the
// wire, the protocol's doubles fields, the seat panels' and the teams' model, and the match
// model's team words.
import assert from 'node:assert/strict';
import test from 'node:test';

import { AimController } from '../../web/js/aim_controller.js';
import { alongOf, strikerAt } from '../../web/js/board_geometry.js';
import { MatchModel } from '../../web/js/match_model.js';
import { gameEndSentence } from '../../web/js/plain_words.js';
import * as proto from '../../web/js/protocol.js';
import { freeSeats, seatPanels, teamSummaries, viewTurns } from '../../web/js/seat_panels.js';
import { ScreenMapping, screenSide, SIDES, turnsForSide } from '../../web/js/screen_mapping.js';

const near = (a, b, eps, what = '') => assert.ok(Math.abs(a - b) <= eps, `${what} ${a} is not within ${eps} of ${b}`);
const nearPoint = (p, q, eps, what = '') => {
  near(p.x, q.x, eps, `${what} x`);
  near(p.y, q.y, eps, `${what} y`);
};

// A canvas of 900 CSS px at (10, 20): 1.5 CSS px per board px.
const mappingFor = (side) => new ScreenMapping(10, 20, 1.5, 600, turnsForSide(side));
const screenOf = (x, y) => ({ x: 10 + 1.5 * x, y: 20 + 1.5 * y });

// ---- the turned view ----

test('every seat sees its own baseline at the bottom, its striker where the bottom one is', () => {
  for (const side of SIDES) {
    const m = mappingFor(side);
    for (const along of [113, 200, 300, 487]) {
      // The middle of the own baseline is the bottom middle of the screen; the rest of it lies
      // on the screen's bottom baseline too.
      const p = m.toScreen(strikerAt(side, along));
      near(p.y, screenOf(0, 520).y, 1e-9, `${side} ${along}: screen y`);
    }
    nearPoint(m.toScreen(strikerAt(side, 300)), screenOf(300, 520), 1e-9, side);
  }
});

test('the quarter turns: right seat sees board +x downwards, left seat board -x', () => {
  const right = mappingFor('right');
  nearPoint(right.toScreen({ x: 520, y: 300 }), screenOf(300, 520), 1e-9, 'right striker');
  nearPoint(right.toScreen({ x: 300, y: 80 }), screenOf(520, 300), 1e-9, 'top seat on the right');
  nearPoint(right.toScreen({ x: 300, y: 520 }), screenOf(80, 300), 1e-9, 'bottom seat on the left');
  const left = mappingFor('left');
  nearPoint(left.toScreen({ x: 80, y: 300 }), screenOf(300, 520), 1e-9, 'left striker');
  nearPoint(left.toScreen({ x: 300, y: 520 }), screenOf(520, 300), 1e-9, 'bottom seat on the right');
  nearPoint(left.toScreen({ x: 520, y: 300 }), screenOf(300, 80), 1e-9, 'partner (right) across');
  const top = mappingFor('top');
  nearPoint(top.toScreen({ x: 300, y: 80 }), screenOf(300, 520), 1e-9, 'top striker');
  assert.equal(top.flipped, true);
  assert.equal(right.flipped, false);
});

test('board -> screen -> board is the identity for every turn, and directions follow points', () => {
  for (const side of SIDES) {
    const m = mappingFor(side);
    for (const p of [{ x: 0, y: 0 }, { x: 123, y: 456 }, { x: 600, y: 17.5 }]) {
      nearPoint(m.toBoard(m.toScreen(p)), p, 1e-9, side);
      const q = m.toScreen(p);
      const d = { x: 3, y: -7 };
      const moved = m.toBoard({ x: q.x + d.x, y: q.y + d.y });
      const dir = m.directionToBoard(d);
      nearPoint({ x: (moved.x - p.x) * 1.5, y: (moved.y - p.y) * 1.5 }, dir, 1e-9, `${side} direction`);
    }
  }
});

test('the seats keep their anticlockwise order on every screen: the next seat is on the right', () => {
  const expected = {
    bottom: { bottom: 'bottom', right: 'right', top: 'top', left: 'left' },
    right: { bottom: 'left', right: 'bottom', top: 'right', left: 'top' },
    top: { bottom: 'top', right: 'left', top: 'bottom', left: 'right' },
    left: { bottom: 'right', right: 'top', top: 'left', left: 'bottom' },
  };
  for (const own of SIDES) {
    for (const seat of SIDES) {
      assert.equal(screenSide(seat, turnsForSide(own)), expected[own][seat], `${seat} seen from ${own}`);
      // The panel side agrees with where the mapping draws that seat's striker.
      const m = mappingFor(own);
      const p = m.toScreen(strikerAt(seat, 300));
      const at = p.y > screenOf(0, 500).y ? 'bottom' : p.y < screenOf(0, 100).y ? 'top'
        : p.x > screenOf(500, 0).x ? 'right' : 'left';
      assert.equal(at, expected[own][seat], `${seat}'s striker seen from ${own}`);
    }
  }
  assert.equal(turnsForSide('nowhere'), 0);
});

// ---- aiming from a side baseline ----

test('a right seat slides along board y and pulls back towards the frame to shoot into the board', () => {
  const aim = new AimController();
  aim.beginTurn('right', 200);
  assert.deepEqual(aim.striker(), { x: 520, y: 200 });
  // A press on the baseline band, away from the striker, slides it along y.
  aim.pointerDown({ x: 530, y: 350 }, []);
  assert.equal(aim.phase, 'sliding');
  assert.equal(aim.x, 350);
  aim.pointerMove({ x: 560, y: 590 }, []);
  assert.equal(aim.x, 487, 'clamped to the legal range');
  aim.pointerUp({ x: 560, y: 590 }, []);
  aim.setX(260, []);
  // Pulled back towards the right frame (board +x): the shot goes to board -x, angle pi.
  aim.pointerDown({ x: 520, y: 260 }, []);
  assert.equal(aim.phase, 'pulling');
  const shot = aim.pointerUp({ x: 606, y: 260 }, []);
  near(Math.abs(shot.angle), Math.PI, 1e-12, 'angle');
  near(shot.power, 12.5, 1e-9, 'power');
  assert.equal(shot.x, 260, 'x on the wire is the position along the baseline (board y)');
});

test('a left seat: presses far across the baseline do nothing, an overlap is illegal', () => {
  const aim = new AimController();
  aim.beginTurn('left', 300);
  assert.deepEqual(aim.striker(), { x: 80, y: 300 });
  aim.pointerDown({ x: 300, y: 200 }, []);
  assert.equal(aim.phase, 'idle', 'the middle of the board is no slide');
  const coin = [{ id: 3, kind: 'white', x: 80, y: 250, pocketed: false }];
  aim.pointerDown({ x: 70, y: 240 }, coin);
  assert.equal(aim.phase, 'sliding');
  assert.equal(aim.placement.legal, false);
  assert.equal(aim.placement.blockingId, 3);
  assert.equal(aim.pointerUp({ x: 70, y: 240 }, coin), null);
  // Pull towards the left frame and down the board: the shot goes up and right.
  aim.setX(400, []);
  aim.pointerDown({ x: 80, y: 400 }, []);
  const shot = aim.pointerUp({ x: 80 - 60, y: 400 + 60 }, []);
  near(shot.angle, -Math.PI / 4, 1e-12, 'angle');
  assert.equal(shot.x, 400);
});

test('the arrow keys move the striker right on the screen for every seat', () => {
  for (const side of SIDES) {
    const m = mappingFor(side);
    const aim = new AimController();
    aim.beginTurn(side, 300);
    const before = m.toScreen(aim.striker());
    // What the page does for ArrowRight: the screen's +x as a step along the own baseline.
    const dir = alongOf(side, m.directionToBoard({ x: 1, y: 0 }));
    aim.nudge(dir, true, []);
    const after = m.toScreen(aim.striker());
    near(after.x - before.x, 10 * 1.5, 1e-9, `${side}: screen x step`);
    near(after.y - before.y, 0, 1e-9, `${side}: screen y step`);
  }
});

// ---- protocol ----

test('doubles requests: seats 4 sent only for doubles, three bots by default', () => {
  assert.deepEqual(proto.createRoom('icf', {}, 'easy', 4),
    { type: 'create_room', rule_set: 'icf', seats: 4, bot: { level: 'easy' } });
  assert.deepEqual(proto.createRoom('icf', {}, null, 4), { type: 'create_room', rule_set: 'icf', seats: 4 });
  assert.deepEqual(proto.createRoom('icf', {}, 'easy', 2), { type: 'create_room', rule_set: 'icf', bot: { level: 'easy' } });
  assert.deepEqual(proto.quickMatch('seed', 4), { type: 'quick_match', rule_set: 'seed', seats: 4 });
  assert.deepEqual(proto.quickMatch('seed'), { type: 'quick_match', rule_set: 'seed' });
});

function seatJson(name, baseline, extra = {}) {
  return { occupied: true, name, connected: true, bot: false, colour: 'none', baseline, ...extra };
}

function doublesState(extra = {}) {
  return {
    type: 'room_state', code: 'K7M2QX', you: 1, rule_set: 'icf',
    options: { target_points: 25, boards: 8, shot_clock_s: 0 },
    seats: [
      seatJson('Asha', 'bottom', { team: 0, colour: 'white' }),
      seatJson('Ravi', 'right', { team: 1, colour: 'black' }),
      seatJson('Chitra', 'top', { team: 0, colour: 'white', bot: true }),
      seatJson('Dev', 'left', { team: 1, colour: 'black', connected: false }),
    ],
    spectators: 1, scores: [3, 5, 3, 5], dues: [0, 1, 0, 1], board_number: 1, turn: 4, to_play: 3,
    server_time_ms: 1000000000, phase: 'aiming', queen: { state: 'on_board', seat: -1 }, winner: -1,
    bodies: [{ id: 0, kind: 'queen', x: 300, y: 300, vx: 0, vy: 0, pocketed: false }],
    ...extra,
  };
}

test('the decoder reads four seats on four baselines with their teams', () => {
  const ok = proto.decodeServer(JSON.stringify(doublesState()));
  assert.ok(ok.message, ok.error);
  assert.deepEqual(ok.message.seats.map((s) => [s.baseline, s.team]),
    [['bottom', 0], ['right', 1], ['top', 0], ['left', 1]]);
  // An older server sends no team: seat % 2 in doubles, the seat in singles.
  const old = doublesState();
  old.seats.forEach((s) => { delete s.team; });
  assert.deepEqual(proto.decodeServer(JSON.stringify(old)).message.seats.map((s) => s.team), [0, 1, 0, 1]);
  const singles = doublesState({ seats: [seatJson('Asha', 'bottom'), seatJson('Ravi', 'top')] });
  assert.deepEqual(proto.decodeServer(JSON.stringify(singles)).message.seats.map((s) => s.team), [0, 1]);
});

test('the decoder refuses three seats, an unknown baseline and a bad team', () => {
  const three = doublesState();
  three.seats.pop();
  assert.equal(proto.decodeServer(JSON.stringify(three)).error,
    "room_state: field 'seats' must be an array of 2 or 4 seats");
  const middle = doublesState();
  middle.seats[1].baseline = 'middle';
  assert.equal(proto.decodeServer(JSON.stringify(middle)).error,
    "room_state: field 'seats[1].baseline' must be bottom, right, top or left");
  const team = doublesState();
  team.seats[2].team = 4;
  assert.equal(proto.decodeServer(JSON.stringify(team)).error,
    "room_state: field 'seats[2].team' must be a team number");
});

// ---- seat panels and teams ----

function viewOf(state) {
  const m = new MatchModel();
  m.handle(proto.decodeServer(JSON.stringify(state)).message, 10);
  return m;
}

test('the right seat: own panel at the bottom, partner across at the top, opponents at the sides', () => {
  const m = viewOf(doublesState());
  assert.equal(m.viewTurns(), 1);
  assert.equal(m.doubles(), true);
  const panels = seatPanels(m.view);
  const at = Object.fromEntries(panels.map((p) => [p.at, p]));
  assert.deepEqual([at.bottom.seat, at.right.seat, at.top.seat, at.left.seat], [1, 2, 3, 0]);
  assert.deepEqual([at.bottom.tag, at.top.tag, at.left.tag, at.right.tag], ['you', 'partner', 'opponent', 'opponent']);
  assert.equal(at.top.name, 'Dev');
  assert.equal(at.top.away, true, 'Dev is away');
  assert.equal(at.right.bot, true, 'Chitra is a bot');
  assert.equal(at.top.toPlay, true, 'seat 3 plays');
  assert.equal(panels.filter((p) => p.toPlay).length, 1);
  // Partners show the same team score and dues.
  assert.deepEqual(panels.map((p) => [p.score, p.dues]), [[3, 0], [5, 1], [3, 0], [5, 1]]);
  assert.deepEqual(panels.map((p) => p.colour), ['white', 'black', 'white', 'black']);
});

test('the left seat and a spectator', () => {
  const left = seatPanels(viewOf(doublesState({ you: 3 })).view);
  assert.deepEqual(left.map((p) => p.at), ['right', 'top', 'left', 'bottom']);
  assert.deepEqual(left.map((p) => p.tag), ['opponent', 'partner', 'opponent', 'you']);
  const m = viewOf(doublesState({ you: -1 }));
  assert.equal(m.viewTurns(), 0, "a spectator sees seat 0's view");
  const watched = seatPanels(m.view);
  assert.deepEqual(watched.map((p) => p.at), ['bottom', 'right', 'top', 'left']);
  assert.deepEqual(watched.map((p) => p.tag), ['team 1', 'team 2', 'team 1', 'team 2']);
});

test('teams: ours first with both names, the shared score, whose turn and free seats', () => {
  const m = viewOf(doublesState());
  const [ours, theirs] = teamSummaries(m.view);
  assert.deepEqual([ours.team, ours.names, ours.ours, ours.score, ours.dues, ours.toPlay],
    [1, 'Ravi & Dev', true, 5, 1, true]);
  assert.deepEqual([theirs.team, theirs.names, theirs.ours, theirs.score, theirs.toPlay],
    [0, 'Asha & Chitra', false, 3, false]);
  const spectator = teamSummaries(viewOf(doublesState({ you: -1 })).view);
  assert.deepEqual(spectator.map((t) => t.team), [0, 1]);
  const waiting = doublesState({ phase: 'waiting', you: 0 });
  waiting.seats[1] = { ...waiting.seats[1], occupied: false, name: '' };
  waiting.seats[3] = { ...waiting.seats[3], occupied: false, name: '' };
  const w = viewOf(waiting);
  assert.equal(freeSeats(w.view), 2);
  assert.equal(teamSummaries(w.view)[1].free, 2);
  assert.equal(seatPanels(w.view)[1].name, 'Free seat');
  assert.equal(teamSummaries(w.view)[1].names, '');
  assert.equal(viewTurns(w.view), 0);
});

// ---- the model's words for teams ----

test('a due is the team\'s: both partners owe it', () => {
  const m = viewOf(doublesState({ you: 0, dues: [0, 0, 0, 0] }));
  m.handle({ type: 'event', kind: 'due', seat: 3, owed: 2 }, 11);
  assert.deepEqual(m.view.seats.map((s) => s.dues), [0, 2, 0, 2]);
  assert.equal(m.log.lines[m.log.lines.length - 1].text,
    'Ravi & Dev owe 2 dues: the next coins they pocket go back to the centre');
});

test('the server\'s due per seat of a team makes one line per stroke', () => {
  const m = viewOf(doublesState({ you: 0, dues: [0, 0, 0, 0] }));
  const lines = () => m.log.lines.filter((l) => l.tone === 'foul').map((l) => l.text);
  m.handle({ type: 'event', kind: 'due', seat: 1, owed: 1 }, 11);
  m.handle({ type: 'event', kind: 'due', seat: 3, owed: 1 }, 11);
  const one = 'Ravi & Dev owe 1 due: the next coin they pocket goes back to the centre';
  const two = (who) => `${who} owe 2 dues: the next coins they pocket go back to the centre`;
  assert.deepEqual(lines(), [one]);
  m.handle({ type: 'event', kind: 'due', seat: 1, owed: 2 }, 11); // another count: a line
  m.handle({
    type: 'shot_result', turn: 7, seat: 1, x: 300, angle: 0, power: 5, pocketed: [], returned: [],
    fouls: [], points: [0, 0, 0, 0], scores: [0, 0, 0, 0], dues: [0, 2, 0, 2],
    queen: { state: 'on_board', seat: -1 }, extra_turn: false, next_turn: 8, next_seat: 2,
    board_over: false, game_over: false, winner: -1,
  }, 12);
  m.handle({ type: 'event', kind: 'due', seat: 3, owed: 2 }, 12); // another stroke: a line
  m.handle({ type: 'event', kind: 'due', seat: 0, owed: 2 }, 12); // the other team: a line
  // Said again in the next stroke: the line still shown moves to the newest place (no line twice).
  assert.deepEqual(lines(), [one, two('Ravi & Dev'), two('Asha & Chitra')]);
  assert.equal(m.log.lines.find((l) => l.text === two('Ravi & Dev')).posted, 12);
  assert.deepEqual(m.view.seats.map((s) => s.dues), [2, 2, 2, 2]);
});

test('the game over names the winning team; a board end too', () => {
  const m = viewOf(doublesState({ you: 0 }));
  m.handle({ type: 'event', kind: 'board_end', board: 1, winner: 1, points: 3, scores: [0, 3, 0, 3] }, 11);
  assert.ok(m.log.lines.some((l) => l.text === 'Board 1 to Ravi & Dev (+3)'), m.log.lines.map((l) => l.text).join('|'));
  m.handle({ type: 'event', kind: 'game_end', winner: 1, reason: 'score', scores: [0, 25, 0, 25] }, 12);
  assert.equal(m.view.gameEnd.sentence, 'Ravi & Dev win the game (target score reached)');
  assert.ok(!m.log.lines.some((l) => l.text === m.view.gameEnd.sentence), 'the result panel says it, no HUD line');
  assert.deepEqual(m.view.seats.map((s) => s.score), [0, 25, 0, 25]);
  const partner = viewOf(doublesState({ you: 3 }));
  partner.handle({ type: 'event', kind: 'game_end', winner: 1, reason: 'left', scores: [0, 9, 0, 9] }, 12);
  assert.equal(partner.view.gameEnd.sentence, 'Your team wins the game (a player of the other team left)');
  assert.equal(gameEndSentence(0, false, 'Asha & Chitra', 'clock', true, true),
    'Asha & Chitra win the game (the other team ran out of time)');
  // Singles words are unchanged.
  assert.equal(gameEndSentence(1, false, 'Ravi', 'left'), 'Ravi wins the game (the opponent left)');
});
