// The player's ratings in the lobby (docs/web.md, docs/ratings.md): read from GET /players/NAME
// after each welcome and on each return to the lobby (then once more a moment later: a forfeit's
// result may still be on its way to the store); the change since the last game began shows after
// a rated game: "Rating: freestyle 1532 (+14)". A player without a rated game sees nothing.

import { labelWithChange, parsePlayerRatings, RULE_SET_WORDS } from './rating_words.js';

// The line for `after` (the "ratings" of GET /players/NAME), with the rounded change from
// `before` (the previous read's, or null) where the games played grew.
export function ratingLine(before, after) {
  if (!Array.isArray(after) || after.length === 0) return '';
  const parts = after.map((r) => `${RULE_SET_WORDS[r.rule_set] ?? r.rule_set} ${labelWithChange(before, r)}`);
  return `Rating: ${parts.join(', ')}`;
}

export class RatingView {
  // element: where the line goes; getJson(path) -> parsed JSON or null; kept: playersKept's.
  constructor(element, getJson, kept) {
    this.element = element;
    this.getJson = getJson;
    this.kept = kept;
    this.name = '';
    this.last = null; // the last read's ratings for this.name
    this.base = null; // the ratings as the last game began (the change is shown against them)
  }

  // A room's state came: a game is (or may be) under way.
  gameStarts() {
    this.base = this.last;
  }

  async refresh(name) {
    if (!name || !(await this.kept())) return;
    if (name !== this.name) {
      this.name = name;
      this.last = null;
      this.base = null;
    }
    // A player the store does not know yet (its first hello is still being written) has none.
    const ratings = parsePlayerRatings(await this.getJson(playerPath(name)));
    if (!ratings) return;
    this.element.textContent = ratingLine(this.base, ratings);
    this.last = ratings;
  }
}

export const playerPath = (name) => `/players/${encodeURIComponent(name)}`;

// Whether the server keeps players and ratings (GET /players; with --data none every player
// read would be a 503): a function that asks once per page and answers true or false; a
// question without an answer is asked again next time.
export function playersKept(getJson) {
  let asked = null;
  return async () => {
    asked ??= getJson('/players');
    const answer = await asked;
    if (answer === null) asked = null;
    return answer?.kept === true;
  };
}

// GET path on the page's own server: {status, body}, body the parsed JSON (an error's too) or
// null when there is none; status 0 when the request failed.
export async function getAnswer(path) {
  let status = 0;
  try {
    const response = await fetch(path, { cache: 'no-store' });
    status = response.status;
    return { status, body: await response.json() };
  } catch {
    return { status, body: null };
  }
}

// The JSON answer of GET path (an error's too), or null on any failure.
export async function getJson(path) {
  return (await getAnswer(path)).body;
}
