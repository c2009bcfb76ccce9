// The session's hello / resume / back-off decisions without I/O or clocks: the port of
// net/session_core/ (net::SessionCore, which carrom-client and carrom-bot drive). Both replay
// tests/golden/session/*.json (tests/web/session_test.mjs here, tests/net there); a change to
// one that the other does not follow fails one of them. The rules are in session_core.hpp.
//
// Events in (with the time in seconds where it matters), actions out: {kind, waitS, reason}
// with kind connect (to this.url), send_hello, send_resume, send_room_request, send_join
// (join_room{this.joinCode, this.joinAs}: the room a redirect named), send_leave, wait, resumed,
// seat_lost, refused or give_up (reason no_retry, time_up, version_mismatch, replaced,
// redirect_refused).
// Phases: connecting, greeting, lobby, joining, in_room, reconnecting, failed.

export const BACKOFF_DEFAULTS = Object.freeze({ firstS: 0.5, capS: 5.0, giveUpAfterS: 130.0 });

// Errors that answer a room request with no: the session goes back to the lobby.
const REFUSALS = ['room_not_found', 'room_full', 'unsupported', 'too_many_rooms', 'bad_field',
  'already_in_room'];
const CLOSE_VERSION_MISMATCH = 4001;
const CLOSE_REPLACED = 4002;
const CLOSE_REDIRECTED = 4005;
// Redirects in a row a session follows; the next one is refused.
export const MAX_REDIRECTS = 3;

// A URL from the network in a sentence: at most 80 characters, control characters as '?'.
function shownUrl(url) {
  const control = (c) => c.charCodeAt(0) < 0x20 || c.charCodeAt(0) === 0x7f;
  const shown = [...url.slice(0, 80)].map((c) => (control(c) ? '?' : c)).join('');
  return url.length > 80 ? `${shown}...` : shown;
}

