// The page's ratings without a browser (docs/web.md, "Ratings in a match", "Leaderboard"): the
// answers of GET /players/NAME and GET /leaderboard read field by field (bad ones read as none),
// a rating's change in words, the leaderboard's rows and sentences, My matches' lines from the
// player's side, the seats' reads (SeatRatings: when it asks, what each seat and the game-over
// card say), and the aim assist off in a rated room.
import assert from 'node:assert/strict';
import test from 'node:test';

import { aimAssistAllowed } from '../../web/js/aim_assist.js';
import { matchLine } from '../../web/js/my_matches.js';
import {
  labelWithChange, leaderboardView, NEW_RATING_LABEL, parsePlayerRatings, ratingChange, ratingOf,
} from '../../web/js/rating_words.js';
import { playersKept } from '../../web/js/rating_view.js';
import { RATING_REREAD_MS, SeatRatings } from '../../web/js/seat_ratings.js';

const icf = (rating, games, label = String(Math.round(rating))) => ({ rule_set: 'icf', rating, label, games, deviation: 80 });

// ---- GET /players/NAME ----

test('a player answer gives its ratings; a guest none; anything else nothing known', () => {
  const ratings = [icf(1532.4, 14), { rule_set: 'freestyle', rating: 1662.3, label: '1662?', games: 1 }];
  assert.deepEqual(parsePlayerRatings({ name: 'Asha', ratings, matches: [] }), ratings);
  assert.deepEqual(parsePlayerRatings({ name: 'Asha', ratings: [] }), []);
  assert.deepEqual(parsePlayerRatings({ error: { code: 'unknown_player', message: 'no such player' } }), []);
  assert.equal(parsePlayerRatings(null), null); // no answer, or not JSON
  assert.equal(parsePlayerRatings('1532'), null);
  assert.equal(parsePlayerRatings(42), null);
  assert.equal(parsePlayerRatings({ error: { code: 'rate_limited' } }), null);
  assert.equal(parsePlayerRatings({ error: { code: 'store_disabled' } }), null);
  assert.equal(parsePlayerRatings({ name: 'Asha' }), null);
  assert.equal(parsePlayerRatings({ ratings: {} }), null);
});

test('a rating with a missing or wrong field makes the answer unknown', () => {
  const bad = [null, 'icf', { ...icf(1500, 1), rule_set: 3 }, { ...icf(1500, 1), rating: '1500' },
    { ...icf(1500, 1), rating: NaN }, { ...icf(1500, 1), rating: Infinity }, { ...icf(1500, 1), label: '' },
    { ...icf(1500, 1), label: 1500 }, { ...icf(1500, 1), games: -1 }, { ...icf(1500, 1), games: 1.5 },
    { rule_set: 'icf', rating: 1500, label: '1500' }];
  for (const r of bad) assert.equal(parsePlayerRatings({ ratings: [icf(1500, 3), r] }), null, JSON.stringify(r));
});

test('the rating of a rule set is found by its name', () => {
  const ratings = [icf(1532, 14), { rule_set: 'seed', rating: 1400, label: '1400', games: 2 }];
  assert.equal(ratingOf(ratings, 'seed').rating, 1400);
  assert.equal(ratingOf(ratings, 'freestyle'), null);
  assert.equal(ratingOf(null, 'icf'), null);
  assert.equal(ratingOf(undefined, 'icf'), null);
});

// ---- the change after a game ----

test('a change is the rounded difference once the games grew', () => {
  assert.equal(ratingChange([icf(1518.4, 12)], icf(1532.2, 13)), 14);
  assert.equal(ratingChange([icf(1532.6, 13)], icf(1518.4, 14)), -15);
  assert.equal(ratingChange([icf(1500.2, 3)], icf(1499.9, 4)), 0);
  assert.equal(ratingChange([icf(1518.4, 12)], icf(1532.2, 12)), null); // no game since
  assert.equal(ratingChange(null, icf(1532.2, 13)), null); // nothing read before
  assert.equal(ratingChange([icf(1518.4, 12)], null), null);
});

test('a first rated game counts from 1500', () => {
  assert.equal(ratingChange([], icf(1662.3, 1, '1662?')), 162);
  assert.equal(ratingChange([], icf(1337.7, 1, '1338?')), -162);
  assert.equal(ratingChange([], icf(1500, 0, '1500?')), null);
  assert.equal(ratingChange([{ rule_set: 'seed', rating: 1600, label: '1600', games: 9 }], icf(1662.3, 1)), 162);
});

