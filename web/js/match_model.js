// Everything the page knows about its match, built only from server messages
// (client/src/match_model.cpp): the HUD's view (seats, scores, turn, shot clock, queen, dues),
// the board to draw (through the playout clock and the interpolation buffer), sound cues and
// short messages for the player.
//
// Snapshot and event times are seconds since the start of their shot, so each shot's times are
// placed on one continuous timeline: the first snapshot of a shot starts where the local clock
// (less the base network transit) is when it arrives. A keyframe at t = 0 (the board at rest, on
// a join, a resume or a new game) is placed there too but fixes nothing: the turn's shot starts
// its own t = 0 only when it is played, maybe minutes later. Physics events of a turn whose first
// snapshot has not arrived yet wait for it. Local times in s (performance.now() / 1000).

import { makeBoardGeometry, PHYSICS } from './board_geometry.js';
import { EmoteBoard } from './emotes.js';
import { HudLog } from './hud_log.js';
import { InterpolationBuffer } from './interpolation_buffer.js';
import { PLAYOUT_DEFAULTS, PlayoutClock } from './playout_clock.js';
import {
  duesSentence, errorSentence, forfeitSentence, foulCost, foulSentence, gameEndSentence,
  pocketList, queenSentence, strokePoints,
} from './plain_words.js';
import { DEFAULT_MOTION } from './protocol.js';
import { ShotPrediction } from './prediction.js';
import { viewTurns } from './seat_panels.js';
import { ServerClock } from './server_clock.js';
import { loudnessFromImpulse, SoundCueQueue } from './sound_cues.js';

const TURNS_KEPT = 8;
const TRANSCRIPT_LINES = 200;
export const COUNTDOWN_S = 5;
export const BOARD_SUMMARY_S = 6; // the card between boards, unless dismissed // the shot clock's last seconds, counted down aloud
const PENDING_CUES_KEPT = 256; // cues of turns whose first snapshot has not arrived

function emptyView() {
  return {
    inRoom: false,
    code: '',
    you: -1, // our seat, -1 for a spectator
    ruleSet: 'icf',
    options: { target_points: 0, boards: 0, shot_clock_s: 0 },
    seats: [], // {occupied, name, connected, bot, colour, baseline, team, score, dues}
    spectators: 0,
    boardNumber: 1,
    turn: 0,
    toPlay: 0,
    phase: 'waiting',
    queen: { state: 'on_board', seat: -1 },
    winner: -1,
    deadlineMs: null, // shot clock, server clock
    aimX: null, // the shooter's live striker x (aim events)
    aimAssist: true, // room_state's aim_assist
    // {winner, reason, sentence} once the game ended; reason: the name the journal, the Match API
    // and carrom-bot give the end (game_end's rule code, or its reason from a server without one).
    gameEnd: null,
    rematchAsked: false,
    // The board that ended last, for the card before the next board: {board, winner, points,
    // shownAt (local s)}; null once dismissed or when the game ended with it.
    boardSummary: null,
  };
}

export class MatchModel {
  constructor(physics = PHYSICS) {
    this.physics = physics;
    this.geometry = makeBoardGeometry(physics);
    this.serverClock = new ServerClock();
    this.log = new HudLog();
    this.prediction = null; // a ShotPrediction once the engine is loaded (setEngine)
    this.transcript = []; // every line said, the newest TRANSCRIPT_LINES (the debug hook's)
    this.emotes = new EmoteBoard(); // kept across rooms: the mutes are the player's choice
    this.reset();
  }

  // The exact engine (engine.js) has loaded: the own strokes are predicted from now on.
  setEngine(engine) {
    this.prediction = new ShotPrediction(engine, loudnessFromImpulse);
  }

