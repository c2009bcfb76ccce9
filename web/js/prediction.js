// The shooter's own stroke, simulated on release with the exact engine (engine.js) from the board
// the page holds and drawn from the next frame on, instead of a round trip later: the port of the
// desktop client's ShotPrediction (client/src/shot_prediction.cpp; docs/interpolation.md, "Shot
// prediction"). The server's snapshots of the stroke take over: for each body the difference
// between the server's state and the predicted one at the same shot time is measured on every
// snapshot, and the drawn offset moves linearly to it within blendS: each change of a
// difference over stepPx is faded in over blendS, smaller ones at once. A body whose difference
// exceeds correctionPx (or whose pocketing differs) counts once per stroke as a correction.
// Times: the continuous timeline (s) for the board, the local clock (s) for the blends.
//
// The engine keeps one stroke: while a prediction is active nothing else may simulate on it.

export const PREDICTION_DEFAULTS = Object.freeze({
  blendS: 0.1, // time the drawn state takes to reach the server's
  correctionPx: 0.5, // a larger difference counts as a correction
  cueToleranceS: 0.005, // a server sound cue this close to a predicted one is the same
  stepPx: 0.1, // smaller changes of a difference are drawn at once
});

const CUE_KINDS = { collision: 'click', cushion: 'cushion', pocket: 'pocket' };

export class ShotPrediction {
  constructor(engine, loudness, config = PREDICTION_DEFAULTS) {
    this.engine = engine;
    this.loudness = loudness; // impulse -> volume 0..1 (sound_cues.js)
    this.config = config;
    this.active = false;
    this.confirmed = false;
    this.serverDone = false;
    this.turn = -1;
    this.offset = 0;
    this.events = [];
    this.claimed = [];
    this.blends = new Map(); // id -> {target: {x, y}, fades: [{x, y, start}], serverPocketed, counted}
    // simulateMs: the last stroke's simulation on release (ms), the page's cost of a prediction.
    this.stats = { strokes: 0, corrections: 0, maxDifferencePx: 0, strokeMaxDifferencePx: 0, simulateMs: 0 };
  }

  // Simulates the stroke of `turn` from `board` (at rest; a striker in it is replaced) for the
  // seat's side and shot {x, angle, power}; its t = 0 is `offset` on the continuous timeline.
  // False (nothing predicted) when the engine refuses the scene: the server refuses the shot too.
  start(turn, board, side, shot, offset) {
    this.active = false;
    const started = performance.now();
    const r = this.engine.simulate(board, side, shot);
    this.stats.simulateMs = performance.now() - started;
    if (r.error) return false;
    Object.assign(this, {
      active: true, confirmed: false, serverDone: false, turn, offset, events: r.events,
    });
    this.claimed = r.events.map(() => false);
    this.blends.clear();
    this.stats.strokes += 1;
    this.stats.strokeMaxDifferencePx = 0;
    return true;
  }

  stop() {
    this.active = false;
  }

  // Forgets the prediction (a refused shot, a reset).
  drop() {
    this.active = false;
    this.turn = -1;
  }

  markServerDone() {
    this.serverDone = true;
    this.confirmed = true;
  }

  blend(id) {
    let b = this.blends.get(id);
    if (!b) {
      b = { target: { x: 0, y: 0 }, fades: [], serverPocketed: false, counted: false };
      this.blends.set(id, b);
    }
    return b;
  }

  drawnOffset(b, localS) {
    let { x, y } = b.target;
    for (const f of b.fades) {
      const u = (localS - f.start) / this.config.blendS;
      if (u < 1) {
        x -= f.x * (1 - Math.max(u, 0));
        y -= f.y * (1 - Math.max(u, 0));
      }
    }
    return { x, y };
  }

  // The server's full board ({id, x, y, pocketed}) at shot time shotT (the snapshot's own t),
  // arrived at localS.
  confirm(server, shotT, localS) {
    if (!this.active) return;
    this.confirmed = true;
    const predicted = new Map(this.engine.stateAt(shotT).map((p) => [p.id, p]));
    const c = this.config;
    for (const s of server) {
      const p = predicted.get(s.id);
      if (!p) continue;
      const dx = s.x - p.x;
      const dy = s.y - p.y;
      const size = s.pocketed && p.pocketed ? 0 : Math.hypot(dx, dy);
      const b = this.blend(s.id);
      b.serverPocketed = s.pocketed;
      this.stats.maxDifferencePx = Math.max(this.stats.maxDifferencePx, size);
      this.stats.strokeMaxDifferencePx = Math.max(this.stats.strokeMaxDifferencePx, size);
      if ((size > c.correctionPx || s.pocketed !== p.pocketed) && !b.counted) {
        b.counted = true;
        this.stats.corrections += 1;
      }
      if (s.pocketed || p.pocketed) continue;
      b.fades = b.fades.filter((f) => localS - f.start < c.blendS);
      const step = { x: dx - b.target.x, y: dy - b.target.y };
      if (Math.hypot(step.x, step.y) > c.stepPx) b.fades.push({ ...step, start: localS });
      b.target = { x: dx, y: dy };
    }
  }

  // Some body's drawn offset is still moving towards the server's.
  blending(localS) {
    for (const b of this.blends.values()) {
      if (b.fades.some((f) => localS - f.start < this.config.blendS)) return true;
    }
    return false;
  }

  // The bodies to draw at continuous time t ({id, kind, x, y, scale, alpha, falling}). `server`:
  // the server's sample at t when its states reach t, else null (the prediction is drawn, each
  // body offset by its blend).
  draw(t, localS, server) {
    if (server) {
      return server.map((r) => {
        const b = this.blends.get(r.id);
        if (!b || r.falling) return r;
        const o = this.drawnOffset(b, localS);
        const rx = o.x - b.target.x;
        const ry = o.y - b.target.y;
        return rx === 0 && ry === 0 ? r : { ...r, x: r.x + rx, y: r.y + ry };
      });
    }
    const out = [];
    for (const p of this.engine.stateAt(t - this.offset)) {
      const b = this.blends.get(p.id);
      if (p.pocketed || (b && b.serverPocketed)) continue;
      const o = b ? this.drawnOffset(b, localS) : { x: 0, y: 0 };
      out.push({ id: p.id, kind: p.kind, x: p.x + o.x, y: p.y + o.y, scale: 1, alpha: 1, falling: false });
    }
    return out;
  }

  // The predicted collision, cushion and pocket sounds ({time, kind, volume}, continuous time).
  cues() {
    const out = [];
    for (const e of this.events) {
      const kind = CUE_KINDS[e.kind];
      if (!kind) continue;
      const volume = kind === 'pocket' ? 1 : (kind === 'cushion' ? 0.8 : 1) * this.loudness(e.impulse);
      if (volume > 0) out.push({ time: this.offset + e.t, kind, volume });
    }
    return out;
  }

  // True when a server sound of `turn` at shot time t matches a predicted one not yet claimed
  // (it was played already and must not play twice).
  claimCue(turn, kind, t) {
    if (turn !== this.turn) return false;
    for (let i = 0; i < this.events.length; i += 1) {
      const e = this.events[i];
      if (!this.claimed[i] && CUE_KINDS[e.kind] === kind && Math.abs(e.t - t) <= this.config.cueToleranceS) {
        this.claimed[i] = true;
        return true;
      }
    }
    return false;
  }
}
