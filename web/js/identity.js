// The player's key (docs/ratings.md, "Identity"): 256 bits from crypto.getRandomValues as 64
// lowercase hex digits, kept in localStorage under 'carrom.identity' and sent in every hello.
// The same key is the same player on any device: the lobby's "My player key" copies it out and
// takes one pasted in. Without storage the page plays as a guest.

export const IDENTITY_STORAGE_KEY = 'carrom.identity';

export function isIdentityKey(text) {
  return typeof text === 'string' && /^[0-9a-f]{64}$/.test(text);
}

export function newIdentityKey(random = (bytes) => crypto.getRandomValues(bytes)) {
  const bytes = random(new Uint8Array(32));
  return Array.from(bytes, (b) => b.toString(16).padStart(2, '0')).join('');
}

// The stored key, or a new one stored now; null without storage (a guest).
export function loadOrCreateIdentity(storage) {
  if (!storage) return null;
  const stored = storage.getItem(IDENTITY_STORAGE_KEY);
  if (isIdentityKey(stored)) return stored;
  const key = newIdentityKey();
  storage.setItem(IDENTITY_STORAGE_KEY, key);
  return key;
}

// Replaces the stored key with a pasted one (spaces around it ignored); false when it is not a
// key (nothing changes).
export function replaceIdentity(storage, text) {
  const key = typeof text === 'string' ? text.trim().toLowerCase() : '';
  if (!storage || !isIdentityKey(key)) return false;
  storage.setItem(IDENTITY_STORAGE_KEY, key);
  return true;
}
