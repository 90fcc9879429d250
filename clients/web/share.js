// share.js — a lab's whole state in its URL, so a copied link reproduces it,
// and Reset back to the defaults.
//
// The URL is #lab?name=value&…: the controls the student changed (inputs,
// selects: the form's values and the view's choices such as the exaggeration
// or the frame), the worked example loaded (ex=its title) and, in the link
// that "Copy link" makes, the time each animation shows (t0, t1, … as the
// slider's position 0…1000) and the camera of each 3-D view the student turned
// (v0, v1, … as yaw,pitch,zoom: view3d.js). A control is named by its id when the lab gave it
// one, else by its place among the lab's controls (c12); the example picker
// and the players' speed are not state. A lab whose form grows (the inertia
// lab's parts) keeps that structure in one hidden input of its own and marks
// the grown controls data-noshare. Only what the student touched is
// written, so a link stays short and the lab's later defaults still apply.
//
// Restoring (on a page opened at such a URL, or a link pasted into the tab):
// the example is loaded first, then the controls are set (with input and
// change events, so a slider's label follows) and every form holding one is
// submitted; once the runs have answered, the animations are put at their
// times and the 3-D views turned as they were. Reset opens #lab afresh (a reload: labs keep their inputs in module
// state between visits, which only a new page forgets).
import {el, examples} from './lib.js';

const AUTO_ID = /^(f|ex|anim|cost|v3d|view)\d+/; // ids lib.js, anim.js and view3d.js number as they go
const controls = (main) => [...main.querySelectorAll('input, select, textarea')].filter(c =>
  c.type !== 'button' && c.type !== 'submit' && c.type !== 'file' && c.type !== 'password' &&
  c.dataset.role !== 'examples' && c.dataset.role !== 'speed' && c.dataset.role !== 'time' && !c.closest('[data-noshare]'));
const keyOf = (c, i) => c.id && !AUTO_ID.test(c.id) ? c.id : 'c' + i;
const read = (c) => c.type === 'checkbox' ? (c.checked ? '1' : '0') : c.value;
function write(c, v) {
  if (read(c) === v) return true; // as it is: no events (a select's change may rebuild the form around it)
  if (c.type === 'checkbox') c.checked = v === '1';
  else if (c.tagName === 'SELECT' && ![...c.options].some(o => o.value === v)) return false; // an option the run has not offered yet
  else c.value = v;
  c.dispatchEvent(new Event('input', {bubbles: true}));
  c.dispatchEvent(new Event('change', {bubbles: true}));
  return true;
}

