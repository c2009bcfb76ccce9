// Messages and error codes in plain words (client/src/plain_words.cpp).

export function countWords(count, one, many) {
  return `${count} ${count === 1 ? one : many}`;
}

// "2 white coins, 1 black coin and the queen".
export function pocketList(kinds) {
  const black = kinds.filter((k) => k === 'black').length;
  const white = kinds.filter((k) => k === 'white').length;
  const parts = [];
  if (white > 0) parts.push(countWords(white, 'white coin', 'white coins'));
  if (black > 0) parts.push(countWords(black, 'black coin', 'black coins'));
  if (kinds.includes('queen')) parts.push('the queen');
  if (kinds.includes('striker')) parts.push('the striker');
  if (parts.length === 0) return 'nothing';
  return parts.length === 1 ? parts[0]
    : `${parts.slice(0, -1).join(', ')} and ${parts[parts.length - 1]}`;
}

export function queenSentence(queen, seatName) {
  switch (queen.state) {
    case 'pending': return `${seatName} pocketed the queen: cover it with the next coin`;
    case 'covered': return `${seatName} covered the queen`;
    case 'on_board': return 'The queen is back on the centre';
    default: return 'The queen moved';
  }
}

// Why a game ended, from game_end's reason. In doubles (team) the winner is a team, named by its
// players ("Asha & Chitra").
export function gameEndSentence(winner, weWon, winnerName, reason, spectator = false, team = false) {
  let why = '';
  if (reason === 'forfeit') why = ' (the opponent did not come back in time)';
  else if (reason === 'left') why = ' (the opponent left)';
  else if (reason === 'clock') why = ' (the opponent ran out of time)';
  else if (reason === 'boards') why = ' (all boards played)';
  else if (reason === 'cleared') why = ' (no coin left)';
  else if (reason === 'score') why = ' (target score reached)';
  if (spectator && (reason === 'forfeit' || reason === 'left' || reason === 'clock')) {
    why = reason === 'clock' ? ' (the other player ran out of time)'
      : ' (the other player left)';
  }
  if (team && (reason === 'forfeit' || reason === 'left' || reason === 'clock')) {
    why = {
      forfeit: ' (a player of the other team did not come back in time)',
      left: ' (a player of the other team left)',
      clock: ' (the other team ran out of time)',
    }[reason];
  }
  if (winner < 0) return `The game is drawn${why}`;
  if (team) return `${weWon ? 'Your team wins the game' : `${winnerName} win the game`}${why}`;
  return `${weWon ? 'You win the game' : `${winnerName} wins the game`}${why}`;
}

const ERROR_WORDS = {
  room_not_found: 'There is no room with that code. Check the code and try again.',
  room_full: 'That room is full. You can join it as a spectator.',
  not_your_turn: 'Wait for your turn.',
  stale_turn: 'That shot was for an earlier turn and was not played.',
  in_motion: 'Wait until the pieces stop.',
  illegal_placement: 'The striker cannot go there: it overlaps a piece.',
  illegal_shot: 'That shot is not allowed.',
  spectator: 'Spectators cannot play.',
  version_mismatch: 'This page and the server speak different protocol versions. Reload the page.',
  bad_token: 'Your seat could not be resumed: the grace period is over.',
  server_full: 'The server is full. Try again in a moment.',
  too_many_connections: 'Too many connections from your address: close another tab or window.',
  too_many_rooms: 'The server has no room for another match. Try again later.',
  rate_limited: 'Too many messages: slow down.',
  shutting_down: 'The server is shutting down.',
  unsupported: 'This server does not offer that.',
  replaced: 'This seat was opened in another tab or window.',
};

export function errorSentence(error) {
  if (ERROR_WORDS[error.code]) {
    if (error.code === 'unsupported' && error.message) return error.message;
    return ERROR_WORDS[error.code];
  }
  return error.message ? error.message : `The server reported an error (${error.code}).`;
}

export function ruleSetName(ruleSet) {
  return {
    icf: 'ICF rules', seed: 'Classic (seed) rules', freestyle: 'Freestyle', discpool: 'Disc pool',
  }[ruleSet] ?? 'Unknown rules';
}

// A WebSocket close code in plain words (docs/protocol.md, "Close codes").
export function closeSentence(code, reason) {
  const words = {
    1000: 'The connection was closed',
    1001: 'The server is shutting down',
    1006: 'The connection was lost',
    1008: 'The server closed the connection (policy)',
    1009: 'The server closed the connection (message too large)',
    1011: 'The server hit an internal error',
    1013: 'The server is full',
    4001: 'The server speaks another protocol version',
    4002: 'This seat was opened in another tab or window',
    4003: 'The connection was too slow to keep up',
  }[code];
  return words ?? (reason ? `Connection closed: ${reason}` : `Connection closed (code ${code})`);
}
