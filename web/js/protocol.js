// The wire protocol of docs/protocol.md: client message builders, field limits, and a decoder
// that turns one server text frame into a checked plain object (or a reason why not). The
// decoder checks the fields this client reads, so a malformed frame is reported and ignored
// instead of breaking the page.

import { EMOTE_IDS } from './emotes.js';
import { PHYSICS, PROTOCOL } from './physics_config.js';

// The server's own values (physics_config.js, generated from proto/version.hpp and limits.hpp).
export const PROTOCOL_VERSION = PROTOCOL.version;
export const MAX_NAME_BYTES = PROTOCOL.maxNameBytes;
export const ROOM_CODE_LENGTH = PROTOCOL.roomCodeLength;
export const ROOM_CODE_ALPHABET = PROTOCOL.roomCodeAlphabet;
export const MAX_REDIRECT_URL_BYTES = 2000; // proto::kMaxUrlBytes
export const RULE_SETS = ['icf', 'seed', 'freestyle', 'discpool'];
export const BOT_LEVELS = ['random', 'easy', 'medium', 'hard'];
export const SEAT_COUNTS = [2, 4]; // singles, doubles
export const BASELINES = ['bottom', 'right', 'top', 'left']; // seat order 0..3 in doubles
export const MAX_SERVER_MESSAGE_BYTES = PROTOCOL.maxServerMessageBytes;

const utf8 = new TextEncoder();

// A name the server accepts: 1 to MAX_NAME_BYTES UTF-8 bytes, no control characters, a visible
// character.
export function isPlayerName(name) {
  if (typeof name !== 'string') return false;
  const bytes = utf8.encode(name);
  if (bytes.length === 0 || bytes.length > MAX_NAME_BYTES) return false;
  let visible = false;
  for (const b of bytes) {
    if (b < 0x20 || b === 0x7f) return false;
    visible = visible || b !== 0x20;
  }
  return visible;
}

// Cuts a name to at most MAX_NAME_BYTES UTF-8 bytes without splitting a character.
export function clipName(name) {
  let out = '';
  for (const ch of String(name).replace(/[\u0000-\u001f\u007f]/g, '')) {
    if (utf8.encode(out + ch).length > MAX_NAME_BYTES) break;
    out += ch;
  }
  return out;
}

export function isRoomCode(code) {
  if (typeof code !== 'string' || code.length !== ROOM_CODE_LENGTH) return false;
  for (const ch of code) {
    if (!ROOM_CODE_ALPHABET.includes(ch)) return false;
  }
  return true;
}

// Upper-cases and drops characters that cannot be in a room code.
export function normaliseRoomCode(text) {
  return String(text).toUpperCase().split('').filter((c) => ROOM_CODE_ALPHABET.includes(c))
    .join('').slice(0, ROOM_CODE_LENGTH);
}

export function isResumeToken(token) {
  return typeof token === 'string' && /^[0-9a-f]{32}$/.test(token);
}

// ---- client -> server ----

// identity: the player's key (identity.js); absent: a guest.
// followsRedirects: the client follows a cluster's `redirect` (sent only when true).
export function hello(name, resumeToken, identity, followsRedirects = false) {
  const m = { type: 'hello', version: PROTOCOL_VERSION, name };
  if (resumeToken) m.resume_token = resumeToken;
  if (identity) m.identity = identity;
  if (followsRedirects) m.follows_redirects = true;
  return m;
}

// options: {target_points?, boards?, shot_clock_s?}; bot: level string or null; seats: 2 or 4
// (sent only for doubles: older servers know singles only). In doubles the server's bots take
// every seat but ours (bot.seats left out).
export function createRoom(ruleSet, options = {}, botLevel = null, seats = 2) {
  const m = { type: 'create_room', rule_set: ruleSet };
  if (seats === 4) m.seats = 4;
  const o = {};
  for (const key of ['target_points', 'boards', 'shot_clock_s']) {
    if (options[key] !== undefined && options[key] !== null && options[key] !== '') {
      o[key] = Number(options[key]);
    }
  }
  if (Object.keys(o).length > 0) m.options = o;
  if (botLevel) m.bot = { level: botLevel };
  return m;
}

export function joinRoom(code, asSpectator = false) {
  return { type: 'join_room', code, as: asSpectator ? 'spectator' : 'player' };
}

export function quickMatch(ruleSet, seats = 2) {
  const m = { type: 'quick_match', rule_set: ruleSet };
  if (seats === 4) m.seats = 4;
  return m;
}

export function aim(turn, x) {
  return { type: 'aim', turn, x };
}

export function shoot(turn, x, angle, power) {
  return { type: 'shoot', turn, x, angle, power };
}

export const rematch = () => ({ type: 'rematch' });
export const leave = () => ({ type: 'leave' });
export const ping = (nonce) => ({ type: 'ping', nonce });
// A quick reaction: one of EMOTE_IDS (emotes.js).
export const emote = (id) => ({ type: 'emote', emote: id });

// ---- server -> client ----

