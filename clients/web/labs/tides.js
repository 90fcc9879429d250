// Tides lab (chapter 1, §1.4): the tidal field around the Earth as arrows and
// the equilibrium tide's two bulges, from the Moon, the Sun or both, with the
// Sun aligned (spring tide) or at a quarter Moon (neap tide). One
// POST /v1/batch of /v1/earth/tides at every 15° (the field is symmetric about
// the line to each body, so 0…180° is enough), plus the marked point.
import {el, svg, put, add, field, val, fmt, num, labLayout, runner, examplePicker, plotSize, plotTools, pow10, notesBox, textShade} from '../lib.js';
import {player} from '../anim.js';

const MONTH = 29.53; // days from new Moon to new Moon (the synodic month)

const st = {show: 'both', sun: 0, point: 0};
const BUILTIN = [
  {title: 'Spring tide: Sun and Moon in line (new or full Moon)', operation: '/v1/earth/tides', section: '1.4 The Tides',
   request: {body: 'moon', angle_deg: 0}, lab: {show: 'both', sun: 0}},
  {title: 'Neap tide: the Sun at 90° (quarter Moon)', operation: '/v1/earth/tides', section: '1.4 The Tides',
   request: {body: 'moon', angle_deg: 0}, lab: {show: 'both', sun: 90}},
];
const STEP = 15, N = 360 / STEP;
const wrap = (d) => ((d + 540) % 360) - 180; // an angle in [−180°, 180°)

