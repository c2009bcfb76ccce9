// Board px <-> canvas CSS px. The board is a square at (originX, originY) of side
// boardSize * scale. A seat that shoots from the top baseline sees the board turned half a turn,
// so that every player's own baseline is at the bottom (client/src/screen_mapping.cpp).

export class ScreenMapping {
  constructor(originX, originY, scale, boardSize, flipped) {
    this.originX = originX;
    this.originY = originY;
    this.scale = Math.max(scale, 1e-6); // invariant: > 0
    this.boardSize = boardSize;
    this.flipped = flipped;
  }

  toScreen(p) {
    const x = this.flipped ? this.boardSize - p.x : p.x;
    const y = this.flipped ? this.boardSize - p.y : p.y;
    return { x: this.originX + x * this.scale, y: this.originY + y * this.scale };
  }

  toBoard(p) {
    const x = (p.x - this.originX) / this.scale;
    const y = (p.y - this.originY) / this.scale;
    return this.flipped ? { x: this.boardSize - x, y: this.boardSize - y } : { x, y };
  }

  lengthToScreen(v) {
    return v * this.scale;
  }

  lengthToBoard(v) {
    return v / this.scale;
  }
}
