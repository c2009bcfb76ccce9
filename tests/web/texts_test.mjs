// What a player reads in the page's pure modules under node (issue: a first game that teaches):
// a foul in the warning colour with what it cost, the missed shot clock's count, the forfeit
// line, the board summary card, the game over from the reader's side, the shot clock's
// countdown ticks, the HUD's target and coins left.
import assert from 'node:assert/strict';
import test from 'node:test';

import { boardSummaryText } from '../../web/js/board_summary_text.js';
import { gameOverText } from '../../web/js/game_over_text.js';
import { MatchModel } from '../../web/js/match_model.js';
import { coinsLeftText, targetWords } from '../../web/js/plain_words.js';
import * as proto from '../../web/js/protocol.js';

const seat = (name, baseline, extra = {}) => ({
  occupied: true, name, connected: true, bot: false, colour: 'none', baseline, ...extra,
});

function singles(extra = {}) {
  return {
    type: 'room_state', code: 'K7M2QX', you: 0, rule_set: 'icf',
    options: { target_points: 25, boards: 8, shot_clock_s: 20 },
    seats: [seat('Asha', 'bottom', { colour: 'white' }), seat('Ravi', 'top', { colour: 'black', bot: true })],
    spectators: 0, scores: [0, 0], dues: [0, 0], board_number: 1, turn: 4, to_play: 0,
    server_time_ms: 1000000000, phase: 'aiming', queen: { state: 'on_board', seat: -1 }, winner: -1,
    bodies: [
      { id: 0, kind: 'queen', x: 300, y: 300, vx: 0, vy: 0, pocketed: false },
      { id: 1, kind: 'white', x: 320, y: 300, vx: 0, vy: 0, pocketed: false },
      { id: 2, kind: 'white', x: 280, y: 300, vx: 0, vy: 0, pocketed: false },
      { id: 10, kind: 'black', x: 300, y: 320, vx: 0, vy: 0, pocketed: false },
      { id: 19, kind: 'striker', x: 300, y: 520, vx: 0, vy: 0, pocketed: false },
    ],
    ...extra,
  };
}

function modelOf(state) {
  const m = new MatchModel();
  const decoded = proto.decodeServer(JSON.stringify(state));
  assert.ok(decoded.message, decoded.error);
  m.handle(decoded.message, 10);
  return m;
}

function shotResult(extra) {
  return {
    type: 'shot_result', turn: 4, seat: 0, x: 300, angle: -1.57, power: 5, pocketed: [], returned: [],
    fouls: [], points: [0, 0], scores: [0, 0], dues: [0, 0], queen: { state: 'on_board', seat: -1 },
    extra_turn: false, next_turn: 5, next_seat: 1, board_over: false, game_over: false, winner: -1,
    ...extra,
  };
}

const handle = (m, message, t = 11) => {
  const decoded = proto.decodeServer(JSON.stringify(message));
  assert.ok(decoded.message, decoded.error);
  m.handle(decoded.message, t);
};
const lines = (m) => m.log.lines.filter((l) => !/^(Joined|Watching) room/.test(l.text)).map((l) => [l.text, l.tone]);

test('a clean pocketing is good news', () => {
  const m = modelOf(singles());
  handle(m, shotResult({ pocketed: [1], extra_turn: true, next_seat: 0 }));
  assert.deepEqual(lines(m), [['Asha pocketed 1 white coin', 'good'], ['Asha plays again', 'info']]);
});

test('a foul is a warning and says what it cost', () => {
  const m = modelOf(singles());
  handle(m, shotResult({
    pocketed: [1, 19], returned: [1, 2],
    fouls: [{ rule: 'striker_pocketed', message: 'The striker went into a pocket.' }],
  }));
  handle(m, { type: 'event', kind: 'foul', seat: 0, rule: 'striker_pocketed', message: 'The striker went into a pocket.' });
  handle(m, { type: 'event', kind: 'due', seat: 0, owed: 1 });
  assert.deepEqual(lines(m), [
    ['Asha pocketed 1 white coin and the striker', 'foul'],
    ['Foul by Asha: The striker went into a pocket.', 'foul'],
    ['Cost: 2 white coins back to the centre', 'foul'],
    ['Asha owes 1 due: the next coin Asha pockets goes back to the centre', 'foul'],
  ]);
  assert.ok(!m.log.lines.some((l) => l.tone === 'good'), 'no foul line in the good-news colour');
});

test('a missed shot clock says how many more misses lose the game', () => {
  const m = modelOf(singles());
  const message = 'The shot clock ran out; the turn passes. 2 more missed turns in a row lose the game.';
  handle(m, shotResult({ fouls: [{ rule: 'shot_clock_expired', message }] }));
  assert.deepEqual(lines(m), [[`Foul by Asha: ${message}`, 'foul']]);
});

test('freestyle: a stroke names its points, a foul its lost points, the board end no "+0"', () => {
  const m = modelOf(singles({
    rule_set: 'freestyle', options: { target_points: 40, boards: 8, shot_clock_s: 20 },
    seats: [seat('Asha', 'bottom'), seat('Ravi', 'top', { bot: true })],
  }));
  handle(m, shotResult({ pocketed: [1], points: [20, 0], extra_turn: true, next_seat: 0 }));
  assert.deepEqual(lines(m).map(([text]) => text), ['Asha pocketed 1 white coin (+20)', 'Asha plays again']);
  m.log.lines = [];
  handle(m, shotResult({
    turn: 5, pocketed: [19], points: [-10, 0],
    fouls: [{ rule: 'striker_pocketed', message: 'The striker went into a pocket.' }],
  }));
  handle(m, { type: 'event', kind: 'board_end', board: 1, winner: 1, points: 0, scores: [10, 40] });
  const said = lines(m).map(([text]) => text);
  assert.deepEqual(said, ['Asha pocketed the striker (-10)', 'Foul by Asha: The striker went into a pocket.', 'Cost: 10 points',
    'Board 1 to Ravi']);
  assert.equal(targetWords('freestyle', 40), 'first to 40 points');
  assert.equal(coinsLeftText({ white: 5, black: 7, queen: 1 }, 'freestyle', 'none'), '12 coins + queen left');
});

