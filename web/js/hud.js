// The heads-up display as HTML around and over the canvas (client/app/hud_painter.cpp): both
// seats with names, colours, dues and scores (in doubles: the two teams in the top bar and one
// panel per seat on the board's frame at that seat's side, seat_panels.js); whose turn and the
// shot clock; the queen; room,
// rule set, board number, coins left and spectators; the connection and round trip; short
// messages over the board; the room code with its shareable link while waiting; the result and
// why the game ended, with Rematch and Lobby; the reconnecting notice. Text is written to the
// DOM only when it changed, so a frame costs almost nothing here.

import { countWords, ruleSetName } from './plain_words.js';
import { roomLink } from './room_link.js';
import { freeSeats, seatPanels, teamSummaries } from './seat_panels.js';

const $ = (id) => document.getElementById(id);

function setText(el, text) {
  if (el.textContent !== text) el.textContent = text;
}

function setClass(el, name, on) {
  if (el.classList.contains(name) !== on) el.classList.toggle(name, on);
}

function setHidden(el, hidden) {
  if (el.hidden !== hidden) el.hidden = hidden;
}

function queenText(model) {
  const q = model.view.queen;
  switch (q.state) {
    case 'pending': return `Queen: ${model.seatName(q.seat)} must cover`;
    case 'covered': return `Queen: covered by ${model.seatName(q.seat)}`;
    case 'none': return 'No queen in this game';
    default: return 'Queen: on the board';
  }
}

export class Hud {
  // actions: {rematch(), lobby(), retry(), cancelAim(), toggleMute(), copyLink()}
  constructor(actions) {
    this.el = {
      top: $('top-bar'), seats: [$('seat-left'), $('seat-right')], status: $('status-line'),
      queen: $('queen-line'), room: $('room-info'), coins: $('coins-left'), conn: $('connection'),
      messages: $('messages'), waiting: $('waiting'), code: $('waiting-code'),
      link: $('waiting-link'), over: $('game-over'), result: $('game-over-result'),
      rematch: $('rematch'), notice: $('notice'), noticeTitle: $('notice-title'),
      noticeText: $('notice-text'), retry: $('retry'), cancel: $('cancel-aim'), mute: $('mute'),
      leave: $('leave'), copy: $('copy-link'), share: $('waiting-share'),
      frameSeats: [...document.querySelectorAll('.frame-seat')],
    };
    this.panels = []; // what the frame panels show (doubles), for the debug hook
    this.messagesKey = '';
    this.el.rematch.addEventListener('click', () => actions.rematch());
    $('to-lobby').addEventListener('click', () => actions.lobby());
    this.el.leave.addEventListener('click', () => actions.lobby());
    this.el.retry.addEventListener('click', () => actions.retry());
    this.el.cancel.addEventListener('click', () => actions.cancelAim());
    this.el.mute.addEventListener('click', () => actions.toggleMute());
    this.el.copy.addEventListener('click', () => actions.copyLink());
  }

  seat(el, model, seat) {
    const v = model.view;
    const s = v.seats[seat];
    if (!s) {
      setHidden(el, true);
      return;
    }
    setHidden(el, false);
    const toPlay = v.phase === 'aiming' && v.toPlay === seat;
    setClass(el, 'to-play', toPlay);
    let name = s.occupied ? s.name : '(empty seat)';
    if (s.occupied && !s.connected) name += ' (away)';
    if (seat === v.you) name += ' (you)';
    let sub = s.colour === 'none' ? '' : s.colour;
    this.fill(el, name, sub, s);
  }

  // A team in a top-bar box (doubles).
  team(el, model, t) {
    setHidden(el, false);
    setClass(el, 'to-play', t.toPlay);
    let name = t.names;
    if (t.ours) name += ' (your team)';
    let sub = t.colour === 'none' ? '' : t.colour;
    if (t.free > 0) sub += `${sub ? ', ' : ''}${countWords(t.free, 'seat', 'seats')} free`;
    this.fill(el, name, sub, t);
  }

  // A box's name, sub-line (plus the dues owed, in the alert colour), score and colour dot.
  fill(el, name, sub, { dues, score, colour }) {
    if (dues > 0) sub += `${sub ? ', ' : ''}owes ${countWords(dues, 'due', 'dues')}`;
    const parts = this.parts(el);
    setText(parts.name, name);
    setText(parts.sub, sub);
    setClass(parts.sub, 'alert', dues > 0);
    setText(parts.score, String(score));
    if (parts.dot.dataset.colour !== colour) parts.dot.dataset.colour = colour;
  }

  parts(el) {
    return el.parts ?? (el.parts = {
      name: el.querySelector('.name'), sub: el.querySelector('.sub'),
      score: el.querySelector('.score'), dot: el.querySelector('.dot'), tag: el.querySelector('.tag'),
      dues: el.querySelector('.dues'),
    });
  }

  // The four seats at their sides of the board (doubles); hidden in singles.
  frameSeats(model) {
    const panels = model.doubles() ? seatPanels(model.view) : [];
    this.panels = panels;
    for (const el of this.el.frameSeats) {
      const p = panels.find((x) => x.at === el.dataset.at);
      setHidden(el, !p);
      if (!p) continue;
      const parts = this.parts(el);
      let name = p.name;
      if (p.away) name += ' (away)';
      else if (p.bot) name += ' (bot)';
      setText(parts.name, name);
      setText(parts.tag, p.tag);
      setText(parts.dues, p.dues > 0 ? `owes ${p.dues}` : '');
      setText(parts.score, String(p.score));
      setClass(el, 'to-play', p.toPlay);
      if (el.dataset.tag !== p.tag) el.dataset.tag = p.tag;
      if (parts.dot.dataset.colour !== p.colour) parts.dot.dataset.colour = p.colour;
    }
  }

