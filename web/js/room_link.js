// The page's address as a room link: `#/room/CODE` joins room CODE as a player (a full room is
// watched instead), `#/watch/CODE` watches it. The address bar always shows the link of the room
// the page is in, so it can be shared as it is.

import { isRoomCode, normaliseRoomCode } from './protocol.js';

// {kind: 'room' | 'watch', code} or null.
export function parseRoomHash(hash) {
  const m = /^#\/(room|watch)\/([^/?#]+)\/?$/.exec(hash ?? '');
  if (!m) return null;
  const code = normaliseRoomCode(decodeURIComponent(m[2]));
  return isRoomCode(code) ? { kind: m[1], code } : null;
}

export function roomHash(code, spectator = false) {
  return `#/${spectator ? 'watch' : 'room'}/${code}`;
}

// The full shareable address of a room (the page's own address with the room hash).
export function roomLink(location, code) {
  return `${location.origin}${location.pathname}${location.search}${roomHash(code)}`;
}

// Shows `hash` in the address bar without adding a history entry or firing hashchange.
export function showHash(hash) {
  if (window.location.hash !== hash) {
    window.history.replaceState(null, '', `${window.location.pathname}${window.location.search}${hash}`);
  }
}
