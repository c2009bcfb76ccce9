// A match journal (docs/matches.md) played back with the engine (engine.js): every input
// (stroke, shot clock expiry, forfeit) run through the rules again as the server ran it and laid
// out on one replay timeline, as carrom-client --replay does (client/src/replay_model.cpp). Pure:
// no DOM, no clock; replay_page.js draws what it says.
//
// The timeline: each input gets LEAD_S seconds showing the board it was played on (a stroke's
// striker where it was placed), then the stroke's motion (shot time 0 to its simulation's end),
// then TAIL_S seconds showing the board as the rules left it. Clock expiries and forfeits have no
// motion. Times in seconds of replay time; wall time times the speed.

import { RULE_SETS } from './engine.js';

export const LEAD_S = 0.6;
export const TAIL_S = 0.8;
export const SPEEDS = [0.25, 0.5, 1, 2, 4];
const OUTCOME_TYPES = ['stroke', 'clock_expired', 'forfeit'];

// Why this page cannot replay `journal` (one sentence), or null.
export function refusal(journal, engine) {
  const head = journal?.match;
  if (journal?.format !== 1 || !head || !Array.isArray(journal.entries)) {
    return 'This is not a match journal this page can read (format 1).';
  }
  const v = head.versions ?? {};
  if (v.physics !== engine.physicsVersion) {
    return `This match was played with physics version ${v.physics}; this page runs version `
      + `${engine.physicsVersion}, whose strokes would differ, so it cannot be replayed here.`;
  }
  if (v.rules !== engine.rulesVersion) {
    return `This match was played with rules version ${v.rules}; this page runs version `
      + `${engine.rulesVersion}, so it cannot be replayed here.`;
  }
  if (!RULE_SETS.includes(head.rule_set)) return `The rule set ${head.rule_set} is unknown to this page.`;
  return null;
}

// The replayed state shows what the journal recorded: the scores and the seat to play next.
function sameOutcome(result, recorded) {
  if (!recorded || result.toPlay !== recorded.next_seat) return false;
  return recorded.scores.every((score, team) => result.scores[team] === score);
}

export class ReplayModel {
  // {model} or {error: sentence}.
  static load(journal, engine) {
    const refused = refusal(journal, engine);
    if (refused) return { error: refused };
    const head = journal.match;
    const started = engine.replayStart(head.rule_set, head.rules, head.first_turn);
    if (started.error) return { error: `The rules refuse this match's settings (${started.error}).` };
    const m = new ReplayModel(engine, journal);
    m.initial = started.result;
    let board = engine.replayBoard(true);
    let t = 0;
    for (const [entry, e] of journal.entries.entries()) {
      if (!OUTCOME_TYPES.includes(e.type)) continue; // membership: no state change
      const stroke = e.type === 'stroke';
      const shot = stroke ? { x: e.shot.x, angle: e.shot.angle, power: e.shot.power } : undefined;
      const played = engine.replayPlay(e.type, e.seat, shot);
      if (played.error) return { error: `The rules refuse entry ${entry} of this match (${played.error}).` };
      const turn = {
        entry, stroke, seat: e.seat, side: started.result.sides[e.seat], shot, before: board,
        result: played.result, after: engine.replayBoard(false),
        // Bit for bit (the state hash) and as a player sees it (scores, the seat to play next).
        sameBits: played.result.stateHash === e.outcome?.state_hash,
        sameOutcome: sameOutcome(played.result, e.outcome),
        strokeNumber: m.strokes + (stroke ? 1 : 0), duration: 0,
      };
      board = engine.replayBoard(true);
      if (stroke) {
        const sim = engine.simulate(turn.before, turn.side, shot);
        turn.duration = sim.error ? 0 : sim.endTime;
        turn.sameBits = turn.sameBits && sim.hash === e.result_hash;
        m.strokes += 1;
      }
      turn.start = t;
      turn.motion = t + LEAD_S;
      turn.rest = turn.motion + turn.duration;
      turn.end = turn.rest + TAIL_S;
      t = turn.end;
      if (!turn.sameOutcome) m.mismatches += 1;
      if (!turn.sameBits) m.bitDifferences += 1;
      m.turns.push(turn);
    }
    m.duration = t;
    return { model: m };
  }

