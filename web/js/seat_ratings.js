// Each seat's rating in a singles match, beside its name in the top bar, and after a rated game
// each player's change in the game-over card: "Ratings: Asha 1532 (+14), Ravi 1468 (-14)"
// (docs/web.md, "Ratings in a match"). room_state carries no ratings: the page reads
// GET /players/NAME of each seat's holder once when a game starts (a room's first state, a new
// holder, a rematch) and once when it ends; in a rated room whose end read shows no new game yet
// (the store writes the result beside the room) once more RATING_REREAD_MS later. So a seat costs
// at most three reads per game; none where the server keeps no players. Bots are not read; a
// guest (unknown_player) has none. Doubles are not rated (docs/ratings.md): no ratings there.

import { labelWithChange, NEW_RATING_LABEL, parsePlayerRatings, ratingChange, ratingOf } from './rating_words.js';
import { playerPath } from './rating_view.js';

export const RATING_REREAD_MS = 1500;

// One seat's holder in one game: ratings as the game started and as it ended (an array, [] for
// none, null when the read failed, undefined while unread); endReads: reads of the end asked.
class SeatHolder {
  constructor(name) {
    this.name = name;
    this.start = undefined;
    this.end = undefined;
    this.endReads = 0;
    this.pending = 0;
  }
}

export class SeatRatings {
  // getJson(path): the parsed JSON answer or null; kept(): whether the server keeps players
  // (rating_view.js, playersKept); later(fn, ms): a timer.
  constructor(getJson, kept, later = (fn, ms) => setTimeout(fn, ms)) {
    this.getJson = getJson;
    this.kept = kept;
    this.later = later;
    this.reads = 0; // GET /players/NAME asked, for the debug hook
    this.clear();
  }

  clear() {
    this.code = '';
    this.ruleSet = '';
    this.rated = false;
    this.over = false;
    this.holders = [];
  }

  // After each message: the model's view (match_model.js). Starts the reads a new game, a new
  // holder or the game's end needs.
  update(view) {
    if (!view.inRoom || view.seats.length !== 2) {
      if (this.code !== '') this.clear();
      return;
    }
    if (view.code !== this.code) {
      this.clear();
      this.code = view.code;
    }
    this.ruleSet = view.ruleSet;
    this.rated = view.aimAssist === false; // a rated room has no aim assist (docs/ratings.md)
    const over = view.phase === 'game_over';
    if (this.over && !over) this.holders = []; // a rematch: a new game, read again
    this.over = over;
    view.seats.forEach((s, i) => {
      const name = s.occupied && !s.bot ? s.name : '';
      // A player who leaves an ended game (or forfeits by leaving) is still the one who played it.
      const left = name === '' && over;
      if (!left && (this.holders[i]?.name ?? '') !== name) this.holders[i] = name ? new SeatHolder(name) : undefined;
      const h = this.holders[i];
      if (!h) return;
      if (h.start === undefined && h.pending === 0 && !over) this.read(h, 'start');
      if (over && h.endReads === 0) this.read(h, 'end');
    });
  }

  async read(h, which) {
    h.pending += 1;
    if (which === 'end') h.endReads += 1;
    const kept = await this.kept();
    if (kept) this.reads += 1;
    const ratings = kept ? parsePlayerRatings(await this.getJson(playerPath(h.name))) : null;
    h.pending -= 1;
    if (!this.holders.includes(h)) return; // another room, holder or game since
    if (which === 'start') {
      h.start = ratings;
      return;
    }
    if (ratings !== null || h.end === undefined) h.end = ratings;
    // A rated game's result may reach the store after its end reached the page: one more read.
    if (kept && this.rated && h.endReads === 1 && this.change(h) === null) {
      h.pending += 1;
      this.later(() => {
        h.pending -= 1;
        if (this.holders.includes(h)) this.read(h, 'end');
      }, RATING_REREAD_MS);
    }
  }

  change(h) {
    if (!h.start || !h.end) return null;
    return ratingChange(h.start, ratingOf(h.end, this.ruleSet));
  }

  // The seat's rating in the room's rule set ("1532", "1520?"), '' when unknown or none. An
  // identified player without a rating of this rule set in a rated room starts at NEW_RATING.
  label(seat) {
    const h = this.holders[seat];
    const ratings = h?.end ?? h?.start;
    if (!ratings) return '';
    const r = ratingOf(ratings, this.ruleSet);
    if (r) return r.label;
    return this.rated && h.start !== null ? NEW_RATING_LABEL : '';
  }

  // The game-over card's line: each player whose rating changed with this game ("Ratings: Asha
  // 1614\u00a0(+14), Ravi 1506\u00a0(-14)"), or while a rated
  // game's reads are outstanding "Ratings: being updated...", else ''.
  gameOverLine() {
    if (!this.over) return '';
    // A rating and its change stay on one line (a no-break space between them).
    const changed = this.holders.filter((h) => h && this.change(h) !== null)
      .map((h) => `${h.name} ${labelWithChange(h.start, ratingOf(h.end, this.ruleSet)).replace(' ', '\u00a0')}`);
    if (changed.length > 0) return `Ratings: ${changed.join(', ')}`;
    return this.rated && this.holders.some((h) => h?.pending > 0) ? 'Ratings: being updated...' : '';
  }

  debugState() {
    return { seats: [0, 1].map((i) => this.label(i)), gameOver: this.gameOverLine(), reads: this.reads, rated: this.rated };
  }
}
