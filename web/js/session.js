// The connection's life (client/src/client_session.cpp): open a WebSocket, say hello, ask for a
// room (create, join, spectate or quick match), ping for the round trip and the server clock,
// and when the link drops open a new one and resume the seat with the token. When to connect,
// say hello or resume, ask, wait and give up is SessionCore's decision (session_core.js, the
// port of net::SessionCore, checked against the same golden cases): back-off 0.5 s doubling to
// 5 s, each delay drawn from [d/2, d], giving up after 130 s (the server's default idle timeout,
// after which it notices a silent link, plus its grace, plus a margin); close 4001 and 4002 are
// final. Every hello says follows_redirects: a cluster's `redirect` is followed as SessionCore
// decides (to the host of the page's own address only; docs/protocol.md, "Redirects"), and a
// refused one ends the session with its sentence. This class carries the decisions out on a
// Connection, with timers, and words them. A
// link on which nothing (not even a pong to the pings every 2 s) arrived for 10 s is taken for
// lost: a browser's WebSocket may wait minutes before it notices a dead path by itself. The
// token and whether we hold a seat are kept in sessionStorage, so a reload of the page resumes
// the seat too.
//
// Phases: idle (before start), then SessionCore's: connecting, greeting, lobby, joining, in_room,
// reconnecting, failed.

import * as proto from './protocol.js';
import { SessionCore } from './session_core.js';

export const SESSION_DEFAULTS = Object.freeze({
  pingInterval: 2.0,
  firstRetry: 0.5,
  maxRetry: 5.0,
  giveUpAfter: 130.0,
  silenceTimeout: 10.0,
});

// Messages that belong to a room.
const ROOM_TRAFFIC = { room_state: true, snapshot: true, event: true, shot_result: true };

const now = () => performance.now() / 1000;

function seconds(s) {
  return `${s < 10 ? s.toFixed(1) : s.toFixed(0)} s`;
}

export class Session {
  // url: the WebSocket URL (the address the player gave: the page's own). storage: a Storage (sessionStorage) or null. hooks:
  // onMessage(message, localS) for every message of the match, onChange() when phase or status
  // change, onRefused(error, request) when a room request was refused.
  constructor(url, storage, hooks, config = SESSION_DEFAULTS, ConnectionClass) {
    this.url = url;
    this.storage = storage;
    this.hooks = hooks;
    this.config = config;
    this.ConnectionClass = ConnectionClass;
    this.core = new SessionCore({ firstS: config.firstRetry, capS: config.maxRetry, giveUpAfterS: config.giveUpAfter },
      'always', url);
    this.core.token = storage?.getItem('carrom.token') ?? '';
    this.started = false;
    this.status = '';
    this.name = '';
    this.identity = null; // the player's key sent in hello (identity.js); null: a guest
    this.link = null;
    this.request = null; // the room request, until a room or a refusal answers it
    this.lastRequest = null;
    this.lostReason = ''; // why the last link ended, a sentence
    this.retryTimer = null;
    this.pingTimer = null;
    this.nextNonce = 1;
    this.pings = new Map();
    this.rttMs = null;
    this.pongs = []; // {serverMs, sentS, receivedS}
  }

  get phase() {
    return this.started ? this.core.phase : 'idle';
  }

  get token() {
    return this.core.token;
  }

  // Whether this tab held a seat (or watched) before a reload.
  heldRoom() {
    return this.storage?.getItem('carrom.room') ?? '';
  }

  setHeldRoom(code) {
    if (!this.storage) return;
    if (code) this.storage.setItem('carrom.room', code);
    else this.storage.removeItem('carrom.room');
  }

  // Seconds left until the tries to take the seat back stop (null: no seat being taken back), at
  // local time nowS.
  seatHeldForS(nowS) {
    if (this.core.tries === 0 || ['idle', 'lobby', 'joining', 'in_room', 'failed'].includes(this.phase)) return null;
    return Math.max(this.core.givesUpAtS() - nowS, 0);
  }

  setStatus(status) {
    this.status = status;
    this.hooks.onChange?.();
  }