  // Forget the room (left it, or the seat is gone).
  reset() {
    this.view = emptyView();
    this.emotes?.clear();
    this.playout = new PlayoutClock();
    this.buffer = new InterpolationBuffer(this.geometry);
    this.cues = new SoundCueQueue();
    this.due = [];
    this.kinds = new Map();
    this.turnOffsets = new Map(); // turn -> continuous time of the shot's t = 0
    this.pendingCues = [];
    this.cuesHeard = 0; // audible physics events received (collision, cushion, pocket)
    this.cuesMerged = 0; // cues played as one with another of their kind at the same time
    this.lastProtoSeq = null;
    this.lastDue = null; // the stroke's last due event: {team, owed}
    // The seat whose forfeit the last shot_result reported (game_end's line names it), or -1.
    this.forfeitSeat = -1;
    this.lastTick = null; // 'turn|second' of the last countdown tick
    this.nextSeq = 1;
    this.lastRender = 0;
    this.shots = 0; // shot results received
    this.lastShot = null; // the latest shot_result: {turn, seat, x, angle, power, pocketed}
    this.version = 0; // changes whenever the HUD's view changes
    this.predictedCues = []; // the predicted stroke's sound cues, by time
    this.correctionsLogged = this.prediction?.stats.corrections ?? 0;
    this.prediction?.drop();
  }

  handle(m, localS) {
    switch (m.type) {
      case 'welcome':
        this.serverClock.oneWay(m.server_time_ms, localS);
        this.dropUnconfirmedPrediction(); // a new connection: the shot may be lost
        break;
      case 'room_state': this.onRoomState(m, localS); break;
      case 'snapshot': this.onSnapshot(m, localS); return; // no HUD change
      case 'event': this.onEvent(m, localS); break;
      case 'shot_result': this.onShotResult(m, localS); break;
      case 'error':
        this.dropUnconfirmedPrediction(); // the shot was refused
        this.say(errorSentence(m), 'error', localS);
        break;
      default: return;
    }
    this.version += 1;
  }

  // Posts a line for the HUD and keeps it in the transcript.
  say(text, tone, localS) {
    this.transcript.push({ text, tone });
    if (this.transcript.length > TRANSCRIPT_LINES) this.transcript.shift();
    this.log.post(text, tone, localS);
  }

  myTurn() {
    const v = this.view;
    return v.inRoom && v.you >= 0 && v.phase === 'aiming' && v.toPlay === v.you;
  }

  spectator() {
    return this.view.you < 0;
  }

  seatBaseline(seat) {
    const s = this.view.seats[seat];
    return s ? s.baseline : seat === 1 ? 'top' : 'bottom';
  }

  // Quarter turns of the view that put our baseline at the bottom (screen_mapping.js);
  // spectators see seat 0's view.
  viewTurns() {
    return viewTurns(this.view);
  }

  // Our baseline is the top one: the view is turned half a turn.
  flipped() {
    return this.viewTurns() === 2;
  }

  doubles() {
    return this.view.seats.length === 4;
  }

  seatName(seat) {
    const s = this.view.seats[seat];
    return s && s.name ? s.name : `Seat ${seat + 1}`;
  }

  teamOf(seat) {
    const s = this.view.seats[seat];
    return s ? s.team : seat;
  }

  // A team's name: its players' names ("Asha & Chitra"); in singles the seat's name. The team's
  // number is its first seat (the protocol's `winner`).
  teamName(team) {
    if (!this.doubles()) return this.seatName(team);
    const names = [];
    this.view.seats.forEach((s, i) => { if (s.team === team) names.push(this.seatName(i)); });
    return names.length > 0 ? names.join(' & ') : `Team ${team + 1}`;
  }

  // Whether `team` is ours (never for a spectator).
  ourTeam(team) {
    return this.view.you >= 0 && team >= 0 && this.teamOf(this.view.you) === team;
  }

  // Seconds left on the shot clock by the server's clock, or null when none runs.
  shotClockLeft(localS) {
    const v = this.view;
    if (v.deadlineMs === null || v.phase !== 'aiming') return null;
    return this.serverClock.secondsUntil(v.deadlineMs, localS);
  }

  // The seconds of our own shot clock's last COUNTDOWN_S, each once per turn (5, 4, ... 1) as it
  // is reached: the page plays a tick for it. null otherwise.
  countdownTick(localS) {
    const left = this.shotClockLeft(localS);
    if (left === null || !this.myTurn() || left <= 0 || left > COUNTDOWN_S) return null;
    const secs = Math.ceil(left);
    const key = `${this.view.turn}|${secs}`;
    if (this.lastTick === key) return null;
    this.lastTick = key;
    return secs;
  }

