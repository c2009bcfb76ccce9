// The exact engine (common/) compiled to WebAssembly (js/carrom_engine.wasm, built by
// wasm/CMakeLists.txt), behind its C API (wasm/include/carrom/wasm/engine_api.h): a scene and a
// shot in, the trajectory, events, final bodies and result hash out, through Float64Array views
// of the module's memory. The module has no JavaScript glue: this file instantiates it.
// docs/web.md, "The engine in the page".

const KINDS = ['black', 'white', 'queen', 'striker'];
const EVENT_KINDS = ['collision', 'cushion', 'pocket', 'stop'];
const SIDES = { bottom: 0, right: 1, top: 2, left: 3 };
const SCENE_FIELDS = 5;
const FINAL_FIELDS = 7;
const EVENT_FIELDS = 7;
const MAX_BODIES = 64; // kCarromMaxBodies, the striker included
const COIN_COUNT = 19; // the pieces of carrom_replay_board (kCoinCount)

export const ENGINE_URL = 'js/carrom_engine.wasm';

// The journal's rule set names in the C API's order, and its rules fields in carrom_replay_config's
// (wasm/include/carrom/wasm/replay_api.h).
export const RULE_SETS = ['icf', 'seed', 'freestyle', 'discpool'];
export const RULES_FIELDS = ['seat_count', 'first_breaker', 'shot_clock_s', 'shot_clock_grace_s',
  'missed_turns_to_lose', 'target_points', 'max_boards', 'queen_points', 'queen_points_limit',
  'board_points_cap', 'break_tries'];
export const FREESTYLE_FIELDS = ['white', 'black', 'queen', 'striker_penalty', 'target'];
const INPUT_KINDS = { stroke: 0, clock_expired: 1, forfeit: 2 };
const PHASES = ['aiming', 'board_over', 'game_over'];
const SIDE_NAMES = ['bottom', 'right', 'top', 'left'];

// The module's two imports: memory growth (views are re-made on every call) and abort.
function imports() {
  return {
    env: { emscripten_notify_memory_growth: () => {} },
    wasi_snapshot_preview1: {
      proc_exit: (code) => { throw new Error(`the engine stopped (exit ${code})`); },
    },
  };
}

export class Engine {
  constructor(instance) {
    this.api = instance.exports;
    this.api._initialize?.();
    this.physicsVersion = this.api.carrom_physics_version();
    this.rulesVersion = this.api.carrom_rules_version();
  }

  f64(pointer, count) {
    return new Float64Array(this.api.memory.buffer, pointer, count);
  }

  // Writes pieces ({id, kind, x, y, pocketed}; a striker among them is ignored) into the scene.
  writeScene(pieces) {
    const n = Math.min(pieces.length, MAX_BODIES - 1);
    const scene = this.f64(this.api.carrom_scene(), n * SCENE_FIELDS);
    for (let i = 0; i < n; i += 1) {
      const b = pieces[i];
      scene.set([b.id, Math.max(KINDS.indexOf(b.kind), 0), b.x, b.y, b.pocketed ? 1 : 0], i * SCENE_FIELDS);
    }
    return n;
  }

  // Simulates the stroke of `side` ('bottom', 'right', 'top', 'left' or 0..3) with shot
  // {x, angle, power} from the pieces at rest, the striker placed as the server's rules place it.
  // {error: code} when the engine refuses the scene; else the stroke's summary. The trajectory
  // stays in the engine until the next simulate(): stateAt() reads it.
  simulate(pieces, side, shot) {
    const n = this.writeScene(pieces);
    const s = typeof side === 'number' ? side : SIDES[side] ?? -1;
    if (this.api.carrom_simulate(n, s, shot.x, shot.angle, shot.power) !== 0) {
      return { error: this.error() };
    }
    return {
      error: null,
      endTime: this.api.carrom_end_time_s(),
      hash: this.hash(),
      events: this.events(),
      final: this.finalBodies(),
    };
  }

  error() {
    const p = this.api.carrom_error();
    const bytes = new Uint8Array(this.api.memory.buffer, p, 64);
    const end = bytes.indexOf(0);
    return new TextDecoder().decode(bytes.subarray(0, end < 0 ? 64 : end));
  }

  // The stroke's ResultHash, 16 hex digits.
  hash() {
    const hex = (v) => (v >>> 0).toString(16).padStart(8, '0');
    return hex(this.api.carrom_result_hash_high()) + hex(this.api.carrom_result_hash_low());
  }

  // `count` records of `fields` doubles at `pointer`, each made into an object by make(record).
  records(pointer, count, fields, make) {
    const r = this.f64(pointer, count * fields);
    const out = new Array(count);
    for (let i = 0; i < count; i += 1) out[i] = make(r.subarray(i * fields, (i + 1) * fields));
    return out;
  }

