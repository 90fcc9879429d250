// lib.js — shared helpers of the labs: DOM building (no innerHTML), the API
// call, problem+json errors placed next to the field they name, the curl
// command, the notes' worked examples, and small SVG plotting.

export const SVGNS = 'http://www.w3.org/2000/svg';

// el('div', {class: 'x', onclick: f}, child, 'text', …)
export function el(tag, attrs = {}, ...kids) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) {
    if (v === undefined || v === null || v === false) continue;
    if (k.startsWith('on')) e.addEventListener(k.slice(2), v);
    else if (k === 'text') e.textContent = v;
    else e.setAttribute(k, v === true ? '' : v);
  }
  for (const kid of kids.flat()) if (kid !== null && kid !== undefined)
    e.append(kid instanceof Node ? kid : document.createTextNode(String(kid)));
  return e;
}

export function svg(tag, attrs = {}, text) {
  const e = document.createElementNS(SVGNS, tag);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
  if (text !== undefined) e.textContent = text;
  return e;
}

// A number in 7 significant figures (the full value stays in data-value).
export function fmt(x, sig = 7) {
  if (typeof x !== 'number' || !isFinite(x)) return String(x);
  if (x === 0) return '0';
  const a = Math.abs(x);
  return a >= 1e-4 && a < 1e7 ? String(Number(x.toPrecision(sig))) : x.toExponential(sig - 1);
}

export function num(id, x, unit = '') {
  return el('dd', {id, 'data-value': String(x)}, fmt(x) + (unit ? ' ' + unit : ''));
}

