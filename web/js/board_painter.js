// The static pictures (client/app/board_painter.cpp): the board (wood, markings, pockets)
// painted once per canvas size into an offscreen canvas, and one sprite per piece kind painted
// once per scale. Every frame then copies the board and stamps the sprites.

const INK = 'rgb(48,28,16)';
const RED = 'rgb(178,34,38)';

// Piece colours: fill, rim, ring (as the desktop client's piece_look).
export const PIECE_LOOK = {
  black: { fill: [34, 32, 34], rim: [78, 74, 78], ring: [58, 55, 58] },
  white: { fill: [240, 228, 200], rim: [196, 178, 146], ring: [214, 198, 168] },
  queen: { fill: [196, 28, 44], rim: [128, 16, 28], ring: [160, 22, 36] },
  striker: { fill: [246, 243, 234], rim: [160, 150, 136], ring: [36, 88, 168] },
};

const rgb = ([r, g, b], a = 1) => `rgba(${r},${g},${b},${a})`;

function makeCanvas(w, h) {
  const c = document.createElement('canvas');
  c.width = Math.max(1, Math.round(w));
  c.height = Math.max(1, Math.round(h));
  return c;
}

// Deterministic value noise in [0, 1] for the wood grain.
function hash01(x, y) {
  let h = (Math.imul(x, 374761393) + Math.imul(y, 668265263)) >>> 0;
  h = Math.imul(h ^ (h >>> 13), 1274126177) >>> 0;
  return ((h ^ (h >>> 16)) >>> 0) / 4294967295;
}

function valueNoise(x, y) {
  const xi = Math.floor(x);
  const yi = Math.floor(y);
  const fx = x - xi;
  const fy = y - yi;
  const sx = fx * fx * (3 - 2 * fx);
  const sy = fy * fy * (3 - 2 * fy);
  const a = hash01(xi, yi) + (hash01(xi + 1, yi) - hash01(xi, yi)) * sx;
  const b = hash01(xi, yi + 1) + (hash01(xi + 1, yi + 1) - hash01(xi, yi + 1)) * sx;
  return a + (b - a) * sy;
}

// Wood: grain along `along` (board px), rings across it.
function grain(along, across, seed) {
  const warp = 6 * valueNoise(along * 0.01 + seed, across * 0.03);
  const rings = 0.5 + 0.5 * Math.sin((across + warp * 4) * 0.55);
  const fine = valueNoise(along * 0.15, across * 1.3 + seed);
  return 0.75 * rings + 0.25 * fine;
}

// The wood of the board, side x side px, in board orientation. A turned view uses the picture as
// it is: the markings are the same under every quarter turn; only the grain runs the other way.
function paintWood(geo, side) {
  const canvas = makeCanvas(side, side);
  const ctx = canvas.getContext('2d');
  const image = ctx.createImageData(side, side);
  const data = image.data;
  const k = geo.boardSize / side;
  const s = geo.boardSize;
  for (let j = 0; j < side; j += 1) {
    const y = (j + 0.5) * k;
    for (let i = 0; i < side; i += 1) {
      const x = (i + 0.5) * k;
      const onSurface = x > geo.frame && y > geo.frame && x < s - geo.frame && y < s - geo.frame;
      let r; let g; let b; let m;
      if (onSurface) {
        m = 0.93 + 0.08 * grain(y, x, 11);
        r = 236; g = 202; b = 148;
      } else {
        const toEdge = Math.min(x, y, s - x, s - y);
        const horizontal = Math.min(y, s - y) < Math.min(x, s - x);
        m = 0.85 + 0.2 * (horizontal ? grain(x, y, 3) : grain(y, x, 7));
        const inner = geo.frame - toEdge;
        if (inner < 5) m *= 0.7 + 0.06 * inner; // the cushion lip's shadow
        if (toEdge < 3) m *= 0.75; // outer edge
        r = 118; g = 62; b = 30;
      }
      const o = (j * side + i) * 4;
      data[o] = Math.min(255, r * m);
      data[o + 1] = Math.min(255, g * m);
      data[o + 2] = Math.min(255, b * m);
      data[o + 3] = 255;
    }
  }
  ctx.putImageData(image, 0, 0);
  return canvas;
}

