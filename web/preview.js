// The preview panel: rendered frames as an animation played in real time (each frame held for the scene
// time it stands for, `frame_dt_s` of the answer), or slowed to 0.5x or 0.25x, starting by itself and
// looping, unless the designer paused it; a scrubber, a frame step back and forth, a progress bar while
// frames render and load, and the filmstrip. The frame shown is the page's one time cursor
// (img[data-frame] x data-frame-seconds): the plots' cursors and the live curve's dot follow it, and
// seek() lets a plot move it.

/// Playback speeds offered, as fractions of real time.
export const SPEEDS = [1, 0.5, 0.25];

/// Frames fetched at once while a preview loads: of a browser's six connections to one server, two stay free,
/// so a designer's next change (its tune, its preview and the progress polls) never queues behind a long
/// preview's frames (that queue once held a change's numbers back by 170 ms).
const PRELOAD_AT_ONCE = 4;

export class PreviewPlayer {
  #frames = [];
  #pending = new Set();  // preloading Images not yet in
  #images = [];
  #index = 0;
  #raf = 0;
  #generation = 0;
  #dt = 1 / 30;       // s of scene time per frame
  #startedAt = 0;     // performance.now() at which frame 0 would have shown
  #userPaused = false;
  #speed = 1;

  constructor(root) {
    this.img = root.querySelector('#preview');
    this.play = root.querySelector('#play');
    this.scrub = root.querySelector('#scrub');
    this.out = root.querySelector('#frame-out');
    this.progress = root.querySelector('#preview-progress');
    this.filmstrip = root.querySelector('#filmstrip');
    this.play.addEventListener('click', () => {
      this.#userPaused = this.playing;
      if (this.playing) this.pause();
      else this.start();
    });
    this.scrub.addEventListener('input', () => {
      this.#userPaused = true;
      this.pause();
      this.#show(Number(this.scrub.value));
    });
    this.back = root.querySelector('#frame-back');
    this.forward = root.querySelector('#frame-forward');
    this.speedPick = root.querySelector('#speed');
    this.back?.addEventListener('click', () => this.step(-1));
    this.forward?.addEventListener('click', () => this.step(+1));
    this.speedPick?.addEventListener('change', () => { this.speed = Number(this.speedPick.value); });
  }

  /// The playback speed (a fraction of real time); changing it keeps the frame shown.
  get speed() {
    return this.#speed;
  }

