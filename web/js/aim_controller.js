// Pointer input -> a shot, in board px (client/src/aim_controller.cpp). The page maps canvas px
// to board px first, so the same logic works for a turned view, a mouse or a finger.
//
// On the player's turn the striker sits on their baseline (any of the four sides: `x` is the
// position along it, as the protocol's shot: board x for bottom and top, board y for left and
// right; the angle is the board's absolute angle):
//  - press in the baseline band (not on the striker) and drag: the striker follows along the
//    baseline, clamped to the legal range; arrow keys move it in fine steps;
//  - press on the striker and pull back: the shot goes from the pointer towards the striker, its
//    power grows with the pull up to max power; release shoots; Escape, a second finger or the
//    Cancel button cancels, and a pull shorter than the dead zone is no shot.
// An illegal placement (overlapping a piece) is shown before release and never shoots.

import {
  alongOf, baselineXMax, baselineXMin, PHYSICS, radiusOf, sideways, strikerAt,
} from './board_geometry.js';

export const AIM_DEFAULTS = Object.freeze({
  fullPowerDrag: 160, // pull length (board px) that gives max power
  deadZone: 12, // shorter pulls shoot nothing
  grabFactor: 1.5, // the striker is grabbed within this many radii
  slideBand: 45, // presses this close to the baseline slide the striker
  fineStep: 1, // one arrow key press
  coarseStep: 10, // with Shift
});

export function clampBaselineX(x, c = PHYSICS) {
  if (!Number.isFinite(x)) return c.boardSize / 2;
  return Math.min(Math.max(x, baselineXMin(c)), baselineXMax(c));
}

// Power for a pull of `drag` board px: 0 inside the dead zone, linear above it, capped.
export function powerFromDrag(drag, aim = AIM_DEFAULTS, c = PHYSICS) {
  if (!(drag >= aim.deadZone)) return 0;
  const fraction = Math.min((drag - aim.deadZone) / (aim.fullPowerDrag - aim.deadZone), 1);
  return fraction * c.maxPower;
}

// Whether a striker at p overlaps an unpocketed piece (the striker itself is ignored).
export function checkPlacement(p, bodies, c = PHYSICS) {
  for (const b of bodies) {
    if (b.pocketed || b.kind === 'striker') continue;
    const minD = c.strikerRadius + radiusOf(b.kind, c);
    if ((b.x - p.x) ** 2 + (b.y - p.y) ** 2 < minD * minD) return { legal: false, blockingId: b.id };
  }
  return { legal: true, blockingId: -1 };
}

export class AimController {
  constructor(physics = PHYSICS, aim = AIM_DEFAULTS) {
    this.c = physics;
    this.aim = aim;
    this.phase = 'inactive'; // inactive | idle | sliding | pulling
    this.baseline = 'bottom';
    this.x = physics.boardSize / 2;
    this.pointer = { x: 0, y: 0 };
    this.placement = { legal: true, blockingId: -1 };
    this.moved = false;
  }

  // Our turn starts: the striker goes to x along our baseline (clamped). baseline: the seat's
  // side, 'bottom', 'right', 'top' or 'left'.
  beginTurn(baseline, x) {
    this.baseline = baseline;
    this.x = clampBaselineX(x, this.c);
    this.phase = 'idle';
    this.placement = { legal: true, blockingId: -1 };
    this.moved = false;
  }

  endTurn() {
    this.phase = 'inactive';
  }

  striker() {
    return strikerAt(this.baseline, this.x, this.c);
  }

  setX(x, pieces) {
    const clamped = clampBaselineX(x, this.c);
    if (clamped !== this.x) {
      this.x = clamped;
      this.moved = true;
    }
    this.placement = checkPlacement(this.striker(), pieces, this.c);
  }

  // minGrab: the smallest grab radius in board px (a finger needs a larger target than a mouse).
  pointerDown(p, pieces, minGrab = 0) {
    if (this.phase !== 'idle' || !Number.isFinite(p.x) || !Number.isFinite(p.y)) return;
    this.pointer = p;
    const s = this.striker();
    const grab = Math.max(this.aim.grabFactor * this.c.strikerRadius, minGrab);
    if ((p.x - s.x) ** 2 + (p.y - s.y) ** 2 <= grab * grab) {
      this.phase = 'pulling';
      this.placement = checkPlacement(s, pieces, this.c);
    } else if (this.acrossDistance(p, s) <= Math.max(this.aim.slideBand, minGrab)) {
      this.phase = 'sliding';
      this.setX(alongOf(this.baseline, p), pieces);
    }
  }

  pointerMove(p, pieces) {
    if (!Number.isFinite(p.x) || !Number.isFinite(p.y)) return;
    this.pointer = p;
    if (this.phase === 'sliding') this.setX(alongOf(this.baseline, p), pieces);
  }

  // Returns the shot {x, angle, power} to send, or null.
  pointerUp(p, pieces) {
    this.pointerMove(p, pieces);
    if (this.phase === 'sliding') {
      this.phase = 'idle';
      return null;
    }
    if (this.phase !== 'pulling') return null;
    this.phase = 'idle';
    this.placement = checkPlacement(this.striker(), pieces, this.c);
    const shot = this.pendingShot();
    if (!this.placement.legal || shot.power <= 0) return null;
    return shot;
  }

  // How far p is from the baseline through s, across it.
  acrossDistance(p, s) {
    return sideways(this.baseline) ? Math.abs(p.x - s.x) : Math.abs(p.y - s.y);
  }

  // Arrow keys: +1 or -1 steps along the baseline (board x, or board y for a side baseline).
  nudge(direction, coarse, pieces) {
    if (this.phase !== 'idle' && this.phase !== 'sliding') return;
    const step = coarse ? this.aim.coarseStep : this.aim.fineStep;
    this.setX(this.x + step * direction, pieces);
  }

  // Drop the pull or the slide, keeping the striker where it is.
  cancel() {
    if (this.phase === 'pulling' || this.phase === 'sliding') this.phase = 'idle';
  }

  // The shot a release would make now (meaningful while pulling).
  pendingShot() {
    const s = this.striker();
    const px = s.x - this.pointer.x;
    const py = s.y - this.pointer.y;
    return {
      x: this.x,
      angle: Math.atan2(py, px),
      power: powerFromDrag(Math.hypot(px, py), this.aim, this.c),
    };
  }

  powerFraction() {
    return this.c.maxPower > 0 ? this.pendingShot().power / this.c.maxPower : 0;
  }

  // True once after the striker x changed (to tell the server the aim moved).
  takeMoved() {
    const m = this.moved;
    this.moved = false;
    return m;
  }
}
