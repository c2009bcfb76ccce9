// Where the page puts the side area (the message log, the first-game tips, Cancel shot): beside
// the board on wide stages, under it on tall ones; never over the board.

// The side area (the log, the tips, Cancel shot), CSS px: its width beside the board, its height
// under it (a fifth of the stage within these bounds), and the gap to the board.
const SIDE_W = 220;
const UNDER_H = [80, 150];
const SIDE_GAP = 10;
// Where the side area goes for a stage of w x h CSS px: {mode: 'beside' | 'under', side (the
// board's CSS px), sideW, sideH}. The place that leaves the bigger board wins (beside on a tie);
// under the board, the side area takes all the height the board leaves.
export function sideLayout(w, h) {
  const beside = Math.floor(Math.max(Math.min(h, w - SIDE_W - SIDE_GAP), 1));
  const underH = Math.min(Math.max(h * 0.2, UNDER_H[0]), UNDER_H[1]);
  const under = Math.floor(Math.max(Math.min(w, h - underH - SIDE_GAP), 1));
  if (beside >= under) return { mode: 'beside', side: beside, sideW: SIDE_W, sideH: beside };
  return { mode: 'under', side: under, sideW: under, sideH: Math.floor(Math.max(h - under - SIDE_GAP, 0)) };
}
