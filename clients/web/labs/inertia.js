// Inertia lab: build a body from parts (POST /v1/rigid/inertia), see the
// tensor, the principal moments and the principal axes drawn over the body in
// a small 3D view (drag or arrow keys to rotate).
import {el, svg, put, add, field, val, fmt, num, labLayout, runner, examplePicker, notesBox} from '../lib.js';
import {handle, rerun} from '../handles.js';
import {THREE, view3d, axesArrows, sceneAxes, label as tag} from '../view3d.js';

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
    state = state || {req: structuredClone(BUILTIN[0].request), answer: null};
    // the parts (their number, shapes, sizes, positions, orientations) travel in a link as one hidden input
    // holding them as JSON (share.js): its own controls are rebuilt with each part added or removed
    const partsBox = el('div', {id: 'parts', 'data-noshare': true});
    const partsState = el('input', {type: 'hidden', id: 'inertia-parts', value: JSON.stringify(state.req.bodies)});
    const publish = () => { // the parts as they stand, told to the address bar when they changed
      const v = JSON.stringify(state.req.bodies);
      if (v !== partsState.value) { partsState.value = v; partsState.dispatchEvent(new Event('input', {bubbles: true})); }
    };
    partsState.addEventListener('change', () => { // a link's parts (share.js restores them)
      let b = null;
      try { b = JSON.parse(partsState.value); } catch (e) { b = null; }
      if (!Array.isArray(b) || !b.length || b.length > 64 || !b.every(x => x && typeof x === 'object' && typeof x.shape === 'string')) return;
      state.req.bodies = b; renderParts(); drawPlan();
    });
    partsBox.addEventListener('change', () => { sync(); publish(); });
    const originSel = field({label: 'Origin', pointer: '/origin', value: Array.isArray(state.req.origin) ? 'point' : 'center_of_mass',
      options: [['center_of_mass', 'centre of mass'], ['point', 'a point']], id: 'inertia-origin'});
    const o = Array.isArray(state.req.origin) ? state.req.origin : [0, 0, 0];
    const ox = o.map((v, k) => field({label: 'origin ' + 'xyz'[k], pointer: `/origin/${k}`, value: v, unit: 'm', cls: 'small',
      id: `inertia-origin-${k}`}));
    const w = Array.isArray(state.req.omega) ? state.req.omega : ['', '', ''];
    const om = w.map((v, k) => field({label: 'ω' + 'xyz'[k], pointer: `/omega/${k}`, value: v, unit: 'rad/s', cls: 'small',
      id: `inertia-omega-${k}`}));
    // rolling down an incline (optional: the slope's angle and the rolling radius ask for it)
    const inc = state.req.incline || {};
    const incAngle = field({label: 'slope angle', pointer: '/incline/angle_deg', value: inc.angle_deg ?? '', unit: '°', id: 'inertia-inc-angle',
      help: 'between 0° and 90°'});
    const incRadius = field({label: 'rolling radius', pointer: '/incline/radius', value: inc.radius ?? '', unit: 'm', id: 'inertia-inc-radius',
      help: 'rolling axis to the slope'});
    const incAxis = (inc.axis || [0, 0, 1]).map((v, k) => field({label: 'rolling axis ' + 'xyz'[k], pointer: `/incline/axis/${k}`, value: v,
      cls: 'small', id: `inertia-inc-axis-${k}`}));
    const incLength = field({label: 'distance rolled', pointer: '/incline/length', value: inc.length ?? '', unit: 'm', id: 'inertia-inc-length',
      help: 'optional: adds the time and speed'});
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
          state.req.bodies[i] = nb; renderParts(); publish();
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
            disabled: state.req.bodies.length < 2, onclick: () => { sync(); state.req.bodies.splice(i, 1); renderParts(); publish(); }},
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
      // the incline: asked for when its angle or radius is given (the distance is optional)
      if (incAngle.input.value.trim() === '' && incRadius.input.value.trim() === '') delete state.req.incline;
      else {
        state.req.incline = {angle_deg: val(incAngle.input), radius: val(incRadius.input), axis: incAxis.map(f => val(f.input))};
        if (incLength.input.value.trim() !== '') state.req.incline.length = val(incLength.input);
      }
    };
    add(L.form,
      examplePicker(['/v1/rigid/inertia'], BUILTIN, (ex) => {
        // the form is rebuilt for the example's parts; the picker keeps showing it
        state.req = structuredClone(ex.request); state.answer = null; state.example = ex.id || ex.title;
        // Copy link and Reset (share.js) stay under the title, the embedded page's link out at the end
        const bar = main.querySelector(':scope > .share'), out = main.querySelector(':scope > .embed-bar');
        this.mount(main);
        const h = main.querySelector('h2');
        if (bar && h) h.after(bar);
        if (out) add(main, out);
      }, {selected: state.example}),
      partsState, partsBox,
      el('div', {class: 'buttons'}, el('button', {type: 'button', class: 'secondary', id: 'inertia-add-part', onclick: () => {
        sync(); state.req.bodies.push({shape: 'point', mass: 1, position: [0, 0, 1]}); renderParts(); publish();
      }}, 'Add part')),
      el('fieldset', {}, el('legend', {}, 'Tensor about'), originSel.wrap, ox.map(f => f.wrap)),
      el('fieldset', {}, el('legend', {}, 'Turning at ω (optional)'), om.map(f => f.wrap),
        el('p', {class: 'muted'}, 'Give ω to see the angular momentum L = I ω and the kinetic energy ½ ω·L.')),
      el('fieldset', {}, el('legend', {}, 'Rolling down an incline (optional)'), incAngle.wrap, incRadius.wrap, incAxis.map(f => f.wrap), incLength.wrap,
        el('p', {class: 'muted'}, 'The body rolls without slipping from rest about the rolling axis through its centre of mass ',
          '(a ball or a cylinder: its radius; a cylinder as built rolls about z).')),
      el('div', {class: 'buttons'}, el('button', {type: 'submit', id: 'inertia-submit'}, 'Compute')));
    renderParts();
    const box3d = el('div', {class: 'view3d-box'});
    add(L.figure, el('h3', {}, 'Body, principal axes and ellipsoid of inertia'), box3d,
      el('p', {class: 'muted'}, 'The parts as solids (the centre of mass ', el('span', {class: 'c4'}, '○'), '); principal axes ',
        el('span', {class: 'c1'}, 'e₁'), ', ', el('span', {class: 'c2'}, 'e₂'), ', ', el('span', {class: 'c3'}, 'e₃'),
        ' from the origin of the tensor (lengths ∝ moments); the grey ellipsoid of inertia x·I x = const has semi-axes ∝ 1/√Iₖ ',
        '(longest along the smallest moment; capped at 3× the shortest where a moment is near zero). Drag, or focus it and use the arrow keys, to turn it.'));
    const V = view3d(box3d, {label: 'The body, its principal axes and ellipsoid of inertia in 3-D', id: 'inertia-view'});
    if (state.cam) for (const k of ['yaw', 'pitch', 'zoom', 'turned']) V.view[k] = state.cam[k]; // the view as it was turned
    state.cam = V.view;
    const world = new THREE.Group();
    V.scene.add(world);
    const draw = () => { drawBody(world, state); V.frame(extentOf(state) * 1.45); };
    const notes = notesBox('inertia-notes'); L.figure.after(notes.box); // under the figure: the picture stays by the answer
    const run = runner(L, '/v1/rigid/inertia', () => { sync(); publish(); return structuredClone(state.req); }, (a) => {
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
          el('dt', {}, 'kinetic energy'), num('inertia-T', a.kinetic_energy, 'J')) : null,
        a.incline ? rolling(a.incline, state.req.incline) : null);
      // notes §2.3 Parallel Axis Theorem: about a point O with the centre of mass at a from it,
      // I_ij = I_ij(cm) + M (a² δ_ij − a_i a_j); computed here from the API's tensor about the centre of mass
      const o = Array.isArray(a.origin) ? a.origin : a.center_of_mass, d = a.center_of_mass.map((c, k) => c - o[k]);
      const d2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2], Icm = a.tensor_center_of_mass;
      if (Array.isArray(Icm)) {
        const P = Icm.map((row, i) => row.map((v, j) => v + a.mass * ((i === j ? d2 : 0) - d[i] * d[j])));
        const big = Math.max(...a.tensor.flat().map(Math.abs)) || 1;
        const abs = Math.max(...P.flatMap((row, i) => row.map((v, j) => Math.abs(v - a.tensor[i][j]))));
        const show = (T) => `I_xx = ${fmt(T[0][0], 7)}, I_xy = ${fmt(T[0][1], 7)}, I_zz = ${fmt(T[2][2], 7)} kg m²`;
        notes.update({section: '2.3', heading: 'Parallel Axis Theorem',
          formula: ['I', el('sub', {}, 'ij'), ' = I', el('sub', {}, 'ij'), el('sup', {}, '(cm)'), ' + M (a² δ', el('sub', {}, 'ij'),
            ' − a', el('sub', {}, 'i'), ' a', el('sub', {}, 'j'), '),  a = the centre of mass seen from the origin'],
          what: 'the parallel-axis tensor', formulaShown: show(P), apiShown: show(a.tensor), abs, rel: abs / big, unit: 'kg m²',
          sourceText: 'computed in this page from the API\'s tensor about the centre of mass, the mass and a',
          how: d2 === 0 ? 'The origin is the centre of mass: a = 0 and the theorem adds nothing.'
            : `The tensor about the origin, a = (${d.map(v => fmt(v, 4)).join(', ')}) m; the difference is the largest of the nine entries'.`,
          note: 'The notes\' worked example, a cube of side s about a corner: I = M s² (⅔ δ − ¼) (§2.4, its number read from the contents), ' +
            'principal moments M s²/6 and 11 M s²/12 twice (§2.5, Example: Cube Rotating about a Corner).'});
      }
      draw();
      drawPlan();
    });
    // the parts seen from above (x right, y up): each part's position a handle to drag (or arrow keys, 0.1 m)
    const plan = svg('svg', {class: 'plot dial', id: 'inertia-plan', role: 'group',
      'aria-label': 'The parts from above: drag a part to move it in x and y, or focus it and use the arrow keys'});
    add(L.figure, el('h3', {}, 'The parts from above: drag one to move it'), plan,
      el('p', {class: 'muted'}, 'Each part at its position in x and y (z stays as typed); the ring is the centre of mass.'));
    let planR = null;
    const again = rerun(() => run(), 150);
    const drawPlan = () => {
      const ps = rows.map(r => r.pos.map(f => val(f.input)));
      const R = planR || Math.max(1, ...ps.flatMap(p => [Math.abs(p[0]), Math.abs(p[1])]).filter(Number.isFinite)) * 1.4;
      const W = 300, H = 300, k = (W / 2 - 16) / R;
      put(plan); plan.setAttribute('viewBox', `0 0 ${W} ${H}`);
      const X = (x) => W / 2 + k * x, Y = (y) => H / 2 - k * y;
      X.invert = (p) => (p - W / 2) / k; Y.invert = (p) => (H / 2 - p) / k;
      add(plan, svg('line', {x1: 8, y1: Y(0), x2: W - 8, y2: Y(0), stroke: '#aaa'}), svg('line', {x1: X(0), y1: 8, x2: X(0), y2: H - 8, stroke: '#aaa'}),
        svg('text', {x: W - 12, y: Y(0) - 6, 'font-size': 13, fill: '#444'}, 'x'), svg('text', {x: X(0) + 6, y: 18, 'font-size': 13, fill: '#444'}, 'y'),
        svg('text', {x: 8, y: H - 8, 'font-size': 12, fill: '#444'}, `±${fmt(Number(R.toPrecision(2)))} m`));
      const cm = state.answer && state.answer.center_of_mass;
      if (cm) add(plan, svg('circle', {cx: X(cm[0]), cy: Y(cm[1]), r: 6, fill: 'none', stroke: '#a65300', 'stroke-width': 2}));
      ps.forEach((p, i) => {
        if (!Number.isFinite(p[0]) || !Number.isFinite(p[1])) return;
        add(plan, handle(plan, {id: `inertia-part-${i}`, X, Y, at: [p[0], p[1]], step: [0.1, 0.1], color: '#1864ab',
          label: `part ${i + 1} (${rows[i].shape.input.value})`,
          text: (x, y) => `part ${i + 1} at x = ${fmt(x, 3)} m, y = ${fmt(y, 3)} m, z = ${fmt(p[2], 3)} m`,
          onMove: (x, y, done) => {
            rows[i].pos[0].input.value = Number(x.toFixed(2)); rows[i].pos[1].input.value = Number(y.toFixed(2));
            planR = done ? null : R; drawPlan(); again(done);
          }}),
        svg('text', {x: X(p[0]) + 12, y: Y(p[1]) - 10, 'font-size': 13, fill: '#1864ab', 'font-weight': 700}, String(i + 1)));
      });
    };
    draw();
    drawPlan();
    run();
  },
};

