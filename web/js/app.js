// The page: wires the session, the match model, the aim, the renderer, the HUD, the lobby and
// the sounds, runs one requestAnimationFrame loop, and exposes a read-only debug hook
// (window.carrom) that tests and scripts/web_report.mjs use to see what the page shows.
//
// The WebSocket address is the page's own host (the server serves this page), or the `ws`
// query parameter: index.html?ws=ws://127.0.0.1:7777/.

import { AimAssist } from './aim_assist.js';
import { AimController, clampBaselineX } from './aim_controller.js';
import { alongOf, radiusOf, strikerAt } from './board_geometry.js';
import { Connection } from './connection.js';
import { EmoteView } from './emote_view.js';
import { loadEngine } from './engine.js';
import { Help } from './help.js';
import { Hud } from './hud.js';
import { loadOrCreateIdentity } from './identity.js';
import { IdentityPanel } from './identity_panel.js';
import { getAnswer, getJson, playersKept, RatingView } from './rating_view.js';
import { Leaderboard } from './leaderboard.js';
import { Lobby } from './lobby.js';
import { MatchModel } from './match_model.js';
import { MyMatches } from './my_matches.js';
import { errorSentence } from './plain_words.js';
import { STRIKER_ID } from './physics_config.js';
import * as proto from './protocol.js';
import { Renderer } from './renderer.js';
import { parseReplayHash, startReplayPage } from './replay_page.js';
import { parseRoomHash, roomHash, roomLink, showHash } from './room_link.js';
import { teamSummaries } from './seat_panels.js';
import { SeatRatings } from './seat_ratings.js';
import { Session, SESSION_DEFAULTS } from './session.js';
import { Settings } from './settings.js';
import { sideLayout } from './side_layout.js';
import { SoundPlayer } from './sound.js';

const AIM_SEND_INTERVAL_S = 0.05; // at most 20 aim messages a second
const TOUCH_GRAB_CSS_PX = 30; // a finger grabs the striker within 30 CSS px (a 60 px target)
const FRAME_LOG = 20000; // frame times kept for the debug hook (a minute at 300 frames/s)

// After a game the lobby reads the ratings again this much later (rating_view.js).
const RATING_REREAD_MS = 1500;

function storage(kind) {
  try {
    const s = window[kind];
    s.getItem('carrom.probe');
    return s;
  } catch {
    return null; // storage disabled: the page still works, without resume across reloads
  }
}

function serverUrl() {
  const given = new URLSearchParams(window.location.search).get('ws');
  if (given) return given;
  const scheme = window.location.protocol === 'https:' ? 'wss' : 'ws';
  return `${scheme}://${window.location.host}/`;
}

