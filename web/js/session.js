// The connection's life (client/src/client_session.cpp): open a WebSocket, say hello, ask for a
// room (create, join, spectate or quick match), ping for the round trip and the server clock,
// and when the link drops open a new one and resume the seat with the token, backing off 0.5 s
// doubling to 5 s and giving up after 130 s (the server's default idle timeout, after which it
// notices a silent link, plus its grace, plus a margin). A link on which nothing (not even a pong
// to the pings every 2 s) arrived for 10 s is taken for lost: a browser's WebSocket may wait
// minutes before it notices a dead path by itself. The token and whether
// we hold a seat are kept in sessionStorage, so a reload of the page resumes the seat too.
//
// Phases: idle, connecting, greeting, lobby, joining, in_room, reconnecting, failed.

import * as proto from './protocol.js';

export const SESSION_DEFAULTS = Object.freeze({
  pingInterval: 2.0,
  firstRetry: 0.5,
  maxRetry: 5.0,
  giveUpAfter: 130.0,
  silenceTimeout: 10.0,
});

// Errors that answer a room request with no: the player picks something else in the lobby.
const REFUSALS = ['room_not_found', 'room_full', 'unsupported', 'too_many_rooms', 'bad_field',
  'already_in_room'];
// Messages that belong to a room.
const ROOM_TRAFFIC = { room_state: true, snapshot: true, event: true, shot_result: true };
// Close codes after which reconnecting cannot help.
const FINAL_CLOSES = { 4001: true, 4002: true };

const now = () => performance.now() / 1000;

function seconds(s) {
  return `${s < 10 ? s.toFixed(1) : s.toFixed(0)} s`;
}

