// handles.js — draggable handles on the physical objects of a picture (an
// event on the Minkowski diagram, a puck's start and velocity, a launch
// velocity, a planet's perihelion, a top's tilt): dragged with a pointer (a
// mouse, a finger) or, focused, moved with the arrow keys. Each handle is an
// SVG <g role="slider"> with its value in physical units in aria-valuetext.
//
// The lab gives the handle its place in the picture's own units and the
// picture's scales (X, Y: units -> SVG user units, with .invert), and
// onMove(x, y) which sets the lab's inputs and asks for the answer again
// (through rerun(): debounced, and the runner cancels the request still on
// its way). The picture is redrawn with each answer, so a handle is made anew
// each time: a drag in progress and the keyboard focus carry over to the new
// one (same id).
import {svg, add} from './lib.js';

const live = new Map(); // id -> {root, X, Y, onMove, at}: the newest handle of that id
let drag = null;        // {id, dx, dy}: the handle being dragged (offset of the grab from its centre)
let focusId = null;     // the handle that had the keyboard focus

function toUnits(spec, e) {
  const r = spec.root.getBoundingClientRect(), vb = spec.root.viewBox.baseVal;
  const k = vb && vb.width ? vb.width / r.width : 1;
  const px = (e.clientX - r.left) * k - drag.dx, py = (e.clientY - r.top) * k - drag.dy;
  return [spec.X.invert(px), spec.Y.invert(py), px, py];
}
window.addEventListener('pointermove', (e) => {
  if (!drag) return;
  const spec = live.get(drag.id);
  if (!spec) return;
  e.preventDefault();
  const [x, y, px, py] = toUnits(spec, e);
  const g = document.getElementById(drag.id);
  if (g) g.setAttribute('transform', `translate(${px - spec.X(spec.at[0])} ${py - spec.Y(spec.at[1])})`); // follows the finger at once
  spec.onMove(x, y, false);
}, {passive: false});
const end = (e) => {
  if (!drag) return;
  const spec = live.get(drag.id);
  if (spec && e.type === 'pointerup') { const [x, y] = toUnits(spec, e); spec.onMove(x, y, true); window.dispatchEvent(new Event('mechd:moved')); }
  drag = null;
  document.body.classList.remove('dragging');
};
window.addEventListener('pointerup', end);
window.addEventListener('pointercancel', end);

