// The heads-up display as HTML around and over the canvas (client/app/hud_painter.cpp): both
// seats with names, ratings (singles), colours, dues and scores (in doubles: the two teams in the top bar and one
// panel per seat on the board's frame at that seat's side, seat_panels.js); whose turn and the
// shot clock; the queen; room,
// rule set, board number, coins left and spectators; the connection and round trip; the message
// log beside or under the board (side_layout.js); the room code with its shareable link while waiting; the result and
// why the game ended and the ratings' changes, with Rematch and Lobby; the reconnecting notice. Text is written to the
// DOM only when it changed, so a frame costs almost nothing here.

import { boardSummaryText } from './board_summary_text.js';
import { gameOverText } from './game_over_text.js';
import { COUNTDOWN_S } from './match_model.js';
import { coinsLeftText, countWords, ruleSetName, targetWords } from './plain_words.js';
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
  // actions: {rematch(), lobby(), leave(), retry(), cancelAim(), toggleMute(), help(), settings(),
  // copyLink(), dismissSummary()}
  constructor(actions) {
    this.el = {
      top: $('top-bar'), seats: [$('seat-left'), $('seat-right')], status: $('status-line'),
      queen: $('queen-line'), room: $('room-info'), coins: $('coins-left'), conn: $('connection'),
      messages: $('messages'), waiting: $('waiting'), code: $('waiting-code'),
      link: $('waiting-link'), over: $('game-over'), result: $('game-over-result'),
      rematch: $('rematch'), overReason: $('game-over-reason'), overScore: $('game-over-score'),
      overRatings: $('game-over-ratings'),
      overWaiting: $('game-over-waiting'), summary: $('board-summary'),
      summaryTitle: $('board-summary-title'), summaryPoints: $('board-summary-points'),
      summaryColours: $('board-summary-colours'), notice: $('notice'), noticeTitle: $('notice-title'),
      noticeText: $('notice-text'), retry: $('retry'), cancel: $('cancel-aim'), mute: $('mute'),
      leave: $('leave'), copy: $('copy-link'), share: $('waiting-share'),
      frameSeats: [...document.querySelectorAll('.frame-seat')],
    };
    this.panels = []; // what the frame panels show (doubles), for the debug hook
    this.messagesKey = '';
    this.el.rematch.addEventListener('click', () => actions.rematch());
    this.el.summary.addEventListener('click', () => actions.dismissSummary());
    $('to-lobby').addEventListener('click', () => actions.lobby());
    this.el.leave.addEventListener('click', () => actions.leave());
    this.el.help = $('help');
    this.el.settings = $('settings-open');
    this.el.help.addEventListener('click', () => actions.help());
    this.el.settings.addEventListener('click', () => actions.settings());
    this.el.leaveAsk = $('leave-ask');
    this.el.leaveAskText = $('leave-ask-text');
    this.el.wrap = $('board-wrap');
    this.el.retry.addEventListener('click', () => actions.retry());
    this.el.cancel.addEventListener('click', () => actions.cancelAim());
    this.el.mute.addEventListener('click', () => actions.toggleMute());
    this.el.copy.addEventListener('click', () => actions.copyLink());
  }

  // rating: the seat's rating label ('' for none: seat_ratings.js).
  seat(el, model, seat, rating) {
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
    // The colour, and while the seat plays: what it has left to pocket (as the desktop client).
    let sub = s.colour === 'none' ? '' : s.colour;
    if (s.occupied) sub = coinsLeftText(model.coinsLeft(), v.ruleSet, s.colour) || sub;
    this.fill(el, name, sub, s);
    setText(this.parts(el).rating, s.occupied ? rating : ''); // a player who left keeps it on the card
  }

  // A team in a top-bar box (doubles).
  team(el, model, t) {
    setHidden(el, false);
    setClass(el, 'to-play', t.toPlay);
    // Ours: "You & Ravi" (partner named), with "your team"; theirs: their names, "opponents".
    const v = model.view;
    let name = t.names;
    let sub = t.colour === 'none' ? '' : t.colour;
    if (t.ours) {
      const partner = t.seats.find((i) => i !== v.you && v.seats[i].occupied);
      name = partner === undefined ? 'You' : `You & ${v.seats[partner].name}`;
      sub = `your team${sub ? `, ${sub}` : ''}`;
    } else if (v.you >= 0) {
      sub = `opponents${sub ? `, ${sub}` : ''}`;
    }
    if (name === '') name = 'Nobody yet';
    if (t.free > 0) sub += `${sub ? ', ' : ''}${countWords(t.free, 'seat', 'seats')} free`;
    this.fill(el, name, sub, t);
    setText(this.parts(el).rating, '');
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
      dues: el.querySelector('.dues'), rating: el.querySelector('.rating'),
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
      else if (p.bot && !name.startsWith('Bot')) name += ' (bot)'; // server bots say so already
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
      const hurry = left <= COUNTDOWN_S;
      text += `  ${Math.ceil(left)}${hurry && model.myTurn() ? ' s left!' : ' s'}`;
      if (hurry) tone = 'alert';
    }
    return { text, tone };
  }

  // The question before leaving a running game: `consequence` is what leaving costs; null hides it.
  askLeave(consequence) {
    setHidden(this.el.leaveAsk, consequence === null);
    if (consequence !== null) {
      setText(this.el.leaveAskText, consequence);
      $('leave-stay').focus();
    }
  }

  leaveAsked() {
    return !this.el.leaveAsk.hidden;
  }

  // Everything the HUD shows, from the model and the session, at local time `now`; ui: {pulling,
  // muted, ratings (a SeatRatings: each seat's rating and the game-over card's changes)}.
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
        this.seat(e.seats[0], model, left, ui.ratings.label(left));
        this.seat(e.seats[1], model, 1 - left, ui.ratings.label(1 - left));
      }
      const status = this.statusLine(model, now);
      setText(e.status, status.text);
      e.status.dataset.tone = status.tone;
      setText(e.queen, queenText(model));
      let room = `Room ${v.code} · ${ruleSetName(v.ruleSet)} `
        + `${targetWords(v.ruleSet, v.options.target_points)} · Board ${v.boardNumber}`;
      if (v.spectators > 0) room += ` · ${countWords(v.spectators, 'spectator', 'spectators')}`;
      if (v.you < 0) room += ' · spectating';
      setText(e.room, room);
      // What is left to pocket is said per seat (the seat boxes), as the desktop client does.
      setText(e.coins, '');
    } else {
      setText(e.room, '');
      setText(e.coins, '');
    }
    // While the link is lost the card over the board has the details; the bar its title, so that
    // the bar keeps one short line.
    const lost = v.inRoom && ['reconnecting', 'failed', 'connecting', 'greeting'].includes(session.phase);
    let conn = lost ? (session.phase === 'failed' ? 'Disconnected' : 'Reconnecting...') : session.status;
    if (session.rttMs !== null && session.phase === 'in_room') conn += ` · RTT ${Math.round(session.rttMs)} ms`;
    const p = model.prediction?.stats;
    if (p && p.strokes > 0 && session.phase === 'in_room') conn += ` · predicted ${p.strokes}, corrected ${p.corrections}`;
    setText(e.conn, conn);
    setClass(e.conn, 'alert', !['in_room', 'lobby', 'joining', 'idle'].includes(session.phase));
    setHidden(e.leave, !v.inRoom);
    setHidden(e.help, !v.inRoom);
    setHidden(e.settings, !v.inRoom);
    if (!v.inRoom) setHidden(e.leaveAsk, true);
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
    const summary = v.inRoom && model.boardSummaryShown(now) && !trouble;
    setHidden(e.summary, !summary);
    if (summary) {
      const t = boardSummaryText(v);
      setText(e.summaryTitle, t.title);
      setText(e.summaryPoints, t.points);
      setText(e.summaryColours, t.colours);
      setHidden(e.summaryColours, t.colours === '');
    }
    const over = v.inRoom && v.phase === 'game_over' && !model.animating() && !trouble;
    setHidden(e.over, !over);
    if (over) {
      const t = gameOverText(v, v.rematchAsked);
      setText(e.result, t.title);
      setText(e.overReason, t.reason);
      setText(e.overScore, t.score);
      setText(e.overRatings, ui.ratings.gameOverLine());
      setText(e.overWaiting, t.waiting);
      setHidden(e.overWaiting, t.waiting === '');
      // Withdrawn once a player left: the server would wait for an empty seat.
      setHidden(e.rematch, v.you < 0 || t.opponentLeft);
      e.rematch.disabled = !t.canRematch;
      setText(e.rematch, v.rematchAsked ? 'Rematch asked…' : 'Rematch');
    }
    setHidden(e.notice, !trouble);
    setClass(e.wrap, 'dimmed', trouble);
    if (trouble) {
      setText(e.noticeTitle, session.phase === 'failed' ? 'Disconnected' : 'Reconnecting');
      let text = session.status;
      // The server holds the seat for its grace period: the tries go on that long (docs/protocol.md,
      // "Resume"), the countdown in whole seconds.
      const held = session.seatHeldForS(now);
      if (session.phase !== 'failed' && held !== null) {
        text += ` Your seat is held; giving up in ${Math.ceil(held)} s.`;
      }
      setText(e.noticeText, text);
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