export default {
  id: 'tides', title: 'Tides',
  mount(main) {
    const L = labLayout(main, {title: 'Tides: the tidal field around the Earth',
      intro: 'The Earth falls freely towards the Moon (and the Sun), so what is felt on it is the difference between the ' +
             'pull at a point and at the centre: outwards on the sides facing towards and away from the body, inwards ' +
             'around the middle. The water piles up into two bulges; with the Sun in line they add (spring tide), with the ' +
             'Sun at 90° they partly cancel (neap tide).'});
    const show = field({label: 'Tide-raising body', pointer: '/operations', value: st.show, id: 'tides-show',
      options: [['both', 'Moon and Sun'], ['moon', 'Moon only'], ['sun', 'Sun only']]});
    const sun = field({label: 'Sun\'s angle from the Moon', pointer: '/operations', value: st.sun, id: 'tides-sun',
      options: [0, 15, 30, 45, 60, 75, 90, 105, 120, 135, 150, 165, 180].map(a => [a, a + '°' + (a === 0 ? ' (new Moon: spring)' :
        a === 90 ? ' (quarter Moon: neap)' : a === 180 ? ' (full Moon: spring)' : '')])});
    const point = field({label: 'Marked point: angle from the Moon', pointer: '/operations/0/request/angle_deg', value: st.point,
      id: 'tides-point', unit: '°', min: 0, max: 180, step: 1});
    add(L.form, examplePicker(['/v1/earth/tides'], BUILTIN, (ex) => {
      const r = ex.request || {};
      if (ex.lab) { show.input.value = ex.lab.show; sun.input.value = ex.lab.sun; }
      else { show.input.value = typeof r.body === 'string' ? r.body : 'moon'; sun.input.value = 0; }
      point.input.value = r.angle_deg || 0;
      run();
    }, {fits: (ex) => ex.request && (ex.request.body === 'moon' || ex.request.body === 'sun') && ex.request.radius === undefined}),
    show.wrap, sun.wrap, point.wrap, el('div', {class: 'buttons'}, el('button', {type: 'submit', id: 'tides-submit'}, 'Show the field')));
    for (const c of [show.input, sun.input]) c.addEventListener('change', () => run());

    const plot = svg('svg', {class: 'plot', id: 'tides-field', role: 'img', 'aria-label': 'The tidal field around the Earth'});
    const note = el('p', {class: 'muted', id: 'tides-note'});
    const month = player({label: 'A month of tides', unit: 'days', seconds: 86400});
    const phase = el('p', {id: 'tides-phase', class: 'muted'});
    add(L.figure, el('h3', {}, 'The tidal field and the bulges'), plot, month.root, phase, note);

    const tideNotes = notesBox('tides-notes');
    const run = runner(L, '/v1/batch', () => {
      const s = show.input.value, a = Number(sun.input.value), p = val(point.input);
      Object.assign(st, {show: s, sun: a, point: p});
      const ops = [];
      for (const b of ['moon', 'sun']) {
        // the marked point's angle from this body (the Sun is at a from the Moon)
        ops.push({operation: '/v1/earth/tides', request: {body: b, angle_deg: b === 'moon' || !isFinite(p) ? p : Math.abs(wrap(p - a))}});
        for (let k = 0; k <= 180 / STEP; k++) ops.push({operation: '/v1/earth/tides', request: {body: b, angle_deg: k * STEP}});
      }
      return {operations: ops};
    }, (res, req) => {
      const bad = res.results.findIndex(r => r.status !== 200);
      if (bad >= 0) { // placed on the field at fault like any problem (the marked point's item comes first); the picture stays, dimmed
        const pr = res.results[bad].problem || res.results[bad].body || {};
        return {status: res.results[bad].status, problem: {...pr, errors: (pr.errors || []).map(x => ({...x,
          pointer: x.pointer && x.pointer.startsWith('/operations/') ? x.pointer : `/operations/${bad}/request${x.pointer || ''}`}))}};
      }
      const m = 1 + 180 / STEP, body = (k) => res.results.slice(k * (m + 1), (k + 1) * (m + 1)).map(r => r.body);
      const [moon, sunA] = [body(0), body(1)];
      const s = st.show, alpha = st.sun;
      const M = moon[0], S = sunA[0];
      const a1 = M.acceleration;
      put(L.results, el('h3', {}, `At ${fmt(st.point)}° from the Moon`),
        el('dl', {class: 'nums'},
          el('dt', {}, 'Moon: radial pull (exact)'), num('tides-moon-radial', a1.exact.radial, 'm/s²'),
          el('dt', {}, 'Moon: tangential (exact)'), num('tides-moon-tangential', a1.exact.tangential, 'm/s²'),
          el('dt', {}, 'Moon: first order − exact'), num('tides-moon-diff', -a1.difference.magnitude, 'm/s²'),
          el('dt', {}, 'Moon: tide height here'), num('tides-moon-h', M.equilibrium_tide.height, 'm'),
          el('dt', {}, `Sun (${fmt(S.angle_deg)}° from it): tide height`), num('tides-sun-h', S.equilibrium_tide.height, 'm')),
        el('h3', {}, 'Spring and neap'),
        el('dl', {class: 'nums'},
          el('dt', {}, 'Moon\'s range'), num('tides-moon-range', M.spring_neap.moon_range, 'm'),
          el('dt', {}, 'Sun\'s range'), num('tides-sun-range', M.spring_neap.sun_range, 'm'),
          el('dt', {}, 'spring range (sum)'), num('tides-spring', M.spring_neap.spring_range, 'm'),
          el('dt', {}, 'neap range (difference)'), num('tides-neap', M.spring_neap.neap_range, 'm'),
          el('dt', {}, 'Sun / Moon'), num('tides-ratio', M.spring_neap.sun_to_moon)),
        // the named bodies' constants the answers used, with their source (the set: M.named_bodies)
        el('p', {class: 'muted', id: 'tides-constants'}, `Constants (${M.named_bodies}): ${M.body.source}; ${S.body.source}.`),
        tideNotes.box);
      // notes §1.4 The Tides: the Moon's pull less its pull at the Earth's centre, to first order in r/d:
      // a = (GM r/d³)(2 cos θ radially, −sin θ across), 2GMr/d³ straight below the Moon; the API's exact pull beside it
      const below = moon[1].acceleration;
      tideNotes.update({section: '1.4', heading: 'The Tides',
        formula: ['a = (G M r / d³) (2 cos θ ê', el('sub', {}, 'r'), ' − sin θ ê', el('sub', {}, 'θ'), '),  so 2 G M r / d³ below the Moon;  ',
          'g h = (3/2) G M r² / d³ for the water'],
        what: 'the first-order formula', formulaValue: below.first_order.radial, apiValue: below.exact.radial,
        diff: -below.difference.radial, unit: 'm/s²', source: 'api',
        how: 'The tidal pull straight below the Moon: the first order in r/d against the exact difference of the Moon\'s pulls ' +
          'at the surface and at the centre.',
        note: `The next term of the series is about (3/2) r/d = ${fmt(150 * M.r_over_d, 3)} % of the first. The range ` +
          `(3/2) GM r⁴/(GM_E d³) = ${fmt(M.spring_neap.moon_range, 3)} m for the Moon and ${fmt(M.spring_neap.sun_range, 3)} m for the Sun ` +
          '(the notes: 0.54 and 0.25 m).'});
      // a month: the Sun's angle from the Moon goes round once in 29.53 days (the same answers,
      // the Sun's every 15°, drawn at each angle); spring at new and full Moon, neap at the quarters
      const days = Array.from({length: 49}, (_, k) => k * MONTH / 48);
      month.set(days, (i, f, t) => {
        const al = 360 * t / MONTH, a2 = ((al % 360) + 360) % 360;
        drawField(plot, note, {moon: s !== 'sun' ? moon.slice(1) : null, sun: s !== 'moon' ? sunA.slice(1) : null, alpha: a2, point: st.point, wrap});
        const ph = Math.min(a2, 360 - a2);
        phase.textContent = `Day ${fmt(t, 3)}: the Sun ${fmt(Math.round(a2 * 10) / 10, 4)}° from the Moon — ` +
          (ph < 20 || ph > 160 ? `spring tide (${a2 < 90 || a2 > 270 ? 'new' : 'full'} Moon)` : ph > 70 && ph < 110 ? 'neap tide (quarter Moon)' : 'between spring and neap') + '.';
      });
      month.seek(alpha / 360 * MONTH);
      plotTools(plot, {name: 'tides', csv: () => 'angle_from_moon_deg,moon_radial,moon_tangential,moon_height,sun_radial,sun_tangential,sun_height\n' +
        moon.slice(1).map((x, k) => [k * STEP, x.acceleration.exact.radial, x.acceleration.exact.tangential, x.equilibrium_tide.height,
          sunA[k + 1].acceleration.exact.radial, sunA[k + 1].acceleration.exact.tangential, sunA[k + 1].equilibrium_tide.height].join(',')).join('\n') + '\n'});
    });
    L.results.before(L.figure); // the picture first, the numbers under it (on a phone, right below the form)
    run();
  },
};

