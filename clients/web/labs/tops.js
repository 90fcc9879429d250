// Tops lab: the heavy symmetric top (POST /v1/rigid/top): the symmetry axis
// tracing nutation loops on the unit sphere and θ(t); and the Dzhanibekov flip
// of an asymmetric free body (POST /v1/rigid/rotate).
import {el, svg, field, val, fmt, num, labLayout, runner, examplePicker, linePlot, showProblem, clearErrors, api, curlBox} from '../lib.js';

const BUILTIN = [{title: 'Fast top: I1 = 0.02, I3 = 0.01, θ0 = 0.5, ψ̇ = 60 rad/s', operation: '/v1/rigid/top',
  request: {I1: 0.02, I3: 0.01, mass: 1, distance: 0.1, theta: 0.5, psi_dot: 60, t_end: 2, samples: 801}}];

export default {
  id: 'tops', title: 'Tops',
  mount(main) {
    const L = labLayout(main, {title: 'The heavy symmetric top',
      intro: 'Released with spin ψ̇ at tilt θ0 and no precession, the top\'s axis dips and loops: θ(t) nutates between the ' +
             'roots of the cubic, and the axis tip draws loops on the sphere (seen from above).'});
    const f = {
      I1: field({label: 'I1', pointer: '/I1', value: 0.02, unit: 'kg m²', id: 'top-I1'}),
      I3: field({label: 'I3', pointer: '/I3', value: 0.01, unit: 'kg m²', id: 'top-I3'}),
      mass: field({label: 'mass', pointer: '/mass', value: 1, unit: 'kg', id: 'top-mass'}),
      distance: field({label: 'tip to CM', pointer: '/distance', value: 0.1, unit: 'm', id: 'top-distance'}),
      theta: field({label: 'θ0', pointer: '/theta', value: 0.5, unit: 'rad', id: 'top-theta'}),
      psi_dot: field({label: 'spin ψ̇', pointer: '/psi_dot', value: 60, unit: 'rad/s', id: 'top-psidot'}),
      t_end: field({label: 'duration', pointer: '/t_end', value: 2, unit: 's', id: 'top-tend'}),
    };
    L.form.append(examplePicker(['/v1/rigid/top'], BUILTIN, (ex) => {
      for (const [k, c] of Object.entries(f)) if (ex.request[k] !== undefined) c.input.value = ex.request[k];
      run();
    }), ...Object.values(f).map(c => c.wrap), el('div', {class: 'buttons'}, el('button', {type: 'submit', id: 'top-submit'}, 'Spin')));
    const sphere = svg('svg', {class: 'plot', id: 'top-sphere', role: 'img', 'aria-label': 'axis tip seen from above'});
    const theta = svg('svg', {class: 'plot', id: 'top-theta-plot', role: 'img', 'aria-label': 'theta against time'});
    L.figure.append(el('h3', {}, 'Axis tip on the sphere (top view)'), sphere, el('h3', {}, 'θ(t)'), theta);
    const run = runner(L, '/v1/rigid/top', () => {
      const b = {}; for (const [k, c] of Object.entries(f)) b[k] = val(c.input); b.samples = 801; return b;
    }, (a) => {
      L.results.replaceChildren(el('dl', {class: 'nums'},
        el('dt', {}, 'θ min'), num('top-thmin', a.nutation.theta_min, 'rad'),
        el('dt', {}, 'θ max'), num('top-thmax', a.nutation.theta_max, 'rad'),
        el('dt', {}, 'mean precession'), num('top-prec', a.precession.measured_mean_rate, 'rad/s'),
        el('dt', {}, 'sleeping top stable'), el('dd', {id: 'top-sleeping'}, String(a.sleeping_top.stable)),
        el('dt', {}, 'energy drift'), num('top-drift', a.conserved.energy.max_relative_drift)));
      linePlot(sphere, [{points: a.axis.map(v => [v[0], v[1]]), label: 'axis tip (x, y)'}], {xlabel: 'x', ylabel: 'y', equal: true});
      linePlot(theta, [{points: a.t.map((t, i) => [t, a.theta[i]]), label: 'θ'}], {xlabel: 't [s]', ylabel: 'θ [rad]'});
    });
    run();

    // Dzhanibekov
    const df = el('form', {novalidate: true, id: 'dz-form', 'aria-label': 'Dzhanibekov inputs'});
    const dm = [1, 2, 3].map((v, k) => field({label: `I${k + 1}`, pointer: `/moments/${k}`, value: v, cls: 'small', id: `dz-I${k}`}));
    const dw = field({label: 'ω₂ (middle axis)', pointer: '/omega/1', value: 1, unit: 'rad/s', id: 'dz-w'});
    const dprob = el('div', {class: 'problem', role: 'alert'}), dres = el('section', {class: 'results', 'aria-live': 'polite'});
    const dplot = svg('svg', {class: 'plot', id: 'dz-plot', role: 'img', 'aria-label': 'omega components against time'});
    const dcurl = curlBox();
    df.append(...dm.map(c => c.wrap), dw.wrap, el('div', {class: 'buttons'}, el('button', {type: 'submit', id: 'dz-submit'}, 'Spin')));
    main.append(el('h2', {}, 'The Dzhanibekov flip'), el('p', {class: 'intro'},
      'Spun about the middle principal axis with a small wobble, a free body flips over again and again.'),
      el('div', {class: 'grid'}, el('div', {}, df, dprob, dcurl.box), el('div', {}, dres, dplot)));
    const drun = async () => {
      const body = {moments: dm.map(c => val(c.input)), omega: [0.01, val(dw.input), 0.01], t_end: 60, samples: 601};
      dcurl.update('/v1/rigid/rotate', body);
      const r = await api('/v1/rigid/rotate', body);
      if (!r.ok) { showProblem(df, dprob, r.status, r.body); df.dataset.state = 'error'; return; }
      clearErrors(df, dprob); df.dataset.state = 'done';
      const a = r.body, om = a.omega || (a.samples && a.samples.omega) || [];
      const t = a.t || (a.samples && a.samples.t) || [];
      dres.replaceChildren(el('dl', {class: 'nums'},
        el('dt', {}, 'flip interval (exact)'), num('dz-flip', a.flip ? a.flip.exact_flip_interval : NaN, 's'),
        el('dt', {}, 'period (exact, elliptic)'), num('dz-period', a.flip ? a.flip.exact_period : NaN, 's'),
        el('dt', {}, 'flips seen'), el('dd', {id: 'dz-seen'}, String(a.flip ? a.flip.sign_changes_seen : '?'))));
      if (t.length && om.length) linePlot(dplot, [0, 1, 2].map(k => ({points: t.map((tt, i) => [tt, om[i][k]]), label: `ω${k + 1}`})),
        {xlabel: 't [s]', ylabel: 'ω (body) [rad/s]'});
    };
    df.addEventListener('submit', (e) => { e.preventDefault(); drun(); });
    drun();
  },
};
