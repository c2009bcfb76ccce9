// The heads-up display as HTML around and over the canvas (client/app/hud_painter.cpp): both
// seats with names, colours, dues and scores; whose turn and the shot clock; the queen; room,
// rule set, board number, coins left and spectators; the connection and round trip; short
// messages over the board; the room code with its shareable link while waiting; the result and
// why the game ended, with Rematch and Lobby; the reconnecting notice. Text is written to the
// DOM only when it changed, so a frame costs almost nothing here.

import { countWords, ruleSetName } from './plain_words.js';
import { roomLink } from './room_link.js';

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
      leave: $('leave'), copy: $('copy-link'),
    };
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
    if (s.dues > 0) sub += `${sub ? ', ' : ''}owes ${countWords(s.dues, 'due', 'dues')}`;
    const parts = el.parts ?? (el.parts = {
      name: el.querySelector('.name'), sub: el.querySelector('.sub'),
      score: el.querySelector('.score'), dot: el.querySelector('.dot'),
    });
    setText(parts.name, name);
    setText(parts.sub, sub);
    setClass(parts.sub, 'alert', s.dues > 0);
    setText(parts.score, String(s.score));
    if (parts.dot.dataset.colour !== s.colour) parts.dot.dataset.colour = s.colour;
  }

  statusLine(model, now) {
    const v = model.view;
    let text;
    let tone = '';
    switch (v.phase) {
      case 'waiting': text = 'Waiting for a player'; break;
      case 'moving': text = `${model.seatName(v.toPlay)} shot`; break;
      case 'aiming':
        text = model.myTurn() ? 'Your turn' : `${model.seatName(v.toPlay)} to play`;
        if (model.myTurn()) tone = 'gold';
        break;
      case 'board_over': text = `Board ${v.boardNumber} over`; break;
      default:
        text = v.winner < 0 ? 'Game drawn' : v.winner === v.you ? 'You won!' : `${model.seatName(v.winner)} won`;
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
    if (v.inRoom) {
      const left = v.you >= 0 ? v.you : 0;
      this.seat(e.seats[0], model, left);
      this.seat(e.seats[1], model, 1 - left);
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
