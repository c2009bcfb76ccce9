// When to play which sound (client/src/sound_synth.cpp): loudness from a collision impulse, and
// cues that wait until the board is rendered at their time, so sounds match what is seen.

// Loudness 0..1 on a log scale: impulses at or below `quiet` are silent, `loud` and above full.
export function loudnessFromImpulse(impulse, quiet = 5, loud = 2000) {
  if (!(impulse > quiet)) return 0;
  const level = Math.log(impulse / quiet) / Math.log(loud / quiet);
  return Math.min(Math.max(level, 0), 1);
}

// Cues {time, kind: 'click' | 'cushion' | 'pocket', volume} sorted by time (server match time).
// At most `capacity` wait (a hidden tab draws no frames, so none are taken; the oldest go).
export class SoundCueQueue {
  constructor(capacity = 512) {
    this.capacity = capacity;
    this.cues = [];
    this.late = 0; // cues dropped as late
  }

  push(cue) {
    if (!Number.isFinite(cue.time)) return;
    let i = this.cues.length;
    while (i > 0 && this.cues[i - 1].time > cue.time) i -= 1;
    this.cues.splice(i, 0, cue);
    if (this.cues.length > this.capacity) this.cues.shift();
  }

  // Cues with time <= renderTime, in time order; those more than `stale` s late are dropped
  // instead (a resume or a stall should not play a burst of old clicks).
  takeDue(renderTime, stale = 0.25) {
    let n = 0;
    const due = [];
    while (n < this.cues.length && this.cues[n].time <= renderTime) {
      if (renderTime - this.cues[n].time <= stale) due.push(this.cues[n]);
      else this.late += 1;
      n += 1;
    }
    this.cues.splice(0, n);
    return due;
  }

  clear() {
    this.cues = [];
  }
}
