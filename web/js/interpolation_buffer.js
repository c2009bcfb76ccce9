// Snapshots in, the board at any server time out (client/src/interpolation_buffer.cpp;
// docs/interpolation.md). Keeps a short history of full board states (a delta is applied onto
// the previous state), interpolates each body between the two states around the requested time
// with a cubic Hermite curve through their positions and velocities, and animates a pocketed
// piece into its pocket (sliding to the pocket centre while it shrinks and fades).
//
// A body state: {id, kind, x, y, vx, vy, pocketed}; board px, px/s. Times: server match time, s.
// A rendered body: {id, kind, x, y, scale, alpha, falling}.

import { hermite } from './hermite.js';
import { nearestPocket } from './board_geometry.js';

export const INTERPOLATION_DEFAULTS = Object.freeze({
  pocketAnim: 0.15, // time a piece takes to vanish into its pocket
  pocketEndScale: 0.35, // its size at the end of that animation
  holdGap: 0.25, // a longer gap after a board at rest is a jump, not a glide
  maxExtrapolation: 0.05,
  history: 2.0, // states older than this behind the newest are dropped
});

const byId = (a, b) => a.id - b.id;

function findBody(bodies, id) {
  let lo = 0;
  let hi = bodies.length;
  while (lo < hi) {
    const mid = (lo + hi) >> 1;
    if (bodies[mid].id < id) lo = mid + 1;
    else hi = mid;
  }
  return lo < bodies.length && bodies[lo].id === id ? bodies[lo] : null;
}

function allAtRest(bodies) {
  return bodies.every((b) => b.pocketed || (b.vx === 0 && b.vy === 0));
}

// Listed bodies replace (or join) the previous ones; the rest keep their place and are at rest
// (a body that moved would have been listed).
function applyDelta(previous, changed) {
  const out = previous.map((b) => ({ ...b, vx: 0, vy: 0 }));
  for (const c of changed) {
    const i = out.findIndex((b) => b.id >= c.id);
    if (i >= 0 && out[i].id === c.id) out[i] = c;
    else if (i >= 0) out.splice(i, 0, c);
    else out.push(c);
  }
  return out;
}

const rendered = (b, x, y) => ({ id: b.id, kind: b.kind, x, y, scale: 1, alpha: 1, falling: false });

export class InterpolationBuffer {
  constructor(geometry, config = INTERPOLATION_DEFAULTS) {
    this.geometry = geometry;
    this.config = config;
    this.frames = []; // {seq, time, bodies (sorted by id), atRest}
    this.falls = []; // {id, kind, start, fromX, fromY, fromVx, fromVy, pocket}
  }

  clear() {
    this.frames = [];
    this.falls = [];
  }

  empty() {
    return this.frames.length === 0;
  }

  newestTime() {
    return this.frames.length === 0 ? 0 : this.frames[this.frames.length - 1].time;
  }

  newestState() {
    return this.frames.length === 0 ? null : this.frames[this.frames.length - 1].bodies;
  }

  // snapshot: {seq, time, keyframe, bodies}. A delta needs a previous state; a snapshot older
  // than (or as old as) the newest one is ignored. Returns false if ignored.
  push(snapshot) {
    if (!Number.isFinite(snapshot.time)) return false;
    if (this.frames.length > 0) {
      const last = this.frames[this.frames.length - 1];
      if (snapshot.seq <= last.seq) return false; // duplicate or reordered
      if (snapshot.time < last.time) {
        if (!snapshot.keyframe) return false;
        this.clear(); // the server's clock restarted (a new match): start over
      }
    }
    if (this.frames.length === 0 && !snapshot.keyframe) return false;
    const frame = { seq: snapshot.seq, time: snapshot.time, bodies: null, atRest: true };
    if (snapshot.keyframe) {
      frame.bodies = [...snapshot.bodies].sort(byId);
    } else {
      const changed = [...snapshot.bodies].sort(byId);
      frame.bodies = applyDelta(this.frames[this.frames.length - 1].bodies, changed);
    }
    frame.atRest = allAtRest(frame.bodies);
    if (this.frames.length > 0) {
      const last = this.frames[this.frames.length - 1];
      this.recordFalls(last, frame);
      if (frame.time === last.time) this.frames.pop(); // same instant, newer data
    }
    this.frames.push(frame);
    this.trim();
    return true;
  }

