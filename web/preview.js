// The preview panel: rendered frames as an animation (play/pause, scrubber), a progress bar while they
// render and load, and the filmstrip.

const PLAYBACK_FPS = 30;

export class PreviewPlayer {
  #frames = [];
  #images = [];
  #index = 0;
  #timer = 0;
  #generation = 0;

  constructor(root) {
    this.img = root.querySelector('#preview');
    this.play = root.querySelector('#play');
    this.scrub = root.querySelector('#scrub');
    this.out = root.querySelector('#frame-out');
    this.progress = root.querySelector('#preview-progress');
    this.filmstrip = root.querySelector('#filmstrip');
    this.play.addEventListener('click', () => (this.#timer ? this.pause() : this.start()));
    this.scrub.addEventListener('input', () => {
      this.pause();
      this.#show(Number(this.scrub.value));
    });
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

  /// A finished preview: frame URLs and the filmstrip URL. Frames are fetched up front so playback is
  /// smooth; the bar counts them in, and the first frame shows as soon as it is there.
  load(urls, filmstripUrl) {
    const generation = ++this.#generation;
    this.pause();
    this.#frames = urls;
    this.#images = urls.map(() => null);
    this.scrub.max = String(Math.max(0, urls.length - 1));
    this.scrub.disabled = urls.length < 2;
    this.play.disabled = urls.length < 2;
    this.progress.max = urls.length;
    this.progress.value = 0;
    this.progress.hidden = false;
    let loaded = 0;
    urls.forEach((url, i) => {
      const image = new Image();
      image.onload = () => {
        if (generation !== this.#generation) return;
        this.#images[i] = image;
        this.progress.value = ++loaded;
        if (i === this.#index) this.#show(i);
        if (loaded === urls.length) this.progress.hidden = true;
      };
      image.src = url;
    });
    this.#index = 0;
    this.#show(0);
    if (filmstripUrl) {
      this.filmstrip.src = filmstripUrl;
      this.filmstrip.hidden = false;
    } else {
      this.filmstrip.hidden = true;
    }
  }

  clear() {
    ++this.#generation;
    this.pause();
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
    if (this.#frames.length < 2 || this.#timer) return;
    this.play.textContent = 'Pause';
    this.play.setAttribute('aria-pressed', 'true');
    this.#timer = setInterval(() => this.#show((this.#index + 1) % this.#frames.length), 1000 / PLAYBACK_FPS);
  }

  pause() {
    clearInterval(this.#timer);
    this.#timer = 0;
    this.play.textContent = 'Play';
    this.play.setAttribute('aria-pressed', 'false');
  }
}