class App {
  constructor() {
    this.canvas = document.getElementById('board');
    this.stage = document.getElementById('stage');
    this.model = new MatchModel();
    this.aim = new AimController(this.model.physics);
    this.aimAssist = new AimAssist(this.model.physics); // the first-contact guide (aim_assist.js)
    this.assist = null; // the guide the last frame drew
    this.renderer = new Renderer(this.canvas, document.getElementById('board-bg'), this.model.geometry);
    this.sound = new SoundPlayer();
    this.reducedMotion = false;
    this.settings = new Settings(storage('localStorage'), (v) => {
      this.sound.configure(v);
      this.reducedMotion = v.reducedMotion;
      this.dirty = true;
    });
    this.help = new Help(storage('localStorage'));
    this.session = new Session(serverUrl(), storage('sessionStorage'), {
      onMessage: (m, localS) => this.onMessage(m, localS),
      onChange: () => { this.dirty = true; },
      onRefused: (error, request) => this.onRefused(error, request),
    }, SESSION_DEFAULTS, Connection);
    this.lobby = new Lobby(storage('localStorage'), (name, request) => this.request(name, request));
    this.session.identity = loadOrCreateIdentity(storage('localStorage'));
    this.identityPanel = new IdentityPanel(document.getElementById('identity'), storage('localStorage'),
      this.session.identity, (key) => { this.session.identity = key; });
    const kept = playersKept(getJson); // GET /players, asked once for both
    this.ratingView = new RatingView(document.getElementById('my-rating'), getJson, kept);
    this.myMatches = new MyMatches(this.lobby.form, () => this.lobby.storedName());
    this.leaderboard = new Leaderboard(this.lobby.form, () => this.lobby.storedName(), getAnswer);
    this.seatRatings = new SeatRatings(getJson, kept);
    this.hud = new Hud({
      rematch: () => this.rematch(),
      lobby: () => this.toLobby(),
      leave: () => this.askLeave(),
      retry: () => this.retry(),
      cancelAim: () => { this.aim.cancel(); this.pointerId = null; },
      toggleMute: () => this.settings.set({ muted: !this.settings.values.muted }),
      help: () => this.help.open(this.model.view.ruleSet),
      settings: () => this.settings.show(true),
      copyLink: () => this.copyLink(),
      dismissSummary: () => { this.model.dismissBoardSummary(); this.dirty = true; },
    });
    this.emoteView = new EmoteView((id) => this.session.sendGame(proto.emote(id)));
    this.bodies = [];
    this.countdownTicks = 0; // shot-clock ticks played (the debug hook reports them)
    this.aimTurn = -1; // the turn the aim was set up for
    this.shotSentTurn = -1; // the turn we already shot in (no double shots)
    this.lastAimSent = -1;
    this.aimDirty = false;
    this.pointerId = null;
    this.fromLink = null; // the room link the page was opened with
    this.drawKey = '';
    this.frameLog = [];
    this.resizes = []; // stage sizes the board was laid out for
  }

  start() {
    this.bindInput();
    new ResizeObserver(() => this.layout()).observe(this.stage);
    window.addEventListener('hashchange', () => this.onHash());
    document.getElementById('lobby-cancel').addEventListener('click', () => this.toLobby());
    document.getElementById('lobby-help').addEventListener('click', () => this.help.open(this.lobby.ruleSet.value));
    document.getElementById('lobby-settings').addEventListener('click', () => this.settings.show(true));
    document.getElementById('leave-stay').addEventListener('click', () => this.hud.askLeave(null));
    document.getElementById('leave-yes').addEventListener('click', () => this.toLobby());
    this.layout();
    const name = this.lobby.storedName();
    this.fromLink = parseRoomHash(window.location.hash);
    if (this.fromLink) this.lobby.offerRoom(this.fromLink.code, this.fromLink.kind === 'watch');
    if (this.session.heldRoom() && name && proto.isResumeToken(this.session.token)) {
      this.session.start(name, true); // a reload: take the seat back
    } else if (this.fromLink && name) {
      this.joinLink(name);
    }
    requestAnimationFrame((ts) => this.frame(ts));
    this.startEngine();
  }

  // The exact engine for the own strokes' prediction; without it (no WebAssembly, no file) the
  // page draws the server's snapshots only.
  async startEngine() {
    const started = performance.now();
    try {
      this.engine = await loadEngine();
      this.engineMs = performance.now() - started;
      this.model.setEngine(this.engine);
      this.aimAssist.setEngine(this.engine);
    } catch (e) {
      this.engineError = String(e.message ?? e);
    }
  }

  joinLink(name) {
    const l = this.fromLink;
    this.request(name, { kind: l.kind === 'watch' ? 'spectate' : 'join', code: l.code });
  }

  onHash() {
    if (parseReplayHash(window.location.hash) !== null) {
      window.location.reload(); // the replay page replaces the game page
      return;
    }
    const link = parseRoomHash(window.location.hash);
    if (!link || (this.model.view.inRoom && link.code === this.model.view.code)) return;
    this.fromLink = link;
    this.lobby.offerRoom(link.code, link.kind === 'watch');
    if (!this.model.view.inRoom && this.lobby.storedName()) this.joinLink(this.lobby.storedName());
  }

  request(name, request) {
    this.lobby.setError('');
    if (['idle', 'failed'].includes(this.session.phase) || this.session.name !== name) {
      this.session.start(name);
    }
    this.session.ask(request);
  }