  set speed(v) {
    if (!SPEEDS.includes(v)) return;
    this.#speed = v;
    if (this.speedPick) this.speedPick.value = String(v);
    if (this.#raf) this.#startedAt = performance.now() - (this.#index * this.#dt * 1000) / v;
  }

  /// One frame back (-1) or forward (+1), looping; pauses, as a frame step is for looking closely.
  step(by) {
    if (this.#frames.length < 2) return;
    this.#userPaused = true;
    this.pause();
    const n = this.#frames.length;
    this.#show((((this.#index + by) % n) + n) % n);
  }

  /// Shows the frame nearest scene time `t` (s), paused (a plot's time cursor dragged).
  seek(t) {
    if (this.#frames.length === 0) return;
    this.#userPaused = true;
    this.pause();
    this.#show(Math.max(0, Math.min(this.#frames.length - 1, Math.round(t / this.#dt))));
  }

  get playing() {
    return this.#raf !== 0;
  }

  /// The frame URLs shown now (A/B keeps them when this tuning is pinned).
  get frames() {
    return this.#frames;
  }

  /// Seconds of scene time between frames (for tests and tools).
  get frameSeconds() {
    return this.#dt;
  }

  /// Render progress reported by the server ({done, total} frames), or an indeterminate bar (null).
  rendering(progress) {
    if (progress && progress.total > 0) {
      this.progress.max = progress.total;
      this.progress.value = progress.done;
    } else {
      this.progress.removeAttribute('value');
    }
    this.progress.hidden = false;
  }

  /// Frames stream: the first frame of a preview still rendering, shown as soon as the server has it
  /// (progress.ready >= 1), before the rest are done.
  first(url) {
    this.#stop();
    this.img.src = url;
    this.img.dataset.frame = '0';
    this.out.textContent = 'first frame; the others are rendering';
  }

  /// A finished preview: frame URLs, the filmstrip URL and the seconds between frames. Every frame is
  /// fetched up front so playback is smooth; the first shows as soon as it is there, and playback starts
  /// once all are in (a frame that is not in yet would stall the clock).
  load(urls, filmstripUrl, frameSeconds) {
    this.supersede();
    const generation = this.#generation;
    this.#stop();
    this.#frames = urls;
    this.#images = urls.map(() => null);
    this.#dt = frameSeconds > 0 ? frameSeconds : 1 / 30;
    this.scrub.max = String(Math.max(0, urls.length - 1));
    this.scrub.disabled = urls.length < 2;
    this.play.disabled = urls.length < 2;
    for (const b of [this.back, this.forward]) if (b) b.disabled = urls.length < 2;
    this.progress.max = urls.length;
    this.progress.value = 0;
    this.progress.hidden = false;
    this.img.dataset.frameSeconds = String(this.#dt);
    let loaded = 0, next = 0;
    const fetchNext = () => {
      if (generation !== this.#generation || next >= urls.length) return;
      const i = next++;
      const image = new Image();
      this.#pending.add(image);
      image.onload = () => {
        this.#pending.delete(image);
        if (generation !== this.#generation) return;
        this.#images[i] = image;
        this.progress.value = ++loaded;
        if (i === this.#index) this.#show(i);
        if (loaded === urls.length) {
          this.progress.hidden = true;
          if (!this.#userPaused) this.start();
        }
        fetchNext();
      };
      image.onerror = () => {
        this.#pending.delete(image);
        fetchNext();
      };
      image.src = urls[i];
    };
    for (let k = 0; k < PRELOAD_AT_ONCE; ++k) fetchNext();
    this.#index = 0;
    this.#show(0);
    if (filmstripUrl) {
      this.filmstrip.src = filmstripUrl;
      this.filmstrip.hidden = false;
    } else {
      this.filmstrip.hidden = true;
    }
  }

  /// A newer preview is on its way: the frames of this one still loading are dropped (what shows stays).
  supersede() {
    ++this.#generation;
    for (const image of this.#pending) image.src = '';  // aborts the request
    this.#pending.clear();
  }

  clear() {
    this.supersede();
    this.#stop();
    this.#frames = [];
    this.img.removeAttribute('src');
    this.filmstrip.hidden = true;
    this.progress.hidden = true;
    this.scrub.disabled = true;
    this.play.disabled = true;
    this.out.textContent = '';
  }

  #show(i) {
    if (!this.#frames.length) return;
    this.#index = i;
    this.scrub.value = String(i);
    this.out.textContent = `${i + 1} / ${this.#frames.length}`;
    this.img.src = this.#frames[i];
    this.img.dataset.frame = String(i);
  }

  start() {
    if (this.#frames.length < 2 || this.#raf) return;
    this.play.textContent = 'Pause';
    this.play.setAttribute('aria-pressed', 'true');
    this.#startedAt = performance.now() - (this.#index * this.#dt * 1000) / this.#speed;
    const tick = (now) => {
      // The frame of this moment in scene time, looping: real time (times the speed) whatever the display's
      // refresh rate. (rAF's timestamp may precede the start by a fraction of a frame: never a negative index.)
      const n = Math.max(0, Math.floor(((now - this.#startedAt) * this.#speed) / (this.#dt * 1000))) % this.#frames.length;
      if (n !== this.#index) this.#show(n);
      this.#raf = requestAnimationFrame(tick);
    };
    this.#raf = requestAnimationFrame(tick);
  }

  pause() {
    this.#stop();
  }

  #stop() {
    cancelAnimationFrame(this.#raf);
    this.#raf = 0;
    this.play.textContent = 'Play';
    this.play.setAttribute('aria-pressed', 'false');
  }
}
