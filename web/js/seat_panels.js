// What the seat panels show, from the match model's view (pure: the HUD writes it to the page).
//
// Doubles: one panel per seat, placed at the side of the turned board where that seat sits
// (our own at the bottom, our partner across at the top, the opponents left and right), with
// the name, whether it is us, our partner or an opponent (for a spectator: the team), the
// team's colour, the team's score and dues (partners share them), whose turn it is, and whether
// the player is away or a bot. The top bar then shows the two teams: ours first (for a
// spectator, team 0 first).

import { screenSide, turnsForSide } from './screen_mapping.js';

function ourSeat(view) {
  return view.you >= 0 && view.seats[view.you] ? view.seats[view.you] : null;
}

// Quarter turns of the view: our baseline at the bottom; a spectator sees seat 0's view.
export function viewTurns(view) {
  const me = ourSeat(view);
  return me ? turnsForSide(me.baseline) : 0;
}

// One panel per seat: {seat, at ('bottom'|'right'|'top'|'left' on screen), name, tag, team,
// colour, score, dues, bot, away, toPlay}.
export function seatPanels(view) {
  const me = ourSeat(view);
  const turns = viewTurns(view);
  return view.seats.map((s, i) => {
    let tag;
    if (me === null) tag = `team ${s.team + 1}`;
    else if (i === view.you) tag = 'you';
    else if (s.team === me.team) tag = 'partner';
    else tag = 'opponent';
    return {
      seat: i,
      at: screenSide(s.baseline, turns),
      name: s.occupied ? s.name : 'Free seat',
      tag,
      team: s.team,
      colour: s.colour,
      score: s.score,
      dues: s.dues,
      bot: s.occupied && s.bot,
      away: s.occupied && !s.connected,
      toPlay: view.phase === 'aiming' && view.toPlay === i,
    };
  });
}

// The teams, ours first (a spectator's: team 0 first): {team, seats, names, ours, colour, score,
// dues, toPlay, free}. A team's score and dues are any of its seats' (the server sends the
// team's value at each seat).
export function teamSummaries(view) {
  const me = ourSeat(view);
  const byTeam = new Map();
  view.seats.forEach((s, i) => {
    if (!byTeam.has(s.team)) byTeam.set(s.team, []);
    byTeam.get(s.team).push(i);
  });
  const teams = [...byTeam.entries()].map(([team, seats]) => {
    const first = view.seats[seats[0]];
    return {
      team,
      seats,
      // The players seated (a free seat is counted in `free`, not named).
      names: seats.filter((i) => view.seats[i].occupied).map((i) => view.seats[i].name).join(' & '),
      ours: me !== null && me.team === team,
      colour: first.colour,
      score: first.score,
      dues: first.dues,
      toPlay: view.phase === 'aiming' && seats.includes(view.toPlay),
      free: seats.filter((i) => !view.seats[i].occupied).length,
    };
  });
  teams.sort((a, b) => (a.ours === b.ours ? a.team - b.team : a.ours ? -1 : 1));
  return teams;
}

// Seats nobody has taken yet.
export function freeSeats(view) {
  return view.seats.filter((s) => !s.occupied).length;
}