test('a leave names who left and who wins, from the reader\'s side', () => {
  for (const [you, text, tone] of [
    [1, 'Asha left the match: you win by forfeit', 'good'],
    [-1, 'Asha left the match: Ravi wins by forfeit', 'info'],
  ]) {
    const m = modelOf(singles({ you }));
    handle(m, shotResult({ fouls: [{ rule: 'forfeit', message: 'A player forfeited.' }], game_over: true, winner: 1 }));
    handle(m, { type: 'event', kind: 'game_end', winner: 1, reason: 'left', scores: [0, 0], rule: 'forfeit' });
    assert.deepEqual(lines(m), [[text, tone]]);
  }
  const late = modelOf(singles());
  handle(late, shotResult({ seat: 1, fouls: [{ rule: 'forfeit', message: 'A player forfeited.' }], game_over: true, winner: 0 }));
  handle(late, { type: 'event', kind: 'game_end', winner: 0, reason: 'forfeit', scores: [0, 0], rule: 'forfeit' });
  assert.deepEqual(lines(late), [['Ravi did not come back in time: you win by forfeit', 'good']]);
});

test('the game over from the loser\'s and the winner\'s side, with the score', () => {
  const m = modelOf(singles());
  handle(m, { type: 'event', kind: 'game_end', winner: 1, reason: 'clock', scores: [0, 3], rule: 'missed_turns' });
  assert.deepEqual(gameOverText(m.view, false), {
    title: 'You lost', reason: 'You let the shot clock run out three times in a row.',
    score: 'Final score: Asha 0, Ravi 3', canRematch: true, opponentLeft: false, waiting: '',
  });
  const w = modelOf(singles({ you: 1 }));
  handle(w, { type: 'event', kind: 'game_end', winner: 1, reason: 'clock', scores: [0, 3], rule: 'missed_turns' });
  const won = gameOverText(w.view, false);
  assert.deepEqual([won.title, won.reason, won.score],
    ['You won!', 'Asha let the shot clock run out three times in a row.', 'Final score: Ravi 3, Asha 0']);
  assert.equal(gameOverText(w.view, true).waiting, 'Waiting for Asha to agree to a rematch');
});

test('no rematch once the opponent left the room', () => {
  const m = modelOf(singles({ you: 1 }));
  handle(m, { type: 'event', kind: 'game_end', winner: 1, reason: 'left', scores: [0, 0], rule: 'forfeit' });
  // Already before the room state that frees the seat.
  assert.equal(gameOverText(m.view, false).canRematch, false);
  handle(m, singles({ you: 1, phase: 'game_over', winner: 1, seats: [
    { occupied: false, name: '', connected: false, bot: false, colour: 'none', baseline: 'bottom' },
    seat('Ravi', 'top', { colour: 'black' })] }));
  const t = gameOverText(m.view, false);
  assert.deepEqual([t.title, t.reason, t.canRematch, t.opponentLeft, t.waiting],
    ['You won!', 'Asha left the game.', false, true, 'Your opponent left the room: no rematch']);
});

test('a board summary before the next board: winner, points, score, the new colour', () => {
  const m = modelOf(singles());
  handle(m, { type: 'event', kind: 'board_end', board: 1, winner: 1, points: 3, scores: [0, 3] }, 20);
  handle(m, singles({ board_number: 2, scores: [0, 3], seats: [
    seat('Asha', 'bottom', { colour: 'black' }), seat('Ravi', 'top', { colour: 'white', bot: true })] }), 20);
  assert.equal(m.boardSummaryShown(20), true);
  assert.deepEqual(boardSummaryText(m.view), {
    title: 'Ravi won board 1', points: '+3 points. Score: you 0, Ravi 3', colours: 'Board 2: you play black',
  });
  assert.equal(m.boardSummaryShown(25.9), true);
  assert.equal(m.boardSummaryShown(26.1), false, 'gone after 6 s');
  m.dismissBoardSummary();
  assert.equal(m.boardSummaryShown(21), false, 'dismissed');
  // A board that ends the game: the game-over panel says it, no card.
  const end = modelOf(singles());
  handle(end, { type: 'event', kind: 'board_end', board: 1, winner: 0, points: 25, scores: [25, 0] }, 20);
  handle(end, { type: 'event', kind: 'game_end', winner: 0, reason: 'score', scores: [25, 0] }, 20);
  assert.equal(end.boardSummaryShown(20), false);
});

test('the shot clock ticks once a second in its last 5 s, on our own turn only', () => {
  const m = modelOf(singles({ shot_clock_deadline_ms: 1000000000 + 20000 }));
  // The server's clock at local 10 s is 1e9 ms (room_state's one-way stamp).
  const ticks = [];
  for (let t = 10; t <= 30; t += 0.05) {
    const tick = m.countdownTick(t);
    if (tick !== null) ticks.push(tick);
  }
  assert.deepEqual(ticks, [5, 4, 3, 2, 1]);
  const theirs = modelOf(singles({ to_play: 1, shot_clock_deadline_ms: 1000000000 + 20000 }));
  assert.equal(theirs.countdownTick(27), null);
  assert.equal(targetWords('icf', 25), 'to 25, scored at board end');
  assert.equal(coinsLeftText({ white: 9, black: 9, queen: 1 }, 'icf', 'white'), '9 white + queen left');
});
