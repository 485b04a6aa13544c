// Talking to softtune's REST API: which routes this server has, JSON calls that turn problem+json
// answers into errors naming the field, and "latest wins" channels so a slow, stale answer never
// overwrites a fresh one.

/// Thrown for any answer that is not 2xx. `unavailable` is true when the server has no such route.
export class ApiError extends Error {
  constructor(status, problem) {
    super(problem?.detail ?? problem?.title ?? `HTTP ${status}`);
    this.status = status;
    this.problem = problem ?? {};
    this.field = problem?.field ?? '';
    this.unavailable = status === 404 || status === 405 || status === 501;
  }
}

let documented = null;
let words = {};

/// The server's OpenAPI document lists exactly the routes it serves (the service tests that), so the page
/// asks for it once and does not call routes this server lacks. Without the document every route is tried
/// and a 404 answer is handled the same way.
export async function loadRoutes() {
  try {
    const r = await fetch('api/v1/openapi.json');
    if (!r.ok) return;
    const doc = await r.json();
    documented = new Set();
    for (const [path, ops] of Object.entries(doc.paths ?? {})) {
      for (const method of Object.keys(ops)) documented.add(`${method.toUpperCase()} ${path}`);
    }
    words = doc.components?.schemas?.TuneRequest?.properties?.oscillation?.['x-damping-ratio'] ?? {};
  } catch {
    documented = null;
  }
}

/// The damping ratio of each oscillation word ({free: 0, some: 0.5, none: 1}) as the server's OpenAPI
/// document gives it (core's designer mapping; tests/http/openapi_test.cpp holds them equal), so the page
/// keeps no copy. Empty without the document: the slider then follows the tune answer's requested ratio.
export function oscillationWords() {
  return words;
}

/// Whether the server documents `method path` (path as in OpenAPI, e.g. /api/v1/presets/{name}).
export function hasRoute(method, path) {
  return documented === null || documented.has(`${method} ${path}`);
}

/// fetch + JSON; non-2xx becomes an ApiError carrying the problem document.
export async function callJson(method, url, body, signal) {
  const init = { method, signal, headers: {} };
  if (body !== undefined) {
    init.body = JSON.stringify(body);
    init.headers['Content-Type'] = 'application/json';
  }
  let r;
  try {
    r = await fetch(url, init);
  } catch (e) {
    if (e?.name === 'AbortError') throw e;
    // No answer at all (server stopped, network down): status 0, shown like any other refusal.
    throw new ApiError(0, { title: 'Cannot reach the softtune server', detail: `Cannot reach the softtune server (${e.message})` });
  }
  const text = await r.text();
  let doc = null;
  try {
    doc = text ? JSON.parse(text) : null;
  } catch {
    doc = null;
  }
  if (!r.ok) throw new ApiError(r.status, doc);
  return doc;
}

/// One kind of request whose newest call alone may deliver: a new call aborts the one in flight, and an
/// answer that arrives after a newer call started is dropped (resolves to `stale`).
export class Latest {
  static stale = Symbol('stale');
  #seq = 0;
  #controller = null;

  async run(fn) {
    const seq = ++this.#seq;
    this.#controller?.abort();
    const controller = new AbortController();
    this.#controller = controller;
    try {
      const value = await fn(controller.signal);
      return seq === this.#seq ? value : Latest.stale;
    } catch (e) {
      if (seq !== this.#seq || e?.name === 'AbortError') return Latest.stale;
      throw e;
    }
  }

  /// Makes the call in flight stale (and aborts it) without starting another: the input it was for was
  /// replaced by input the page refuses.
  cancel() {
    ++this.#seq;
    this.#controller?.abort();
    this.#controller = null;
  }
}
