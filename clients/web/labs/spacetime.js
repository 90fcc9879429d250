// Spacetime lab: a Minkowski diagram (events, light cone, the boosted axes
// ct' and x' sliding with beta, the invariant hyperbola) from
// POST /v1/relativity/boost, and the twin paradox from /v1/relativity/worldline
// (played: both twins move up their worldlines, each clock showing its proper time).
import {player} from '../anim.js';
import {el, svg, put, add, field, val, fmt, num, labLayout, labSection, runner, examplePicker, linePlot,
        drawPlot, plotSize, plotTools, notesBox} from '../lib.js';
import {handle, rerun} from '../handles.js';

const BUILTIN = [
  {title: 'Boost by β = 0.6: the event (ct, x) = (1, 0) → (1.25, −0.75)', operation: '/v1/relativity/boost',
   request: {vectors: [[1, 0, 0, 0], [1, 1, 0, 0], [2, 0.5, 0, 0]], velocity: {beta: [0.6, 0, 0]}}},
];
const st = {events: '1, 0; 1, 1; 2, 0.5', beta: 0.6};
const SLIDER_MAX = 0.99;

// The events of a boost request: "vectors" is one 4-vector or a list of them.
const eventsOf = (vectors) => (Array.isArray(vectors) && vectors.length && !Array.isArray(vectors[0]) ? [vectors] : vectors || []);
// A worldline example the twin form can hold: out at β and back at −β over the same distance.
const twinLike = (r) => r && Array.isArray(r.legs) && r.legs.length === 2 && r.legs.every(l =>
  l.velocity && Array.isArray(l.velocity.beta) && typeof l.distance === 'number' && !l.velocity.beta[1] && !l.velocity.beta[2]) &&
  r.legs[0].velocity.beta[0] === -r.legs[1].velocity.beta[0] && r.legs[0].distance === r.legs[1].distance;