// --- the body in 3-D (three.js) -------------------------------------------------
// A part's rotation from its orientation.axis_angle (identity without one).
function orient(b) {
  const aa = b.orientation && b.orientation.axis_angle, q = new THREE.Quaternion();
  if (aa && Array.isArray(aa.axis) && Math.hypot(...aa.axis) > 0)
    q.setFromAxisAngle(new THREE.Vector3(...aa.axis).normalize(), aa.angle || 0);
  return q;
}
const okPart = (b) => Array.isArray(b.position) && b.position.length === 3 && b.position.every(Number.isFinite);
// The scene's radius: every part's reach from the origin.
function extentOf(st) {
  let ext = 0.5;
  for (const b of st.req.bodies.filter(okPart)) {
    const r = Math.max((b.radius || 0), ...(Array.isArray(b.size) ? b.size.map(v => (v || 0) / 2) : [0]),
      (b.length || 0) / 2, (b.height || 0) / 2);
    ext = Math.max(ext, Math.hypot(...b.position) + (Number.isFinite(r) ? r : 0));
  }
  return ext;
}
function drawBody(world, st) {
  world.clear();
  const ext = extentOf(st);
  world.add(sceneAxes(ext * 1.2));
  const mat = () => new THREE.MeshStandardMaterial({color: 0x8c98a8, transparent: true, opacity: 0.55, depthWrite: false});
  const edge = new THREE.LineBasicMaterial({color: 0x333333});
  for (const b of st.req.bodies.filter(okPart)) {
    let geo = null, turn = null;
    const pos = (v) => Number.isFinite(v) && v > 0;
    if (b.shape === 'box' && Array.isArray(b.size) && b.size.every(pos)) geo = new THREE.BoxGeometry(...b.size);
    else if (b.shape === 'sphere' && pos(b.radius)) geo = new THREE.SphereGeometry(b.radius, 32, 16);
    else if (b.shape === 'cylinder' && pos(b.radius) && pos(b.height)) { geo = new THREE.CylinderGeometry(b.radius, b.radius, b.height, 40); turn = true; }
    else if (b.shape === 'rod' && pos(b.length)) { geo = new THREE.CylinderGeometry(ext * 0.025, ext * 0.025, b.length, 12); turn = true; }
    else geo = new THREE.SphereGeometry(ext * 0.07, 16, 8); // a point mass
    const g = new THREE.Group();
    const solid = b.shape === 'point' || b.shape === 'rod';
    const mesh = new THREE.Mesh(geo, solid ? new THREE.MeshStandardMaterial({color: 0x495057}) : mat());
    if (turn) mesh.rotation.x = Math.PI / 2; // three.js cylinders run along y; the API's along z
    g.add(mesh);
    if (b.shape === 'box' || b.shape === 'cylinder') {
      const lines = new THREE.LineSegments(new THREE.EdgesGeometry(geo, 30), edge);
      lines.rotation.copy(mesh.rotation); g.add(lines);
    }
    g.quaternion.copy(orient(b)); g.position.set(...b.position);
    world.add(g);
  }
  const a = st.answer;
  if (!a) return;
  const org = Array.isArray(a.origin) ? a.origin : a.center_of_mass;
  const m = a.principal.moments, mmax = Math.max(...m.map(Math.abs)) || 1;
  world.add(axesArrows(a.principal.axes, m.map(v => ext * (0.5 + 0.9 * Math.abs(v) / mmax)), org));
  a.principal.axes.forEach((ax, k) => {
    const L = ext * (0.5 + 0.9 * Math.abs(m[k]) / mmax), s = tag('e' + (k + 1), ['#c92a2a', '#2b8a3e', '#1864ab'][k]);
    s.position.set(org[0] + L * 1.12 * ax[0], org[1] + L * 1.12 * ax[1], org[2] + L * 1.12 * ax[2]);
    s.scale.set(ext * 0.3, ext * 0.15, 1); world.add(s);
  });
  // ellipsoid of inertia: semi-axes ∝ 1/√I_k, the longest at 0.8 ext, none longer than 3× the shortest
  const inv = m.map(v => 1 / Math.sqrt(Math.max(Math.abs(v), 1e-300)));
  const lo = Math.min(...inv), semi = inv.map(v => Math.min(v, 3 * lo)), top = Math.max(...semi);
  const ell = new THREE.Mesh(new THREE.SphereGeometry(1, 48, 24),
    new THREE.MeshStandardMaterial({color: 0x868e96, transparent: true, opacity: 0.22, depthWrite: false}));
  ell.scale.set(...semi.map(v => 0.8 * ext * v / top));
  const ax = a.principal.axes.map(r => r.slice()); // rows: e1, e2, e3 -> the columns of the rotation
  const det = ax[0][0] * (ax[1][1] * ax[2][2] - ax[1][2] * ax[2][1]) - ax[0][1] * (ax[1][0] * ax[2][2] - ax[1][2] * ax[2][0]) +
    ax[0][2] * (ax[1][0] * ax[2][1] - ax[1][1] * ax[2][0]);
  if (det < 0) ax[2] = ax[2].map(v => -v); // a proper rotation (the ellipsoid is symmetric about each axis)
  ell.quaternion.setFromRotationMatrix(new THREE.Matrix4().set(
    ax[0][0], ax[1][0], ax[2][0], 0, ax[0][1], ax[1][1], ax[2][1], 0, ax[0][2], ax[1][2], ax[2][2], 0, 0, 0, 0, 1));
  ell.position.set(...org);
  world.add(ell);
  const cm = new THREE.Mesh(new THREE.TorusGeometry(ext * 0.06, ext * 0.012, 8, 24), new THREE.MeshBasicMaterial({color: 0xe67700}));
  cm.position.set(...a.center_of_mass); world.add(cm);
}

