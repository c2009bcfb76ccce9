// Snapshots in, the board at any server time out (client/src/interpolation_buffer.cpp;
// docs/interpolation.md). Keeps a short history of full board states (a delta is applied onto
// the previous state) and draws each body between the two states around the requested time
// along the damped free motion p(t) = p0 + v0 (1 - e^(-k dt)) / k when that explains both states
// (no change of motion between them, or exactly one, whose instant it solves for), else along a
// cubic Hermite curve through their positions and velocities; and animates a pocketed piece into
// its pocket (sliding to the pocket centre while it shrinks and fades).
//
// A body state: {id, kind, x, y, vx, vy, pocketed}; board px, px/s. Times: server match time, s.
// A rendered body: {id, kind, x, y, scale, alpha, falling}.

import { hermite } from './hermite.js';
import { nearestPocket, PHYSICS } from './board_geometry.js';

export const INTERPOLATION_DEFAULTS = Object.freeze({
  pocketAnim: 0.15, // time a piece takes to vanish into its pocket
  pocketEndScale: 0.35, // its size at the end of that animation
  holdGap: 0.25, // a longer gap after a board at rest is a jump, not a glide
  maxExtrapolation: 0.05, // past the newest state, along the free motion
  // the same when the server sends a delta at every change of motion (the free motion past the
  // newest state is then exact until the next delta arrives)
  maxExtrapolationEveryChange: 0.25,
  dampingPerS: PHYSICS.dampingPerS, // k of the free motion, 1/s
  freeMotionTolerance: 0.05, // px: how closely the free motion must explain a state
  history: 2.0, // states older than this behind the newest are dropped
});

// How far a body travels in dt along the damped free motion per px/s of velocity:
// (1 - e^(-k dt)) / k, dt for k = 0 (common/src/trajectory.cpp travel_factor_s). dt may be
// negative: the same motion run backwards.
export function travelFactor(k, dt) {
  if (k === 0) return dt;
  return -Math.expm1(-k * dt) / k;
}

// Where a body at (x, y) with velocity (vx, vy) is dt later along the free motion.
function freeMotion(x, y, vx, vy, k, dt) {
  const f = travelFactor(k, dt);
  return { x: x + vx * f, y: y + vy * f };
}

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
    this.everyChangeSent = false;
  }

  // The server's motion model (room_state "motion"): k, and whether it sends a delta at the
  // instant of every change of motion (contact, stop, pocketing).
  setMotion(dampingPerS, everyChangeSent) {
    this.config = { ...this.config, dampingPerS };
    this.everyChangeSent = everyChangeSent;
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
      const fall = {
        id: b.id, kind: b.kind, start: before.time, fromX: a.x, fromY: a.y, fromVx: a.vx,
        fromVy: a.vy, pocket: this.geometry.pockets[nearestPocket(this.geometry, heading)],
      };
      if (this.everyChangeSent) {
        // The pocketing is itself a change of motion: it happened at after's instant, and the
        // body got there along the free motion from before.
        const k = this.config.dampingPerS;
        const p = freeMotion(a.x, a.y, a.vx, a.vy, k, dt);
        const decay = Math.exp(-k * dt);
        Object.assign(fall, {
          start: after.time, fromX: p.x, fromY: p.y, fromVx: a.vx * decay, fromVy: a.vy * decay,
        });
      }
      this.falls.push(fall);
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
    const ba = findBody(a.bodies, bb.id);
    if (bb.pocketed) {
      if (this.everyChangeSent && ba !== null && !ba.pocketed && t < b.time) {
        // Pocketed at b's instant: until then it moves on freely from a.
        const p = freeMotion(ba.x, ba.y, ba.vx, ba.vy, this.config.dampingPerS, t - a.time);
        return rendered(bb, p.x, p.y);
      }
      return this.fallingBody(bb.id, t);
    }
    if (ba === null) return rendered(bb, bb.x, bb.y); // appears with the newer state
    if (ba.pocketed) return null; // back on the board from the newer state on
    const gap = b.time - a.time;
    if (gap > this.config.holdGap && a.atRest) return rendered(bb, ba.x, ba.y); // a jump
    const k = this.config.dampingPerS;
    const tol = this.config.freeMotionTolerance;
    const dtA = t - a.time;
    // No change of motion between a and b: the free motion from a reaches b.
    const reach = freeMotion(ba.x, ba.y, ba.vx, ba.vy, k, gap);
    if (Math.hypot(reach.x - bb.x, reach.y - bb.y) <= tol) {
      const p = freeMotion(ba.x, ba.y, ba.vx, ba.vy, k, dtA);
      return rendered(bb, p.x, p.y);
    }
    // One change of motion at an unknown instant c: forwards from a before c, backwards from b
    // after c. With u = e^(-k (t - t_a)) their difference is linear in u,
    //   d(u) = (p_a - p_b) + (v_a - v_b) / k + u (v_b e^(k gap) - v_a) / k,
    // and c is where it vanishes (solved in least squares; accepted when the residual is within
    // the tolerance).
    if (k > 0) {
      const d0x = ba.x - bb.x + (ba.vx - bb.vx) * (1 / k);
      const d0y = ba.y - bb.y + (ba.vy - bb.vy) * (1 / k);
      const grow = Math.exp(k * gap);
      const wx = (bb.vx * grow - ba.vx) * (1 / k);
      const wy = (bb.vy * grow - ba.vy) * (1 / k);
      const ww = wx * wx + wy * wy;
      if (ww > 0) {
        const u = Math.min(Math.max(-(d0x * wx + d0y * wy) / ww, Math.exp(-k * gap)), 1);
        if (Math.hypot(d0x + wx * u, d0y + wy * u) <= tol) {
          const change = a.time - Math.log(u) / k;
          const p = t <= change ? freeMotion(ba.x, ba.y, ba.vx, ba.vy, k, dtA)
            : freeMotion(bb.x, bb.y, bb.vx, bb.vy, k, t - b.time);
          return rendered(bb, p.x, p.y);
        }
      }
    }
    const s = Math.min(Math.max(dtA / gap, 0), 1);
    const p = hermite({ x: ba.x, y: ba.y }, { x: ba.vx, y: ba.vy }, { x: bb.x, y: bb.y },
      { x: bb.vx, y: bb.vy }, gap, s);
    return rendered(bb, p.x, p.y);
  }

  // The bodies to draw at server time t, sorted by id. Before the oldest state: the oldest;
  // after the newest: the newest, continued along the free motion for at most
  // maxExtrapolationEveryChange when the server sends every change of motion, else
  // maxExtrapolation.
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
      const c = this.config;
      const ahead = Math.min(t - last.time,
        this.everyChangeSent ? c.maxExtrapolationEveryChange : c.maxExtrapolation);
      for (const b of last.bodies) {
        if (!b.pocketed) {
          const p = freeMotion(b.x, b.y, b.vx, b.vy, c.dampingPerS, ahead);
          out.push(rendered(b, p.x, p.y));
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