  // The summary card of the board that just ended: shown BOARD_SUMMARY_S after its board_end,
  // unless dismissed or the game ended with it.
  boardSummaryShown(localS) {
    const b = this.view.boardSummary;
    return b !== null && this.view.phase !== 'game_over' && localS < b.shownAt + BOARD_SUMMARY_S;
  }

  dismissBoardSummary() {
    this.view.boardSummary = null;
    this.version += 1;
  }

  kindOf(id) {
    return this.kinds.get(id) ?? 'black';
  }

  continuousNow(localS) {
    const now = localS - this.playout.baseTransit();
    return this.buffer.empty() ? now : Math.max(now, this.buffer.newestTime() + 1e-3);
  }

  // The server's motion model (room_state "motion") for the buffer and the playout clock. A server
  // that sends a delta at every change of motion makes the free motion past the newest state
  // exact: the delay only covers the jitter, and the board may be drawn further ahead of the
  // newest state (docs/interpolation.md, "The render time").
  applyMotion(motion = DEFAULT_MOTION) {
    this.playout.setIntervalFactor(motion.contact_snapshots ? 0 : PLAYOUT_DEFAULTS.intervalFactor);
    this.buffer.setMotion(motion.damping_per_s, motion.contact_snapshots);
  }

  onRoomState(m, localS) {
    if (this.view.inRoom && m.code !== this.view.code) this.reset();
    const joined = !this.view.inRoom;
    this.serverClock.oneWay(m.server_time_ms, localS);
    this.applyMotion(m.motion ?? DEFAULT_MOTION);
    const v = this.view;
    if (v.phase === 'game_over' && m.phase !== 'game_over') {
      v.gameEnd = null; // a rematch started
      v.rematchAsked = false;
    }
    Object.assign(v, {
      inRoom: true, code: m.code, you: m.you, ruleSet: m.rule_set, options: m.options,
      aimAssist: m.aim_assist, // the first-contact guide is allowed (practice and unrated games)
      spectators: m.spectators, boardNumber: m.board_number, turn: m.turn, toPlay: m.to_play,
      phase: m.phase, queen: m.queen, winner: m.winner,
      deadlineMs: m.shot_clock_deadline_ms ?? null,
    });
    const p = this.prediction;
    if (p?.active && m.turn !== p.turn) {
      // The predicted stroke is over (its last keyframe may have been lost with a connection
      // that a resume replaced): the prediction ends once its blends are done.
      if (p.confirmed) p.markServerDone();
      else this.dropUnconfirmedPrediction();
    }
    v.seats = m.seats.map((s, i) => ({
      occupied: s.occupied, name: s.name, connected: s.connected, bot: s.bot, colour: s.colour,
      baseline: s.baseline, team: s.team ?? (m.seats.length === 4 ? i % 2 : i), score: m.scores[i] ?? 0, dues: m.dues[i] ?? 0,
    }));
    const bodies = m.bodies.map((b) => {
      this.kinds.set(b.id, b.kind);
      return { id: b.id, kind: b.kind, x: b.x, y: b.y, vx: b.vx, vy: b.vy, pocketed: b.pocketed };
    });
    this.buffer.push({ seq: this.nextSeq++, time: this.continuousNow(localS), keyframe: true, bodies });
    if (joined) {
      this.say(m.you >= 0 ? `Joined room ${m.code}` : `Watching room ${m.code}`, 'info', localS);
    }
  }

