// The page's player key (web/js/identity.js) under node: made once, kept, replaced only by a key,
// and sent in hello (docs/ratings.md, "Identity").
import assert from 'node:assert/strict';
import test from 'node:test';

import { IDENTITY_STORAGE_KEY, isIdentityKey, loadOrCreateIdentity, newIdentityKey, replaceIdentity } from '../../web/js/identity.js';
import * as proto from '../../web/js/protocol.js';

class MemoryStorage {
  constructor() { this.items = new Map(); }
  getItem(k) { return this.items.has(k) ? this.items.get(k) : null; }
  setItem(k, v) { this.items.set(k, String(v)); }
}

test('a new key is 64 lowercase hex digits from the 32 random bytes', () => {
  const key = newIdentityKey((bytes) => bytes.fill(0xab));
  assert.equal(key, 'ab'.repeat(32));
  assert.ok(isIdentityKey(newIdentityKey()));
  assert.notEqual(newIdentityKey(), newIdentityKey());
});

test('the key is made on the first load and kept on the next ones', () => {
  const storage = new MemoryStorage();
  const first = loadOrCreateIdentity(storage);
  assert.ok(isIdentityKey(first));
  assert.equal(storage.getItem(IDENTITY_STORAGE_KEY), first);
  assert.equal(loadOrCreateIdentity(storage), first);
  assert.equal(loadOrCreateIdentity(null), null); // no storage: a guest
  storage.setItem(IDENTITY_STORAGE_KEY, 'damaged');
  assert.notEqual(loadOrCreateIdentity(storage), 'damaged');
});

test('a pasted key replaces the stored one only when it is a key', () => {
  const storage = new MemoryStorage();
  const mine = loadOrCreateIdentity(storage);
  assert.equal(replaceIdentity(storage, 'not a key'), false);
  assert.equal(replaceIdentity(storage, 'A'.repeat(63)), false);
  assert.equal(storage.getItem(IDENTITY_STORAGE_KEY), mine);
  assert.equal(replaceIdentity(storage, `  ${'C'.repeat(64)}\n`), true);
  assert.equal(storage.getItem(IDENTITY_STORAGE_KEY), 'c'.repeat(64));
});

test('hello carries the key only when there is one', () => {
  assert.deepEqual(proto.hello('Asha'), { type: 'hello', version: 1, name: 'Asha' });
  assert.deepEqual(proto.hello('Asha', undefined, 'd'.repeat(64)),
    { type: 'hello', version: 1, name: 'Asha', identity: 'd'.repeat(64) });
});

test('the lobby\'s rating line shows labels and the change after a rated game', async () => {
  const { ratingLine } = await import('../../web/js/rating_view.js');
  const before = [{ rule_set: 'icf', rating: 1518.4, label: '1518', games: 12 }];
  const after = [{ rule_set: 'icf', rating: 1532.2, label: '1532', games: 13 },
    { rule_set: 'freestyle', rating: 1662.3, label: '1662?', games: 1 }];
  assert.equal(ratingLine(null, []), '');
  assert.equal(ratingLine(null, before), 'Rating: ICF 1518');
  assert.equal(ratingLine(before, after), 'Rating: ICF 1532 (+14), freestyle 1662? (+162)');
  assert.equal(ratingLine(after, after), 'Rating: ICF 1532, freestyle 1662?');
});
