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
import { loadEngine } from '../../web/js/engine.js';

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
console.log(`determinism: ${lines.length} cases (the standard break and ${lines.length - 1} random shots), `
  + `${identical} bit-identical, ${sameEvents} with the same event count, largest final position `
  + `difference ${largest.toExponential(3)} px (case ${largestCase}); wasm ${(ms / lines.length).toFixed(2)} ms a case`);
if (failures.length > 0) {
  console.error(failures.slice(0, 20).join('\n'));
  process.exit(1);
}
