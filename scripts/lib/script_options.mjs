// What the web scripts (web_report, web_screenshots, web_first_motion) share: the repository's
// root, their command line's `--name value` options, and the carrom-server they start
// (--server PATH, else $CARROM_SERVER, else the test build's), set in CARROM_SERVER for
// tests/web/lib/harness.mjs.
import { fileURLToPath } from 'node:url';
import path from 'node:path';

export const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
export const args = process.argv.slice(2);
export const opt = (name, fallback) => {
  const i = args.indexOf(name);
  return i >= 0 ? args[i + 1] : fallback;
};
process.env.CARROM_SERVER = path.resolve(opt('--server', process.env.CARROM_SERVER ?? path.join(root, 'build/test/server/carrom-server')));