test('the label with its change reads "1532 (+14)"', () => {
  assert.equal(labelWithChange([icf(1518.4, 12)], icf(1532.2, 13)), '1532 (+14)');
  assert.equal(labelWithChange([icf(1532.6, 13)], icf(1518.4, 14)), '1518 (-15)');
  assert.equal(labelWithChange([icf(1500.2, 3)], icf(1499.9, 4)), '1500 (+0)');
  assert.equal(labelWithChange([], icf(1337.7, 1, '1338?')), '1338? (-162)');
  assert.equal(labelWithChange([icf(1532, 13)], icf(1532, 13)), '1532');
  assert.equal(NEW_RATING_LABEL, '1500?');
});

// ---- GET /leaderboard ----

const row = (rank, name, label, games) => ({ rank, name, rating: Number(label), deviation: 70, volatility: 0.06, provisional: false, label, games, wins: 1, losses: 1, draws: 0, last_game_ms: 1 });

test('the leaderboard lists rank, name, rating label and games in the answer\'s order', () => {
  const body = { rule_set: 'icf', players: [row(1, 'Asha', '1687', 31), row(2, 'Ravi', '1540', 12)] };
  assert.deepEqual(leaderboardView('icf', 200, body), {
    rows: [{ rank: 1, name: 'Asha', label: '1687', games: 31 }, { rank: 2, name: 'Ravi', label: '1540', games: 12 }],
    sentence: '',
  });
});

test('an empty leaderboard says why in one sentence naming the rule set', () => {
  assert.deepEqual(leaderboardView('icf', 200, { rule_set: 'icf', players: [] }),
    { rows: [], sentence: 'Nobody has an established ICF rating yet (it takes about 10 rated games).' });
  assert.equal(leaderboardView('discpool', 200, { rule_set: 'discpool', players: [] }).sentence,
    'Nobody has an established disc pool rating yet (it takes about 10 rated games).');
});

test('a refused or failed leaderboard is one sentence and no rows', () => {
  const unreadable = 'The leaderboard could not be read; try again in a moment.';
  const limited = 'Too many requests: try the leaderboard again in a few seconds.';
  const cases = [
    [429, { error: { code: 'rate_limited', message: 'too many requests' } }, limited],
    [429, null, limited],
    [503, { error: { code: 'store_disabled', message: 'no store' } }, 'This server keeps no ratings, so it has no leaderboard.'],
    [503, { error: { code: 'store_busy', message: 'busy' } }, unreadable],
    [400, { error: { code: 'bad_query', message: 'bad' } }, unreadable],
    [404, null, unreadable], // a server without the endpoint answers its page, not JSON
    [500, { error: { code: 'store_error' } }, unreadable],
    [0, null, unreadable], // the request failed
  ];
  for (const [status, body, sentence] of cases) {
    assert.deepEqual(leaderboardView('icf', status, body), { rows: [], sentence }, `${status} ${JSON.stringify(body)}`);
  }
});

test('a malformed leaderboard answer is unreadable, not a list', () => {
  const unreadable = { rows: [], sentence: 'The leaderboard could not be read; try again in a moment.' };
  const good = row(1, 'Asha', '1687', 31);
  const bodies = [null, 'text', [], {}, { rule_set: 'icf' }, { rule_set: 'icf', players: {} },
    { rule_set: 'seed', players: [good] }, // another rule set's answer
    { rule_set: 'icf', players: [null] }, { rule_set: 'icf', players: [{ ...good, rank: 0 }] },
    { rule_set: 'icf', players: [{ ...good, rank: '1' }] }, { rule_set: 'icf', players: [{ ...good, name: 7 }] },
    { rule_set: 'icf', players: [{ ...good, label: 1687 }] }, { rule_set: 'icf', players: [{ ...good, games: -2 }] },
    { rule_set: 'icf', players: [good, { ...good, games: undefined }] }];
  for (const body of bodies) assert.deepEqual(leaderboardView('icf', 200, body), unreadable, JSON.stringify(body));
});

// ---- My matches ----

