// The page follows a cluster's redirect (docs/protocol.md, "Redirects"): its address is a
// redirecting instance of tests/web/lib/redirector.mjs in front of a real carrom-server on the
// same host. The room it creates is on the real server; a reload resumes the seat through the
// same redirecting address (hello with the token there, then at the real server).

import { check, launchBrowser, run, startServer, startWebServer } from './lib/harness.mjs';
import { Player } from './lib/player.mjs';
import { redirector } from './lib/redirector.mjs';

run('web.redirect_page', 60000, async (t) => {
  const server = await startServer(['--shot-clock', '0']);
  const web = await startWebServer(server);
  const front = await redirector(server.ws);
  t.browser = await launchBrowser();
  const url = `http://127.0.0.1:${web.port}/index.html?ws=${encodeURIComponent(front.ws)}`;
  const page = await Player.open(await t.browser.newContext({ viewport: { width: 900, height: 900 } }), 'Asha', url, t.errors);
  await page.fillLobby({ name: 'Asha', ruleSet: 'freestyle' });
  await page.press('#create');
  const { code } = await page.waitFor('the room on the real server', (s) => s.inRoom && s.phase === 'waiting');
  check(front.hellos.length === 1 && front.hellos[0].follows_redirects === true,
    `the redirecting address got one hello with follows_redirects (${JSON.stringify(front.hellos)})`);
  console.log(`room ${code} created through the redirect`);

  await page.page.reload();
  const back = await page.waitFor('the seat back after the reload', (s) => s.inRoom && s.session.phase === 'in_room', 15000);
  check(back.code === code && back.you === 0, `same room and seat after the reload (${back.code}, seat ${back.you})`);
  check(front.hellos.length === 2 && /^[0-9a-f]{32}$/.test(front.hellos[1].resume_token ?? ''),
    `the reload said hello with its token at the redirecting address (${JSON.stringify(front.hellos[1])})`);
  front.close();
});
