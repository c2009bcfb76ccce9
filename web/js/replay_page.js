// The replay page: `#/replay/ID` plays the stored match ID (the Match API's GET /matches/ID,
// docs/matches.md) back with the engine: the board drawn as in a game (seat 0's view), a bar with
// the players and their scores, board and stroke, and the controls of carrom-client --replay:
// play/pause (Space), previous/next stroke (Left/Right arrows), slower/faster 0.25x-4x (-/+,
// Down/Up), from the start (Home).
// A journal of another physics or rules version is refused with one sentence. The lobby and the
// WebSocket are not used. window.carrom.replay() is its debug hook.

import { makeBoardGeometry, PHYSICS } from './board_geometry.js';
import { loadEngine } from './engine.js';
import { Renderer } from './renderer.js';
import { gameEndSentence, pocketList } from './plain_words.js';
import { ReplayModel } from './replay_model.js';

// {id} of a `#/replay/ID` address (ID as the Match API accepts it), or null.
export function parseReplayHash(hash) {
  const m = /^#\/replay\/([0-9A-Za-z_-]{1,64})\/?$/.exec(hash ?? '');
  return m ? m[1] : null;
}

export function replayHash(id) {
  return `#/replay/${id}`;
}

// A Match API address on the page's server (its own origin, or the `ws` query parameter's host):
// path is `matches/ID` or `matches?player=...`.
export function matchApiUrl(path) {
  const ws = new URLSearchParams(window.location.search).get('ws');
  const base = ws ? ws.replace(/^ws/, 'http') : `${window.location.origin}/`;
  return new URL(path, base).toString();
}

function element(tag, props = {}, children = []) {
  const e = Object.assign(document.createElement(tag), props);
  e.append(...children);
  return e;
}

class ReplayPage {
  constructor(id) {
    this.id = id;
    this.model = null;
    this.error = null;
    this.engineMs = null;
    this.geometry = makeBoardGeometry(PHYSICS);
    this.renderer = new Renderer(document.getElementById('board'), document.getElementById('board-bg'), this.geometry);
    this.stage = document.getElementById('stage');
    this.lastTs = null;
    this.texts = new Map();
    this.buildBar();
  }

  buildBar() {
    document.getElementById('lobby').hidden = true;
    const button = (id, text, action) => {
      const b = element('button', { type: 'button', id, textContent: text });
      b.addEventListener('click', () => { action(); this.dirty = true; });
      return b;
    };
    this.bar = element('div', { id: 'replay-bar' }, [
      element('div', { id: 'replay-players' }),
      element('div', { id: 'replay-status' }),
      element('div', { id: 'replay-event' }),
      element('div', { className: 'buttons' }, [
        button('replay-prev', 'Previous', () => this.model?.previousTurn()),
        button('replay-play', 'Pause', () => this.model?.togglePlay()),
        button('replay-next', 'Next', () => this.model?.nextTurn()),
        button('replay-slower', 'Slower', () => this.model?.slower()),
        button('replay-faster', 'Faster', () => this.model?.faster()),
      ]),
    ]);
    document.getElementById('app').prepend(this.bar);
    window.addEventListener('keydown', (e) => {
      const m = this.model;
      if (!m) return;
      const keys = {
        ' ': () => m.togglePlay(), ArrowLeft: () => m.previousTurn(), ArrowRight: () => m.nextTurn(),
        '-': () => m.slower(), '+': () => m.faster(), '=': () => m.faster(),
        ArrowUp: () => m.faster(), ArrowDown: () => m.slower(), Home: () => m.restart(),
      };
      if (keys[e.key]) {
        keys[e.key]();
        e.preventDefault();
      }
    });
    window.addEventListener('hashchange', () => window.location.reload());
  }

  async start() {
    new ResizeObserver(() => this.layout()).observe(this.stage);
    this.layout();
    requestAnimationFrame((ts) => this.frame(ts));
    try {
      const started = performance.now();
      const [engine, answer] = await Promise.all([
        loadEngine().catch(() => null),
        fetch(matchApiUrl(`matches/${encodeURIComponent(this.id)}`)),
      ]);
      if (!engine) {
        this.fail('This page has no engine to replay matches with (its server was built without WebAssembly, or the browser has none).');
        return;
      }
      this.engineMs = performance.now() - started;
      const body = await answer.json().catch(() => null);
      if (!answer.ok) {
        this.fail(body?.error?.message ?? `The server has no match ${this.id} (HTTP ${answer.status}).`);
        return;
      }
      const loaded = ReplayModel.load(body, engine);
      if (loaded.error) this.fail(loaded.error);
      else {
        this.model = loaded.model;
        this.dirty = true;
      }
    } catch (e) {
      this.fail(`This match cannot be replayed here: ${e.message ?? e}.`);
    }
  }

  fail(sentence) {
    this.error = sentence;
    this.setText('replay-status', sentence);
    this.bar.classList.add('alert');
  }

