// Earth lab: the falling object and the cannonball on the rotating Earth
// (POST /v1/scenes/falling-object, /v1/scenes/cannonball): with Coriolis beside
// without (where it would land if the Earth did not turn), the deflection
// magnified and labelled; and the Foucault pendulum (POST /v1/scenes/foucault):
// its trace from above, and its swing plane standing on the turning Earth in
// 3-D over one sidereal day (drawn to scale in angle: nothing exaggerated).
import {el, svg, put, add, field, val, fmt, num, examplePicker, labSection, runner, drawPlot, plotSize, plotTools, api, curlBox, linePlot, notesBox} from '../lib.js';
import {player} from '../anim.js';
import {THREE, view3d, label} from '../view3d.js';
import {handle, rerun} from '../handles.js';
import {arrow, energyBars} from '../draw.js';

const BUILTIN = [
  {title: 'Falling object: 100 m at 32° N (notes: x_east = (1/3) ω cos λ √(8h³/g))', operation: '/v1/scenes/falling-object',
   request: {height: 100, latitude_deg: 32}},
  {title: 'Cannonball: 500 m/s, 30° elevation, due east, 45° N', operation: '/v1/scenes/cannonball',
   request: {speed: 500, elevation_deg: 30, azimuth_deg: 0, latitude_deg: 45}},
  {title: 'Foucault: the Panthéon, 67 m at 48.846° N', operation: '/v1/scenes/foucault',
   request: {latitude_deg: 48.846, length: 67, release: {amplitude_deg: 3}, swings: 100}},
];

// One scene: heading, intro, its form (fields + a button), results and a picture.
function section(main, title, intro, fields, button, id) {
  const S = labSection(main, {title, intro, id});
  add(S.form, fields.map(f => f.wrap), el('div', {class: 'buttons'}, el('button', {type: 'submit', id: id + '-submit'}, button)));
  S.plot = svg('svg', {class: 'plot', id: id + '-plot', role: 'img', 'aria-label': title + ' picture'});
  add(S.figure, S.plot);
  return S;
}

// A plan view (east right, north up): the landing point with and without the
// Earth's rotation, the offset magnified by k and labelled with its true size.
// The offset is drawn 0.39 W long (mag = that / its true length in m).
function planView(root, east, north, label) {
  const [W, H] = plotSize(root, 640, 360); put(root); root.setAttribute('viewBox', `0 0 ${W} ${H}`);
  const cx = W / 2, cy = H / 2, mag = 0.39 * W / Math.max(Math.hypot(east, north), 1e-12);
  add(root, svg('line', {x1: 20, y1: cy, x2: W - 20, y2: cy, stroke: '#bbb'}), svg('line', {x1: cx, y1: 20, x2: cx, y2: H - 20, stroke: '#bbb'}),
    svg('text', {x: W - 14, y: cy + 24, 'font-size': 16, 'text-anchor': 'end'}, 'east'), svg('text', {x: cx + 6, y: 34, 'font-size': 16}, 'north'));
  const px = cx + east * mag, py = cy - north * mag;
  add(root, svg('circle', {cx, cy, r: 9, fill: 'none', stroke: '#2b8a3e', 'stroke-width': 3}),
    svg('text', {x: cx - 8, y: cy + 30, 'font-size': 15, fill: '#1f6f30', 'text-anchor': 'end'}, 'without Coriolis'),
    svg('line', {x1: cx, y1: cy, x2: px, y2: py, stroke: '#c92a2a', 'stroke-width': 3, 'stroke-dasharray': '8 4'}),
    svg('circle', {cx: px, cy: py, r: 9, fill: '#c92a2a'}),
    svg('text', {x: px + (east >= 0 ? -10 : 10), y: py - 16, 'font-size': 16, fill: '#c92a2a', 'font-weight': 700,
      'text-anchor': east >= 0 ? 'end' : 'start'}, label),
    svg('text', {x: 12, y: H - 12, 'font-size': 14, fill: '#444'}, `offset magnified: 1 px = ${fmt(1 / mag, 3)} m`));
}