function strokeLine(ctx, a, b) {
  ctx.beginPath();
  ctx.moveTo(a.x, a.y);
  ctx.lineTo(b.x, b.y);
  ctx.stroke();
}

function circle(ctx, c, r, a0 = 0, a1 = 2 * Math.PI) {
  ctx.beginPath();
  ctx.arc(c.x, c.y, r, a0, a1);
}

// Markings and pockets in board px (the context is scaled to the board).
function paintMarkings(ctx, g) {
  ctx.lineWidth = 1.4;
  ctx.strokeStyle = 'rgba(48,28,16,0.6)';
  const lo = g.frame + 1;
  const hi = g.boardSize - lo;
  ctx.strokeRect(lo, lo, hi - lo, hi - lo);
  ctx.strokeStyle = INK;
  for (const b of g.baselines) {
    for (const side of [-1, 1]) {
      const off = { x: b.normal.x * side * b.halfGap, y: b.normal.y * side * b.halfGap };
      strokeLine(ctx, { x: b.start.x + off.x, y: b.start.y + off.y },
        { x: b.end.x + off.x, y: b.end.y + off.y });
    }
    for (const c of [b.start, b.end]) {
      circle(ctx, c, b.endR);
      ctx.fillStyle = RED;
      ctx.fill();
      ctx.stroke();
    }
  }
  for (const a of g.arrows) {
    const dx = a.tip.x - a.tail.x;
    const dy = a.tip.y - a.tail.y;
    const len = Math.hypot(dx, dy);
    const d = { x: dx / len, y: dy / len };
    const n = { x: -d.y, y: d.x };
    strokeLine(ctx, a.tail, { x: a.tip.x - d.x * a.head, y: a.tip.y - d.y * a.head });
    ctx.beginPath();
    ctx.moveTo(a.tip.x, a.tip.y);
    ctx.lineTo(a.tip.x - d.x * 2 * a.head + n.x * a.head, a.tip.y - d.y * 2 * a.head + n.y * a.head);
    ctx.lineTo(a.tip.x - d.x * 2 * a.head - n.x * a.head, a.tip.y - d.y * 2 * a.head - n.y * a.head);
    ctx.closePath();
    ctx.fillStyle = INK;
    ctx.fill();
    // The arc at the inner end opens towards the pocket.
    const facing = Math.atan2(dy, dx);
    circle(ctx, { x: a.tail.x - d.x * a.arcR * 0.2, y: a.tail.y - d.y * a.arcR * 0.2 }, a.arcR,
      facing + 0.25 * Math.PI, facing + 1.75 * Math.PI);
    ctx.stroke();
  }
  // Centre: a double circle, a red rose, the small circle the queen sits on.
  circle(ctx, g.centre, g.outerCircleR);
  ctx.stroke();
  ctx.lineWidth = 1;
  circle(ctx, g.centre, g.outerCircleR - 4);
  ctx.stroke();
  ctx.fillStyle = 'rgba(178,34,38,0.85)';
  for (let i = 0; i < 8; i += 1) {
    const ang = (Math.PI / 4) * i + Math.PI / 8;
    const u = { x: Math.cos(ang), y: Math.sin(ang) };
    const v = { x: -u.y, y: u.x };
    const base = { x: g.centre.x + u.x * (g.centreCircleR + 2), y: g.centre.y + u.y * (g.centreCircleR + 2) };
    const tip = { x: g.centre.x + u.x * (g.outerCircleR - 8), y: g.centre.y + u.y * (g.outerCircleR - 8) };
    ctx.beginPath();
    ctx.moveTo(base.x + v.x * 6, base.y + v.y * 6);
    ctx.lineTo(tip.x, tip.y);
    ctx.lineTo(base.x - v.x * 6, base.y - v.y * 6);
    ctx.closePath();
    ctx.fill();
  }
  ctx.lineWidth = 1.4;
  circle(ctx, g.centre, g.centreCircleR);
  ctx.fillStyle = RED;
  ctx.fill();
  ctx.stroke();
  for (const p of g.pockets) {
    circle(ctx, p, g.pocketR + 2);
    ctx.fillStyle = 'rgb(70,38,18)';
    ctx.fill();
    for (let i = 0; i < 6; i += 1) {
      const k = 1 - i / 6;
      const v = 12 + 26 * k;
      circle(ctx, p, g.pocketR * (1 - 0.12 * i));
      ctx.fillStyle = `rgb(${v},${v * 0.8},${v * 0.6})`;
      ctx.fill();
    }
  }
}

