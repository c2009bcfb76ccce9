// What the game-over panel says, in plain words (client/src/game_over_text.cpp, the same
// sentences): who won from the reader's side, why the game ended, the final score, and what the
// player can do next (a rematch, or back to the lobby).
//
// view: the model's view (match_model.js) with gameEnd {winner, why (game_end's reason: "score",
// "boards", "cleared", "forfeit", "left", "clock"; '' when the page came in after the end),
// scores, names (per seat when the game ended)}.

const doubles = (v) => v.seats.length === 4;
const teamOf = (v, seat) => (seat >= 0 && seat < v.seats.length ? (doubles(v) ? seat % 2 : seat) : -1);
const teamSeats = (v, team) => v.seats.map((_, i) => i).filter((i) => teamOf(v, i) === team);

function seatName(v, seat) {
  const s = v.seats[seat];
  return s && s.name ? s.name : `Seat ${seat + 1}`;
}

function nameAtEnd(v, seat) {
  const names = v.gameEnd?.names ?? [];
  return names[seat] ? names[seat] : seatName(v, seat);
}

function otherTeam(v, team) {
  if (team < 0 || (v.seats.length !== 2 && v.seats.length !== 4)) return -1;
  return 1 - team;
}

const ours = (v, team) => team >= 0 && team === teamOf(v, v.you);

// The team's players: "Ana", or "Ana & Cy" (the names they had when the game ended).
function name(v, team) {
  if (!doubles(v)) return nameAtEnd(v, team);
  const names = teamSeats(v, team).map((s) => nameAtEnd(v, s));
  return names.length > 0 ? names.join(' & ') : `Team ${team + 1}`;
}

// To start a sentence: "You", "You & Cy" (our partner named), or the team's players.
function subject(v, team) {
  if (!ours(v, team)) return name(v, team);
  const partner = teamSeats(v, team).find((s) => s !== v.you);
  return partner !== undefined ? `You & ${nameAtEnd(v, partner)}` : 'You';
}

const has = (v, team) => (ours(v, team) || doubles(v) ? 'have' : 'has');

function whoLeads(v, winner) {
  if (winner < 0) return 'the scores are level';
  let who = subject(v, winner);
  if (ours(v, winner)) who = `y${who.slice(1)}`; // mid-sentence: "you", "you & Cy"
  return `${who} ${has(v, winner)} more points`;
}

function clearedReason(v, winner) {
  switch (v.ruleSet) {
    case 'seed': return `A colour is off the board and ${whoLeads(v, winner)}.`;
    case 'freestyle': return `No coins are left on the board and ${whoLeads(v, winner)}.`;
    case 'discpool':
      if (winner < 0) return 'The coins are off the board.';
      if (ours(v, winner)) {
        return doubles(v) ? "All your team's coins are off the board." : 'All your coins are off the board.';
      }
      return `All of ${name(v, winner)}'s coins are off the board.`;
    default:
      return winner < 0 ? 'The board is cleared.' : `${subject(v, winner)} cleared the board.`;
  }
}

function lostReason(v, loser, reason) {
  if (doubles(v)) {
    const who = ours(v, loser) ? 'your team' : name(v, loser);
    if (reason === 'clock') return `A player of ${who} let the shot clock run out three times in a row.`;
    if (reason === 'forfeit') return `A player of ${who} lost the connection and did not come back in time.`;
    return `A player of ${who} left the game.`;
  }
  if (reason === 'clock') return `${subject(v, loser)} let the shot clock run out three times in a row.`;
  if (reason === 'forfeit') return `${subject(v, loser)} lost the connection and did not come back in time.`;
  return `${subject(v, loser)} left the game.`;
}

function reasonSentence(v, winner, why) {
  const loser = otherTeam(v, winner);
  if (why === 'score' && winner >= 0) return `${subject(v, winner)} reached ${v.options.target_points} points.`;
  if (why === 'boards') {
    const played = v.options.boards === 1 ? 'The board is played'
      : `All ${v.options.boards} boards are played`;
    return `${played} and ${whoLeads(v, winner)}.`;
  }
  if (why === 'cleared') return clearedReason(v, winner);
  if (loser >= 0 && ['clock', 'forfeit', 'left'].includes(why)) return lostReason(v, loser, why);
  return why ? `The game is over (${why}).` : 'The game is over.';
}

function title(v, winner) {
  if (winner < 0) return 'A draw';
  if (doubles(v)) return `${subject(v, winner)} win`;
  if (ours(v, winner)) return 'You won!';
  return v.you >= 0 ? 'You lost' : `${name(v, winner)} won`;
}

// Our team first (seat 0's for a spectator); a team's score is any of its seats' entry.
function scoreLine(v, scores) {
  const n = scores.length;
  const teams = doubles(v) ? 2 : n;
  const first = v.you >= 0 && v.you < n ? teamOf(v, v.you) : 0;
  const parts = [];
  for (let i = 0; i < teams; i += 1) {
    const team = (first + i) % teams;
    if (team < n) parts.push(`${name(v, team)} ${scores[team]}`);
  }
  return `Final score: ${parts.join(', ')}`;
}

// Whose seat is empty: a player left after the game (no rematch until someone takes the seat).
function emptySeat(v) {
  return v.seats.some((s, i) => i !== v.you && !s.occupied);
}

function rematchWait(v) {
  let otherHumans = 0;
  let other = -1;
  v.seats.forEach((s, seat) => {
    if (seat !== v.you && s.occupied && (!s.bot || !doubles(v))) {
      otherHumans += 1;
      other = seat;
    }
  });
  if (otherHumans === 1) return `Waiting for ${seatName(v, other)} to agree to a rematch`;
  return 'Waiting for the other players to agree to a rematch';
}

// {title, reason, score, canRematch, opponentLeft, waiting}.
export function gameOverText(v, rematchAsked) {
  const end = v.gameEnd ?? { winner: v.winner, why: '', scores: [], names: [] };
  const scores = end.scores.length > 0 ? end.scores : v.seats.map((s) => s.score);
  const seated = v.you >= 0;
  // A game that ended because a player left: that seat is on its way to empty (the room state
  // that frees it follows the game_end).
  const left = seated && (emptySeat(v) || end.why === 'left');
  let waiting = '';
  if (left) {
    waiting = doubles(v) ? 'A player left the room: no rematch' : 'Your opponent left the room: no rematch';
  } else if (seated && rematchAsked) {
    waiting = rematchWait(v);
  }
  return {
    title: title(v, end.winner),
    reason: reasonSentence(v, end.winner, end.why),
    score: scoreLine(v, scores),
    canRematch: seated && !rematchAsked && !left,
    opponentLeft: left,
    waiting,
  };
}
