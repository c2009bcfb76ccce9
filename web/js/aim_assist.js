// The aim guide of practice and unrated games (room_state's aim_assist), the port of the desktop
// client's AimAssist (client/src/aim_assist.cpp, drawn by client/app/app_window_draw.cpp): for the
// shot a release would make now, the first piece the striker would touch, where the striker
// touches it and the direction that piece would take, from the exact engine (engine.js,
// firstContact) on the board the page holds. The answer for the same board, side and shot is
// kept, so a frame that changes none of them runs no simulation. docs/web.md, "Aim assist".
//
// The engine keeps one stroke and firstContact replaces it: nothing is asked while a prediction
// of the own stroke is active (prediction.js). Board px, y down; times in s, costs in ms.

import { PHYSICS, STRIKER_ID } from './physics_config.js';

export const AIM_ASSIST_LOOK = Object.freeze({
  maxRollPx: 200, // the piece's line is as long as it would roll freely (v / k), at most this
  path: 'rgba(150,230,255,0.78)', // the striker's path to the contact and its outline there
  piece: 'rgba(255,210,80,0.9)', // the piece's direction
});

// Shot time (s) after the contact at which the piece's speed is read from the trajectory: short
// enough that nothing else touches it meanwhile, long enough for a displacement far above
// rounding (at 10 px/s, 1e-3 px).
const SPEED_PROBE_S = 1e-4;

// Whether the guide is shown: the room allows it (absent reads as on), the reader holds a seat,
// the engine is loaded and no prediction of the own stroke is using it.
export function aimAssistAllowed({ aimAssist, you, engineLoaded, predicting }) {
  return aimAssist !== false && Number.isInteger(you) && you >= 0 && engineLoaded && !predicting;
}

export class AimAssist {
  constructor(physics = PHYSICS) {
    this.physics = physics;
    this.engine = null;
    this.key = null; // the last question (board, side, shot) as a string
    this.answer = null;
    // runs: engine runs; asked: questions (a repeated one runs nothing); lastMs / maxMs / totalMs:
    // the cost of the runs (performance.now()).
    this.stats = { asked: 0, runs: 0, lastMs: 0, maxMs: 0, totalMs: 0 };
  }

  setEngine(engine) {
    this.engine = engine;
    this.key = null;
  }

  // The guide for the page (app.js) while the player pulls: null when it is off (aimAssistAllowed)
  // or the placement is illegal, else guide() of the board drawn now.
  forPull(model, aim, shot) {
    const v = model.view;
    const allowed = aimAssistAllowed({
      aimAssist: v.aimAssist, you: v.you, engineLoaded: this.engine !== null,
      predicting: Boolean(model.prediction?.active),
    });
    if (!allowed || !aim.placement.legal) return null;
    return this.guide(model.boardNow(), aim.baseline, shot);
  }

  // The first contact of `shot` ({x, angle, power}) from `side` on `board` (at rest; a striker in
  // it is replaced by the shot's, placed as the server's rules place it): {id, t, striker: {x, y}
  // where the striker touches, piece: {x, y} the piece's centre, direction: unit {x, y}, speed
  // (px/s) just after the contact, rollPx, side, shot}, or null when the striker would touch
  // nothing or the engine refuses the scene.
  guide(board, side, shot) {
    const pieces = board.filter((b) => b.id !== STRIKER_ID && b.kind !== 'striker');
    const key = [side, shot.x, shot.angle, shot.power,
      ...pieces.map((b) => `${b.id}:${b.kind}:${b.x}:${b.y}:${b.pocketed ? 1 : 0}`)].join('|');
    this.stats.asked += 1;
    if (key === this.key) return this.answer;
    const started = performance.now();
    const hit = this.engine.firstContact(pieces, side, shot);
    this.answer = hit ? { ...this.describe(hit, pieces), side, shot: { ...shot } } : null;
    const ms = performance.now() - started;
    this.key = key;
    Object.assign(this.stats, {
      runs: this.stats.runs + 1, lastMs: ms, maxMs: Math.max(this.stats.maxMs, ms),
      totalMs: this.stats.totalMs + ms,
    });
    return this.answer;
  }

  // Every piece is at rest until the striker's first contact, so the piece's centre there is its
  // place on the board. Its speed just after comes from the stroke firstContact left in the engine:
  // under the damping dv/dt = -k v a piece starting at speed v covers v (1 - e^(-k h)) / k in h.
  describe(hit, pieces) {
    const at = pieces.find((b) => b.id === hit.id);
    const later = this.engine.stateAt(hit.t + SPEED_PROBE_S).find((b) => b.id === hit.id);
    const k = this.physics.dampingPerS;
    const moved = later ? Math.hypot(later.x - at.x, later.y - at.y) : 0;
    const speed = (moved * k) / -Math.expm1(-k * SPEED_PROBE_S);
    return {
      id: hit.id, t: hit.t, striker: hit.striker, piece: { x: at.x, y: at.y },
      direction: hit.direction, speed, rollPx: Math.min(speed / k, AIM_ASSIST_LOOK.maxRollPx),
    };
  }

  // Plain data for the debug hook.
  debugState(guide) {
    return { shown: Boolean(guide), guide: guide ? { ...guide } : null, stats: { ...this.stats } };
  }
}

// Draws `guide` on ctx (CSS px through the mapping m, the board turned per seat): the striker's
// path from `from` (its place on the baseline) to the contact, its outline there (radius
// strikerR, board px), and the piece's direction as long as it would roll with a dot at its end.
export function drawAimAssist(ctx, m, from, guide, strikerR) {
  const a = m.toScreen(from);
  const s = m.toScreen(guide.striker);
  const p = m.toScreen(guide.piece);
  const end = m.toScreen({
    x: guide.piece.x + guide.direction.x * guide.rollPx,
    y: guide.piece.y + guide.direction.y * guide.rollPx,
  });
  ctx.lineCap = 'round';
  ctx.strokeStyle = AIM_ASSIST_LOOK.path;
  ctx.lineWidth = Math.max(m.lengthToScreen(1.5), 1);
  ctx.beginPath();
  ctx.moveTo(a.x, a.y);
  ctx.lineTo(s.x, s.y);
  ctx.moveTo(s.x + m.lengthToScreen(strikerR), s.y);
  ctx.arc(s.x, s.y, m.lengthToScreen(strikerR), 0, 2 * Math.PI);
  ctx.stroke();
  ctx.strokeStyle = AIM_ASSIST_LOOK.piece;
  ctx.lineWidth = Math.max(m.lengthToScreen(2.5), 1.5);
  ctx.beginPath();
  ctx.moveTo(p.x, p.y);
  ctx.lineTo(end.x, end.y);
  ctx.stroke();
  ctx.fillStyle = AIM_ASSIST_LOOK.piece;
  ctx.beginPath();
  ctx.arc(end.x, end.y, Math.max(m.lengthToScreen(3), 2), 0, 2 * Math.PI);
  ctx.fill();
}
