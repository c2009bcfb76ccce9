#!/usr/bin/env node
// Figures of the web client for docs/web.md: the frame time while a break plays in headless
// Chromium at 900 x 900, and what the page downloads.
//
//   node scripts/web_report.mjs [--server PATH] [--web-root DIR] [--runs N] [--mute] [--json]
//
// It starts carrom-server (default build/test/server/carrom-server), which serves the page (its
// embedded copy, or the files of --web-root DIR), opens the page (playwright-core from tests/web,
// the system chromium, the tests' flags), creates a room against a server bot and breaks at full
// power with the mouse, in real time. Frame time
// is, for each requestAnimationFrame callback while pieces move on screen, the time from the
// callback's timestamp (the frame's start) to the end of the page's work in it; the interval
// between timestamps is reported too. The break is the page's own stroke, so it is predicted
// with the engine (the prediction's figures are printed). Download: every response of a fresh
// load (no cache), the engine included, as the browser's resource timing reports it; the first
// contentful paint (the lobby drawn) and the engine's load time (fetch, compile, instantiate).

import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';

const { root, args, opt } = await import('./lib/script_options.mjs');
const runs = Number(opt('--runs', '5'));
const unthrottled = args.includes('--unthrottled');
const muted = args.includes('--mute');
const webRoot = opt('--web-root', null);

const { launchBrowser, pageUrl, run, startServer, startWebServer, check } = await import(path.join(root, 'tests/web/lib/harness.mjs'));
const { Player } = await import(path.join(root, 'tests/web/lib/player.mjs'));
const { breakShot } = await import(path.join(root, 'tests/web/lib/match.mjs'));

// Playwright starts the browser in a session of its own, so it would not share this process's
// scheduling (nice value, scheduler autogroup): give the browser the same, before it starts its
// page processes (they inherit it).
function shareScheduling() {
  const own = /nice\s+(-?\d+)/.exec(fs.readFileSync('/proc/self/autogroup', 'utf8').toString());
  for (const entry of fs.readdirSync('/proc')) {
    if (!/^\d+$/.test(entry)) continue;
    let stat;
    try {
      stat = fs.readFileSync(`/proc/${entry}/stat`, 'utf8');
    } catch {
      continue;
    }
    const fields = stat.slice(stat.lastIndexOf(')') + 2).split(' ');
    if (Number(fields[1]) !== process.pid) continue; // its parent
    const pid = Number(entry);
    try {
      os.setPriority(pid, os.getPriority());
      if (own) fs.writeFileSync(`/proc/${pid}/autogroup`, own[1]);
    } catch {
      // not allowed (not root): the figures then say what an ordinary user gets
    }
  }
}

// CPU time (user + system, ms) of the browser's processes (every chromium descendant of this
// process) by pid: {name: the process type (browser, renderer, gpu-process, utility:audio, ...),
// ms}.
function browserCpu() {
  const tick = 1000 / 100; // USER_HZ
  const parent = new Map();
  const info = new Map();
  for (const entry of fs.readdirSync('/proc')) {
    if (!/^\d+$/.test(entry)) continue;
    try {
      const stat = fs.readFileSync(`/proc/${entry}/stat`, 'utf8');
      const fields = stat.slice(stat.lastIndexOf(')') + 2).split(' ');
      parent.set(Number(entry), Number(fields[1]));
      const cmd = fs.readFileSync(`/proc/${entry}/cmdline`, 'utf8').split(/[\0 ]/);
      const type = cmd.find((a) => a.startsWith('--type='))?.slice(7) ?? 'browser';
      const service = cmd.find((a) => a.startsWith('--utility-sub-type='))?.slice(19).replace(/\.mojom\.\w+$/, '');
      info.set(Number(entry), { name: service ? `${type}:${service}` : type, ms: (Number(fields[11]) + Number(fields[12])) * tick, exe: cmd[0] });
    } catch {
      // gone meanwhile
    }
  }
  const out = new Map();
  for (const [pid, i] of info) {
    let p = parent.get(pid);
    let under = false;
    while (p && p > 1) {
      if (p === process.pid) { under = true; break; }
      p = parent.get(p);
    }
    if (!under || !/chrom/.test(i.exe)) continue;
    out.set(pid, i);
  }
  return out;
}
// By process type, of the processes alive at both ends.
const cpuSince = (before) => {
  const d = {};
  for (const [pid, i] of browserCpu()) {
    if (before.has(pid)) d[i.name] = (d[i.name] ?? 0) + Math.round(i.ms - before.get(pid).ms);
  }
  return d;
};