  recordFalls(before, after) {
    const dt = after.time - before.time;
    for (const b of after.bodies) {
      const a = findBody(before.bodies, b.id);
      if (!b.pocketed || a === null || a.pocketed) continue;
      const heading = { x: a.x + a.vx * dt, y: a.y + a.vy * dt };
      this.falls.push({
        id: b.id, kind: b.kind, start: before.time, fromX: a.x, fromY: a.y, fromVx: a.vx,
        fromVy: a.vy, pocket: this.geometry.pockets[nearestPocket(this.geometry, heading)],
      });
    }
  }

  trim() {
    const keepFrom = this.frames[this.frames.length - 1].time - this.config.history;
    while (this.frames.length > 2 && this.frames[1].time <= keepFrom) this.frames.shift();
    const fallFrom = this.frames[0].time - this.config.pocketAnim;
    this.falls = this.falls.filter((f) => f.start >= fallFrom);
  }

  fallingBody(id, t) {
    let fall = null;
    for (const f of this.falls) {
      if (f.id === id && f.start <= t && (fall === null || f.start > fall.start)) fall = f;
    }
    if (fall === null) return null;
    const elapsed = t - fall.start;
    const u = elapsed / this.config.pocketAnim;
    if (u >= 1) return null;
    // The piece keeps its speed towards the pocket centre but gets there by the end at the latest.
    const tx = fall.pocket.x - fall.fromX;
    const ty = fall.pocket.y - fall.fromY;
    const dist = Math.hypot(tx, ty);
    const eased = u * u * (3 - 2 * u);
    const bySpeed = dist > 0 ? (Math.hypot(fall.fromVx, fall.fromVy) * elapsed) / dist : 1;
    const progress = Math.min(1, Math.max(eased, bySpeed));
    return {
      id, kind: fall.kind, x: fall.fromX + tx * progress, y: fall.fromY + ty * progress,
      scale: 1 - (1 - this.config.pocketEndScale) * u, alpha: 1 - u, falling: true,
    };
  }

  bodyBetween(a, b, bb, t) {
    if (bb.pocketed) return this.fallingBody(bb.id, t);
    const ba = findBody(a.bodies, bb.id);
    if (ba === null) return rendered(bb, bb.x, bb.y); // appears with the newer state
    if (ba.pocketed) return null; // back on the board from the newer state on
    const gap = b.time - a.time;
    if (gap > this.config.holdGap && a.atRest) return rendered(bb, ba.x, ba.y); // a jump
    const s = Math.min(Math.max((t - a.time) / gap, 0), 1);
    const p = hermite({ x: ba.x, y: ba.y }, { x: ba.vx, y: ba.vy }, { x: bb.x, y: bb.y },
      { x: bb.vx, y: bb.vy }, gap, s);
    return rendered(bb, p.x, p.y);
  }

  // The bodies to draw at server time t, sorted by id. Before the oldest state: the oldest;
  // after the newest: the newest, extrapolated for at most maxExtrapolation.
  sample(t) {
    const out = [];
    const frames = this.frames;
    if (frames.length === 0) return out;
    let after = 0; // first frame with time > t
    while (after < frames.length && frames[after].time <= t) after += 1;
    if (after === 0) {
      for (const b of frames[0].bodies) if (!b.pocketed) out.push(rendered(b, b.x, b.y));
      return out;
    }
    if (after === frames.length) {
      const last = frames[frames.length - 1];
      const ahead = Math.min(t - last.time, this.config.maxExtrapolation);
      for (const b of last.bodies) {
        if (!b.pocketed) {
          out.push(rendered(b, b.x + b.vx * ahead, b.y + b.vy * ahead));
        } else {
          const fall = this.fallingBody(b.id, t);
          if (fall) out.push(fall);
        }
      }
      return out;
    }
    const b = frames[after];
    const a = frames[after - 1];
    for (const bb of b.bodies) {
      const r = this.bodyBetween(a, b, bb, t);
      if (r) out.push(r);
    }
    return out;
  }
}
