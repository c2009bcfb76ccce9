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

// A foul, in the warning colour: "Foul by Asha: The striker went into a pocket." (the server's
// sentence for the foul).
export function foulSentence(name, message) {
  return `Foul by ${name}: ${message}`;
}

// What a stroke's fouls cost besides the turn and dues: the pieces back to the centre and the
// points lost, e.g. "Cost: 1 white coin back to the centre and 10 points"; '' when none.
export function foulCost(returned, points) {
  const parts = [];
  if (returned.length > 0) parts.push(`${pocketList(returned)} back to the centre`);
  if (points < 0) parts.push(countWords(-points, 'point', 'points'));
  return parts.length === 0 ? '' : `Cost: ${parts.join(' and ')}`;
}

// A stroke's points where each stroke scores (freestyle): " (+20)", " (-10)"; '' for 0.
export function strokePoints(points) {
  if (points === 0) return '';
  return ` (${points > 0 ? '+' : ''}${points})`;
}

// A team's unpaid dues: "Asha owes 1 due: the next coin Asha pockets goes back to the centre".
export function duesSentence(subject, plural, owed) {
  const coin = owed === 1 ? 'the next coin ' : 'the next coins ';
  const goes = owed === 1 ? ' goes' : ' go';
  return `${subject}${plural ? ' owe ' : ' owes '}${countWords(owed, 'due', 'dues')}: ${coin}`
    + `${plural ? 'they pocket' : `${subject} pockets`}${goes} back to the centre`;
}

// "Asha left the match: Ravi wins by forfeit" (reason "left"), "Asha did not come back in time:
// you win by forfeit" (reason "forfeit"); plural: the winners are a pair, or "you".
export function forfeitSentence(leaver, reason, winner, plural) {
  const what = reason === 'left' ? ' left the match: ' : ' did not come back in time: ';
  return `${leaver}${what}${winner}${plural ? ' win' : ' wins'} by forfeit`;
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

// The game's target for the HUD: "to 25, scored at board end" (icf, seed: a board's
// points come when it ends), "first to 40 points" (freestyle), "to 25 points" (discpool).
export function targetWords(ruleSet, targetPoints) {
  const points = countWords(targetPoints, 'point', 'points');
  if (ruleSet === 'icf' || ruleSet === 'seed') return `to ${targetPoints}, scored at board end`;
  if (ruleSet === 'freestyle') return `first to ${points}`;
  return `to ${points}`;
}

// What a seat has left to pocket (client/src/coins_left.cpp and coins_left_text): "7 white +
// queen left", "12 coins left" (freestyle: every coin), "no black left"; '' while the seat has
// no colour. left: {white, black, queen} on the board.
export function coinsLeftText(left, ruleSet, colour) {
  const queen = ruleSet !== 'discpool' && left.queen > 0;
  let coins;
  let what;
  if (ruleSet === 'freestyle') {
    coins = left.white + left.black;
    what = coins === 1 ? 'coin' : 'coins';
  } else if (colour === 'white' || colour === 'black') {
    coins = left[colour];
    what = colour;
  } else {
    return '';
  }
  if (coins === 0) return queen ? 'only the queen left' : `no ${what} left`;
  return `${coins} ${what}${queen ? ' + queen' : ''} left`;
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
    4004: 'The match moved to another server',
  }[code];
  return words ?? (reason ? `Connection closed: ${reason}` : `Connection closed (code ${code})`);
}