const percentile = (values, p) => {
  if (values.length === 0) return NaN;
  const v = [...values].sort((a, b) => a - b);
  return v[Math.min(v.length - 1, Math.ceil(p * v.length) - 1)];
};
const round = (x) => Math.round(x * 100) / 100;

run('web_report', 300000, async (t) => {
  const server = await startServer(['--shot-clock', '0', '--bot-think-ms', '100',
    ...(webRoot ? ['--web-root', path.resolve(webRoot)] : [])]);
  const web = await startWebServer(server);
  // Unthrottled frames: the interval between rAF timestamps is then the whole frame's cost.
  const extra = unthrottled ? ['--disable-frame-rate-limit', '--disable-gpu-vsync'] : [];
  if (args.includes('--mute-audio')) extra.push('--mute-audio');
  t.browser = await launchBrowser(extra);
  shareScheduling();
  const results = [];
  const pooled = { work: [], inside: [], idle: [] };
  let download = null;
  for (let i = 0; i < runs; i += 1) {
    const context = await t.browser.newContext({ viewport: { width: 900, height: 900 } });
    const p = await Player.open(context, `run ${i + 1}`, pageUrl(web, server), t.errors);
    // The engine loads after the page starts (js/carrom_engine.wasm, streamed and compiled).
    const loaded = await p.waitFor('the engine', (st) => st.engine.loaded || st.engine.error !== null, 10000);
    if (!download) {
      download = await p.page.evaluate(() => {
        const entries = [...performance.getEntriesByType('navigation'), ...performance.getEntriesByType('resource')];
        return {
          files: entries.length,
          transferBytes: entries.reduce((s, e) => s + e.transferSize, 0),
          bodyBytes: entries.reduce((s, e) => s + e.encodedBodySize, 0),
          engineBytes: entries.filter((e) => e.name.endsWith('.wasm')).reduce((s, e) => s + e.transferSize, 0),
          firstPaintMs: performance.getEntriesByType('paint').find((e) => e.name === 'first-contentful-paint')?.startTime ?? null,
        };
      });
    }
    // Baseline: the same page doing nothing (the lobby) for 5 s, so the machine's own noise shows.
    await p.page.evaluate(() => window.carrom.clearFrameTimes());
    await new Promise((r) => { setTimeout(r, 5000); });
    const idle = (await p.page.evaluate(() => window.carrom.frameTimes())).map((f) => f.ms);
    await p.fillLobby({ name: 'Report', ruleSet: 'icf', botLevel: 'random' });
    await p.press('#play-bot');
    const s = await p.waitFor('our break', (st) => st.inRoom && st.myTurn && !st.animating && st.aim.phase === 'idle', 20000);
    if (muted) await p.press('#mute');
    await p.page.evaluate(() => window.carrom.clearFrameTimes());
    const cpuBefore = browserCpu();
    await p.shoot(breakShot(s.aim.y));
    // While frames are timed, the page is looked at only through its cheap progress() hook, 4
    // times a second (window.carrom.state() costs the page a layout and a copy of everything).
    const progress = async (what, fn) => {
      const deadline = Date.now() + 30000;
      while (!fn(await p.page.evaluate(() => window.carrom.progress()))) {
        check(Date.now() < deadline, `${what} did not happen within 30 s`);
        await new Promise((r) => { setTimeout(r, 250); });
      }
    };
    await progress('the break on screen', (st) => st.animating);
    await progress('the break over', (st) => st.turn !== s.turn);
    const cpu = cpuSince(cpuBefore);
    // The break only: the frames where it moves on screen (the bot's reply is another turn).
    const log = await p.page.evaluate(() => window.carrom.frameTimes());
    const frames = log.filter((f) => f.moving && f.turn === s.turn);
    check(frames.length > 30, `only ${frames.length} frames while moving`);
    const work = frames.map((f) => f.ms);
    const inside = frames.map((f) => f.work);
    const intervals = frames.slice(1).map((f, k) => f.ts - frames[k].ts);
    pooled.work.push(...work);
    pooled.inside.push(...inside);
    pooled.idle.push(...idle);
    const after = await p.state();
    check(muted || after.audio === 'running', `the page's sound is on (audio ${after.audio})`);
    results.push({
      frames: frames.length,
      seconds: round((frames[frames.length - 1].ts - frames[0].ts) / 1000),
      idle_p50_ms: round(percentile(idle, 0.5)),
      idle_p99_ms: round(percentile(idle, 0.99)),
      board_paints: after.paints,
      wood_ms: round(after.woodMs),
      p50_ms: round(percentile(work, 0.5)),
      p99_ms: round(percentile(work, 0.99)),
      max_ms: round(percentile(work, 1)),
      work_p50_ms: round(percentile(inside, 0.5)),
      work_p99_ms: round(percentile(inside, 0.99)),
      interval_p50_ms: round(percentile(intervals, 0.5)),
      interval_p99_ms: round(percentile(intervals, 0.99)),
      browser_cpu_ms: cpu,
      audio: muted ? 'muted' : after.audio,
      sounds: after.sounds,
      cues: after.cues,
      engine_ms: loaded.engine.ms === null ? null : round(loaded.engine.ms),
      prediction: after.prediction,
    });
    await context.close();
  }
  const all = {
    frames: pooled.work.length,
    p50_ms: round(percentile(pooled.work, 0.5)),
    p99_ms: round(percentile(pooled.work, 0.99)),
    max_ms: round(percentile(pooled.work, 1)),
    work_p99_ms: round(percentile(pooled.inside, 0.99)),
    idle_p99_ms: round(percentile(pooled.idle, 0.99)),
  };
  const report = { all, served_by: 'carrom-server', viewport: '900x900', chromium_args: 'see tests/web/lib/harness.mjs', runs: results, download };
  if (args.includes('--json')) {
    console.log(JSON.stringify(report));
  } else {
    console.log('run | frames moving | frame p50 | frame p99 | max | callback p50 / p99 | rAF interval p50 / p99 | idle page p50 / p99 | paints | wood | sound | browser CPU in the break by process type');
    results.forEach((r, i) => console.log(`${i + 1} | ${r.frames} in ${r.seconds} s | ${r.p50_ms} ms | ${r.p99_ms} ms | ${r.max_ms} ms | ${r.work_p50_ms} / ${r.work_p99_ms} ms | ${r.interval_p50_ms} / ${r.interval_p99_ms} ms | ${r.idle_p50_ms} / ${r.idle_p99_ms} ms | ${r.board_paints} | ${r.wood_ms} ms | ${r.audio}, ${r.sounds} sounds for ${r.cues.heard} cues (${r.cues.merged} merged, ${r.cues.late} late) | browser CPU ${JSON.stringify(r.browser_cpu_ms)} ms`));
    console.log(`all ${runs} runs: ${all.frames} frames, frame p50 ${all.p50_ms} ms, p99 ${all.p99_ms} ms, max ${all.max_ms} ms; page's work p99 ${all.work_p99_ms} ms; idle page p99 ${all.idle_p99_ms} ms`);
    console.log(`files served by ${report.served_by}`);
    console.log(`download: ${download.files} files, ${download.bodyBytes} bytes of bodies, ${download.transferBytes} bytes transferred (uncompressed), the engine ${download.engineBytes} of them; first contentful paint (the lobby) ${round(download.firstPaintMs)} ms`);
    results.forEach((r, i) => console.log(`${i + 1}: engine loaded in ${r.engine_ms} ms; prediction ${JSON.stringify(r.prediction)}`));
  }
});
