// Accuracy lab: a work-precision plot from POST /v1/compare — error against
// right-hand-side evaluations for several integrators on a Kepler orbit.
import {el, put, add, field, val, fmt, svg, sci, labLayout, runner, examplePicker, linePlot, plotTools, notesBox} from '../lib.js';

const BUILTIN = [{title: 'Kepler orbit, e ≈ 0.44, 20 time units', operation: '/v1/compare',
  request: {operation: '/v1/trajectory', request: {particle: {mass: 1, position: [1, 0, 0], velocity: [0, 1.2, 0]},
    forces: [{type: 'central_gravity', gm: 1}], t_end: 20, samples: 21},
    sweep: {methods: ['rk8pd', 'rkf45', 'verlet', 'yoshida4'], tolerances: [1e-4, 1e-6, 1e-8, 1e-10], dts: [0.04, 0.01, 0.0025]}}}];

export default {
  id: 'accuracy', title: 'Accuracy',
  mount(main) {
    const L = labLayout(main, {title: 'Accuracy: work against precision',
      intro: 'The same scene run with many integrators and settings. Lower and further left is better: the plot shows ' +
             'what each digit of accuracy costs.'});
    const vy = field({label: 'initial speed', pointer: '/request/particle/velocity/1', value: 1.2, id: 'acc-v'});
    const te = field({label: 'duration', pointer: '/request/t_end', value: 20, id: 'acc-t'});
    let base = BUILTIN[0].request; // the example's sweep; the fields change its speed and duration
    add(L.form, examplePicker(['/v1/compare'], BUILTIN, (ex) => {
      base = ex.request; vy.input.value = base.request.particle.velocity[1]; te.input.value = base.request.t_end; run();
    }, {fits: (ex) => ex.request && ex.request.request && ex.request.request.particle && typeof ex.request.request.t_end === 'number'}),
    vy.wrap, te.wrap,
      el('div', {class: 'buttons'}, el('button', {type: 'submit', id: 'acc-submit'}, 'Compare')));
    const plot = svg('svg', {class: 'plot', id: 'acc-plot', role: 'img', 'aria-label': 'work-precision plot'});
    add(L.figure, el('h3', {}, 'Work-precision'), plot);
    const accNotes = notesBox('acc-notes'); L.figure.after(accNotes.box); // under the figure: the picture stays by the answer
    const run = runner(L, '/v1/compare', () => {
      const b = structuredClone(base);
      b.request.particle.velocity[1] = val(vy.input); b.request.t_end = val(te.input); return b;
    }, (r, req) => {
      const by = {};
      for (const run of r.runs) if (run.status === 'ok') (by[run.method] = by[run.method] || []).push([run.rhs_evaluations, run.max_position_error]);
      const ref = r.reference || {};
      const short = (v) => (v < 1e-3 ? v.toExponential() : String(v)); // 1e-8, 0.01: as the sweep says them
      const setting1 = (x) => typeof x.dt === 'number' ? 'dt ' + short(x.dt) : typeof x.rtol === 'number' ? 'rtol ' + short(x.rtol) : '';
      const setting = (x) => setting1(x) || (x.requested ? setting1(x.requested) : ''); // a run not run has only what was asked
      put(L.results, el('p', {}, `${r.runs.length} runs against the ${ref.kind || 'reference'} solution`,
        ref.name ? ` (${ref.name})` : '', '.',
        r.partial ? ' The budget ran out before every run finished: the rows marked "not run" say why.' : null),
        el('table', {id: 'acc-table'}, el('tr', {}, ['method', 'tolerance or step', 'evaluations', 'max position error'].map(h => el('th', {}, h))),
          r.runs.map(x => el('tr', {}, el('td', {}, x.method || (x.requested && x.requested.method) || '?'), el('td', {}, setting(x)),
            x.status === 'ok' ? [el('td', {}, String(x.rhs_evaluations)), el('td', {}, fmt(x.max_position_error, 3))]
              : el('td', {colspan: 2, class: 'muted'}, (x.status || 'not run').replace(/_/g, ' ') +
                  (x.reason || x.detail ? ': ' + (x.reason || x.detail) : ''))))));
      // chapter 5, Example: Motion in a Central Potential: H = p²/2m + V(r) has no explicit t, so dH/dt = ∂H/∂t = 0.
      // H at the start from the inputs, against how well the runs keep it (the API's largest relative drift).
      const q = req.request, P = q.particle, gm = (q.forces.find(f => f.type === 'central_gravity') || {}).gm;
      const E0 = 0.5 * P.mass * P.velocity.reduce((s2, v) => s2 + v * v, 0) - gm * P.mass / Math.hypot(...P.position);
      const drifts = r.runs.filter(x => x.status === 'ok').map(x => [(x.invariants || []).find(i => i.name === 'energy'), x])
        .filter(([e]) => e && Number.isFinite(e.max_relative_drift)).sort((u, w) => u[0].max_relative_drift - w[0].max_relative_drift);
      if (drifts.length && Number.isFinite(E0)) {
        const [e, best] = drifts[0], worst = drifts[drifts.length - 1];
        accNotes.update({section: '5', heading: 'Hamiltonian Mechanics: Example: Motion in a Central Potential V(r)',
          formula: ['H = p²/2m − G M m / r,  dH/dt = ∂H/∂t = 0  ⇒  H stays ' + fmt(E0, 7)],
          what: 'the energy', formulaShown: `H = ${fmt(E0, 7)}, the same at every time`,
          apiShown: `kept to ${sci(e.max_relative_drift)} of it (relative) by ${best.method} ${setting(best)}, the best of the runs`,
          abs: Math.abs(E0) * e.max_relative_drift, rel: e.max_relative_drift, unit: '',
          how: 'The energy from the start\'s position and velocity (in this page; the scene\'s units: GM = 1), against its largest change along each integrated orbit.',
          note: `The worst run, ${worst[1].method} ${setting(worst[1])}, changes it by ${sci(worst[0].max_relative_drift)}: ` +
            'a symplectic method (verlet, yoshida4) keeps the energy within a bound for ever; an adaptive one lets it drift slowly. ' +
            'The extracted notes end at §4.2: the Hamiltonian chapter\'s section numbers are not in their text.'});
      } else put(accNotes.box);
      linePlot(plot, Object.entries(by).map(([m, pts]) => ({label: m, points: pts.sort((p, q) => p[0] - q[0]), markers: true})),
        {xlabel: 'right-hand-side evaluations', ylabel: 'max position error', logx: true, logy: true, legend: 'bottom', name: 'work-precision'});
      // the CSV of every run, with the tolerance or step it used
      plotTools(plot, {name: 'work-precision', csv: () => 'method,rtol,dt,status,rhs_evaluations,max_position_error\n' +
        r.runs.map(x => { const q = x.requested || {};
          return [x.method || q.method || '', x.rtol ?? q.rtol ?? '', x.dt ?? q.dt ?? '', x.status || '',
            x.status === 'ok' ? x.rhs_evaluations : '', x.status === 'ok' ? x.max_position_error : ''].join(','); }).join('\n') + '\n'});
    });
    run();
  },
};