let uid = 0;
// A labelled number (or text/select) control; pointer = the JSON pointer it fills
// (several, separated by spaces, when one control fills more than one place).
export function field({label, pointer, value, unit, step = 'any', min, max, type = 'number',
                       options, id, cls, help}) {
  id = id || 'f' + (++uid);
  const errId = id + '-err';
  let input;
  if (options) {
    input = el('select', {id, 'data-pointer': pointer, 'aria-describedby': errId},
      options.map(o => el('option', {value: o[0], selected: String(o[0]) === String(value)}, o[1])));
  } else {
    input = el('input', {id, type, value, step: type === 'number' || type === 'range' ? step : undefined,
      min, max, class: cls, 'data-pointer': pointer, 'aria-describedby': errId,
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

export async function api(path, body) {
  const init = body === undefined ? {} : {method: 'POST', headers: {'Content-Type': 'application/json'},
    body: toJSON(body)};
  let res;
  try { res = await fetch(path, init); } catch (e) {
    return {ok: false, status: 0, body: {title: 'Network error', detail: String(e)}};
  }
  let json = null;
  try { json = await res.json(); } catch (e) { json = {title: 'Not JSON', detail: String(e)}; }
  return {ok: res.ok, status: res.status, body: json};
}

export function curlCommand(path, body) {
  const q = (s) => "'" + s.replace(/'/g, "'\\''") + "'";
  return body === undefined ? `curl -s ${q(location.origin + path)}`
    : `curl -s --json ${q(toJSON(body))} ${q(location.origin + path)}`;
}

// The copyable curl box: update(path, body).
export function curlBox() {
  const pre = el('pre', {tabindex: 0, 'aria-label': 'curl command'});
  const btn = el('button', {type: 'button', class: 'secondary', onclick: async () => {
    try { await navigator.clipboard.writeText(pre.textContent); btn.textContent = 'Copied'; }
    catch (e) { const r = document.createRange(); r.selectNodeContents(pre);
      getSelection().removeAllRanges(); getSelection().addRange(r); btn.textContent = 'Selected: press Ctrl+C'; }
    setTimeout(() => { btn.textContent = 'Copy curl'; }, 2000);
  }}, 'Copy curl');
  const box = el('section', {class: 'curl'}, el('h3', {}, 'The request'), pre, btn);
  return {box, update: (path, body) => { pre.textContent = curlCommand(path, body); }};
}

// Clear every field error of a form and the general problem box.
export function clearErrors(form, problemBox) {
  for (const c of form.querySelectorAll('[data-pointer]')) c.removeAttribute('aria-invalid');
  for (const e of form.querySelectorAll('.err')) e.textContent = '';
  problemBox.textContent = '';
}

// Place a problem+json next to the fields its errors[].pointer name: the control
// whose data-pointer equals the pointer or is its longest prefix, else the first
// control below it; whatever cannot be placed goes to the problem box.
export function showProblem(form, problemBox, status, prob) {
  clearErrors(form, problemBox);
  const controls = [...form.querySelectorAll('[data-pointer]')];
  const left = [];
  const errors = Array.isArray(prob && prob.errors) ? prob.errors : [];
  let first = null;
  for (const e of errors) {
    const p = e.pointer || '';
    let best = null;
    let bestLen = -1;
    for (const c of controls) for (const cp of c.dataset.pointer.split(' ')) // a control may fill several places
      if ((p === cp || p.startsWith(cp + '/')) && cp.length > bestLen) { best = c; bestLen = cp.length; }
    if (!best && p) best = controls.find(c => c.dataset.pointer.split(' ').some(cp => cp.startsWith(p + '/'))) || null;
    if (!best) { left.push(e); continue; }
    best.setAttribute('aria-invalid', 'true');
    const box = document.getElementById(best.getAttribute('aria-describedby'));
    if (box) box.textContent = (box.textContent ? box.textContent + '; ' : '') + e.detail;
    first = first || best;
  }
  const head = `${status} ${prob && prob.title ? prob.title : 'Error'}`;
  if (left.length || !errors.length)
    problemBox.append(el('strong', {}, head + ': '), (prob && prob.detail) || '',
      left.length ? el('ul', {}, left.map(e => el('li', {}, `${e.pointer || '(body)'}: ${e.detail}`))) : null);
  else problemBox.append(el('span', {class: 'muted'}, head + ' — see the marked field' + (errors.length > 1 ? 's' : '') + '.'));
  if (first) first.focus();
}

let examplesPromise = null;
// GET /v1/examples ({examples: [{id, title, section, operation, request, notes_answer}]}),
// or [] when the server has none.
export function examples() {
  if (!examplesPromise) examplesPromise = api('/v1/examples').then(r =>
    r.ok && r.body && Array.isArray(r.body.examples) ? r.body.examples : []);
  return examplesPromise;
}

// The "worked examples" picker: the server's examples for these operations
// plus the lab's built-in ones; onLoad(example) fills the form.
export function examplePicker(operations, builtin, onLoad) {
  const id = 'ex' + (++uid);
  const select = el('select', {id});
  const wrap = el('div', {class: 'examples'}, el('label', {for: id}, 'Worked example: '), select,
    el('button', {type: 'button', class: 'secondary', onclick: () => {
      const ex = list[Number(select.value)];
      if (ex) onLoad(ex);
    }}, 'Load'));
  let list = builtin.slice();
  const render = () => {
    select.replaceChildren(...list.map((ex, i) => el('option', {value: i},
      (ex.section ? `§${ex.section} ` : '') + ex.title)));
  };
  render();
  examples().then(server => {
    const mine = server.filter(ex => operations.includes(ex.operation));
    if (mine.length) { list = mine.concat(builtin.filter(b => !mine.some(m => m.title === b.title))); render(); }
  });
  return wrap;
}

// Linear map helper for plots.
export function scale(d0, d1, r0, r1) {
  const k = (r1 - r0) / ((d1 - d0) || 1);
  return (x) => r0 + (x - d0) * k;
}

// A simple x-y line plot into an <svg class="plot">: series = [{points: [[x,y]], cls, label}].
export function linePlot(root, series, {xlabel = '', ylabel = '', logx = false, logy = false,
                                        width = 640, height = 400, equal = false} = {}) {
  root.replaceChildren();
  root.setAttribute('viewBox', `0 0 ${width} ${height}`);
  const tx = logx ? Math.log10 : (v) => v, ty = logy ? Math.log10 : (v) => v;
  const pts = series.flatMap(s => s.points).filter(p => isFinite(tx(p[0])) && isFinite(ty(p[1])));
  if (!pts.length) return;
  let [x0, x1] = [Math.min(...pts.map(p => tx(p[0]))), Math.max(...pts.map(p => tx(p[0])))];
  let [y0, y1] = [Math.min(...pts.map(p => ty(p[1]))), Math.max(...pts.map(p => ty(p[1])))];
  if (x0 === x1) { x0 -= 1; x1 += 1; }
  if (y0 === y1) { y0 -= 1; y1 += 1; }
  const m = {l: 88, r: 38, t: 15, b: 45};
  if (equal) {
    const sx = (x1 - x0) / (width - m.l - m.r), sy = (y1 - y0) / (height - m.t - m.b), s = Math.max(sx, sy);
    const cx = (x0 + x1) / 2, cy = (y0 + y1) / 2;
    x0 = cx - s * (width - m.l - m.r) / 2; x1 = cx + s * (width - m.l - m.r) / 2;
    y0 = cy - s * (height - m.t - m.b) / 2; y1 = cy + s * (height - m.t - m.b) / 2;
  }
  const X = scale(x0, x1, m.l, width - m.r), Y = scale(y0, y1, height - m.b, m.t);
  root.append(svg('rect', {x: m.l, y: m.t, width: width - m.l - m.r, height: height - m.t - m.b,
    fill: 'none', stroke: '#888'}));
  for (let i = 0; i <= 4; i++) {
    let xv = x0 + (x1 - x0) * i / 4, yv = y0 + (y1 - y0) * i / 4;
    if (Math.abs(xv) < 1e-6 * (x1 - x0)) xv = 0; // a round-off tick next to zero reads 0
    if (Math.abs(yv) < 1e-6 * (y1 - y0)) yv = 0;
    root.append(svg('text', {x: X(xv), y: height - m.b + 18, 'text-anchor': 'middle', 'font-size': 13},
      logx ? '1e' + xv.toFixed(1) : fmt(xv, 3)));
    root.append(svg('text', {x: m.l - 6, y: Y(yv) + 4, 'text-anchor': 'end', 'font-size': 13},
      logy ? '1e' + yv.toFixed(1) : fmt(yv, 3)));
  }
  root.append(svg('text', {x: (m.l + width - m.r) / 2, y: height - 6, 'text-anchor': 'middle', 'font-size': 15}, xlabel));
  root.append(svg('text', {x: 14, y: (m.t + height - m.b) / 2, 'text-anchor': 'middle', 'font-size': 15,
    transform: `rotate(-90 14 ${(m.t + height - m.b) / 2})`}, ylabel));
  const colors = ['#c92a2a', '#2b8a3e', '#1864ab', '#e67700', '#862e9c', '#495057'];
  series.forEach((s, i) => {
    const c = s.color || colors[i % colors.length];
    const p = s.points.filter(q => isFinite(tx(q[0])) && isFinite(ty(q[1])))
      .map(q => `${X(tx(q[0])).toFixed(2)},${Y(ty(q[1])).toFixed(2)}`);
    if (s.dots) for (const q of p) { const [a, b] = q.split(','); root.append(svg('circle', {cx: a, cy: b, r: 4, fill: c})); }
    else root.append(svg('polyline', {points: p.join(' '), fill: 'none', stroke: c, 'stroke-width': 2.5}));
    if (s.label) root.append(svg('text', {x: m.l + 8, y: m.t + 18 + 18 * i, fill: c, 'font-size': 15,
      'font-weight': 700}, s.label));
  });
}

// The common lab layout: intro, examples, a form, results, plot, curl.
export function labLayout(main, {title, intro}) {
  const form = el('form', {novalidate: true, 'aria-label': title + ' inputs'});
  const problem = el('div', {class: 'problem', role: 'alert', 'data-role': 'problem'});
  const results = el('section', {class: 'results', 'aria-live': 'polite', 'aria-label': 'Results'});
  const figure = el('section', {class: 'figure'});
  const curl = curlBox();
  main.replaceChildren(el('h2', {}, title), el('p', {class: 'intro'}, intro),
    el('div', {class: 'grid'}, el('div', {}, form, problem, curl.box), el('div', {}, results, figure)));
  return {form, problem, results, figure, curl};
}

// Wire a form to one operation: build() -> body, show(body, answer) renders.
export function runner(L, path, build, show) {
  const run = async () => {
    let body;
    try { body = build(); } catch (e) { L.problem.textContent = String(e); return; }
    L.curl.update(typeof path === 'function' ? path() : path, body);
    const r = await api(typeof path === 'function' ? path() : path, body);
    if (!r.ok) { showProblem(L.form, L.problem, r.status, r.body); L.form.dataset.state = 'error'; return; }
    clearErrors(L.form, L.problem);
    show(r.body, body);
    L.form.dataset.state = 'done';
  };
  L.form.addEventListener('submit', (e) => { e.preventDefault(); run(); });
  return run;
}