// The answer's incline block: the body rolling without slipping down the slope from rest, a = g sin α/(1 + k),
// k = I/(m R²) (torque about the contact line), drawn as the slope with the body at the start and the end.
function rolling(r, req) {
  const deg = req.angle_deg, g = req.g ?? 9.80665, al = deg * Math.PI / 180;
  const W = 320, H = 150, x0 = 20, y0 = 22, x1 = W - 20, y1 = Math.min(H - 14, y0 + (x1 - x0) * Math.tan(al));
  const xe = Math.min(x1, x0 + (y1 - y0) / Math.tan(al)), R = 12, nx = Math.sin(al), ny = -Math.cos(al); // the slope's outward normal
  const pic = svg('svg', {class: 'plot dial', id: 'inertia-incline-plot', role: 'img', viewBox: `0 0 ${W} ${H}`,
    'aria-label': `the body rolling down a ${fmt(deg, 3)}° slope`});
  add(pic, svg('path', {d: `M ${x0} ${y0} L ${xe} ${y1} L ${x0} ${y1} z`, fill: '#e9ecef', stroke: '#555'}),
  svg('circle', {cx: x0 + 18 * Math.cos(al) + R * nx, cy: y0 + 18 * Math.sin(al) + R * ny, r: R, fill: '#8c98a8'}),
  svg('circle', {cx: xe - 18 * Math.cos(al) + R * nx, cy: y1 - 18 * Math.sin(al) + R * ny, r: R, fill: 'none', stroke: '#1864ab', 'stroke-width': 2, 'stroke-dasharray': '4 3'}),
  svg('text', {x: xe - 60, y: y1 - 6, 'font-size': 13, fill: '#444'}, `${fmt(deg, 3)}°`));
  return el('div', {id: 'inertia-incline'}, el('h3', {}, 'Rolling down the incline'), pic,
    el('dl', {class: 'nums'},
      el('dt', {}, 'I about the rolling axis'), num('inertia-inc-I', r.moment_axis, 'kg m²'),
      el('dt', {}, 'k = I/(m R²)'), num('inertia-inc-k', r.k),
      el('dt', {}, 'acceleration g sin α/(1 + k)'), num('inertia-inc-a', r.acceleration, 'm/s²'),
      el('dt', {}, 'sliding without friction, g sin α'), el('dd', {}, fmt(g * Math.sin(al), 6) + ' m/s²'),
      typeof r.time === 'number' ? [el('dt', {}, `time for ${fmt(req.length)} m`), num('inertia-inc-time', r.time, 's'),
        el('dt', {}, 'speed at the end'), num('inertia-inc-speed', r.speed, 'm/s'),
        el('dt', {}, 'turning at the end'), num('inertia-inc-omega', r.angular_speed, 'rad/s')] : null,
      el('dt', {}, 'friction needed'), num('inertia-inc-friction', r.friction_force, 'N'),
      el('dt', {}, 'least friction coefficient'), num('inertia-inc-mu', r.min_friction_coefficient),
      el('dt', {}, 'share of m g h in moving along'), num('inertia-inc-share', r.translational_energy_fraction)),
    el('p', {class: 'muted'}, `Torque about the contact line: m g sin α = m a (1 + k). A body sliding without friction would ` +
      `arrive √(1 + k) = ${fmt(Math.sqrt(1 + r.k), 4)} times sooner; rolling, the rest of m g h (a share k/(1 + k)) goes into turning.`));
}
