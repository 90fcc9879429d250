// Phase-space lab (Hamiltonian mechanics): Liouville's theorem — a loop of
// initial conditions carried by the flow keeps its area (its points from one
// /v1/batch of /v1/hamiltonian/flow, animated; the area A(t) and its drift
// for a symplectic and a non-symplectic integrator from
// /v1/hamiltonian/liouville in the same batch) — and Poincaré sections of the
// Hénon–Heiles system (/v1/hamiltonian/poincare): closed curves for regular
// orbits, a scatter for chaotic ones.
import {el, svg, put, add, field, val, fmt, num, labLayout, labSection, runner, examplePicker, linePlot, plotSize, plotTools, notesBox} from '../lib.js';
import {player, lerp} from '../anim.js';

const LOOP = 40, SAMPLES = 81;
const st = {theta: 1.2, p: 0, a: 0.35, b: 0.6, t_end: 6, energy: 0.125};
const BUILTIN = [
  {title: 'Pendulum: a loop round (1.2 rad, 0) for 6 s', operation: '/v1/hamiltonian/liouville', section: 'Extra: 5 Hamiltonian Mechanics — Phase Space and Liouville\'s Theorem',
   request: {system: {name: 'pendulum', mass: 1, length: 1}, curve: {type: 'ellipse', center: [1.2, 0], semi_axes: [0.35, 0.6]}, t_end: 6}},
];
const PBUILTIN = [
  {title: 'Hénon–Heiles at E = 1/8: islands and a chaotic sea', operation: '/v1/hamiltonian/poincare', section: 'Extra: 5 Hamiltonian Mechanics',
   request: {system: {name: 'henon_heiles'}, energy: 0.125}},
];
const COLORS = ['#c92a2a', '#1864ab', '#2b8a3e', '#e67700', '#862e9c', '#0b7285', '#5c940d', '#a61e4d', '#364fc7', '#495057'];

// n points on the curve of initial conditions (an ellipse: centre + u cos 2πs + w sin 2πs, or
// semi-axes along q and p for one degree of freedom; a polygon or cloud: its vertices)
function loopPoints(curve, n) {
  if (curve.type !== 'ellipse') return (curve.vertices || curve.points || []).slice(0, 90);
  const c = curve.center, d = c.length;
  const u = curve.u || (curve.semi_axes ? [curve.semi_axes[0], 0] : c.map(() => 0));
  const w = curve.w || (curve.semi_axes ? [0, curve.semi_axes[1]] : c.map(() => 0));
  return Array.from({length: n}, (_, k) => { const s = 2 * Math.PI * k / n; return Array.from({length: d}, (_, i) => c[i] + u[i] * Math.cos(s) + w[i] * Math.sin(s)); });
}