// The host of a ws:// or wss:// URL, lowercased ("[::1]" keeps its brackets); '' when the URL is
// not ws:// or wss://, has user information, a space or a control character, or no host
// (net::ws_url_host).
export function wsUrlHost(url) {
  const tls = url.startsWith('wss://');
  if (!tls && !url.startsWith('ws://')) return '';
  if ([...url].some((c) => c.charCodeAt(0) <= 0x20 || c.charCodeAt(0) === 0x7f)) return '';
  const rest = url.slice(tls ? 6 : 5);
  const end = rest.search(/[/?#]/);
  const authority = end < 0 ? rest : rest.slice(0, end);
  if (authority.includes('@')) return '';
  let host;
  if (authority.startsWith('[')) {
    const close = authority.indexOf(']');
    host = close < 0 ? '' : authority.slice(0, close + 1);
  } else {
    const colon = authority.indexOf(':');
    host = colon < 0 ? authority : authority.slice(0, colon);
  }
  host = host.replace(/[A-Z]/g, (c) => c.toLowerCase());
  return host === '[]' ? '' : host;
}

// Whether a redirect from the link to fromUrl, for the player's address, to toUrl is followed:
// the same host as the address, ws:// or wss://, never from wss:// to ws:// (net::redirect_allowed).
export function redirectAllowed(fromUrl, address, toUrl) {
  const host = wsUrlHost(toUrl);
  if (host === '' || host !== wsUrlHost(address)) return false;
  return !fromUrl.startsWith('wss://') || toUrl.startsWith('wss://');
}

const act = (kind) => ({ kind, waitS: 0, reason: 'no_retry' });

export class SessionCore {
  // policy: 'always', 'seat_only' or 'never' (when a lost link is tried again).
  // address: the server address the player gave (the page's own, in the web client).
  constructor(backoff = BACKOFF_DEFAULTS, policy = 'always', address = '') {
    this.backoff = backoff;
    this.policy = policy;
    this.address = address;
    this.url = address; // the current (or next) link's URL: the address or a redirect's
    this.redirects = 0; // followed since the session was last in a room or the lobby
    this.redirectCloseDue = false; // the redirected link's close (4005) is still to come
    this.retryNextLoss = false; // match_moving: the next loss is tried again
    this.joinCode = ''; // a redirect's room, joined when no seat comes back
    this.joinAs = 'player';
    this.refusedRedirect = ''; // after give_up (redirect_refused): the sentence saying why
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
    this.backInRoomOrLobby();
    this.url = this.address;
    this.redirectCloseDue = false;
    this.retryNextLoss = false;
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
    this.backInRoomOrLobby();
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
    if (closeCode === CLOSE_REDIRECTED && this.redirectCloseDue) {
      this.redirectCloseDue = false; // the link the redirect left; the new one is up
      return [];
    }
    this.linkUp = false;
    this.redirectCloseDue = false;
    this.url = this.address;
    this.redirects = 0;
    const retryAnyway = this.retryNextLoss;
    this.retryNextLoss = false;
    if (closeCode === CLOSE_VERSION_MISMATCH) return this.giveUp('version_mismatch');
    if (closeCode === CLOSE_REPLACED) return this.giveUp('replaced');
    const holdsSeat = this.phase === 'in_room' || this.resuming;
    if (this.policy === 'never' || (this.policy === 'seat_only' && !holdsSeat && !retryAnyway)) {
      return this.giveUp('no_retry');
    }
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
    this.redirectCloseDue = false;
    if (this.resuming) {
      if (token !== this.token) { // a new player: the seat is not ours any more
        this.token = token;
        if (this.joinCode !== '') { // a redirect named the room: join it instead
          this.resuming = false;
          this.phase = 'joining';
          return [act('send_join')];
        }
        return this.giveUpSeat();
      }
      this.phase = 'joining'; // the server sends the room back
      return [];
    }
    this.token = token;
    this.tries = 0;
    this.phase = 'lobby';
    if (!this.wantsRoom) {
      this.backInRoomOrLobby();
      return [];
    }
    this.phase = 'joining';
    return [act(this.joinCode === '' ? 'send_room_request' : 'send_join')];
  }

  roomState() {
    if (this.phase !== 'joining' && this.phase !== 'in_room') return []; // not ours
    this.phase = 'in_room';
    this.wantsRoom = false;
    this.tries = 0;
    this.backInRoomOrLobby();
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
      if (this.joinCode !== '') { // a redirect named the room: the welcome that follows joins it
        this.resuming = false;
        return [];
      }
      return this.giveUpSeat();
    }
    if (code === 'match_moving') {
      this.retryNextLoss = true; // the close 1013 that follows is tried again
      return [];
    }
    if (this.phase === 'joining' && !this.resuming && REFUSALS.includes(code)) {
      this.wantsRoom = false;
      this.backInRoomOrLobby();
      this.phase = 'lobby';
      return [act('refused')];
    }
    return [];
  }

  // A `redirect` {url, reason, code?, as?} on the current link: connect (to its url) or give_up
  // (redirect_refused).
  redirect(message) {
    const greeted = ['greeting', 'lobby', 'joining', 'in_room'].includes(this.phase);
    if (!this.linkUp || !greeted) return [];
    if (!redirectAllowed(this.url, this.address, message.url)) {
      this.refusedRedirect = `redirect refused: ${shownUrl(message.url)} is not an address of this cluster `
        + `(${shownUrl(this.address)}).`;
      return this.giveUp('redirect_refused');
    }
    if (this.redirects >= MAX_REDIRECTS) {
      this.refusedRedirect = `redirect refused: more than ${MAX_REDIRECTS} redirects in a row, `
        + `the last to ${shownUrl(message.url)}.`;
      return this.giveUp('redirect_refused');
    }
    this.redirects += 1;
    // A spectator holds no seat: it joins the named room again, without its token.
    const watching = Boolean(message.code) && message.as === 'spectator';
    this.resuming = (this.phase === 'in_room' || this.resuming) && this.token !== '' && !watching;
    if (message.code) {
      this.joinCode = message.code;
      this.joinAs = message.as === 'spectator' ? 'spectator' : 'player';
      this.wantsRoom = true;
    }
    this.url = message.url;
    this.redirectCloseDue = true;
    this.phase = this.everWelcomed ? 'reconnecting' : 'connecting';
    return [act('connect')];
  }

  backInRoomOrLobby() { // the redirects in a row start again
    this.redirects = 0;
    this.joinCode = '';
    this.joinAs = 'player';
  }

  giveUpSeat() {
    this.resuming = false;
    this.wantsRoom = false;
    this.backInRoomOrLobby();
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
