// Board px <-> canvas CSS px. The board is a square at (originX, originY) of side
// boardSize * scale, turned by a number of quarter turns so that every player's own baseline is
// at the bottom (client/src/screen_mapping.cpp): 0 for the bottom seat, 1 for the right one
// (board +x points down the screen), 2 for the top one (a half turn), 3 for the left one. Each
// quarter turn takes the board direction (x, y) to (-y, x) on the screen (y down), so the seats
// keep their anticlockwise order on every screen.

export const SIDES = Object.freeze(['bottom', 'right', 'top', 'left']);

// Quarter turns of the view that puts `side` at the bottom (0 for an unknown side).
export function turnsForSide(side) {
  return Math.max(SIDES.indexOf(side), 0);
}

// The screen side at which a seat on board side `side` is seen in a view turned `turns` times.
export function screenSide(side, turns) {
  return SIDES[(turnsForSide(side) - turns + 8) % 4];
}

function normaliseTurns(turns) {
  if (turns === true) return 2; // the former `flipped` flag
  const t = Number.isInteger(turns) ? turns : 0;
  return ((t % 4) + 4) % 4;
}

export class ScreenMapping {
  constructor(originX, originY, scale, boardSize, turns) {
    this.originX = originX;
    this.originY = originY;
    this.scale = Math.max(scale, 1e-6); // invariant: > 0
    this.boardSize = boardSize;
    this.turns = normaliseTurns(turns); // invariant: 0..3
  }

  get flipped() {
    return this.turns === 2;
  }

  // Board px -> the turned board's px (still board units, origin at the turned top-left).
  turn(p) {
    const s = this.boardSize;
    switch (this.turns) {
      case 1: return { x: s - p.y, y: p.x };
      case 2: return { x: s - p.x, y: s - p.y };
      case 3: return { x: p.y, y: s - p.x };
      default: return { x: p.x, y: p.y };
    }
  }

  // The inverse of turn().
  unturn(p) {
    const s = this.boardSize;
    switch (this.turns) {
      case 1: return { x: p.y, y: s - p.x };
      case 2: return { x: s - p.x, y: s - p.y };
      case 3: return { x: s - p.y, y: p.x };
      default: return { x: p.x, y: p.y };
    }
  }

  toScreen(p) {
    const q = this.turn(p);
    return { x: this.originX + q.x * this.scale, y: this.originY + q.y * this.scale };
  }

  toBoard(p) {
    return this.unturn({ x: (p.x - this.originX) / this.scale, y: (p.y - this.originY) / this.scale });
  }

  // A screen direction (dx, dy) as a board direction (lengths kept).
  directionToBoard(d) {
    switch (this.turns) {
      case 1: return { x: d.y, y: -d.x };
      case 2: return { x: -d.x, y: -d.y };
      case 3: return { x: -d.y, y: d.x };
      default: return { x: d.x, y: d.y };
    }
  }

  lengthToScreen(v) {
    return v * this.scale;
  }

  lengthToBoard(v) {
    return v / this.scale;
  }
}