class FieldError extends Error {}

function need(cond, path, what) {
  if (!cond) throw new FieldError(`field '${path}' must be ${what}`);
}
const isInt = (v) => Number.isInteger(v);
const isNum = (v) => typeof v === 'number' && Number.isFinite(v);
const isStr = (v) => typeof v === 'string';
const isBool = (v) => typeof v === 'boolean';

function int(o, k, path = k) {
  need(isInt(o[k]), path, 'an integer');
  return o[k];
}
function num(o, k, path = k) {
  need(isNum(o[k]), path, 'a number');
  return o[k];
}
function str(o, k, path = k) {
  need(isStr(o[k]), path, 'a string');
  return o[k];
}
function optInt(o, k) {
  if (o[k] === undefined) return undefined;
  return int(o, k);
}
function optStr(o, k) {
  if (o[k] === undefined) return undefined;
  return str(o, k);
}
function intArray(o, k) {
  need(Array.isArray(o[k]) && o[k].every(isInt), k, 'an array of integers');
  return o[k];
}
function oneOf(o, k, values) {
  need(values.includes(o[k]), k, `one of ${values.join(', ')}`);
  return o[k];
}

// room_state's motion when the server sends none (an older server): the default k
// (common/include/carrom/config.hpp) and only the regular snapshots.
export const DEFAULT_MOTION = Object.freeze({
  damping_per_s: PHYSICS.dampingPerS, contact_snapshots: false,
});

const KINDS = ['black', 'white', 'queen', 'striker'];
const PHASES = ['waiting', 'aiming', 'moving', 'board_over', 'game_over'];
const QUEEN_STATES = ['on_board', 'pending', 'covered', 'none'];

function queen(q, path) {
  need(q !== null && typeof q === 'object', path, 'an object');
  need(QUEEN_STATES.includes(q.state), `${path}.state`, 'a queen state');
  need(isInt(q.seat), `${path}.seat`, 'an integer');
  return { state: q.state, seat: q.seat };
}

function roomState(m) {
  str(m, 'code');
  int(m, 'you');
  oneOf(m, 'rule_set', RULE_SETS);
  need(m.options && typeof m.options === 'object', 'options', 'an object');
  need(Array.isArray(m.seats) && SEAT_COUNTS.includes(m.seats.length), 'seats',
    'an array of 2 or 4 seats');
  const count = m.seats.length;
  m.seats.forEach((s, i) => {
    const p = `seats[${i}]`;
    need(s && typeof s === 'object', p, 'an object');
    need(isBool(s.occupied) && isStr(s.name) && isBool(s.connected) && isBool(s.bot), p,
      'a seat');
    need(['none', 'black', 'white'].includes(s.colour), `${p}.colour`, 'a colour');
    need(BASELINES.includes(s.baseline), `${p}.baseline`, 'bottom, right, top or left');
    // An older server sends no team: the singles team is the seat, doubles' is seat % 2.
    if (s.team === undefined) s.team = count === 4 ? i % 2 : i;
    need(isInt(s.team) && s.team >= 0 && s.team < count, `${p}.team`, 'a team number');
  });
  intArray(m, 'scores');
  intArray(m, 'dues');
  int(m, 'board_number');
  int(m, 'turn');
  int(m, 'to_play');
  optInt(m, 'shot_clock_deadline_ms');
  int(m, 'server_time_ms');
  // Absent (a server before aim assist): allowed.
  if (m.aim_assist === undefined) m.aim_assist = true;
  need(isBool(m.aim_assist), 'aim_assist', 'a boolean');
  oneOf(m, 'phase', PHASES);
  m.queen = queen(m.queen, 'queen');
  int(m, 'winner');
  need(Array.isArray(m.bodies), 'bodies', 'an array');
  m.bodies.forEach((b, i) => {
    const p = `bodies[${i}]`;
    need(b && typeof b === 'object', p, 'an object');
    int(b, 'id', `${p}.id`);
    need(KINDS.includes(b.kind), `${p}.kind`, 'a body kind');
    num(b, 'x', `${p}.x`);
    num(b, 'y', `${p}.y`);
    num(b, 'vx', `${p}.vx`);
    num(b, 'vy', `${p}.vy`);
    need(isBool(b.pocketed), `${p}.pocketed`, 'a boolean');
  });
  if (m.motion === undefined) {
    m.motion = { ...DEFAULT_MOTION };
  } else {
    const o = m.motion;
    need(o !== null && typeof o === 'object' && !Array.isArray(o), 'motion', 'an object');
    need(isNum(o.damping_per_s) && o.damping_per_s >= 0 && o.damping_per_s <= 100,
      'motion.damping_per_s', 'a number in [0, 100]');
    need(isBool(o.contact_snapshots), 'motion.contact_snapshots', 'a boolean');
    m.motion = { damping_per_s: o.damping_per_s, contact_snapshots: o.contact_snapshots };
  }
}

