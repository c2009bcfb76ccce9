// The WebAssembly engine against the native one (docs/web.md, "Determinism across builds"):
// carrom-engine-cases (native) writes the standard break and COUNT random shots from real
// positions with its answers; this runs the same scenes through web/js/engine.js on
// carrom_engine.wasm under node and compares result hashes (every event and final state, bit for
// bit), event counts and final positions.
//
//   CARROM_ENGINE_CASES=build/test/tools/carrom-engine-cases \
//   CARROM_ENGINE_WASM=build/test/web-wasm/carrom_engine.wasm node tests/wasm/determinism_test.mjs [COUNT]
//
// Prints one line: cases, bit-identical, same events, largest final position difference (px).
// Fails when the standard break differs in any bit, or when a case differs by more than the
// prediction's correction limit (0.5 px, docs/client.md) or pockets another set of pieces.
import { execFileSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { FREESTYLE_FIELDS, loadEngine, RULES_FIELDS } from '../../web/js/engine.js';

const count = process.argv[2] ?? '1000';
const casesTool = process.env.CARROM_ENGINE_CASES;
const wasmPath = process.env.CARROM_ENGINE_WASM;
if (!casesTool || !wasmPath) {
  console.error('determinism_test: set CARROM_ENGINE_CASES and CARROM_ENGINE_WASM');
  process.exit(2);
}
const CORRECTION_PX = 0.5;

const lines = execFileSync(casesTool, [count, '1'], { maxBuffer: 1 << 28 }).toString().trim().split('\n');
const engine = await loadEngine(readFileSync(wasmPath));
let identical = 0;
const sameBits = []; // per case: the wasm result has the native one's hash
let sameEvents = 0;
let largest = 0;
let largestCase = -1;
const failures = [];
const started = performance.now();
lines.forEach((line, i) => {
  const c = JSON.parse(line);
  const pieces = c.bodies.map(([id, kind, x, y, pocketed]) => ({
    id, kind: ['black', 'white', 'queen', 'striker'][kind], x, y, pocketed: pocketed === 1,
  }));
  const r = engine.simulate(pieces, c.side, { x: c.shot[0], angle: c.shot[1], power: c.shot[2] });
  if (r.error) {
    failures.push(`case ${i}: the engine refused it (${r.error})`);
    return;
  }
  sameBits.push(r.hash === c.hash);
  if (r.hash === c.hash) identical += 1;
  if (r.events.length === c.events) sameEvents += 1;
  let worst = 0;
  c.final.forEach(([id, x, y, pocketed], k) => {
    const b = r.final[k];
    if (b.id !== id || b.pocketed !== (pocketed === 1)) {
      failures.push(`case ${i}: piece ${id} pocketed natively ${pocketed === 1}, in wasm ${b.pocketed}`);
    } else if (!b.pocketed) {
      worst = Math.max(worst, Math.hypot(b.x - x, b.y - y));
    }
  });
  if (worst > largest) {
    largest = worst;
    largestCase = i;
  }
  if (worst > CORRECTION_PX) failures.push(`case ${i}: a final position differs by ${worst} px`);
  if (i === 0 && r.hash !== c.hash) failures.push(`the standard break differs: ${r.hash} vs ${c.hash}`);
});
const ms = performance.now() - started;

// The same games replayed from their start through the rules in wasm (carrom_replay_*), as the
// replay page does: each board a stroke is played on, against the native game's. Until a
// stroke's result differs in some bit, every board must be the native game's bit for bit; after
// it the difference grows with each stroke (counted, not failed: the page says so).
const replay = await loadEngine(readFileSync(wasmPath));
// boards compared, boards bit for bit the native ones (and before the first differing stroke),
// the largest difference (px), boards with another piece pocketed, strokes the rules refused.
const tally = { boards: 0, sameBoards: 0, exactUntilDifference: 0, drift: 0, otherPocketing: 0, refused: 0 };
let diverged = false;
for (const [k, line] of lines.slice(1).entries()) {
  const c = JSON.parse(line);
  if (c.rules) {
    diverged = false;
    const rules = Object.fromEntries(RULES_FIELDS.map((k, i) => [k, c.rules[i]]));
    rules.freestyle = Object.fromEntries(FREESTYLE_FIELDS.map((k, i) => [k, c.rules[RULES_FIELDS.length + i]]));
    const started = replay.replayStart('icf', rules, 0);
    if (started.error) failures.push(`game ${c.game}: the rules refuse its config (${started.error})`);
  }
  const board = replay.replayBoard(true);
  tally.boards += 1;
  let same = true;
  for (const [id, , x, y, pocketed] of c.bodies) {
    const b = board.find((p) => p.id === id);
    if (b.pocketed !== (pocketed === 1)) {
      tally.otherPocketing += same ? 1 : 0;
      same = false;
    } else if (!b.pocketed && (b.x !== x || b.y !== y)) {
      tally.drift = Math.max(tally.drift, Math.hypot(b.x - x, b.y - y));
      same = false;
    }
  }
  if (same) tally.sameBoards += 1;
  if (!diverged && !same) failures.push(`case ${k + 1}: the rules' replay left another board than the native game before any stroke differed`);
  if (!diverged) tally.exactUntilDifference += 1;
  if (!sameBits[k + 1]) diverged = true;
  const played = replay.replayPlay('stroke', c.seat, { x: c.shot[0], angle: c.shot[1], power: c.shot[2] });
  if (played.error) tally.refused += 1;
}

console.log(`determinism: ${lines.length} cases (the standard break and ${lines.length - 1} random shots), `
  + `${identical} bit-identical, ${sameEvents} with the same event count, largest final position `
  + `difference ${largest.toExponential(3)} px (case ${largestCase}); wasm ${(ms / lines.length).toFixed(2)} ms a case`);
console.log(`replayed through the rules: ${tally.boards} strokes of ${JSON.parse(lines[lines.length - 1]).game + 1} games, `
  + `${tally.sameBoards} played on the native game's board bit for bit (${tally.exactUntilDifference} before a stroke differed, all of them), `
  + `largest difference ${tally.drift.toExponential(3)} px; ${tally.otherPocketing} boards with another piece pocketed, `
  + `${tally.refused} strokes refused by the replayed game's rules`);
if (failures.length > 0) {
  console.error(failures.slice(0, 20).join('\n'));
  process.exit(1);
}
