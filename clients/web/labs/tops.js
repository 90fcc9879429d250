// Tops lab: the heavy symmetric top (POST /v1/rigid/top): the symmetry axis
// tracing nutation loops on the unit sphere and θ(t); and the Dzhanibekov flip
// of an asymmetric free body (POST /v1/rigid/rotate).
import {el, svg, put, add, field, val, num, labLayout, labSection, runner, examplePicker, linePlot} from '../lib.js';

const BUILTIN = [{title: 'Fast top: I1 = 0.02, I3 = 0.01, θ0 = 0.5, ψ̇ = 60 rad/s', operation: '/v1/rigid/top',
  request: {I1: 0.02, I3: 0.01, mass: 1, distance: 0.1, theta: 0.5, psi_dot: 60, t_end: 2, samples: 801}},
  {title: 'Dzhanibekov flip: spun about the middle axis', operation: '/v1/rigid/rotate',
   request: {moments: [1, 2, 3], omega: [0.01, 1, 0.01], t_end: 60, samples: 601}}];

export default {
  id: 'tops', title: 'Tops',
  mount(main) {
    const L = labLayout(main, {title: 'The heavy symmetric top',
      intro: 'Released with spin ψ̇ at tilt θ0 and no precession (φ̇0 = 0), the top\'s axis dips and loops: θ(t) nutates between the ' +
             'roots of the cubic, and the axis tip draws loops on the sphere (seen from above). Started at the steady rate φ̇0, ' +
             'it precesses without nodding.'});
    const f = {
      I1: field({label: 'I1', pointer: '/I1', value: 0.02, unit: 'kg m²', id: 'top-I1'}),
      I3: field({label: 'I3', pointer: '/I3', value: 0.01, unit: 'kg m²', id: 'top-I3'}),
      mass: field({label: 'mass', pointer: '/mass', value: 1, unit: 'kg', id: 'top-mass'}),
      distance: field({label: 'tip to CM', pointer: '/distance', value: 0.1, unit: 'm', id: 'top-distance'}),
      theta: field({label: 'θ0', pointer: '/theta', value: 0.5, unit: 'rad', id: 'top-theta'}),
      phi_dot: field({label: 'precession φ̇0', pointer: '/phi_dot', value: 0, unit: 'rad/s', id: 'top-phidot'}),
      psi_dot: field({label: 'spin ψ̇', pointer: '/psi_dot', value: 60, unit: 'rad/s', id: 'top-psidot'}),
      t_end: field({label: 'duration', pointer: '/t_end', value: 2, unit: 's', id: 'top-tend'}),
    };
    add(L.form, examplePicker(['/v1/rigid/top', '/v1/rigid/rotate'], BUILTIN, (ex) => {
      const r = ex.request;
      if (ex.operation === '/v1/rigid/rotate') {
        dm.forEach((c, k) => { c.input.value = r.moments[k]; }); dw.forEach((c, k) => { c.input.value = r.omega[k]; });
        dt.input.value = r.t_end; drun(); df.scrollIntoView({block: 'nearest'}); return;
      }
      for (const [k, c] of Object.entries(f)) c.input.value = r[k] !== undefined ? r[k] : k === 'phi_dot' ? 0 : c.input.value;
      run();
    }, {fits: (ex) => ex.operation !== '/v1/rigid/rotate' || (Array.isArray(ex.request.moments) && Array.isArray(ex.request.omega) &&
        typeof ex.request.t_end === 'number' && !ex.request.orientation)}),
    Object.values(f).map(c => c.wrap), el('div', {class: 'buttons'}, el('button', {type: 'submit', id: 'top-submit'}, 'Spin')));
    const sphere = svg('svg', {class: 'plot', id: 'top-sphere', role: 'img', 'aria-label': 'axis tip seen from above'});
    const theta = svg('svg', {class: 'plot', id: 'top-theta-plot', role: 'img', 'aria-label': 'theta against time'});
    add(L.figure, el('h3', {}, 'Axis tip on the sphere (top view)'), sphere, el('h3', {}, 'θ(t)'), theta);
    const run = runner(L, '/v1/rigid/top', () => {
      const b = {}; for (const [k, c] of Object.entries(f)) b[k] = val(c.input); b.samples = 801; return b;
    }, (a) => {
      put(L.results, el('dl', {class: 'nums'},
        el('dt', {}, 'θ min'), num('top-thmin', a.nutation.theta_min, 'rad'),
        el('dt', {}, 'θ max'), num('top-thmax', a.nutation.theta_max, 'rad'),
        el('dt', {}, 'mean precession'), num('top-prec', a.precession.measured_mean_rate, 'rad/s'),
        el('dt', {}, 'sleeping top stable'), el('dd', {id: 'top-sleeping'}, String(a.sleeping_top.stable)),
        el('dt', {}, 'energy drift'), num('top-drift', a.conserved.energy.max_relative_drift)));
      linePlot(sphere, [{points: a.axis.map(v => [v[0], v[1]]), label: 'axis tip (x, y)'}], {xlabel: 'x', ylabel: 'y', equal: true});
      linePlot(theta, [{points: a.t.map((t, i) => [t, a.theta[i]]), label: 'θ'}], {xlabel: 't [s]', ylabel: 'θ [rad]'});
    });
    run();

    // free rotation (Dzhanibekov)
    const df = el('form', {novalidate: true, id: 'dz-form', 'aria-label': 'Free rotation inputs'});
    const dm = [1, 2, 3].map((v, k) => field({label: `I${k + 1}`, pointer: `/moments/${k}`, value: v, unit: 'kg m²', cls: 'small', id: `dz-I${k}`}));
    const dw = [0.01, 1, 0.01].map((v, k) => field({label: `ω${'₁₂₃'[k]}`, pointer: `/omega/${k}`, value: v, unit: 'rad/s',
      cls: 'small', id: k === 1 ? 'dz-w' : `dz-w${k}`, help: k === 1 ? 'about the middle axis' : undefined}));
    const dt = field({label: 'duration', pointer: '/t_end', value: 60, unit: 's', id: 'dz-tend'});
    add(df, dm.map(c => c.wrap), dw.map(c => c.wrap), dt.wrap,
      el('div', {class: 'buttons'}, el('button', {type: 'submit', id: 'dz-submit'}, 'Spin')));
    const D = labSection(main, {title: 'The Dzhanibekov flip', form: df,
      intro: 'Spun about the middle principal axis with a small wobble (ω₁, ω₃), a free body flips over again and again.'});
    const dplot = svg('svg', {class: 'plot', id: 'dz-plot', role: 'img', 'aria-label': 'omega components against time'});
    add(D.figure, dplot);
    const drun = runner(D, '/v1/rigid/rotate', () => ({moments: dm.map(c => val(c.input)), omega: dw.map(c => val(c.input)),
      t_end: val(dt.input), samples: 601}), (a) => {
      const om = a.omega || (a.samples && a.samples.omega) || [];
      const t = a.t || (a.samples && a.samples.t) || [];
      put(D.results, el('dl', {class: 'nums'}, a.flip ? [
        el('dt', {}, 'flip interval (exact)'), num('dz-flip', a.flip.exact_flip_interval, 's'),
        el('dt', {}, 'period (exact, elliptic)'), num('dz-period', a.flip.exact_period, 's'),
        el('dt', {}, 'flips seen'), el('dd', {id: 'dz-seen'}, String(a.flip.sign_changes_seen))]
        : [el('dt', {}, 'flips'), el('dd', {id: 'dz-seen'}, 'none: not spun near the middle axis')]));
      if (t.length && om.length) linePlot(dplot, [0, 1, 2].map(k => ({points: t.map((tt, i) => [tt, om[i][k]]), label: `ω${k + 1}`})),
        {xlabel: 't [s]', ylabel: 'ω (body) [rad/s]'});
    });
    drun();
  },
};
