// The session's hello / resume / back-off decisions without I/O or clocks: the port of
// net/session_core/ (net::SessionCore, which carrom-client and carrom-bot drive). Both replay
// tests/golden/session/*.json (tests/web/session_test.mjs here, tests/net there); a change to
// one that the other does not follow fails one of them. The rules are in session_core.hpp.
//
// Events in (with the time in seconds where it matters), actions out: {kind, waitS, reason}
// with kind connect, send_hello, send_resume, send_room_request, send_leave, wait, resumed,
// seat_lost, refused or give_up (reason no_retry, time_up, version_mismatch, replaced).
// Phases: connecting, greeting, lobby, joining, in_room, reconnecting, failed.

export const BACKOFF_DEFAULTS = Object.freeze({ firstS: 0.5, capS: 5.0, giveUpAfterS: 130.0 });

// Errors that answer a room request with no: the session goes back to the lobby.
const REFUSALS = ['room_not_found', 'room_full', 'unsupported', 'too_many_rooms', 'bad_field',
  'already_in_room'];
const CLOSE_VERSION_MISMATCH = 4001;
const CLOSE_REPLACED = 4002;

const act = (kind) => ({ kind, waitS: 0, reason: 'no_retry' });

export class SessionCore {
  // policy: 'always', 'seat_only' or 'never' (when a lost link is tried again).
  constructor(backoff = BACKOFF_DEFAULTS, policy = 'always') {
    this.backoff = backoff;
    this.policy = policy;
    this.phase = 'connecting';
    this.token = '';
    this.resuming = false; // hello carries the token; cleared by the room's state
    this.wantsRoom = false; // a room request not yet answered by a room or a refusal
    this.everWelcomed = false; // since start()
    this.linkUp = false; // between connect and linkClosed() or give_up
    this.waiting = false; // for retryAtS
    this.tries = 0; // of the current loss (0: none)
    this.lostSinceS = 0;
    this.retryAtS = 0;
  }

  givesUpAtS() {
    return this.lostSinceS + this.backoff.giveUpAfterS;
  }

  // A room's messages in the lobby come from a room we left (or lost): the caller drops them.
  dropsRoomMessages() {
    return this.phase === 'lobby';
  }

  // With a token, hello asks for that token's seat back (a reload of the page).
  start(resumeToken) {
    if (resumeToken) this.token = resumeToken;
    this.resuming = Boolean(resumeToken);
    this.everWelcomed = false;
    this.waiting = false;
    this.tries = 0;
    this.phase = 'connecting';
    this.linkUp = true;
    return [act('connect')];
  }

  request() {
    this.wantsRoom = true;
    if (this.phase !== 'lobby') return []; // sent once welcomed
    this.phase = 'joining';
    return [act('send_room_request')];
  }

  leave() {
    this.wantsRoom = false;
    this.resuming = false; // a reconnect says hello as a new player, without the old seat
    if (this.phase !== 'in_room' && this.phase !== 'joining') return [];
    this.phase = 'lobby';
    return [act('send_leave')];
  }

  linkOpened() {
    if (!this.linkUp || (this.phase !== 'connecting' && this.phase !== 'reconnecting')) return [];
    this.phase = 'greeting';
    return [act(this.resuming ? 'send_resume' : 'send_hello')];
  }

  // closeCode: the server's close frame's code, 0 without one; jitter: a uniform draw in [0, 1].
  linkClosed(nowS, closeCode, jitter) {
    if (!this.linkUp || this.phase === 'failed') return [];
    this.linkUp = false;
    if (closeCode === CLOSE_VERSION_MISMATCH) return this.giveUp('version_mismatch');
    if (closeCode === CLOSE_REPLACED) return this.giveUp('replaced');
    const holdsSeat = this.phase === 'in_room' || this.resuming;
    if (this.policy === 'never' || (this.policy === 'seat_only' && !holdsSeat)) return this.giveUp('no_retry');
    if (this.tries === 0) this.lostSinceS = nowS;
    if (nowS - this.lostSinceS >= this.backoff.giveUpAfterS) return this.giveUp('time_up');
    this.tries += 1;
    this.resuming = holdsSeat && this.token !== '';
    let nominal = this.backoff.firstS;
    for (let n = 1; n < this.tries && nominal < this.backoff.capS; n += 1) nominal *= 2.0;
    nominal = Math.min(nominal, this.backoff.capS);
    const drawn = nominal * (0.5 + 0.5 * Math.min(Math.max(jitter, 0.0), 1.0));
    const waitS = Math.min(drawn, this.givesUpAtS() - nowS);
    this.retryAtS = nowS + waitS;
    this.waiting = true;
    this.phase = this.everWelcomed ? 'reconnecting' : 'connecting';
    return [{ kind: 'wait', waitS, reason: 'no_retry' }];
  }

  tick(nowS) {
    if (!this.waiting || nowS < this.retryAtS) return [];
    this.waiting = false;
    this.linkUp = true;
    return [act('connect')];
  }

  welcome(token) {
    if (this.phase === 'failed') return [];
    this.everWelcomed = true;
    if (this.resuming) {
      if (token !== this.token) { // a new player: the seat is not ours any more
        this.token = token;
        return this.giveUpSeat();
      }
      this.phase = 'joining'; // the server sends the room back
      return [];
    }
    this.token = token;
    this.tries = 0;
    this.phase = 'lobby';
    if (!this.wantsRoom) return [];
    this.phase = 'joining';
    return [act('send_room_request')];
  }

  roomState() {
    if (this.phase !== 'joining' && this.phase !== 'in_room') return []; // not ours
    this.phase = 'in_room';
    this.wantsRoom = false;
    this.tries = 0;
    if (!this.resuming) return [];
    this.resuming = false;
    return [act('resumed')];
  }

  error(code) {
    if (this.phase === 'failed') return [];
    if (code === 'version_mismatch') return this.giveUp('version_mismatch');
    if (code === 'replaced') return this.giveUp('replaced');
    if (code === 'bad_token' && this.resuming) {
      this.token = '';
      return this.giveUpSeat();
    }
    if (this.phase === 'joining' && !this.resuming && REFUSALS.includes(code)) {
      this.wantsRoom = false;
      this.phase = 'lobby';
      return [act('refused')];
    }
    return [];
  }

  giveUpSeat() {
    this.resuming = false;
    this.wantsRoom = false;
    this.tries = 0;
    this.phase = 'lobby';
    return [act('seat_lost')];
  }

  giveUp(reason) {
    this.phase = 'failed';
    this.linkUp = false;
    this.waiting = false;
    this.resuming = false;
    return [{ kind: 'give_up', waitS: 0, reason }];
  }
}