  onSnapshot(m, localS) {
    if (this.lastProtoSeq !== null && m.seq <= this.lastProtoSeq && !m.keyframe) return;
    this.lastProtoSeq = m.seq;
    if (!m.keyframe && this.view.phase !== 'moving') {
      this.view.phase = 'moving';
      this.version += 1;
    }
    // A keyframe at t = 0 is the board at rest (a join, a resume or a new game before the turn's
    // shot): the shot's own t = 0 comes later, when it is played, so it fixes no offset.
    const atRest = m.keyframe && m.t <= 0;
    let offset = atRest ? this.continuousNow(localS) : this.turnOffsets.get(m.turn);
    if (offset === undefined) {
      offset = this.continuousNow(localS) - m.t;
      this.turnOffsets.set(m.turn, offset);
      while (this.turnOffsets.size > TURNS_KEPT) {
        this.turnOffsets.delete(this.turnOffsets.keys().next().value);
      }
      this.pendingCues = this.pendingCues.filter((p) => {
        if (p.turn !== m.turn) return true;
        this.cues.push({ ...p.cue, time: offset + p.t });
        return false;
      });
    }
    const before = this.buffer.newestState() ?? [];
    const bodies = m.bodies.map(([id, x, y, vx, vy]) => ({
      id, kind: this.kindOf(id), x, y, vx, vy, pocketed: false,
    }));
    for (const id of m.pocketed) {
      const prev = before.find((b) => b.id === id);
      bodies.push({
        id, kind: this.kindOf(id), x: prev ? prev.x : 0, y: prev ? prev.y : 0, vx: 0, vy: 0,
        pocketed: true,
      });
    }
    const s = { seq: this.nextSeq++, time: offset + m.t, keyframe: m.keyframe, bodies };
    const p = this.prediction;
    const predicted = p?.active && m.turn === p.turn && !atRest;
    if (!this.buffer.push(s)) return;
    if (!predicted) {
      this.playout.onSnapshot(s.time, localS);
    } else if (m.keyframe) {
      p.markServerDone(); // the board after the rules: no physics to compare
    } else {
      // At the server's own shot time (offset + t - offset is not always t).
      p.confirm(this.buffer.newestState(), m.t, localS);
    }
  }

  // Predicts our stroke {turn, x, angle, power} just sent (docs/interpolation.md, "Shot
  // prediction"): only on our turn, with the board at rest and the engine loaded. Its t = 0 is
  // the time drawn now, so the next frame shows it moving; the board at rest is placed again just
  // before it so that the server's snapshots follow it in the buffer.
  predict(shot, localS) {
    const p = this.prediction;
    if (!p || p.active || !this.myTurn() || shot.turn !== this.view.turn || this.buffer.empty()) {
      return false;
    }
    const board = this.boardNow();
    if (!board.every((b) => b.pocketed || (b.vx === 0 && b.vy === 0))) return false;
    const start = this.playout.renderTime(localS);
    if (!p.start(this.view.turn, board, this.seatBaseline(this.view.you), shot, start)) return false;
    this.buffer.clear();
    this.buffer.push({ seq: this.nextSeq++, time: start - 1e-3, keyframe: true, bodies: board });
    this.turnOffsets.set(this.view.turn, start);
    this.predictedCues = p.cues().sort((a, b) => a.time - b.time);
    this.view.phase = 'moving';
    this.version += 1;
    return true;
  }

  dropUnconfirmedPrediction() {
    const p = this.prediction;
    if (!p?.active || p.confirmed) return;
    // Back to the board at rest.
    this.turnOffsets.delete(p.turn);
    p.drop();
    this.predictedCues = [];
    if (this.view.phase === 'moving') this.view.phase = 'aiming';
    this.version += 1;
  }

  // The drawn bodies while a prediction is active (ShotPrediction.draw); its end, once the
  // server's last keyframe arrived and every blend is done, posts the corrections as a HUD line.
  renderPredicted(t, localS) {
    const p = this.prediction;
    const serverReaches = p.confirmed
      && (p.serverDone || (!this.buffer.empty() && this.buffer.newestTime() >= t));
    if (!serverReaches) return p.draw(t, localS, null);
    const server = this.buffer.sample(t);
    if (p.serverDone && !p.blending(localS)) {
      p.stop();
      const n = p.stats.corrections - this.correctionsLogged;
      if (n > 0) {
        this.log.post(`The server corrected the predicted shot: ${countWords(n, 'piece', 'pieces')} moved, `
          + `by up to ${p.stats.strokeMaxDifferencePx.toFixed(2)} px`, 'info', localS);
        this.correctionsLogged = p.stats.corrections;
      }
      return server;
    }
    return p.draw(t, localS, server);
  }

  cue(turn, t, kind, volume) {
    if (volume <= 0) return;
    this.cuesHeard += 1;
    if (this.prediction?.claimCue(turn, kind, t)) return; // predicted, and played already
    const offset = this.turnOffsets.get(turn);
    if (offset === undefined) {
      this.pendingCues.push({ turn, t, cue: { time: 0, kind, volume } });
      if (this.pendingCues.length > PENDING_CUES_KEPT) this.pendingCues.shift();
      return;
    }
    this.cues.push({ time: offset + t, kind, volume });
  }

