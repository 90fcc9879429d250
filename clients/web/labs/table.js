// Rotating table lab (chapter 1, §1.1): a puck on a frictionless turning table
// seen from both frames side by side and animated together by one player —
// the inertial straight line (the table turning under it) and the curve the
// table's frame sees, integrated by the API with centrifugal and Coriolis
// forces (POST /v1/scenes/rotating-table), with the exact rotated line dashed
// and the effective force at the start beside the notes' formula.
import {el, svg, put, add, field, val, fmt, num, labLayout, runner, examplePicker, plotSize, plotTools, notesBox} from '../lib.js';
import {player, lerp} from '../anim.js';
import {handle, rerun} from '../handles.js';
import {arrow, energyBars} from '../draw.js';

const st = {experiment: 'through_center', omega: 1, radius: 1, mass: 1, px: 0.5, py: 0, vx: 0, vy: 0.8, t_end: 4};
const BUILTIN = [
  {title: 'Through the centre: ω = 1 rad/s, r₁ = 1 m', operation: '/v1/scenes/rotating-table', section: '1.1 Rotating Coordinate System',
   request: {experiment: 'through_center', omega: 1, radius: 1}},
  {title: 'At rest in the room: a circle on the table (ω = 2 rad/s, r₁ = 0.5 m)', operation: '/v1/scenes/rotating-table',
   section: '1.1 Rotating Coordinate System', request: {experiment: 'at_rest', omega: 2, radius: 0.5}},
];
const SAMPLES = 161;

// A /v1/frames/effective-force puck example as the scene it describes: the
// puck's velocity in the table's frame is ω r₁ e_x (at rest in the room) or
// that plus −(2 r₁ ω / π) e_y (through the centre).
function sceneOf(ex) {
  if (ex.operation === '/v1/scenes/rotating-table') return ex.request;
  const r = ex.request, w = r.frame.omega[2], p = r.particle.position, v = r.particle.velocity;
  return {experiment: Math.abs(v[1]) < 1e-12 ? 'at_rest' : 'through_center', omega: w, radius: Math.hypot(p[0], p[1]), mass: r.particle.mass};
}
const fits = (ex) => ex.operation === '/v1/scenes/rotating-table' || (ex.request && ex.request.frame && Array.isArray(ex.request.frame.omega) &&
  !ex.request.frame.omega[0] && !ex.request.frame.omega[1] && ex.request.particle && Array.isArray(ex.request.particle.position) &&
  Math.abs(ex.request.particle.position[0]) < 1e-12 && !ex.request.frame.acceleration);

