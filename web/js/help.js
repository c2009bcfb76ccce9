// "How to play" (a rules screen per rule set, from the lobby and the match) and the first-game
// tips (place, aim, power, what a foul costs: one card at a time beside or under the board, each
// step skippable, all of them once per browser unless asked for again). The words are
// how_to_play.js's.

import { controlsHelp, howToPlay, walkthroughSteps } from './how_to_play.js';
import { RULE_SETS } from './protocol.js';

const $ = (id) => document.getElementById(id);
const COACHED_KEY = 'carrom.coached'; // '1' once the tips were seen to the end or skipped

function fillList(ul, lines) {
  ul.replaceChildren(...lines.map((line) => {
    const li = document.createElement('li');
    li.textContent = line;
    return li;
  }));
}

export class Help {
  constructor(storage) {
    this.storage = storage;
    this.sheet = $('rules');
    this.ruleSet = $('rules-set');
    this.ruleSet.replaceChildren(...RULE_SETS.map((r) => new Option(howToPlay(r).title, r)));
    this.ruleSet.addEventListener('change', () => this.fill());
    $('rules-close').addEventListener('click', () => this.show(false));
    $('coach-again').addEventListener('click', () => {
      this.storage?.removeItem(COACHED_KEY);
      this.step = 0;
      this.show(false);
    });
    $('coach-next').addEventListener('click', () => this.next());
    $('coach-skip').addEventListener('click', () => this.finish());
    this.coach = $('coach');
    this.coachText = $('coach-text');
    this.nextButton = $('coach-next');
    this.step = 0;
    fillList($('rules-controls'), controlsHelp());
    this.fill();
  }

  // Opens the rules screen at `ruleSet` (the room's, or the lobby's choice).
  open(ruleSet) {
    if (ruleSet && this.ruleSet.value !== ruleSet) this.ruleSet.value = ruleSet;
    this.fill();
    this.show(true);
  }

  fill() {
    fillList($('rules-text'), howToPlay(this.ruleSet.value).rules);
  }

  show(visible) {
    this.sheet.hidden = !visible;
  }

  coached() {
    return this.storage?.getItem(COACHED_KEY) === '1';
  }

  next() {
    this.step += 1;
    if (this.step >= 4) this.finish();
  }

  finish() {
    this.storage?.setItem(COACHED_KEY, '1');
    this.step = 0;
    this.coach.hidden = true;
  }

  // Each frame: the tips show while we play (a player seat in a room) until seen or skipped.
  update(inMatch, ruleSet) {
    const show = inMatch && !this.coached();
    if (this.coach.hidden === show) this.coach.hidden = !show;
    if (!show) return;
    if (this.stepsFor !== ruleSet) {
      this.steps = walkthroughSteps(ruleSet); // made once per rule set, not every frame
      this.stepsFor = ruleSet;
    }
    const text = this.steps[this.step];
    if (this.coachText.textContent !== text) this.coachText.textContent = text;
    const next = this.step === 3 ? 'Got it' : 'Next';
    if (this.nextButton.textContent !== next) this.nextButton.textContent = next;
  }
}
