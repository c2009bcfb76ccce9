// Draws the board on two stacked canvases: below, the board's picture, drawn only when its size
// changes; above, a transparent layer with the pieces at their interpolated places, the striker
// being placed with the aim guide (direction, power ring, placement warning), or the opponent's
// striker where they are placing it. Each frame clears only what the last one drew on the upper
// layer, so a frame costs the browser the pieces, not the whole board. Coordinates: CSS px of the
// canvas (the mapping), drawn at devicePixelRatio for sharp pictures.

import { drawAimAssist } from './aim_assist.js';
import { BoardPainter } from './board_painter.js';
import { ScreenMapping } from './screen_mapping.js';

// The striker's opacity while it overlaps a piece (the piece shows through it).
export const OVERLAP_ALPHA = 0.45;

export class Renderer {
  constructor(canvas, background, geometry) {
    this.canvas = canvas;
    this.ctx = canvas.getContext('2d');
    this.background = background;
    this.bgCtx = background.getContext('2d', { alpha: false });
    this.dirty = []; // device px rects the last frame drew on, [x, y, w, h]
    this.dirtyAll = false;
    this.geometry = geometry;
    this.painter = new BoardPainter(geometry);
    this.side = 0; // CSS px
    this.dpr = 1;
    this.drawn = []; // what the last frame showed (the debug hook reports it)
    this.frames = 0;
  }

  // The canvas is a square of `side` CSS px.
  resize(side, dpr) {
    const s = Math.max(1, Math.floor(side));
    if (s === this.side && dpr === this.dpr) return false;
    this.side = s;
    this.dpr = dpr;
    for (const c of [this.canvas, this.background]) {
      c.style.width = `${s}px`;
      c.style.height = `${s}px`;
      c.width = Math.round(s * dpr);
      c.height = Math.round(s * dpr);
    }
    const devSide = Math.round(s * dpr);
    this.bgCtx.drawImage(this.painter.boardCanvas(devSide), 0, 0);
    this.dirty = [];
    this.dirtyAll = false;
    return true;
  }

  // turns: quarter turns of the view (screen_mapping.js).
  mapping(turns) {
    return new ScreenMapping(0, 0, this.side / this.geometry.boardSize, this.geometry.boardSize,
      turns);
  }

  // frame: {bodies, turns, placing: {striker, alpha, warning, blocking: {x, y, r} | null} | null,
  //         aim: {striker, angle, fraction} | null, grabHint: bool,
  //         assist: a guide of aim_assist.js | null (drawn with aim only)}
  draw(frame) {
    const ctx = this.ctx;
    const m = this.mapping(frame.turns);
    const devSide = Math.round(this.side * this.dpr);
    if (devSide <= 0) return;
    this.clearLastFrame(devSide);
    ctx.setTransform(this.dpr, 0, 0, this.dpr, 0, 0);
    const sprites = this.painter.spritesFor(m.scale * this.dpr);
    const cell = sprites.cell / this.dpr;
    this.drawn = [];
    // Falling pieces first, so that pieces on the board cover them.
    for (const pass of [true, false]) {
      for (const b of frame.bodies) {
        if (b.falling !== pass) continue;
        const p = m.toScreen(b);
        const size = cell * b.scale;
        ctx.globalAlpha = Math.min(Math.max(b.alpha, 0), 1);
        ctx.drawImage(sprites.byKind[b.kind], p.x - size / 2, p.y - size / 2, size, size);
        this.markDirty(p.x - size / 2, p.y - size / 2, size);
        this.drawn.push({ id: b.id, kind: b.kind, x: b.x, y: b.y, sx: p.x, sy: p.y, falling: b.falling });
      }
    }
    ctx.globalAlpha = 1;
    if (frame.aim) this.drawAim(m, frame.aim);
    if (frame.aim && frame.assist) drawAimAssist(ctx, m, frame.aim.striker, frame.assist, this.geometry.strikerR);
    if (frame.placing) this.drawPlacing(m, sprites, cell, frame.placing, frame.grabHint);
    // The aim guide and the labels reach anywhere: the next frame clears everything.
    this.dirtyAll = Boolean(frame.aim || (frame.placing && (frame.placing.warning || frame.grabHint)));
    this.frames += 1;
  }

  // A square of `size` CSS px at (x, y) was drawn on (with a margin for antialiasing).
  markDirty(x, y, size) {
    const d = this.dpr;
    const x0 = Math.floor((x - 2) * d);
    const y0 = Math.floor((y - 2) * d);
    this.dirty.push([x0, y0, Math.ceil((x + size + 2) * d) - x0, Math.ceil((y + size + 2) * d) - y0]);
  }

  clearLastFrame(devSide) {
    const ctx = this.ctx;
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    if (this.dirtyAll) {
      ctx.clearRect(0, 0, devSide, devSide);
    } else {
      for (const [x, y, w, h] of this.dirty) ctx.clearRect(x, y, w, h);
    }
    this.dirty = [];
    this.dirtyAll = false;
  }