// A piece centred at (c, c) with radius r (device px): shadow, rim, face, ring, highlight.
function paintPiece(ctx, c, r, kind) {
  const look = PIECE_LOOK[kind];
  circle(ctx, { x: c + r * 0.12, y: c + r * 0.18 }, r * 1.02);
  ctx.fillStyle = 'rgba(0,0,0,0.27)';
  ctx.fill();
  circle(ctx, { x: c, y: c }, r);
  ctx.fillStyle = rgb(look.rim);
  ctx.fill();
  circle(ctx, { x: c, y: c }, r * 0.88);
  ctx.fillStyle = rgb(look.fill);
  ctx.fill();
  ctx.strokeStyle = rgb(look.ring);
  ctx.lineWidth = kind === 'striker' ? r * 0.12 : r * 0.06;
  circle(ctx, { x: c, y: c }, r * 0.62);
  ctx.stroke();
  if (kind === 'striker') {
    ctx.strokeStyle = RED;
    ctx.lineWidth = r * 0.08;
    circle(ctx, { x: c, y: c }, r * 0.3);
    ctx.stroke();
  }
  ctx.strokeStyle = 'rgba(255,255,255,0.24)';
  ctx.lineWidth = r * 0.08;
  circle(ctx, { x: c, y: c }, r * 0.78, 1.1 * Math.PI, 1.45 * Math.PI);
  ctx.stroke();
}

// The wood is painted per pixel, once, at WOOD_PX and scaled to whatever size the board has:
// a resize (a bar changing height, a phone turning) only redraws the markings.
const WOOD_PX = 1024;

export class BoardPainter {
  constructor(geometry) {
    this.geometry = geometry;
    this.wood = null; // board-orientation wood, WOOD_PX square
    this.board = null; // {canvas, key}
    this.sprites = null; // {scale, cell, byKind}
    this.paints = 0; // how many times a static picture was painted (a figure for docs/web.md)
    this.woodMs = 0; // how long painting the wood took
  }

  // The board picture for a square of `side` device px.
  boardCanvas(side) {
    const s = Math.max(1, Math.round(side));
    if (this.board && this.board.side === s) return this.board.canvas;
    if (!this.wood) {
      const t0 = performance.now();
      this.wood = paintWood(this.geometry, WOOD_PX);
      this.woodMs = performance.now() - t0;
      this.paints += 1;
    }
    const canvas = makeCanvas(s, s);
    const ctx = canvas.getContext('2d');
    ctx.imageSmoothingQuality = 'high';
    ctx.drawImage(this.wood, 0, 0, s, s);
    ctx.save();
    ctx.scale(s / this.geometry.boardSize, s / this.geometry.boardSize);
    paintMarkings(ctx, this.geometry);
    ctx.restore();
    this.board = { side: s, canvas };
    this.paints += 1;
    return canvas;
  }

  // Sprites of the four kinds for `scale` device px per board px; cell is each sprite's side.
  spritesFor(scale) {
    if (this.sprites && this.sprites.scale === scale) return this.sprites;
    const cell = 2 * Math.ceil(this.geometry.strikerR * scale * 1.25 + 2);
    const byKind = {};
    for (const kind of Object.keys(PIECE_LOOK)) {
      const canvas = makeCanvas(cell, cell);
      const r = (kind === 'striker' ? this.geometry.strikerR : this.geometry.coinR) * scale;
      paintPiece(canvas.getContext('2d'), cell / 2, r, kind);
      byKind[kind] = canvas;
    }
    this.sprites = { scale, cell, byKind };
    this.paints += 1;
    return this.sprites;
  }
}