const when = (ms) => `t${ms}`;
const stored = (over) => ({
  id: 'k3j9x0a1b2c3d4e5', rule_set: 'icf', players: ['Asha', 'Ravi'], teams: [0, 1], created_ms: 5,
  finished_ms: 9, result: { winner_team: 0, reason: 'target_points' }, scores: [25, 11], ...over,
});

test('a match reads from the player\'s side: opponent, result, our score first, rules, date', () => {
  assert.equal(matchLine(stored(), 'Asha', when), 'vs Ravi · won 25 : 11 · ICF · t5');
  assert.equal(matchLine(stored(), 'Ravi', when), 'vs Asha · lost 11 : 25 · ICF · t5');
  assert.equal(matchLine(stored(), 'ravi', when), 'vs Asha · lost 11 : 25 · ICF · t5'); // names compare case-blind
  assert.equal(matchLine(stored({ result: { winner_team: null, reason: 'cleared' }, scores: [3, 3], rule_set: 'freestyle' }), 'Asha', when),
    'vs Ravi · drawn 3 : 3 · freestyle · t5');
  assert.equal(matchLine(stored({ result: null, finished_ms: null, scores: [] }), 'Asha', when), 'vs Ravi · playing · ICF · t5');
  assert.equal(matchLine(stored({ result: null, scores: [], rule_set: 'seed' }), 'Asha', when), 'vs Ravi · unfinished · classic · t5');
});

test('a doubles match names the partner and both opponents', () => {
  const m = stored({ players: ['Asha', 'Ravi', 'Chitra', 'Dev'], teams: [0, 1, 0, 1], result: { winner_team: 1 }, scores: [4, 9] });
  assert.equal(matchLine(m, 'Chitra', when), 'with Asha vs Ravi & Dev · lost 4 : 9 · ICF · t5');
  assert.equal(matchLine(m, 'Dev', when), 'with Ravi vs Asha & Chitra · won 9 : 4 · ICF · t5');
});

test('a match without a seat of that name lists its players', () => {
  assert.equal(matchLine(stored(), 'Old name', when), 'Asha v Ravi 25 : 11 · ICF · t5');
});

// ---- the seats' ratings in a match ----

// The page's server as SeatRatings sees it: answers by path, each read recorded; later() keeps
// the timer's function for the test to run.
class Answers {
  constructor(byName) {
    this.byName = byName;
    this.paths = [];
    this.timers = [];
    this.kept = true; // GET /players says {"kept": true}
    this.seats = new SeatRatings((path) => this.get(path), async () => this.kept, (fn, ms) => this.timers.push({ fn, ms }));
  }

  async get(path) {
    this.paths.push(path);
    const name = decodeURIComponent(path.slice('/players/'.length));
    const answer = this.byName[name];
    return typeof answer === 'function' ? answer() : (answer ?? { error: { code: 'unknown_player' } });
  }
}

const settle = () => new Promise((r) => { setImmediate(r); });

function room(phase, seats, over = {}) {
  return {
    inRoom: true, code: 'ABCDEF', ruleSet: 'icf', aimAssist: false, phase,
    seats: seats.map((s) => (typeof s === 'string' ? { occupied: true, name: s, bot: false } : s)),
    ...over,
  };
}

const empty = { occupied: false, name: '', bot: false };

test('each seat is read once as the game starts; its label is the room\'s rule set\'s', async () => {
  const a = new Answers({ Asha: { ratings: [icf(1600.2, 20), { rule_set: 'seed', rating: 1400, label: '1400', games: 2 }] }, Ravi: { ratings: [icf(1498.7, 21)] } });
  a.seats.update(room('waiting', ['Asha', empty]));
  a.seats.update(room('waiting', ['Asha', empty]));
  a.seats.update(room('aiming', ['Asha', 'Ravi']));
  a.seats.update(room('moving', ['Asha', 'Ravi']));
  await settle();
  assert.deepEqual(a.paths, ['/players/Asha', '/players/Ravi']);
  assert.equal(a.seats.label(0), '1600');
  assert.equal(a.seats.label(1), '1499');
  assert.equal(a.seats.gameOverLine(), '');
});

