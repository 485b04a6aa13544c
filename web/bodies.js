// The 2-D constraint's two bodies: one <template> in index.html, stamped out as body A and body B with
// their own control names (a_mass, b_inertia, ...: the URL keys) and the request fields their errors name
// (constraint.body_a.mass, ...). Runs before the page reads its defaults from the form.

/// The page defaults of each body: A static (a wall), B a 2 kg body free to rotate.
const BODIES = {
  a: { label: 'Body A', static: true, mass: '1', inertia: '', x: '0', y: '0', angle: '0' },
  b: { label: 'Body B', static: false, mass: '2', inertia: '0.5', x: '1', y: '0', angle: '0' },
};

export function buildBodies(container, template) {
  for (const [p, d] of Object.entries(BODIES)) {
    const fs = template.content.firstElementChild.cloneNode(true);
    fs.dataset.body = p;
    fs.querySelector('legend').textContent = d.label;
    const check = fs.querySelector('input[data-key="static"]');
    check.name = `${p}_static`;
    check.checked = d.static;
    for (const group of fs.querySelectorAll('.field[data-key]')) {
      group.dataset.field = `constraint.body_${p}.${group.dataset.key}`;
      const inputs = group.querySelectorAll('input');
      const labels = group.querySelectorAll('label');
      inputs.forEach((input, i) => {
        const key = input.dataset.key ?? group.dataset.key;
        input.id = input.name = `${p}_${key}`;
        input.value = d[key];
        labels[i].htmlFor = input.id;
        if (labels[i].classList.contains('sr')) labels[i].textContent = `${d.label} ${key}`;
      });
      group.querySelector('output').htmlFor = [...inputs].map((i) => i.id).join(' ');
    }
    container.append(fs);
  }
}