  // Connects as `name`. With resume true and a stored token, asks for the old seat back.
  start(name, resume = false) {
    this.stopLink();
    this.name = name;
    this.started = true;
    this.apply(this.core.start(resume && proto.isResumeToken(this.core.token) ? this.core.token : ''));
  }

  // Carries out SessionCore's actions; `error`: the error message they answer, if any.
  apply(actions, error = null) {
    for (const a of actions) {
      switch (a.kind) {
        case 'connect':
          this.openLink();
          break;
        case 'send_hello':
        case 'send_resume':
          this.link.send(proto.hello(this.name, a.kind === 'send_resume' ? this.core.token : undefined,
            this.identity ?? undefined, true));
          this.setStatus('Saying hello...');
          clearInterval(this.pingTimer);
          this.pingTimer = setInterval(() => this.ping(), this.config.pingInterval * 1000);
          break;
        case 'send_room_request':
          this.sendRequest();
          break;
        case 'send_join':
          this.link.send(proto.joinRoom(this.core.joinCode, this.core.joinAs === 'spectator'));
          this.setStatus('Joining...');
          break;
        case 'send_leave':
          this.link?.send(proto.leave());
          break;
        case 'wait':
          this.setStatus(`${this.lostReason} Retrying in ${seconds(a.waitS)} (attempt ${this.core.tries})`);
          this.scheduleRetry();
          break;
        case 'resumed':
          break;
        case 'seat_lost':
          this.request = null;
          this.setHeldRoom('');
          this.setStatus('Connected (your old seat is gone)');
          break;
        case 'refused':
          this.request = null;
          this.setStatus('Connected');
          this.hooks.onRefused?.(error, this.lastRequest);
          break;
        case 'give_up':
          this.stopLink();
          if (a.reason === 'redirect_refused') {
            this.lostReason = this.core.refusedRedirect;
            this.setStatus(this.core.refusedRedirect);
          } else if (a.reason === 'time_up') {
            this.setStatus(`${this.lostReason} Gave up after ${seconds(now() - this.core.lostSinceS)}.`);
          } else if (error?.code === 'version_mismatch') {
            this.setStatus('The server speaks another protocol version');
          } else if (error?.code === 'replaced') {
            this.setStatus('This seat was opened in another tab or window.');
          } else {
            this.setStatus(this.lostReason);
          }
          break;
        default:
          break;
      }
    }
  }

  openLink() {
    clearTimeout(this.retryTimer);
    this.retryTimer = null;
    this.link?.close(); // a redirect's: the server closes it (4005) once we go; its end is not ours
    const link = new this.ConnectionClass(this.core.url, {
      onOpen: () => this.onOpen(link),
      onMessage: (m, localS) => this.onMessage(link, m, localS),
      onClose: (sentence, code) => this.onLinkLost(link, sentence, code),
    });
    this.link = link;
    if (this.core.redirects > 0 && this.core.tries === 0) {
      this.setStatus('Moving to another server of the cluster...');
    } else if (this.core.phase === 'reconnecting') {
      this.setStatus(`Reconnecting (attempt ${this.core.tries})...`);
    } else {
      this.setStatus('Connecting...');
    }
  }

  // The next try once SessionCore's wait is over.
  scheduleRetry() {
    clearTimeout(this.retryTimer);
    const left = Math.max(this.core.retryAtS - now(), 0);
    this.retryTimer = setTimeout(() => {
      this.retryTimer = null;
      const actions = this.core.tick(now());
      if (actions.length > 0) this.apply(actions);
      else if (this.core.waiting) this.scheduleRetry(); // a timer that fired early
    }, left * 1000);
  }

  stopLink() {
    clearTimeout(this.retryTimer);
    clearInterval(this.pingTimer);
    this.retryTimer = null;
    this.pingTimer = null;
    if (this.link) this.link.close();
    this.link = null;
  }

  onOpen(link) {
    if (link !== this.link) return;
    this.lastHeard = now();
    this.apply(this.core.linkOpened());
  }

