// The lobby's "My matches": opened, it lists the player's most recent stored matches (GET
// /matches?player=NAME, docs/matches.md), each a link to its replay page (`#/replay/ID`,
// replay_page.js). Asked only when opened (a server without a match store answers 503, which
// the list says in words).

import { RULE_SET_WORDS } from './rating_words.js';
import { matchApiUrl, replayHash } from './replay_page.js';

const SHOWN = 5;

const localDate = (ms) => new Date(ms).toLocaleString([], { dateStyle: 'medium', timeStyle: 'short' });

// One stored match (an entry of GET /matches) from `name`'s side: "vs Ravi · won 25 : 11 · ICF ·
// Nov 28, 2026, 6:02 PM" (doubles: "with Chitra vs Ravi & Dev ..."; our score first); the
// result "won", "lost", "drawn", "playing" or "unfinished" (cut off, no result). A match without
// a seat of that name (names compare case-blind) lists its players: "Asha v Ravi 3 : 0 · ...".
export function matchLine(m, name, when = localDate) {
  const me = m.players.findIndex((p) => p.toLowerCase() === name.toLowerCase());
  const team = m.teams[me];
  const scores = me < 0 ? m.scores : [m.scores[team], ...m.scores.filter((_, t) => t !== team)];
  const score = m.scores.length > 0 ? ` ${scores.join(' : ')}` : '';
  let result;
  if (m.result === null) result = m.finished_ms === null ? 'playing' : 'unfinished';
  else if (m.result.winner_team === null) result = 'drawn';
  else result = m.result.winner_team === team ? 'won' : 'lost';
  let who = m.players.join(' v ');
  if (me >= 0) {
    const names = (pick) => m.players.filter((_, i) => i !== me && pick(m.teams[i] === team)).join(' & ');
    who = `vs ${names((same) => !same)}`;
    if (names((same) => same)) who = `with ${names((same) => same)} ${who}`;
  }
  const rules = RULE_SET_WORDS[m.rule_set] ?? m.rule_set;
  return me < 0 ? `${who}${score} · ${rules} · ${when(m.created_ms)}`
    : `${who} · ${result}${score} · ${rules} · ${when(m.created_ms)}`;
}

function item(child) {
  const li = document.createElement('li');
  li.append(child);
  return li;
}

export class MyMatches {
  // form: the lobby's form, which the list joins at its end; name(): the player's name.
  constructor(form, name) {
    this.details = Object.assign(document.createElement('details'), { id: 'my-matches' });
    this.list = document.createElement('ul');
    this.details.append(Object.assign(document.createElement('summary'), { textContent: 'My matches' }), this.list);
    form.append(this.details);
    this.details.addEventListener('toggle', () => { if (this.details.open) this.show(name()); });
  }

  async show(name) {
    if (!name) {
      this.list.replaceChildren(item(document.createTextNode('Pick a name first.')));
      return;
    }
    let rows;
    try {
      const answer = await fetch(matchApiUrl(`matches?player=${encodeURIComponent(name)}&limit=${SHOWN}`));
      const body = await answer.json();
      rows = answer.ok ? body.matches.map((m) => item(Object.assign(document.createElement('a'), { href: replayHash(m.id), textContent: matchLine(m, name) })))
        : [item(document.createTextNode(body.error?.message ?? 'The server cannot list matches.'))];
      if (answer.ok && rows.length === 0) rows = [item(document.createTextNode(`No stored matches of ${name} yet.`))];
    } catch {
      rows = [item(document.createTextNode('The server cannot list matches.'))];
    }
    this.list.replaceChildren(...rows);
  }
}
