// lib.js — shared helpers of the labs: DOM building (no innerHTML; null and
// undefined children are skipped everywhere, never shown as text), the API call
// (with the session's access token, cancellable), problem+json errors placed
// next to the field they name, the busy/cancel state of a running request, the
// curl command, the notes' worked examples, and small SVG plotting sized to the
// element so plot text reads at its nominal px size on a phone.

import './vendor/d3-7.9.0/d3.min.js'; // d3 (UMD) sets globalThis.d3: ticks, nice, formats
const d3 = globalThis.d3;

export const SVGNS = 'http://www.w3.org/2000/svg';

// The nodes for a list of children: arrays flattened; null, undefined and false
// skipped (a conditional child `cond ? node : null` leaves nothing, never the
// text "null"); anything else not a Node becomes a text node.
export function nodes(kids) {
  const out = [];
  for (const kid of kids.flat(Infinity))
    if (kid !== null && kid !== undefined && kid !== false)
      out.push(kid instanceof Node ? kid : document.createTextNode(String(kid)));
  return out;
}
// parent.replaceChildren / parent.append through nodes(): use these, never the
// DOM methods directly (they turn null into the text "null").
export function put(parent, ...kids) { parent.replaceChildren(...nodes(kids)); return parent; }
export function add(parent, ...kids) { parent.append(...nodes(kids)); return parent; }

// el('div', {class: 'x', onclick: f}, child, 'text', …)
export function el(tag, attrs = {}, ...kids) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) {
    if (v === undefined || v === null || v === false) continue;
    if (k.startsWith('on')) e.addEventListener(k.slice(2), v);
    else if (k === 'text') e.textContent = v;
    else e.setAttribute(k, v === true ? '' : v);
  }
  e.append(...nodes(kids));
  return e;
}

export function svg(tag, attrs = {}, text) {
  const e = document.createElementNS(SVGNS, tag);
  for (const [k, v] of Object.entries(attrs)) if (v !== undefined && v !== null) e.setAttribute(k, v);
  if (text !== undefined && text !== null) e.textContent = text;
  return e;
}

// A number in 7 significant figures (the full value stays in data-value). A
// value the API could not give (null: JSON has no infinity or NaN) reads "—".
export function fmt(x, sig = 7) {
  if (x === Infinity) return '∞';
  if (x === -Infinity) return '−∞';
  if (typeof x !== 'number' || Number.isNaN(x)) return typeof x === 'string' ? x : '—';
  if (x === 0) return '0';
  const a = Math.abs(x);
  return a >= 1e-4 && a < 1e7 ? String(Number(x.toPrecision(sig))) : x.toExponential(sig - 1);
}

// A <dd> with a number and its unit; a missing value (null, NaN) reads "—"
// without the unit, titled "not available".
export function num(id, x, unit = '') {
  const ok = typeof x === 'number' && !Number.isNaN(x);
  return el('dd', {id, 'data-value': String(x), title: ok ? undefined : 'not available'},
    fmt(x) + (ok && unit ? ' ' + unit : ''));
}

let uid = 0;
// A labelled number (or text/select) control; pointer = the JSON pointer it fills
// (several, separated by spaces, when one control fills more than one place).
export function field({label, pointer, value, unit, step = 'any', min, max, type = 'number',
                       options, id, cls, help, budget}) {
  id = id || 'f' + (++uid);
  const errId = id + '-err';
  let input;
  if (options) {
    input = el('select', {id, 'data-pointer': pointer, 'aria-describedby': errId},
      options.map(o => el('option', {value: o[0], selected: String(o[0]) === String(value)}, o[1])));
  } else {
    input = el('input', {id, type, value, step: type === 'number' || type === 'range' ? step : undefined,
      min, max, class: cls, 'data-pointer': pointer, 'aria-describedby': errId, 'data-budget': budget,
      inputmode: type === 'number' ? 'decimal' : undefined});
  }
  const wrap = el('div', {class: 'field'}, el('label', {for: id}, label), input,
    unit ? el('span', {class: 'unit'}, unit) : null,
    help ? el('span', {class: 'muted'}, help) : null,
    el('div', {class: 'err', id: errId, role: 'alert'}));
  return {wrap, input};
}

export const val = (input) => input.type === 'number' || input.type === 'range'
  ? (input.value.trim() === '' ? NaN : Number(input.value)) : input.value;

// JSON for a body: NaN (an empty field) becomes null so the server names it.
export const toJSON = (body) => JSON.stringify(body, (k, v) =>
  typeof v === 'number' && !isFinite(v) ? null : v);

// The access token of a server started with --token-file: kept for this tab's
// session only (sessionStorage, never localStorage), sent as
// "Authorization: Bearer TOKEN" on every /v1 request (server/http.c token_ok).
const TOKEN_KEY = 'mechd-token';
export function getToken() {
  try { return sessionStorage.getItem(TOKEN_KEY) || ''; } catch (e) { return ''; }
}
export function setToken(t) {
  try { if (t) sessionStorage.setItem(TOKEN_KEY, t); else sessionStorage.removeItem(TOKEN_KEY); } catch (e) { /* private mode */ }
  examplesPromise = null; // fetch the examples again with the new token
}

// POST body (or GET when body is undefined) to path. Never throws: answers
// {ok, status, body}; {aborted: true} when signal aborts it (the server's
// hang-up watcher then cancels the work); status 0 on a network error. A 401
// also fires "mechd:unauthorized" on window (app.js offers the token field).
export async function api(path, body, {signal} = {}) {
  const headers = {};
  if (body !== undefined) headers['Content-Type'] = 'application/json';
  const token = getToken();
  if (token) headers.Authorization = 'Bearer ' + token;
  const init = {method: body === undefined ? 'GET' : 'POST', headers, signal,
    body: body === undefined ? undefined : toJSON(body)};
  let res;
  try { res = await fetch(path, init); } catch (e) {
    if (e && e.name === 'AbortError') return {ok: false, aborted: true, status: 0, body: null};
    return {ok: false, status: 0, body: {title: 'Network error', detail: String(e)}};
  }
  let json = null;
  try { json = await res.json(); } catch (e) {
    if (e && e.name === 'AbortError') return {ok: false, aborted: true, status: 0, body: null};
    json = {title: 'Not JSON', detail: String(e)};
  }
  if (res.status === 401)
    window.dispatchEvent(new CustomEvent('mechd:unauthorized', {detail: {hadToken: !!token, problem: json}}));
  return {ok: res.ok, status: res.status, body: json};
}

