// The server's clock as seen from this page (client/src/server_clock.cpp): offset = server time
// - local time, from the server_time_ms of welcome, room_state and turn events (one-way, late by
// the latency) and from pongs (taken at the round trip's midpoint; the sample with the smallest
// round trip of the last 8 wins). Times in ms; local times in s.

const WINDOW = 8;

export class ServerClock {
  constructor() {
    this.offsetMs = null;
    this.rttMs = null;
    this.samples = []; // pong samples, newest last
  }

  oneWay(serverMs, localS) {
    if (this.samples.length > 0) return; // round-trip samples are better
    this.offsetMs = serverMs - localS * 1000;
  }

  roundTrip(serverMs, sentLocalS, localS) {
    const rtt = Math.max(localS - sentLocalS, 0) * 1000;
    const midLocalMs = (sentLocalS * 1000 + localS * 1000) / 2;
    this.samples.push({ offsetMs: serverMs - midLocalMs, rttMs: rtt });
    while (this.samples.length > WINDOW) this.samples.shift();
    this.rttMs = rtt;
    let best = this.samples[0];
    for (const s of this.samples) if (s.rttMs < best.rttMs) best = s;
    this.offsetMs = best.offsetMs;
  }

  known() {
    return this.offsetMs !== null;
  }

  serverNowMs(localS) {
    return localS * 1000 + (this.offsetMs ?? 0);
  }

  // Seconds left until deadlineMs (server clock), never negative.
  secondsUntil(deadlineMs, localS) {
    return Math.max((deadlineMs - this.serverNowMs(localS)) / 1000, 0);
  }
}