  drawAim(m, aim) {
    const ctx = this.ctx;
    const s = aim.striker;
    const f = aim.fraction;
    const dir = { x: Math.cos(aim.angle), y: Math.sin(aim.angle) };
    const at = (d) => m.toScreen({ x: s.x + dir.x * d, y: s.y + dir.y * d });
    const reach = 40 + 260 * f;
    ctx.lineCap = 'round';
    ctx.strokeStyle = 'rgba(255,255,255,0.82)';
    ctx.lineWidth = Math.max(m.lengthToScreen(2), 1.5);
    ctx.beginPath();
    for (let d = this.geometry.strikerR + 4; d < reach; d += 14) {
      const a = at(d);
      const b = at(Math.min(d + 8, reach));
      ctx.moveTo(a.x, a.y);
      ctx.lineTo(b.x, b.y);
    }
    ctx.stroke();
    const c = m.toScreen(s);
    const back = at(-(20 + 140 * f));
    ctx.strokeStyle = 'rgba(40,20,10,0.6)';
    ctx.lineWidth = Math.max(m.lengthToScreen(1), 1);
    ctx.beginPath();
    ctx.moveTo(c.x, c.y);
    ctx.lineTo(back.x, back.y);
    ctx.stroke();
    ctx.strokeStyle = `rgb(${Math.round(60 + 195 * f)},${Math.round(210 - 150 * f)},40)`;
    ctx.lineWidth = m.lengthToScreen(4);
    ctx.lineCap = 'butt';
    ctx.beginPath();
    ctx.arc(c.x, c.y, m.lengthToScreen(this.geometry.strikerR + 7), -Math.PI / 2,
      -Math.PI / 2 + 2 * Math.PI * f);
    ctx.stroke();
    this.label(`Power ${Math.round(100 * f)}%`, c.x,
      c.y - m.lengthToScreen(this.geometry.strikerR + 22), m, '#fff');
  }

  drawPlacing(m, sprites, cell, placing, grabHint) {
    const ctx = this.ctx;
    const p = m.toScreen(placing.striker);
    const r = m.lengthToScreen(this.geometry.strikerR);
    if (grabHint) {
      ctx.strokeStyle = 'rgba(236,184,64,0.9)';
      ctx.lineWidth = 2;
      ctx.beginPath();
      ctx.arc(p.x, p.y, r + 5, 0, 2 * Math.PI);
      ctx.stroke();
    }
    // Over a piece the striker is see-through, so the piece under it stays visible.
    ctx.globalAlpha = placing.warning ? OVERLAP_ALPHA : placing.alpha;
    ctx.drawImage(sprites.byKind.striker, p.x - cell / 2, p.y - cell / 2, cell, cell);
    this.markDirty(p.x - cell / 2, p.y - cell / 2, cell);
    ctx.globalAlpha = 1;
    this.drawn.push({
      id: -1, kind: 'striker', x: placing.striker.x, y: placing.striker.y, sx: p.x, sy: p.y, falling: false,
      alpha: placing.warning ? OVERLAP_ALPHA : placing.alpha,
    });
    if (placing.warning) {
      ctx.strokeStyle = 'rgb(230,20,20)';
      ctx.lineWidth = 3;
      ctx.beginPath();
      ctx.arc(p.x, p.y, r + 2, 0, 2 * Math.PI);
      ctx.stroke();
      if (placing.blocking) {
        // The piece in the way, outlined on top of everything.
        const b = m.toScreen(placing.blocking);
        const br = m.lengthToScreen(placing.blocking.r);
        ctx.strokeStyle = 'rgb(255,230,60)';
        ctx.lineWidth = 2.5;
        ctx.setLineDash([4, 3]);
        ctx.beginPath();
        ctx.arc(b.x, b.y, br + 2, 0, 2 * Math.PI);
        ctx.stroke();
        ctx.setLineDash([]);
      }
      this.label('Overlaps a piece', p.x, p.y + m.lengthToScreen(this.geometry.strikerR + 16), m,
        'rgb(255,90,80)');
    }
  }

  label(text, x, y, m, colour) {
    const ctx = this.ctx;
    ctx.font = `600 ${Math.max(12, Math.round(m.lengthToScreen(11)))}px system-ui, sans-serif`;
    ctx.textAlign = 'center';
    ctx.textBaseline = 'middle';
    ctx.lineWidth = 3;
    ctx.strokeStyle = 'rgba(20,12,8,0.8)';
    ctx.strokeText(text, x, y);
    ctx.fillStyle = colour;
    ctx.fillText(text, x, y);
  }

  // Only the board, with no pieces (the lobby's background).
  drawEmpty() {
    this.clearLastFrame(Math.round(this.side * this.dpr));
    this.drawn = [];
  }
}