  events() {
    return this.records(this.api.carrom_events(), this.api.carrom_event_count(), EVENT_FIELDS,
      (e) => ({ t: e[0], kind: EVENT_KINDS[e[1]], a: e[2], b: e[3], impulse: e[4], x: e[5], y: e[6] }));
  }

  finalBodies() {
    return this.records(this.api.carrom_final(), this.api.carrom_body_count(), FINAL_FIELDS,
      (b) => ({ id: b[0], kind: KINDS[b[1]], x: b[2], y: b[3], vx: b[4], vy: b[5], pocketed: b[6] !== 0 }));
  }

  // Every body of the last stroke at shot time t (s): {id, kind, x, y, pocketed}, by id with the
  // striker last.
  stateAt(t) {
    const n = this.api.carrom_state_at(t);
    return this.records(this.api.carrom_frame(), n, SCENE_FIELDS,
      (b) => ({ id: b[0], kind: KINDS[b[1]], x: b[2], y: b[3], pocketed: b[4] !== 0 }));
  }

  // For an aim assist: the first piece the striker touches ({id, t, striker: {x, y}, direction:
  // {x, y}}), or null. Replaces the last stroke.
  firstContact(pieces, side, shot) {
    const n = this.writeScene(pieces);
    const s = typeof side === 'number' ? side : SIDES[side] ?? -1;
    const id = this.api.carrom_first_contact(n, s, shot.x, shot.angle, shot.power);
    if (id < 0) return null;
    const c = this.f64(this.api.carrom_contact(), 5);
    return { id, t: c[0], striker: { x: c[1], y: c[2] }, direction: { x: c[3], y: c[4] } };
  }

  // The replay half: a journal's game played input by input through the rules (replay_api.h).
  replayStart(ruleSet, rules, firstTurn) {
    const config = this.f64(this.api.carrom_replay_config(), 16);
    config.set([...RULES_FIELDS.map((k) => rules[k]), ...FREESTYLE_FIELDS.map((k) => rules.freestyle?.[k])]);
    if (this.api.carrom_replay_start(RULE_SETS.indexOf(ruleSet), firstTurn) !== 0) return { error: this.error() };
    return { error: null, result: this.replayResult() };
  }

  // kind: 'stroke', 'clock_expired' or 'forfeit'; shot {x, angle, power} for a stroke.
  replayPlay(kind, seat, shot = { x: 0, angle: 0, power: 0 }) {
    if (this.api.carrom_replay_play(INPUT_KINDS[kind] ?? -1, seat, shot.x, shot.angle, shot.power) !== 0) {
      return { error: this.error() };
    }
    return { error: null, result: this.replayResult() };
  }

  // The state the last input left (see carrom_replay_result).
  replayResult() {
    const r = this.f64(this.api.carrom_replay_result(), 24);
    const hex = (v) => (v >>> 0).toString(16).padStart(8, '0');
    return {
      turn: r[0], toPlay: r[1], board: r[2], phase: PHASES[r[3]],
      scores: Array.from(r.subarray(4, 8)), dues: Array.from(r.subarray(8, 12)),
      winner: r[12] === -2 ? null : r[12], reasonCode: r[13], boardWinner: r[14], boardPoints: r[15],
      stateHash: hex(r[16]) + hex(r[17]),
      sides: Array.from(r.subarray(18, 22)).filter((x) => x >= 0).map((x) => SIDE_NAMES[x]),
    };
  }

  // The board as the rules left it (next false) or the one the next input is played on (true).
  replayBoard(next) {
    return this.records(this.api.carrom_replay_board(next ? 1 : 0), COIN_COUNT, SCENE_FIELDS,
      (b) => ({ id: b[0], kind: KINDS[b[1]], x: b[2], y: b[3], vx: 0, vy: 0, pocketed: b[4] !== 0 }));
  }
}

// Instantiates the engine from its bytes (node, tests) or its URL (the page: streamed, so the
// module compiles while it downloads). Rejects when WebAssembly or the file is missing.
export async function loadEngine(source = ENGINE_URL) {
  if (typeof WebAssembly !== 'object') throw new Error('this browser has no WebAssembly');
  let result;
  if (typeof source === 'string') {
    const response = await fetch(source);
    if (!response.ok) throw new Error(`no engine at ${source} (HTTP ${response.status})`);
    result = await WebAssembly.instantiateStreaming(response, imports());
  } else {
    result = await WebAssembly.instantiate(source, imports());
  }
  return new Engine(result.instance);
}