// The lab id and its state from a location's hash ("#spacetime?st-beta=0.9").
export function parseHash(hash) {
  const h = hash.replace(/^#/, ''), q = h.indexOf('?');
  return {id: q < 0 ? h : h.slice(0, q), params: new URLSearchParams(q < 0 ? '' : h.slice(q + 1))};
}

const settled = (main) => [...main.querySelectorAll('form[data-state]')].every(f => f.dataset.state !== 'busy');
const wait = (ms) => new Promise(r => setTimeout(r, ms));

// share(main, labId, params) after a lab is mounted: restores params, then
// keeps the address bar's #lab?… up to date as the student changes things,
// and puts a "Copy link" and a "Reset" button under the lab's title.
// Returns {link()} (the URL that reproduces the lab as it is now, with times).
let listening = null; // the AbortController of the mounted lab's listeners: a new mount takes them off
export function share(main, labId, params) {
  if (listening) listening.abort();
  const off = listening = new AbortController(), opts = {signal: off.signal};
  const dirty = new Map(); // key -> control the student changed
  let example = params.get('ex') || '';
  let restoring = false; // the events restore() sends are not the student's
  const list = () => controls(main);
  const index = () => new Map(list().map((c, i) => [keyOf(c, i), c]));
  // the values the lab started with: a field a handle changed (no input event) differs from them
  const init = new Map(list().map((c, i) => [keyOf(c, i), read(c)]));
  const state = (withTime) => {
    const q = new URLSearchParams();
    if (example) q.set('ex', example);
    const idx = index();
    for (const [k, c] of idx)
      // (a control named by its place may be another one after a redraw; one with an id is the same)
      if ((dirty.has(k) && (dirty.get(k) === c || !/^c\d+$/.test(k))) || (c.tagName !== 'SELECT' && init.has(k) && read(c) !== init.get(k))) q.set(k, read(c));
    if (withTime) main.querySelectorAll('[data-role=time]').forEach((s, k) => { if (!s.disabled && Number(s.value) > 0) q.set('t' + k, s.value); });
    main.querySelectorAll('canvas.view3d').forEach((cv, k) => {
      const cam = cv.camera && cv.camera.get();
      if (cam && cam.turned) q.set('v' + k, [cam.yaw, cam.pitch, cam.zoom].map(x => Number(x.toFixed(3))).join(','));
    });
    const s = q.toString();
    return '#' + labId + (s ? '?' + s : '');
  };
  let timer = 0;
  const update = () => { clearTimeout(timer); timer = setTimeout(() => {
    if (main.dataset.lab === labId && !off.signal.aborted) history.replaceState(null, '', location.pathname + location.search + state(false));
  }, 250); };
  const touched = (e) => {
    const c = e.target;
    if (restoring || !c.matches('input, select, textarea')) return;
    const i = list().indexOf(c);
    if (i < 0) return;
    dirty.set(keyOf(c, i), c); update();
  };
  main.addEventListener('input', touched, opts);
  main.addEventListener('change', touched, opts);
  window.addEventListener('mechd:moved', () => { if (!restoring) update(); }, opts); // a handle let go
  // loading a worked example: it sets the form, so what was changed before is no longer the state
  main.addEventListener('click', (e) => {
    const b = e.target.closest('.examples button');
    if (!b || !e.isTrusted) return;
    const sel = b.closest('.examples').querySelector('select');
    const opt = sel && sel.selectedOptions[0];
    if (opt) { example = opt.textContent; dirty.clear(); update(); }
  }, opts);

  // the bar: Copy link, Reset, and what they did
  const note = el('span', {class: 'muted', role: 'status', 'data-role': 'share-note'});
  const linkBox = el('input', {type: 'text', readonly: true, class: 'share-link', 'aria-label': 'Link to this lab as it is now',
    hidden: true, 'data-noshare': true});
  const link = () => location.origin + location.pathname + location.search + state(true);
  const bar = el('div', {class: 'share', role: 'group', 'aria-label': 'Share or reset this lab', 'data-noshare': true},
    el('button', {type: 'button', class: 'secondary small-btn', 'data-role': 'copy-link', onclick: async () => {
      const url = link();
      history.replaceState(null, '', location.pathname + location.search + state(true));
      linkBox.value = url; linkBox.hidden = false;
      try { await navigator.clipboard.writeText(url); note.textContent = 'Link copied: it opens this lab with these inputs, example, view and time.'; }
      catch (e) { linkBox.select(); note.textContent = 'Press Ctrl+C to copy the selected link.'; }
    }}, 'Copy link'),
    el('button', {type: 'button', class: 'secondary small-btn', 'data-role': 'reset', onclick: () => {
      location.hash = '#' + labId; // a fresh page: every input back to its default
      location.reload();
    }}, 'Reset'), note, linkBox);
  const h = main.querySelector('h2');
  main.insertBefore(bar, h ? h.nextSibling : main.firstChild);

  // restore what the URL says
  const restore = async () => {
    restoring = true;
    try { await restoreNow(); } finally { restoring = false; }
  };
  const restoreNow = async () => {
    if (example) {
      await examples();
      await wait(0);
      const pick = main.querySelector('.examples select');
      const opt = pick && [...pick.options].find(o => o.textContent === example);
      if (opt) { pick.value = opt.value; pick.closest('.examples').querySelector('button').click(); }
      else note.textContent = `The worked example “${example}” is not offered here.`;
    }
    const idx = index(), forms = new Set(), late = [];
    for (const [k, v] of params) {
      if (k === 'ex' || /^[tv]\d+$/.test(k)) continue;
      const c = idx.get(k);
      if (!c) continue;
      dirty.set(k, c);
      if (!write(c, v)) { late.push([c, v]); continue; }
      if (c.form) forms.add(c.form);
    }
    for (const f of forms) if (f.querySelector('[type=submit]')) f.requestSubmit();
    const times = [...params].filter(([k]) => /^t\d+$/.test(k)), cams = [...params].filter(([k]) => /^v\d+$/.test(k));
    if (!late.length && !times.length && !cams.length) return;
    // after the runs have answered: the choices their answers offer, then the times
    for (let k = 0; k < 150 && !(k > 2 && settled(main)); k++) await wait(100);
    for (const [c, v] of late) write(c, v);
    const sliders = main.querySelectorAll('[data-role=time]');
    for (const [k, v] of times) {
      const s = sliders[Number(k.slice(1))];
      if (s && !s.disabled) { s.value = v; s.dispatchEvent(new Event('input', {bubbles: true})); }
    }
    const canvases = main.querySelectorAll('canvas.view3d');
    for (const [k, v] of cams) {
      const cv = canvases[Number(k.slice(1))], [yaw, pitch, zoom] = v.split(',').map(Number);
      if (cv && cv.camera) cv.camera.set({yaw, pitch, zoom});
    }
  };
  const done = [...params].length ? restore() : Promise.resolve();
  main.dataset.restored = 'pending';
  done.then(() => { main.dataset.restored = 'done'; });
  return {link};
}

// Embedded in another site's page (?embed=1, or inside a frame): a compact
// layout (no tabs, footer or request box) and a link out to the full lab.
export function embedded() {
  let framed = false;
  try { framed = window.self !== window.top; } catch (e) { framed = true; }
  return new URLSearchParams(location.search).get('embed') === '1' || framed;
}
export function embedBar(labTitle) {
  return el('p', {class: 'embed-bar'}, el('a', {href: location.href.replace(/([?&])embed=1&?/, '$1').replace(/[?&]$/, ''),
    target: '_blank', rel: 'noopener'}, `Open the ${labTitle} lab in full ↗`));
}