test('a new player in a rated room shows 1500?; in an unrated room nothing; a guest nothing', async () => {
  const a = new Answers({ Asha: { ratings: [] } });
  a.seats.update(room('aiming', ['Asha', 'Guest']));
  await settle();
  assert.equal(a.seats.label(0), NEW_RATING_LABEL);
  assert.equal(a.seats.label(1), NEW_RATING_LABEL); // a rated room seats identified players only
  const u = new Answers({ Asha: { ratings: [] } });
  u.seats.update(room('aiming', ['Asha', 'Guest'], { aimAssist: true }));
  await settle();
  assert.deepEqual([u.seats.label(0), u.seats.label(1)], ['', '']);
});

test('a server bot is not read and shows nothing', async () => {
  const a = new Answers({ Asha: { ratings: [icf(1600, 20)] } });
  a.seats.update(room('aiming', ['Asha', { occupied: true, name: 'Bot (easy)', bot: true }], { aimAssist: true }));
  await settle();
  assert.deepEqual(a.paths, ['/players/Asha']);
  assert.equal(a.seats.label(1), '');
});

test('a failed or malformed read shows nothing and throws nothing', async () => {
  const a = new Answers({ Asha: () => null, Ravi: { ratings: [{ rule_set: 'icf', rating: 'x' }] } });
  a.seats.update(room('aiming', ['Asha', 'Ravi']));
  await settle();
  assert.deepEqual([a.seats.label(0), a.seats.label(1)], ['', '']);
});

// Asha and Ravi read as a rated game starts (ratings `before`), then its end comes with the
// seats `atEnd` and the store holds `after`; the end's reads are under way.
async function endedGame(before, after, atEnd = ['Asha', 'Ravi']) {
  let ended = false;
  const a = new Answers({
    Asha: () => ({ ratings: [ended ? after[0] : before[0]] }),
    Ravi: () => ({ ratings: [ended ? after[1] : before[1]] }),
  });
  a.seats.update(room('aiming', ['Asha', 'Ravi']));
  await settle();
  ended = true;
  a.seats.update(room('game_over', atEnd));
  return a;
}

test('at the end each seat is read once; the card shows both changes', async () => {
  const a = await endedGame([icf(1600.2, 20), icf(1498.7, 21)], [icf(1609.6, 21), icf(1490.4, 22)]);
  a.seats.update(room('game_over', ['Asha', 'Ravi']));
  assert.equal(a.seats.gameOverLine(), 'Ratings: being updated...');
  await settle();
  assert.equal(a.paths.length, 4);
  assert.equal(a.seats.label(0), '1610');
  assert.equal(a.seats.gameOverLine(), 'Ratings: Asha 1610\u00a0(+10), Ravi 1490\u00a0(-9)');
  assert.equal(a.timers.length, 0); // the change is known: no second read
});

test('a rated end whose result is not stored yet is read once more, later', async () => {
  let stored = false;
  const a = new Answers({
    Asha: () => ({ ratings: stored ? [icf(1337.7, 1, '1338?')] : [] }),
    Ravi: () => ({ ratings: stored ? [icf(1662.3, 1, '1662?')] : [] }),
  });
  a.seats.update(room('aiming', ['Asha', 'Ravi']));
  await settle();
  a.seats.update(room('game_over', ['Asha', 'Ravi']));
  await settle();
  assert.deepEqual(a.timers.map((t) => t.ms), [RATING_REREAD_MS, RATING_REREAD_MS]);
  assert.equal(a.seats.gameOverLine(), 'Ratings: being updated...');
  stored = true;
  for (const t of a.timers.splice(0)) t.fn();
  await settle();
  assert.equal(a.paths.length, 6);
  assert.equal(a.seats.gameOverLine(), 'Ratings: Asha 1338?\u00a0(-162), Ravi 1662?\u00a0(+162)');
  a.seats.update(room('game_over', ['Asha', 'Ravi']));
  await settle();
  assert.equal(a.paths.length, 6); // bounded: three reads per seat and game at most
  assert.equal(a.timers.length, 0);
});

test('an unrated game is not read again at its end and its card has no ratings line', async () => {
  const a = new Answers({ Asha: { ratings: [icf(1600, 20)] }, Ravi: { ratings: [icf(1500, 20)] } });
  a.seats.update(room('aiming', ['Asha', 'Ravi'], { aimAssist: true }));
  a.seats.update(room('game_over', ['Asha', 'Ravi'], { aimAssist: true }));
  await settle();
  assert.equal(a.paths.length, 4);
  assert.equal(a.timers.length, 0);
  assert.equal(a.seats.gameOverLine(), '');
  assert.equal(a.seats.label(0), '1600');
});