  setSeat(seat, fields) {
    const s = this.view.seats[seat];
    if (s) Object.assign(s, fields);
  }

  onEvent(e, localS) {
    const v = this.view;
    const post = (text, tone) => this.say(text, tone, localS);
    switch (e.kind) {
      case 'collision': this.cue(e.turn, e.t, 'click', loudnessFromImpulse(e.impulse)); break;
      case 'cushion': this.cue(e.turn, e.t, 'cushion', 0.8 * loudnessFromImpulse(e.impulse)); break;
      case 'pocket': this.cue(e.turn, e.t, 'pocket', 1); break;
      case 'foul': break; // said with its stroke's shot_result
      case 'queen':
        v.queen = e.queen;
        post(queenSentence(e.queen, this.seatName(e.queen.seat)), 'info');
        break;
      case 'due': {
        // Dues are the team's: partners owe them together. The server sends one event per seat
        // of the team; the partner's event with the same count in the same stroke (since the
        // stroke's shot_result, which its rule events follow) adds no line.
        const team = this.teamOf(e.seat);
        v.seats.forEach((s, i) => { if (i === e.seat || s.team === team) s.dues = e.owed; });
        const last = this.lastDue;
        const repeat = last !== null && last.team === team && last.owed === e.owed;
        this.lastDue = { team, owed: e.owed };
        const who = this.doubles() ? this.teamName(team) : this.seatName(e.seat);
        if (e.owed > 0 && !repeat) post(duesSentence(who, this.doubles(), e.owed), 'foul');
        break;
      }
      case 'turn':
        this.serverClock.oneWay(e.server_time_ms, localS);
        Object.assign(v, {
          turn: e.turn, toPlay: e.seat, deadlineMs: e.deadline_ms ?? null, phase: 'aiming',
          aimX: null,
        });
        // Not said: the status line names the seat to play ('Your turn').
        break;
      case 'board_end':
        e.scores.forEach((score, i) => this.setSeat(i, { score }));
        v.phase = 'board_over';
        v.boardSummary = { board: e.board, winner: e.winner, points: e.points, shownAt: localS };
        // Freestyle scores each stroke: its board_end adds no points, so none are named.
        post(e.winner >= 0
          ? `Board ${e.board} to ${this.teamName(e.winner)}${e.points > 0 ? ` (+${e.points})` : ''}`
          : `Board ${e.board} ends, no winner`, 'good');
        break;
      case 'game_end': {
        e.scores.forEach((score, i) => this.setSeat(i, { score }));
        v.winner = e.winner;
        v.phase = 'game_over';
        v.boardSummary = null; // the game-over panel says it
        const sentence = gameEndSentence(e.winner, this.ourTeam(e.winner), this.teamName(e.winner),
          e.reason, v.you < 0, this.doubles());
        // Said by the result panel (hud.js), as the desktop client's game-over panel says it: no
        // HUD line.
        // why: game_end's reason for the panel's sentence (game_over_text.js); names: the
        // seats' names at the end (a player may leave afterwards).
        v.gameEnd = {
          winner: e.winner, reason: e.rule || e.reason, why: e.reason, sentence,
          scores: e.scores, names: v.seats.map((s) => (s.occupied ? s.name : '')),
        };
        this.onForfeitEnd(e, localS);
        break;
      }
      case 'player_dropped': {
        this.setSeat(e.seat, { connected: false });
        const grace = Math.trunc((e.grace_deadline_ms - e.server_time_ms) / 1000);
        post(`${this.seatName(e.seat)} lost the connection; they have ${grace} s to come back`, 'error');
        break;
      }
      case 'player_returned':
        this.setSeat(e.seat, { connected: true });
        post(`${this.seatName(e.seat)} is back`, 'info');
        break;
      case 'aim':
        if (e.seat !== v.you && e.turn === v.turn) v.aimX = e.x;
        break;
      case 'emote':
        this.emotes.receive(e.seat, e.emote, localS);
        break;
      case 'paused': // the server cannot commit the stroke yet: nothing of it moves until resumed
        post(e.message, 'error');
        break;
      case 'resumed':
        post('The match goes on', 'info');
        break;
      default:
        break;
    }
  }