export default {
  id: 'earth', title: 'Earth',
  mount(main) {
    put(main);
    add(main, el('h2', {}, 'Earth: the rotating frame'), examplePicker(['/v1/scenes/falling-object', '/v1/scenes/cannonball', '/v1/scenes/foucault'], BUILTIN, (ex) => {
      const r = ex.request;
      if (ex.operation === '/v1/scenes/falling-object') { fh.input.value = r.height; fl.input.value = r.latitude_deg;
        fm.input.value = r.model ?? 'auto'; fall(); fallS.form.scrollIntoView(); }
      if (ex.operation === '/v1/scenes/cannonball') { cs.input.value = r.speed; ce.input.value = r.elevation_deg;
        ca.input.value = r.azimuth_deg ?? 0; cl.input.value = r.latitude_deg; cm.input.value = r.model ?? 'auto'; cannon(); canS.form.scrollIntoView(); }
      if (ex.operation === '/v1/scenes/foucault') { pl.input.value = r.latitude_deg; pL.input.value = r.length ?? 67;
        pa.input.value = (r.release && r.release.amplitude_deg) ?? 3; ps.input.value = r.swings ?? 100; pend(); fouS.form.scrollIntoView(); }
    }));
    // falling object
    const fh = field({label: 'height h', pointer: '/height', value: 100, unit: 'm', id: 'fall-height'});
    const fl = field({label: 'latitude λ', pointer: '/latitude_deg', value: 32, unit: '°', id: 'fall-lat'});
    // the equations the numerical run solves (the scenes' model): as the textbooks do (Coriolis only) or more
    const models = [['auto', 'auto: the terms that matter'], ['coriolis', 'Coriolis only (textbooks)'],
      ['coriolis_centrifugal', 'Coriolis and centrifugal']];
    const fm = field({label: 'model', pointer: '/model', value: 'auto', options: models, id: 'fall-model'});
    const fallS = section(main, 'Falling object', 'Dropped from rest, it lands east of the point below (and a little south). ' +
      'Without the Earth\'s rotation it would land exactly below.', [fh, fl, fm], 'Drop', 'fall');
    const fallNotes = notesBox('fall-notes');
    const fall = runner(fallS, '/v1/scenes/falling-object', () => ({height: val(fh.input), latitude_deg: val(fl.input),
      model: val(fm.input)}), (a) => {
      put(fallS.results, el('dl', {class: 'nums'},
        el('dt', {}, 'model solved'), el('dd', {id: 'fall-model-used', 'data-value': a.physics_model.name}, a.physics_model.equation),
        el('dt', {}, 'fall time'), num('fall-t', a.numerical.t, 's'),
        el('dt', {}, 'east (numerical)'), num('fall-east', a.numerical.east, 'm'),
        el('dt', {}, 'east (first order)'), num('fall-east-1', a.first_order.east, 'm'),
        el('dt', {}, 'south (numerical)'), num('fall-south', a.numerical.south, 'm'),
        el('dt', {}, 'numerical − first order'), num('fall-diff', a.difference.east, 'm')), fallNotes.box);
      // notes §1.4 (the example follows "1.4 The Tides" and precedes "1.5 Homework"): v_east = ω g t² cos λ
      // integrated once more, t = √(2h/g). The API carries the first-order value and its own difference.
      fallNotes.update({section: '1.4', heading: 'Example: Deflection of a Falling Object',
        formula: ['x', el('sub', {}, 'east'), ' = ⅓ ω g t³ cos λ = ⅓ ω cos λ √(8h³/g),  t = √(2h/g)'],
        what: 'the first-order formula', formulaValue: a.first_order.east, apiValue: a.numerical.east, diff: -a.difference.east,
        unit: 'm', source: 'api', how: 'The eastward drift at the ground: the notes keep only the Coriolis term, first order in ω; ' +
          'the API integrates ' + a.physics_model.equation + ' to the landing.',
        note: 'The notes: "for a height of 100 meters, at 32 degrees latitude, the displacement is about 1.9 cm."'});
      drawPlot(fallS.plot, () => planView(fallS.plot, a.numerical.east, a.numerical.north, `${fmt(a.numerical.east * 100, 4)} cm east`));
      fallPath(a);
    });
    // the fall itself, animated: the same drop as a trajectory in the Earth's frame (POST /v1/trajectory,
    // gravity and Coriolis, 121 samples up to the scene's fall time), height against the eastward drift
    const pathPlot = svg('svg', {class: 'plot', id: 'fall-path', role: 'img', 'aria-label': 'the fall: height against eastward drift'});
    const pathNote = el('p', {class: 'muted', id: 'fall-path-note'});
    const pathCurl = curlBox();
    put(pathCurl.box.querySelector('h3'), 'The animation\'s request');
    const fallPlay = player({label: 'The falling object'});
    add(fallS.figure, el('h3', {}, 'The fall'), pathPlot, fallPlay.root, pathNote, pathCurl.box);
    let pathCtl = null;
    const fallPath = async (a) => {
      const h = a.parameters.height, lat = a.parameters.latitude_deg, T = a.numerical.t;
      const body = {particle: {mass: 1, position: [0, 0, h], velocity: [0, 0, 0]}, frame: {type: 'earth', latitude_deg: lat},
        forces: [{type: 'uniform_gravity', g: [0, 0, -a.parameters.g]}], fictitious: ['coriolis'], t_end: T, samples: 121,
        stop: {coordinate: 'z', crosses: 0, direction: 'decreasing'}};
      pathCurl.update('/v1/trajectory', body);
      if (pathCtl) pathCtl.abort();
      const mine = pathCtl = new AbortController();
      const r = await api('/v1/trajectory', body, {signal: mine.signal});
      if (mine !== pathCtl || r.aborted) return;
      if (!r.ok || !r.body || !Array.isArray(r.body.t)) { pathNote.textContent = 'The animation\'s trajectory could not be computed.'; return; }
      let t = r.body.t.slice(), pos = r.body.position.slice();
      const st = r.body.stopped; // nothing after the landing
      if (st && typeof st.t === 'number') { const k = t.findIndex(x => x > st.t); if (k > 0) { t = t.slice(0, k); pos = pos.slice(0, k); }
        if (st.t > t[t.length - 1]) { t.push(st.t); pos.push(st.position); } }
      const pts = pos.map(p => [p[0] * 100, Math.abs(p[2]) < 1e-9 ? 0 : p[2]]); // the landing's −1.4e-14 m is the ground
      const dot = svg('circle', {r: 7, fill: '#c92a2a', stroke: '#fff', 'stroke-width': 2, id: 'fall-dot'});
      let XY = null, cur = pts[0];
      linePlot(pathPlot, [{points: pts, label: 'with Coriolis', t}, {points: [[0, h], [0, 0]], label: 'without', color: '#2b8a3e', dash: '6 4'}],
        {xlabel: 'east [cm]', ylabel: 'height [m]', name: 'falling-object-path', legend: 'below', marks: [({X, Y}) => {
          XY = [X, Y]; dot.setAttribute('cx', X(cur[0])); dot.setAttribute('cy', Y(cur[1]));
          // px per metre across (X counts cm) over px per metre up: how much the drift is magnified
          const k = Math.abs(X(1) - X(0)) * 100 / Math.abs(Y(1) - Y(0));
          pathNote.textContent = `East in cm, height in m: the drift (${fmt(pos[pos.length - 1][0] * 100, 4)} cm at the ground) ` +
            `is drawn ${fmt(Number(k.toPrecision(2)))} times larger than the height's scale.`;
          return dot; }]});
      fallPlay.set(t, (i, f) => {
        const j = Math.min(i + 1, pts.length - 1);
        cur = [pts[i][0] + (pts[j][0] - pts[i][0]) * f, pts[i][1] + (pts[j][1] - pts[i][1]) * f];
        if (XY) { dot.setAttribute('cx', XY[0](cur[0])); dot.setAttribute('cy', XY[1](cur[1])); }
      }, {grow: [pathPlot]});
    };
    // cannonball
    const cs = field({label: 'speed', pointer: '/speed', value: 500, unit: 'm/s', id: 'can-speed'});
    const ce = field({label: 'elevation', pointer: '/elevation_deg', value: 30, unit: '°', id: 'can-elev'});
    const ca = field({label: 'azimuth', pointer: '/azimuth_deg', value: 0, unit: '° from east', id: 'can-az'});
    const cl = field({label: 'latitude λ', pointer: '/latitude_deg', value: 45, unit: '°', id: 'can-lat'});
    const cm = field({label: 'model', pointer: '/model', value: 'auto', options: models, id: 'can-model'});
    const canS = section(main, 'Cannonball', 'Fired over the rotating Earth it is deflected to the right in the northern ' +
      'hemisphere (to the left in the southern). The picture shows the landing point relative to where it would land on a ' +
      'non-rotating Earth.', [cs, ce, ca, cl, cm], 'Fire', 'can');
    const canNotes = notesBox('can-notes');
    const cannon = runner(canS, '/v1/scenes/cannonball', () => ({speed: val(cs.input), elevation_deg: val(ce.input),
      azimuth_deg: val(ca.input), latitude_deg: val(cl.input), model: val(cm.input)}), (a) => {
      put(canS.results, el('dl', {class: 'nums'},
        el('dt', {}, 'model solved'), el('dd', {id: 'can-model-used', 'data-value': a.physics_model.name}, a.physics_model.equation),
        el('dt', {}, 'time of flight'), num('can-t', a.numerical.t, 's'),
        el('dt', {}, 'range'), num('can-range', a.numerical.range, 'm'),
        el('dt', {}, 'deflection to the right'), num('can-right', a.numerical.right, 'm'),
        el('dt', {}, 'right (first order)'), num('can-right-1', a.first_order.right, 'm')), canNotes.box);
      // notes §1.4, Example: Deflection of Cannon Balls: a = −2 ω × v; to first order in ω the
      // displacement is r₁ = −ω × (v₀ t² + g t³/3) (integrated twice), read at the landing
      canNotes.update({section: '1.4', heading: 'Example: Deflection of Cannon Balls',
        formula: ['a = −2 ω × v  ⇒  r', el('sub', {}, '1'), ' = −ω × (v', el('sub', {}, '0'), ' t² + g t³/3)  (first order in ω, at the landing)'],
        what: 'the first-order formula', formulaValue: a.first_order.right, apiValue: a.numerical.right, diff: -a.difference.right,
        unit: 'm', source: 'api', how: 'The deflection to the right of the aim: to the right in the northern hemisphere, ' +
          'to the left in the southern (the notes\' first two terms of a).',
        note: 'Most of the difference is the second order in ω (Coriolis acting on the first-order drift, and the centrifugal term): ' +
          'it grows with the time of flight.'});
      // relative to the non-rotating landing point (range v² sin 2α / g along the azimuth)
      const g = a.parameters.g, v = a.parameters.speed, al = a.parameters.elevation_deg * Math.PI / 180;
      const az = a.parameters.azimuth_deg * Math.PI / 180, R0 = v * v * Math.sin(2 * al) / g;
      const de = a.numerical.east - R0 * Math.cos(az), dn = a.numerical.north - R0 * Math.sin(az);
      drawPlot(canS.plot, () => planView(canS.plot, de, dn, `${fmt(a.numerical.right, 4)} m to the right`));
      flight(a);
    });
    // the flight itself, animated: the same shot as a trajectory in the Earth's frame (POST /v1/trajectory,
    // gravity and the fictitious terms chosen as the scene chooses them ("auto": Coriolis and, at this
    // accuracy, centrifugal), 121 samples up to the scene's time of flight), seen from the side to scale
    // (downrange against height, equal aspect), the drift to the right of the aim written as it grows
    const flightPlot = svg('svg', {class: 'plot', id: 'can-path', role: 'img', 'aria-label': 'the flight: height against distance downrange'});
    const flightNote = el('p', {class: 'muted', id: 'can-path-note', 'aria-live': 'off'});
    const flightCurl = curlBox();
    put(flightCurl.box.querySelector('h3'), 'The animation\'s request');
    const canPlay = player({label: 'The cannonball', reverse: 'Backwards: without air the flight run backwards is a flight too, on an Earth turning the other way (the Coriolis force changes sign with the velocity).'});
    const canEnergy = svg('svg', {class: 'plot dial energy', id: 'can-energy', role: 'img', 'aria-label': 'energy bars'});
    const canForces = el('p', {class: 'muted', id: 'can-forces'});
    add(canS.figure, el('h3', {}, 'The flight, from the side'), flightPlot, canPlay.root, flightNote, canForces,
      el('h3', {}, 'Energy (per kg)'), canEnergy, flightCurl.box);
    let flightCtl = null;
    const flight = async (a) => {
      const P = a.parameters, el0 = P.elevation_deg * Math.PI / 180, az = P.azimuth_deg * Math.PI / 180; // velocity: (east, north, up)
      const aim = [Math.cos(az), Math.sin(az)], right = [Math.sin(az), -Math.cos(az)]; // (east, north): the aim and its right
      const v = Array.isArray(P.velocity) ? P.velocity : [P.speed * Math.cos(el0) * aim[0], P.speed * Math.cos(el0) * aim[1], P.speed * Math.sin(el0)];
      const body = {particle: {mass: 1, position: [0, 0, 0], velocity: v}, frame: {type: 'earth', latitude_deg: P.latitude_deg},
        forces: [{type: 'uniform_gravity', g: [0, 0, -P.g]}], fictitious: 'auto', t_end: a.numerical.t * 1.02, samples: 121,
        stop: {coordinate: 'z', crosses: 0, direction: 'decreasing'}};
      flightCurl.update('/v1/trajectory', body);
      if (flightCtl) flightCtl.abort();
      const mine = flightCtl = new AbortController();
      const r = await api('/v1/trajectory', body, {signal: mine.signal});
      if (mine !== flightCtl || r.aborted) return;
      if (!r.ok || !r.body || !Array.isArray(r.body.t)) { flightNote.textContent = 'The animation\'s trajectory could not be computed.'; return; }
      let t = r.body.t.slice(), pos = r.body.position.slice(), vel = (r.body.velocity || []).slice();
      const st = r.body.stopped;
      if (st && typeof st.t === 'number') { const k = t.findIndex(x => x > st.t); if (k > 0) { t = t.slice(0, k); pos = pos.slice(0, k); vel = vel.slice(0, k); }
        if (st.t > t[t.length - 1]) { t.push(st.t); pos.push(st.position); vel.push(st.velocity || vel[vel.length - 1]); } }
      const down = (p) => p[0] * aim[0] + p[1] * aim[1], side = (p) => p[0] * right[0] + p[1] * right[1];
      // on the moving ball: its velocity (1 km of arrow per 100 m/s) and its weight mg (m = 1 kg); the Coriolis
      // force −2m ω×v (ω = ω(0, cos λ, sin λ) east-north-up) is mostly sideways, out of this picture: said in words;
      // energy bars: ½mv² and mgz, their sum level (the Coriolis force does no work: it is always across v)
      const Om = 7.292115e-5, lat = P.latitude_deg * Math.PI / 180, wv = [0, Om * Math.cos(lat), Om * Math.sin(lat)];
      const coriolis = (v) => [-2 * (wv[1] * v[2] - wv[2] * v[1]), -2 * (wv[2] * v[0] - wv[0] * v[2]), -2 * (wv[0] * v[1] - wv[1] * v[0])];
      const vecs = svg('g', {id: 'can-vectors'});
      const pts = pos.map(p => [down(p) / 1000, p[2] / 1000]);
      const ball = svg('circle', {r: 7, fill: '#c92a2a', stroke: '#fff', 'stroke-width': 2, id: 'can-ball'});
      let XY = null, cur = pts[0];
      linePlot(flightPlot, [{points: pts, label: 'with Coriolis', t}], {xlabel: 'downrange [km]', ylabel: 'height [km]', equal: true,
        name: 'cannonball-path', marks: [({X, Y}) => { XY = [X, Y]; ball.setAttribute('cx', X(cur[0])); ball.setAttribute('cy', Y(cur[1]));
          const g = svg('g', {}); add(g, vecs, ball); return g; }]});
      canPlay.set(t, (i, f, tt) => {
        const j = Math.min(i + 1, pos.length - 1), p = pos[i].map((x, k) => x + (pos[j][k] - x) * f);
        const v = vel.length === pos.length ? vel[i].map((x, k) => x + (vel[j][k] - x) * f) : null;
        cur = [down(p) / 1000, p[2] / 1000];
        if (XY) { ball.setAttribute('cx', XY[0](cur[0])); ball.setAttribute('cy', XY[1](cur[1])); }
        if (XY && v) {
          const bx = XY[0](cur[0]), by = XY[1](cur[1]), kx = XY[0](1) - XY[0](0); // px per km
          put(vecs, arrow(bx, by, bx + kx * down(v) / 100, by - kx * v[2] / 100, '#1864ab', 'v'),
            arrow(bx, by, bx, by + 46, '#5c3b00', 'mg'));
          const fc = coriolis(v), E = [0.5 * (v[0] ** 2 + v[1] ** 2 + v[2] ** 2), P.g * p[2]];
          energyBars(canEnergy, [['kinetic ½mv²', E[0], '#1864ab'], ['potential mgz', E[1], '#5c3b00'], ['total', E[0] + E[1], '#111']],
            0.5 * (vel[0][0] ** 2 + vel[0][1] ** 2 + vel[0][2] ** 2), 'energy of the ball (1 kg)');
          canForces.textContent = `On the ball (m = 1 kg): weight mg = ${fmt(P.g, 4)} N down; Coriolis −2m ω×v = ${fmt(Math.hypot(...fc), 3)} N, ` +
            `${fmt(side(fc), 3)} N to the right of the aim and ${fmt(fc[2], 3)} N up; speed ${fmt(Math.hypot(...v), 4)} m/s (blue arrow: 1 km per 100 m/s).`;
        }
        flightNote.dataset.right = String(side(p));
        flightNote.dataset.down = String(down(p));
        const up = Math.abs(p[2]) < 1e-6 ? 0 : p[2]; // the landing sample's round-off, not "-4.5e-16 km up"
        flightNote.textContent = `t = ${fmt(tt, 4)} s: ${fmt(down(p) / 1000, 4)} km downrange, ${fmt(up / 1000, 4)} km up, ` +
          `${fmt(side(p), 3)} m to the right of the aim (too small to see at this scale: the plan view above magnifies it).`;
      }, {grow: [flightPlot]}); // the flight's path grows behind the ball as it plays
    };
    // Foucault
    const pl = field({label: 'latitude λ', pointer: '/latitude_deg', value: 48.846, unit: '°', id: 'fou-lat', min: -90, max: 90});
    const pL = field({label: 'length', pointer: '/length', value: 67, unit: 'm', id: 'fou-len'});
    const pa = field({label: 'amplitude', pointer: '/release/amplitude_deg', value: 3, unit: '°', id: 'fou-amp'});
    const ps = field({label: 'swings', pointer: '/swings', value: 100, id: 'fou-swings', min: 1, step: 1, budget: 'swings'});
    const fouS = section(main, 'Foucault pendulum', 'The swing plane turns clockwise (northern hemisphere) at ω sin λ. ' +
      'The trace (and the bob when played) is drawn from the measured rate and swing period, with the turn exaggerated so that it shows; the exaggeration is written under it.', [pl, pL, pa, ps], 'Swing', 'fou');
    const fouNotes = notesBox('fou-notes');
    const pend = runner(fouS, '/v1/scenes/foucault', () => ({latitude_deg: val(pl.input), length: val(pL.input),
      release: {amplitude_deg: val(pa.input)}, swings: val(ps.input)}), (a) => {
      const p = a.precession;
      // at the equator ω sin λ = 0: the swing plane does not turn (no full turn, nothing to exaggerate)
      const still = p.first_order_rate === 0;
      put(fouS.results, el('dl', {class: 'nums'},
        el('dt', {}, 'measured rate'), num('fou-rate', p.measured_rate_deg_per_hour, '°/h'),
        el('dt', {}, 'ω sin λ'), num('fou-first', p.first_order_rate * 180 / Math.PI * 3600, '°/h'),
        el('dt', {}, 'full turn'), still || p.full_precession_hours === null
          ? el('dd', {id: 'fou-hours'}, 'none: no precession at the equator (ω sin λ = 0)')
          : num('fou-hours', p.full_precession_hours, 'h'),
        el('dt', {}, 'swing period'), num('fou-period', a.swing.period, 's')), fouNotes.box);
      // notes §1.4, Example: The Foucault Pendulum: q = x + iy = q₀ e^(−iω_z t) cos(√(g/l) t), ω_z = ω sin λ
      const h = 180 / Math.PI * 3600; // rad/s -> °/h
      fouNotes.update({section: '1.4', heading: 'Example: The Foucault Pendulum',
        formula: ['x + iy = q', el('sub', {}, '0'), ' e', el('sup', {}, '−iω_z t'), ' cos(√(g/l) t),  ω', el('sub', {}, 'z'),
          ' = ω sin λ  (clockwise seen from above in the north)'],
        what: 'the notes\' rate', formulaValue: p.first_order_rate * h, apiValue: p.measured_rate * h,
        diff: typeof p.difference === 'number' ? -p.difference * h : undefined, unit: '°/h', source: 'api',
        how: 'The rate the swing plane turns: the notes keep first order in the swing\'s size over l; the API integrates the ' +
          'pendulum and fits the plane\'s turn over every swing.',
        note: still ? 'At the equator sin λ = 0: in the notes the plane does not turn at all.' : typeof p.airy_correction === 'number'
          ? `Most of the difference is the Airy precession of a slightly elliptical swing (${fmt(p.airy_correction * h, 2)} °/h by its formula), not the Earth.` : null});
      const flat = a.swing.semi_major_axis > 0 ? Math.min(1, Math.abs(a.swing.semi_minor_axis / a.swing.semi_major_axis)) : 0;
      let bob = null;
      drawPlot(fouS.plot, () => { bob = rosette(fouS.plot, p.measured_rate, a.swing.period, still, flat); });
      // 12 swings, 40 frames a swing: the bob on the (exaggerated) trace
      const T = a.swing.period, times = Array.from({length: 12 * 40 + 1}, (_, i) => i * T / 40);
      fouPlay.set(times, (i, f, t) => { if (bob) bob(t / T); });
      globe(a);
    });
    plotTools(fallS.plot, {name: 'falling-object'}); plotTools(canS.plot, {name: 'cannonball'});
    const fouPlay = player({label: 'The Foucault pendulum'});
    fouS.plot.after(fouPlay.root);
    plotTools(fouS.plot, {name: 'foucault'});
    // the swing plane over the Earth in 3-D, one sidereal day played
    const gbox = el('div', {class: 'view3d-box', id: 'fou-3d-box'});
    const gnote = el('p', {class: 'muted', id: 'fou-3d-note'});
    const dayPlay = player({label: 'The Earth and the swing plane', unit: 'h', seconds: 3600});
    const frameSel = el('select', {id: 'fou-frame', 'data-role': 'frame'},
      el('option', {value: 'stars', selected: true}, 'the stars (the Earth turns)'), el('option', {value: 'ground'}, 'the ground (the Earth still)'));
    add(fouS.figure, el('h3', {}, 'The swing plane over the Earth'),
      el('div', {class: 'exaggerate'}, el('label', {for: 'fou-frame'}, 'Seen from'), frameSel), gbox, dayPlay.root, gnote);
    const G = view3d(gbox, {label: 'The Foucault pendulum\'s swing plane on the turning Earth', id: 'fou-view', extent: 1.3});
    const globe = (a) => foucaultGlobe(G, gbox, gnote, dayPlay, a, () => frameSel.value === 'ground');
    frameSel.addEventListener('change', () => dayPlay.seek(Number(gbox.dataset.hours) || 0));
    // direct manipulation: the launch velocity as an arrow whose tip is dragged (speed and elevation), and
    // the pendulum's place on the Earth dragged round a meridian (the latitude); each asks again as it moves
    const aim = svg('svg', {class: 'plot dial', id: 'can-aim', role: 'group',
      'aria-label': 'The launch velocity: drag the arrow\'s tip, or focus it and use the arrow keys'});
    canS.form.querySelector('.buttons').before(el('div', {class: 'dial-box'}, el('p', {class: 'muted'}, 'Or drag the launch velocity:'), aim));
    const canAgain = rerun(() => cannon());
    const drawAim = () => aimDial(aim, val(cs.input), val(ce.input), (v, e, done) => {
      cs.input.value = v; ce.input.value = e; drawAim(); canAgain(done);
    });
    for (const c of [cs.input, ce.input]) c.addEventListener('input', drawAim);
    drawAim();
    const dial = svg('svg', {class: 'plot dial', id: 'fou-dial', role: 'group',
      'aria-label': 'The pendulum\'s latitude: drag it round the Earth, or focus it and use the arrow keys'});
    fouS.form.querySelector('.buttons').before(el('div', {class: 'dial-box'}, el('p', {class: 'muted'}, 'Or drag the pendulum round the Earth:'), dial));
    const fouAgain = rerun(() => pend(), 200);
    const drawDial = () => latitudeDial(dial, val(pl.input), (lat, done) => { pl.input.value = lat; drawDial(); fouAgain(done); });
    pl.input.addEventListener('input', drawDial);
    drawDial();
    fall(); cannon(); pend();
  },
};

