// Quick reactions between two browser pages through a real carrom-server: Asha sends "Nice shot!"
// from the React menu and Ravi's page shows it beside Asha's side of the board (the top, in his
// turned view), then hides it after its time; Ravi mutes Asha and her next emote is received but
// not shown; a spectator has no React button; a burst over the room's limit gets the
// emote_too_fast sentence and the match goes on. No console errors.

import { check, launchBrowser, pageUrl, run, startServer, startWebServer } from './lib/harness.mjs';
import { Player } from './lib/player.mjs';

const VIEW = { viewport: { width: 900, height: 900 } };

// The text and side of the bubble showing seat `seat`'s emote, or null.
function bubbleOf(page, seat) {
  return page.evaluate((s) => {
    const b = document.querySelector(`.emote-bubble[data-seat="${s}"]:not([hidden])`);
    return b ? { text: b.textContent, at: b.dataset.at } : null;
  }, seat);
}

async function sendEmote(player, id) {
  await player.press('#emote-toggle');
  await player.press(`#emote-menu button[data-emote="${id}"]`);
}

run('web.emotes_pages', 120000, async (t) => {
  const server = await startServer(['--shot-clock', '0', '--no-bots']);
  const web = await startWebServer(server);
  t.browser = await launchBrowser();

  const asha = await Player.open(await t.browser.newContext(VIEW), 'Asha', pageUrl(web, server), t.errors);
  await asha.fillLobby({ name: 'Asha' });
  await asha.press('#create');
  const { code } = await asha.waitFor('the room', (s) => s.inRoom && s.phase === 'waiting');
  check(!(await asha.page.isVisible('#emote-toggle')), 'no React button while the room waits');
  const ravi = await Player.open(await t.browser.newContext(VIEW), 'Ravi', pageUrl(web, server, `#/room/${code}`), t.errors);
  await ravi.fillLobby({ name: 'Ravi' });
  await ravi.press('#join');
  await ravi.waitFor('seat 1', (s) => s.inRoom && s.you === 1 && s.phase === 'aiming');
  await asha.waitFor('the game', (s) => s.phase === 'aiming');
  const watcher = await Player.open(await t.browser.newContext(VIEW), 'Mira', pageUrl(web, server, `#/watch/${code}`), t.errors);
  await watcher.fillLobby({ name: 'Mira' });
  await watcher.press('#watch');
  await watcher.waitFor('watching', (s) => s.inRoom && s.you === -1);
  check(!(await watcher.page.isVisible('#emote-toggle')), 'a spectator has no React button');

  // Asha's emote: on Ravi's page beside Asha's side (the top of his turned view), on her own
  // page at the bottom, and on the spectator's page.
  check(await asha.page.isVisible('#emote-toggle'), 'a seated player has a React button');
  await sendEmote(asha, 'nice_shot');
  await ravi.waitFor('the emote', (s) => s.emotes.visible.length === 1);
  const seen = await bubbleOf(ravi.page, 0);
  check(seen && seen.text === 'Asha: Nice shot!' && seen.at === 'top', `Ravi sees ${JSON.stringify(seen)}`);
  await asha.waitFor('her own emote', (s) => s.emotes.visible.length === 1);
  const own = await bubbleOf(asha.page, 0);
  check(own && own.at === 'bottom' && own.text === 'Asha: Nice shot!', `Asha sees ${JSON.stringify(own)}`);
  await watcher.waitFor('the emote', (s) => s.emotes.visible.length === 1);
  check(!(await asha.page.isVisible('#emote-menu')), 'the menu closes after a pick');

  // It goes away by itself (4 s).
  await ravi.waitFor('the bubble gone', (s) => s.emotes.visible.length === 0, 8000);
  check((await bubbleOf(ravi.page, 0)) === null, 'no bubble after its time');

  // Ravi mutes Asha: her next emote arrives but shows nothing on his page, still on the spectator's.
  await ravi.press('#emote-toggle');
  const muteLabel = await ravi.page.textContent('#emote-menu button[data-mute-seat="0"]');
  check(muteLabel === 'Mute Asha', `the mute switch reads ${muteLabel}`);
  await ravi.press('#emote-menu button[data-mute-seat="0"]');
  await ravi.waitFor('Asha muted', (s) => s.emotes.mutedSeats.includes(0));
  check((await ravi.page.textContent('#emote-menu button[data-mute-seat="0"]')) === 'Unmute Asha', 'the switch now unmutes');
  await ravi.press('#emote-toggle'); // close the menu
  const before = (await ravi.state()).emotes.received;
  await sendEmote(asha, 'wow');
  await ravi.waitFor('the muted emote received', (s) => s.emotes.received === before + 1);
  await watcher.waitFor('the second emote', (s) => s.emotes.received === 2);
  await new Promise((r) => setTimeout(r, 300));
  const muted = await ravi.state();
  check(muted.emotes.visible.length === 0, 'a muted seat shows nothing');
  check((await bubbleOf(ravi.page, 0)) === null, 'no bubble for a muted seat');

  // A burst over the limit (3 at once, then 1 per 2 s): the server's sentence, the match goes on.
  for (let i = 0; i < 3; i += 1) await sendEmote(asha, 'oops');
  await asha.page.waitForFunction(() => document.body.innerText
    .includes('Too many emotes; wait a moment before the next one.'), null, { timeout: 5000 });
  const after = await asha.state();
  check(after.inRoom && after.phase === 'aiming' && after.session.phase === 'in_room', 'the match goes on');
  console.log(`room ${code}: emote shown, hidden after 4 s, muted, rate-limited`);
});