export default {
  id: 'phase', title: 'Phase space',
  mount(main) {
    const L = labLayout(main, {title: 'Phase space: Liouville\'s theorem',
      intro: 'Start many pendulums from a loop of initial conditions (θ, p) and let each move by Hamilton\'s equations. ' +
             'The loop is sheared and stretched — points near the top swing slower — but the area it encloses stays exactly ' +
             'the same: the Hamiltonian flow preserves phase-space area.'});
    const th = field({label: 'centre θ₀', pointer: '/operations/0/request/curve/center/0', value: st.theta, unit: 'rad', id: 'ph-theta', step: 0.1});
    const p0 = field({label: 'centre p₀', pointer: '/operations/0/request/curve/center/1', value: st.p, unit: 'kg m²/s', id: 'ph-p', step: 0.1});
    const a = field({label: 'half-width in θ', pointer: '/operations/0/request/curve/semi_axes/0', value: st.a, unit: 'rad', id: 'ph-a', step: 0.05});
    const b = field({label: 'half-height in p', pointer: '/operations/0/request/curve/semi_axes/1', value: st.b, unit: 'kg m²/s', id: 'ph-b', step: 0.05});
    const te = field({label: 'duration', pointer: '/operations/0/request/t_end', value: st.t_end, unit: 's', id: 'ph-tend'});
    let pending = null; // an example's own liouville request
    const form = el('form', {novalidate: true, 'aria-label': 'Poincaré section inputs', id: 'poincare-form'});
    const en = field({label: 'energy E', pointer: '/orbits', value: st.energy, id: 'pc-energy', step: 0.005,
      help: 'Hénon–Heiles: bounded below E = 1/6 ≈ 0.1667'});
    let prun = () => {};
    // one picker for both sections (a Poincaré example fills the section below)
    add(L.form, examplePicker(['/v1/hamiltonian/liouville', '/v1/hamiltonian/poincare'], BUILTIN.concat(PBUILTIN), (ex) => {
      const r = ex.request;
      if (ex.operation === '/v1/hamiltonian/poincare') {
        if (r.energy) en.input.value = r.energy;
        else if (Array.isArray(r.orbits) && r.orbits[0] && r.orbits[0].energy) en.input.value = r.orbits[0].energy;
        prun(); form.scrollIntoView({block: 'nearest'}); return;
      }
      if (r.system && r.system.name === 'pendulum' && r.curve && r.curve.type === 'ellipse' && r.curve.semi_axes && r.curve.center.length === 2) {
        th.input.value = r.curve.center[0]; p0.input.value = r.curve.center[1];
        a.input.value = r.curve.semi_axes[0]; b.input.value = r.curve.semi_axes[1]; te.input.value = r.t_end; pending = null;
      } else pending = r;
      run();
    }, {fits: (ex) => ex.operation !== '/v1/hamiltonian/poincare' || (ex.request.system && ex.request.system.name === 'henon_heiles')}),
    el('p', {class: 'muted'}, 'A pendulum of 1 kg on 1 m, g = 9.80665 m/s² (θ from the downward vertical, p = m l² θ′).'),
    th.wrap, p0.wrap, a.wrap, b.wrap, te.wrap, el('div', {class: 'buttons'}, el('button', {type: 'submit', id: 'ph-submit'}, 'Let it flow')));
    const plot = svg('svg', {class: 'plot', id: 'ph-loop', role: 'img', 'aria-label': 'The loop of initial conditions in phase space'});
    const play = player({label: 'The phase-space loop'});
    const areaOut = el('p', {id: 'ph-area-now', 'aria-live': 'off'});
    const aplot = svg('svg', {class: 'plot', id: 'ph-area', role: 'img', 'aria-label': 'Area of the loop against time'});
    add(L.figure, el('h3', {}, 'The loop in phase space'), plot, play.root, areaOut, el('h3', {}, 'Its area against time'), aplot);

    const phNotes = notesBox('ph-notes');
    const run = runner(L, '/v1/batch', () => {
      const req = pending || {system: {name: 'pendulum', mass: 1, length: 1},
        curve: {type: 'ellipse', center: [val(th.input), val(p0.input)], semi_axes: [val(a.input), val(b.input)]}, t_end: val(te.input)};
      const lv = {...req, samples: SAMPLES};
      const ok = req.curve && Array.isArray(req.curve.center) && req.curve.center.every(Number.isFinite) &&
        (req.curve.type !== 'ellipse' || !req.curve.semi_axes || req.curve.semi_axes.every(Number.isFinite));
      const d = ok ? req.curve.center.length / 2 : 1;
      const flows = ok ? loopPoints(req.curve, LOOP).map(y => ({operation: '/v1/hamiltonian/flow',
        request: {system: req.system, q: y.slice(0, d), p: y.slice(d), t_end: req.t_end, samples: SAMPLES}})) : [];
      return {operations: [{operation: '/v1/hamiltonian/liouville', request: lv}, ...flows]};
    }, (res, req) => {
      const first = res.results[0];
      if (first.status !== 200) { // a batch item's problem: its pointers start /operations/0/request
        // placed on the fields it names like any problem; the previous loop stays, dimmed and labelled "not updated"
        return {status: first.status, problem: first.problem || first.body || {}};
      }
      const lv = first.body, flows = res.results.slice(1).filter(r => r.status === 200).map(r => r.body);
      const runs = lv.runs, A0 = lv.area_initial;
      const lvReq = req.operations[0].request;
      const notes = lvReq.curve.type === 'ellipse' && lvReq.curve.semi_axes ? Math.PI * lvReq.curve.semi_axes[0] * lvReq.curve.semi_axes[1] : null;
      put(L.results, el('h3', {}, 'The area of the loop'),
        el('dl', {class: 'nums'}, el('dt', {}, 'at the start'), num('ph-area0', A0, lv.system.degrees_of_freedom === 1 ? 'J s' : ''),
          ...runs.flatMap((r, k) => [el('dt', {}, `${r.method}${r.symplectic ? ' (symplectic)' : ''}: largest relative change`), num(`ph-drift-${k}`, r.max_relative_area_drift)])),
        el('p', {id: 'ph-verdict'}, runs.map(r => r.symplectic
          ? `With ${r.method}, a symplectic method, the area stays the same to ${fmt(r.max_relative_area_drift, 2)}: round-off.`
          : `With ${r.method} at a step of ${fmt(r.diagnostics.dt, 3)} s (not symplectic) it ${r.max_relative_area_drift > 1e-6 ? 'drifts' : 'changes'} by ${fmt(r.max_relative_area_drift, 2)}: the numerical flow, not the physics.`).join(' ')),
        phNotes.box);
      // chapter 5, Phase Space and Liouville's Theorem: the flow keeps phase-space area, d/dt ∮ p dq = 0;
      // an ellipse of half-axes a, b has area π a b. Against it: the loop's area at the end of the best-keeping run.
      const keep = runs.find(r => r.symplectic) || runs[0], Aend = keep.area[keep.area.length - 1];
      phNotes.update({section: '5', heading: 'Hamiltonian Mechanics: Phase Space and Liouville\'s Theorem',
        formula: ['d/dt ∮ p dq = 0  (the area of a loop of states carried by the flow does not change);  ellipse: A = π a b'],
        what: notes === null ? 'Liouville\'s constant area' : 'π a b', formulaValue: notes === null ? A0 : notes, apiValue: Aend,
        unit: lv.system.degrees_of_freedom === 1 ? 'J s' : '',
        sourceText: notes === null ? 'the API\'s area at the start, which Liouville says stays' : 'computed in this page from the half-axes',
        how: `The loop's area after the flow, with ${keep.method}${keep.symplectic ? ' (symplectic)' : ''}: Liouville says it is the area it started with.`,
        note: 'The extracted notes end at §4.2: the Hamiltonian chapter\'s section numbers are not in their text. A non-symplectic ' +
          'method does not keep the area: the change it shows is the numerical flow, not the physics.'});
      linePlot(aplot, runs.map((r, k) => ({points: lv.t.map((t, i) => [t, r.area[i] / A0 - 1]), label: `${r.method}: A/A₀ − 1`})),
        {xlabel: 't [s]', ylabel: 'A/A₀ − 1'});
      drawLoop(plot, flows, lv, play, areaOut);
    });
    L.results.before(L.figure); // the picture first, the numbers under it (on a phone, right below the form)
    run();

    // --- Poincaré sections ---
    add(form, en.wrap, el('div', {class: 'buttons'}, el('button', {type: 'submit', id: 'pc-submit'}, 'Section')));
    const P = labSection(main, {title: 'Poincaré sections: order and chaos', form, id: 'poincare',
      intro: 'H = (p_x² + p_y²)/2 + (x² + y²)/2 + x² y − y³/3. Each time an orbit crosses x = 0 going forwards, mark its (y, p_y). ' +
             'A regular orbit marks a closed curve; a chaotic one sprinkles a region. Raise the energy towards 1/6 and the curves break up.'});
    const pplot = svg('svg', {class: 'plot', id: 'pc-plot', role: 'img', 'aria-label': 'Poincaré section (y, p_y) at x = 0'});
    add(P.figure, pplot);
    const starts = [-0.3, -0.2, -0.1, 0, 0.1, 0.2, 0.3, 0.4];
    prun = runner(P, '/v1/hamiltonian/poincare', () => {
      st.energy = val(en.input);
      return {system: {name: 'henon_heiles'}, orbits: starts.map(y => ({energy: val(en.input), on_section: [y, 0]})),
        t_max: 1500, max_crossings: 250, integrator: {method: 'rk8pd', rtol: 1e-9, atol: 1e-12}};
    }, (a) => {
      const drift = Math.max(...a.orbits.map(o => o.energy.max_rel_drift));
      const n = a.orbits.reduce((s, o) => s + o.points.length, 0);
      put(P.results, el('dl', {class: 'nums'}, el('dt', {}, 'orbits'), num('pc-orbits', a.orbits.length),
        el('dt', {}, 'crossings'), num('pc-crossings', n), el('dt', {}, 'largest energy drift'), num('pc-drift', drift),
        el('dt', {}, 'largest distance off the section'), num('pc-residual', Math.max(...a.orbits.map(o => o.max_section_residual)))));
      linePlot(pplot, a.orbits.map((o, k) => ({points: o.points, label: k < 1 ? 'one colour per orbit' : undefined, dots: true, r: 1.8, color: COLORS[k % COLORS.length]})),
        {xlabel: 'y', ylabel: 'p_y', equal: true, dots: true});
      plotTools(pplot, {name: 'poincare', csv: () => 'orbit,y,p_y\n' + a.orbits.flatMap((o, k) => o.points.map(p => [k, p[0], p[1]].join(','))).join('\n') + '\n'});
    });
    prun();
  },
};