// The launch velocity to scale (0 to 1000 m/s), its tip a handle: (v cos α, v sin α) in m/s; the arrow keys move
// the tip 10 m/s across or up (Shift: 100). onMove(speed in m/s, elevation in degrees, done).
function aimDial(root, v, e, onMove) {
  const W = 300, H = 170, k = (W - 50) / 1000;
  put(root); root.setAttribute('viewBox', `0 0 ${W} ${H}`);
  const X = (vx) => 24 + vx * k, Y = (vz) => H - 24 - vz * k;
  X.invert = (px) => (px - 24) / k; Y.invert = (py) => (H - 24 - py) / k;
  add(root, svg('line', {x1: 8, y1: Y(0), x2: W - 8, y2: Y(0), stroke: '#555', 'stroke-width': 2}));
  for (const s of [250, 500, 750, 1000]) add(root, svg('path', {d: `M ${X(s)} ${Y(0)} A ${s * k} ${s * k} 0 0 0 ${X(0)} ${Y(s)}`, fill: 'none', stroke: '#ddd'}),
    svg('text', {x: X(s), y: Y(0) + 16, 'font-size': 12, 'text-anchor': 'middle', fill: '#444'}, `${s}`));
  add(root, svg('text', {x: W - 8, y: 14, 'font-size': 12, 'text-anchor': 'end', fill: '#444'}, 'm/s'));
  const ok = Number.isFinite(v) && Number.isFinite(e), a = (ok ? e : 30) * Math.PI / 180, s0 = ok ? v : 500;
  const tip = [s0 * Math.cos(a), s0 * Math.sin(a)];
  const words = (vx, vz) => `${fmt(Math.hypot(vx, vz), 3)} m/s at ${fmt(Math.atan2(vz, vx) * 180 / Math.PI, 3)}° elevation`;
  add(root, svg('line', {x1: X(0), y1: Y(0), x2: X(tip[0]), y2: Y(tip[1]), stroke: '#c92a2a', 'stroke-width': 4}),
    svg('text', {x: 30, y: 18, 'font-size': 14, fill: '#c92a2a', 'font-weight': 700, 'data-role': 'aim-words'}, words(...tip)),
    handle(root, {id: 'can-aim-tip', X, Y, at: tip, color: '#c92a2a', step: [10, 10], label: 'launch velocity (the arrow\'s tip)', text: words,
      onMove: (vx, vz, done) => {
        const sp = Math.min(1000, Math.max(1, Math.round(Math.hypot(vx, vz)))), el0 = Math.min(90, Math.max(0, Math.round(Math.atan2(vz, vx) * 1800 / Math.PI) / 10));
        onMove(sp, el0, done);
      }}));
}