  statusLine(model, now) {
    const v = model.view;
    let text;
    let tone = '';
    switch (v.phase) {
      case 'waiting':
        text = model.doubles() ? `Waiting for ${countWords(freeSeats(v), 'player', 'players')}`
          : 'Waiting for a player';
        break;
      case 'moving': text = `${model.seatName(v.toPlay)} shot`; break;
      case 'aiming':
        text = model.myTurn() ? 'Your turn' : `${model.seatName(v.toPlay)} to play`;
        if (model.myTurn()) tone = 'gold';
        break;
      case 'board_over': text = `Board ${v.boardNumber} over`; break;
      default:
        if (v.winner < 0) text = 'Game drawn';
        else if (model.ourTeam(v.winner)) text = model.doubles() ? 'Your team won!' : 'You won!';
        else text = `${model.teamName(v.winner)} won`;
        tone = 'gold';
        break;
    }
    const left = model.shotClockLeft(now);
    if (left !== null) {
      text += `  ${Math.ceil(left)} s`;
      if (left < 5) tone = 'alert';
    }
    return { text, tone };
  }

  // Everything the HUD shows, from the model and the session, at local time `now`.
  update(model, session, ui, now) {
    const v = model.view;
    const e = this.el;
    setHidden(e.top, !v.inRoom);
    this.frameSeats(model);
    if (v.inRoom) {
      if (model.doubles()) {
        const teams = teamSummaries(v);
        this.team(e.seats[0], model, teams[0]);
        this.team(e.seats[1], model, teams[1]);
      } else {
        const left = v.you >= 0 ? v.you : 0;
        this.seat(e.seats[0], model, left);
        this.seat(e.seats[1], model, 1 - left);
      }
      const status = this.statusLine(model, now);
      setText(e.status, status.text);
      e.status.dataset.tone = status.tone;
      setText(e.queen, queenText(model));
      let room = `Room ${v.code} · ${ruleSetName(v.ruleSet)} · Board ${v.boardNumber}`;
      if (v.spectators > 0) room += ` · ${countWords(v.spectators, 'spectator', 'spectators')}`;
      if (v.you < 0) room += ' · spectating';
      setText(e.room, room);
      const c = model.coinsLeft();
      let coins = `Left: ${c.white} white, ${c.black} black`;
      if (v.queen.state !== 'none') coins += c.queen > 0 ? ', queen' : '';
      setText(e.coins, coins);
    } else {
      setText(e.room, '');
      setText(e.coins, '');
    }
    let conn = session.status;
    if (session.rttMs !== null && session.phase === 'in_room') conn += ` · RTT ${Math.round(session.rttMs)} ms`;
    const p = model.prediction?.stats;
    if (p && p.strokes > 0 && session.phase === 'in_room') conn += ` · predicted ${p.strokes}, corrected ${p.corrections}`;
    setText(e.conn, conn);
    setClass(e.conn, 'alert', !['in_room', 'lobby', 'joining', 'idle'].includes(session.phase));
    setHidden(e.leave, !v.inRoom);
    setHidden(e.cancel, !ui.pulling);
    setText(e.mute, ui.muted ? 'Sound: off' : 'Sound: on');
    e.mute.setAttribute('aria-pressed', ui.muted ? 'false' : 'true');
    this.messages(model, now);
    // Panels over the board; the connection's trouble hides the others.
    const trouble = ['reconnecting', 'failed'].includes(session.phase)
      || (v.inRoom && ['connecting', 'greeting'].includes(session.phase));
    const waiting = v.inRoom && v.phase === 'waiting' && !trouble;
    setHidden(e.waiting, !waiting);
    if (waiting) {
      setText(e.code, v.code);
      setText(e.link, roomLink(window.location, v.code));
      setText(e.share, model.doubles()
        ? 'Share this link: your partner and your opponents open it and play.'
        : 'Share this link: your opponent opens it and plays.');
    }
    const over = v.inRoom && v.phase === 'game_over' && !model.animating() && !trouble;
    setHidden(e.over, !over);
    if (over) {
      setText(e.result, v.gameEnd ? v.gameEnd.sentence : 'The game is over');
      setHidden(e.rematch, v.you < 0);
      e.rematch.disabled = v.rematchAsked;
      setText(e.rematch, v.rematchAsked ? 'Rematch asked…' : 'Rematch');
    }
    setHidden(e.notice, !trouble);
    if (trouble) {
      setText(e.noticeTitle, session.phase === 'failed' ? 'Disconnected' : 'Reconnecting');
      setText(e.noticeText, session.status);
      setHidden(e.retry, session.phase !== 'failed');
    }
  }

  messages(model, now) {
    const lines = model.log.visible(now);
    const key = lines.map((l) => `${l.posted}|${l.text}`).join('\n');
    if (key === this.messagesKey) return;
    this.messagesKey = key;
    const box = this.el.messages;
    box.replaceChildren(...lines.map((l) => {
      const div = document.createElement('div');
      div.className = `message ${l.tone}`;
      div.textContent = l.text;
      return div;
    }));
  }
}
