// Game sounds made in code with Web Audio, the same voices as the desktop client
// (client/src/sound_synth.cpp): a wooden click (coin on coin), a dull thud (cushion) and a drop
// and rattle (pocket), each a decaying tone with a sweep plus decaying noise, peak-normalised to
// 0.9. The audio context starts on the first user gesture (browsers require one); the volume and
// the mute choice come from the settings (settings.js).

const VOICES = {
  // duration s, tone start Hz, tone end Hz, tone decay s, noise amount, noise decay s
  click: [0.045, 2600, 2200, 0.008, 0.6, 0.003],
  cushion: [0.12, 170, 120, 0.035, 0.35, 0.010],
  pocket: [0.30, 320, 90, 0.090, 0.25, 0.060],
};

const MASK64 = (1n << 64n) - 1n;
const VOICES_AT_ONCE = 12; // as the desktop client: a new sound stops the oldest beyond this
const LEVELS = 9; // loudness steps: 0, 1/8, ..., 1

// The desktop client's noise source: a 64-bit LCG, values in [-1, 1).
function noiseSource() {
  let state = 0x9E3779B97F4A7C15n;
  return () => {
    state = (state * 6364136223846793005n + 1442695040888963407n) & MASK64;
    return Number(state >> 11n) / 2 ** 52 - 1;
  };
}

// One voice as samples in [-0.9, 0.9] at `rate` Hz.
export function synthSound(kind, rate) {
  const [duration, f0, f1, toneDecay, noiseAmount, noiseDecay] = VOICES[kind];
  const count = Math.floor(duration * Math.max(rate, 8000));
  const wave = new Float32Array(count);
  const noise = noiseSource();
  let phase = 0;
  let peak = 0;
  for (let i = 0; i < count; i += 1) {
    const t = i / rate;
    const f = f0 + ((f1 - f0) * t) / duration;
    phase += (2 * Math.PI * f) / rate;
    const tone = Math.sin(phase) * Math.exp(-t / toneDecay);
    const hiss = noiseAmount * noise() * Math.exp(-t / noiseDecay);
    const attack = Math.min(1, t / 0.0008); // no click from a hard start
    const release = Math.min(1, (duration - t) / 0.005);
    wave[i] = (tone + hiss) * attack * release;
    peak = Math.max(peak, Math.abs(wave[i]));
  }
  const gain = peak > 0 ? 0.9 / peak : 0;
  for (let i = 0; i < count; i += 1) wave[i] *= gain;
  return wave;
}

export class SoundPlayer {
  constructor() {
    this.muted = false;
    this.volume = 1; // the settings' volume, 0..1, times each cue's own
    this.context = null;
    this.buffers = null;
    this.voices = []; // sources playing, oldest first
    this.played = 0; // cues played (the debug hook reports it)
  }

  // Call from a user gesture (pointerdown, keydown, click).
  unlock() {
    if (this.context) {
      if (this.context.state === 'suspended') this.context.resume().catch(() => {});
      return;
    }
    const AudioContextClass = window.AudioContext || window.webkitAudioContext;
    if (!AudioContextClass) return;
    try {
      this.context = new AudioContextClass();
    } catch {
      this.context = null;
      return;
    }
    this.gains = [];
    for (let i = 0; i < LEVELS; i += 1) {
      const gain = this.context.createGain();
      gain.gain.value = i / (LEVELS - 1);
      gain.connect(this.context.destination);
      this.gains.push(gain);
    }
    this.buffers = {};
    for (const kind of Object.keys(VOICES)) {
      const wave = synthSound(kind, this.context.sampleRate);
      const buffer = this.context.createBuffer(1, wave.length, this.context.sampleRate);
      buffer.copyToChannel(wave, 0);
      this.buffers[kind] = buffer;
    }
  }

  configure({ volume, muted }) {
    this.volume = volume / 100;
    this.muted = muted;
  }

  // cue: {kind, volume 0..1}
  play(cue) {
    this.played += 1;
    if (this.muted || !this.context || this.context.state !== 'running') return;
    if (this.voices.length >= VOICES_AT_ONCE) this.voices.shift().stop();
    const source = this.context.createBufferSource();
    source.buffer = this.buffers[cue.kind];
    // One connection per sound, to a gain made once per loudness step: changing the audio
    // graph takes a lock the audio thread holds while it renders.
    const level = Math.round(Math.min(Math.max(cue.volume * this.volume, 0), 1) * (LEVELS - 1));
    if (level === 0) return;
    source.connect(this.gains[level]);
    source.onended = () => {
      const i = this.voices.indexOf(source);
      if (i >= 0) this.voices.splice(i, 1);
    };
    this.voices.push(source);
    source.start();
  }
}