// A meridian of the Earth with the pendulum at latitude λ on it, a handle moved round the circle (the arrow
// keys: 1°, Shift 10°). onMove(latitude in degrees, done).
function latitudeDial(root, lat, onMove) {
  const W = 220, H = 200, R = 80, cx = 100, cy = 100;
  put(root); root.setAttribute('viewBox', `0 0 ${W} ${H}`);
  const X = (x) => cx + R * x, Y = (y) => cy - R * y;
  X.invert = (px) => (px - cx) / R; Y.invert = (py) => (cy - py) / R;
  const l = Number.isFinite(lat) ? Math.max(-90, Math.min(90, lat)) : 0, a = l * Math.PI / 180;
  add(root, svg('circle', {cx, cy, r: R, fill: '#e7f5ff', stroke: '#1864ab', 'stroke-width': 2}),
    svg('line', {x1: cx - R - 10, y1: cy, x2: cx + R + 10, y2: cy, stroke: '#1864ab', 'stroke-dasharray': '4 4'}),
    svg('line', {x1: cx, y1: cy - R - 14, x2: cx, y2: cy + R + 14, stroke: '#444', 'stroke-width': 2}),
    svg('text', {x: cx + 6, y: cy - R - 2, 'font-size': 12, fill: '#444'}, 'ω'),
    svg('line', {x1: cx, y1: cy, x2: X(Math.cos(a)), y2: Y(Math.sin(a)), stroke: '#c92a2a', 'stroke-width': 2}),
    svg('text', {x: 8, y: H - 8, 'font-size': 14, fill: '#c92a2a', 'font-weight': 700}, `λ = ${fmt(l, 4)}°`),
    handle(root, {id: 'fou-lat-handle', X, Y, at: [Math.cos(a), Math.sin(a)], color: '#c92a2a', label: 'the pendulum\'s latitude',
      text: (x, y) => `latitude ${fmt(Math.round(Math.atan2(y, Math.max(0, x)) * 180 / Math.PI * 10) / 10, 4)}°`,
      nudge: (sign, big, at) => { const d = (Math.atan2(at[1], Math.max(0, at[0])) * 180 / Math.PI) + sign * (big ? 10 : 1);
        const n = Math.max(-90, Math.min(90, Math.round(d))) * Math.PI / 180; return [Math.cos(n), Math.sin(n)]; },
      onMove: (x, y, done) => onMove(Math.max(-90, Math.min(90, Math.round(Math.atan2(y, Math.max(0, x)) * 180 / Math.PI * 10) / 10)), done)}));
}

