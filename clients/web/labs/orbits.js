// Orbits lab: the Schwarzschild precession of Mercury and light bending by the
// Sun (POST /v1/gr/geodesic, timelike and null).
import {el, field, val, fmt, num, svg, labLayout, runner, examplePicker, linePlot, api, curlBox, showProblem, clearErrors} from '../lib.js';

const BUILTIN = [{title: 'Mercury: 43″ per century', operation: '/v1/gr/geodesic',
  request: {M: 'sun', kind: 'timelike', initial: {semi_major_axis: 57909050000, eccentricity: 0.20563593}, orbits: 3, samples: 5}}];

export default {
  id: 'orbits', title: 'Orbits',
  mount(main) {
    const L = labLayout(main, {title: 'Orbits: Schwarzschild precession',
      intro: 'A test mass around the Sun in Schwarzschild spacetime: its perihelion advances by about 6πGM/(c²a(1−e²)) per orbit.'});
    const a = field({label: 'semi-major axis', pointer: '/initial/semi_major_axis', value: 57909050000, unit: 'm', id: 'orb-a'});
    const e = field({label: 'eccentricity', pointer: '/initial/eccentricity', value: 0.20563593, id: 'orb-e'});
    const n = field({label: 'orbits', pointer: '/orbits', value: 3, id: 'orb-n'});
    L.form.append(examplePicker(['/v1/gr/geodesic'], BUILTIN, (ex) => {
      if (ex.request.initial) { a.input.value = ex.request.initial.semi_major_axis; e.input.value = ex.request.initial.eccentricity; }
      if (ex.request.orbits) n.input.value = ex.request.orbits; run();
    }), a.wrap, e.wrap, n.wrap, el('div', {class: 'buttons'}, el('button', {type: 'submit', id: 'orb-submit'}, 'Orbit')));
    const plot = svg('svg', {class: 'plot', id: 'orb-plot', role: 'img', 'aria-label': 'orbit'});
    L.figure.append(el('h3', {}, 'The orbit'), plot);
    const run = runner(L, '/v1/gr/geodesic', () => ({M: 'sun', kind: 'timelike',
      initial: {semi_major_axis: val(a.input), eccentricity: val(e.input)}, orbits: val(n.input), samples: 600}), (r) => {
      const p = r.precession;
      L.results.replaceChildren(el('dl', {class: 'nums'},
        el('dt', {}, 'advance per orbit (measured)'), num('orb-measured', p.measured_per_orbit, 'rad'),
        el('dt', {}, 'exact'), num('orb-exact', p.exact_per_orbit, 'rad'),
        el('dt', {}, '6πGM/(c²a(1−e²))'), num('orb-first', p.first_order_per_orbit, 'rad'),
        el('dt', {}, 'per century'), num('orb-century', p.arcsec_per_century.measured, '″')));
      const s = r.samples;
      linePlot(plot, [{points: s.r.map((rr, i) => [rr * Math.cos(s.phi[i]), rr * Math.sin(s.phi[i])]), label: 'orbit (m)'}],
        {xlabel: 'x [m]', ylabel: 'y [m]', equal: true});
    });
    run();

    // light bending: a null geodesic past the Sun
    const lf = el('form', {novalidate: true, id: 'light-form', 'aria-label': 'Light bending inputs'});
    const lb = field({label: 'impact parameter b', pointer: '/initial/impact_parameter', value: 696340000, unit: 'm', id: 'light-b',
      help: 'the Sun\'s radius grazes it'});
    const lprob = el('div', {class: 'problem', role: 'alert'}), lres = el('section', {class: 'results', 'aria-live': 'polite'});
    const lplot = svg('svg', {class: 'plot', id: 'light-plot', role: 'img', 'aria-label': 'light ray bent by the Sun (exaggerated)'});
    const lcurl = curlBox();
    lf.append(lb.wrap, el('div', {class: 'buttons'}, el('button', {type: 'submit', id: 'light-submit'}, 'Shine')));
    main.append(el('h2', {}, 'Light bending'), el('p', {class: 'intro'},
      'Starlight passing the Sun at impact parameter b is deflected by 4GM/(c²b) to first order: 1.75″ at the limb (Eddington, 1919).'),
      el('div', {class: 'grid'}, el('div', {}, lf, lprob, lcurl.box), el('div', {}, lres, lplot)));
    const lrun = async () => {
      const body = {M: 'sun', kind: 'null', r0: 1e13, initial: {impact_parameter: val(lb.input)}, samples: 200};
      lcurl.update('/v1/gr/geodesic', body);
      const r = await api('/v1/gr/geodesic', body);
      if (!r.ok) { showProblem(lf, lprob, r.status, r.body); lf.dataset.state = 'error'; return; }
      clearErrors(lf, lprob); lf.dataset.state = 'done';
      const d = r.body.deflection;
      lres.replaceChildren(el('dl', {class: 'nums'},
        el('dt', {}, 'deflection (measured)'), num('light-measured', d.arcsec.measured, '″'),
        el('dt', {}, 'exact'), num('light-exact', d.arcsec.exact, '″'),
        el('dt', {}, '4GM/(c²b)'), num('light-first', d.arcsec.first_order, '″'),
        el('dt', {}, 'closest approach'), num('light-rmin', d.closest_approach, 'm')));
      // schematic: the ray's two asymptotes, the angle between them drawn ×(30°/deflection)
      const W = 640, H = 300; lplot.replaceChildren(); lplot.setAttribute('viewBox', `0 0 ${W} ${H}`);
      const shown = Math.PI / 6, cx = W / 2, cy = H / 2 + 30, y0 = cy - 40;
      lplot.append(svg('circle', {cx, cy, r: 34, fill: '#f59f00'}),
        svg('line', {x1: 20, y1: y0, x2: cx, y2: y0, stroke: '#1864ab', 'stroke-width': 3}),
        svg('line', {x1: cx, y1: y0, x2: cx + 300 * Math.cos(shown), y2: y0 + 300 * Math.sin(shown), stroke: '#1864ab', 'stroke-width': 3}),
        svg('line', {x1: cx, y1: y0, x2: W - 20, y2: y0, stroke: '#999', 'stroke-dasharray': '6 5'}),
        svg('text', {x: cx + 120, y: y0 + 30, 'font-size': 17, fill: '#c92a2a', 'font-weight': 700}, `δ = ${fmt(d.arcsec.measured, 4)}″`),
        svg('text', {x: 14, y: H - 12, 'font-size': 14, fill: '#444'}, `angle drawn ×${fmt(shown / d.measured, 3)}`));
    };
    lf.addEventListener('submit', (e) => { e.preventDefault(); lrun(); });
    lrun();
  },
};
