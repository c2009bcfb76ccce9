// The lobby's "My matches": opened, it lists the player's most recent stored matches (GET
// /matches?player=NAME, docs/matches.md), each a link to its replay page (`#/replay/ID`,
// replay_page.js). Asked only when opened (a server without a match store answers 503, which
// the list says in words).

import { matchApiUrl, replayHash } from './replay_page.js';

const SHOWN = 5;

function line(m) {
  const when = new Date(m.created_ms).toLocaleString();
  const score = m.scores.length > 0 ? ` ${m.scores.join(' : ')}` : '';
  const result = m.result === null ? (m.finished_ms === null ? ' (playing)' : ' (unfinished)') : '';
  return `${m.players.join(' v ')}${score}${result}, ${when}`;
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
      rows = answer.ok ? body.matches.map((m) => item(Object.assign(document.createElement('a'), { href: replayHash(m.id), textContent: line(m) })))
        : [item(document.createTextNode(body.error?.message ?? 'The server cannot list matches.'))];
      if (answer.ok && rows.length === 0) rows = [item(document.createTextNode(`No stored matches of ${name} yet.`))];
    } catch {
      rows = [item(document.createTextNode('The server cannot list matches.'))];
    }
    this.list.replaceChildren(...rows);
  }
}
