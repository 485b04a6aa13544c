// The long-lived scene worker: one node process that the C++ client (node_worker.cpp) starts once and reuses
// for every scene run in a JavaScript engine (Jolt, Rapier as WebAssembly). It reads one JSON request per
// line on stdin and writes one JSON answer per line on stdout, in order (docs/scene-backends.md, "The node
// worker"). Each engine module (engines/<engine>/<engine>_scene.mjs) is imported on its first build and its
// WebAssembly initialised once; worlds are kept by id until destroyed.
//
//   -> {"op":"build","engine":"jolt"|"rapier","settings":{...},"world":{...},"bodies":[...],"joints":[...]}
//   <- {"ok":true,"world":N} | {"ok":false,"field":"joints.2.type","message":"rapier has no ..."}
//   -> {"op":"step","world":N,"frame":f}            <- {"bodies":[[ox,oy,cx,cy,angle,vx,vy,w],...]}
//   -> {"op":"run","world":N,"frame":f,"frames":n}  <- {"frames":[bodies after frame f, ..., after f+n-1]}
//   -> {"op":"contacts","world":N}                  <- {"contacts":[[px,py,nx,ny],...]}
//   -> {"op":"destroy","world":N}                   <- {"ok":true}
//   -> {"op":"ping"}                                <- {"ok":true,"pid":P,"worlds":W}
// Any other failure answers {"ok":false,"message":"..."}.
import { createInterface } from 'node:readline';

// stdout carries the protocol only: whatever an engine prints goes to stderr.
console.log = console.error;
console.info = console.error;
console.warn = console.error;

const kModules = {
  jolt: new URL('../jolt/jolt_scene.mjs', import.meta.url),
  rapier: new URL('../rapier/rapier_scene.mjs', import.meta.url),
};
const loaded = new Map();  // engine name -> Promise of its initialised module
const worlds = new Map();  // world id -> world object
let nextWorld = 1;

function engineModule(name) {
  if (!Object.hasOwn(kModules, name)) {
    return Promise.reject({ field: 'engine', message: `the node worker has no engine "${name}" (jolt, rapier)` });
  }
  if (!loaded.has(name)) {
    const promise = import(kModules[name].href).then(async (module) => {
      await module.init();
      return module;
    }, (e) => {
      throw { field: 'engine', message: `${name}: the scene module ${kModules[name].pathname} cannot be loaded: ${e.message ?? e}` };
    });
    promise.catch(() => loaded.delete(name));  // a module that failed may be installed later
    loaded.set(name, promise);
  }
  return loaded.get(name);
}

function worldOf(request) {
  const world = worlds.get(request.world);
  if (!world) throw new Error(`no world ${request.world}`);
  return world;
}

async function answer(request) {
  switch (request.op) {
    case 'build': {
      const module = await engineModule(request.engine);
      const world = module.build(request);
      const id = nextWorld++;
      worlds.set(id, world);
      return { ok: true, world: id };
    }
    case 'step': {
      const world = worldOf(request);
      world.step(request.frame);
      return { bodies: world.bodies() };
    }
    case 'run': {
      const world = worldOf(request);
      const frames = [];
      for (let i = 0; i < request.frames; ++i) {
        world.step(request.frame + i);
        frames.push(world.bodies());
      }
      return { frames };
    }
    case 'contacts':
      return { contacts: worldOf(request).contacts() };
    case 'destroy': {
      const world = worldOf(request);
      worlds.delete(request.world);
      world.destroy();
      return { ok: true };
    }
    case 'ping':
      return { ok: true, pid: process.pid, worlds: worlds.size };
    default:
      throw new Error(`unknown op "${request.op}"`);
  }
}

function failure(e) {
  if (e && typeof e === 'object' && typeof e.field === 'string') return { ok: false, field: e.field, message: String(e.message) };
  return { ok: false, message: String(e?.message ?? e) };
}

const lines = createInterface({ input: process.stdin, crlfDelay: Infinity });
for await (const line of lines) {
  if (!line.trim()) continue;
  let reply;
  try {
    reply = await answer(JSON.parse(line));
  } catch (e) {
    reply = failure(e);
  }
  // A non-finite number has no JSON form: null tells the client the state blew up.
  process.stdout.write(JSON.stringify(reply) + '\n');
}