// handle(root, {id, X, Y, at: [x, y], label, text(x, y), step: [dx, dy], onMove(x, y, done), axes: 'xy' | 'x' | 'y',
//   color, shape: 'dot' | 'ring'}) -> an SVG <g> to add to root (an <svg> with a viewBox).
//   X, Y: scales from the picture's units to user units, with .invert. step: what one arrow key press moves
//   (Shift: ten times, PageUp/PageDown: ten times along y, Home/End not used). axes: which arrows move it.
//   text(x, y): the value in words with units ("ct = 1.5 s, x = 0.5 ls"), read by screen readers.
//   nudge(sign, big) -> [x, y]: for a handle that moves along a curve (an angle on a dial), where one arrow key
//   press takes it (sign +1: Right or Up, −1: Left or Down; big: Shift or Page keys); replaces step and axes.
export function handle(root, {id, X, Y, at, label, text, step = [0.1, 0.1], onMove, axes = 'xy', color = '#111', r = 9, nudge}) {
  const spec = {root, X, Y, at, onMove};
  live.set(id, spec);
  const cx = X(at[0]), cy = Y(at[1]);
  const g = svg('g', {id, class: 'handle', role: 'slider', tabindex: 0, 'aria-label': label,
    'aria-valuenow': Number((axes === 'y' ? at[1] : at[0]).toPrecision(6)), 'aria-valuetext': text(at[0], at[1]),
    'aria-orientation': axes === 'y' ? 'vertical' : 'horizontal', 'data-x': String(at[0]), 'data-y': String(at[1])});
  add(g, svg('circle', {cx, cy, r: 22, fill: 'transparent', class: 'handle-hit'}), // a finger-sized target
    svg('circle', {cx, cy, r, fill: '#fff', stroke: color, 'stroke-width': 3, class: 'handle-ring'}),
    svg('circle', {cx, cy, r: 3, fill: color}));
  g.addEventListener('pointerdown', (e) => {
    if (e.button !== 0) return;
    e.preventDefault();
    const r0 = root.getBoundingClientRect(), vb = root.viewBox.baseVal, k = vb && vb.width ? vb.width / r0.width : 1;
    drag = {id, dx: (e.clientX - r0.left) * k - cx, dy: (e.clientY - r0.top) * k - cy};
    document.body.classList.add('dragging');
    g.focus();
  });
  g.addEventListener('keydown', (e) => {
    if (nudge) {
      const sign = {ArrowRight: 1, ArrowUp: 1, PageUp: 1, ArrowLeft: -1, ArrowDown: -1, PageDown: -1}[e.key];
      if (!sign) return;
      e.preventDefault();
      const s = live.get(id), [nx, ny] = nudge(sign, e.shiftKey || e.key.startsWith('Page'), s.at);
      s.at = [nx, ny];
      const t = g.isConnected ? g : document.getElementById(id);
      if (t) t.setAttribute('aria-valuetext', text(nx, ny));
      s.onMove(nx, ny, true);
      window.dispatchEvent(new Event('mechd:moved'));
      return;
    }
    const big = e.shiftKey ? 10 : 1;
    let dx = 0, dy = 0;
    if (e.key === 'ArrowLeft' && axes !== 'y') dx = -step[0];
    else if (e.key === 'ArrowRight' && axes !== 'y') dx = step[0];
    else if (e.key === 'ArrowUp' && axes !== 'x') dy = step[1];
    else if (e.key === 'ArrowDown' && axes !== 'x') dy = -step[1];
    else if (e.key === 'ArrowUp' && axes === 'x') dx = step[0];
    else if (e.key === 'ArrowDown' && axes === 'x') dx = -step[0];
    else if (e.key === 'PageUp') { if (axes === 'x') dx = 10 * step[0]; else dy = 10 * step[1]; }
    else if (e.key === 'PageDown') { if (axes === 'x') dx = -10 * step[0]; else dy = -10 * step[1]; }
    else return;
    e.preventDefault();
    const s = live.get(id);
    // round to the step, so that keys walk through round values (0.5, 0.6 …), not 0.6000000000000001
    const snap = (v, d) => { const q = Math.abs(d) / big || 1, n = Math.round(v / q) * q; return Number(n.toPrecision(12)); };
    const nx = dx ? snap(s.at[0] + dx * big, dx) : s.at[0], ny = dy ? snap(s.at[1] + dy * big, dy) : s.at[1];
    s.at = [nx, ny];
    const t = g.isConnected ? g : document.getElementById(id);
    if (t) t.setAttribute('aria-valuetext', text(nx, ny));
    s.onMove(nx, ny, true);
    window.dispatchEvent(new Event('mechd:moved')); // the address bar follows (share.js)
  });
  g.addEventListener('focus', () => { focusId = id; });
  // a blur because the picture was redrawn (this handle removed) keeps the focus for the new one; one because
  // the student moved on (this handle still there) does not
  g.addEventListener('blur', () => setTimeout(() => { if (g.isConnected && focusId === id) focusId = null; }, 0));
  // the keyboard focus stays on the handle when its picture is redrawn
  if (focusId === id) queueMicrotask(() => { if (g.isConnected && (!document.activeElement || document.activeElement === document.body)) g.focus(); });
  return g;
}

// rerun(run, ms): a function that asks run() again after ms of quiet (the
// runner cancels a request still on its way, so a drag sends what is needed).
export function rerun(run, ms = 120) {
  let t = 0;
  return (now) => { clearTimeout(t); if (now) run(); else t = setTimeout(run, ms); };
}
