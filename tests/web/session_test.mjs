// The web client's session decisions (web/js/session_core.js) against the golden cases that
// net::SessionCore wrote (tests/golden/session/*.json, carrom-session-golden; tests/net replays
// them against the C++ core): every event gives the recorded actions and state. Run:
// node tests/web/session_test.mjs
import assert from 'node:assert/strict';
import { readdirSync, readFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import test from 'node:test';
import { fileURLToPath } from 'node:url';

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
