// The lobby's "Leaderboard" (docs/web.md): opened, it reads GET /leaderboard?rule_set=R&limit=50
// for the chosen rule set and lists rank, name, rating and games, the player's own row marked;
// an answer without rows (none yet, refused, rate-limited, malformed, no answer) is one sentence
// (rating_words.js, leaderboardView). Asked when opened and when the rule set changes; an older
// answer that comes after a newer question is dropped.

import { leaderboardView } from './rating_words.js';

export const LEADERBOARD_ROWS = 50;

const el = (tag, props = {}) => Object.assign(document.createElement(tag), props);

export class Leaderboard {
  // form: the lobby's form, which the view joins at its end; name(): the player's name;
  // getAnswer(path) -> {status, body} (rating_view.js).
  constructor(form, name, getAnswer) {
    this.name = name;
    this.getAnswer = getAnswer;
    this.asked = 0;
    this.details = el('details', { id: 'leaderboard' });
    this.ruleSet = el('select', { id: 'leaderboard-rule-set' });
    // The rule sets as the lobby's new game names them.
    for (const o of form.querySelector('#rule-set').options) this.ruleSet.append(el('option', { value: o.value, textContent: o.textContent }));
    const chooser = el('label', { className: 'row', textContent: 'Rules ' });
    chooser.append(this.ruleSet);
    this.note = el('p', { id: 'leaderboard-note', className: 'dim' });
    this.table = el('table', { id: 'leaderboard-rows', hidden: true });
    this.details.append(el('summary', { textContent: 'Leaderboard' }), chooser, this.note, this.table);
    form.append(this.details);
    this.details.addEventListener('toggle', () => { if (this.details.open) this.show(); });
    this.ruleSet.addEventListener('change', () => this.show());
  }

  async show() {
    const ruleSet = this.ruleSet.value;
    const asked = ++this.asked;
    this.note.textContent = 'Reading the leaderboard...';
    const { status, body } = await this.getAnswer(`/leaderboard?rule_set=${ruleSet}&limit=${LEADERBOARD_ROWS}`);
    if (asked !== this.asked) return;
    const view = leaderboardView(ruleSet, status, body);
    this.note.textContent = view.sentence;
    const me = this.name().toLowerCase();
    const head = el('tr');
    for (const h of ['#', 'Player', 'Rating', 'Games']) head.append(el('th', { textContent: h }));
    this.table.replaceChildren(head, ...view.rows.map((r) => {
      const tr = el('tr', { className: r.name.toLowerCase() === me ? 'you' : '' });
      for (const v of [r.rank, r.name, r.label, r.games]) tr.append(el('td', { textContent: String(v) }));
      return tr;
    }));
    this.table.hidden = view.rows.length === 0;
  }
}