function snapshot(m) {
  int(m, 'seq');
  int(m, 'turn');
  num(m, 't');
  need(isBool(m.keyframe), 'keyframe', 'a boolean');
  need(Array.isArray(m.bodies), 'bodies', 'an array');
  m.bodies.forEach((b, i) => {
    need(Array.isArray(b) && b.length === 5 && isInt(b[0]) && b.slice(1).every(isNum),
      `bodies[${i}]`, '[id, x, y, vx, vy]');
  });
  intArray(m, 'pocketed');
}

const EVENT_FIELDS = {
  collision: (m) => { int(m, 'turn'); num(m, 't'); num(m, 'impulse'); },
  cushion: (m) => { int(m, 'turn'); num(m, 't'); num(m, 'impulse'); },
  pocket: (m) => { int(m, 'turn'); num(m, 't'); int(m, 'body'); },
  foul: (m) => { int(m, 'seat'); str(m, 'rule'); str(m, 'message'); },
  queen: (m) => { m.queen = queen(m.queen, 'queen'); },
  due: (m) => { int(m, 'seat'); int(m, 'owed'); },
  turn: (m) => { int(m, 'turn'); int(m, 'seat'); optInt(m, 'deadline_ms'); int(m, 'server_time_ms'); },
  board_end: (m) => { int(m, 'board'); int(m, 'winner'); int(m, 'points'); intArray(m, 'scores'); },
  game_end: (m) => { int(m, 'winner'); str(m, 'reason'); intArray(m, 'scores'); optStr(m, 'rule'); },
  player_dropped: (m) => { int(m, 'seat'); int(m, 'grace_deadline_ms'); int(m, 'server_time_ms'); },
  player_returned: (m) => { int(m, 'seat'); },
  aim: (m) => { int(m, 'seat'); int(m, 'turn'); num(m, 'x'); },
  emote: (m) => { int(m, 'seat'); need(EMOTE_IDS.includes(m.emote), 'emote', 'a known emote'); },
  paused: (m) => { str(m, 'reason'); str(m, 'message'); },
  resumed: () => {},
};

const SERVER_FIELDS = {
  welcome: (m) => { int(m, 'version'); int(m, 'player_id'); str(m, 'resume_token'); int(m, 'server_time_ms'); },
  room_state: roomState,
  snapshot,
  event: (m) => {
    str(m, 'kind');
    const check = EVENT_FIELDS[m.kind];
    need(check !== undefined, 'kind', 'a known event kind');
    check(m);
  },
  shot_result: (m) => {
    int(m, 'turn'); int(m, 'seat'); intArray(m, 'pocketed'); intArray(m, 'scores');
    intArray(m, 'dues'); m.queen = queen(m.queen, 'queen'); int(m, 'next_turn');
    int(m, 'next_seat'); need(isBool(m.extra_turn), 'extra_turn', 'a boolean');
    need(isBool(m.board_over) && isBool(m.game_over), 'game_over', 'a boolean');
    for (const k of ['returned', 'points', 'fouls']) m[k] ??= []; // absent: none
    intArray(m, 'returned'); intArray(m, 'points');
    need(Array.isArray(m.fouls) && m.fouls.every((f) => f && isStr(f.rule) && isStr(f.message)),
      'fouls', 'an array of {rule, message}');
  },
  error: (m) => { str(m, 'code'); str(m, 'message'); },
  pong: (m) => { int(m, 'nonce'); int(m, 'server_time_ms'); },
  // Another instance of the cluster runs the room or seat (docs/protocol.md, "Redirects").
  redirect: (m) => {
    str(m, 'url');
    need(m.url.length >= 6 && new TextEncoder().encode(m.url).length <= MAX_REDIRECT_URL_BYTES
      && (m.url.startsWith('ws://') || m.url.startsWith('wss://')), 'url',
    `a ws:// or wss:// URL of at most ${MAX_REDIRECT_URL_BYTES} bytes`);
    str(m, 'reason');
    need(m.reason.length > 0, 'reason', 'a reason');
    if (m.code === undefined) return;
    need(isRoomCode(m.code), 'code', 'a room code');
    m.as ??= 'player';
    need(m.as === 'player' || m.as === 'spectator', 'as', 'player or spectator');
  },
};

// Returns {message} or {error: sentence}. Never throws.
export function decodeServer(text) {
  if (typeof text !== 'string') return { error: 'not a text frame' };
  if (text.length > MAX_SERVER_MESSAGE_BYTES) return { error: 'frame too large' };
  let m;
  try {
    m = JSON.parse(text);
  } catch {
    return { error: 'not JSON' };
  }
  if (m === null || typeof m !== 'object' || Array.isArray(m)) return { error: 'not an object' };
  if (typeof m.type !== 'string') return { error: "no string 'type'" };
  const check = SERVER_FIELDS[m.type];
  if (check === undefined) return { error: `unknown type '${m.type}'` };
  try {
    check(m);
  } catch (e) {
    if (e instanceof FieldError) return { error: `${m.type}: ${e.message}` };
    throw e;
  }
  return { message: m };
}
