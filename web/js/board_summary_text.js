// What the card between two boards says (client/src/board_summary_text.cpp, the same words),
// from the reader's side: who won the board, its points and the score, and the colour the
// player has on the next board. view: the model's view with boardSummary {board, winner, points}.

function ourTeam(v, team) {
  return v.you >= 0 && team >= 0 && v.seats[v.you] && v.seats[v.you].team === team;
}

function seatName(v, seat) {
  const s = v.seats[seat];
  return s && s.name ? s.name : `Seat ${seat + 1}`;
}

// "you" for our team (a pair: "your team"), else the team's players ("Ravi", "Ravi & Dev").
function who(v, team) {
  const doubles = v.seats.length === 4;
  if (ourTeam(v, team)) return doubles ? 'your team' : 'you';
  if (!doubles) return seatName(v, team);
  const names = [];
  v.seats.forEach((s, i) => { if (s.team === team) names.push(seatName(v, i)); });
  return names.length > 0 ? names.join(' & ') : `Team ${team + 1}`;
}

const plural = (n, one, many) => `${n} ${n === 1 ? one : many}`;

// {title, points, colours}.
export function boardSummaryText(v) {
  const summary = v.boardSummary ?? { board: 1, winner: -1, points: 0 };
  let title;
  if (summary.winner < 0) {
    title = `Board ${summary.board}: no winner`;
  } else {
    const winner = who(v, summary.winner);
    title = `${winner[0].toUpperCase()}${winner.slice(1)} won board ${summary.board}`;
  }
  const teams = v.seats.length === 4 ? 2 : v.seats.length;
  const first = v.you >= 0 && v.seats[v.you] ? v.seats[v.you].team : 0;
  const score = [];
  for (let i = 0; i < teams; i += 1) {
    const team = (first + i) % teams;
    score.push(`${who(v, team)} ${v.seats[team].score}`);
  }
  const points = `${summary.points > 0 ? `+${plural(summary.points, 'point', 'points')}. ` : ''}`
    + `Score: ${score.join(', ')}`;
  let colours = '';
  const me = v.you >= 0 ? v.seats[v.you] : null;
  if (me && me.colour !== 'none') {
    colours = `Board ${v.boardNumber}: ${v.seats.length === 4 ? 'your team plays' : 'you play'} ${me.colour}`;
  }
  return { title, points, colours };
}