// The swing traced from above over 12 swings, the plane turned at the measured
// rate, each swing an ellipse of the measured axis ratio `flat` (minor/major).
// The real turn per swing is tiny (~0.05°), so it is exaggerated to 60°
// over the 12 swings and the factor is labelled; at the equator (still) there
// is no turn and the trace is drawn to scale.
function rosette(root, rate, period, still, flat) {
  const [W, H] = plotSize(root, 640, 400); put(root); root.setAttribute('viewBox', `0 0 ${W} ${H}`);
  const n = 12, real = (rate || 0) * period * n; // rad over n swings, signed (negative: clockwise)
  const turn = still || !real ? real : Math.sign(real) * Math.PI / 3, R = Math.min(W * 0.42, H * 0.4), pts = [];
  for (let i = 0; i <= n * 80; i++) {
    const s = i / 80, ang = turn * s / n, x = Math.cos(Math.PI * s), y = flat * Math.sin(Math.PI * s);
    pts.push(`${(W / 2 + R * (x * Math.cos(ang) - y * Math.sin(ang))).toFixed(1)},${(H / 2 - R * (x * Math.sin(ang) + y * Math.cos(ang))).toFixed(1)}`);
  }
  const perSwing = Math.abs(real / n) * 180 / Math.PI;
  // played: the trace so far drawn bold over the whole (faint) one, the bob at its end
  const bob = svg('circle', {r: 8, fill: '#c92a2a', stroke: '#fff', 'stroke-width': 2, id: 'fou-bob'});
  const sofar = svg('polyline', {fill: 'none', stroke: '#1864ab', 'stroke-width': 2.5});
  const at = (s) => { const ang = turn * s / n, x = Math.cos(Math.PI * s), y = flat * Math.sin(Math.PI * s);
    bob.setAttribute('cx', (W / 2 + R * (x * Math.cos(ang) - y * Math.sin(ang))).toFixed(1));
    bob.setAttribute('cy', (H / 2 - R * (x * Math.sin(ang) + y * Math.cos(ang))).toFixed(1));
    sofar.setAttribute('points', pts.slice(0, Math.floor(s * 80) + 1).join(' ') + ' ' + bob.getAttribute('cx') + ',' + bob.getAttribute('cy')); };
  at(0);
  add(root, svg('text', {x: W / 2, y: 22, 'font-size': 15, 'text-anchor': 'middle', fill: '#444'}, 'N'),
    svg('text', {x: W - 16, y: H / 2 + 5, 'font-size': 15, 'text-anchor': 'middle', fill: '#444'}, 'E'),
    svg('polyline', {points: pts.join(' '), fill: 'none', stroke: '#a5c8ec', 'stroke-width': 1.5}), sofar,
    svg('text', {x: 12, y: H - 30, 'font-size': 14, fill: '#444'}, still ? 'no precession at the equator (ω sin λ = 0)'
      : `real turn per swing ${fmt(perSwing, 3)}°`),
    svg('text', {x: 12, y: H - 10, 'font-size': 14, fill: '#444'}, still || !real ? '12 swings, drawn to scale'
      : `12 swings, turn drawn ×${fmt(Math.abs(turn / real), 3)}`), bob);
  return at;
}

