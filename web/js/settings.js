// The player's settings (client/app/settings_file.cpp keeps the desktop client's): sound volume
// and mute, reduced motion (pocketed pieces vanish at once, lines appear without sliding in) and
// left-handed (Cancel shot on the left under the board). Kept in localStorage under
// `carrom.settings` as JSON; a missing or damaged entry gives the defaults (reduced motion from
// the system's prefers-reduced-motion).

const KEY = 'carrom.settings';
const $ = (id) => document.getElementById(id);

// Whole percent in [0, 100]; anything else gives `fallback`.
function percent(value, fallback) {
  return Number.isInteger(value) && value >= 0 && value <= 100 ? value : fallback;
}

export function defaultSettings(prefersReducedMotion = false) {
  return { volume: 80, muted: false, reducedMotion: prefersReducedMotion, leftHanded: false };
}

// Settings from stored text (null: none stored); unknown or bad fields take the defaults.
export function parseSettings(text, defaults) {
  let stored = {};
  try {
    stored = text ? JSON.parse(text) : {};
  } catch {
    stored = {};
  }
  if (typeof stored !== 'object' || stored === null) stored = {};
  const flag = (v, d) => (typeof v === 'boolean' ? v : d);
  return {
    volume: percent(stored.volume, defaults.volume),
    muted: flag(stored.muted, defaults.muted),
    reducedMotion: flag(stored.reducedMotion, defaults.reducedMotion),
    leftHanded: flag(stored.leftHanded, defaults.leftHanded),
  };
}

export class Settings {
  // onChange(settings) after every change (and once at the start).
  constructor(storage, onChange) {
    this.storage = storage;
    this.onChange = onChange;
    const reduced = window.matchMedia?.('(prefers-reduced-motion: reduce)').matches ?? false;
    const defaults = defaultSettings(reduced);
    this.values = parseSettings(storage?.getItem(KEY) ?? null, defaults);
    this.sheet = $('settings');
    this.inputs = { volume: $('volume'), muted: $('muted'), reducedMotion: $('reduced-motion'), leftHanded: $('left-handed') };
    this.inputs.volume.addEventListener('input', () => this.set({ volume: Number(this.inputs.volume.value) }));
    for (const key of ['muted', 'reducedMotion', 'leftHanded']) {
      this.inputs[key].addEventListener('change', () => this.set({ [key]: this.inputs[key].checked }));
    }
    $('settings-close').addEventListener('click', () => this.show(false));
    this.apply();
  }

  set(changes) {
    this.values = { ...this.values, ...changes };
    this.storage?.setItem(KEY, JSON.stringify(this.values));
    this.apply();
  }

  apply() {
    const v = this.values;
    this.inputs.volume.value = String(v.volume);
    this.inputs.muted.checked = v.muted;
    this.inputs.reducedMotion.checked = v.reducedMotion;
    this.inputs.leftHanded.checked = v.leftHanded;
    document.body.classList.toggle('reduced-motion', v.reducedMotion);
    document.body.classList.toggle('left-handed', v.leftHanded);
    this.onChange(v);
  }

  show(visible) {
    this.sheet.hidden = !visible;
  }
}