// The request as a curl command; with a token in use, the header names the
// shell variable $MECHD_TOKEN instead of showing the secret (projectors).
export function curlCommand(path, body) {
  const q = (s) => "'" + s.replace(/'/g, "'\\''") + "'";
  const auth = getToken() ? ' -H "Authorization: Bearer $MECHD_TOKEN"' : '';
  return body === undefined ? `curl -s${auth} ${q(location.origin + path)}`
    : `curl -s${auth} --json ${q(toJSON(body))} ${q(location.origin + path)}`;
}

// The request as a call of the Python client (clients/python/mechd.py): the
// method generated for the operation (/v1/rigid/inertia -> m.rigid_inertia,
// its fields as keyword arguments), Client.batch for /v1/batch (each answer, or
// the error of that item), Client.call for a GET. The client reads the token
// from $MECHD_TOKEN: with a token in use the line says so, never the token.
const PY_KEYWORDS = new Set(['False', 'None', 'True', 'and', 'as', 'assert', 'async', 'await', 'break', 'class', 'continue',
  'def', 'del', 'elif', 'else', 'except', 'finally', 'for', 'from', 'global', 'if', 'import', 'in', 'is', 'lambda',
  'nonlocal', 'not', 'or', 'pass', 'raise', 'return', 'try', 'while', 'with', 'yield', 'body']);
export const pyMethod = (path) => path.replace(/^\/v1\//, '').replace(/[/-]/g, '_'); // mechd.py method_name()
export function pythonCommand(path, body) {
  const py = (v, ind) => {
    if (v === null || v === undefined) return 'None';
    if (v === true) return 'True';
    if (v === false) return 'False';
    if (typeof v === 'number') return Number.isFinite(v) ? String(v) : 'None';
    if (typeof v === 'string') return JSON.stringify(v);
    const pad = ind + '    ';
    if (Array.isArray(v)) {
      const flat = '[' + v.map(x => py(x, pad)).join(', ') + ']';
      return flat.length <= 72 ? flat : '[\n' + v.map(x => pad + py(x, pad)).join(',\n') + ',\n' + ind + ']';
    }
    const items = Object.entries(v).filter(([, x]) => x !== undefined).map(([k, x]) => JSON.stringify(k) + ': ' + py(x, pad));
    const flat = '{' + items.join(', ') + '}';
    return flat.length <= 72 ? flat : '{\n' + items.map(x => pad + x).join(',\n') + ',\n' + ind + '}';
  };
  const head = 'import mechd  # clients/python/mechd.py (pip install ./clients/python)\n' +
    `m = mechd.Client(${JSON.stringify(location.origin)})` +
    (getToken() ? '  # this server wants a token: export MECHD_TOKEN=… first (the client reads it)' : '') + '\n';
  if (body === undefined) return head + `answer = m.call(${JSON.stringify(path)})\n`;
  const b = JSON.parse(toJSON(body));
  if (path === '/v1/batch' && b && Array.isArray(b.operations) && Object.keys(b).every(k => k === 'operations'))
    return head + '# each answer, or the mechd error of that item\nanswers = m.batch([\n' +
      b.operations.map(o => `    (${JSON.stringify(o.operation)}, ${py(o.request, '    ')}),\n`).join('') + '])\n';
  const keys = Object.keys(b || {});
  const named = keys.length > 0 && keys.every(k => /^[A-Za-z_][A-Za-z0-9_]*$/.test(k) && !PY_KEYWORDS.has(k));
  if (!named) return head + `answer = m.${pyMethod(path)}(${py(b, '')})\n`;
  const args = keys.map(k => `${k}=${py(b[k], '    ')}`);
  const flat = `answer = m.${pyMethod(path)}(${args.join(', ')})\n`;
  return head + (flat.length <= 80 ? flat : `answer = m.${pyMethod(path)}(\n${args.map(a => '    ' + a + ',\n').join('')})\n`);
}

// A copy button for the text of pre (falls back to selecting it).
function copyButton(pre, name) {
  const btn = el('button', {type: 'button', class: 'secondary', 'data-copy': name.toLowerCase(), onclick: async () => {
    try { await navigator.clipboard.writeText(pre.textContent); btn.textContent = 'Copied'; }
    catch (e) { const r = document.createRange(); r.selectNodeContents(pre);
      getSelection().removeAllRanges(); getSelection().addRange(r); btn.textContent = 'Selected: press Ctrl+C'; }
    setTimeout(() => { btn.textContent = 'Copy as ' + name; }, 2000);
  }}, 'Copy as ' + name);
  return btn;
}

// The copyable request box: the curl line, and the same call from Python
// (folded away until asked for); update(path, body).
export function curlBox() {
  const pre = el('pre', {tabindex: 0, 'aria-label': 'curl command'});
  const pyPre = el('pre', {tabindex: 0, 'aria-label': 'Python call', 'data-role': 'python'});
  const box = el('section', {class: 'curl'}, el('h3', {}, 'The request'), pre, copyButton(pre, 'curl'),
    el('details', {class: 'python'}, el('summary', {}, 'As Python'), pyPre, copyButton(pyPre, 'Python')));
  return {box, update: (path, body) => { pre.textContent = curlCommand(path, body); pyPre.textContent = pythonCommand(path, body); }};
}

// --- problems in a student's words ------------------------------------------
// A number as a reader writes it, from the server's 17-digit echo: the shortest
// form that reads back as the same double ("1.0000000000000001e+300" -> 10³⁰⁰,
// "148.84600000000001" -> 148.846), large and small ones as m·10ⁿ, thousands
// grouped (100,000).
export function shortNum(x) {
  if (typeof x === 'string') x = Number(x);
  if (typeof x !== 'number' || !Number.isFinite(x)) return String(x);
  const s = String(x); // JavaScript's shortest round-trip form
  const m = /^(-?[\d.]+)e([+-]\d+)$/.exec(s);
  if (m) return (m[1] === '1' ? '' : m[1] === '-1' ? '−' : m[1].replace('-', '−') + '·') + pow10(Number(m[2]));
  if (Math.abs(x) >= 1e4 && Number.isInteger(x)) return x.toLocaleString('en-US').replace('-', '−');
  return s.replace('-', '−');
}
// every number in a text in its shortest form
const NUMBER = /-?\d+(?:\.\d+)?(?:e[+-]?\d+)?/gi;
export const shortNumbers = (text) => String(text).replace(NUMBER, (t) => /^-?\d{1,4}$/.test(t) ? t : shortNum(t));

// The field's name and unit as the page shows them (its <label>, its unit span).
function fieldWords(c) {
  const lab = c && c.id ? document.querySelector(`label[for="${c.id}"]`) : null;
  const wrap = c && c.closest('.field');
  const unit = wrap && wrap.querySelector('.unit');
  return {label: lab ? lab.textContent.trim() : (c && c.getAttribute('aria-label')) || 'this value',
    unit: unit ? unit.textContent.trim() : '', min: c && c.getAttribute('min'), max: c && c.getAttribute('max')};
}
const withUnit = (v, unit) => unit ? `${v} ${unit}`.replace(/ °$/, '°') : v;
// The allowed range of a control, in words, from its min and max (or the schema's bound in a message).
function rangeWords(w) {
  const lo = w.min !== null && w.min !== '' ? shortNum(w.min) : null, hi = w.max !== null && w.max !== '' ? shortNum(w.max) : null;
  if (lo !== null && hi !== null) return `between ${withUnit(lo, w.unit)} and ${withUnit(hi, w.unit)}`;
  if (lo !== null) return `at least ${withUnit(lo, w.unit)}`;
  if (hi !== null) return `at most ${withUnit(hi, w.unit)}`;
  return '';
}

// One error's detail in physics words for the control it lands on (c may be
// null): bounds with the allowed range, an empty field, a name not in a list
// (the list wraps: it is a <ul> of names, not one long line), the integrator's
// words (a step size that cannot shrink, a right-hand side that failed),
// numbers in shortest form. Returns an array of nodes.
export function plainDetail(detail, c, value) {
  const d = String(detail || '');
  const w = fieldWords(c);
  let m;
  if ((m = /^must be (>=|>|<=|<) (\S+), got (\S+)$/.exec(d))) {
    const bound = shortNum(m[2]), got = shortNum(m[3]);
    // the range: the control's own min and max, the message's bound in place of the side it names
    const range = rangeWords({...w, ...(m[1] === '>=' ? {min: m[2]} : m[1] === '<=' ? {max: m[2]} : {})});
    const rule = {'>=': `at least ${withUnit(bound, w.unit)}`, '>': `more than ${withUnit(bound, w.unit)}`,
      '<=': `at most ${withUnit(bound, w.unit)}`, '<': `less than ${withUnit(bound, w.unit)}`}[m[1]];
    return [`${w.label} is ${withUnit(got, w.unit)}: it must be ${range && (m[1] === '>=' || m[1] === '<=') ? range : rule}.`];
  }
  if ((m = /^must be an? (number|integer|string|object|array)[^,]*, got (null|\S+)$/.exec(d))) {
    const range = rangeWords(w);
    if (m[2] === 'null') return [`${w.label} is empty: enter a${m[1] === 'integer' ? ' whole' : ''} number${range ? ' ' + range : ''}.`];
    return [`${w.label}: enter a${m[1] === 'integer' ? ' whole' : ''} ${m[1] === 'integer' ? 'number' : m[1]}${range ? ' ' + range : ''}.`];
  }
  if ((m = /^must be one of \[(.*)/.exec(d))) {
    const names = [...m[1].matchAll(/"((?:[^"\\]|\\.)*)"/g)].map(x => x[1]);
    const given = typeof value === 'string' && value ? `“${value}”` : 'That';
    return [`${given} is not a name this server knows for ${w.label.toLowerCase()}. Known names: `,
      el('ul', {class: 'names'}, names.map(n => el('li', {}, n)))];
  }
  if ((m = /(\w+): cannot reach the requested tolerance at t = (\S+) s \(step size (\S+) s/.exec(d)))
    return [`The motion could not be followed past t = ${amount(Number(m[2]), 's')}: to keep the accuracy asked for, the time step ` +
      `had to shrink to ${amount(Number(m[3]), 's')}, which a computer's numbers cannot resolve. Something happens there too fast to ` +
      'follow (a collision, a body falling into the centre, a force without bound). Try other starting values, a lower accuracy or a shorter time.'];
  if ((m = /(\w+): (?:the right-hand side failed|bad function value) at t = (\S+) s/.exec(d)))
    return [`The equations of motion could not be evaluated at t = ${amount(Number(m[2]), 's')} (the bodies reach a point where a force is ` +
      'infinite or undefined). Try other starting values or a shorter time.'];
  if (/^is required$/.test(d)) return [`${w.label} is needed.`];
  return [shortNumbers(d)];
}

// A compute budget or deadline problem on the control that sets the run's
// length (data-budget on it: "swings", "orbits", …): "100,000 swings is more than
// this server runs at once (at most about 54,000); try fewer."
function budgetDetail(prob, c) {
  const what = c.dataset.budget, v = Number(c.value);
  const m = /^(\d+) steps needed, the step budget is (\d+)/.exec((prob && prob.detail) || '');
  const frac = m ? Number(m[2]) / Number(m[1]) : prob && prob.progress && prob.progress.fraction_done;
  const most = Number.isFinite(v) && frac > 0 && frac < 1 ? Number((v * frac).toPrecision(2)) : null;
  const too = prob.type === '/problems/deadline-exceeded' ? 'takes longer than this server allows one request' : 'is more than this server runs at once';
  const k = most ? 10 ** Math.max(0, Math.floor(Math.log10(most)) - 1) : 1; // two figures, rounded down
  return `${shortNum(v)} ${what} ${too}${most ? ` (at most about ${shortNum(Math.floor(most / k) * k)})` : ''}; try fewer` +
    (c.form && c.form.querySelector('[data-role=accuracy]') ? ', or a lower accuracy.' : '.');
}

// Clear every field error of a form and the general problem box.
export function clearErrors(form, problemBox) {
  for (const c of form.querySelectorAll('[data-pointer]')) c.removeAttribute('aria-invalid');
  for (const e of form.querySelectorAll('.err')) put(e);
  put(problemBox);
}

// Place a problem+json next to the fields its errors[].pointer name: the control
// whose data-pointer equals the pointer or is its longest prefix, else the first
// control below it; a compute budget or deadline with no pointer goes to the
// control marked data-budget; whatever cannot be placed goes to the problem box.
// Every message is put in physics words (plainDetail); focus moves to the first
// marked control.
export function showProblem(form, problemBox, status, prob) {
  clearErrors(form, problemBox);
  const controls = [...form.querySelectorAll('[data-pointer]')];
  const left = [];
  let errors = Array.isArray(prob && prob.errors) ? prob.errors : [];
  const budgetCtl = form.querySelector('[data-budget]');
  const budget = prob && (prob.type === '/problems/compute-budget-exceeded' || prob.type === '/problems/deadline-exceeded');
  let first = null;
  const mark = (c, nodesOf) => {
    c.setAttribute('aria-invalid', 'true');
    const box = document.getElementById((c.getAttribute('aria-describedby') || '').split(' ')[0]);
    if (box) {
      const ns = nodesOf();
      const text = ns.map(n => typeof n === 'string' ? n : n.textContent).join('');
      if (!box.textContent.includes(text)) add(box, box.textContent ? ' ' : null, ns); // one control may fill several places: once
    }
    first = first || c;
  };
  if (budget && budgetCtl && !errors.some(e => e.pointer)) { mark(budgetCtl, () => [budgetDetail(prob, budgetCtl)]); errors = []; }
  for (const e of errors) {
    const p = e.pointer || '';
    let best = null;
    let bestLen = -1;
    for (const c of controls) for (const cp of c.dataset.pointer.split(' ')) // a control may fill several places
      if ((p === cp || p.startsWith(cp + '/')) && cp.length > bestLen) { best = c; bestLen = cp.length; }
    if (!best && p) best = controls.find(c => c.dataset.pointer.split(' ').some(cp => cp.startsWith(p + '/'))) || null;
    if (!best) { left.push(e); continue; }
    mark(best, () => plainDetail(e.detail, best, best.value));
  }
  const head = status === 422 && first ? 'Not computed' : `${status} ${prob && prob.title ? prob.title : 'Error'}`;
  const hint = status === 401 ? el('p', {}, 'This server needs an access token: ',
    el('button', {type: 'button', class: 'secondary', onclick: () => window.dispatchEvent(new CustomEvent('mechd:token-open'))},
      'Enter the access token')) : null;
  if (!first && (left.length || !errors.length))
    add(problemBox, el('strong', {}, head + ': '), plainDetail((prob && prob.detail) || '', null),
      left.length ? el('ul', {}, left.map(e => el('li', {}, plainDetail(e.detail, null)))) : null, hint);
  else if (left.length)
    add(problemBox, el('ul', {}, left.map(e => el('li', {}, plainDetail(e.detail, null)))));
  else add(problemBox, el('span', {class: 'muted'}, head + ' — see the marked field' + (form.querySelectorAll('[aria-invalid=true]').length > 1 ? 's' : '') + '.'));
  if (first) first.focus();
}

// The previous answer while an error stands: the column of results, picture
// and notes dimmed, with "Not updated" over it, so nobody reads it as the
// answer to the inputs now in the form. staleMark(S, false) takes it away.
export function staleMark(S, on) {
  const col = S.results.parentElement;
  col.classList.toggle('stale', on);
  const old = col.querySelector(':scope > [data-role=not-updated]');
  if (old) old.remove();
  if (on && S.results.childElementCount)
    col.prepend(el('p', {class: 'not-updated', 'data-role': 'not-updated'},
      'Not updated: the answer and picture below are for the previous inputs, not for what is in the form now.'));
  S.form.dataset.stale = on ? 'true' : 'false';
}

let examplesPromise = null;
// GET /v1/examples ({examples: [{id, title, section, operation, request, notes_answer}]}),
// or [] when the server has none (a failure is not kept: the next call asks again).
export function examples() {
  if (!examplesPromise) {
    const p = api('/v1/examples').then(r => {
      if (!(r.ok && r.body && Array.isArray(r.body.examples))) { if (examplesPromise === p) examplesPromise = null; return []; }
      return r.body.examples;
    });
    examplesPromise = p;
  }
  return examplesPromise;
}

// A request as canonical JSON (keys sorted, "cost" left out): two examples
// asking the same thing compare equal.
function canon(v) {
  if (Array.isArray(v)) return '[' + v.map(canon).join(',') + ']';
  if (v && typeof v === 'object')
    return '{' + Object.keys(v).filter(k => k !== 'cost').sort().map(k => JSON.stringify(k) + ':' + canon(v[k])).join(',') + '}';
  return JSON.stringify(v);
}
const exKey = (ex) => ex.id || ex.title;

// The "worked examples" picker: the server's examples for these operations
// (those fits(example) accepts: the ones the lab's forms can hold) plus the
// lab's built-in ones not already among them, grouped by the notes' section.
// onLoad(example) fills the form and runs it. The picker keeps showing the
// example last loaded — `selected` (an example's id or title) on a fresh mount,
// by default the first built-in one, which the lab's form starts with; a
// built-in example the server also lists is shown as the server's. The notes'
// answer of the loaded example, when it has one, is shown under the picker.
export function examplePicker(operations, builtin, onLoad, {selected, fits = () => true} = {}) {
  const id = 'ex' + (++uid);
  const select = el('select', {id, 'data-role': 'examples'});
  const answer = el('p', {class: 'notes-answer muted', 'aria-live': 'polite'});
  let list = builtin.slice();
  let current = selected || (builtin[0] && exKey(builtin[0]));
  const showAnswer = () => {
    const ex = list.find(e => exKey(e) === current);
    const t = ex && ex.notes_answer && ex.notes_answer.text;
    put(answer, t ? [el('strong', {}, 'The notes: '), t] : null);
  };
  const wrap = el('div', {class: 'examples'}, el('label', {for: id}, 'Worked example'), select,
    el('button', {type: 'button', class: 'secondary', onclick: () => {
      const ex = list[Number(select.value)];
      if (!ex) return;
      current = exKey(ex); showAnswer();
      onLoad(ex);
    }}, 'Load'), answer);
  const render = () => {
    const groups = new Map();
    list.forEach((ex, i) => {
      const g = ex.section ? '§' + ex.section : 'More examples';
      if (!groups.has(g)) groups.set(g, []);
      groups.get(g).push(el('option', {value: i, selected: exKey(ex) === current}, ex.title));
    });
    put(select, [...groups].map(([g, opts]) => el('optgroup', {label: g}, opts)));
    showAnswer();
  };
  render();
  examples().then(server => {
    const mine = server.filter(ex => operations.includes(ex.operation) && fits(ex));
    if (!mine.length) return;
    const same = (b) => mine.find(m => m.operation === b.operation && canon(m.request) === canon(b.request));
    const cur = builtin.find(b => exKey(b) === current);
    if (cur && same(cur)) current = exKey(same(cur));
    list = mine.concat(builtin.filter(b => !same(b) && !mine.some(m => m.title === b.title)));
    render();
  });
  return wrap;
}

// Linear map helper for plots.
export function scale(d0, d1, r0, r1) {
  const k = (r1 - r0) / ((d1 - d0) || 1);
  const f = (x) => r0 + (x - d0) * k;
  f.invert = (y) => d0 + (y - r0) / k; // from the picture back to the units (dragged handles)
  return f;
}

// The width in px an <svg class="plot"> is drawn at (its viewBox width): the
// element's laid-out width, so that one user unit is one CSS px and a
// font-size of 13 reads as 13 px on a phone as on a desktop; `max` (the CSS
// max-width) before layout. Plots keep their aspect ratio: H = W * h / max.
// In projector mode (larger type) a plot is laid out 4/3 narrower in user
// units, so its text, lines and marks show 4/3 larger, like the page's text.
export function plotSize(root, max = 640, h = 400) {
  const k = document.body.classList.contains('projector') ? 4 / 3 : 1;
  const w = Math.round(root.getBoundingClientRect().width / k);
  const W = w > 0 ? Math.max(260, Math.min(max, w)) : max;
  return [W, Math.round(W * h / max)];
}

// Draw a plot now and again whenever its width changes (a phone turned, a
// window resized): draw() reads plotSize(root) itself.
const redraws = new WeakMap();
const resizeObs = typeof ResizeObserver === 'function' ? new ResizeObserver((entries) => {
  for (const en of entries) {
    const r = redraws.get(en.target);
    const w = Math.round(en.contentRect.width);
    if (r && w > 0 && Math.abs(w - r.w) >= 8) { r.w = w; r.draw(); }
  }
}) : null;
// Plots on the page, drawn again when projector mode changes (app.js fires
// "mechd:redraw"); those no longer in the document are dropped.
const livePlots = new Set();
window.addEventListener('mechd:redraw', () => {
  for (const root of livePlots) if (!root.isConnected) livePlots.delete(root); else redraws.get(root).draw();
});
export function drawPlot(root, draw) {
  draw();
  const prev = redraws.get(root);
  redraws.set(root, {draw, w: prev ? prev.w : Math.round(root.getBoundingClientRect().width)});
  livePlots.add(root);
  if (!prev && resizeObs) resizeObs.observe(root);
}

// A simple x-y line plot into an <svg class="plot">: series = [{points: [[x,y]], cls, label}];
// the labels are listed in the top (legend: 'top') or bottom ('bottom') left corner.
// Ticks at round numbers (d3's 1-2-5 steps; an axis of large or small numbers
// says "×10ⁿ" once in its label instead of on every tick), log axes at whole
// decades labelled 10ⁿ, equal aspect on request (space drawn as space), a hover
// (and touch) read-out of the nearest sample, and PNG/SVG/CSV export under it.
export function linePlot(root, series, opts = {}) {
  drawPlot(root, () => linePlotNow(root, series, opts));
  plotTools(root, {name: opts.name || root.id || 'plot', csv: () => seriesCsv(series, opts)});
}
const SUP = {'-': '⁻', 0: '⁰', 1: '¹', 2: '²', 3: '³', 4: '⁴', 5: '⁵', 6: '⁶', 7: '⁷', 8: '⁸', 9: '⁹'};
export const pow10 = (k) => '10' + String(k).split('').map(c => SUP[c]).join('');
// Round ticks over [a, b] (about n of them) and their labels. A log axis (a, b
// in decades) gets whole decades, thinned to about n, labelled 10ⁿ; a linear
// axis d3's 1-2-5 ticks; when they are all large (≥ 10⁴) or small (< 10⁻²) they
// are divided by a common 10ᵉ, which the axis label then states once.
export function roundTicks(a, b, n, log, exp) {
  if (log) {
    const k0 = Math.ceil(a - 1e-9), k1 = Math.floor(b + 1e-9);
    if (k1 - k0 >= 1) {
      const step = Math.max(1, Math.ceil((k1 - k0) / n)), out = [];
      for (let k = k0; k <= k1; k += step) out.push(k);
      return {ticks: out, labels: out.map(pow10), factor: ''};
    }
    // less than two decades: 1-2-5 values in linear space, placed at their logs
    const v = d3.ticks(10 ** a, 10 ** b, n), f = d3.format('~r');
    return {ticks: v.map(Math.log10), labels: v.map(x => f(Number(x.toPrecision(6)))), factor: ''};
  }
  const v = d3.ticks(a, b, n);
  const big = Math.max(...v.map(Math.abs));
  const e = exp !== undefined ? exp : big >= 1e4 || (big > 0 && big < 1e-2) ? Math.floor(Math.log10(big)) : 0;
  const step = v.length > 1 ? (v[1] - v[0]) / 10 ** e : 1;
  const f = d3.format('.' + d3.precisionFixed(step) + 'f');
  return {ticks: v, labels: v.map(x => f(x / 10 ** e).replace('-', '−')), factor: e ? '×' + pow10(e) : ''};
}
// The axis label with its common factor: "x [m]" + "×10¹⁰" -> "x [×10¹⁰ m]".
const withFactor = (label, factor) => !factor ? label
  : /\[.*\]$/.test(label) ? label.replace(/\[(.*)\]$/, `[${factor} $1]`) : `${label} [${factor}]`;

function linePlotNow(root, series, {xlabel = '', ylabel = '', logx = false, logy = false,
                                    width = 640, height = 400, equal = false, legend = 'top', marks = [], frame} = {}) {
  [width, height] = plotSize(root, width, height);
  put(root);
  root.setAttribute('viewBox', `0 0 ${width} ${height}`);
  const tx = logx ? Math.log10 : (v) => v, ty = logy ? Math.log10 : (v) => v;
  const pts = series.flatMap(s => s.points).filter(p => isFinite(tx(p[0])) && isFinite(ty(p[1])));
  if (!pts.length) return;
  let [x0, x1] = d3.extent(pts, p => tx(p[0])), [y0, y1] = d3.extent(pts, p => ty(p[1]));
  if (x0 === x1) { x0 -= 1; x1 += 1; }
  if (y0 === y1) { y0 -= 1; y1 += 1; }
  if (frame) [x0, x1, y0, y1] = frame; // held while a handle is dragged: the picture does not rescale under the pointer
  const narrow = width < 480, nx = narrow ? 4 : 6, ny = 5;
  if (!equal && !frame) { // frame ends on round values (whole decades on a log axis)
    if (logx) { x0 = Math.floor(x0); x1 = Math.ceil(x1); } else [x0, x1] = d3.nice(x0, x1, nx);
    if (logy) { y0 = Math.floor(y0); y1 = Math.ceil(y1); } else [y0, y1] = d3.nice(y0, y1, ny);
  }
  const textW = (s, size = 13) => s.length * size * 0.6; // a generous estimate of a label's width
  // the left margin fits the longest y tick label beside the rotated axis label
  // on a phone (or when asked) the legend goes under the plot, one row per series, not over the data
  const below = legend === 'below' || (narrow && series.filter(s => s.label).length > 1);
  const nLeg = below ? series.filter(s => s.label).length : 0;
  // a phone's plot is taller for its width (the axis label fits beside it), and the legend rows add to it
  if (narrow) height = Math.max(height, Math.round(width * 0.75));
  height += 20 * nLeg;
  root.setAttribute('viewBox', `0 0 ${width} ${height}`);
  const m = {l: Math.max(narrow ? 50 : 60, 34 + Math.max(...roundTicks(y0, y1, ny, logy).labels.map(s => textW(s)))),
    r: narrow ? 14 : 30, t: 15, b: 48 + 20 * nLeg};
  if (equal) { // one unit is as long across as up: widen the shorter range about its middle
    const sx = (x1 - x0) / (width - m.l - m.r), sy = (y1 - y0) / (height - m.t - m.b), s = Math.max(sx, sy) * 1.04;
    const cx = (x0 + x1) / 2, cy = (y0 + y1) / 2;
    x0 = cx - s * (width - m.l - m.r) / 2; x1 = cx + s * (width - m.l - m.r) / 2;
    y0 = cy - s * (height - m.t - m.b) / 2; y1 = cy + s * (height - m.t - m.b) / 2;
  }
  const X = scale(x0, x1, m.l, width - m.r), Y = scale(y0, y1, height - m.b, m.t);
  add(root, svg('rect', {x: m.l, y: m.t, width: width - m.l - m.r, height: height - m.t - m.b,
    fill: 'none', stroke: '#888'}));
  let xt = roundTicks(x0, x1, nx, logx), yt = roundTicks(y0, y1, ny, logy);
  if (equal && xt.factor !== yt.factor) { // space drawn as space: one power of ten on both axes
    const big = Math.max(...[x0, x1, y0, y1].map(Math.abs)), e = big >= 1e4 || big < 1e-2 ? Math.floor(Math.log10(big)) : 0;
    xt = roundTicks(x0, x1, nx, logx, e); yt = roundTicks(y0, y1, ny, logy, e);
  }
  xt.ticks.forEach((xv, i) => { // centred under its tick, but kept inside the picture
    const s = xt.labels[i], half = textW(s) / 2;
    add(root, svg('line', {x1: X(xv), y1: m.t, x2: X(xv), y2: height - m.b, stroke: '#e4e4e4', class: 'grid'}),
      svg('line', {x1: X(xv), y1: height - m.b, x2: X(xv), y2: height - m.b + 5, stroke: '#666'}),
      svg('text', {x: Math.max(half + 2, Math.min(width - half - 2, X(xv))), y: height - m.b + 19, 'text-anchor': 'middle',
        'font-size': 13, class: 'tick-x'}, s));
  });
  yt.ticks.forEach((yv, i) => add(root,
    svg('line', {x1: m.l, y1: Y(yv), x2: width - m.r, y2: Y(yv), stroke: '#e4e4e4', class: 'grid'}),
    svg('line', {x1: m.l - 5, y1: Y(yv), x2: m.l, y2: Y(yv), stroke: '#666'}),
    svg('text', {x: m.l - 7, y: Y(yv) + 4, 'text-anchor': 'end', 'font-size': 13, class: 'tick-y'}, yt.labels[i])));
  add(root, svg('text', {x: (m.l + width - m.r) / 2, y: height - 8 - 20 * nLeg, 'text-anchor': 'middle', 'font-size': 15},
    withFactor(xlabel, xt.factor)));
  add(root, svg('text', {x: 16, y: (m.t + height - m.b) / 2, 'text-anchor': 'middle', 'font-size': 15,
    transform: `rotate(-90 16 ${(m.t + height - m.b) / 2})`}, withFactor(ylabel, yt.factor)));
  const colors = ['#c92a2a', '#2b8a3e', '#1864ab', '#e67700', '#862e9c', '#495057'];
  const hover = []; // [px, py, x, y, series label, colour] of every drawn sample
  const data = svg('g', {class: 'data'});
  add(root, data);
  const growing = []; // series that grow with an animation: [their element(s), projected points, times]
  series.forEach((s, i) => {
    const c = s.color || colors[i % colors.length];
    const keep = s.points.map((p, k) => k).filter(k => isFinite(tx(s.points[k][0])) && isFinite(ty(s.points[k][1])));
    const q = keep.map(k => s.points[k]);
    const p = q.map(r => [X(tx(r[0])), Y(ty(r[1]))]);
    p.forEach((r, k) => hover.push([r[0], r[1], q[k][0], q[k][1], s.label || '', c]));
    let drawn;
    if (s.dots) { drawn = p.map(r => svg('circle', {cx: r[0].toFixed(2), cy: r[1].toFixed(2), r: s.r || 4, fill: c})); add(data, drawn); }
    else add(data, drawn = svg('polyline', {points: p.map(r => r[0].toFixed(2) + ',' + r[1].toFixed(2)).join(' '), fill: 'none', stroke: c,
      'stroke-width': 2.5, 'stroke-dasharray': s.dash || null}));
    if (Array.isArray(s.t)) growing.push([drawn, p, keep.map(k => s.t[k])]);
    if (s.markers) for (const r of p) add(data, svg('circle', {cx: r[0].toFixed(2), cy: r[1].toFixed(2), r: 3.5, fill: c}));
    const k = series.slice(0, i).filter(q => q.label).length, lx = below ? 12 : m.l + 8;
    const ly = below ? height - 8 - 20 * (nLeg - 1 - k) : legend === 'bottom' ? height - m.b - 10 - 19 * (series.length - 1 - i) : m.t + 19 + 19 * i;
    if (s.label) add(root, s.dots ? svg('circle', {cx: lx + 9, cy: ly - 5, r: 4, fill: c})
      : svg('line', {x1: lx, y1: ly - 5, x2: lx + 18, y2: ly - 5, stroke: c, 'stroke-width': 3, 'stroke-dasharray': s.dash || null}),
      svg('text', {x: lx + 24, y: ly, fill: textShade(c), 'font-size': 15, 'font-weight': 700, class: 'legend'}, s.label));
  });
  for (const mk of marks) add(root, mk({X, Y, tx, ty, top: m.t, bottom: height - m.b, frame: [x0, x1, y0, y1]}));
  // growing with the animation (anim.js player's grow): the samples up to time t and the point between two
  // samples at t; Infinity draws everything
  root._grow = (t) => {
    root._growT = t;
    root.dataset.grownTo = String(t);
    for (const [drawn, p, ts] of growing) {
      let k = ts.length - 1;
      if (t !== Infinity) { k = -1; while (k + 1 < ts.length && ts[k + 1] <= t) k++; }
      if (Array.isArray(drawn)) { drawn.forEach((d, j) => d.setAttribute('visibility', j <= k ? 'visible' : 'hidden')); continue; }
      const pts = p.slice(0, k + 1);
      if (k >= 0 && k + 1 < ts.length && t > ts[k]) { const f = (t - ts[k]) / (ts[k + 1] - ts[k]);
        pts.push([p[k][0] + (p[k + 1][0] - p[k][0]) * f, p[k][1] + (p[k + 1][1] - p[k][1]) * f]); }
      drawn.setAttribute('points', pts.map(r => r[0].toFixed(2) + ',' + r[1].toFixed(2)).join(' '));
    }
  };
  if (root._growT !== undefined && root._growT !== Infinity) root._grow(root._growT);
  // hover / touch read-out: the nearest sample's values
  const dot = svg('circle', {r: 6, fill: 'none', stroke: '#111', 'stroke-width': 2, visibility: 'hidden'});
  const tip = svg('text', {'font-size': 14, 'font-weight': 700, class: 'readout', visibility: 'hidden'});
  add(root, dot, tip);
  const xname = xlabel.replace(/\s*\[.*\]$/, ''), yname = ylabel.replace(/\s*\[.*\]$/, '');
  const unit = (l) => { const u = /\[(.*)\]$/.exec(l); return u ? ' ' + u[1] : ''; };
  root.onpointermove = (e) => {
    const r = root.getBoundingClientRect(), k = width / (r.width || width);
    const px = (e.clientX - r.left) * k, py = (e.clientY - r.top) * k;
    let best = null, bd = Infinity;
    for (const h of hover) { const d = (h[0] - px) ** 2 + (h[1] - py) ** 2; if (d < bd) { bd = d; best = h; } }
    if (!best || bd > 60 * 60) { root.onpointerleave(); return; }
    dot.setAttribute('cx', best[0]); dot.setAttribute('cy', best[1]); dot.setAttribute('stroke', best[5]);
    dot.setAttribute('visibility', 'visible');
    tip.textContent = `${best[4] ? best[4] + ': ' : ''}${xname} = ${fmt(best[2], 4)}${unit(xlabel)}, ${yname} = ${fmt(best[3], 4)}${unit(ylabel)}`;
    const w = textW(tip.textContent, 14), left = best[0] + 10 + w < width - 4;
    tip.setAttribute('x', left ? best[0] + 10 : Math.max(4, best[0] - 10 - w));
    tip.setAttribute('y', Math.max(m.t + 16, best[1] - 10));
    tip.setAttribute('visibility', 'visible');
    root.dataset.readout = tip.textContent;
  };
  root.onpointerleave = () => { dot.setAttribute('visibility', 'hidden'); tip.setAttribute('visibility', 'hidden'); };
}

// A line colour as text: the palette's orange (3.0:1 on white), green (4.37:1)
// and amber darkened to at least 4.5:1; the other colours already are.
const SHADES = {'#e67700': '#a65300', '#2b8a3e': '#1f6f30', '#f59f00': '#a65300', '#f08c00': '#a65300', '#5c940d': '#3b5e08', '#0ca678': '#087055'};
export const textShade = (c) => SHADES[String(c).toLowerCase()] || c;

// The data of a line plot as CSV: one block per series ("series,x,y" rows),
// numbers as the API gave them (full precision).
function seriesCsv(series, {xlabel = 'x', ylabel = 'y'} = {}) {
  const q = (s) => /[",\n]/.test(s) ? '"' + s.replace(/"/g, '""') + '"' : s;
  const rows = [['series', xlabel, ylabel].map(q).join(',')];
  series.forEach((s, i) => { for (const p of s.points) rows.push([q(s.label || 'series ' + (i + 1)), String(p[0]), String(p[1])].join(',')); });
  return rows.join('\n') + '\n';
}

// Save a Blob under a file name (an <a download> click; no popup, no server).
function save(blob, name) {
  const a = el('a', {href: URL.createObjectURL(blob), download: name});
  document.body.appendChild(a); a.click(); a.remove();
  setTimeout(() => URL.revokeObjectURL(a.href), 1000);
}
// The SVG as a stand-alone file: the page's text style inlined as attributes.
function svgText(root) {
  const c = root.cloneNode(true);
  c.setAttribute('xmlns', SVGNS);
  const [, , w, h] = (root.getAttribute('viewBox') || '0 0 640 400').split(' ').map(Number);
  c.setAttribute('width', w); c.setAttribute('height', h);
  for (const t of c.querySelectorAll('text')) {
    t.setAttribute('font-family', 'system-ui, sans-serif');
    t.setAttribute('paint-order', 'stroke'); t.setAttribute('stroke', '#fff'); t.setAttribute('stroke-width', '3');
  }
  for (const t of c.querySelectorAll('[visibility=hidden]')) t.remove();
  c.insertBefore(svg('rect', {width: '100%', height: '100%', fill: '#fff'}), c.firstChild);
  return new XMLSerializer().serializeToString(c);
}
// A PNG of an <svg> (drawn at twice its size) or of a <canvas>.
async function pngOf(root) {
  if (root instanceof HTMLCanvasElement) {
    if (root.dataset.render) window.dispatchEvent(new CustomEvent('mechd:render', {detail: root}));
    return new Promise(r => root.toBlob(r, 'image/png'));
  }
  const src = 'data:image/svg+xml;base64,' + btoa(unescape(encodeURIComponent(svgText(root))));
  const img = new Image(); img.src = src; await img.decode();
  const cv = document.createElement('canvas'); cv.width = img.width * 2; cv.height = img.height * 2;
  const g = cv.getContext('2d'); g.scale(2, 2); g.drawImage(img, 0, 0);
  return new Promise(r => cv.toBlob(r, 'image/png'));
}
// The export buttons under a figure (once per figure): PNG, SVG (an <svg>
// only) and, when csv() gives the data, CSV.
export function plotTools(root, {name = 'plot', csv} = {}) {
  let bar = root.nextElementSibling;
  if (bar && bar.dataset.role === 'plot-tools') {
    bar._csv = csv; bar.querySelector('[data-export=csv]').hidden = !csv; return bar;
  }
  const label = root.getAttribute('aria-label') || name;
  bar = el('div', {class: 'plot-tools', 'data-role': 'plot-tools', role: 'group', 'aria-label': 'Export ' + label},
    el('span', {class: 'muted'}, 'Export:'),
    el('button', {type: 'button', class: 'secondary small-btn', 'data-export': 'png', 'aria-label': `Save ${label} as PNG`,
      onclick: async () => save(await pngOf(root), name + '.png')}, 'PNG'),
    root instanceof SVGElement ? el('button', {type: 'button', class: 'secondary small-btn', 'data-export': 'svg',
      'aria-label': `Save ${label} as SVG`, onclick: () => save(new Blob([svgText(root)], {type: 'image/svg+xml'}), name + '.svg')}, 'SVG') : null,
    el('button', {type: 'button', class: 'secondary small-btn', 'data-export': 'csv', 'aria-label': `Save the data of ${label} as CSV`,
      hidden: !csv, onclick: () => { if (bar._csv) save(new Blob([bar._csv()], {type: 'text/csv'}), name + '.csv'); }}, 'CSV'));
  bar._csv = csv;
  root.after(bar);
  return bar;
}

// A section of a lab: a form, the problem box under it, the curl box; results
// and a figure beside (one column on a phone). parent gets a heading and intro.
export function labSection(parent, {title, intro, form, level = 'h2', id}) {
  form = form || el('form', {novalidate: true, 'aria-label': title + ' inputs', id: id ? id + '-form' : undefined});
  const problem = el('div', {class: 'problem', role: 'alert', 'data-role': 'problem'});
  const results = el('section', {class: 'results', 'aria-live': 'polite', 'aria-label': title + ': results',
    id: id ? id + '-results' : undefined});
  const figure = el('section', {class: 'figure', 'aria-label': title + ': figure'});
  const curl = curlBox();
  add(parent, el(level, {}, title), intro ? el('p', {class: 'intro'}, intro) : null,
    el('div', {class: 'grid'}, el('div', {}, form, problem, curl.box), el('div', {}, results, figure)));
  return {form, problem, results, figure, curl};
}

// The common lab layout: intro, examples, a form, results, plot, curl.
export function labLayout(main, {title, intro}) {
  put(main);
  return labSection(main, {title, intro});
}

// While a request runs: the form says data-state="busy", its submit button is
// disabled, the results and figure are dimmed and marked aria-busy (they are
// the previous answer's), and after a moment (no flicker for quick answers) a
// "Computing… n s" status with a Cancel button shows by the button.
function busyUi(S, onCancel) {
  const buttons = S.form.querySelector('.buttons') || S.form;
  const submit = S.form.querySelector('[type=submit]');
  const secs = el('span', {});
  const cancel = el('button', {type: 'button', class: 'secondary', 'data-role': 'cancel', onclick: onCancel}, 'Cancel');
  const status = el('span', {class: 'busy', role: 'status', 'data-role': 'busy'},
    el('span', {class: 'spinner', 'aria-hidden': 'true'}), 'Computing… ', secs, ' ', cancel);
  const old = S.form.querySelector('[data-role=busy], [data-role=cancelled]');
  if (old) old.remove();
  const t0 = performance.now();
  const pressed = document.activeElement === submit; // the user pressed the button (not a load or a slider)
  S.form.dataset.state = 'busy';
  if (submit) submit.disabled = true;
  for (const e of [S.results, S.figure]) if (e) e.setAttribute('aria-busy', 'true');
  let shown = false;
  const show = () => {
    if (!shown) {
      shown = true;
      for (const e of [S.results, S.figure]) if (e) e.classList.add('stale');
      add(buttons, status);
      if (pressed && (document.activeElement === submit || document.activeElement === document.body)) cancel.focus();
    }
    const s = Math.round((performance.now() - t0) / 1000);
    secs.textContent = s ? s + ' s' : '';
  };
  const timer = setInterval(show, 1000);
  const soon = setTimeout(show, 150);
  // end(cancelled): back to idle; cancelled leaves the old results dimmed with a note
  return (cancelled) => {
    clearInterval(timer); clearTimeout(soon);
    const hadFocus = document.activeElement === cancel;
    status.remove();
    if (submit) { submit.disabled = false; if (hadFocus) submit.focus(); }
    for (const e of [S.results, S.figure]) if (e) { e.removeAttribute('aria-busy'); e.classList.toggle('stale', !!cancelled); }
    if (cancelled) add(buttons, el('span', {class: 'busy', role: 'status', 'data-role': 'cancelled'},
      'Cancelled: the results shown are from the previous request.'));
  };
}

// Wire a section's form to one operation: build() -> body, show(answer, body)
// renders (returning false when the answer holds a failure, e.g. a batch item's). Returns run(); a new run cancels one still running (the slider),
// and Cancel aborts the request (AbortController: the server's hang-up
// watcher then stops the pooled work). data-state on the form: busy, done,
// error or cancelled. path may be a function of nothing.
export function runner(S, path, build, show) {
  let ctl = null, endCur = null;
  const run = async () => {
    let body;
    try { body = build(); } catch (e) {
      if (e && e.problem) { fail(422, e.problem); return; } // the lab's own check of an input, placed like the server's
      put(S.problem, String(e)); S.form.dataset.state = 'error'; staleMark(S, true); return;
    }
    const p = typeof path === 'function' ? path() : path;
    S.curl.update(p, body);
    if (ctl) { ctl.abort(); endCur(false); }
    const mine = ctl = new AbortController();
    let cancelled = false;
    const end = endCur = busyUi(S, () => { cancelled = true; mine.abort(); });
    const r = await api(p, body, {signal: mine.signal});
    if (mine !== ctl) return; // a newer run took over (and owns the busy state)
    ctl = null;
    end(r.aborted && cancelled);
    if (r.aborted) { S.form.dataset.state = 'cancelled'; return; }
    if (!r.ok) { fail(r.status, r.body); return; }
    clearErrors(S.form, S.problem);
    // show() returns false when the answer carries a failure of its own (a batch
    // item) that it has said, or {status, problem} to be placed on the fields
    let out;
    try { out = show(r.body, body); } catch (e) {
      out = {status: r.status, problem: {title: 'Not shown', detail: 'This answer could not be drawn by the page (' + e.message + ').'}};
    }
    if (out && out.problem) { fail(out.status || 422, out.problem); return; }
    staleMark(S, out === false);
    S.form.dataset.state = out === false ? 'error' : 'done';
  };
  // an error stands: on its field, the previous answer dimmed and labelled "not updated"
  const fail = (status, prob) => { showProblem(S.form, S.problem, status, prob); staleMark(S, true); S.form.dataset.state = 'error'; };
  S.form.addEventListener('submit', (e) => { e.preventDefault(); run(); });
  return run;
}

// A positive number in two figures, powers of ten as a reader writes them: 7.9·10⁻⁵, 10⁻¹³, 2100, 2.1·10⁷.
export function sci(x) {
  if (typeof x !== 'number' || !Number.isFinite(x)) return '—';
  if (x === 0 || (Math.abs(x) >= 1e-3 && Math.abs(x) < 1e4)) return fmt(x, 2);
  const e = Math.floor(Math.log10(Math.abs(x))), m = Number((x / 10 ** e).toPrecision(2));
  return m === 10 ? pow10(e + 1) : (m === 1 ? '' : m + '·') + pow10(e);
}

// A duration in words a student reads at a glance: 40 µs, 3.2 ms, 2.1 s, 3.5 min.
export function humanSeconds(s) {
  if (typeof s !== 'number' || !Number.isFinite(s) || s < 0) return '—';
  if (s < 1e-3) return `${fmt(Math.max(s * 1e6, 1), 2)} µs`;
  if (s < 1) return `${fmt(s * 1e3, 2)} ms`;
  if (s < 120) return `${fmt(s, 2)} s`;
  return `${fmt(s / 60, 2)} min`;
}

// The accuracy presets of every time-evolution operation's integrator block
// (docs/accuracy.md "What the accuracy presets do"): relative error targets.
const PRESETS = [['draft', 'draft (10⁻³)'], ['balanced', 'balanced (10⁻⁸)'], ['precise', 'precise (10⁻¹⁰)'], ['machine', 'machine (10⁻¹¹)']];

// costPreview(form, path, build) -> {wrap, withAccuracy(body), after(answer), predict()}
//   An "Accuracy" choice for a time-evolution operation and, under it, the
//   chooser's prediction of the run's cost before it is run: the same request
//   with "dry_run": true (the server integrates nothing and answers
//   diagnostics.selection: the chosen method, its predicted error, evaluations
//   and CPU seconds) at the chosen accuracy and at draft, e.g. "about 2.1 s at
//   precise (rk8pd, rtol 10⁻¹³), 40 ms at draft". Asked again (debounced) when
//   an input of the form changes. build() gives the lab's body; withAccuracy
//   adds {integrator: {accuracy}} to it. after(answer) says what the run cost
//   beside the prediction. The paragraph carries data-cpu and data-draft-cpu
//   (predicted seconds) for tests. A dry run that fails says nothing: the run
//   itself names the field.
export function costPreview(form, path, build, {id = 'cost' + (++uid), value = 'balanced'} = {}) {
  const sel = el('select', {id: id + '-acc', 'data-pointer': '/integrator', 'aria-describedby': id + '-acc-err ' + id,
    'data-role': 'accuracy'}, PRESETS.map(([v, t]) => el('option', {value: v, selected: v === value}, t)));
  const out = el('p', {class: 'cost', id, 'data-role': 'cost', 'aria-live': 'polite'});
  const wrap = el('div', {class: 'field'}, el('label', {for: sel.id}, 'Accuracy'), sel,
    el('div', {class: 'err', id: id + '-acc-err', role: 'alert'}), out);
  const withAccuracy = (body) => ({...body, integrator: {...(body.integrator || {}), accuracy: sel.value}});
  const chosen = (s) => (Array.isArray(s.candidates) && s.candidates.find(c => c.verdict === 'chosen')) || null;
  const setting = (s) => typeof s.rtol === 'number' ? `rtol ${sci(s.rtol)}` : typeof s.dt === 'number' ? `dt ${sci(s.dt)}` : '';
  let ctl = null, timer = 0, predicted = null, took = null;
  // what the last run cost beside what was predicted for it
  const sayTook = () => {
    const old = out.querySelector('[data-role=took]');
    if (old) old.remove();
    if (took) add(out, el('span', {'data-role': 'took'}, ` The last run took ${humanSeconds(took[0])} of CPU` +
      (typeof took[1] === 'number' ? ` (predicted ${humanSeconds(took[1])}).` : '.')));
  };
  const predict = async () => {
    clearTimeout(timer);
    let body;
    try { body = build(); } catch (e) { return; }
    if (ctl) ctl.abort();
    const mine = ctl = new AbortController();
    const levels = sel.value === 'draft' ? ['draft'] : [sel.value, 'draft'];
    out.dataset.state = 'busy';
    const rs = await Promise.all(levels.map(l => api(path, {...body, dry_run: true, integrator: {...(body.integrator || {}), accuracy: l}},
      {signal: mine.signal})));
    if (mine !== ctl) return;
    ctl = null;
    const sels = rs.map(r => r.ok && r.body && r.body.diagnostics && r.body.diagnostics.selection);
    // a failed prediction says nothing of its own, but keeps what the last run took
    if (!sels.every(Boolean)) { put(out); predicted = null; out.dataset.state = 'error'; sayTook(); return; }
    const cs = sels.map(chosen);
    const cpu = cs.map(c => c && typeof c.predicted_cpu_s === 'number' ? c.predicted_cpu_s : null);
    predicted = cpu[0];
    out.dataset.cpu = String(cpu[0]);
    out.dataset.draftCpu = String(cpu[cpu.length - 1]);
    out.dataset.state = 'done';
    const s = sels[0];
    put(out, el('strong', {}, 'Predicted cost: '), cpu[0] === null ? `${s.method || 'the chosen method'} (no cost prediction for it)`
      : [`about ${humanSeconds(cpu[0])} at ${sel.value} (${s.method}${setting(s) ? ', ' + setting(s) : ''}, `,
         `${sci(cs[0].predicted_evaluations)} force evaluations, error about ${sci(cs[0].predicted_error)})`],
      levels.length > 1 && cpu[1] !== null ? `, ${humanSeconds(cpu[1])} at draft` : '',
      // the chooser's best is predicted to miss the target: say so in words
      cpu[0] !== null && typeof s.target_error === 'number' && cs[0].predicted_error > s.target_error
        ? el('span', {class: 'warn', 'data-role': 'misses'}, `; the error predicted at ${sel.value} is above its target ${sci(s.target_error)}: over this long a run ` +
          'even the most accurate method is not expected to reach it') : null, '. ',
      el('span', {class: 'muted'}, 'From the chooser\'s model ("dry_run": nothing integrated).'),
      cpu[0] !== null && cpu[0] > 2 ? el('span', {class: 'warn'}, ' A long run: try draft first, or fewer orbits or a shorter time.') : null);
    sayTook();
  };
  const schedule = () => { clearTimeout(timer); timer = setTimeout(predict, 350); };
  sel.addEventListener('change', predict);
  form.addEventListener('input', (e) => { if (e.target !== sel) schedule(); });
  // after the run: what it cost beside what was predicted
  // (the prediction is the run's own, from its diagnostics.selection, when the
  // answer carries one: the dry run made for these inputs may have failed or
  // may still be on its way)
  const after = (a) => {
    const cpu = a && a.cost && a.cost.cpu_seconds;
    const own = a && a.diagnostics && a.diagnostics.selection && chosen(a.diagnostics.selection);
    const p = own && typeof own.predicted_cpu_s === 'number' ? own.predicted_cpu_s : predicted;
    took = typeof cpu === 'number' ? [cpu, p] : null;
    sayTook();
  };
  return {wrap, select: sel, out, withAccuracy, after, predict};
}

// --- "What the notes say": the course notes' formula beside the API's answer ---
// A quantity in words a student reads: the unit's SI prefix chosen so the
// number is between 1 and 1000 (0.3 mm, 12 µs), two significant figures.
const PREFIXED = new Set(['m', 's', 'N', 'J', 'eV', 'Hz']);
const PREFIX = [[1e9, 'G'], [1e6, 'M'], [1e3, 'k'], [1, ''], [1e-3, 'm'], [1e-6, 'µ'], [1e-9, 'n'], [1e-12, 'p'], [1e-15, 'f']];
export function amount(x, unit = '') {
  if (typeof x !== 'number' || !Number.isFinite(x)) return '—';
  const a = Math.abs(x);
  if (a === 0) return '0' + (unit ? ' ' + unit : '');
  if (PREFIXED.has(unit) && a >= 1e-15 && a < (unit === 'm' ? 1e6 : 1e12)) {
    const [k, p] = PREFIX.find(([k]) => a >= k * 0.9995) || PREFIX[PREFIX.length - 1];
    return `${fmt(x / k, 2)} ${p}${unit}`;
  }
  return sci(x) + (unit ? ' ' + unit : '');
}
// A relative difference in words: "0.02 %", or "3 parts in 10¹³" when smaller than 10⁻⁶.
export function relWords(r) {
  if (typeof r !== 'number' || !Number.isFinite(r)) return '—';
  if (r === 0) return '0 %';
  if (r >= 1e-6) return `${fmt(r * 100, 2)} %`;
  const e = Math.floor(Math.log10(r)), m = Math.round(r / 10 ** e);
  return m >= 10 ? `1 part in ${pow10(-e - 1)}` : `${m} part${m === 1 ? '' : 's'} in ${pow10(-e)}`;
}

// notesBox(id) -> {box, update(spec)}: the lab's "What the notes say" section.
// spec: {section: '1.4' (the notes' section number as their text carries it),
//   heading (the title under it), inferred (the number is not in the extracted
//   text: taken from the contents' order, said so), formula (nodes: the
//   formula rebuilt from its derivation, Unicode/HTML), what ('the first-order
//   formula'), formulaValue, apiValue (numbers) or formulaShown/apiShown (text,
//   for vectors and matrices) with abs and rel given, unit, diff (the API's own
//   formula − full difference when it reports one, kept to its digits),
//   source: 'api' (the formula's value is the API's) or 'page' (computed here
//   from the inputs), sourceText (says it otherwise), diffUnit and diffScale (the
//   difference said in that unit: 'eV' and 1e6 for values in MeV), how (one line: what is compared), note (more words),
//   cite (a topic the notes do not treat: the standard text cited instead, "Beyond the notes: …", section then a short tag)}.
// The box carries data-abs and data-rel (finite numbers) for tests.
export function notesBox(id) {
  // named by its own heading ("What the notes say: §4 … Deflection of Light"), so two boxes in a lab differ
  const box = el('section', {class: 'teach', 'data-role': 'teach', id, 'aria-labelledby': id + '-h'});
  const update = (s) => {
    let abs = s.abs, rel = s.rel;
    if (typeof s.formulaValue === 'number' && typeof s.apiValue === 'number') {
      const d = typeof s.diff === 'number' ? s.diff : s.formulaValue - s.apiValue;
      abs = Math.abs(d);
      // relative to the full answer (to the larger of the two when the full answer is 0)
      const ref = Math.abs(s.apiValue) || Math.abs(s.formulaValue);
      rel = abs === 0 ? 0 : abs / ref;
      s = {...s, sign: d};
    }
    const ok = Number.isFinite(abs) && Number.isFinite(rel);
    const what = s.what || 'the notes\' formula';
    const k = s.diffScale || 1, u = s.diffUnit || s.unit; // the difference said in another unit (pm as m, MeV as eV)
    const words = !ok ? 'cannot be compared here (the API gave no finite number)'
      : abs === 0 ? `${what} and the full answer agree to every digit: the difference is 0`
      : rel < 1e-12 ? `they agree to round-off: ${amount(abs * k, u)}, ${relWords(rel)}`
      : `${what} is ${typeof s.sign === 'number' ? (s.sign > 0 ? 'high' : 'low') + ' by' : 'off by'} ${amount(abs * k, u)}, ${relWords(rel)}`;
    const shown = (x, t) => t !== undefined ? t : fmt(x) + (s.unit && typeof x === 'number' ? ' ' + s.unit : '');
    put(box, el('h3', {id: id + '-h'}, s.cite ? ['Beyond the notes: ', el('span', {'data-role': 'section'}, s.cite), ' — ']
      : ['What the notes say: ', el('span', {'data-role': 'section'}, '§' + s.section), ' '], s.heading),
      s.inferred ? el('p', {class: 'muted'}, `(The number §${s.section} is read from the notes' contents: the extracted text lost it.)`) : null,
      el('div', {class: 'formula', 'data-role': 'formula'}, s.formula),
      s.how ? el('p', {class: 'muted'}, s.how) : null,
      el('dl', {class: 'nums'},
        el('dt', {}, 'the formula gives'), el('dd', {'data-role': 'formula-value', 'data-value': String(s.formulaValue)},
          shown(s.formulaValue, s.formulaShown), el('span', {class: 'muted'}, ' (' + (s.sourceText || (s.source === 'api' ? 'the API\'s first-order value'
            : 'computed in this page from your inputs')) + ')')),
        el('dt', {}, 'the full answer (API)'), el('dd', {'data-role': 'api-value', 'data-value': String(s.apiValue)}, shown(s.apiValue, s.apiShown)),
        el('dt', {}, 'difference'), el('dd', {'data-role': 'diff', 'data-abs': String(abs), 'data-rel': String(rel)}, words)),
      s.note ? el('p', {class: 'muted'}, s.note) : null);
    box.dataset.abs = String(abs); box.dataset.rel = String(rel); box.dataset.section = s.section;
  };
  return {box, update};
}
