// The emotes on the page: a "React" button in the bottom bar opening a menu of the fixed set and
// of mute switches (every other seat by name, and all), and a bubble beside each seat's side of
// the board while its emote is on show (EmoteBoard in emotes.js decides what shows).

import { EMOTES } from './emotes.js';
import { seatPanels } from './seat_panels.js';

function el(tag, props = {}, text = '') {
  const e = document.createElement(tag);
  Object.assign(e, props);
  if (text) e.textContent = text;
  return e;
}

export class EmoteView {
  // send(id): sends the emote (the page's session).
  constructor(send) {
    this.send = send;
    this.open = false;
    this.key = '';
    this.toggle = el('button', { id: 'emote-toggle', type: 'button', hidden: true }, 'React');
    this.toggle.setAttribute('aria-expanded', 'false');
    this.menu = el('div', { id: 'emote-menu', hidden: true });
    this.menu.setAttribute('role', 'menu');
    const picks = el('div', { className: 'emote-picks' });
    for (const e of EMOTES) {
      const b = el('button', { type: 'button' }, e.text);
      b.dataset.emote = e.id;
      b.addEventListener('click', () => {
        this.send(e.id);
        this.setOpen(false);
      });
      picks.append(b);
    }
    this.mutes = el('div', { className: 'emote-mutes' });
    this.menu.append(picks, this.mutes);
    this.toggle.addEventListener('click', () => this.setOpen(!this.open));
    const bar = document.getElementById('bottom-bar');
    bar.insertBefore(this.toggle, document.getElementById('mute'));
    const wrap = document.getElementById('board-wrap');
    wrap.append(this.menu);
    this.bubbles = new Map(); // screen side -> element
    for (const at of ['bottom', 'right', 'top', 'left']) {
      const b = el('div', { className: 'emote-bubble', hidden: true });
      b.dataset.at = at;
      b.setAttribute('aria-live', 'polite');
      wrap.append(b);
      this.bubbles.set(at, b);
    }
  }

  setOpen(open) {
    this.open = open;
    this.menu.hidden = !open;
    this.toggle.setAttribute('aria-expanded', String(open));
  }

  // The mute switches for the other seats of `view` and for all, as `board` has them.
  renderMutes(view, board) {
    const others = view.seats
      .map((s, i) => ({ seat: i, name: s.name, occupied: s.occupied }))
      .filter((s) => s.seat !== view.you && s.occupied);
    const key = JSON.stringify([others, [...board.mutedSeats], board.allMuted]);
    if (key === this.key) return;
    this.key = key;
    this.mutes.replaceChildren();
    for (const s of others) {
      const b = el('button', { type: 'button' },
        `${board.isMuted(s.seat) ? 'Unmute' : 'Mute'} ${s.name}`);
      b.dataset.muteSeat = String(s.seat);
      b.setAttribute('aria-pressed', String(board.isMuted(s.seat)));
      b.disabled = board.allMuted;
      b.addEventListener('click', () => board.setMuted(s.seat, !board.mutedSeats.has(s.seat)));
      this.mutes.append(b);
    }
    const all = el('button', { type: 'button' }, board.allMuted ? 'Show emotes' : 'Mute all emotes');
    all.dataset.muteAll = 'true';
    all.setAttribute('aria-pressed', String(board.allMuted));
    all.addEventListener('click', () => board.setAllMuted(!board.allMuted));
    this.mutes.append(all);
  }

  update(model, nowS) {
    const v = model.view;
    const seated = v.inRoom && v.you >= 0 && v.phase !== 'waiting';
    if (this.toggle.hidden === seated) this.toggle.hidden = !seated;
    if (!seated && this.open) this.setOpen(false);
    if (v.inRoom) this.renderMutes(v, model.emotes);
    const sideOf = new Map(v.inRoom ? seatPanels(v).map((p) => [p.seat, p.at]) : []);
    const showing = new Map();
    for (const e of v.inRoom ? model.emotes.visible(nowS) : []) {
      const at = sideOf.get(e.seat);
      if (at) showing.set(at, e);
    }
    for (const [at, bubble] of this.bubbles) {
      const e = showing.get(at);
      const text = e ? `${v.seats[e.seat]?.name ?? ''}: ${e.text}` : '';
      if (bubble.textContent !== text) bubble.textContent = text;
      if (bubble.hidden !== !e) bubble.hidden = !e;
      if (e) bubble.dataset.seat = String(e.seat);
    }
  }
}
