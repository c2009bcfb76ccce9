// Quick reactions (the "emote" message, docs/protocol.md): the fixed set with the words the page
// shows, and which seat's emote is on show (pure: emote_view.js puts it on the page). A muted
// seat's emotes are not shown; muting every seat mutes the ones that join later too. Times are
// local seconds (performance.now() / 1000).

// In the protocol's order; `id` is the wire name.
export const EMOTES = Object.freeze([
  { id: 'nice_shot', text: 'Nice shot!' },
  { id: 'good_game', text: 'Good game!' },
  { id: 'well_played', text: 'Well played!' },
  { id: 'thanks', text: 'Thanks!' },
  { id: 'good_luck', text: 'Good luck!' },
  { id: 'oops', text: 'Oops!' },
  { id: 'wow', text: 'Wow!' },
  { id: 'sorry', text: 'Sorry!' },
]);
export const EMOTE_IDS = Object.freeze(EMOTES.map((e) => e.id));
export const EMOTE_SHOW_S = 4; // an emote stays beside its seat this long

export function emoteText(id) {
  return EMOTES.find((e) => e.id === id)?.text ?? '';
}

export class EmoteBoard {
  constructor(showS = EMOTE_SHOW_S) {
    this.showS = showS;
    this.shown = new Map(); // seat -> {id, untilS}
    this.mutedSeats = new Set();
    this.allMuted = false;
    this.received = 0; // emotes received, shown or not
  }

  // An emote from `seat` arrived at nowS; false when the seat is muted (nothing is shown).
  receive(seat, id, nowS) {
    this.received += 1;
    if (this.isMuted(seat)) return false;
    this.shown.set(seat, { id, untilS: nowS + this.showS });
    return true;
  }

  isMuted(seat) {
    return this.allMuted || this.mutedSeats.has(seat);
  }

  // Mutes or unmutes one seat; muting hides what it shows now.
  setMuted(seat, muted) {
    if (muted) {
      this.mutedSeats.add(seat);
      this.shown.delete(seat);
    } else {
      this.mutedSeats.delete(seat);
    }
  }

  setAllMuted(muted) {
    this.allMuted = muted;
    if (muted) this.shown.clear();
  }

  // The emotes on show at nowS: [{seat, id, text}] in seat order.
  visible(nowS) {
    const out = [];
    for (const [seat, s] of this.shown) {
      if (nowS < s.untilS) out.push({ seat, id: s.id, text: emoteText(s.id) });
    }
    return out.sort((a, b) => a.seat - b.seat);
  }

  // A new room: nothing on show; the mutes stay (they are the player's choice).
  clear() {
    this.shown.clear();
  }
}