  onMessage(m, localS) {
    if (m.type === 'error') {
      this.shotSentTurn = -1; // a rejected shot: aim again
      if (!this.model.view.inRoom) this.lobby.setError(errorSentence(m));
    }
    if (m.type === 'room_state') {
      showHash(roomHash(m.code, m.you < 0));
      this.ratingView.gameStarts();
    }
    if (m.type === 'welcome') this.ratingView.refresh(this.session.name);
    this.model.handle(m, localS);
    this.seatRatings.update(this.model.view);
    this.dirty = true;
  }

  onRefused(error, request) {
    // A friend's link to a full room: watch it instead.
    if (error.code === 'room_full' && request?.kind === 'join' && this.fromLink?.code === request.code) {
      this.session.ask({ kind: 'spectate', code: request.code });
      return;
    }
    this.lobby.setError(errorSentence(error));
  }

  // Leave: while our game runs it forfeits, so the page asks first (Stay or Leave).
  askLeave() {
    const v = this.model.view;
    const running = v.you >= 0 && ['aiming', 'moving', 'board_over'].includes(v.phase);
    if (!running) {
      this.toLobby();
      return;
    }
    const others = this.model.doubles() ? 'Your team loses this game by forfeit.'
      : `You lose this game: ${this.model.seatName(1 - v.you)} wins it by forfeit.`;
    this.aim.cancel();
    this.pointerId = null;
    this.hud.askLeave(others);
  }

  toLobby() {
    this.hud.askLeave(null);
    this.ratingView.refresh(this.session.name);
    setTimeout(() => this.ratingView.refresh(this.session.name), RATING_REREAD_MS);
    this.session.leaveRoom();
    this.model.reset();
    this.seatRatings.update(this.model.view);
    this.aim.endTurn();
    this.pointerId = null;
    this.fromLink = null;
    showHash('');
    this.dirty = true;
  }

  retry() {
    const name = this.lobby.storedName() || this.session.name;
    this.session.start(name, Boolean(this.session.heldRoom()));
  }

  rematch() {
    if (this.session.sendGame(proto.rematch())) {
      this.model.view.rematchAsked = true;
      this.model.log.post('Rematch asked for', 'info', performance.now() / 1000);
    }
  }

  copyLink() {
    const link = roomLink(window.location, this.model.view.code);
    navigator.clipboard?.writeText(link).then(
      () => this.model.log.post('Link copied', 'info', performance.now() / 1000),
      () => this.model.log.post(link, 'info', performance.now() / 1000));
  }

  // The board's size, and where the side area goes (in a room only; the lobby has the stage).
  layout() {
    const w = this.stage.clientWidth;
    const h = this.stage.clientHeight;
    this.layoutInRoom = this.model.view.inRoom;
    let side = Math.min(w, h);
    const sideArea = document.getElementById('side');
    if (this.layoutInRoom) {
      const l = sideLayout(w, h);
      side = l.side;
      this.stage.dataset.log = l.mode;
      sideArea.style.width = `${l.sideW}px`;
      sideArea.style.height = `${l.sideH}px`;
      sideArea.hidden = false;
    } else {
      delete this.stage.dataset.log;
      sideArea.hidden = true;
    }
    if (this.renderer.resize(side, window.devicePixelRatio || 1)) {
      this.dirty = true;
      // The seat panels on the frame (doubles) size themselves from these.
      const wrap = document.getElementById('board-wrap').style;
      const g = this.model.geometry;
      wrap.setProperty('--side', `${this.renderer.side}px`);
      wrap.setProperty('--frame', `${(this.renderer.side * g.frame) / g.boardSize}px`);
      this.resizes.push(`${this.stage.clientWidth}x${this.stage.clientHeight}`);
    }
  }

  mapping() {
    return this.renderer.mapping(this.model.viewTurns());
  }

  boardPoint(e) {
    const rect = this.canvas.getBoundingClientRect();
    return this.mapping().toBoard({ x: e.clientX - rect.left, y: e.clientY - rect.top });
  }

