// The board as the server simulates it and its markings (client/src/board_geometry.cpp). Board
// px, origin at the top-left corner, y down. PHYSICS and STRIKER_ID are the server's own
// (physics_config.js, generated from common/include/carrom/config.hpp and scene.hpp).

import { PHYSICS, STRIKER_ID } from './physics_config.js';

export { PHYSICS, STRIKER_ID };

export function radiusOf(kind, c = PHYSICS) {
  return kind === 'striker' ? c.strikerRadius : c.coinRadius;
}

// Whether a side's baseline runs down the board (left, right) rather than across it.
export function sideways(side) {
  return side === 'left' || side === 'right';
}

// A board point's coordinate along a side's baseline: x for bottom and top, y for left and right
// (the protocol's shot and aim `x`).
export function alongOf(side, p) {
  return sideways(side) ? p.y : p.x;
}

// The striker's centre on a side's baseline ('bottom', 'right', 'top', 'left') at `along`
// (rules::striker_for): baselines at baselineOffset from their edge.
export function strikerAt(side, along, c = PHYSICS) {
  const near = c.baselineOffset;
  const far = c.boardSize - c.baselineOffset;
  switch (side) {
    case 'top': return { x: along, y: near };
    case 'left': return { x: near, y: along };
    case 'right': return { x: far, y: along };
    default: return { x: along, y: far };
  }
}

export function baselineXMin(c = PHYSICS) {
  return c.frame + c.baselineEndMargin + c.strikerRadius;
}

export function baselineXMax(c = PHYSICS) {
  return c.boardSize - baselineXMin(c);
}

// Pocket centres: top-left, top-right, bottom-left, bottom-right.
export function pocketCentres(c = PHYSICS) {
  const lo = c.frame + c.pocketRadius;
  const hi = c.boardSize - lo;
  return [{ x: lo, y: lo }, { x: hi, y: lo }, { x: lo, y: hi }, { x: hi, y: hi }];
}

// Baseline markings: the centre line from start to end (end circle centres), the unit normal
// towards the board centre, the half gap between the two drawn lines. Bottom, top, left, right.
function baselines(c) {
  const near = c.baselineOffset;
  const far = c.boardSize - c.baselineOffset;
  const lo = c.frame + c.baselineEndMargin + c.strikerRadius;
  const hi = c.boardSize - lo;
  const g = 0.77 * c.strikerRadius; // ICF: the gap is 0.77 of the striker diameter
  return [
    { start: { x: lo, y: far }, end: { x: hi, y: far }, normal: { x: 0, y: -1 }, halfGap: g, endR: g },
    { start: { x: lo, y: near }, end: { x: hi, y: near }, normal: { x: 0, y: 1 }, halfGap: g, endR: g },
    { start: { x: near, y: lo }, end: { x: near, y: hi }, normal: { x: 1, y: 0 }, halfGap: g, endR: g },
    { start: { x: far, y: lo }, end: { x: far, y: hi }, normal: { x: -1, y: 0 }, halfGap: g, endR: g },
  ];
}

// A diagonal arrow from near a pocket towards the centre, with an arc at its inner end.
function arrow(pocket, centre, c) {
  const dx = centre.x - pocket.x;
  const dy = centre.y - pocket.y;
  const len = Math.hypot(dx, dy);
  const d = { x: dx / len, y: dy / len };
  const at = (k) => ({ x: pocket.x + d.x * k, y: pocket.y + d.y * k });
  return {
    tip: at(c.pocketRadius + 1.2 * c.coinRadius),
    tail: at(c.pocketRadius + 10.5 * c.coinRadius),
    head: 0.6 * c.coinRadius,
    arcR: 1.3 * c.coinRadius,
  };
}

export function makeBoardGeometry(c = PHYSICS) {
  const centre = { x: c.boardSize / 2, y: c.boardSize / 2 };
  const pockets = pocketCentres(c);
  return {
    boardSize: c.boardSize,
    frame: c.frame,
    pocketR: c.pocketRadius,
    coinR: c.coinRadius,
    strikerR: c.strikerRadius,
    pockets,
    centre,
    centreCircleR: c.coinRadius,
    outerCircleR: 6 * c.coinRadius, // encloses the starting layout's outer ring
    baselines: baselines(c),
    arrows: pockets.map((p) => arrow(p, centre, c)),
  };
}

// Index of the pocket whose centre is nearest to p.
export function nearestPocket(geometry, p) {
  let best = 0;
  let bestD2 = Infinity;
  geometry.pockets.forEach((q, i) => {
    const d2 = (p.x - q.x) ** 2 + (p.y - q.y) ** 2;
    if (d2 < bestD2) {
      bestD2 = d2;
      best = i;
    }
  });
  return best;
}