export class Session {
  // url: the WebSocket URL. storage: a Storage (sessionStorage) or null. hooks:
  // onMessage(message, localS) for every message of the match, onChange() when phase or status
  // change, onRefused(error) when a room request was refused.
  constructor(url, storage, hooks, config = SESSION_DEFAULTS, ConnectionClass) {
    this.url = url;
    this.storage = storage;
    this.hooks = hooks;
    this.config = config;
    this.ConnectionClass = ConnectionClass;
    this.phase = 'idle';
    this.status = '';
    this.name = '';
    this.link = null;
    this.request = null; // the room request waiting to be sent
    this.lastRequest = null;
    this.token = storage?.getItem('carrom.token') ?? '';
    this.resuming = false;
    this.everWelcomed = false;
    this.attempts = 0;
    this.retryDelay = 0;
    this.lostSince = 0;
    this.retryTimer = null;
    this.pingTimer = null;
    this.nextNonce = 1;
    this.pings = new Map();
    this.rttMs = null;
    this.pongs = []; // {serverMs, sentS, receivedS}
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

  setStatus(phase, status) {
    this.phase = phase;
    this.status = status;
    this.hooks.onChange?.();
  }

  // Connects as `name`. With resume true and a stored token, asks for the old seat back.
  start(name, resume = false) {
    this.stopLink();
    this.name = name;
    this.resuming = resume && proto.isResumeToken(this.token);
    this.attempts = 0;
    this.everWelcomed = false;
    this.openLink();
  }

  openLink() {
    clearTimeout(this.retryTimer);
    this.retryTimer = null;
    const link = new this.ConnectionClass(this.url, {
      onOpen: () => this.onOpen(link),
      onMessage: (m, localS) => this.onMessage(link, m, localS),
      onClose: (sentence, code) => this.onLinkLost(link, sentence, code),
    });
    this.link = link;
    if (this.phase === 'reconnecting') {
      this.setStatus('reconnecting', `Reconnecting (attempt ${this.attempts})...`);
    } else {
      this.setStatus('connecting', 'Connecting...');
    }
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
    link.send(proto.hello(this.name, this.resuming ? this.token : undefined));
    this.setStatus('greeting', 'Saying hello...');
    clearInterval(this.pingTimer);
    this.pingTimer = setInterval(() => this.ping(), this.config.pingInterval * 1000);
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
    if (this.phase === 'lobby') this.sendRequest();
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
    this.request = null;
    let status = 'Joining...';
    if (r.kind === 'quick') status = r.seats === 4 ? 'Waiting for three players...' : 'Waiting for an opponent...';
    this.setStatus('joining', status);
  }

  // Game input (aim, shoot, rematch): sent only while in a room.
  sendGame(message) {
    if (this.phase !== 'in_room' || !this.link) return false;
    return this.link.send(message);
  }

  // Leave the room (or the quick-match queue) and go back to the lobby.
  leaveRoom() {
    if (this.link) this.link.send(proto.leave());
    this.setHeldRoom('');
    this.request = null;
    if (this.link && ['in_room', 'joining', 'lobby'].includes(this.phase)) {
      this.setStatus('lobby', 'Connected');
    }
  }

  onMessage(link, m, localS) {
    if (link !== this.link) return;
    this.lastHeard = now();
    // In the lobby no room is ours: what a room we just left still sends is not shown.
    if (this.phase === 'lobby' && ROOM_TRAFFIC[m.type]) return;
    switch (m.type) {
      case 'welcome':
        this.token = m.resume_token;
        this.storage?.setItem('carrom.token', m.resume_token);
        this.everWelcomed = true;
        this.attempts = 0;
        if (this.resuming) {
          this.setStatus('joining', 'Resuming your seat...'); // the server sends the room back
        } else {
          this.setStatus('lobby', 'Connected');
          if (this.request) this.sendRequest();
        }
        break;
      case 'room_state':
        this.resuming = false;
        this.setHeldRoom(m.code);
        if (this.phase !== 'in_room') this.setStatus('in_room', 'Connected');
        break;
      case 'pong': {
        const sent = this.pings.get(m.nonce);
        if (sent !== undefined) {
          this.rttMs = Math.max(localS - sent, 0) * 1000;
          this.pongs.push({ serverMs: m.server_time_ms, sentS: sent, receivedS: localS });
          this.pings.delete(m.nonce);
        }
        return; // the session measures round trips
      }
      case 'error':
        if (m.code === 'version_mismatch') {
          this.setStatus('failed', 'The server speaks another protocol version');
        } else if (m.code === 'bad_token') {
          this.resuming = false;
          this.setHeldRoom('');
          this.setStatus('lobby', 'Connected (your old seat is gone)');
        } else if (this.phase === 'joining' && REFUSALS.includes(m.code)) {
          this.setStatus('lobby', 'Connected');
          this.hooks.onRefused?.(m, this.lastRequest);
        }
        break;
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
    if (this.phase === 'failed' || this.phase === 'idle') return;
    if (FINAL_CLOSES[code]) {
      this.setStatus('failed', `${sentence}.`);
      return;
    }
    const t = now();
    if (this.attempts === 0) this.lostSince = t;
    this.attempts += 1;
    const reason = `${sentence}.`;
    if (t - this.lostSince >= this.config.giveUpAfter) {
      this.setStatus('failed', `${reason} Gave up after ${seconds(t - this.lostSince)}.`);
      return;
    }
    this.retryDelay = this.attempts === 1 ? this.config.firstRetry
      : Math.min(2 * this.retryDelay, this.config.maxRetry);
    const held = ['in_room', 'joining'].includes(this.phase) || this.resuming;
    this.resuming = proto.isResumeToken(this.token) && held;
    if (!held && this.lastRequest && this.phase === 'joining') this.request = this.lastRequest;
    this.phase = this.everWelcomed ? 'reconnecting' : 'connecting';
    this.setStatus(this.phase, `${reason} Retrying in ${seconds(this.retryDelay)} (attempt ${this.attempts})`);
    this.retryTimer = setTimeout(() => this.openLink(), this.retryDelay * 1000);
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