test('a player who forfeits by leaving is still read and named at the end', async () => {
  const a = await endedGame([icf(1600, 20), icf(1500, 20)], [icf(1604, 21), icf(1496, 21)], ['Asha', empty]);
  await settle();
  assert.equal(a.seats.gameOverLine(), 'Ratings: Asha 1604\u00a0(+4), Ravi 1496\u00a0(-4)');
  assert.equal(a.seats.label(1), '1496');
});

test('a rematch is a new game: read again, no change until it ends', async () => {
  const a = new Answers({ Asha: { ratings: [icf(1600, 20)] }, Ravi: { ratings: [icf(1500, 20)] } });
  a.seats.update(room('aiming', ['Asha', 'Ravi'], { aimAssist: true }));
  a.seats.update(room('game_over', ['Asha', 'Ravi'], { aimAssist: true }));
  await settle();
  a.seats.update(room('aiming', ['Asha', 'Ravi'], { aimAssist: true }));
  await settle();
  assert.equal(a.paths.length, 6);
  assert.equal(a.seats.gameOverLine(), '');
});

test('doubles, the lobby and another room show nothing; a late answer of a left room is dropped', async () => {
  const answers = [];
  const a = new Answers({ Asha: () => new Promise((r) => { answers.push(r); }), Ravi: { ratings: [icf(1500, 20)] } });
  a.seats.update(room('aiming', ['Asha', 'Ravi', 'Chitra', 'Dev']));
  assert.equal(a.paths.length, 0);
  a.seats.update(room('aiming', ['Asha', 'Ravi']));
  a.seats.update(room('aiming', ['Ravi', 'Asha'], { code: 'GHJKLM' }));
  await settle();
  assert.equal(answers.length, 2);
  answers[0]({ ratings: [icf(1800, 20)] }); // the first room's read of Asha
  await settle();
  assert.equal(a.seats.label(1), '');
  assert.equal(a.seats.label(0), '1500');
  a.seats.update({ inRoom: false, seats: [] });
  assert.deepEqual([a.seats.label(0), a.seats.label(1), a.seats.gameOverLine()], ['', '', '']);
});

test('a server that keeps no players is not read and shows nothing', async () => {
  const a = new Answers({ Asha: { ratings: [icf(1600, 20)] } });
  a.kept = false;
  a.seats.update(room('aiming', ['Asha', 'Ravi']));
  a.seats.update(room('game_over', ['Asha', 'Ravi']));
  await settle();
  assert.deepEqual(a.paths, []);
  assert.deepEqual([a.seats.label(0), a.seats.gameOverLine(), a.timers.length], ['', '', 0]);
  a.seats.update(room('game_over', ['Asha', 'Ravi']));
  await settle();
  assert.equal(a.seats.debugState().reads, 0);
});

test('GET /players is asked once per page, again only after no answer', async () => {
  const asked = [];
  let answer = null;
  const kept = playersKept(async (path) => { asked.push(path); return answer; });
  assert.equal(await kept(), false); // no answer: not known to keep players
  answer = { kept: true };
  assert.deepEqual(await Promise.all([kept(), kept()]), [true, true]);
  answer = { kept: false };
  assert.equal(await kept(), true);
  assert.deepEqual(asked, ['/players', '/players']);
  assert.equal(await playersKept(async () => ({ kept: 'yes' }))(), false);
  assert.equal(await playersKept(async () => ({ error: { code: 'rate_limited' } }))(), false);
});

// ---- aim assist ----

test('the aim assist is off in a rated room (aim_assist false) and on where it is allowed', () => {
  const on = { aimAssist: true, you: 0, engineLoaded: true, predicting: false };
  assert.equal(aimAssistAllowed(on), true);
  assert.equal(aimAssistAllowed({ ...on, aimAssist: undefined }), true); // an older server
  assert.equal(aimAssistAllowed({ ...on, aimAssist: false }), false);
  assert.equal(aimAssistAllowed({ ...on, aimAssist: false, you: 1 }), false);
  assert.equal(aimAssistAllowed({ ...on, you: -1 }), false); // a spectator
  assert.equal(aimAssistAllowed({ ...on, engineLoaded: false }), false);
  assert.equal(aimAssistAllowed({ ...on, predicting: true }), false);
});
