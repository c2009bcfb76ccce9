// The player's ratings in the lobby (docs/web.md, docs/ratings.md): read from GET /players/NAME
// after each welcome and on each return to the lobby; the change since the previous read shows
// after a rated game: "Rating: freestyle 1532 (+14)". A guest, or a player without a rated game,
// sees nothing.

const RULE_SET_WORDS = { icf: 'ICF', seed: 'classic', freestyle: 'freestyle', discpool: 'disc pool' };

// The line for `after` (the "ratings" of GET /players/NAME), with the rounded change from
// `before` (the previous read's, or null) where the games played grew.
export function ratingLine(before, after) {
  if (!Array.isArray(after) || after.length === 0) return '';
  const parts = after.map((r) => {
    const old = (before ?? []).find((b) => b.rule_set === r.rule_set);
    let text = `${RULE_SET_WORDS[r.rule_set] ?? r.rule_set} ${r.label}`;
    if (old && r.games > old.games) {
      const change = Math.round(r.rating) - Math.round(old.rating);
      text += ` (${change >= 0 ? '+' : ''}${change})`;
    } else if (!old && before !== null && r.games > 0) {
      text += ` (${Math.round(r.rating) >= 1500 ? '+' : ''}${Math.round(r.rating) - 1500})`;
    }
    return text;
  });
  return `Rating: ${parts.join(', ')}`;
}

export class RatingView {
  // element: where the line goes; getJson(path) -> parsed JSON or null.
  constructor(element, getJson) {
    this.element = element;
    this.getJson = getJson;
    this.name = '';
    this.last = null; // the last read's ratings for this.name
  }

  async refresh(name) {
    if (name !== this.name) {
      this.name = name;
      this.last = null;
    }
    const answer = await this.getJson(`/players/${encodeURIComponent(name)}`);
    const ratings = answer?.ratings ?? null;
    if (!ratings) return;
    this.element.textContent = ratingLine(this.last, ratings);
    this.last = ratings;
  }
}

// GET path on the page's own server: the JSON, or null on any failure.
export async function getJson(path) {
  try {
    const response = await fetch(path, { cache: 'no-store' });
    return response.ok ? await response.json() : null;
  } catch {
    return null;
  }
}
