// Checks a page's screenshot against what the page says it drew: the board's frame and surface
// colours, and every drawn piece's colour at its centre (black, white, queen or striker), so a
// piece drawn in the wrong place, in the wrong colour or not at all is caught. Pieces under an
// HTML overlay (messages, panels) or under a piece drawn later are not sampled.

import { check } from './harness.mjs';
import { decodePng } from './png.mjs';

const LOOK = {
  black: [34, 32, 34],
  white: [240, 228, 200],
  queen: [196, 28, 44],
  striker: [246, 243, 234],
};

const close = (c, want, tol) => c.every((v, i) => Math.abs(v - want[i]) <= tol);

// Returns {pieces: number of pieces checked, drawn: pieces drawn}. Throws when a check fails.
export async function checkPicture(player, { minPieces = 1 } = {}) {
  const page = player.page;
  const s = await player.state();
  const overlays = await page.evaluate(() => [...document.querySelectorAll('#messages .message, .panel, #lobby')]
    .filter((e) => !e.hidden && e.getClientRects().length > 0)
    .map((e) => { const r = e.getBoundingClientRect(); return { x: r.left, y: r.top, w: r.width, h: r.height }; }));
  const shot = decodePng(await page.screenshot());
  const dpr = shot.width / page.viewportSize().width;
  const px = (x, y) => shot.at(x * dpr, y * dpr);
  const { left, top, side } = s.canvas;
  const scale = side / 600;
  // The frame (wood, dark red-brown) near a corner, and the light surface near the middle of an
  // edge, between the pocket and the baseline circle.
  const frame = px(left + 12 * scale, top + 300 * scale);
  check(frame[0] > frame[1] && frame[1] > frame[2] && frame[0] > 60 && frame[0] < 170,
    `${player.label}: frame colour ${frame} at the board's left edge`);
  const onBoard = s.board.filter((b) => !b.pocketed);
  const freeSpot = [[300, 45], [300, 555], [45, 300], [555, 300]]
    .find(([x, y]) => onBoard.every((b) => Math.hypot(b.x - x, b.y - y) > 30));
  if (freeSpot) {
    const surface = px(left + (s.flipped ? 600 - freeSpot[0] : freeSpot[0]) * scale,
      top + (s.flipped ? 600 - freeSpot[1] : freeSpot[1]) * scale);
    check(surface[0] > 180 && surface[1] > 150 && surface[2] > 100 && surface[0] > surface[2],
      `${player.label}: surface colour ${surface} at board ${freeSpot}`);
  }
  // The drawn pieces are the board's pieces (the striker at rest is hidden while someone aims).
  const drawnCoins = s.drawn.filter((d) => d.id >= 0 && !d.falling && d.kind !== 'striker');
  const drawnIds = new Set(drawnCoins.map((d) => d.id));
  const coins = onBoard.filter((b) => b.kind !== 'striker');
  for (const b of coins) {
    check(drawnIds.has(b.id), `${player.label}: piece ${b.id} (${b.kind}) is on the board but not drawn`);
  }
  check(drawnCoins.length === coins.length, `${player.label}: ${drawnCoins.length} coins drawn, ${coins.length} on the board`);
  const strikers = s.drawn.filter((d) => d.kind === 'striker' && !d.falling).length;
  check(strikers === 1, `${player.label}: ${strikers} strikers drawn`);
  let checked = 0;
  s.drawn.forEach((d, i) => {
    if (d.falling) return;
    const cx = left + d.sx;
    const cy = top + d.sy;
    if (overlays.some((r) => cx > r.x - 20 && cx < r.x + r.w + 20 && cy > r.y - 20 && cy < r.y + r.h + 20)) return;
    const covered = s.drawn.slice(i + 1).some((e) => Math.hypot(e.sx - d.sx, e.sy - d.sy) < 20 * scale * 2);
    if (covered) return;
    if (d.id === -1 && s.aim.phase === 'inactive') return; // the opponent's half-transparent striker
    const c = px(cx, cy);
    check(close(c, LOOK[d.kind], 24), `${player.label}: piece ${d.id} (${d.kind}) at ${cx.toFixed(1)},${cy.toFixed(1)} has colour ${c}, want ${LOOK[d.kind]}`);
    checked += 1;
  });
  check(checked >= minPieces, `${player.label}: only ${checked} pieces could be checked`);
  return { pieces: checked, drawn: s.drawn.length };
}