  layout() {
    const side = Math.min(this.stage.clientWidth, this.stage.clientHeight);
    if (this.renderer.resize(side, window.devicePixelRatio || 1)) this.dirty = true;
  }

  setText(id, text) {
    if (this.texts.get(id) === text) return;
    this.texts.set(id, text);
    document.getElementById(id).textContent = text;
  }

  teamName(team) {
    const seats = this.model.journal.match.seats;
    const names = seats.filter((_, i) => (seats.length === 4 ? i % 2 : i) === team).map((s) => s.name);
    return names.join(' & ');
  }

  hudTexts() {
    const m = this.model;
    const state = m.stateNow();
    const seats = m.journal.match.seats;
    const teams = seats.length === 4 ? 2 : seats.length;
    const players = [];
    for (let t = 0; t < teams; t += 1) players.push(`${this.teamName(t)} ${state.scores[t]}`);
    this.setText('replay-players', players.join(' · '));
    let status = `Board ${state.board} · Stroke ${m.strokeNumber()} / ${m.strokes} · ${m.speed}x`;
    if (m.finished()) {
      const r = m.finalResult();
      status += r.winner === null ? ' · the game did not end'
        : r.winner < 0 ? ' · a draw' : ` · ${this.teamName(r.winner)} won`;
    }
    if (m.mismatches > 0) status += ` · ${m.mismatches} inputs replay differently from the record`;
    this.setText('replay-status', status);
    this.setText('replay-event', this.eventText());
    this.setText('replay-play', m.playing ? 'Pause' : 'Play');
  }

  // What the input shown did, once its motion is over, in the game's words: the pocketed pieces,
  // fouls, a board's or the game's end (as the journal recorded them).
  eventText() {
    const m = this.model;
    if (m.turns.length === 0) return '';
    const turn = m.turns[m.turnAt(m.time)];
    if (m.time < turn.rest) return '';
    const entry = m.journal.entries[turn.entry];
    const o = entry.outcome;
    const seats = m.journal.match.seats;
    const who = seats[entry.seat]?.name ?? `Seat ${entry.seat + 1}`;
    const doubles = seats.length === 4;
    const parts = [];
    if (entry.type === 'stroke') {
      const kinds = o.pocketed.map((id) => turn.before.find((b) => b.id === id)?.kind ?? 'black');
      parts.push(`${who} pocketed ${pocketList(kinds)}`);
    } else {
      parts.push(entry.type === 'forfeit' ? `${who} forfeited` : `${who} ran out of time`);
    }
    if (o.fouls.length > 0) parts.push(`foul: ${o.fouls.join(', ').replaceAll('_', ' ')}`);
    if (o.board_end) {
      parts.push(o.board_end.winner_team === null ? `board ${o.board_end.board} ends, no winner`
        : `board ${o.board_end.board} to ${this.teamName(o.board_end.winner_team)} (+${o.board_end.points})`);
    }
    if (o.game_end) {
      const w = o.game_end.winner_team ?? -1;
      parts.push(gameEndSentence(w, false, w >= 0 ? this.teamName(w) : '', o.game_end.reason, true, doubles));
    }
    return parts.join(' · ');
  }

  frame(ts) {
    const wall = this.lastTs === null ? 0 : (ts - this.lastTs) / 1000;
    this.lastTs = ts;
    const m = this.model;
    if (m) {
      const before = m.time;
      m.advance(Math.min(wall, 0.25));
      if (m.time !== before || this.dirty) {
        this.bodies = m.bodies().filter((b) => !b.pocketed)
          .map((b) => ({ id: b.id, kind: b.kind, x: b.x, y: b.y, scale: 1, alpha: 1, falling: false }));
        this.renderer.draw({ bodies: this.bodies, turns: 0, placing: null, aim: null, grabHint: false });
        this.dirty = false;
      }
      this.hudTexts();
    } else if (this.dirty) {
      this.renderer.drawEmpty();
      this.dirty = false;
    }
    requestAnimationFrame((t) => this.frame(t));
  }

  // The debug hook's picture (plain data).
  debugState() {
    const m = this.model;
    return {
      id: this.id, error: this.error, loaded: Boolean(m), engineMs: this.engineMs,
      ...(m ? {
        time: m.time, duration: m.duration, playing: m.playing, speed: m.speed, finished: m.finished(),
        strokes: m.strokes, stroke: m.strokeNumber(), inputs: m.turns.length, mismatches: m.mismatches,
        bitDifferences: m.bitDifferences,
        state: m.stateNow(), final: m.finalResult(), drawn: this.renderer.drawn.map((d) => ({ ...d })),
        board: m.bodies().map((b) => ({ ...b })),
      } : {}),
    };
  }
}

export function startReplayPage(id) {
  document.body.classList.add('replay');
  const page = new ReplayPage(id);
  window.carrom = Object.freeze({ replay: () => page.debugState() });
  page.start();
}
