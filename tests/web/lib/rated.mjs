// Two identified pages in a rated game (docs/ratings.md), for web.ratings_page and
// scripts/web_screenshots.mjs: a carrom-server with a match store whose ratings table holds Asha
// (ICF 1600) and Ravi (ICF 1520), both established (deviation 80, 20 games), written with the
// sqlite3 program between the store's first start (which makes the schema) and the server's
// start; two pages that take those players' keys through the lobby's "My player key" and meet
// in a rated quick match.

import { execFileSync } from 'node:child_process';
import { createHash } from 'node:crypto';
import path from 'node:path';

import { env, pageUrl, startServer, startWebServer } from './harness.mjs';
import { Player } from './player.mjs';

export const SEEDED = Object.freeze([
  { name: 'Asha', key: 'a'.repeat(64), rating: 1600, games: 20 },
  { name: 'Ravi', key: 'b'.repeat(64), rating: 1520, games: 20 },
]);

// The store keeps a key's SHA-256 (of its 64 hex characters), never the key.
const keyHash = (key) => createHash('sha256').update(key).digest('hex');

function seedSql() {
  const now = Date.now();
  return SEEDED.map((p) => `INSERT INTO identities VALUES (X'${keyHash(p.key)}', '${p.name}', '${p.name.toLowerCase()}', ${now});
INSERT INTO ratings VALUES (X'${keyHash(p.key)}', 'icf', ${p.rating}, 80, 0.06, ${p.games}, 10, 10, 0, ${now});`).join('\n');
}

// carrom-server on dir/c.db with the seeded players; resolves {server, web}.
export async function startSeededServer(dir, args = []) {
  const data = ['--data', path.join(dir, 'c.db')];
  const first = await startServer(data); // writes the store's schema
  await first.child.stop();
  execFileSync(env.sqlite3 || 'sqlite3', [path.join(dir, 'c.db')], { input: seedSql() });
  const server = await startServer([...data, ...args]);
  return { server, web: await startWebServer(server) };
}

// A page that plays as the seeded player p: the key pasted in the lobby, then a quick match.
async function openAs(browser, p, url, errors, viewport) {
  const player = await Player.open(await browser.newContext({ viewport }), p.name, url, errors);
  await player.page.click('#identity summary');
  await player.page.fill('#identity-paste', p.key);
  await player.page.click('#identity-use');
  await player.page.click('#identity summary'); // folded again
  await player.fillLobby({ name: p.name, ruleSet: 'icf' });
  await player.press('#quick');
  await player.waitFor('waiting for a quick match', (s) => s.session.phase === 'joining' || s.inRoom);
  return player;
}

// Asha's and Ravi's pages seated in one rated room (a quick match between identified players).
export async function ratedPair(browser, server, web, errors, viewport = { width: 900, height: 900 }) {
  const url = pageUrl(web, server);
  const pages = [];
  for (const p of SEEDED) pages.push(await openAs(browser, p, url, errors, viewport));
  for (const page of pages) {
    await page.waitFor('the rated room', (s) => s.inRoom && s.seats.every((x) => x.occupied) && s.phase === 'aiming');
  }
  return pages;
}
