// The ratings in words (docs/ratings.md, docs/protocol.md "Players and leaderboard"), pure: the
// answers of GET /players/NAME and GET /leaderboard checked field by field (a malformed answer
// reads as none), a rating with its change after a rated game ("1532 (+14)"), the leaderboard's
// rows, and one sentence for each answer that has none.

export const RULE_SET_WORDS = Object.freeze({ icf: 'ICF', seed: 'classic', freestyle: 'freestyle', discpool: 'disc pool' });

// A new identified player's rating in a rule set (Glicko-2's start; its label is provisional).
export const NEW_RATING = 1500;
export const NEW_RATING_LABEL = `${NEW_RATING}?`;

const isCount = (n) => Number.isInteger(n) && n >= 0;

function isRating(r) {
  return r !== null && typeof r === 'object' && typeof r.rule_set === 'string'
    && Number.isFinite(r.rating) && typeof r.label === 'string' && r.label !== '' && isCount(r.games);
}

// The "ratings" of a GET /players/NAME answer: an array (empty for a player the store does not
// know: a guest, or a first hello still being written), or null when the answer is missing,
// an error or malformed (nothing is known).
export function parsePlayerRatings(answer) {
  if (answer === null || typeof answer !== 'object') return null;
  if (answer.error?.code === 'unknown_player') return [];
  if (!Array.isArray(answer.ratings) || !answer.ratings.every(isRating)) return null;
  return answer.ratings;
}

// The rating of `ruleSet` in a parsed ratings array, or null.
export function ratingOf(ratings, ruleSet) {
  return ratings?.find((r) => r.rule_set === ruleSet) ?? null;
}

// The rounded change of `after` (one rule set's rating) since `before` (the ratings read
// earlier; null: none read), when its games grew: a first game counts from NEW_RATING. Else null.
export function ratingChange(before, after) {
  if (before === null || !after) return null;
  const old = ratingOf(before, after.rule_set);
  if (old) return after.games > old.games ? Math.round(after.rating) - Math.round(old.rating) : null;
  return after.games > 0 ? Math.round(after.rating) - NEW_RATING : null;
}

// "1532 (+14)", or the label alone without a change.
export function labelWithChange(before, after) {
  const change = ratingChange(before, after);
  return change === null ? after.label : `${after.label} (${change >= 0 ? '+' : ''}${change})`;
}

const LEADERBOARD_UNREADABLE = 'The leaderboard could not be read; try again in a moment.';

// What the lobby's leaderboard shows for the answer to GET /leaderboard?rule_set=R: status (the
// HTTP status, 0 when the request failed) and body (the parsed JSON, null when it was none).
// Returns {rows: [{rank, name, label, games}], sentence} with a sentence when there are no rows.
export function leaderboardView(ruleSet, status, body) {
  const none = (sentence) => ({ rows: [], sentence });
  if (status !== 200) {
    const code = body?.error?.code;
    if (status === 429 || code === 'rate_limited') return none('Too many requests: try the leaderboard again in a few seconds.');
    if (code === 'store_disabled') return none('This server keeps no ratings, so it has no leaderboard.');
    return none(LEADERBOARD_UNREADABLE);
  }
  const players = body?.players;
  const valid = body?.rule_set === ruleSet && Array.isArray(players) && players.every((p) => p !== null
    && typeof p === 'object' && Number.isInteger(p.rank) && p.rank > 0 && typeof p.name === 'string'
    && typeof p.label === 'string' && isCount(p.games));
  if (!valid) return none(LEADERBOARD_UNREADABLE);
  if (players.length === 0) {
    return none(`Nobody has an established ${RULE_SET_WORDS[ruleSet] ?? ruleSet} rating yet (it takes about 10 rated games).`);
  }
  return { rows: players.map(({ rank, name, label, games }) => ({ rank, name, label, games })), sentence: '' };
}