  bindInput() {
    const c = this.canvas;
    c.addEventListener('pointerdown', (e) => {
      this.sound.unlock();
      e.preventDefault();
      if (this.pointerId !== null && e.pointerId !== this.pointerId) {
        this.aim.cancel(); // a second finger cancels
        this.pointerId = null;
        return;
      }
      if (e.button !== undefined && e.button > 0) {
        this.aim.cancel(); // right or middle button cancels
        return;
      }
      this.pointerId = e.pointerId;
      c.setPointerCapture(e.pointerId);
      const minGrab = e.pointerType === 'mouse' ? 0 : this.mapping().lengthToBoard(TOUCH_GRAB_CSS_PX);
      this.aim.pointerDown(this.boardPoint(e), this.model.boardNow(), minGrab);
    });
    c.addEventListener('pointermove', (e) => {
      if (e.pointerId !== this.pointerId) return;
      this.aim.pointerMove(this.boardPoint(e), this.model.boardNow());
    });
    const up = (e) => {
      if (e.pointerId !== this.pointerId) return;
      this.pointerId = null;
      const shot = this.aim.pointerUp(this.boardPoint(e), this.model.boardNow());
      if (shot) this.shoot(shot);
    };
    c.addEventListener('pointerup', up);
    const cancel = (e) => {
      if (e.pointerId !== this.pointerId) return;
      this.pointerId = null;
      this.aim.cancel();
    };
    c.addEventListener('pointercancel', cancel);
    c.addEventListener('lostpointercapture', cancel);
    c.addEventListener('contextmenu', (e) => {
      e.preventDefault();
      this.aim.cancel(); // the right button, also while the left one pulls
    });
    window.addEventListener('keydown', (e) => {
      this.sound.unlock();
      if (e.target instanceof HTMLInputElement || e.target instanceof HTMLSelectElement) return;
      if (this.model.boardSummaryShown(performance.now() / 1000)) {
        this.model.dismissBoardSummary(); // the card between boards, then play on
        this.dirty = true;
        return;
      }
      const pieces = this.model.boardNow();
      if (e.key === 'Escape' && this.hud.leaveAsked()) {
        this.hud.askLeave(null); // Escape answers Stay
      } else if (e.key === 'Escape') {
        this.aim.cancel();
        this.pointerId = null;
      } else if (e.key === 'ArrowLeft' || e.key === 'ArrowRight') {
        // Screen left and right as a step along our baseline in the turned view.
        const screen = { x: e.key === 'ArrowLeft' ? -1 : 1, y: 0 };
        const dir = alongOf(this.aim.baseline, this.mapping().directionToBoard(screen));
        this.aim.nudge(dir, e.shiftKey, pieces);
        e.preventDefault();
      }
    });
  }

  shoot(shot) {
    const turn = this.model.view.turn;
    if (this.session.sendGame(proto.shoot(turn, shot.x, shot.angle, shot.power))) {
      this.shotSentTurn = turn;
      this.aim.endTurn();
      this.releaseMs = performance.now(); // the release, on the frames' clock (first motion)
      this.model.predict({ turn, ...shot }, this.releaseMs / 1000);
    }
  }

  syncAim(now) {
    const v = this.model.view;
    const canAim = this.model.myTurn() && !this.model.animating() && this.shotSentTurn !== v.turn
      && this.session.phase === 'in_room';
    if (!canAim) {
      this.aim.endTurn();
      return;
    }
    if (this.aim.phase === 'inactive') {
      const x = this.aimTurn === v.turn ? this.aim.x : this.model.physics.boardSize / 2;
      this.aim.beginTurn(this.model.seatBaseline(v.you), x);
      this.aimTurn = v.turn;
      this.aimDirty = true;
    }
    if (this.aim.takeMoved()) this.aimDirty = true;
    // Tell the room where the striker is, at most 20 times a second.
    if (this.aimDirty && now - this.lastAimSent >= AIM_SEND_INTERVAL_S) {
      this.session.sendGame(proto.aim(v.turn, this.aim.x));
      this.lastAimSent = now;
      this.aimDirty = false;
    }
  }

