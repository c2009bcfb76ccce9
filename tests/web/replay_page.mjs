// The replay page (`#/replay/ID`, web/js/replay_page.js) against a match two carrom-bot
// processes played through a real carrom-server with a match store: the Match API's list and
// the lobby's "My matches" link to it, the page replays every input with the engine, each
// replayed outcome (scores, the seat to play next) equals the journal's, the final scores and
// winner are the stored result's and the drawn board is the replayed final board; play/pause,
// previous/next and 0.25x-4x work; a journal whose physics version differs (rewritten in
// flight) is refused with its sentence, and a page without the engine says it has none.
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { check, env, launchBrowser, run, sleep, startChild, startServer } from './lib/harness.mjs';

// The sampling strategy with a seed decides by its 200 candidates, never by the clock (the think
// time is far beyond them): the same match every run, so its replay is the same every run.
function bot(server, name, seed, roomArgs) {
  return startChild(`carrom-bot ${name}`, env.bot, [
    '--url', server.ws, '--name', name, ...roomArgs, '--strategy', 'sampling', '--seed', String(seed),
    '--think-ms', '5000', '--games', '1', '--timeout', '150', '--log-level', 'info',
  ], /room ([A-Z0-9]{6})/);
}

run('web.replay_page', 180000, async (t) => {
  check(env.bot, 'CARROM_BOT is not set');
  const dir = mkdtempSync(join(tmpdir(), 'carrom-replay-'));
  try {
    const server = await startServer(['--shot-clock', '0', '--time-scale', '8', '--no-bots',
      '--data', join(dir, 'matches.sqlite')]);
    const alpha = await bot(server, 'Alpha', 1, ['--create', '--rule-set', 'icf', '--boards', '1']);
    const beta = await bot(server, 'Beta', 2, ['--join', alpha.match[1]]);
    const [a, b] = await Promise.all([alpha.exited, beta.exited]);
    check(a === 0 && b === 0, `the bots finished (exit ${a}, ${b})`);

    // The stored result, and the list's link to the replay page.
    const base = `http://127.0.0.1:${server.port}`;
    let listed = null;
    for (let i = 0; i < 50 && !listed?.result; i += 1) {
      listed = (await (await fetch(`${base}/matches?player=Alpha`)).json()).matches[0];
      if (!listed?.result) await sleep(100);
    }
    check(listed?.result, `the match is stored with its result: ${JSON.stringify(listed)}`);
    check(listed.replay === `/#/replay/${listed.id}`, `the list links to the replay page (${listed.replay})`);

    t.browser = await launchBrowser();
    const context = await t.browser.newContext({ viewport: { width: 900, height: 900 } });
    const page = await context.newPage();
    page.on('console', (m) => { if (m.type() === 'error') t.errors.push(m.text()); });
    page.on('pageerror', (e) => t.errors.push(e.message));
    const look = () => page.evaluate(() => window.carrom.replay());
    const waitFor = async (what, fn, ms = 20000) => {
      const deadline = Date.now() + ms;
      for (;;) {
        const s = await look();
        if (fn(s)) return s;
        check(Date.now() < deadline, `${what}: not after ${ms} ms: ${JSON.stringify({ ...s, board: undefined, drawn: undefined })}`);
        await sleep(50);
      }
    };
    // The lobby's "My matches" lists it; its link opens the replay page.
    await page.goto(`${base}/`);
    await page.fill('#name', 'Alpha');
    await page.click('#my-matches summary');
    await page.click(`#my-matches a[href="${listed.replay.slice(1)}"]`);
    await page.waitForFunction(() => window.carrom?.replay !== undefined);
    const loaded = await waitFor('the replay loaded', (s) => s.loaded || s.error);
    check(!loaded.error, `the replay loaded: ${loaded.error}`);
    check(loaded.mismatches === 0, `every input replays as recorded (${loaded.mismatches} differ)`);
    check(loaded.strokes > 0 && loaded.playing && loaded.speed === 1, 'it plays from the first stroke at 1x');
    check(await page.isHidden('#lobby'), 'no lobby on the replay page');

    // Controls: pause, faster to 4x, slower to 0.25x, next and previous stroke.
    await page.click('#replay-play');
    check(!(await look()).playing, 'Pause pauses');
    for (let i = 0; i < 5; i += 1) await page.click('#replay-faster');
    check((await look()).speed === 4, 'Faster reaches 4x and stops there');
    for (let i = 0; i < 6; i += 1) await page.click('#replay-slower');
    check((await look()).speed === 0.25, 'Slower reaches 0.25x and stops there');
    await page.click('#replay-next');
    await page.click('#replay-next');
    const second = await look();
    await page.click('#replay-prev');
    const back = await look();
    check(back.time < second.time, `Previous goes back (${second.time} -> ${back.time})`);
    await page.keyboard.press('+');
    check((await look()).speed === 0.5, 'the + key is faster');
    await page.keyboard.press('ArrowUp');
    check((await look()).speed === 1, 'Up is faster');
    await page.keyboard.press('ArrowDown');
    check((await look()).speed === 0.5, 'Down is slower');
    await page.keyboard.press('Home');
    const home = await look();
    check(home.time < 0.5 && home.playing, `Home plays from the start (${home.time})`);
    await page.keyboard.press(' ');

    // To the last input, then play to the end at 4x.
    for (let i = 0; i < loaded.inputs + 1; i += 1) await page.keyboard.press('ArrowRight');
    const end = await look();
    check(end.finished, 'Next past the last input ends the replay');
    await page.keyboard.press('ArrowLeft');
    for (let i = 0; i < 4; i += 1) await page.click('#replay-faster');
    await page.keyboard.press(' ');
    const done = await waitFor('the end played', (s) => s.finished && !s.playing, 30000);
    const teams = listed.scores.length;
    check(JSON.stringify(done.final.scores.slice(0, teams)) === JSON.stringify(listed.scores),
      `final scores: replay ${done.final.scores.slice(0, teams)}, stored ${listed.scores}`);
    check(done.final.winner === (listed.result.winner_team ?? -1),
      `winner: replay ${done.final.winner}, stored ${listed.result.winner_team}`);
    check(done.final.phase === 'game_over', `the replayed game is over (${done.final.phase})`);
    const onBoard = done.board.filter((x) => !x.pocketed);
    check(onBoard.length === done.drawn.length && onBoard.every((x) => done.drawn.some(
      (d) => d.id === x.id && d.x === x.x && d.y === x.y)), 'the drawn board is the replayed final board');
    const status = await page.textContent('#replay-status');
    check(status.includes(`Stroke ${done.strokes} / ${done.strokes}`), `the bar counts the strokes: ${status}`);
    const said = await page.textContent('#replay-event');
    const winner = listed.players[listed.result.winner_team];
    check(said.includes(`${winner} wins the game`), `the bar says the last stroke's end: ${said}`);

    // A journal of another physics version: refused with one sentence.
    const other = await context.newPage();
    await other.route('**/matches/*', async (route) => {
      const journal = await (await route.fetch()).json();
      journal.match.versions.physics += 1;
      await route.fulfill({ json: journal });
    });
    await other.goto(`${base}${listed.replay}`);
    await other.waitForFunction(() => window.carrom?.replay().error);
    const refused = await other.evaluate(() => window.carrom.replay().error);
    check(/played with physics version \d+; this page runs version \d+/.test(refused), `the refusal: ${refused}`);
    check((await other.textContent('#replay-status')) === refused, 'the refusal is shown');
    // A page without the engine (an empty module, as a build without emscripten embeds): said so.
    const bare = await context.newPage();
    await bare.route('**/*.wasm', (route) => route.fulfill({ status: 200, contentType: 'application/wasm', body: '' }));
    await bare.goto(`${base}${listed.replay}`);
    await bare.waitForFunction(() => window.carrom?.replay().error);
    const none = await bare.evaluate(() => window.carrom.replay().error);
    check(/^This page has no engine to replay matches with/.test(none), `without the engine: ${none}`);
    console.log(`match ${listed.id}: ${done.strokes} strokes, ${done.inputs} inputs replayed, scores ${listed.scores}, `
      + `${loaded.bitDifferences} inputs not bit-identical to the server's, engine and journal in ${loaded.engineMs.toFixed(0)} ms`);
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});
