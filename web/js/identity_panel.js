// The lobby's "My player key" (docs/web.md): shows this page's key, copies it, and takes a key
// pasted from another device (the page then says hello with it from the next connection on).
import { isIdentityKey, replaceIdentity } from './identity.js';

export class IdentityPanel {
  // root: the <details id="identity"> element; onChange(key) when a pasted key is taken.
  constructor(root, storage, key, onChange) {
    this.root = root;
    this.storage = storage;
    this.onChange = onChange;
    this.shown = root.querySelector('#identity-key');
    this.pasted = root.querySelector('#identity-paste');
    this.note = root.querySelector('#identity-note');
    root.querySelector('#identity-copy').addEventListener('click', () => this.copy());
    root.querySelector('#identity-use').addEventListener('click', () => this.use());
    this.show(key);
  }

  show(key) {
    this.shown.value = key ?? '';
    this.root.hidden = !isIdentityKey(key);
  }

  async copy() {
    try {
      await navigator.clipboard.writeText(this.shown.value);
      this.note.textContent = 'Copied. Keep it secret: whoever has it plays as you.';
    } catch {
      this.shown.select();
      this.note.textContent = 'Select the key and copy it.';
    }
  }

  use() {
    if (!replaceIdentity(this.storage, this.pasted.value)) {
      this.note.textContent = 'A player key is 64 characters 0-9 and a-f.';
      return;
    }
    const key = this.pasted.value.trim().toLowerCase();
    this.pasted.value = '';
    this.show(key);
    this.note.textContent = 'This page now plays as that player.';
    this.onChange(key);
  }
}