// Arrows at every 15° round the Earth (the sum of the bodies shown), the
// water's outline (heights exaggerated, by how much said), and the directions
// to the Moon and the Sun. list[k] is the answer at k·15° from that body.
function drawField(root, note, {moon, sun, alpha, point, wrap}) {
  const [W] = plotSize(root, 520, 520), H = W;
  put(root); root.setAttribute('viewBox', `0 0 ${W} ${H}`);
  const cx = W / 2, cy = H / 2, R0 = W * 0.27;
  const at = (list, beta, phi) => { // the acceleration (x, y) and height at picture angle phi from a body at angle beta
    // between two of the API's angles (every 15°), linearly (the Sun during the month's animation)
    const d = wrap(phi - beta), u = Math.abs(d) / STEP, k = Math.min(Math.floor(u), list.length - 2), f = u - k;
    const mix = (g) => g(list[k]) + (g(list[k + 1]) - g(list[k])) * f;
    const ar = mix(x => x.acceleration.exact.radial), t = mix(x => x.acceleration.exact.tangential) * Math.sign(d || 1);
    const c = Math.cos(phi * Math.PI / 180), s = Math.sin(phi * Math.PI / 180);
    return [ar * c - t * s, ar * s + t * c, mix(x => x.equilibrium_tide.height)];
  };
  const field = [];
  for (let i = 0; i < N; i++) {
    const phi = i * STEP, v = [0, 0, 0];
    for (const [list, beta] of [[moon, 0], [sun, alpha]]) if (list) { const a = at(list, beta, phi); v[0] += a[0]; v[1] += a[1]; v[2] += a[2]; }
    field.push([phi, ...v]);
  }
  const amax = Math.max(...field.map(f => Math.hypot(f[1], f[2]))) || 1, hmax = Math.max(...field.map(f => Math.abs(f[3]))) || 1;
  const sa = R0 * 0.42 / amax, sh = R0 * 0.22 / hmax;
  // the water: radius R0 + sh h(phi), a smooth closed curve through the 24 points
  const pts = field.map(f => [cx + (R0 + sh * f[3]) * Math.cos(f[0] * Math.PI / 180), cy - (R0 + sh * f[3]) * Math.sin(f[0] * Math.PI / 180)]);
  // a closed Catmull-Rom curve through the points (drawn as cubic Béziers)
  const P = (k) => pts[(k + N) % N];
  let d = `M${P(0)[0].toFixed(1)},${P(0)[1].toFixed(1)}`;
  for (let k = 0; k < N; k++) {
    const [p0, p1, p2, p3] = [P(k - 1), P(k), P(k + 1), P(k + 2)];
    const c1 = [p1[0] + (p2[0] - p0[0]) / 6, p1[1] + (p2[1] - p0[1]) / 6], c2 = [p2[0] - (p3[0] - p1[0]) / 6, p2[1] - (p3[1] - p1[1]) / 6];
    d += ` C${c1.map(v => v.toFixed(1))} ${c2.map(v => v.toFixed(1))} ${p2.map(v => v.toFixed(1))}`;
  }
  add(root, svg('path', {d: d + 'Z', fill: '#d0ebff', stroke: '#1c7ed6', 'stroke-width': 2, 'data-role': 'water'}),
    svg('circle', {cx, cy, r: R0, fill: '#d8f5a2', stroke: '#5c940d', 'stroke-width': 1.5}));
  add(root, svg('defs', {}), svg('text', {x: cx, y: cy + 5, 'text-anchor': 'middle', 'font-size': 15}, 'Earth'));
  const defs = root.querySelector('defs');
  add(defs, (() => { const m = svg('marker', {id: 'tide-head', viewBox: '0 0 10 10', refX: 9, refY: 5, markerWidth: 6, markerHeight: 6, orient: 'auto-start-reverse'});
    add(m, svg('path', {d: 'M0,0 L10,5 L0,10 z', fill: '#c92a2a'})); return m; })());
  for (const f of field) {
    const c = Math.cos(f[0] * Math.PI / 180), s = Math.sin(f[0] * Math.PI / 180);
    const x0 = cx + R0 * 0.97 * c, y0 = cy - R0 * 0.97 * s;
    add(root, svg('line', {x1: x0, y1: y0, x2: x0 + sa * f[1], y2: y0 - sa * f[2], stroke: '#c92a2a', 'stroke-width': 2.5,
      'marker-end': 'url(#tide-head)', 'data-role': 'tide-arrow'}));
  }
  // the bodies' directions
  const dir = (beta, name, color, below) => {
    const c = Math.cos(beta * Math.PI / 180), s = Math.sin(beta * Math.PI / 180), r = W * (below ? 0.42 : 0.46);
    add(root, svg('line', {x1: cx + R0 * 1.55 * c, y1: cy - R0 * 1.55 * s, x2: cx + r * c, y2: cy - r * s, stroke: color, 'stroke-width': 2, 'stroke-dasharray': '4 4'}),
      svg('circle', {cx: cx + r * c, cy: cy - r * s, r: 9, fill: color}),
      svg('text', {x: cx + r * c, y: cy - r * s + (below ? 28 : s > 0.5 ? 26 : -14), 'text-anchor': c > 0.5 ? 'end' : c < -0.5 ? 'start' : 'middle', 'font-size': 15, 'font-weight': 700, fill: textShade(color)}, name));
  };
  if (moon) dir(0, 'Moon', '#495057');
  if (sun) dir(alpha, 'Sun', '#e67700', moon && alpha === 0);
  // the marked point
  const pc = Math.cos(point * Math.PI / 180), ps = Math.sin(point * Math.PI / 180);
  add(root, svg('circle', {cx: cx + R0 * pc, cy: cy - R0 * ps, r: 5, fill: '#1864ab', stroke: '#fff', 'stroke-width': 1.5}));
  // the arrow scale: a round acceleration
  const e = Math.floor(Math.log10(amax)), unit = 10 ** e;
  add(root, svg('line', {x1: 12, y1: H - 14, x2: 12 + sa * unit, y2: H - 14, stroke: '#c92a2a', 'stroke-width': 2.5, 'marker-end': 'url(#tide-head)'}),
    svg('text', {x: 12, y: H - 22, 'font-size': 13}, `${pow10(e)} m/s²`));
  const km = R0 / 6371; // pixels per km at the Earth's true scale
  const hm = hmax * sh / (km / 1000 * hmax); // exaggeration of the heights
  const exag = Number((hm / 10 ** Math.floor(Math.log10(hm))).toPrecision(2)) + '·' + pow10(Math.floor(Math.log10(hm)));
  note.textContent = `Red arrows: the tidal acceleration (${moon && sun ? 'Moon and Sun added' : moon ? 'Moon' : 'Sun'}), largest ${fmt(amax, 3)} m/s²; ` +
    `blue: the water's equilibrium surface, its heights drawn ${exag} times larger than the Earth (highest ${fmt(Math.max(...field.map(f => f[3])), 3)} m, ` +
    `lowest ${fmt(Math.min(...field.map(f => f[3])), 3)} m). The blue dot is the marked point.`;
  root.dataset.maxHeight = String(Math.max(...field.map(f => f[3])));
  root.dataset.minHeight = String(Math.min(...field.map(f => f[3])));
}