export default {
  id: 'spacetime', title: 'Spacetime',
  mount(main) {
    const L = labLayout(main, {title: 'Spacetime: Minkowski diagram and the twin paradox',
      intro: 'Events (ct, x) seen from a frame moving with velocity β along x. The boosted axes ct′ and x′ close ' +
             'in on the light cone as β grows; every event stays on its hyperbola c²t² − x² = const.'});
    const ev = field({label: 'Events (ct, x; …)', pointer: '/vectors', value: st.events, type: 'text', id: 'st-events',
      help: 'ct and x in one unit of length (light-seconds, metres…); separate events with ;'});
    const beta = field({label: 'β = v/c', pointer: '/velocity/beta', value: st.beta, step: 0.01, id: 'st-beta'});
    const clampB = (b) => Math.max(-SLIDER_MAX, Math.min(SLIDER_MAX, b));
    const slider = el('input', {type: 'range', min: -SLIDER_MAX, max: SLIDER_MAX, step: 0.01, value: clampB(st.beta),
      id: 'st-beta-slider', 'aria-label': 'β slider (moves the diagram)'});
    const shown = el('output', {for: 'st-beta-slider', id: 'st-beta-shown'}, 'β = ' + fmt(st.beta));
    add(L.form, examplePicker(['/v1/relativity/boost', '/v1/relativity/worldline'], BUILTIN, (ex) => {
      if (ex.operation === '/v1/relativity/worldline') {
        tb.input.value = ex.request.legs[0].velocity.beta[0]; td.input.value = ex.request.legs[0].distance;
        trun(); tw.scrollIntoView({block: 'nearest'}); return;
      }
      ev.input.value = eventsOf(ex.request.vectors).map(v => `${v[0]}, ${v[1]}`).join('; ');
      if (ex.request.velocity && ex.request.velocity.beta) setBeta(ex.request.velocity.beta[0]);
      run();
    }, {fits: (ex) => ex.operation !== '/v1/relativity/worldline' || (twinLike(ex.request) && ex.request.units === 'years')}),
    ev.wrap, beta.wrap, el('div', {class: 'buttons'}, el('button', {type: 'submit', id: 'st-submit'}, 'Boost')));
    const setBeta = (b) => { beta.input.value = b; slider.value = clampB(b); shown.textContent = 'β = ' + fmt(b); };
    const parse = () => ev.input.value.split(';').map(s => s.trim()).filter(Boolean)
      .map(s => { const [t, x] = s.split(',').map(v => (v === undefined || v.trim() === '' ? NaN : Number(v))); return [t, x, 0, 0]; });
    // a group, not an image: the events on it are handles (role slider) to drag or move with the arrow keys
    const plot = svg('svg', {class: 'plot', id: 'st-diagram', role: 'group', 'aria-label': 'Minkowski diagram: drag an event, or focus it and use the arrow keys'});
    const tickNote = el('span', {id: 'st-ticks'});
    // the slider sits right under the diagram it moves (on a phone too)
    add(L.figure, el('h3', {}, 'Minkowski diagram'), plot,
      el('div', {class: 'figure-control'}, el('label', {for: 'st-beta-slider'}, 'Drag β:'), slider, shown),
      el('p', {class: 'muted'}, 'grey: light cone x = ±ct; ', el('span', {class: 'c3'}, 'blue: ct′ and x′ axes, dots evenly spaced ' +
        'in the moving frame', tickNote), '; ', el('span', {class: 'c1'}, 'red: events'), '; dashed: their hyperbolae'));
    const boostNotes = notesBox('st-notes'); L.figure.after(boostNotes.box); // under the figure: the picture stays by the answer
    const run = runner(L, '/v1/relativity/boost', () => {
      st.events = ev.input.value; st.beta = val(beta.input);
      return {vectors: parse(), velocity: {beta: [val(beta.input), 0, 0]}};
    }, (a, body) => {
      put(L.results, el('h3', {}, 'Answer'),
        el('dl', {class: 'nums'}, el('dt', {}, 'γ'), num('st-gamma', a.gamma), el('dt', {}, 'rapidity'), num('st-rapidity', a.rapidity)),
        el('table', {id: 'st-table'}, el('tr', {}, ['event', 'ct', 'x', 'ct′', 'x′', 'c²t² − x²'].map(h => el('th', {}, h))),
          body.vectors.map((v, i) => el('tr', {}, el('td', {}, String(i + 1)), el('td', {}, fmt(v[0])), el('td', {}, fmt(v[1])),
            el('td', {id: `st-ctp-${i}`, 'data-value': a.vectors[i][0]}, fmt(a.vectors[i][0])),
            el('td', {id: `st-xp-${i}`, 'data-value': a.vectors[i][1]}, fmt(a.vectors[i][1])),
            el('td', {}, fmt(-a.invariants_after[i]))))));
      // notes §3.3 The Lorentz Transformation: x′ = γ(x − βct), ct′ = γ(ct − βx), γ = 1/√((1 − β)(1 + β))
      // computed here from the inputs (β near 1 kept as (1 − β)(1 + β), never 1 − β²)
      const b = body.velocity.beta[0], g = 1 / Math.sqrt((1 - b) * (1 + b));
      const mine = body.vectors.map(v => [g * (v[0] - b * v[1]), g * (v[1] - b * v[0])]);
      const big = Math.max(...a.vectors.flatMap(v => [Math.abs(v[0]), Math.abs(v[1])])) || 1;
      const abs = Math.max(0, ...mine.map((v, i) => Math.max(Math.abs(v[0] - a.vectors[i][0]), Math.abs(v[1] - a.vectors[i][1]))));
      const ev1 = (v) => v ? `event 1: ct′ = ${fmt(v[0], 7)}, x′ = ${fmt(v[1], 7)}` : '—';
      boostNotes.update({section: '3.3', heading: 'The Lorentz Transformation',
        formula: ['x′ = γ (x − β ct),  ct′ = γ (ct − β x),  γ = 1/√(1 − β²)'],
        what: 'the formula', formulaShown: ev1(mine[0]), apiShown: ev1(a.vectors[0]), abs, rel: abs / big,
        how: 'Every event boosted by the formula in this page and by the API; the difference is the largest over the events\' ct′ and x′.',
        note: 'The API keeps its digits near β = 1 by working with the rapidity (γ = cosh η, βγ = sinh η); this page takes ' +
          '1 − β² as (1 − β)(1 + β), which loses nothing when β is typed in.'});
      drawPlot(plot, () => diagram(plot, body.vectors, a.beta[0], tickNote, {R: dragR, onEvent: moveEvent}));
      plotTools(plot, {name: 'minkowski', csv: () => 'event,ct,x,ct_boosted,x_boosted,beta\n' +
        body.vectors.map((v, i) => [i + 1, v[0], v[1], a.vectors[i][0], a.vectors[i][1], a.beta[0]].join(',')).join('\n') + '\n'});
    });
    // an event dragged on the diagram (or moved with the arrow keys): its (ct, x) in the events field, the boost asked again
    let dragR = null;
    const again = rerun(() => run());
    const moveEvent = (i, x, t, done, R) => {
      const vs = parse(), r2 = (v) => Number(v.toFixed(2));
      if (!vs[i]) return;
      vs[i] = [r2(t), r2(x)];
      ev.input.value = vs.map(v => `${v[0]}, ${v[1]}`).join('; ');
      dragR = done ? null : R; // the scale stays put while the event is dragged
      again(done);
    };
    slider.addEventListener('input', () => { beta.input.value = slider.value; shown.textContent = 'β = ' + fmt(Number(slider.value)); run(); });
    beta.input.addEventListener('change', () => { const b = val(beta.input); if (isFinite(b)) { slider.value = clampB(b); shown.textContent = 'β = ' + fmt(b); } });
    run();

    // --- twins ---
    const tw = el('form', {novalidate: true, 'aria-label': 'Twin paradox inputs', id: 'twin-form'});
    const tb = field({label: 'β out and back', pointer: '/legs/0/velocity/beta /legs/1/velocity/beta', value: 0.8, step: 0.01, id: 'tw-beta'});
    const td = field({label: 'distance', pointer: '/legs/0/distance /legs/1/distance', value: 8, unit: 'ly', id: 'tw-dist'});
    add(tw, tb.wrap, td.wrap, el('div', {class: 'buttons'}, el('button', {type: 'submit', id: 'tw-submit'}, 'Travel')));
    const T = labSection(main, {title: 'The twin paradox', form: tw,
      intro: 'One twin travels out at β and back; the other stays home. The traveller\'s proper time is shorter by the factor 1/γ.'});
    const tplot = svg('svg', {class: 'plot', id: 'tw-diagram', role: 'img', 'aria-label': 'Twin worldlines'});
    const clocks = el('p', {class: 'clocks', id: 'tw-clocks'});
    const tplay = player({label: 'The twins', unit: 'yr', seconds: 3.15576e7});
    add(T.figure, tplot, tplay.root, clocks,
      el('p', {class: 'muted'}, 'Played in the stay-at-home frame\'s time ct: each twin\'s dot moves along its worldline and its clock ',
        'shows its own proper time (the traveller\'s between the legs\' ends at each leg\'s constant rate).'));
    const twinNotes = notesBox('tw-notes'); T.figure.after(twinNotes.box); // under the figure: the picture stays by the answer
    const trun = runner(T, '/v1/relativity/worldline', () => {
      const b = val(tb.input), d = val(td.input);
      return {units: 'years', legs: [{velocity: {beta: [b, 0, 0]}, distance: d}, {velocity: {beta: [-b, 0, 0]}, distance: d}]};
    }, (r) => {
      const t = r.total;
      put(T.results, el('dl', {class: 'nums'},
        el('dt', {}, 'traveller ages'), num('tw-proper', t.proper_time, 'yr'),
        el('dt', {}, 'stay-at-home ages'), num('tw-home', t.stay_at_home_time, 'yr'),
        el('dt', {}, 'difference'), num('tw-diff', t.age_difference, 'yr')));
      // notes, The Twin Paradox (after §3.14): the traveller's proper time dτ = dt √(1 − β²) on each leg
      const coast = r.legs.every(l => !l.kind || l.kind === 'coast'); // straight legs: τ = √(Δt² − Δx²) each
      const tau = r.legs.reduce((sum, l) => { const dt = l.end[0] - l.start[0], dx = Math.hypot(...[1, 2, 3].map(k => l.end[k] - l.start[k]));
        return sum + (coast ? Math.sqrt((dt - dx) * (dt + dx)) : l.proper_time); }, 0);
      twinNotes.update({section: '3.15', inferred: true, heading: 'The Twin Paradox',
        formula: ['τ = ∫ dt √(1 − β²) = t / γ  on each straight leg'],
        what: 'the formula', formulaValue: tau, apiValue: t.proper_time, unit: 'yr',
        sourceText: coast ? 'computed in this page from the API\'s leg ends: τ = √(Δt² − Δx²) for each leg (c = 1 ly/yr)'
          : 'a leg that accelerates is not a straight line: the sum of the API\'s legs',
        how: 'The traveller\'s age at the reunion, summed over the legs.'});
      const trav = [[0, 0], ...r.legs.map(l => [l.end[1], l.end[0]])];
      // the played state at coordinate time ct: the traveller's place and proper time within its leg
      const legs = r.legs.map(l => ({t0: l.start[0], t1: l.end[0], x0: l.start[1], x1: l.end[1], tau: l.proper_time}));
      const at = (ct) => {
        let tau = 0;
        for (const l of legs) {
          const f = l.t1 > l.t0 ? Math.min(1, Math.max(0, (ct - l.t0) / (l.t1 - l.t0))) : 1;
          if (ct < l.t1) return {x: l.x0 + (l.x1 - l.x0) * f, tau: tau + l.tau * f};
          tau += l.tau;
        }
        const e = legs[legs.length - 1];
        return {x: e ? e.x1 : 0, tau};
      };
      const dots = [svg('circle', {r: 7, fill: '#c92a2a', stroke: '#fff', 'stroke-width': 2, id: 'tw-home-dot'}),
        svg('circle', {r: 7, fill: '#2b8a3e', stroke: '#fff', 'stroke-width': 2, id: 'tw-trav-dot'})];
      let XY = null, now = 0;
      const place = () => { if (!XY) return; const p = at(now);
        dots[0].setAttribute('cx', XY[0](0)); dots[0].setAttribute('cy', XY[1](now));
        dots[1].setAttribute('cx', XY[0](p.x)); dots[1].setAttribute('cy', XY[1](now)); };
      linePlot(tplot, [{points: [[0, 0], [0, t.coordinate_time]], label: `home: ${fmt(t.stay_at_home_time, 4)} yr`},
        {points: trav, label: `traveller: ${fmt(t.proper_time, 4)} yr`}], {xlabel: 'x [ly]', ylabel: 'ct [yr]', equal: true,
        marks: [({X, Y}) => { XY = [X, Y]; const g = svg('g', {}); add(g, dots); place(); return g; }]});
      tplay.set([0, t.coordinate_time], (i, f, ct) => {
        now = ct; place();
        const p = at(ct);
        clocks.dataset.home = String(ct); clocks.dataset.traveller = String(p.tau);
        put(clocks, el('strong', {}, 'Clocks: '), `home ${fmt(ct, 4)} yr, traveller ${fmt(p.tau, 4)} yr `,
          el('span', {class: 'muted'}, `(the traveller ${fmt(Math.abs(p.x), 4)} ly from home)`));
      });
    });
    trun();
  },
};

