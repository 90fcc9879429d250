// Inertia lab: build a body from parts (POST /v1/rigid/inertia), see the
// tensor, the principal moments and the principal axes drawn over the body in
// a small 3D view (drag or arrow keys to rotate).
import {el, put, add, field, val, fmt, num, labLayout, runner, examplePicker} from '../lib.js';

const SHAPES = {
  box: [['size', 'size a b c', 3, [1, 1, 1]]],
  sphere: [['radius', 'radius', 1, 0.5]],
  cylinder: [['radius', 'radius', 1, 0.2], ['height', 'height', 1, 1]],
  rod: [['length', 'length', 1, 1]],
  point: [],
};

const BUILTIN = [
  {title: 'Cube about a corner (notes §2.4: moments M s²/6, 11 M s²/12, 11 M s²/12)', section: '2.4',
   operation: '/v1/rigid/inertia',
   request: {bodies: [{shape: 'box', mass: 1, size: [1, 1, 1], position: [0.5, 0.5, 0.5]}], origin: [0, 0, 0]}},
  {title: 'Dumbbell: two points on a rod', operation: '/v1/rigid/inertia',
   request: {bodies: [{shape: 'point', mass: 1, position: [-0.5, 0, 0]}, {shape: 'point', mass: 1, position: [0.5, 0, 0]},
     {shape: 'rod', mass: 0.2, length: 1, position: [0, 0, 0], orientation: {axis_angle: {axis: [0, 1, 0], angle: 1.5707963267948966}}}],
     origin: 'center_of_mass'}},
  {title: 'Solid sphere (2/5 M R²)', operation: '/v1/rigid/inertia',
   request: {bodies: [{shape: 'sphere', mass: 2, radius: 0.5, position: [0, 0, 0]}], origin: 'center_of_mass'}},
];

let state = null; // kept across re-mounts: the parts and the view angles