  // What the canvas shows besides the pieces: our striker while we aim, or the striker of the seat
  // to play (an opponent, or in doubles our partner) on its own baseline.
  overlays() {
    const v = this.model.view;
    this.assist = null;
    if (this.aim.phase !== 'inactive') {
      const pulling = this.aim.phase === 'pulling';
      const shot = this.aim.pendingShot();
      const blocker = this.model.boardNow().find((b) => b.id === this.aim.placement.blockingId);
      const blocking = blocker ? { x: blocker.x, y: blocker.y, r: radiusOf(blocker.kind, this.model.physics) } : null;
      this.assist = pulling ? this.aimAssist.forPull(this.model, this.aim, shot) : null;
      return {
        placing: { striker: this.aim.striker(), alpha: 1, warning: !this.aim.placement.legal, blocking },
        aim: pulling ? { striker: this.aim.striker(), angle: shot.angle, fraction: this.aim.powerFraction() } : null,
        grabHint: this.aim.phase === 'idle',
        assist: this.assist,
      };
    }
    if (v.inRoom && v.phase === 'aiming' && !this.model.animating() && v.toPlay !== v.you) {
      const x = clampBaselineX(v.aimX ?? this.model.physics.boardSize / 2, this.model.physics);
      const striker = strikerAt(this.model.seatBaseline(v.toPlay), x, this.model.physics);
      return { placing: { striker, alpha: 0.85, warning: false }, aim: null, grabHint: false };
    }
    return { placing: null, aim: null, grabHint: false };
  }

  frame(ts) {
    const started = performance.now();
    const now = started / 1000;
    for (const p of this.session.takePongs()) {
      this.model.serverClock.roundTrip(p.serverMs, p.sentS, p.receivedS);
    }
    const v = this.model.view;
    if (v.inRoom !== this.layoutInRoom) this.layout();
    this.bodies = v.inRoom ? this.model.render(now) : [];
    // Reduced motion: a pocketed piece vanishes at once instead of dropping into the pocket.
    if (this.reducedMotion) this.bodies = this.bodies.filter((b) => !b.falling);
    const animating = v.inRoom && this.model.animating();
    this.syncAim(now);
    if (v.inRoom && this.model.countdownTick(now) !== null) {
      this.countdownTicks += 1;
      this.sound.play({ time: 0, kind: 'click', volume: 0.7 }); // the shot clock's last seconds
    }
    for (const cue of this.model.takeSounds()) this.sound.play(cue);
    const o = this.overlays();
    const key = [v.inRoom, this.model.version, this.aim.phase, this.aim.x, this.aim.pointer.x,
      this.aim.pointer.y, o.placing?.striker.x, o.placing?.striker.y, this.renderer.side,
      this.model.viewTurns()].join('|');
    if (animating || this.dirty || key !== this.drawKey) {
      if (v.inRoom) {
        this.renderer.draw({ bodies: this.bodies, turns: this.model.viewTurns(), ...o });
      } else {
        this.renderer.drawEmpty();
      }
      this.drawKey = key;
      this.dirty = false;
    }
    this.hud.update(this.model, this.session, {
      pulling: this.aim.phase === 'pulling', muted: this.settings.values.muted, ratings: this.seatRatings,
    }, now);
    this.help.update(v.inRoom && v.you >= 0 && ['aiming', 'moving'].includes(v.phase), v.ruleSet);
    this.emoteView.update(this.model, now);
    this.updateLobby();
    document.body.classList.toggle('aiming', this.aim.phase === 'pulling' || this.aim.phase === 'sliding');
    // Frame time: from the frame's start (the rAF timestamp) to the end of this frame's work.
    const striker = this.bodies.find((b) => b.id === STRIKER_ID);
    this.frameLog.push({
      ts, ms: performance.now() - ts, work: performance.now() - started, moving: animating, turn: v.turn,
      sx: striker?.x, sy: striker?.y, // the striker drawn (scripts/web_first_motion.mjs)
    });
    if (this.frameLog.length > FRAME_LOG) this.frameLog.splice(0, FRAME_LOG / 10);
    requestAnimationFrame((t) => this.frame(t));
  }