  constructor(engine, journal) {
    this.engine = engine;
    this.journal = journal;
    this.turns = [];
    this.strokes = 0;
    this.mismatches = 0; // inputs whose replayed scores or next seat differ from the journal's
    // Inputs whose replayed state or stroke differs from the journal's in some bit: the page's
    // engine rounds a few results differently from the server's (docs/web.md, "Determinism
    // across builds"); the differences are far below a pixel unless a later stroke amplifies them.
    this.bitDifferences = 0;
    this.duration = 0;
    this.time = 0;
    this.speed = 1;
    this.playing = true;
    this.simulated = -1; // the turn whose stroke the engine holds
  }

  finished() {
    return this.time >= this.duration;
  }

  play() {
    if (this.finished()) this.time = 0;
    this.playing = true;
  }

  togglePlay() {
    if (this.playing) this.playing = false;
    else this.play();
  }

  setSpeed(speed) {
    this.speed = Math.min(Math.max(speed, SPEEDS[0]), SPEEDS[SPEEDS.length - 1]);
  }

  faster() {
    this.setSpeed(SPEEDS.find((s) => s > this.speed) ?? SPEEDS[SPEEDS.length - 1]);
  }

  slower() {
    this.setSpeed([...SPEEDS].reverse().find((s) => s < this.speed) ?? SPEEDS[0]);
  }

  // Wall seconds passed while playing; pauses at the end.
  advance(wallS) {
    if (!this.playing || !(wallS > 0)) return;
    this.time = Math.min(this.time + wallS * this.speed, this.duration);
    if (this.finished()) this.playing = false;
  }

  restart() {
    this.time = 0;
    this.playing = true;
  }

  seek(time) {
    this.time = Math.min(Math.max(time, 0), this.duration);
  }

  // The input shown at time t (the last one once the replay ends).
  turnAt(t) {
    const i = this.turns.findIndex((x) => t < x.end);
    return i < 0 ? this.turns.length - 1 : i;
  }

  nextTurn() {
    if (this.turns.length === 0) return;
    const i = this.turnAt(this.time);
    this.seek(i + 1 < this.turns.length ? this.turns[i + 1].start : this.duration);
  }

  // The start of the current input's lead; within its first moments, the previous input's.
  previousTurn() {
    if (this.turns.length === 0) return;
    let i = this.turnAt(this.time);
    if (!this.finished() && this.time <= this.turns[i].start + 0.5 * LEAD_S && i > 0) i -= 1;
    this.seek(this.turns[i].start);
  }

  // Strokes played so far, counting the current one once its motion started.
  strokeNumber() {
    if (this.turns.length === 0) return 0;
    const turn = this.turns[this.turnAt(this.time)];
    return turn.stroke && this.time < turn.motion ? turn.strokeNumber - 1 : turn.strokeNumber;
  }

  // The rules' state shown now: the input's before until its motion ends, then its result.
  stateNow() {
    if (this.turns.length === 0) return this.initial;
    const i = this.turnAt(this.time);
    const turn = this.turns[i];
    if (this.time >= turn.rest) return turn.result;
    return i > 0 ? this.turns[i - 1].result : this.initial;
  }

  // Every body to draw now ({id, kind, x, y, pocketed}): the board before with the striker where
  // it was placed, the stroke's motion, then the board as the rules left it.
  bodies() {
    if (this.turns.length === 0) return [];
    const i = this.turnAt(this.time);
    const turn = this.turns[i];
    if (this.time >= turn.rest || !turn.stroke) return this.time >= turn.rest ? turn.after : turn.before;
    if (this.simulated !== i) {
      this.engine.simulate(turn.before, turn.side, turn.shot);
      this.simulated = i;
    }
    return this.engine.stateAt(Math.max(this.time - turn.motion, 0));
  }

  // The state after the last input (as the server held it, start_next_board not applied).
  finalResult() {
    return this.turns.length > 0 ? this.turns[this.turns.length - 1].result : this.initial;
  }
}
