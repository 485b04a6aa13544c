// What the page does with a designer's input before any request goes out: input it refuses (an empty or
// non-numeric field) sends nothing and makes every answer still on its way stale; input it accepts opens
// a new generation, and only answers of the newest generation are shown (an answer of an older keystroke
// never clears a refusal or overwrites newer numbers). Typing waits longer than a drag: "60" typed into the
// frame rate is one request for 60 fps, not one for 6 fps first.

/// Wait after a keystroke in a number field (ms): long enough for the next key of a typed number.
export const TYPING_WAIT_MS = 250;
/// Wait after a slider, radio or checkbox moves (ms): short, so the numbers follow a drag at once.
export const GESTURE_WAIT_MS = 30;

/// How long to wait after `event` before asking the server: typing in a text or number field waits for
/// the next key (its change event, a commit such as Enter or leaving the field, sends at once); every other
/// control sends after GESTURE_WAIT_MS.
export function waitFor(event) {
  const t = event?.target;
  const typed = t && (t.type === 'number' || t.type === 'text');
  return typed && event.type === 'input' ? TYPING_WAIT_MS : GESTURE_WAIT_MS;
}

/// The generations of accepted input: `accept()` opens a new one, `refuse()` closes the current one (so
/// no answer in flight belongs to anything shown), `belongs(g)` says whether an answer started in
/// generation `g` may still be shown.
export class InputGenerations {
  #current = 0;
  #refused = false;

  get current() {
    return this.#current;
  }

  get refused() {
    return this.#refused;
  }

  accept() {
    this.#refused = false;
    return ++this.#current;
  }

  refuse() {
    this.#refused = true;
    return ++this.#current;
  }

  belongs(generation) {
    return !this.#refused && generation === this.#current;
  }
}

/// A debounced call whose wait may differ per call (the newest call's wait counts from its own time), and
/// that can be cancelled. `onArm()` runs when a call is first scheduled, `onRelease()` when it has run or
/// was cancelled: the page counts the wait as pending work (body[data-pending]).
export class Debounced {
  #timer = 0;
  #armed = false;

  constructor(fn, { onArm = () => {}, onRelease = () => {}, timers = globalThis } = {}) {
    this.fn = fn;
    this.onArm = onArm;
    this.onRelease = onRelease;
    this.timers = timers;
  }

  get armed() {
    return this.#armed;
  }

  call(ms, ...args) {
    if (!this.#armed) this.onArm();
    this.#armed = true;
    this.timers.clearTimeout(this.#timer);
    this.#timer = this.timers.setTimeout(() => {
      this.#armed = false;
      try {
        this.fn(...args);  // starts its requests (counted) before the wait is released
      } finally {
        this.onRelease();
      }
    }, ms);
  }

  cancel() {
    this.timers.clearTimeout(this.#timer);
    if (!this.#armed) return;
    this.#armed = false;
    this.onRelease();
  }
}
