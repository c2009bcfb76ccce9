// A simple shot maker for test players (they must finish matches, not play well): for every
// coin, pocket and striker position on the baseline, aim the striker at the ghost-ball point
// that sends the coin straight at the pocket; keep shots whose striker and coin paths are clear
// and whose cut is at most 60 degrees, and take the straightest, shortest one. Board px.

const STRIKER_R = 18;
const COIN_R = 14;
const X_MIN = 113;
const X_MAX = 487;
const POCKETS = [{ x: 57, y: 57 }, { x: 543, y: 57 }, { x: 57, y: 543 }, { x: 543, y: 543 }];

function segmentDistance(p, a, b) {
  const dx = b.x - a.x;
  const dy = b.y - a.y;
  const len2 = dx * dx + dy * dy;
  const t = len2 > 0 ? Math.min(Math.max(((p.x - a.x) * dx + (p.y - a.y) * dy) / len2, 0), 1) : 0;
  return Math.hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

const unit = (v) => {
  const l = Math.hypot(v.x, v.y);
  return { x: v.x / l, y: v.y / l };
};

// The striker on a side's baseline at `along` (board x for bottom and top, y for left and right).
function strikerAt(side, along) {
  return {
    bottom: { x: along, y: 520 }, top: { x: along, y: 80 }, left: { x: 80, y: along }, right: { x: 520, y: along },
  }[side];
}

// The angle from a side's baseline straight into the board.
const INWARD = { bottom: -Math.PI / 2, right: Math.PI, top: Math.PI / 2, left: 0 };

// board: [{id, kind, x, y, pocketed}]; side: 'bottom', 'right', 'top', 'left', or the baseline's
// board y in singles (520 bottom, 80 top).
// Returns {x, angle, power} and `why` (which coin into which pocket, or 'fallback'); x is the
// position along the baseline, as the protocol's shot.
export function chooseShot(board, side, seed = 0) {
  if (typeof side === 'number') side = side > 300 ? 'bottom' : 'top';
  const pieces = board.filter((b) => !b.pocketed && b.kind !== 'striker');
  let best = null;
  for (let x = X_MIN; x <= X_MAX; x += 3) {
    const s = strikerAt(side, x);
    if (pieces.some((q) => Math.hypot(q.x - s.x, q.y - s.y) < STRIKER_R + COIN_R + 1)) continue;
    for (const c of pieces) {
      for (const p of POCKETS) {
        const u = unit({ x: p.x - c.x, y: p.y - c.y });
        const g = { x: c.x - u.x * (COIN_R + STRIKER_R), y: c.y - u.y * (COIN_R + STRIKER_R) };
        const d = unit({ x: g.x - s.x, y: g.y - s.y });
        const cut = d.x * u.x + d.y * u.y;
        if (cut < 0.5) continue;
        const others = pieces.filter((q) => q.id !== c.id);
        if (others.some((q) => segmentDistance(q, s, g) < STRIKER_R + COIN_R + 1)) continue;
        if (others.some((q) => segmentDistance(q, c, p) < 2 * COIN_R + 1)) continue;
        const travel = Math.hypot(g.x - s.x, g.y - s.y) + Math.hypot(p.x - c.x, p.y - c.y);
        const score = cut * 2 - travel / 600;
        if (!best || score > best.score) {
          best = { score, x, angle: Math.atan2(d.y, d.x), travel, why: `coin ${c.id} to pocket ${POCKETS.indexOf(p)}` };
        }
      }
    }
  }
  if (best) {
    // Enough speed for the travel with some to spare, well below full power.
    const power = Math.min(9 + best.travel / 60, 17);
    return { x: best.x, angle: best.angle, power, why: best.why };
  }
  const x = X_MIN + ((seed * 97) % (X_MAX - X_MIN));
  const angle = INWARD[side] + (side === 'top' ? -0.3 : 0.3);
  return { x, angle, power: 18, why: 'fallback' };
}