  onShotResult(m, localS) {
    const v = this.view;
    this.shots += 1;
    this.lastDue = null; // the stroke's rule events (due among them) follow
    this.lastShot = {
      turn: m.turn, seat: m.seat, x: m.x, angle: m.angle, power: m.power, pocketed: m.pocketed,
    };
    v.seats.forEach((s, i) => {
      if (i < m.scores.length) s.score = m.scores[i];
      if (i < m.dues.length) s.dues = m.dues[i];
    });
    v.queen = m.queen;
    v.turn = m.next_turn;
    v.toPlay = m.next_seat;
    const kinds = m.pocketed.map((id) => this.kindOf(id));
    const points = m.points[m.seat] ?? 0;
    const fouled = m.fouls.length > 0;
    const name = this.seatName(m.seat);
    if (kinds.length > 0) {
      this.say(`${name} pocketed ${pocketList(kinds)}${strokePoints(points)}`,
        fouled ? 'foul' : 'good', localS);
    }
    for (const foul of m.fouls) {
      if (foul.rule === 'forfeit') this.forfeitSeat = m.seat; // said with game_end (its reason)
      else this.say(foulSentence(name, foul.message), 'foul', localS);
    }
    const cost = fouled ? foulCost(m.returned.map((id) => this.kindOf(id)), points) : '';
    if (cost !== '') this.say(cost, 'foul', localS);
    if (m.extra_turn && !m.game_over && !m.board_over) {
      this.say(`${this.seatName(m.seat)} plays again`, 'info', localS);
    }
  }

  // "Asha left the match: Ravi wins by forfeit", from the reader's side: good news for the
  // winners, a warning for the losers.
  onForfeitEnd(e, localS) {
    const leaver = this.forfeitSeat;
    this.forfeitSeat = -1;
    if ((e.reason !== 'left' && e.reason !== 'forfeit') || leaver < 0 || e.winner < 0) return;
    const doubles = this.doubles();
    const ours = this.ourTeam(e.winner);
    const winner = ours ? (doubles ? 'your team' : 'you') : this.teamName(e.winner);
    let tone = 'info';
    if (ours) tone = 'good';
    else if (this.view.you >= 0) tone = 'foul';
    this.say(forfeitSentence(this.seatName(leaver), e.reason, winner, doubles ? !ours : ours),
      tone, localS);
  }

  // The board to draw at localS; sound cues that became due are kept for takeSounds().
  render(localS) {
    const t = this.playout.renderTime(localS);
    this.lastRender = t;
    let bodies = this.prediction?.active ? this.renderPredicted(t, localS) : this.buffer.sample(t);
    for (const c of this.cues.takeDue(t)) this.due.push(c);
    while (this.predictedCues.length > 0 && this.predictedCues[0].time <= t) {
      this.due.push(this.predictedCues.shift());
    }
    // While aiming, the striker is drawn where the shooter places it, not where it last stopped.
    if (this.view.phase === 'aiming' && !this.animating()) {
      bodies = bodies.filter((b) => b.kind !== 'striker');
    }
    return bodies;
  }

  // The cues due since the last call, each once; cues of one kind at the same event time (within
  // 1 ms: a straight break hits two mirrored coins at once) are one sound, the loudest.
  takeSounds() {
    const sounds = new Map();
    for (const cue of this.due) {
      const key = `${cue.kind}|${Math.round(cue.time * 1000)}`;
      const same = sounds.get(key);
      if (same) this.cuesMerged += 1;
      if (!same || cue.volume > same.volume) sounds.set(key, cue);
    }
    this.due = [];
    return [...sounds.values()];
  }

  // True while a shot is still being played on screen.
  animating() {
    return this.view.phase === 'moving' || Boolean(this.prediction?.active)
      || (!this.buffer.empty() && this.lastRender < this.buffer.newestTime());
  }

  // The newest board (for placement checks and the coins left), [] before the first state.
  boardNow() {
    return this.buffer.newestState() ?? [];
  }

  // Coins still on the board by kind, from the newest state.
  coinsLeft() {
    const left = { black: 0, white: 0, queen: 0 };
    for (const b of this.boardNow()) if (!b.pocketed && b.kind in left) left[b.kind] += 1;
    return left;
  }
}