export default {
  id: 'inertia', title: 'Inertia',
  mount(main) {
    const L = labLayout(main, {title: 'Inertia tensor and principal axes',
      intro: 'Build a rigid body from parts. mechd returns the inertia tensor about the origin you choose, ' +
             'the principal moments and the principal axes, drawn over the body (drag or use the arrow keys to turn it).'});
    state = state || {req: structuredClone(BUILTIN[0].request), yaw: 0.6, pitch: 0.35, answer: null};
    const partsBox = el('div', {id: 'parts'});
    const originSel = field({label: 'Origin', pointer: '/origin', value: Array.isArray(state.req.origin) ? 'point' : 'center_of_mass',
      options: [['center_of_mass', 'centre of mass'], ['point', 'a point']], id: 'inertia-origin'});
    const o = Array.isArray(state.req.origin) ? state.req.origin : [0, 0, 0];
    const ox = o.map((v, k) => field({label: 'origin ' + 'xyz'[k], pointer: `/origin/${k}`, value: v, unit: 'm', cls: 'small',
      id: `inertia-origin-${k}`}));
    const w = Array.isArray(state.req.omega) ? state.req.omega : ['', '', ''];
    const om = w.map((v, k) => field({label: 'ω' + 'xyz'[k], pointer: `/omega/${k}`, value: v, unit: 'rad/s', cls: 'small',
      id: `inertia-omega-${k}`}));
    const rows = [];
    const renderParts = () => {
      rows.length = 0;
      put(partsBox, state.req.bodies.map((b, i) => {
        const p = `/bodies/${i}`;
        const shape = field({label: `Part ${i + 1} shape`, pointer: `${p}/shape`, value: b.shape,
          options: [...new Set([...Object.keys(SHAPES), b.shape])].map(s => [s, s]), id: `inertia-shape-${i}`});
        shape.input.addEventListener('change', () => {
          sync(); const nb = {shape: shape.input.value, mass: b.mass, position: b.position};
          for (const [k, , n, d] of SHAPES[nb.shape]) nb[k] = b[k] !== undefined && (n === 3) === Array.isArray(b[k]) ? b[k] : d;
          state.req.bodies[i] = nb; renderParts();
        });
        const mass = field({label: 'mass', pointer: `${p}/mass`, value: b.mass, unit: 'kg', id: `inertia-mass-${i}`});
        const dims = (SHAPES[b.shape] || []).flatMap(([k, lab, n]) => n === 3
          ? [0, 1, 2].map(j => field({label: `${lab.split(' ')[0]} ${'abc'[j]}`, pointer: `${p}/${k}/${j}`,
              value: (b[k] || [1, 1, 1])[j], unit: 'm', cls: 'small', id: `inertia-${k}-${i}-${j}`}))
          : [field({label: lab, pointer: `${p}/${k}`, value: b[k], unit: 'm', id: `inertia-${k}-${i}`})]);
        const pos = [0, 1, 2].map(j => field({label: 'position ' + 'xyz'[j], pointer: `${p}/position/${j}`,
          value: (b.position || [0, 0, 0])[j], unit: 'm', cls: 'small', id: `inertia-pos-${i}-${j}`}));
        rows.push({b, shape, mass, dims, pos});
        return el('fieldset', {class: 'part'}, el('legend', {}, `Part ${i + 1}`), shape.wrap, mass.wrap,
          dims.map(d => d.wrap), pos.map(d => d.wrap),
          el('button', {type: 'button', class: 'secondary', 'aria-label': `Remove part ${i + 1}`,
            disabled: state.req.bodies.length < 2, onclick: () => { sync(); state.req.bodies.splice(i, 1); renderParts(); }},
            'Remove part'));
      }));
    };
    // Read the controls back into state.req.
    const sync = () => {
      state.req.bodies = rows.map(({b, shape, mass, dims, pos}) => {
        const nb = {...b, shape: shape.input.value, mass: val(mass.input), position: pos.map(f => val(f.input))};
        let j = 0;
        for (const [k, , n] of SHAPES[nb.shape] || []) {
          if (n === 3) { nb[k] = [0, 1, 2].map(() => val(dims[j++].input)); } else nb[k] = val(dims[j++].input);
        }
        return nb;
      });
      state.req.origin = originSel.input.value === 'point' ? ox.map(f => val(f.input)) : 'center_of_mass';
      // ω is optional: all three empty leaves it out (then no L and T)
      if (om.every(f => f.input.value.trim() === '')) delete state.req.omega; else state.req.omega = om.map(f => val(f.input));
    };
    add(L.form,
      examplePicker(['/v1/rigid/inertia'], BUILTIN, (ex) => {
        // the form is rebuilt for the example's parts; the picker keeps showing it
        state.req = structuredClone(ex.request); state.answer = null; state.example = ex.id || ex.title;
        this.mount(main);
      }, {selected: state.example}),
      partsBox,
      el('div', {class: 'buttons'}, el('button', {type: 'button', class: 'secondary', onclick: () => {
        sync(); state.req.bodies.push({shape: 'point', mass: 1, position: [0, 0, 1]}); renderParts();
      }}, 'Add part')),
      el('fieldset', {}, el('legend', {}, 'Tensor about'), originSel.wrap, ox.map(f => f.wrap)),
      el('fieldset', {}, el('legend', {}, 'Turning at ω (optional)'), om.map(f => f.wrap),
        el('p', {class: 'muted'}, 'Give ω to see the angular momentum L = I ω and the kinetic energy ½ ω·L.')),
      el('div', {class: 'buttons'}, el('button', {type: 'submit', id: 'inertia-submit'}, 'Compute')));
    renderParts();
    const canvas = el('canvas', {class: 'plot', width: 640, height: 480, tabindex: 0, id: 'inertia-view',
      'aria-label': 'The body and its principal axes in 3D; arrow keys rotate the view'});
    add(L.figure, el('h3', {}, 'Body and principal axes'), canvas,
      el('p', {class: 'muted'}, 'Principal axes: ', el('span', {class: 'c1'}, 'e₁'), ', ', el('span', {class: 'c2'}, 'e₂'),
        ', ', el('span', {class: 'c3'}, 'e₃'), ' (lengths ∝ moments), from the origin of the tensor.'));
    const draw = () => { fitCanvas(canvas); drawBody(canvas, state); };
    if (typeof ResizeObserver === 'function') new ResizeObserver(() => draw()).observe(canvas);
    let drag = null;
    canvas.addEventListener('pointerdown', (e) => { drag = [e.clientX, e.clientY]; canvas.setPointerCapture(e.pointerId); });
    canvas.addEventListener('pointermove', (e) => {
      if (!drag) return;
      state.yaw += (e.clientX - drag[0]) * 0.01; state.pitch += (e.clientY - drag[1]) * 0.01;
      drag = [e.clientX, e.clientY]; draw();
    });
    canvas.addEventListener('pointerup', () => { drag = null; });
    canvas.addEventListener('keydown', (e) => {
      const d = {ArrowLeft: [-0.1, 0], ArrowRight: [0.1, 0], ArrowUp: [0, -0.1], ArrowDown: [0, 0.1]}[e.key];
      if (d) { e.preventDefault(); state.yaw += d[0]; state.pitch += d[1]; draw(); }
    });
    const run = runner(L, '/v1/rigid/inertia', () => { sync(); return structuredClone(state.req); }, (a) => {
      state.answer = a;
      const m = a.principal.moments;
      // round-off next to zero (a dumbbell's 7e-17 about its axis) reads 0; data-value keeps the number
      const scale = Math.max(...m.map(Math.abs)), zero = (v, s) => (Math.abs(v) < 1e-12 * s ? 0 : v);
      put(L.results, el('h3', {}, 'Answer'),
        el('dl', {class: 'nums'}, el('dt', {}, 'mass'), num('inertia-total-mass', a.mass, 'kg'),
          el('dt', {}, 'centre of mass'), el('dd', {}, a.center_of_mass.map(v => fmt(v)).join(', ') + ' m'),
          el('dt', {}, 'principal moments'), el('dd', {}, ''),
          ...m.flatMap((v, k) => [el('dt', {}, `I${k + 1}`),
            el('dd', {id: `inertia-moment-${k}`, 'data-value': String(v)}, fmt(zero(v, scale)) + ' kg m²')])),
        el('p', {}, 'Tensor about ', Array.isArray(a.origin) ? `(${a.origin.map(v => fmt(v)).join(', ')})` : 'the centre of mass', ' [kg m²]:'),
        el('table', {id: 'inertia-tensor'}, a.tensor.map(r => el('tr', {}, r.map(v => el('td', {}, fmt(zero(v, scale))))))),
        el('p', {}, 'Principal axes (rows):'),
        el('table', {id: 'inertia-axes'}, a.principal.axes.map((r, k) => el('tr', {}, el('th', {class: 'c' + (k + 1)}, `e${k + 1}`),
          r.map(v => el('td', {}, fmt(Math.abs(v) < 1e-15 ? 0 : v)))))),
        a.principal.degenerate ? el('p', {class: 'muted'}, 'Two or more moments are equal: any axes in that plane are principal.') : null,
        Array.isArray(a.angular_momentum) ? el('dl', {class: 'nums'},
          el('dt', {}, 'ω'), el('dd', {}, `(${state.req.omega.map(v => fmt(v)).join(', ')}) rad/s`),
          el('dt', {}, 'L = I ω'), el('dd', {id: 'inertia-L'}, `(${a.angular_momentum.map(v => fmt(v)).join(', ')}) kg m²/s`),
          el('dt', {}, 'kinetic energy'), num('inertia-T', a.kinetic_energy, 'J')) : null);
      draw();
    });
    draw();
    run();
  },
};