export default {
  id: 'table', title: 'Rotating table',
  mount(main) {
    const L = labLayout(main, {title: 'The rotating table, seen from both frames',
      intro: 'A puck slides without friction on a table turning at ω about the vertical. From the room (left) it moves in a ' +
             'straight line while the table turns under it; from the table (right) the same motion curves, pushed by the ' +
             'centrifugal force and the Coriolis force. Both pictures play together.'});
    const exp = field({label: 'Experiment', pointer: '/experiment', value: st.experiment, id: 'table-experiment',
      options: [['through_center', 'launched through the centre'], ['at_rest', 'at rest in the room'], ['custom', 'any launch']]});
    const omega = field({label: 'ω (table)', pointer: '/omega', value: st.omega, unit: 'rad/s', id: 'table-omega', step: 0.1});
    const radius = field({label: 'r₁ (start)', pointer: '/radius', value: st.radius, unit: 'm', id: 'table-radius', step: 0.1});
    const mass = field({label: 'mass', pointer: '/mass', value: st.mass, unit: 'kg', id: 'table-mass', step: 0.1});
    const px = field({label: 'x₀', pointer: '/position/0', value: st.px, unit: 'm', id: 'table-px'});
    const py = field({label: 'y₀', pointer: '/position/1', value: st.py, unit: 'm', id: 'table-py'});
    const vx = field({label: 'vₓ (room)', pointer: '/velocity/0', value: st.vx, unit: 'm/s', id: 'table-vx'});
    const vy = field({label: 'v_y (room)', pointer: '/velocity/1', value: st.vy, unit: 'm/s', id: 'table-vy'});
    const tEnd = field({label: 'duration', pointer: '/t_end', value: st.t_end, unit: 's', id: 'table-tend'});
    const custom = el('fieldset', {class: 'custom'}, el('legend', {}, 'Any launch (in the room\'s frame, at t = 0)'), px.wrap, py.wrap, vx.wrap, vy.wrap, tEnd.wrap);
    const sync = () => { const c = exp.input.value === 'custom'; custom.hidden = !c; radius.wrap.hidden = c; };
    exp.input.addEventListener('change', () => { sync(); run(); });
    add(L.form, examplePicker(['/v1/scenes/rotating-table', '/v1/frames/effective-force'], BUILTIN, (ex) => {
      const s = sceneOf(ex);
      exp.input.value = s.experiment || 'through_center'; omega.input.value = s.omega; radius.input.value = s.radius ?? 1;
      mass.input.value = s.mass ?? 1;
      if (s.position) { px.input.value = s.position[0]; py.input.value = s.position[1]; }
      if (s.velocity) { vx.input.value = s.velocity[0]; vy.input.value = s.velocity[1]; }
      if (s.t_end) tEnd.input.value = s.t_end;
      sync(); run();
    }, {fits}), exp.wrap, omega.wrap, radius.wrap, mass.wrap, custom,
    el('div', {class: 'buttons'}, el('button', {type: 'submit', id: 'table-submit'}, 'Launch')));
    sync();

    // a group: the puck's start and its launch velocity are handles on it (drag them, or focus and use the arrow keys)
    const room = svg('svg', {class: 'plot', id: 'table-room', role: 'group', 'aria-label': 'The puck seen from the room (inertial frame): drag its start or its velocity arrow'});
    const onTable = svg('svg', {class: 'plot', id: 'table-table', role: 'img', 'aria-label': 'The puck seen from the turning table'});
    const tableEnergy = svg('svg', {class: 'plot dial energy', id: 'table-energy', role: 'img', 'aria-label': 'energy bars'});
    const play = player({label: 'The rotating table', reverse: 'Backwards: in the room, the same straight line run back; on the table, the motion on a table turning the other way (ω → −ω: the Coriolis force changes sign with the velocity, the centrifugal force does not).'});
    add(L.figure, el('div', {class: 'pair two'},
      el('div', {}, el('h3', {}, 'From the room (inertial)'), room),
      el('div', {}, el('h3', {}, 'From the table (rotating)'), onTable)), play.root,
    el('p', {class: 'muted', id: 'table-legend'}, el('span', {class: 'c1'}, 'red: the puck and its path so far'), '; ',
      el('span', {class: 'c3'}, 'blue: a line painted on the table'), '; dashed: the whole path (right: the API\'s exact ' +
      'rotated line, under the integrated one).'),
    el('p', {class: 'muted', id: 'table-vectors-legend'}, 'On the puck seen from the table (right): ', el('span', {class: 'c3'}, 'v′ its velocity'),
      ', ', el('span', {class: 'c4'}, 'the centrifugal force mω²r′'), ', ', el('span', {class: 'c2'}, 'the Coriolis force −2mω×v′'),
      ' and in black their sum, the net force (forces to one scale, the velocity to its own).'),
    el('h3', {}, 'Energy seen from the table'), tableEnergy,
    el('p', {class: 'muted'}, 'Seen from the table, ½mv′² and the centrifugal potential −½mω²r′² trade, their sum (the Jacobi integral) level: ',
      'the Coriolis force does no work, being always across v′.'));

    const tableNotes = notesBox('table-notes');
    const run = runner(L, '/v1/scenes/rotating-table', () => {
      const e = exp.input.value;
      Object.assign(st, {experiment: e, omega: val(omega.input), radius: val(radius.input), mass: val(mass.input)});
      const b = {experiment: e, omega: val(omega.input), mass: val(mass.input), samples: SAMPLES};
      if (e === 'custom') Object.assign(b, {position: [val(px.input), val(py.input), 0], velocity: [val(vx.input), val(vy.input), 0], t_end: val(tEnd.input)});
      else b.radius = val(radius.input);
      return b;
    }, (a, req) => {
      const p = a.parameters, f = a.effective_force_at_start, w = p.omega, r1 = p.radius, m = p.mass;
      // notes §1.1 (Calculating the Effective Force, simple rotation): F′ = F − m ω × (ω × r′) − 2 m ω × v′, at t = 0
      // where the frames coincide (r′ = r, v′ = v − ω × r); computed here from the puck's start
      const [r0, v0] = p.experiment === 'custom' ? [req.position, req.velocity]
        : [[0, r1, 0], [0, p.experiment === 'through_center' ? -2 * r1 * Math.abs(w) / Math.PI : 0, 0]];
      const vp = [v0[0] + w * r0[1], v0[1] - w * r0[0]]; // v′ = v − ω × r, ω = ω ẑ
      const F = [m * w * w * r0[0] + 2 * m * w * vp[1], m * w * w * r0[1] - 2 * m * w * vp[0]];
      const abs = Math.hypot(F[0] - f.total[0], F[1] - f.total[1]), big = Math.hypot(f.total[0], f.total[1]);
      const vec = (x) => `(${fmt(x[0], 7)}, ${fmt(x[1], 7)}) N`;
      tableNotes.update({section: '1.1', inferred: true, heading: 'Rotating Coordinate System: Calculating the Effective Force',
        formula: [el('div', {}, 'F′ = F − m ω × (ω × r′) − 2 m ω × v′  (centrifugal, Coriolis; the table turns steadily: no Euler force)'),
          p.experiment === 'through_center' ? el('div', {}, 'through the centre, at the start: F′ = −m ω² r₁ (ê', el('sub', {}, 'y'), ' + (4/π) ê',
            el('sub', {}, 'x'), ')  (ω > 0)')
            : p.experiment === 'at_rest' ? el('div', {}, 'at rest in the room: F′ = −m ω² r₁ ê', el('sub', {}, 'y'), ' (Coriolis 2 m ω² r₁ inwards, twice the centrifugal outwards)') : null],
        what: 'the formula', formulaShown: vec(F), apiShown: vec(f.total), abs, rel: big ? abs / big : (abs ? 1 : 0), unit: 'N',
        how: 'The total effective force on the puck at the start, seen from the table.',
        note: p.experiment === 'through_center' ? 'Seen from the table the puck comes back to where it started after half a turn: it was ' +
          'aimed so the centre passes under it just as the table turns by π.' : null});
      const inv = a.diagnostics && a.diagnostics.invariant;
      put(L.results, el('h3', {}, 'Effective force at the start (table\'s frame)'),
        el('dl', {class: 'nums'},
          el('dt', {}, 'centrifugal'), el('dd', {id: 'table-cf'}, `(${fmt(f.centrifugal[0], 5)}, ${fmt(f.centrifugal[1], 5)}) N`),
          el('dt', {}, 'Coriolis'), el('dd', {id: 'table-cor', 'data-value': f.coriolis.join(',')}, `(${fmt(f.coriolis[0], 5)}, ${fmt(f.coriolis[1], 5)}) N`),
          el('dt', {}, 'total'), el('dd', {id: 'table-total', 'data-value': f.total.join(',')}, `(${fmt(f.total[0], 5)}, ${fmt(f.total[1], 5)}) N`),
          el('dt', {}, 'duration'), num('table-t', p.t_end, 's'),
          el('dt', {}, 'integrated vs exact'), num('table-err', a.rotating_vs_exact.max_position_error, 'm'),
          inv ? el('dt', {}, 'Jacobi integral drift') : null, inv ? num('table-jacobi', inv.max_relative_drift) : null),
        tableNotes.box);
      draw(room, onTable, a, play, {R: dragR, launch, energy: tableEnergy});
      plotTools(onTable, {name: 'rotating-table', csv: () => 't,x_room,y_room,x_table,y_table,x_table_exact,y_table_exact\n' +
        a.t.map((t, i) => [t, a.inertial[i][0], a.inertial[i][1], a.rotating[i][0], a.rotating[i][1], a.rotating_exact[i][0], a.rotating_exact[i][1]].join(',')).join('\n') + '\n'});
    });
    // the launch dragged on the room's picture: any launch, from the start and velocity dragged (in the room's frame)
    let dragR = null;
    const again = rerun(() => run());
    const r3 = (v) => Number(v.toFixed(3));
    const launch = (what, x, y, done, R, a0) => {
      if (exp.input.value !== 'custom') { // from a preset: its start and velocity become the custom launch's
        px.input.value = r3(a0.position[0]); py.input.value = r3(a0.position[1]);
        vx.input.value = r3(a0.velocity_inertial[0]); vy.input.value = r3(a0.velocity_inertial[1]);
        tEnd.input.value = r3(a0.t_end); exp.input.value = 'custom'; sync();
      }
      if (what === 'start') { px.input.value = r3(x); py.input.value = r3(y); }
      else { vx.input.value = r3(x); vy.input.value = r3(y); }
      dragR = done ? null : R;
      again(done);
    };
    L.results.before(L.figure); // the picture first, the numbers under it (on a phone, right below the form)
    run();
  },
};

