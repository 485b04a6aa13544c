// Beside a scene's preview: its 1-D oscillators (the core integrators a preset runs next to Box2D, such as
// the stiff preset's explicit and semi-implicit Euler springs and the soft constraint), each drawn as a
// block on a spring in its own lane at the preview's scene time, from the simulation's own probe series.
// A lane whose motion has grown past a few amplitudes (or stopped being finite) says "blew up".

/// Past this many starting amplitudes an oscillator is drawn as blown up.
export const BLOWN_AMPLITUDES = 5;

/// The oscillator probes of a simulate answer: [{id, time, value, amplitude}].
export function oscillatorLanes(probes) {
  return (probes ?? []).filter((p) => p.kind === 'oscillator' && Array.isArray(p.series?.time) && p.series.time.length > 1)
    .map((p) => {
      const first = p.series.value.find((v) => typeof v === 'number' && v !== 0) ?? 1;
      return { id: p.id, time: p.series.time, value: p.series.value, amplitude: Math.abs(first) || 1 };
    });
}

/// x of a lane at time t (the last sample at or before t), or null once it has blown up.
export function laneValue(lane, t) {
  let i = 0;
  while (i + 1 < lane.time.length && lane.time[i + 1] <= t) ++i;
  for (let k = 0; k <= i; ++k) {
    const v = lane.value[k];
    if (typeof v !== 'number' || !Number.isFinite(v) || Math.abs(v) > BLOWN_AMPLITUDES * lane.amplitude) return null;
  }
  return lane.value[i];
}

/// Draws every lane at scene time t on the canvas.
export function drawLanes(canvas, lanes, t) {
  const ctx = canvas.getContext('2d');
  const w = canvas.width, laneH = 34;
  canvas.height = Math.max(1, lanes.length) * laneH + 16;
  ctx.clearRect(0, 0, w, canvas.height);
  ctx.font = '12px system-ui, sans-serif';
  const wall = 120, rest = (w - wall) / 2 + wall;
  lanes.forEach((lane, i) => {
    const y = 8 + i * laneH + laneH / 2;
    const x = laneValue(lane, t);
    ctx.fillStyle = '#57606a';
    ctx.fillText(lane.id.replaceAll('_', ' '), 4, y + 4);
    ctx.fillRect(wall - 4, y - 12, 4, 24);
    if (x === null) {
      ctx.fillStyle = '#b42318';
      ctx.fillText('blew up', rest - 20, y + 4);
      canvas.dataset[`lane_${lane.id}`] = 'blew up';
      return;
    }
    const scale = (w - wall - 40) / (4 * lane.amplitude);
    const bx = rest + x * scale;
    // The spring as a zig-zag from the wall to the block.
    ctx.strokeStyle = '#8c959f';
    ctx.beginPath();
    ctx.moveTo(wall, y);
    const turns = 10;
    for (let k = 1; k < turns; ++k) ctx.lineTo(wall + ((bx - 10 - wall) * k) / turns, y + (k % 2 ? -7 : 7));
    ctx.lineTo(bx - 10, y);
    ctx.stroke();
    ctx.fillStyle = lane.id.includes('soft') ? '#1f6feb' : '#bf8700';
    ctx.fillRect(bx - 10, y - 10, 20, 20);
    canvas.dataset[`lane_${lane.id}`] = String(x);
  });
}