// --- a tiny 3D wireframe renderer -------------------------------------------
// The canvas' pixel size follows its laid-out size (× devicePixelRatio), so its
// labels are drawn at their nominal CSS px size on a phone as on a desktop.
function fitCanvas(canvas) {
  const w = Math.round(canvas.getBoundingClientRect().width);
  if (!w) return;
  const dpr = window.devicePixelRatio || 1, W = Math.round(w * dpr), H = Math.round(w * 0.75 * dpr);
  if (canvas.width !== W || canvas.height !== H) { canvas.width = W; canvas.height = H; }
  canvas.dataset.px = String(dpr);
}
function project(p, st, W, H, s) {
  const [cy, sy, cp, sp] = [Math.cos(st.yaw), Math.sin(st.yaw), Math.cos(st.pitch), Math.sin(st.pitch)];
  const x1 = cy * p[0] - sy * p[1], y1 = sy * p[0] + cy * p[1];
  const z2 = cp * p[2] - sp * y1, y2 = sp * p[2] + cp * y1;
  return [W / 2 + s * x1, H / 2 - s * z2, y2];
}
function orient(b) {
  const aa = b.orientation && b.orientation.axis_angle;
  if (!aa) return (v) => v;
  const n = Math.hypot(...aa.axis) || 1, [x, y, z] = aa.axis.map(c => c / n), c = Math.cos(aa.angle), s = Math.sin(aa.angle);
  return (v) => [
    (c + x * x * (1 - c)) * v[0] + (x * y * (1 - c) - z * s) * v[1] + (x * z * (1 - c) + y * s) * v[2],
    (y * x * (1 - c) + z * s) * v[0] + (c + y * y * (1 - c)) * v[1] + (y * z * (1 - c) - x * s) * v[2],
    (z * x * (1 - c) - y * s) * v[0] + (z * y * (1 - c) + x * s) * v[1] + (c + z * z * (1 - c)) * v[2]];
}
function drawBody(canvas, st) {
  const ctx = canvas.getContext('2d'), W = canvas.width, H = canvas.height, px = Number(canvas.dataset.px || W / 640);
  ctx.clearRect(0, 0, W, H);
  const bodies = st.req.bodies.filter(b => b.position && b.position.every(isFinite));
  const org = st.answer ? (Array.isArray(st.answer.origin) ? st.answer.origin : st.answer.center_of_mass) : [0, 0, 0];
  let ext = 0.5;
  for (const b of bodies) ext = Math.max(ext, ...b.position.map(v => Math.abs(v - 0)) , (b.radius || 0) + 0.1,
    ...(b.size || [0]).map(v => v / 2 + 0.1), (b.length || 0) / 2, (b.height || 0) / 2);
  const s = Math.min(W, H) / (3.2 * ext);
  const P = (v) => project(v, st, W, H, s);
  const line = (a, b, color, w = 2) => { const [p, q] = [P(a), P(b)]; ctx.strokeStyle = color; ctx.lineWidth = w * px;
    ctx.beginPath(); ctx.moveTo(p[0], p[1]); ctx.lineTo(q[0], q[1]); ctx.stroke(); };
  // scene axes
  for (let k = 0; k < 3; k++) { const e = [0, 0, 0]; e[k] = ext * 1.2; line([0, 0, 0], e, '#aaa', 1);
    const t = P(e); ctx.fillStyle = '#666'; ctx.font = `${16 * px}px system-ui`; ctx.fillText('xyz'[k], t[0] + 4 * px, t[1]); }
  for (const b of bodies) {
    const R = orient(b), at = (v) => { const r = R(v); return [r[0] + b.position[0], r[1] + b.position[1], r[2] + b.position[2]]; };
    const col = '#333';
    if (b.shape === 'box' && b.size) {
      const h = b.size.map(v => v / 2), c = [];
      for (let i = 0; i < 8; i++) c.push(at([(i & 1 ? 1 : -1) * h[0], (i & 2 ? 1 : -1) * h[1], (i & 4 ? 1 : -1) * h[2]]));
      for (let i = 0; i < 8; i++) for (const bit of [1, 2, 4]) if (!(i & bit)) line(c[i], c[i | bit], col);
    } else if (b.shape === 'rod') {
      line(at([0, 0, -b.length / 2]), at([0, 0, b.length / 2]), col, 4);
    } else if (b.shape === 'cylinder' || b.shape === 'sphere') {
      const rings = b.shape === 'sphere' ? [[0, 'xy'], [0, 'xz'], [0, 'yz']] : [[-b.height / 2, 'xy'], [b.height / 2, 'xy']];
      for (const [z0, pl] of rings) {
        ctx.beginPath();
        for (let i = 0; i <= 48; i++) {
          const a = 2 * Math.PI * i / 48, u = b.radius * Math.cos(a), v = b.radius * Math.sin(a);
          const loc = pl === 'xy' ? [u, v, z0] : pl === 'xz' ? [u, 0, v] : [0, u, v];
          const q = P(at(loc)); i ? ctx.lineTo(q[0], q[1]) : ctx.moveTo(q[0], q[1]);
        }
        ctx.strokeStyle = col; ctx.lineWidth = 2 * px; ctx.stroke();
      }
      if (b.shape === 'cylinder') for (const a of [0, Math.PI / 2, Math.PI, 1.5 * Math.PI])
        line(at([b.radius * Math.cos(a), b.radius * Math.sin(a), -b.height / 2]), at([b.radius * Math.cos(a), b.radius * Math.sin(a), b.height / 2]), col);
    }
    const q = P(b.position); ctx.fillStyle = col; ctx.beginPath(); ctx.arc(q[0], q[1], (b.shape === 'point' ? 7 : 3) * px, 0, 7); ctx.fill();
  }
  if (st.answer) {
    const m = st.answer.principal.moments, mmax = Math.max(...m.map(Math.abs)) || 1;
    const colors = ['#c92a2a', '#2b8a3e', '#1864ab'];
    st.answer.principal.axes.forEach((ax, k) => {
      const L = ext * (0.5 + 0.9 * Math.abs(m[k]) / mmax);
      const tip = [org[0] + L * ax[0], org[1] + L * ax[1], org[2] + L * ax[2]];
      line([org[0] - L * ax[0], org[1] - L * ax[1], org[2] - L * ax[2]], tip, colors[k], 4);
      const t = P(tip); ctx.fillStyle = colors[k]; ctx.font = `bold ${20 * px}px system-ui`; ctx.fillText('e' + (k + 1), t[0] + 5 * px, t[1] - 5 * px);
    });
    const c = P(st.answer.center_of_mass); ctx.strokeStyle = '#e67700'; ctx.lineWidth = 3 * px;
    ctx.beginPath(); ctx.arc(c[0], c[1], 9 * px, 0, 7); ctx.stroke();
  }
}
