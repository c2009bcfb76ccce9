// The lobby (client/app/lobby_view.cpp, as an HTML form over the board): the player's name
// (kept in localStorage), a rule set, singles or doubles and match options for a new room, a
// server bot of a chosen level (three of them in doubles), quick match, and a room code to join
// or watch. It hands the app a checked request; it
// never talks to the server itself.

import {
  clipName, isPlayerName, isRoomCode, normaliseRoomCode, RULE_SETS, BOT_LEVELS,
} from './protocol.js';
import { PROTOCOL } from './physics_config.js';

// The new-game buttons' labels for singles and doubles.
const LABELS = {
  2: { create: 'Create room', quick: 'Quick match', 'play-bot': 'Play a bot' },
  4: { create: 'Create doubles', quick: 'Quick match doubles', 'play-bot': 'Play bots (doubles)' },
};

const $ = (id) => document.getElementById(id);

// The lobby's whole-number match options and the range create_room accepts for each
// (proto/include/carrom/proto/limits.hpp; the maxima through physics_config.js).
export const OPTION_RANGES = Object.freeze({
  targetPoints: Object.freeze([1, PROTOCOL.maxTargetPoints]),
  boards: Object.freeze([1, PROTOCOL.maxBoards]),
  shotClock: Object.freeze([0, PROTOCOL.maxShotClockS]),
});

// The lobby's answer to a missing name (the protocol counts UTF-8 bytes: an accented letter
// takes two of the 24).
export function nameMissingSentence() {
  return `Type your name first: 1 to ${PROTOCOL.maxNameBytes} letters (accented letters count twice).`;
}

// Gives the lobby's inputs the protocol's limits (index.html spells none of them): the name's and
// the room code's lengths, the match options' ranges. inputs: {name, code, targetPoints, boards,
// shotClock}, the form's input elements.
export function applyLimits(inputs) {
  inputs.name.maxLength = PROTOCOL.maxNameBytes;
  inputs.code.maxLength = PROTOCOL.roomCodeLength;
  for (const [key, [lo, hi]] of Object.entries(OPTION_RANGES)) {
    inputs[key].min = String(lo);
    inputs[key].max = String(hi);
  }
}

// Reads an optional whole number in [lo, hi] from an input; '' when empty, null when invalid.
function optionalInt(input, lo, hi) {
  const text = input.value.trim();
  if (text === '') return '';
  const n = Number(text);
  return Number.isInteger(n) && n >= lo && n <= hi ? n : null;
}

export class Lobby {
  // onRequest(name, request): request is {kind, ruleSet, options, bot, seats, code}.
  constructor(storage, onRequest) {
    this.storage = storage;
    this.onRequest = onRequest;
    this.form = $('lobby');
    this.name = $('name');
    this.ruleSet = $('rule-set');
    this.targetPoints = $('target-points');
    this.boards = $('boards');
    this.shotClock = $('shot-clock');
    this.botLevel = $('bot-level');
    this.seatCount = $('seat-count');
    this.seatCount.addEventListener('change', () => this.labelButtons());
    this.code = $('room-code');
    this.status = $('lobby-status');
    this.error = $('lobby-error');
    applyLimits(this);
    this.name.value = storage?.getItem('carrom.name') ?? '';
    this.form.addEventListener('submit', (e) => {
      e.preventDefault();
      if (e.submitter) this.submit(e.submitter.value);
    });
    // Enter: join the code when one is typed, else create a room.
    this.form.addEventListener('keydown', (e) => {
      if (e.key !== 'Enter' || e.target.tagName !== 'INPUT') return;
      e.preventDefault();
      this.submit(this.code.value ? 'join' : 'create');
    });
    this.code.addEventListener('input', () => {
      const c = normaliseRoomCode(this.code.value);
      if (c !== this.code.value) this.code.value = c;
    });
    this.labelButtons();
    this.name.addEventListener('input', () => {
      const n = clipName(this.name.value);
      if (n !== this.name.value) this.name.value = n;
    });
  }

  // 2 (singles) or 4 (doubles), as chosen.
  seats() {
    return this.seatCount.value === '4' ? 4 : 2;
  }

  labelButtons() {
    for (const [id, text] of Object.entries(LABELS[this.seats()])) {
      if ($(id).textContent !== text) $(id).textContent = text;
    }
  }

  storedName() {
    const n = this.name.value.trim();
    return isPlayerName(n) ? n : '';
  }

  show(visible) {
    if (this.form.hidden === visible) this.form.hidden = !visible;
  }

  visible() {
    return !this.form.hidden;
  }

  setStatus(text) {
    if (this.status.textContent !== text) this.status.textContent = text;
  }

  setError(text) {
    if (this.error.textContent !== text) this.error.textContent = text;
  }

  setBusy(busy) {
    if (this.busy === busy) return;
    this.busy = busy;
    for (const b of this.form.querySelectorAll('button:not(#lobby-cancel)')) b.disabled = busy;
  }

  // A room link was opened: the code is filled in, the friend's room comes first and its button
  // is the main one.
  offerRoom(code, watch) {
    this.code.value = code;
    $('lobby-title').textContent = watch ? `Watch room ${code}` : `Join room ${code}`;
    const friend = $('friend-room');
    friend.parentNode.insertBefore(friend, $('new-game'));
    $('join').classList.toggle('primary', !watch);
    $('watch').classList.toggle('primary', watch);
  }

  submit(action) {
    const name = this.name.value.trim();
    if (!isPlayerName(name)) {
      this.setError(nameMissingSentence());
      this.name.focus();
      return;
    }
    this.storage?.setItem('carrom.name', name);
    const ruleSet = RULE_SETS.includes(this.ruleSet.value) ? this.ruleSet.value : 'icf';
    const options = {
      target_points: optionalInt(this.targetPoints, ...OPTION_RANGES.targetPoints),
      boards: optionalInt(this.boards, ...OPTION_RANGES.boards),
      shot_clock_s: optionalInt(this.shotClock, ...OPTION_RANGES.shotClock),
    };
    let request;
    if (action === 'create' || action === 'bot') {
      for (const [key, value] of Object.entries(options)) {
        if (value === null) {
          this.setError(`The ${key.replace(/_s$/, '').replace('_', ' ')} is out of range.`);
          return;
        }
      }
      const level = BOT_LEVELS.includes(this.botLevel.value) ? this.botLevel.value : 'medium';
      request = {
        kind: 'create', ruleSet, options, bot: action === 'bot' ? level : null, seats: this.seats(),
      };
    } else if (action === 'quick') {
      request = { kind: 'quick', ruleSet, seats: this.seats() };
    } else {
      const code = normaliseRoomCode(this.code.value);
      if (!isRoomCode(code)) {
        this.setError('A room code has 6 letters and digits, as shown in the room.');
        this.code.focus();
        return;
      }
      request = { kind: action === 'watch' ? 'spectate' : 'join', code };
    }
    this.setError('');
    this.onRequest(name, request);
  }
}
