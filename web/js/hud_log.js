// Short messages for the player, newest last, each shown for a few seconds (client/src/hud_log.cpp).
// Invariant: no two lines shown at once have the same text (posting a line that is still shown
// moves it to the newest place with a new time).
export class HudLog {
  constructor(capacity = 5, showS = 6) {
    this.capacity = capacity;
    this.showS = showS;
    this.lines = [];
    this.version = 0; // changes whenever a line is posted
  }

  post(text, tone, localS) {
    this.lines = this.lines.filter((l) => l.text !== text || localS - l.posted > this.showS);
    this.lines.push({ text, tone, posted: localS });
    while (this.lines.length > this.capacity) this.lines.shift();
    this.version += 1;
  }

  visible(localS) {
    return this.lines.filter((l) => localS - l.posted <= this.showS);
  }
}
