// Earth lab: the falling object and the cannonball on the rotating Earth
// (POST /v1/scenes/falling-object, /v1/scenes/cannonball): with Coriolis beside
// without (where it would land if the Earth did not turn), the deflection
// magnified and labelled; and the Foucault pendulum (POST /v1/scenes/foucault).
import {el, svg, put, add, field, val, fmt, num, examplePicker, labSection, runner, drawPlot, plotSize, plotTools, api, curlBox, linePlot} from '../lib.js';
import {player} from '../anim.js';

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
    svg('text', {x: cx - 8, y: cy + 30, 'font-size': 15, fill: '#2b8a3e', 'text-anchor': 'end'}, 'without Coriolis'),
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
      if (ex.operation === '/v1/scenes/falling-object') { fh.input.value = r.height; fl.input.value = r.latitude_deg; fall(); fallS.form.scrollIntoView(); }
      if (ex.operation === '/v1/scenes/cannonball') { cs.input.value = r.speed; ce.input.value = r.elevation_deg;
        ca.input.value = r.azimuth_deg ?? 0; cl.input.value = r.latitude_deg; cannon(); canS.form.scrollIntoView(); }
      if (ex.operation === '/v1/scenes/foucault') { pl.input.value = r.latitude_deg; pL.input.value = r.length ?? 67;
        pa.input.value = (r.release && r.release.amplitude_deg) ?? 3; ps.input.value = r.swings ?? 100; pend(); fouS.form.scrollIntoView(); }
    }));
    // falling object
    const fh = field({label: 'height h', pointer: '/height', value: 100, unit: 'm', id: 'fall-height'});
    const fl = field({label: 'latitude λ', pointer: '/latitude_deg', value: 32, unit: '°', id: 'fall-lat'});
    const fallS = section(main, 'Falling object', 'Dropped from rest, it lands east of the point below (and a little south). ' +
      'Without the Earth\'s rotation it would land exactly below.', [fh, fl], 'Drop', 'fall');
    const fall = runner(fallS, '/v1/scenes/falling-object', () => ({height: val(fh.input), latitude_deg: val(fl.input)}), (a) => {
      put(fallS.results, el('dl', {class: 'nums'},
        el('dt', {}, 'fall time'), num('fall-t', a.numerical.t, 's'),
        el('dt', {}, 'east (numerical)'), num('fall-east', a.numerical.east, 'm'),
        el('dt', {}, 'east (first order)'), num('fall-east-1', a.first_order.east, 'm'),
        el('dt', {}, 'south (numerical)'), num('fall-south', a.numerical.south, 'm'),
        el('dt', {}, 'numerical − first order'), num('fall-diff', a.difference.east, 'm')),
        el('p', {class: 'muted'}, a.first_order.formula || ''));
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
      const t = r.body.t.slice(), pos = r.body.position.slice();
      if (r.body.stopped && r.body.stopped.t > t[t.length - 1]) { t.push(r.body.stopped.t); pos.push(r.body.stopped.position); }
      const pts = pos.map(p => [p[0] * 100, p[2]]);
      const dot = svg('circle', {r: 7, fill: '#c92a2a', stroke: '#fff', 'stroke-width': 2, id: 'fall-dot'});
      let XY = null, cur = pts[0];
      linePlot(pathPlot, [{points: pts, label: 'with Coriolis'}, {points: [[0, h], [0, 0]], label: 'without', color: '#2b8a3e', dash: '6 4'}],
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
      });
    };
    // cannonball
    const cs = field({label: 'speed', pointer: '/speed', value: 500, unit: 'm/s', id: 'can-speed'});
    const ce = field({label: 'elevation', pointer: '/elevation_deg', value: 30, unit: '°', id: 'can-elev'});
    const ca = field({label: 'azimuth', pointer: '/azimuth_deg', value: 0, unit: '° from east', id: 'can-az'});
    const cl = field({label: 'latitude λ', pointer: '/latitude_deg', value: 45, unit: '°', id: 'can-lat'});
    const canS = section(main, 'Cannonball', 'Fired over the rotating Earth it is deflected to the right in the northern ' +
      'hemisphere (to the left in the southern). The picture shows the landing point relative to where it would land on a ' +
      'non-rotating Earth.', [cs, ce, ca, cl], 'Fire', 'can');
    const cannon = runner(canS, '/v1/scenes/cannonball', () => ({speed: val(cs.input), elevation_deg: val(ce.input),
      azimuth_deg: val(ca.input), latitude_deg: val(cl.input)}), (a) => {
      put(canS.results, el('dl', {class: 'nums'},
        el('dt', {}, 'time of flight'), num('can-t', a.numerical.t, 's'),
        el('dt', {}, 'range'), num('can-range', a.numerical.range, 'm'),
        el('dt', {}, 'deflection to the right'), num('can-right', a.numerical.right, 'm'),
        el('dt', {}, 'right (first order)'), num('can-right-1', a.first_order.right, 'm')));
      // relative to the non-rotating landing point (range v² sin 2α / g along the azimuth)
      const g = a.parameters.g, v = a.parameters.speed, al = a.parameters.elevation_deg * Math.PI / 180;
      const az = a.parameters.azimuth_deg * Math.PI / 180, R0 = v * v * Math.sin(2 * al) / g;
      const de = a.numerical.east - R0 * Math.cos(az), dn = a.numerical.north - R0 * Math.sin(az);
      drawPlot(canS.plot, () => planView(canS.plot, de, dn, `${fmt(a.numerical.right, 4)} m to the right`));
    });
    // Foucault
    const pl = field({label: 'latitude λ', pointer: '/latitude_deg', value: 48.846, unit: '°', id: 'fou-lat'});
    const pL = field({label: 'length', pointer: '/length', value: 67, unit: 'm', id: 'fou-len'});
    const pa = field({label: 'amplitude', pointer: '/release/amplitude_deg', value: 3, unit: '°', id: 'fou-amp'});
    const ps = field({label: 'swings', pointer: '/swings', value: 100, id: 'fou-swings'});
    const fouS = section(main, 'Foucault pendulum', 'The swing plane turns clockwise (northern hemisphere) at ω sin λ. ' +
      'The trace (and the bob when played) is drawn from the measured rate and swing period, with the turn exaggerated so that it shows; the exaggeration is written under it.', [pl, pL, pa, ps], 'Swing', 'fou');
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
        el('dt', {}, 'swing period'), num('fou-period', a.swing.period, 's')));
      const flat = a.swing.semi_major_axis > 0 ? Math.min(1, Math.abs(a.swing.semi_minor_axis / a.swing.semi_major_axis)) : 0;
      let bob = null;
      drawPlot(fouS.plot, () => { bob = rosette(fouS.plot, p.measured_rate, a.swing.period, still, flat); });
      // 12 swings, 40 frames a swing: the bob on the (exaggerated) trace
      const T = a.swing.period, times = Array.from({length: 12 * 40 + 1}, (_, i) => i * T / 40);
      fouPlay.set(times, (i, f, t) => { if (bob) bob(t / T); });
    });
    plotTools(fallS.plot, {name: 'falling-object'}); plotTools(canS.plot, {name: 'cannonball'});
    const fouPlay = player({label: 'The Foucault pendulum'});
    fouS.plot.after(fouPlay.root);
    plotTools(fouS.plot, {name: 'foucault'});
    fall(); cannon(); pend();
  },
};

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
