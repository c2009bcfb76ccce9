// The web client's session decisions (web/js/session_core.js) against the golden cases that
// net::SessionCore wrote (tests/golden/session/*.json, carrom-session-golden; tests/net replays
// them against the C++ core): every event gives the recorded actions and state. Run:
// node tests/web/session_test.mjs
import assert from 'node:assert/strict';
import { readdirSync, readFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import test from 'node:test';
import { fileURLToPath } from 'node:url';

import { decodeServer } from '../../web/js/protocol.js';
import { Session, SESSION_DEFAULTS } from '../../web/js/session.js';
import { SessionCore } from '../../web/js/session_core.js';

const goldenDir = join(dirname(fileURLToPath(import.meta.url)), '..', 'golden', 'session');
const files = readdirSync(goldenDir).filter((f) => f.endsWith('.json')).sort();

// The event's call on the core, as in tests/net/session_golden.cpp.
function feed(core, step) {
  switch (step.event) {
    case 'start': return core.start(step.resume_token ?? '');
    case 'request': return core.request();
    case 'leave': return core.leave();
    case 'link_opened': return core.linkOpened();
    case 'link_closed': return core.linkClosed(step.t, step.close_code, step.jitter);
    case 'tick': return core.tick(step.t);
    case 'welcome': return core.welcome(step.token);
    case 'room_state': return core.roomState();
    case 'error': return core.error(step.code);
    case 'redirect': return core.redirect({ url: step.url, reason: step.reason, code: step.code, as: step.as });
    default: throw new Error(`unknown event ${step.event}`);
  }
}

// The actions and state in the golden files' words.
function answer(core, actions) {
  return {
    actions: actions.map((a) => {
      const out = { kind: a.kind };
      if (a.kind === 'wait') out.wait_s = a.waitS;
      if (a.kind === 'give_up') out.reason = a.reason;
      if (a.kind === 'send_join') {
        out.code = core.joinCode;
        out.as = core.joinAs;
      }
      return out;
    }),
    state: {
      phase: core.phase,
      tries: core.tries,
      resuming: core.resuming,
      wants_room: core.wantsRoom,
      link_up: core.linkUp,
      token: core.token,
      url: core.url,
      redirects: core.redirects,
    },
  };
}

// Equal, numbers within 1e-9 (seconds), as the C++ replay compares.
function same(a, b) {
  if (typeof a === 'number' && typeof b === 'number') return Math.abs(a - b) <= 1e-9;
  if (Array.isArray(a) || Array.isArray(b)) {
    return Array.isArray(a) && Array.isArray(b) && a.length === b.length && a.every((x, i) => same(x, b[i]));
  }
  if (a && b && typeof a === 'object' && typeof b === 'object') {
    const keys = Object.keys(a);
    return keys.length === Object.keys(b).length && keys.every((k) => k in b && same(a[k], b[k]));
  }
  return a === b;
}

test('the golden cases are there', () => {
  assert.ok(files.length >= 20, `${files.length} files in ${goldenDir}`);
});

for (const file of files) {
  const golden = JSON.parse(readFileSync(join(goldenDir, file), 'utf8'));
  test(`${golden.name}: ${golden.about}`, () => {
    const b = golden.backoff;
    const core = new SessionCore({ firstS: b.first_s, capS: b.cap_s, giveUpAfterS: b.give_up_after_s }, golden.policy,
      golden.address);
    golden.steps.forEach((step, i) => {
      const got = answer(core, feed(core, step));
      const expected = { actions: step.actions, state: step.state };
      assert.ok(same(got, expected),
        `${file} step ${i} (${step.event} at ${step.t}): got ${JSON.stringify(got)}, recorded ${JSON.stringify(expected)}`);
    });
  });
}

// ---- web/js/session.js carries the redirect decisions out on real Session objects ----

// A connection that records its URL and what is sent; the test opens it and delivers messages.
class RecordingConnection {
  static made = [];
  constructor(url, hooks) {
    this.url = url;
    this.hooks = hooks;
    this.sent = [];
    this.closed = false;
    RecordingConnection.made.push(this);
  }
  send(m) { this.sent.push(m); return true; }
  close() { this.closed = true; }
}

function redirectSession(address) {
  RecordingConnection.made = [];
  const shown = [];
  const session = new Session(address, null, { onMessage: (m) => shown.push(m), onChange() {} },
    SESSION_DEFAULTS, RecordingConnection);
  return { session, shown };
}

const TOKEN = '5f0c1e0e8a7b4c2d9e3f1a2b3c4d5e6f';
const welcomeMessage = (token) => ({ type: 'welcome', version: 1, player_id: 7, resume_token: token, server_time_ms: 1 });

test('session.js: a redirect opens its URL, says hello with follows_redirects and joins the named room', () => {
  const { session, shown } = redirectSession('ws://127.0.0.1:7777/');
  session.ask({ kind: 'quick', ruleSet: 'icf' });
  session.start('ann');
  const first = RecordingConnection.made[0];
  assert.equal(first.url, 'ws://127.0.0.1:7777/');
  first.hooks.onOpen();
  assert.equal(first.sent[0].follows_redirects, true);
  first.hooks.onMessage(welcomeMessage(TOKEN), 0);
  assert.equal(first.sent.at(-1).type, 'quick_match');
  first.hooks.onMessage({ type: 'redirect', url: 'ws://127.0.0.1:7801/i/b/', reason: 'quick_match', code: 'K7M2QX', as: 'player' }, 0);
  assert.equal(RecordingConnection.made.length, 2);
  assert.ok(first.closed, 'the old link is closed');
  first.hooks.onClose('closed by the server', 4005); // the old link's end is not a loss
  const second = RecordingConnection.made[1];
  assert.equal(second.url, 'ws://127.0.0.1:7801/i/b/');
  second.hooks.onOpen();
  assert.deepEqual(second.sent[0], { type: 'hello', version: 1, name: 'ann', follows_redirects: true });
  second.hooks.onMessage(welcomeMessage(TOKEN), 0);
  assert.deepEqual(second.sent.at(-1), { type: 'join_room', code: 'K7M2QX', as: 'player' });
  assert.equal(session.phase, 'joining');
  assert.ok(!shown.some((m) => m.type === 'redirect'), 'the redirect is the session\'s, not the match\'s');
  session.stopLink();
});

test('session.js: a moved room without a seat to resume is joined without an error shown', () => {
  const { session, shown } = redirectSession('ws://127.0.0.1:7777/');
  session.ask({ kind: 'create', ruleSet: 'icf' });
  session.start('ann');
  const first = RecordingConnection.made[0];
  first.hooks.onOpen();
  first.hooks.onMessage(welcomeMessage(TOKEN), 0);
  first.hooks.onMessage({ type: 'room_state', code: 'K7M2QX' }, 0);
  assert.equal(session.phase, 'in_room');
  first.hooks.onMessage({ type: 'redirect', url: 'ws://127.0.0.1:7801/i/b/', reason: 'moved', code: 'K7M2QX', as: 'player' }, 0);
  const second = RecordingConnection.made[1];
  second.hooks.onOpen();
  assert.equal(second.sent[0].resume_token, TOKEN);
  second.hooks.onMessage({ type: 'error', code: 'bad_token', message: 'That resume token is unknown or expired; you join as a new player.' }, 0);
  second.hooks.onMessage(welcomeMessage('6f0c1e0e8a7b4c2d9e3f1a2b3c4d5e6f'), 0);
  assert.deepEqual(second.sent.at(-1), { type: 'join_room', code: 'K7M2QX', as: 'player' });
  assert.ok(!shown.some((m) => m.type === 'error'), 'the bad_token is the session\'s, not the player\'s');
  session.stopLink();
});

test('session.js: a redirect to another host is refused and never opened', () => {
  const { session } = redirectSession('ws://127.0.0.1:7777/');
  session.start('ann');
  const first = RecordingConnection.made[0];
  first.hooks.onOpen();
  first.hooks.onMessage(welcomeMessage(TOKEN), 0);
  first.hooks.onMessage({ type: 'redirect', url: 'ws://127.0.0.2:7777/', reason: 'room', code: 'K7M2QX', as: 'player' }, 0);
  assert.equal(RecordingConnection.made.length, 1);
  assert.equal(session.phase, 'failed');
  assert.equal(session.status, 'redirect refused: ws://127.0.0.2:7777/ is not an address of this cluster (ws://127.0.0.1:7777/).');
  session.stopLink();
});

test('protocol.js decodes redirect and checks its fields', () => {
  const ok = decodeServer(JSON.stringify({ type: 'redirect', url: 'ws://h:1/i/b/', reason: 'room', code: 'K7M2QX' }));
  assert.deepEqual(ok.message, { type: 'redirect', url: 'ws://h:1/i/b/', reason: 'room', code: 'K7M2QX', as: 'player' });
  assert.ok(!decodeServer(JSON.stringify({ type: 'redirect', url: 'wss://h', reason: 'seat' })).error);
  for (const bad of [
    { url: 'http://h:1/', reason: 'room' },
    { url: 'ws://', reason: 'room' },
    { url: `ws://h/${'a'.repeat(2000)}`, reason: 'room' },
    { url: 'ws://h:1/', reason: '' },
    { reason: 'room' },
    { url: 'ws://h:1/', reason: 'room', code: 'k7m2qx' },
    { url: 'ws://h:1/', reason: 'room', code: 'K7M2QX', as: 'referee' },
  ]) {
    assert.ok(decodeServer(JSON.stringify({ type: 'redirect', ...bad })).error, JSON.stringify(bad));
  }
});
