// Plays turns between pages (and waits for other players, such as a carrom-bot) until the game
// ends: whoever's turn it is on screen aims with the test shot chooser. The first shot of a game
// is a break towards the centre.

import { check, sleep } from './harness.mjs';
import { chooseShot } from './shot_chooser.mjs';

// A full-power shot from the middle of a baseline straight at the centre. side: 'bottom',
// 'right', 'top', 'left', or (singles callers) the baseline's board y.
export function breakShot(side) {
  const s = typeof side === 'number' ? (side > 300 ? 'bottom' : 'top') : side;
  const angle = { bottom: -Math.PI / 2, right: Math.PI, top: Math.PI / 2, left: 0 }[s];
  return { x: 300, angle, power: 25 };
}

// players: pages with seats. onShot(player, shot, state) runs after each shot is sent.
// Returns the number of shots the pages made.
export async function playUntilOver(players, { maxShots = 60, timeoutMs = 120000, onShot } = {}) {
  const deadline = Date.now() + timeoutMs;
  let shots = 0;
  for (;;) {
    check(Date.now() < deadline, `the game did not end within ${timeoutMs} ms (${shots} shots by the pages)`);
    let mover = null;
    let over = false;
    for (const p of players) {
      const s = await p.state();
      if (s.phase === 'game_over') over = true;
      if (s.myTurn && !s.animating && s.aim.phase === 'idle') mover = { p, s };
    }
    if (over) return shots;
    if (!mover) {
      await sleep(50);
      continue;
    }
    const { p, s } = mover;
    check(shots < maxShots, `no winner after ${maxShots} shots by the pages`);
    const shot = s.shots === 0 ? breakShot(s.aim.side) : chooseShot(s.board, s.aim.side, shots);
    await p.shoot(shot);
    shots += 1;
    if (onShot) await onShot(p, shot, s);
    // Wait until this shot's result arrived before looking for the next mover.
    await p.waitFor('the shot result', (st) => st.phase === 'game_over' || st.turn !== st.shotSentTurn, 30000);
  }
}
