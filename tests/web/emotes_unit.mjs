// The page's emotes without a browser: the fixed set (the protocol's names, in its order), the
// decoder's checks of the "emote" event, what EmoteBoard shows and hides, and the match model
// taking the event.
import assert from 'node:assert/strict';
import test from 'node:test';

import { EMOTE_IDS, EMOTE_SHOW_S, EmoteBoard, emoteText } from '../../web/js/emotes.js';
import { MatchModel } from '../../web/js/match_model.js';
import * as proto from '../../web/js/protocol.js';

const event = (fields) => JSON.stringify({ type: 'event', kind: 'emote', ...fields });

test('the set is the protocol\'s, in its order', () => {
  assert.deepEqual(EMOTE_IDS, ['nice_shot', 'good_game', 'well_played', 'thanks', 'good_luck',
    'oops', 'wow', 'sorry']);
});

test('every emote has words', () => {
  for (const id of EMOTE_IDS) assert.ok(emoteText(id).length > 0, id);
  assert.equal(emoteText('nice_shot'), 'Nice shot!');
  assert.equal(emoteText('boo'), '');
});

test('the client message', () => {
  assert.deepEqual(proto.emote('wow'), { type: 'emote', emote: 'wow' });
});

test('a known emote event decodes', () => {
  const d = proto.decodeServer(event({ seat: 1, emote: 'thanks' }));
  assert.equal(d.error, undefined);
  assert.equal(d.message.emote, 'thanks');
});

test('an unknown emote name is refused', () => {
  assert.match(proto.decodeServer(event({ seat: 1, emote: 'boo' })).error, /emote/);
});

test('an emote event without a seat is refused', () => {
  assert.match(proto.decodeServer(event({ emote: 'wow' })).error, /seat/);
});

test('an emote shows for its time, then not', () => {
  const b = new EmoteBoard();
  assert.equal(b.receive(1, 'wow', 10), true);
  assert.deepEqual(b.visible(10), [{ seat: 1, id: 'wow', text: 'Wow!' }]);
  assert.deepEqual(b.visible(10 + EMOTE_SHOW_S - 0.001).length, 1);
  assert.deepEqual(b.visible(10 + EMOTE_SHOW_S), []);
});

test('a newer emote of the same seat replaces the older one', () => {
  const b = new EmoteBoard();
  b.receive(0, 'wow', 10);
  b.receive(0, 'oops', 11);
  assert.deepEqual(b.visible(11).map((e) => e.id), ['oops']);
});

test('visible lists seats in order', () => {
  const b = new EmoteBoard();
  b.receive(3, 'wow', 10);
  b.receive(1, 'oops', 10);
  assert.deepEqual(b.visible(10).map((e) => e.seat), [1, 3]);
});

test('a muted seat shows nothing and says so', () => {
  const b = new EmoteBoard();
  b.setMuted(1, true);
  assert.equal(b.receive(1, 'wow', 10), false);
  assert.deepEqual(b.visible(10), []);
  assert.equal(b.received, 1);
});

test('muting hides what a seat shows now; others stay', () => {
  const b = new EmoteBoard();
  b.receive(1, 'wow', 10);
  b.receive(2, 'oops', 10);
  b.setMuted(1, true);
  assert.deepEqual(b.visible(10).map((e) => e.seat), [2]);
});

test('unmuting shows the next emote', () => {
  const b = new EmoteBoard();
  b.setMuted(1, true);
  b.setMuted(1, false);
  assert.equal(b.receive(1, 'wow', 10), true);
});

test('mute all covers every seat, later ones too', () => {
  const b = new EmoteBoard();
  b.receive(0, 'wow', 10);
  b.setAllMuted(true);
  assert.deepEqual(b.visible(10), []);
  assert.equal(b.receive(3, 'wow', 11), false);
  b.setAllMuted(false);
  assert.equal(b.receive(3, 'wow', 12), true);
});

test('the match model shows an emote event, and a new room clears it but keeps the mutes', () => {
  const m = new MatchModel();
  m.emotes.setMuted(2, true);
  m.handle({ type: 'event', kind: 'emote', seat: 1, emote: 'good_game' }, 5);
  assert.deepEqual(m.emotes.visible(5), [{ seat: 1, id: 'good_game', text: 'Good game!' }]);
  m.reset();
  assert.deepEqual(m.emotes.visible(5), []);
  assert.equal(m.emotes.isMuted(2), true);
});

test('room_state\'s aim_assist: absent reads as on, a non-boolean is refused', () => {
  const room = {
    type: 'room_state', code: 'ABC234', you: 0, rule_set: 'icf', options: {},
    seats: [0, 1].map(() => ({ occupied: true, name: 'A', connected: true, bot: false, colour: 'white', baseline: 'bottom' })),
    spectators: 0, scores: [0, 0], dues: [0, 0], board_number: 1, turn: 0, to_play: 0,
    server_time_ms: 1, phase: 'aiming', queen: { state: 'on_board', seat: -1 }, winner: -1, bodies: [],
  };
  const absent = proto.decodeServer(JSON.stringify(room));
  assert.equal(absent.error, undefined, absent.error);
  assert.equal(absent.message.aim_assist, true);
  assert.equal(proto.decodeServer(JSON.stringify({ ...room, aim_assist: false })).message.aim_assist, false);
  assert.match(proto.decodeServer(JSON.stringify({ ...room, aim_assist: 1 })).error, /aim_assist/);
});
