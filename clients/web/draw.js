// draw.js — small pieces of the live view drawn on a lab's SVG pictures: an
// arrow on a moving body (a velocity, a force) and a row of energy bars whose
// sum shows what is conserved. Only drawing: the values come from the lab.
import {svg, add, put, amount} from './lib.js';

// arrow(x1, y1, x2, y2, color, name) -> an SVG <g data-role="vector" data-name=name>: a line from
// (x1, y1) to (x2, y2) in the picture's user units with its head and the name by the tip.
export function arrow(x1, y1, x2, y2, color, text, size = 13) {
  const g = svg('g', {'data-role': 'vector', 'data-name': text});
  const a = Math.atan2(y2 - y1, x2 - x1), L = Math.hypot(x2 - x1, y2 - y1), h = Math.min(10, L / 2);
  add(g, svg('line', {x1, y1, x2, y2, stroke: color, 'stroke-width': 3}));
  if (L > 2) add(g, svg('path', {d: `M ${x2} ${y2} L ${x2 - h * Math.cos(a - 0.45)} ${y2 - h * Math.sin(a - 0.45)} ` +
    `L ${x2 - h * Math.cos(a + 0.45)} ${y2 - h * Math.sin(a + 0.45)} z`, fill: color}),
    svg('text', {x: x2 + 5, y: y2 - 4, 'font-size': size, 'font-weight': 700, fill: color}, text));
  return g;
}

// energyBars(root, [[name, value, colour], …], ref, what, unit): bars on a baseline (negative values
// below it), heights against ref (in the unit, J by default: the largest size expected), each bar's name
// and value (with an SI prefix: 96 kJ), and the whole said in root's aria-label ("what: name value, …").
export function energyBars(root, bars, ref, what = 'energy', unit = 'J') {
  // three bars in 300 units (shown at most 300 px wide), four or more 90 units each in a wider picture (style.css:
  // .wide, at most 400 px), so the names and values keep their 12 px on a phone
  const wide = bars.length > 3, W = wide ? 40 + bars.length * 90 : 300, step = wide ? 90 : 96;
  const H = 170, base = 92, k = 62 / (Math.abs(ref) || 1), w = 60;
  put(root); root.setAttribute('viewBox', `0 0 ${W} ${H}`); root.classList.toggle('wide', wide);
  add(root, svg('line', {x1: 8, y1: base, x2: W - 8, y2: base, stroke: '#555'}));
  bars.forEach(([name, v, c], i) => {
    const x = 20 + i * step, h = Math.max(-60, Math.min(72, v * k));
    add(root, svg('rect', {x, y: h >= 0 ? base - h : base, width: w, height: Math.abs(h), fill: c, 'data-role': 'bar', 'data-value': String(v)}),
      svg('text', {x: x + w / 2, y: 14, 'font-size': 12, 'text-anchor': 'middle', fill: '#333'}, name),
      svg('text', {x: x + w / 2, y: H - 2, 'font-size': 12, 'text-anchor': 'middle', fill: '#333'}, amount(v, unit)));
  });
  root.setAttribute('aria-label', `${what}: ` + bars.map(([n, v]) => `${n} ${amount(v, unit)}`).join(', '));
}
