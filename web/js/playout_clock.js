// Maps the local clock to the server match time the board is rendered at, a short adaptive
// delay behind the newest snapshot (client/src/playout_clock.cpp; docs/interpolation.md).
//
//   render time = local time - base transit - delay
//   base transit = smallest (arrival - server time) over the last 180 snapshots
//   delay = intervalFactor snapshot intervals + jitter (a decaying peak of how much later than
//           the fastest path snapshots arrive), clamped to [10, 300] ms; intervalFactor is 2,
//           and 0 when the server sends a delta at every change of motion
//
// The rendered time follows the local clock and is pulled towards its target by at most 10 % of
// the elapsed time (never backwards); errors over 0.25 s are corrected at once. Units: s.

export const PLAYOUT_DEFAULTS = Object.freeze({
  intervalFactor: 2.0,
  initialInterval: 1 / 60,
  minDelay: 0.010,
  maxDelay: 0.300,
  jitterDecay: 3.0, // time constant of the jitter peak's decay
  gap: 0.25, // snapshots further apart than this are separate runs
  transitWindow: 180,
  slewRate: 0.1,
  snapThreshold: 0.25,
});

export class PlayoutClock {
  constructor(config = PLAYOUT_DEFAULTS) {
    this.config = config;
    this.hasData = false;
    this.lastServer = 0;
    this.lastArrival = 0;
    this.interval = config.initialInterval;
    this.jitter = 0;
    this.transits = [];
    this.minTransit = Infinity;
    this.hasRender = false;
    this.lastLocal = 0;
    this.lastRender = 0;
  }

  // A snapshot sampled at serverTime arrived at localTime.
  onSnapshot(serverTime, localTime) {
    const c = this.config;
    const transit = localTime - serverTime;
    if (this.hasData) {
      const gap = serverTime - this.lastServer;
      if (gap > 0 && gap <= c.gap) {
        this.interval += 0.1 * (gap - this.interval); // EWMA of the snapshot spacing
      }
      const since = Math.max(localTime - this.lastArrival, 0);
      this.jitter *= Math.exp(-since / c.jitterDecay);
    }
    this.transits.push(transit);
    if (this.transits.length > c.transitWindow) this.transits.shift();
    this.minTransit = Math.min(...this.transits);
    this.jitter = Math.max(this.jitter, transit - this.minTransit);
    this.lastServer = serverTime;
    this.lastArrival = localTime;
    this.hasData = true;
  }

  // A server that sends a snapshot at every change of motion needs no interval in the delay (the
  // free motion is exact past the newest state): 0; otherwise 2.
  setIntervalFactor(factor) {
    this.config = { ...this.config, intervalFactor: factor };
  }

  baseTransit() {
    return this.transits.length === 0 ? 0 : this.minTransit;
  }

  delay() {
    const c = this.config;
    const d = c.intervalFactor * this.interval + this.jitter;
    return Math.min(Math.max(d, c.minDelay), c.maxDelay);
  }

  targetTime(localTime) {
    return localTime - this.baseTransit() - this.delay();
  }

  // The server time to render at localTime. Call with non-decreasing local times.
  renderTime(localTime) {
    const target = this.targetTime(localTime);
    if (!this.hasRender) {
      this.hasRender = true;
      this.lastLocal = localTime;
      this.lastRender = target;
      return target;
    }
    const elapsed = Math.max(localTime - this.lastLocal, 0);
    const freeRun = this.lastRender + elapsed;
    const error = target - freeRun;
    let next = target; // a large error (a new match, a long stall) is corrected at once
    if (Math.abs(error) <= this.config.snapThreshold) {
      const maxStep = this.config.slewRate * elapsed;
      next = Math.max(freeRun + Math.min(Math.max(error, -maxStep), maxStep), this.lastRender);
    }
    this.lastLocal = localTime;
    this.lastRender = next;
    return next;
  }
}