// The loop at time t: the LOOP flowed points joined in order (a coarse outline:
// the area shown is the API's, from the curve refined until converged).
function drawLoop(root, flows, lv, play, out) {
  const d = lv.system.degrees_of_freedom, names = [lv.system.coordinates, lv.system.momenta];
  const pairs = Array.from({length: d}, (_, i) => i);
  const all = flows.flatMap(f => f.q.map((q, s) => pairs.map(i => [q[i], f.p[s][i]]))).flat();
  if (!all.length) { put(root); return; }
  const xs = all.map(p => p[0]), ys = all.map(p => p[1]);
  const [W, H] = plotSize(root, 560, 400);
  put(root); root.setAttribute('viewBox', `0 0 ${W} ${H}`);
  const pad = 46, x0 = Math.min(...xs), x1 = Math.max(...xs), y0 = Math.min(...ys), y1 = Math.max(...ys);
  const X = (x) => pad + (W - pad - 10) * (x - x0) / ((x1 - x0) || 1), Y = (y) => H - pad + 10 - (H - pad - 10) * (y - y0) / ((y1 - y0) || 1);
  // round ticks on both axes
  const ticks = (a, b) => { const r = (b - a) || 1, s0 = 10 ** Math.floor(Math.log10(r / 4)), s = [1, 2, 5, 10].map(m => m * s0).find(v => r / v <= 6);
    const out2 = []; for (let v = Math.ceil(a / s) * s; v <= b + 1e-12; v += s) out2.push(Math.abs(v) < s * 1e-9 ? 0 : v); return out2; };
  for (const v of ticks(x0, x1)) add(root, svg('line', {x1: X(v), y1: 10, x2: X(v), y2: H - pad + 10, stroke: '#e9ecef'}),
    svg('text', {x: X(v), y: H - pad + 28, 'text-anchor': 'middle', 'font-size': 13, class: 'tick-x'}, fmt(Number(v.toPrecision(6))).replace('-', '−')));
  for (const v of ticks(y0, y1)) add(root, svg('line', {x1: pad, y1: Y(v), x2: W - 10, y2: Y(v), stroke: '#e9ecef'}),
    svg('text', {x: pad - 6, y: Y(v) + 4, 'text-anchor': 'end', 'font-size': 13, class: 'tick-y'}, fmt(Number(v.toPrecision(6))).replace('-', '−')));
  add(root, svg('text', {x: W / 2, y: H - 4, 'text-anchor': 'middle', 'font-size': 14}, d === 1 ? `${names[0][0]} [rad]` : names[0].join(', ')),
    svg('text', {x: 12, y: 16, 'font-size': 14}, d === 1 ? `${names[1][0]}` : names[1].join(', ')));
  const start = pairs.map(i => svg('polygon', {fill: 'none', stroke: '#adb5bd', 'stroke-dasharray': '4 4', 'stroke-width': 1.5,
    points: flows.map(f => `${X(f.q[0][i]).toFixed(1)},${Y(f.p[0][i]).toFixed(1)}`).join(' ')}));
  const loops = pairs.map(i => svg('polygon', {fill: COLORS[i] + '33', stroke: COLORS[i], 'stroke-width': 2, 'data-role': 'loop'}));
  add(root, ...start, ...loops);
  const T = flows[0].t;
  play.set(T, (i, f, t) => {
    const j = Math.min(i + 1, T.length - 1);
    pairs.forEach(k => loops[k].setAttribute('points', flows.map(fl => {
      const q = lerp(fl.q[i][k], fl.q[j][k], f), p = lerp(fl.p[i][k], fl.p[j][k], f);
      return `${X(q).toFixed(1)},${Y(p).toFixed(1)}`;
    }).join(' ')));
    // the API's area at the sample nearest t
    const s = lv.t.reduce((best, tt, n) => Math.abs(tt - t) < Math.abs(lv.t[best] - t) ? n : best, 0);
    const r = lv.runs[0];
    out.textContent = `t = ${fmt(t, 4)} s: area ${fmt(r.area[s], 7)} (${r.method}, at t = ${fmt(lv.t[s], 4)} s), at the start ${fmt(lv.area_initial, 7)}.`;
    root.dataset.time = String(t);
  });
}
