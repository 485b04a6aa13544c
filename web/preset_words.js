// Each preset in a designer's words: what they see and what the sliders change, with no solver terms. The
// scene's own `description` (its physics: skins, slops, linearisation) stays one click away, behind the
// preset's "Details" toggle. A preset not listed here (a newer one) shows its description's first sentence.
export const PRESET_WORDS = {
  bridge: 'A rope bridge: ten planks hung from a cable by soft hangers, and a heavy load drops onto the middle. The sliders set how the hangers give and spring back.',
  bridge_deck: 'The bridge without its load. The sliders set how the whole deck heaves, the middle rising and falling in one arc: two swings a second, some bounce.',
  buddhas: 'Identical planks, each hung by one soft spring at a different point along it. The same ask feels different at each point: a spring near the end swings the plank round as well as up and down.',
  chain: 'A heavy weight swinging on a chain of light links, held by rigid pins. The pins stretch a little under the weight; more substeps stretch them less.',
  heavy_on_light: 'A heavy weight hung under a light link by a spring, the link hung from the ceiling by another. The weight drops and bounces.',
  mouse: 'Dragging a crate with the mouse, seen from above. The sliders set how tightly the crate follows the pointer, and how much it overshoots.',
  oscillator: 'One body on a spring and nothing else: the plainest view of how a tuning feels.',
  stiff: 'A very fast spring, 20 swings a second at 60 fps: the plain integrators blow up, the soft constraint stays calm.',
  vehicle: 'A car drops onto the road, settles, then drives into a stack of boxes. The sliders set how the body bobs on its suspension: three bobs a second, some bounce.',
  vehicle_per_spring: 'The same car with each spring tuned on its own, as most tools do: on the road the body then bobs slower than asked.',
};

/// The designer's sentence for preset `name`, or the first sentence of its scene `description`.
export function presetWords(name, description = '') {
  if (PRESET_WORDS[name]) return PRESET_WORDS[name];
  const first = description.match(/^.*?[.!?](\s|$)/);
  return (first ? first[0] : description).trim();
}