  updateLobby() {
    const phase = this.session.phase;
    const show = !this.model.view.inRoom;
    this.lobby.show(show);
    if (!show) return;
    const busy = ['connecting', 'greeting', 'joining', 'reconnecting'].includes(phase);
    this.lobby.setBusy(busy);
    const cancel = document.getElementById('lobby-cancel');
    if (cancel.hidden !== (phase !== 'joining')) cancel.hidden = phase !== 'joining';
    this.lobby.setStatus(phase === 'idle' ? 'Pick a name and a game.' : this.session.status);
  }

  // The debug hook's picture of the page (plain data; nothing in it changes the page).
  debugState() {
    const v = this.model.view;
    const rect = this.canvas.getBoundingClientRect();
    return {
      session: { phase: this.session.phase, status: this.session.status, badFrames: this.session.badFrames() },
      inRoom: v.inRoom, code: v.code, you: v.you, ruleSet: v.ruleSet, phase: v.phase, turn: v.turn,
      toPlay: v.toPlay, winner: v.winner, gameEnd: v.gameEnd, myTurn: this.model.myTurn(),
      log: this.model.transcript.map((l) => ({ ...l })),
      boardSummary: v.boardSummary, countdownTicks: this.countdownTicks, options: { ...v.options },
      boardNumber: v.boardNumber,
      animating: this.model.animating(), flipped: this.model.flipped(), turns: this.model.viewTurns(),
      panels: this.hud.panels.map((p) => ({ ...p })), teams: this.model.doubles() ? teamSummaries(v) : [],
      seats: v.seats.map((s) => ({ ...s })), queen: { ...v.queen }, aimX: v.aimX, aimAssist: v.aimAssist,
      board: this.model.boardNow().map((b) => ({ ...b })),
      drawn: this.renderer.drawn.map((d) => ({ ...d })),
      canvas: { left: rect.left, top: rect.top, side: this.renderer.side, dpr: this.renderer.dpr },
      aim: {
        phase: this.aim.phase, x: this.aim.x, side: this.aim.baseline, striker: this.aim.striker(),
        y: this.aim.striker().y, legal: this.aim.placement.legal,
      },
      shotSentTurn: this.shotSentTurn, shots: this.model.shots, lastShot: this.model.lastShot,
      frames: this.renderer.frames, paints: this.renderer.painter.paints, woodMs: this.renderer.painter.woodMs, resizes: this.resizes.slice(), sounds: this.sound.played,
      cues: { heard: this.model.cuesHeard, late: this.model.cues.late, merged: this.model.cuesMerged },
      muted: this.settings.values.muted, settings: { ...this.settings.values }, audio: this.sound.context ? this.sound.context.state : 'none',
      hash: window.location.hash, logPlace: this.stage.dataset.log ?? null,
      releaseMs: this.releaseMs ?? null,
      engine: { loaded: Boolean(this.engine), ms: this.engineMs ?? null, error: this.engineError ?? null },
      prediction: this.model.prediction ? { active: this.model.prediction.active, ...this.model.prediction.stats } : null,
      emotes: {
        received: this.model.emotes.received, visible: this.model.emotes.visible(performance.now() / 1000),
        mutedSeats: [...this.model.emotes.mutedSeats], allMuted: this.model.emotes.allMuted,
      },
      assist: this.aimAssist.debugState(this.assist),
      ratings: this.seatRatings.debugState(),
    };
  }

  // Client (viewport) px of a board point, as the page maps it now.
  toClient(x, y) {
    const rect = this.canvas.getBoundingClientRect();
    const p = this.mapping().toScreen({ x, y });
    return { x: rect.left + p.x, y: rect.top + p.y };
  }
}

// `#/replay/ID` is the replay page (replay_page.js), without the lobby and the WebSocket.
const replayId = parseReplayHash(window.location.hash);
const app = replayId === null ? new App() : null;
if (replayId !== null) startReplayPage(replayId);
else window.carrom = Object.freeze({
  state: () => app.debugState(),
  toClient: (x, y) => app.toClient(x, y),
  frameTimes: () => app.frameLog.slice(),
  clearFrameTimes: () => { app.frameLog.length = 0; },
  // A cheap look (no layout, three fields) for a caller that polls while frames are timed.
  progress: () => ({ turn: app.model.view.turn, phase: app.model.view.phase, animating: app.model.animating() }),
});
app?.start();