  ping() {
    if (!this.link || !['greeting', 'lobby', 'joining', 'in_room'].includes(this.phase)) return;
    const silent = now() - this.lastHeard;
    if (silent >= this.config.silenceTimeout) {
      const link = this.link;
      this.onLinkLost(link, `Nothing arrived for ${seconds(silent)}: the link is silent, taken for lost`, 0);
      link.close();
      return;
    }
    if (this.phase === 'greeting') return;
    const nonce = this.nextNonce++;
    this.pings.set(nonce, now());
    while (this.pings.size > 16) this.pings.delete(this.pings.keys().next().value);
    this.link.send(proto.ping(nonce));
  }

  // Ask for a room: {kind: create|join|spectate|quick, ruleSet, options, bot, seats, code}. Sent as
  // soon as the server has welcomed us (or at once if it has).
  ask(request) {
    this.request = request;
    this.apply(this.core.request());
  }

  sendRequest() {
    const r = this.request;
    if (!r || !this.link) return;
    let m;
    if (r.kind === 'create') m = proto.createRoom(r.ruleSet, r.options ?? {}, r.bot ?? null, r.seats ?? 2);
    else if (r.kind === 'join') m = proto.joinRoom(r.code, false);
    else if (r.kind === 'spectate') m = proto.joinRoom(r.code, true);
    else m = proto.quickMatch(r.ruleSet, r.seats ?? 2);
    this.link.send(m);
    this.lastRequest = r;
    let status = 'Joining...';
    if (r.kind === 'quick') status = r.seats === 4 ? 'Waiting for three players...' : 'Waiting for an opponent...';
    this.setStatus(status);
  }

  // Game input (aim, shoot, rematch): sent only while in a room.
  sendGame(message) {
    if (this.phase !== 'in_room' || !this.link) return false;
    return this.link.send(message);
  }

  // Leave the room (or the quick-match queue) and go back to the lobby.
  leaveRoom() {
    this.apply(this.core.leave());
    this.setHeldRoom('');
    this.request = null;
    if (this.link && this.phase === 'lobby') this.setStatus('Connected');
  }

  onMessage(link, m, localS) {
    if (link !== this.link) return;
    this.lastHeard = now();
    // In the lobby no room is ours: what a room we just left still sends is not shown.
    if (this.core.dropsRoomMessages() && ROOM_TRAFFIC[m.type]) return;
    switch (m.type) {
      case 'welcome':
        this.storage?.setItem('carrom.token', m.resume_token);
        this.setStatus(this.core.resuming ? 'Resuming your seat...' : 'Connected'); // a resume: the room follows
        this.apply(this.core.welcome(m.resume_token));
        break;
      case 'room_state': {
        const joined = this.core.phase !== 'in_room';
        this.apply(this.core.roomState());
        this.request = null;
        this.setHeldRoom(m.code);
        if (joined) this.setStatus('Connected');
        break;
      }
      case 'pong': {
        const sent = this.pings.get(m.nonce);
        if (sent !== undefined) {
          this.rttMs = Math.max(localS - sent, 0) * 1000;
          this.pongs.push({ serverMs: m.server_time_ms, sentS: sent, receivedS: localS });
          this.pings.delete(m.nonce);
        }
        return; // the session measures round trips
      }
      case 'error': {
        // The resume after a redirect that named its room finds no seat (a room whose match had
        // not begun keeps none): the session joins the room instead; nothing for the player.
        const joinsInstead = m.code === 'bad_token' && this.core.resuming && this.core.joinCode !== '';
        this.apply(this.core.error(m.code), m);
        if (joinsInstead) return;
        break;
      }
      case 'redirect':
        this.apply(this.core.redirect(m));
        return; // the session's business
      default:
        break;
    }
    this.hooks.onMessage(m, localS);
  }

  onLinkLost(link, sentence, code) {
    if (link !== this.link) return;
    clearInterval(this.pingTimer);
    this.pingTimer = null;
    this.link = null;
    if (!this.started || this.core.phase === 'failed') return;
    this.lostReason = `${sentence}.`;
    this.apply(this.core.linkClosed(now(), code, Math.random()));
  }

  takePongs() {
    const out = this.pongs;
    this.pongs = [];
    return out;
  }

  badFrames() {
    return this.link ? this.link.badFrames : 0;
  }
}