// A round step (1, 2 or 5 × 10^k) giving about n ticks over a length R.
function niceStep(R, n) {
  const raw = R / n, p = Math.pow(10, Math.floor(Math.log10(raw))), f = raw / p;
  return (f < 1.5 ? 1 : f < 3.5 ? 2 : f < 7.5 ? 5 : 10) * p;
}

function diagram(root, vectors, b, note, {R: fixedR, onEvent} = {}) {
  const [W, H] = plotSize(root, 640, 480);
  const R = fixedR || Math.max(2.5, ...vectors.flatMap(v => [Math.abs(v[0]), Math.abs(v[1])]).filter(isFinite)) * 1.2;
  put(root); root.setAttribute('viewBox', `0 0 ${W} ${H}`);
  const s = (H / 2 - 10) / R, X = (x) => W / 2 + s * x, Y = (t) => H / 2 - s * t;
  X.invert = (px) => (px - W / 2) / s; Y.invert = (py) => (H / 2 - py) / s;
  const ln = (x0, t0, x1, t1, a) => add(root, svg('line', {x1: X(x0), y1: Y(t0), x2: X(x1), y2: Y(t1), ...a}));
  ln(-R * 1.4, 0, R * 1.4, 0, {stroke: '#000', 'stroke-width': 1.5}); ln(0, -R, 0, R, {stroke: '#000', 'stroke-width': 1.5});
  add(root, svg('text', {x: Math.min(X(R * 1.3), W - 14), y: Y(0) - 6, 'font-size': 18}, 'x'), svg('text', {x: X(0) + 6, y: Y(R) + 16, 'font-size': 18}, 'ct'));
  ln(-R, -R, R, R, {stroke: '#999', 'stroke-width': 2}); ln(-R, R, R, -R, {stroke: '#999', 'stroke-width': 2});
  // tick values every u (a round number) on x and ct, the same u as the boosted axes' marks
  const u0 = niceStep(R, 3), lab = (v) => fmt(v).replace('-', '−');
  for (let k = -Math.floor(R * 1.4 / u0); k <= Math.floor(R * 1.4 / u0); k++) if (k && X(k * u0) > 14 && X(k * u0) < W - 14) {
    ln(k * u0, -4 / s, k * u0, 4 / s, {stroke: '#000', 'stroke-width': 1.5});
    add(root, svg('text', {x: X(k * u0), y: Y(0) + 20, 'text-anchor': 'middle', 'font-size': 14, class: 'tick-x'}, lab(k * u0)));
  }
  for (let k = -Math.floor(R / u0); k <= Math.floor(R / u0); k++) if (k && Y(k * u0) > 14 && Y(k * u0) < H - 8) {
    ln(-4 / s, k * u0, 4 / s, k * u0, {stroke: '#000', 'stroke-width': 1.5});
    add(root, svg('text', {x: X(0) - 7, y: Y(k * u0) + 5, 'text-anchor': 'end', 'font-size': 14, class: 'tick-y'}, lab(k * u0)));
  }
  if (isFinite(b) && Math.abs(b) < 1) {
    ln(-R * b, -R, R * b, R, {stroke: '#1864ab', 'stroke-width': 3}); // ct' axis: x = beta ct
    ln(-R, -R * b, R, R * b, {stroke: '#1864ab', 'stroke-width': 3}); // x' axis: ct = beta x
    add(root, svg('text', {x: X(R * b) + 6, y: Y(R) + 18, fill: '#1864ab', 'font-size': 18, 'font-weight': 700}, 'ct′'),
      svg('text', {x: X(R) - 24, y: Y(R * b) - 8, fill: '#1864ab', 'font-size': 18, 'font-weight': 700}, 'x′'));
    // tick marks every u (a round number of units) on the boosted axes, those inside the picture:
    // (ct, x) = k u gamma (1, beta) on ct', k u gamma (beta, 1) on x'
    const g = 1 / Math.sqrt(1 - b * b), u = niceStep(R, 3);
    for (let k = -Math.ceil(R / u); k <= Math.ceil(R / u); k++) if (k && Math.abs(k * u * g) <= R) {
      add(root, svg('circle', {cx: X(k * u * g * b), cy: Y(k * u * g), r: 3, fill: '#1864ab'}),
        svg('circle', {cx: X(k * u * g), cy: Y(k * u * g * b), r: 3, fill: '#1864ab'}),
        svg('text', {x: X(k * u * g * b) + 7, y: Y(k * u * g) + 5, 'font-size': 13, fill: '#1864ab', class: 'tick-ctp'}, lab(k * u)),
        svg('text', {x: X(k * u * g), y: Y(k * u * g * b) + 19, 'font-size': 13, fill: '#1864ab', 'text-anchor': 'middle', class: 'tick-xp'}, lab(k * u)));
    }
    if (note) note.textContent = ` (every ${fmt(u)} units)`;
  }
  vectors.forEach((v, i) => {
    const [t, x] = v; if (!isFinite(t) || !isFinite(x)) return;
    const s2 = t * t - x * x;
    if (Math.abs(s2) > 1e-12) { // its hyperbola, through the event
      const a = Math.sqrt(Math.abs(s2)), pts = [];
      for (let u = -3; u <= 3.0001; u += 0.05) {
        const p = s2 > 0 ? [a * Math.sinh(u), Math.sign(t) * a * Math.cosh(u)] : [Math.sign(x) * a * Math.cosh(u), a * Math.sinh(u)];
        if (Math.abs(p[0]) <= R * 1.4 && Math.abs(p[1]) <= R) pts.push(`${X(p[0]).toFixed(1)},${Y(p[1]).toFixed(1)}`);
      }
      add(root, svg('polyline', {points: pts.join(' '), fill: 'none', stroke: '#c92a2a', 'stroke-dasharray': '6 5', 'stroke-width': 1.5}));
    }
    add(root, onEvent ? handle(root, {id: `st-event-${i}`, X, Y, at: [x, t], color: '#c92a2a', r: 8, step: [0.1, 0.1],
      label: `event ${i + 1}`, text: (x1, t1) => `event ${i + 1}: ct = ${fmt(t1, 4)}, x = ${fmt(x1, 4)}`,
      onMove: (x1, t1, done) => onEvent(i, x1, t1, done, R)}) : svg('circle', {cx: X(x), cy: Y(t), r: 7, fill: '#c92a2a'}),
      svg('text', {x: X(x) + 11, y: Y(t) - 11, 'font-size': 17, fill: '#c92a2a', 'font-weight': 700}, String(i + 1)));
  });
}