// The Earth (radius 1, axis z, seen from the stars) turning once in a sidereal
// day, and on it at latitude λ an enlarged floor with the pendulum's swing
// plane standing on it. The plane turns relative to the floor at the API's
// measured rate (rad/s; negative: clockwise seen from above), drawn to scale:
// in a day it turns 360° sin λ on the floor. Grey on the floor: where the plane
// stood at the start (in the floor's directions), so the turn shows. The box
// carries data-swing-deg (the plane's turn relative to the floor so far) and
// data-earth-deg (the Earth's turn as drawn) for tests. ground(): seen from the
// ground, the Earth held still (the rotating frame), only the plane turns.
const SIDEREAL_DAY = 86164.0905; // s
function foucaultGlobe(G, box, note, play, a, ground) {
  const lat = a.setup.latitude_deg * Math.PI / 180, rate = a.precession.measured_rate || 0;
  const W = Array.isArray(a.setup.omega) ? Math.hypot(...a.setup.omega) : 0, day = W > 0 ? 2 * Math.PI / W : SIDEREAL_DAY;
  G.scene.children.filter(o => o.userData.mine).forEach(o => G.scene.remove(o));
  const world = new THREE.Group(); world.userData.mine = true; G.scene.add(world);
  const earth = new THREE.Group(); world.add(earth);
  earth.add(new THREE.Mesh(new THREE.SphereGeometry(1, 48, 32), new THREE.MeshStandardMaterial({color: 0x4dabf7})));
  // meridians and parallels every 30°, so the turning shows
  const lineMat = new THREE.LineBasicMaterial({color: 0x1c5d99});
  for (let k = 0; k < 6; k++) {
    const pts = []; for (let i = 0; i <= 64; i++) { const u = Math.PI * i / 64 - Math.PI / 2, v = k * Math.PI / 6;
      pts.push(new THREE.Vector3(1.002 * Math.cos(u) * Math.cos(v), 1.002 * Math.cos(u) * Math.sin(v), 1.002 * Math.sin(u))); }
    earth.add(new THREE.Line(new THREE.BufferGeometry().setFromPoints(pts), lineMat));
    const back = new THREE.Line(new THREE.BufferGeometry().setFromPoints(pts.map(p => new THREE.Vector3(-p.x, -p.y, p.z))), lineMat);
    earth.add(back);
  }
  for (const u of [-60, -30, 0, 30, 60].map(d => d * Math.PI / 180)) {
    const pts = []; for (let i = 0; i <= 96; i++) { const v = 2 * Math.PI * i / 96;
      pts.push(new THREE.Vector3(1.002 * Math.cos(u) * Math.cos(v), 1.002 * Math.cos(u) * Math.sin(v), 1.002 * Math.sin(u))); }
    earth.add(new THREE.Line(new THREE.BufferGeometry().setFromPoints(pts), new THREE.LineBasicMaterial({color: u === 0 ? 0xc92a2a : 0x1c5d99})));
  }
  // the axis, through the poles
  world.add(new THREE.Line(new THREE.BufferGeometry().setFromPoints([new THREE.Vector3(0, 0, -1.35), new THREE.Vector3(0, 0, 1.35)]),
    new THREE.LineBasicMaterial({color: 0x333333})));
  const N = label('N', '#333'); N.position.set(0, 0, 1.45); N.scale.multiplyScalar(0.12); world.add(N);
  // the floor at latitude λ, longitude 0: east e, north n, up u (Earth-fixed)
  const u = new THREE.Vector3(Math.cos(lat), 0, Math.sin(lat)), e = new THREE.Vector3(0, 1, 0);
  const n = new THREE.Vector3(-Math.sin(lat), 0, Math.cos(lat));
  const site = new THREE.Group();
  site.matrixAutoUpdate = false;
  site.matrix.makeBasis(e, n, u).setPosition(u.clone().multiplyScalar(1.0));
  earth.add(site);
  const R = 0.42; // the floor, drawn large
  const floor = new THREE.Mesh(new THREE.CircleGeometry(R, 48), new THREE.MeshStandardMaterial({color: 0xffffff, side: THREE.DoubleSide}));
  floor.position.z = 0.01; site.add(floor);
  const rim = []; for (let i = 0; i <= 64; i++) rim.push(new THREE.Vector3(R * Math.cos(2 * Math.PI * i / 64), R * Math.sin(2 * Math.PI * i / 64), 0.015));
  site.add(new THREE.Line(new THREE.BufferGeometry().setFromPoints(rim), new THREE.LineBasicMaterial({color: 0x333333})));
  const arrow = (dir, col) => new THREE.ArrowHelper(dir, new THREE.Vector3(0, 0, 0.02), R * 1.15, col, 0.07, 0.04);
  site.add(arrow(new THREE.Vector3(0, 1, 0), 0x2b8a3e), arrow(new THREE.Vector3(1, 0, 0), 0x868e96));
  const nl = label('N', '#2b8a3e'); nl.position.set(0, R * 1.35, 0.03); nl.scale.multiplyScalar(0.08); site.add(nl);
  const el2 = label('E', '#555'); el2.position.set(R * 1.35, 0, 0.03); el2.scale.multiplyScalar(0.08); site.add(el2);
  // the swing plane: a vertical sheet through the floor's centre, at first north-south
  const plane = new THREE.Group(); site.add(plane);
  const sheet = new THREE.Mesh(new THREE.PlaneGeometry(2 * R, 0.45), new THREE.MeshStandardMaterial({color: 0xc92a2a,
    transparent: true, opacity: 0.55, side: THREE.DoubleSide}));
  sheet.rotation.x = Math.PI / 2; sheet.rotation.y = Math.PI / 2; sheet.position.z = 0.235; // in the n-u plane
  plane.add(sheet);
  plane.add(new THREE.Line(new THREE.BufferGeometry().setFromPoints([new THREE.Vector3(0, -R, 0.025), new THREE.Vector3(0, R, 0.025)]),
    new THREE.LineBasicMaterial({color: 0xc92a2a})));
  const start = new THREE.Line(new THREE.BufferGeometry().setFromPoints([new THREE.Vector3(0, -R, 0.022), new THREE.Vector3(0, R, 0.022)]),
    new THREE.LineBasicMaterial({color: 0x555555}));
  site.add(start);
  G.frame(1.15);
  G.aim(-0.45, 0.6); // the floor (longitude 0, latitude λ) towards the camera at the start
  const turnDay = rate * day * 180 / Math.PI, still = a.precession.first_order_rate === 0;
  put(note, `Seen from the stars, the Earth turns once in a sidereal day (${fmt(day / 3600, 4)} h). The floor at ${fmt(a.setup.latitude_deg, 5)}° `,
    `(drawn large, north green) turns with it; the swing plane (red) turns on the floor by ${still ? 'nothing: at the equator ω sin λ = 0'
      : `${fmt(Math.abs(turnDay), 4)}° ${turnDay < 0 ? 'clockwise' : 'anticlockwise'} seen from above in that day (360° × sin λ = ${fmt(360 * Math.abs(Math.sin(lat)), 4)}°)`}`,
    '. Drawn to scale: nothing exaggerated. Grey: where the plane stood at the start. Seen from the ground the Earth is held still ',
    '(the rotating frame): the plane turns just the same on the floor.');
  const times = Array.from({length: 289}, (_, i) => i * day / 3600 / 288); // hours, every 5 min
  play.set(times, (i, f, th) => {
    const t = th * 3600, spin = ground() ? 0 : 2 * Math.PI * t / day, turn = rate * t;
    earth.rotation.z = spin;
    box.dataset.hours = String(th);
    plane.rotation.z = turn;
    box.dataset.earthDeg = String(spin * 180 / Math.PI);
    box.dataset.swingDeg = String(turn * 180 / Math.PI);
    G.render();
  });
}
