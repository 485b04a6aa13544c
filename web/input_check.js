// Input handled in the page: a number field left empty or holding text that is not a number is named at
// the field in plain words, and no request goes out with a value the designer did not type (the server
// would fill in its default and the page would read "Up to date"). Problems the API finds (a range, a
// rule) are put at their field in the same words: the API's field names become the controls' names.

/// The controls whose emptiness means "use no value": a body's inertia (empty: it does not rotate).
const OPTIONAL = new Set(['a_inertia', 'b_inertia']);

/// A control's name as the designer reads it: its label without the unit in parentheses.
export function controlName(el) {
  const label = el.labels?.[0]?.textContent ?? el.getAttribute('aria-label') ?? el.name;
  const plain = label.replace(/\s*\(.*$/s, '').replace(/:.*$/s, '').trim();
  return plain ? plain[0].toUpperCase() + plain.slice(1) : el.name;
}

/// [{el, message}] for each number field in use (not hidden, not disabled) that is empty or not a number.
export function inputProblems(form) {
  const problems = [];
  for (const el of form.querySelectorAll('input[type="number"]')) {
    if (!el.name || el.disabled || el.closest('[hidden]')) continue;
    const name = controlName(el);
    if (el.validity.badInput) problems.push({ el, message: `${name} is not a number: type digits, e.g. ${el.defaultValue || '1'}` });
    else if (el.value.trim() === '' && !OPTIONAL.has(el.name)) problems.push({ el, message: `${name} is empty: type a number, e.g. ${el.defaultValue || '1'}` });
  }
  return problems;
}

/// The API's request field names in a problem's detail, as the page's controls call them.
const FIELD_WORDS = {
  effective_mass: 'the effective mass', constraint: 'a 2-D constraint', response_frames: 'the response speed',
  basis_fps: 'the basis fps', frequency_hz: 'the frequency', damping_ratio: 'the damping ratio',
  oscillation: 'the oscillation', substeps: 'the substeps', fps: 'the frame rate', mode: 'the mode',
};

/// Words that make what follows them prose, not a field name: "no mode of the scene" keeps its "mode",
/// while "one of effective_mass or constraint" names two fields.
const DETERMINERS = ['the', 'a', 'an', 'no', 'each', 'every', 'its', 'this', 'that', 'any', 'which', 'one'];

/// A field name standing alone: a whole word, not after a determiner, not part of a dotted path
/// ("modal_tuning.targets.0.mode" is left whole).
function fieldPattern(field) {
  return new RegExp(`(?<!\\b(?:${DETERMINERS.join('|')})\\s)(?<![.\\w])${field}(?![.\\w])`, 'gi');
}

/// A problem's detail in a designer's words: "give exactly one of effective_mass or constraint" reads
/// "give exactly one of the effective mass or a 2-D constraint"; a detail starting with "must" gets the
/// control's name in front ("Frame rate must be > 0").
export function designerMessage(detail, label) {
  let text = String(detail ?? '');
  for (const [field, words] of Object.entries(FIELD_WORDS)) text = text.replace(fieldPattern(field), words);
  if (label && /^(must|is|has|needs)\b/.test(text)) text = `${label} ${text}`;
  return text ? text[0].toUpperCase() + text.slice(1) : text;
}