// Both panels, to the same scale; the player moves the puck on both and turns
// the table on the left (the line painted on it turns with ωt).
function draw(room, onTable, a, play, {R: fixedR, launch, energy} = {}) {
  const pts = [...a.inertial, ...a.rotating];
  const R = fixedR || Math.max(...pts.map(p => Math.hypot(p[0], p[1])), a.parameters.radius || 0) * 1.12 || 1;
  const w = a.parameters.omega;
  const setup = (root) => {
    const [W] = plotSize(root, 420, 420), H = W, s = (W / 2 - 8) / R;
    put(root); root.setAttribute('viewBox', `0 0 ${W} ${H}`);
    const X = (x) => W / 2 + s * x, Y = (y) => H / 2 - s * y;
    X.invert = (px) => (px - W / 2) / s; Y.invert = (py) => (H / 2 - py) / s;
    add(root, svg('circle', {cx: X(0), cy: Y(0), r: s * R * 0.98, fill: '#f1f3f5', stroke: '#868e96', 'stroke-width': 1.5}));
    const line = svg('line', {stroke: '#1864ab', 'stroke-width': 3, 'data-role': 'painted'});
    const path = (ps, a2) => svg('polyline', {points: ps.map(p => `${X(p[0]).toFixed(1)},${Y(p[1]).toFixed(1)}`).join(' '), fill: 'none', ...a2});
    add(root, line, svg('circle', {cx: X(0), cy: Y(0), r: 3, fill: '#333'}));
    // a scale bar of a round length
    const bar = niceLen(R / 2);
    add(root, svg('line', {x1: 10, y1: H - 12, x2: 10 + s * bar, y2: H - 12, stroke: '#333', 'stroke-width': 2}),
      svg('text', {x: 10, y: H - 18, 'font-size': 16}, `${fmt(bar)} m`));
    return {X, Y, line, path};
  };
  const A = setup(room), B = setup(onTable);
  add(room, A.path(a.inertial, {stroke: '#c92a2a', 'stroke-dasharray': '5 5', 'stroke-width': 1.5}));
  add(onTable, B.path(a.rotating_exact, {stroke: '#adb5bd', 'stroke-dasharray': '5 5', 'stroke-width': 4}),
    B.path(a.rotating, {stroke: '#c92a2a', 'stroke-dasharray': '5 5', 'stroke-width': 1.5}));
  const trailA = A.path([], {stroke: '#c92a2a', 'stroke-width': 3}), trailB = B.path([], {stroke: '#c92a2a', 'stroke-width': 3});
  const puckA = svg('circle', {r: 8, fill: '#c92a2a', stroke: '#fff', 'stroke-width': 2, 'data-role': 'puck'});
  const puckB = svg('circle', {r: 8, fill: '#c92a2a', stroke: '#fff', 'stroke-width': 2, 'data-role': 'puck'});
  const vecs = svg('g', {id: 'table-vectors'});
  add(room, trailA, puckA); add(onTable, trailB, vecs, puckB);
  // seen from the table: v′ = R(−ωt)(v − ω×r) from the room's constant velocity v, the centrifugal force mω²r′,
  // the Coriolis force −2mω×v′ = 2mω(v′y, −v′x), the net force their sum; scales fixed by the start
  const m = a.parameters.mass, v0 = a.initial ? a.initial.velocity_inertial : null;
  const seen = (p, t) => {
    const u = [v0[0] + w * p[1], v0[1] - w * p[0]], c = Math.cos(w * t), s = Math.sin(w * t);
    const vp = [c * u[0] + s * u[1], -s * u[0] + c * u[1]];
    return vp;
  };
  const forces = (q, vp) => { const cf = [m * w * w * q[0], m * w * w * q[1]], co = [2 * m * w * vp[1], -2 * m * w * vp[0]];
    return {cf, co, net: [cf[0] + co[0], cf[1] + co[1]]}; };
  let kF = 0, kV = 0, E0 = 1;
  if (v0) {
    const vp0 = seen(a.inertial[0], 0), F0 = forces(a.rotating[0], vp0), sB = B.X(1) - B.X(0);
    kF = 50 / (Math.max(...[F0.cf, F0.co, F0.net].map(f => Math.hypot(f[0], f[1]))) || 1);
    kV = 50 / (Math.hypot(vp0[0], vp0[1]) || 1);
    E0 = Math.max(0.5 * m * (vp0[0] ** 2 + vp0[1] ** 2), 0.5 * m * w * w * (a.rotating[0][0] ** 2 + a.rotating[0][1] ** 2)) || 1;
    void sB;
  }
  // the painted line lies along the table's x′ axis: at angle ωt in the room, fixed on the table
  const paint = (G, ang) => {
    const c = R * 0.98 * Math.cos(ang), d = R * 0.98 * Math.sin(ang);
    for (const [k, v] of [['x1', G.X(-c)], ['y1', G.Y(-d)], ['x2', G.X(c)], ['y2', G.Y(d)]]) G.line.setAttribute(k, v);
  };
  const trail = (G, ps, i, p) => ps.slice(0, i + 1).concat([p]).map(q => `${G.X(q[0]).toFixed(1)},${G.Y(q[1]).toFixed(1)}`).join(' ');
  paint(B, 0);
  // the launch: the start and the velocity arrow (its tip at r₀ + v τ, τ = 1/|ω|: where the puck would be after the
  // table turns one radian), both handles
  if (launch && a.initial) {
    const r0 = a.initial.position, v0 = a.initial.velocity_inertial, tau = 1 / (Math.abs(w) || 1);
    const tip = [r0[0] + v0[0] * tau, r0[1] + v0[1] * tau];
    const a0 = {...a.initial, t_end: a.parameters.t_end};
    const defs = svg('defs', {});
    add(defs, arrowHead('table-arrow', '#5c3b00'));
    add(room, defs, svg('line', {x1: A.X(r0[0]), y1: A.Y(r0[1]), x2: A.X(tip[0]), y2: A.Y(tip[1]), stroke: '#5c3b00', 'stroke-width': 3,
      'marker-end': 'url(#table-arrow)'}),
      handle(room, {id: 'table-start', X: A.X, Y: A.Y, at: [r0[0], r0[1]], color: '#c92a2a', step: [0.05, 0.05],
        label: 'the puck\'s start', text: (x, y) => `start x = ${fmt(x, 3)} m, y = ${fmt(y, 3)} m`,
        onMove: (x, y, done) => launch('start', x, y, done, R, a0)}),
      handle(room, {id: 'table-velocity', X: A.X, Y: A.Y, at: tip, color: '#5c3b00', step: [0.05 * tau, 0.05 * tau], r: 7,
        label: 'the launch velocity (arrow tip)', text: (x, y) => { const u = [(x - r0[0]) / tau, (y - r0[1]) / tau];
          return `velocity vₓ = ${fmt(u[0], 3)} m/s, v_y = ${fmt(u[1], 3)} m/s (${fmt(Math.hypot(u[0], u[1]), 3)} m/s)`; },
        onMove: (x, y, done) => launch('velocity', (x - r0[0]) / tau, (y - r0[1]) / tau, done, R, a0)}));
  }
  play.set(a.t, (i, f, t) => {
    const j = Math.min(i + 1, a.t.length - 1);
    const p = lerp(a.inertial[i], a.inertial[j], f), q = lerp(a.rotating[i], a.rotating[j], f);
    puckA.setAttribute('cx', A.X(p[0])); puckA.setAttribute('cy', A.Y(p[1]));
    puckB.setAttribute('cx', B.X(q[0])); puckB.setAttribute('cy', B.Y(q[1]));
    trailA.setAttribute('points', trail(A, a.inertial, i, p)); trailB.setAttribute('points', trail(B, a.rotating, i, q));
    paint(A, w * t);
    room.dataset.puck = `${p[0].toFixed(4)},${p[1].toFixed(4)}`; onTable.dataset.puck = `${q[0].toFixed(4)},${q[1].toFixed(4)}`;
    if (v0) {
      const vp = seen(p, t), F = forces(q, vp), bx = B.X(q[0]), by = B.Y(q[1]);
      const ar = (f, k, c, name) => arrow(bx, by, bx + k * f[0], by - k * f[1], c, name, 16); // 16: still 10 px in a phone's half-width panel
      put(vecs, ar(F.cf, kF, '#a65300', 'cf'), ar(F.co, kF, '#1f6f30', 'Cor'), ar(F.net, kF, '#111', 'net'), ar(vp, kV, '#1864ab', 'v′'));
      onTable.dataset.forces = JSON.stringify(F);
      if (energy) {
        const K = 0.5 * m * (vp[0] ** 2 + vp[1] ** 2), U = -0.5 * m * w * w * (q[0] ** 2 + q[1] ** 2);
        energyBars(energy, [['½mv′²', K, '#1864ab'], ['−½mω²r′²', U, '#a65300'], ['sum', K + U, '#111']], E0, 'energy seen from the table');
      }
    }
  }, {grow: []});
}
// An SVG arrowhead marker of the colour given.
function arrowHead(id, color) {
  const m = svg('marker', {id, viewBox: '0 0 10 10', refX: 9, refY: 5, markerWidth: 7, markerHeight: 7, orient: 'auto-start-reverse'});
  add(m, svg('path', {d: 'M 0 0 L 10 5 L 0 10 z', fill: color}));
  return m;
}
const niceLen = (x) => { const p = 10 ** Math.floor(Math.log10(x)), m = x / p; return (m < 2 ? 1 : m < 5 ? 2 : 5) * p; };
