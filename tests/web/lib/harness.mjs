// What the browser tests share: a real carrom-server (and carrom-bot) started from the build,
// the web client served by that carrom-server (its embedded copy), the system chromium driven by
// playwright-core (nothing is downloaded), pages as players with the debug hook `window.carrom`,
// console error collection, and cleanup of every child process on any exit. Every wait has a
// deadline.
//
// Environment (set by tests/web/web.cmake): CARROM_SERVER, CARROM_BOT, CARROM_CLIENT (paths of
// the built binaries), CARROM_CHROMIUM (default /usr/bin/chromium), CARROM_SQLITE3 (the sqlite3
// program, default sqlite3); CARROM_WEB_ROOT, when set,
// makes every carrom-server serve that directory (`--web-root`) instead of its embedded copy, to
// test an edit of web/ without a rebuild.

import { spawn } from 'node:child_process';
import { once } from 'node:events';
import { createInterface } from 'node:readline';

export const env = {
  server: process.env.CARROM_SERVER,
  bot: process.env.CARROM_BOT,
  client: process.env.CARROM_CLIENT,
  chromium: process.env.CARROM_CHROMIUM || '/usr/bin/chromium',
  webRoot: process.env.CARROM_WEB_ROOT,
  sqlite3: process.env.CARROM_SQLITE3,
};

export const CHROMIUM_ARGS = [
  '--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
  '--disable-background-networking', '--disable-component-update', '--disable-sync',
];

const children = new Set();

function killGroup(child, signal) {
  try {
    process.kill(-child.pid, signal);
  } catch {
    // already gone
  }
}

async function stopChild(child) {
  if (child.exitCode !== null || child.signalCode !== null) return;
  killGroup(child, 'SIGTERM');
  const timer = setTimeout(() => killGroup(child, 'SIGKILL'), 3000);
  await once(child, 'exit').catch(() => {});
  clearTimeout(timer);
}

// Starts a child in its own process group; resolves when a stdout or stderr line matches `ready`.
// `childEnv` replaces the child's environment (default: this process's).
export async function startChild(label, command, args, ready, timeoutMs = 15000, childEnv = process.env) {
  const child = spawn(command, args, { detached: true, stdio: ['ignore', 'pipe', 'pipe'], env: childEnv });
  children.add(child);
  child.exited = new Promise((res) => { child.on('exit', (code, signal) => res(code ?? signal)); });
  child.on('exit', () => children.delete(child));
  child.log = [];
  const lines = [];
  let resolve;
  let reject;
  const found = new Promise((res, rej) => { resolve = res; reject = rej; });
  const watch = (stream) => {
    createInterface({ input: stream }).on('line', (line) => {
      child.log.push(line);
      if (child.log.length > 200) child.log.shift();
      lines.push(line);
      const m = ready ? ready.exec(line) : null;
      if (m) resolve(m);
    });
  };
  watch(child.stdout);
  watch(child.stderr);
  child.on('error', (e) => reject(new Error(`${label}: cannot start ${command}: ${e.message}`)));
  child.on('exit', (code, signal) => reject(new Error(`${label} exited (${code ?? signal}) before it was ready:\n${lines.join('\n')}`)));
  const timer = setTimeout(() => reject(new Error(`${label}: not ready after ${timeoutMs} ms:\n${lines.join('\n')}`)), timeoutMs);
  try {
    child.match = ready ? await found : null;
  } finally {
    clearTimeout(timer);
  }
  child.stop = () => stopChild(child);
  return child;
}

// carrom-server on 127.0.0.1 with an ephemeral port, without a match store unless args name one
// (--data); resolves {port, ws, child}.
export async function startServer(args = []) {
  if (!env.server) throw new Error('CARROM_SERVER is not set');
  const child = await startChild('carrom-server', env.server,
    ['--host', '127.0.0.1', '--port', '0', ...(args.includes('--data') ? [] : ['--data', 'none']),
      ...(env.webRoot ? ['--web-root', env.webRoot] : []), ...args],
    /listening on [\d.]+:(\d+)/);
  const port = Number(child.match[1]);
  return { port, ws: `ws://127.0.0.1:${port}/`, child };
}

// The web client over HTTP from carrom-server itself (the page's WebSocket is then its own
// host); fails when the server does not answer `GET /` with the page.
export async function startWebServer(server) {
  const answer = await fetch(`http://127.0.0.1:${server.port}/`).catch((e) => e);
  if (answer instanceof Error) throw new Error(`GET / of carrom-server: ${answer.message}`);
  const type = answer.headers.get('content-type') ?? '';
  await answer.arrayBuffer();
  check(answer.status === 200 && type.startsWith('text/html'),
    `carrom-server does not serve the web client at / (${answer.status}, ${type})`);
  return { port: server.port };
}

// The page address: the web client from `web`, talking to the server `server` (another address
// than the page's own is given in the `ws` query parameter).
export function pageUrl(web, server, hash = '') {
  if (web.port === server.port) return `http://127.0.0.1:${web.port}/${hash}`;
  return `http://127.0.0.1:${web.port}/index.html?ws=${encodeURIComponent(server.ws)}${hash}`;
}

// `browserEnv` replaces the browser's environment (default: this process's); a test gives
// Chromium a HOME of its own to trust a test CA through NSS's database there.
export async function launchBrowser(extraArgs = [], browserEnv = undefined) {
  // Imported here so that a missing `npm ci` is one clear sentence.
  let chromium;
  try {
    ({ chromium } = await import('playwright-core'));
  } catch {
    throw new Error('playwright-core is missing: run `npm ci` in tests/web (scripts/install-deps.sh does)');
  }
  // launch() gives every run a fresh temporary profile (user-data-dir) and removes it after.
  return chromium.launch({ executablePath: env.chromium, headless: true, args: [...CHROMIUM_ARGS, ...extraArgs], env: browserEnv });
}

// Runs a test body with a deadline; stops every child and the browser, prints the outcome and
// sets the exit code.
export async function run(name, timeoutMs, body) {
  const started = Date.now();
  const state = { browser: null, errors: [] };
  let failure = null;
  const deadline = setTimeout(() => {
    failure = failure ?? new Error(`${name}: gave up after ${timeoutMs} ms`);
    cleanup(state).finally(() => finish());
  }, timeoutMs);
  const finish = () => {
    clearTimeout(deadline);
    const s = ((Date.now() - started) / 1000).toFixed(1);
    if (failure) {
      console.error(`FAIL ${name} (${s} s): ${failure.stack ?? failure}`);
      process.exitCode = 1;
    } else {
      console.log(`PASS ${name} (${s} s)`);
      process.exitCode = 0;
    }
    process.exit();
  };
  try {
    await body(state);
    if (state.errors.length > 0) {
      throw new Error(`console errors in the pages:\n${state.errors.join('\n')}`);
    }
  } catch (e) {
    failure = failure ?? e;
    for (const child of children) {
      if (child.log?.length) console.error(`--- last output of ${child.spawnargs[0]}:\n${child.log.slice(-30).join('\n')}`);
    }
  }
  await cleanup(state);
  finish();
}

async function cleanup(state) {
  try {
    if (state.browser) await state.browser.close();
  } catch {
    // closing a browser that is already gone
  }
  await Promise.all([...children].map((c) => stopChild(c)));
}

export function check(condition, message) {
  if (!condition) throw new Error(message);
}

export const sleep = (ms) => new Promise((r) => { setTimeout(r, ms); });
