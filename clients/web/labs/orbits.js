// Orbits lab: the Schwarzschild precession of Mercury and light bending by the
// Sun (POST /v1/gr/geodesic, timelike and null).
import {el, put, add, field, val, fmt, num, svg, labLayout, labSection, runner, examplePicker, linePlot, drawPlot, plotSize, pow10, plotTools,
  costPreview, notesBox, relWords, amount} from '../lib.js';
import {player} from '../anim.js';
import {handle, rerun} from '../handles.js';
import {arrow, energyBars} from '../draw.js';

const BUILTIN = [{title: 'Mercury: 43″ per century', operation: '/v1/gr/geodesic',
  request: {M: 'sun', kind: 'timelike', initial: {semi_major_axis: 57909050000, eccentricity: 0.20563593}, orbits: 3, samples: 5}},
  {title: 'Starlight grazing the Sun: 1.75″', operation: '/v1/gr/geodesic',
   request: {M: 'sun', kind: 'null', r0: 1e13, initial: {impact_parameter: 696340000}, samples: 200}}];
// The forms hold the Sun's orbits (a, e) and rays past the Sun (b, r0).
const fits = (ex) => ex.request.M === 'sun' && (ex.request.kind === 'null'
  ? ex.request.initial && typeof ex.request.initial.impact_parameter === 'number'
  : ex.request.initial && typeof ex.request.initial.semi_major_axis === 'number' && typeof ex.request.initial.eccentricity === 'number');

export default {
  id: 'orbits', title: 'Orbits',
  mount(main) {
    const L = labLayout(main, {title: 'Orbits: Schwarzschild precession',
      intro: 'A test mass around the Sun in Schwarzschild spacetime: its perihelion advances by about 6πGM/(c²a(1−e²)) per orbit.'});
    const a = field({label: 'semi-major axis', pointer: '/initial/semi_major_axis', value: 57909050000, unit: 'm', id: 'orb-a'});
    const e = field({label: 'eccentricity', pointer: '/initial/eccentricity', value: 0.20563593, id: 'orb-e'});
    const n = field({label: 'orbits', pointer: '/orbits', value: 3, id: 'orb-n', min: 1, budget: 'orbits'});
    add(L.form, examplePicker(['/v1/gr/geodesic'], BUILTIN, (ex) => {
      const r = ex.request;
      if (r.kind === 'null') { // a light ray: the light-bending form below
        lb.input.value = r.initial.impact_parameter; if (typeof r.r0 === 'number') lr.input.value = r.r0;
        lrun(); lf.scrollIntoView({block: 'nearest'}); return;
      }
      a.input.value = r.initial.semi_major_axis; e.input.value = r.initial.eccentricity;
      if (r.orbits) n.input.value = r.orbits;
      run(); cost.predict();
    }, {fits}), a.wrap, e.wrap, n.wrap);
    // the chooser's predicted cost at the chosen accuracy (and at draft) before the run: a dry run
    const orbitBody = () => ({M: 'sun', kind: 'timelike', initial: {semi_major_axis: val(a.input), eccentricity: val(e.input)},
      orbits: val(n.input), samples: 600});
    const cost = costPreview(L.form, '/v1/gr/geodesic', orbitBody, {id: 'orb-cost'});
    add(L.form, cost.wrap, el('div', {class: 'buttons'}, el('button', {type: 'submit', id: 'orb-submit'}, 'Orbit')));
    // a group: the perihelion and the aphelion are handles (drag them along the axis, or focus and use the arrow keys)
    const plot = svg('svg', {class: 'plot', id: 'orb-plot', role: 'group', 'aria-label': 'orbit: drag the perihelion or the aphelion'});
    const exId = 'orb-exaggerate';
    const exSel = el('select', {id: exId, 'data-role': 'exaggerate'});
    const exNote = el('span', {class: 'muted', id: 'orb-ex-note'});
    const play = player({label: 'The orbit', reverse: 'Backwards: the same orbit travelled the other way round, also a geodesic (gravity has no friction: t → −t is a motion too); the perihelion still advances, in the direction of travel.'});
    const energy = svg('svg', {class: 'plot dial energy', id: 'orb-energy', role: 'img', 'aria-label': 'energy bars'});
    const vecNote = el('p', {class: 'muted', id: 'orb-vec-note'});
    add(L.figure, el('h3', {}, 'The orbit'),
      el('div', {class: 'exaggerate'}, el('label', {for: exId}, 'Precession drawn'), exSel, exNote), plot, play.root, vecNote,
      el('p', {class: 'muted'}, 'Sun at the origin (orange); perihelia marked in red. With the precession exaggerated, each ',
        'sample\'s angle φ is drawn as φ (2π + kδ)/(2π + δ), δ the measured advance per orbit: the perihelion then moves kδ ',
        'per orbit while r(φ) is the API\'s.'),
      el('h3', {}, 'Energy per kilogram, as it plays'), energy,
      el('p', {class: 'muted'}, 'From the orbit\'s constants E and L (the API\'s conserved values) at the planet\'s r: ',
        'the radial equation of the Schwarzschild orbit, ½ṙ² + ½L²/r² − GM/r − GM L²/(c²r³) = ½c²(E² − 1) (dots: proper time), ',
        'read as kinetic energy, Newton\'s potential and the relativistic term. Kinetic and potential trade; their sum stays level.'));
    let last = null, lastOrbits = 1;
    const drawOrbit = () => {
      const r = last;
      if (!r) return;
      const s = r.samples, d = r.precession.measured_per_orbit, k = Number(exSel.value) || 1;
      // fewer than 20 samples an orbit (600 samples over 100,000 orbits): joined, they would draw chords
      // across the ellipse, a thicket, not its path; drawn as dots they show the ring the orbit sweeps
      const sparse = s.r.length / lastOrbits < 20;
      const warp = (phi) => typeof d === 'number' ? phi * (2 * Math.PI + k * d) / (2 * Math.PI + d) : phi;
      const xy = s.r.map((rr, i) => [rr * Math.cos(warp(s.phi[i])), rr * Math.sin(warp(s.phi[i]))]);
      // perihelia: local minima of r
      const peri = [];
      if (!sparse) for (let i = 0; i < s.r.length; i++)
        if ((i === 0 || s.r[i] <= s.r[i - 1]) && (i === s.r.length - 1 || s.r[i] < s.r[i + 1])) peri.push(xy[i]);
      const planet = svg('circle', {r: 7, fill: '#1864ab', stroke: '#fff', 'stroke-width': 2, id: 'orb-planet'});
      const vecs = svg('g', {id: 'orb-vectors'}); // the velocity and the forces on the planet, drawn per frame
      let XY = null;
      const what = sparse ? `1 point per ${fmt(lastOrbits / s.r.length, 2)} orbits` : 'orbit';
      linePlot(plot, [{points: xy, label: k === 1 ? what : `${what}, ${sparse ? '' : 'precession '}×${exLabel(k)}`, dots: sparse, r: 1.8, t: s.t},
        sparse ? null : {points: peri, label: 'perihelia', dots: true, color: '#c92a2a'}].filter(Boolean),
        {xlabel: 'x [m]', ylabel: 'y [m]', equal: true, name: 'orbit', height: 560, legend: 'below', frame: dragFrame || undefined, marks: [({X, Y, frame}) => {
          XY = [X, Y];
          const g = svg('g', {});
          add(g, svg('circle', {cx: X(0), cy: Y(0), r: 9, fill: '#f59f00'}));
          for (const p of peri) add(g, svg('line', {x1: X(0), y1: Y(0), x2: X(p[0]), y2: Y(p[1]), stroke: '#c92a2a', 'stroke-dasharray': '5 4'}));
          add(g, planet, vecs);
          // (over the planet, which starts at perihelion) the turning points to drag: perihelion a(1 − e) on +x where the orbit starts, aphelion a(1 + e) on −x
          const aa = val(a.input), ee = val(e.input);
          if (Number.isFinite(aa) && Number.isFinite(ee)) {
            const rp = aa * (1 - ee), ra = aa * (1 + ee), AU = 1.495978707e11;
            const words = (what, r) => `${what} ${fmt(r / 1e9, 4)} million km (${fmt(r / AU, 3)} AU)`;
            const move = (which) => (x, y, done) => {
              let p = which === 'peri' ? Math.abs(x) : rp, q = which === 'apo' ? Math.abs(x) : ra;
              if (which === 'peri') p = Math.min(p, q * 0.999); else q = Math.max(q, p * 1.001);
              p = Math.max(p, 1e9); // well outside the Sun's Schwarzschild radius, and outside the Sun itself
              a.input.value = Number(((p + q) / 2).toPrecision(6)); e.input.value = Number(((q - p) / (q + p)).toPrecision(6));
              dragFrame = done ? null : frame;
              again(done);
            };
            add(g, handle(plot, {id: 'orb-peri', X, Y, at: [rp, 0], axes: 'x', step: [aa / 100, 0], color: '#c92a2a', label: 'perihelion distance',
              text: (x) => words('perihelion', Math.abs(x)), onMove: move('peri')}),
              handle(plot, {id: 'orb-apo', X, Y, at: [-ra, 0], axes: 'x', step: [aa / 100, 0], color: '#5c3b00', label: 'aphelion distance',
                text: (x) => words('aphelion', Math.abs(x)), onMove: (x, y, done) => move('apo')(x, y, done)}));
          }
          return g;
        }]});
      const live = liveState(r);
      if (sparse || !live) { put(energy); vecNote.textContent = sparse ? 'The velocity, the forces and the energy bars are drawn when the orbit is (20 samples an orbit or more).' : ''; }
      play.set(s.t, (i, f) => {
        const j = Math.min(i + 1, xy.length - 1), x = xy[i][0] + (xy[j][0] - xy[i][0]) * f, y = xy[i][1] + (xy[j][1] - xy[i][1]) * f;
        if (XY) { planet.setAttribute('cx', XY[0](x)); planet.setAttribute('cy', XY[1](y)); }
        if (!live || !XY || sparse) return;
        // the state at this frame: r and φ between the samples, the radial direction where the planet is drawn
        const rr = s.r[i] + (s.r[j] - s.r[i]) * f, th = Math.atan2(y, x), dir = Math.sign(s.r[j] - s.r[i]) || Math.sign(s.r[i] - s.r[Math.max(0, i - 1)]);
        const q = live.at(rr, dir), ur = [Math.cos(th), Math.sin(th)], ut = [-Math.sin(th), Math.cos(th)];
        const v = [q.vr * ur[0] + q.vt * ut[0], q.vr * ur[1] + q.vt * ut[1]];
        const px = XY[0](x), py = XY[1](y), mpx = Math.abs(XY[0](1) - XY[0](0)); // px per metre
        const kv = live.vScale * mpx, kg = live.gScale * mpx;
        put(vecs, arrow(px, py, px + kv * v[0], py - kv * v[1], '#1864ab', 'v', 16),
          arrow(px, py, px - kg * q.g * ur[0], py + kg * q.g * ur[1], '#a65300', 'g', 16),
          k > 1 ? arrow(px, py, px - kg * k * q.gr * ur[0], py + kg * k * q.gr * ur[1], '#6741d9', `GR ×${exLabel(k)}`, 16) : null);
        plot.dataset.state = JSON.stringify({r: rr, vr: q.vr, vt: q.vt, g: q.g, gr: q.gr, K: q.K, U: q.U, Ugr: q.Ugr});
        energyBars(energy, [['½v²', q.K, '#1864ab'], ['−GM/r', q.U, '#a65300'], ['−GML²/c²r³', q.Ugr, '#6741d9'], ['sum', q.K + q.U + q.Ugr, '#111']],
          live.ref, 'energy per kilogram', 'J/kg');
        vecNote.textContent = `At r = ${amount(rr, 'm')}: speed ${amount(Math.hypot(q.vr, q.vt), 'm/s')} (blue, v), gravity GM/r² = ${amount(q.g, 'm/s²')} ` +
          `per kilogram (orange, g), and the relativistic term 3GML²/(c²r⁴) = ${amount(q.gr, 'm/s²')}, ${relWords(q.gr / q.g)} of it` +
          (k > 1 ? ` (violet, drawn ×${exLabel(k)} like the precession)` : ' (too short to draw: choose an exaggerated precession to see it)') +
          '; both pull towards the Sun, and their sum is the net force.';
      }, {grow: [plot]}); // the path grows behind the planet as it plays
    };
    exSel.addEventListener('change', drawOrbit);
    let dragFrame = null;
    const again = rerun(() => { run(); cost.predict(); }, 200);
    const exLabel = (k) => k >= 1e4 ? pow10(Math.round(Math.log10(k))) : String(k);
    const orbNotes = notesBox('orb-notes'); L.figure.after(orbNotes.box); // under the figure: the picture stays by the answer
    const run = runner(L, '/v1/gr/geodesic', () => cost.withAccuracy(orbitBody()), (r, req) => {
      lastOrbits = Math.max(1, Number(req && req.orbits) || 1);
      const p = r.precession;
      if (!p || r.motion !== 'bound') { cost.after(r); put(L.results, outcome(r, 'orbit')); put(orbNotes.box); last = null; put(plot); put(energy); vecNote.textContent = ''; return; }
      cost.after(r);
      put(L.results, el('dl', {class: 'nums'},
        el('dt', {}, 'advance per orbit (measured)'), num('orb-measured', p.measured_per_orbit, 'rad'),
        el('dt', {}, 'exact'), num('orb-exact', p.exact_per_orbit, 'rad'),
        el('dt', {}, '6πGM/(c²a(1−e²))'), num('orb-first', p.first_order_per_orbit, 'rad'),
        el('dt', {}, 'per century'), num('orb-century', p.arcsec_per_century.measured, '″')));
      // chapter 4, Orbits in the Schwarzschild Metric: u'' + u = GM/h² + 3GM u²/c²; to first order in GM/(c²a)
      // the perihelion advances by 6πGM/(c²a(1−e²)) per orbit (the API's first_order_per_orbit)
      const ARC = 180 / Math.PI * 3600;
      orbNotes.update({section: '4', heading: 'A Little General Relativity: Orbits in the Schwarzschild Metric',
        formula: ['u″ + u = GM/h² + 3GM u²/c²  (u = 1/r)  ⇒  Δφ = 6πGM / (c² a (1 − e²)) per orbit'],
        what: 'the first-order formula', formulaValue: p.first_order_per_orbit * ARC, apiValue: p.measured_per_orbit * ARC,
        unit: '″', source: 'api', how: 'The perihelion\'s advance per orbit, in arcseconds: the formula keeps the first order in GM/(c²a); ' +
          'the API integrates the geodesic and measures where the perihelia fall.',
        note: 'The extracted notes end at §4.2, so this chapter\'s section numbers are not in their text; the formula is rebuilt from the ' +
          'Schwarzschild orbit equation. ' + (typeof p.exact_per_orbit === 'number' ? `The exact advance (elliptic integrals) is ${fmt(p.exact_per_orbit * ARC, 7)}″, ` +
          `${relWords(Math.abs(p.first_order_per_orbit - p.exact_per_orbit) / Math.abs(p.exact_per_orbit))} from the formula's: for Mercury the ` +
          'higher orders are tiny, and the rest of the difference is how precisely the perihelia are found in the integrated orbit.' : '')});
      // exaggeration factors that make the advance about 0.3 rad (17°) and a tenth of that per orbit
      const d = Math.abs(p.measured_per_orbit) || 0, prev = Number(exSel.value);
      // ... and no more than a quarter turn over the whole run (10⁶ over 100,000 orbits would turn it round and round)
      const top = d > 0 ? 10 ** Math.max(0, Math.min(Math.round(Math.log10(0.3 / d)), Math.floor(Math.log10(Math.PI / 2 / (d * lastOrbits))))) : 1;
      const opts = [...new Set([1, Math.max(1, top / 10), top])];
      put(exSel, opts.map(k => el('option', {value: k, selected: k === (opts.includes(prev) ? prev : top)},
        k === 1 ? 'true to scale (×1)' : `×${exLabel(k)}`)));
      const kk = Number(exSel.value);
      // the advance per orbit, real and drawn, and over the whole run when it is long
      const say = (k2) => `real advance ${fmt(d * 180 / Math.PI * 3600, 3)}″ per orbit` + (k2 > 1 ? `, drawn ${fmt(k2 * d * 180 / Math.PI, 3)}°` : '') +
        (lastOrbits >= 100 ? `; over the ${fmt(lastOrbits)} orbits ${fmt(lastOrbits * d * 180 / Math.PI * 3600, 3)}″` +
          (k2 > 1 ? `, drawn ${fmt(k2 * lastOrbits * d * 180 / Math.PI, 3)}°` : '') : '');
      exNote.textContent = d > 0 ? say(kk) : '';
      exSel.onchange = () => { exNote.textContent = say(Number(exSel.value)); };
      last = r;
      drawOrbit();
    });
    run(); cost.predict();

    // light bending: a null geodesic past the Sun
    const lf = el('form', {novalidate: true, id: 'light-form', 'aria-label': 'Light bending inputs'});
    const lb = field({label: 'impact parameter b', pointer: '/initial/impact_parameter', value: 696340000, unit: 'm', id: 'light-b',
      help: 'the Sun\'s radius grazes it'});
    const lr = field({label: 'start and end r0', pointer: '/r0', value: 1e13, unit: 'm', id: 'light-r0',
      help: 'far from the Sun'});
    add(lf, lb.wrap, lr.wrap, el('div', {class: 'buttons'}, el('button', {type: 'submit', id: 'light-submit'}, 'Shine')));
    const S = labSection(main, {title: 'Light bending', form: lf,
      intro: 'Starlight passing the Sun at impact parameter b is deflected by 4GM/(c²b) to first order: 1.75″ at the limb (Eddington, 1919).'});
    const lplot = svg('svg', {class: 'plot', id: 'light-plot', role: 'img', 'aria-label': 'light ray bent by the Sun (exaggerated)'});
    add(S.figure, lplot);
    const lightNotes = notesBox('light-notes'); S.figure.after(lightNotes.box); // under the figure: the picture stays by the answer
    const lrun = runner(S, '/v1/gr/geodesic', () => ({M: 'sun', kind: 'null', r0: val(lr.input),
      initial: {impact_parameter: val(lb.input)}, samples: 200}), (r) => {
      const d = r.deflection;
      if (!d || !d.arcsec) { // captured (or any outcome without a deflection): drawn and said, no numbers to compare
        put(S.results, outcome(r, 'light'));
        put(lightNotes.box);
        drawPlot(lplot, () => capturePicture(lplot, r));
        plotTools(lplot, {name: 'light-bending'});
        return;
      }
      put(S.results, el('dl', {class: 'nums'},
        el('dt', {}, 'deflection (measured)'), num('light-measured', d.arcsec.measured, '″'),
        el('dt', {}, 'exact'), num('light-exact', d.arcsec.exact, '″'),
        el('dt', {}, '4GM/(c²b)'), num('light-first', d.arcsec.first_order, '″'),
        el('dt', {}, 'closest approach'), num('light-rmin', d.closest_approach, 'm')));
      // chapter 4, Deflection of Light: the photon's u'' + u = 3GM u²/c², first order: δ = 4GM/(c² b)
      lightNotes.update({section: '4', heading: 'A Little General Relativity: Deflection of Light',
        formula: ['u″ + u = 3GM u²/c²  (a photon)  ⇒  δ = 4GM / (c² b)'],
        what: 'the first-order formula', formulaValue: d.arcsec.first_order, apiValue: d.arcsec.measured, unit: '″', source: 'api',
        how: 'The total bending of a ray from r0 in to r0 out: the formula is for a ray from infinity, to first order in GM/(c²b).',
        note: typeof d.arcsec.exact === 'number' ? `The exact deflection (elliptic integral, same r0) is ${fmt(d.arcsec.exact, 7)}″: ` +
          'a ray that starts and ends at a finite r0 is bent a little less than one from infinity.' : null});
      drawPlot(lplot, () => rayPicture(lplot, d));
      plotTools(lplot, {name: 'light-bending'});
    });
    lrun();
  },
};

// What happened to a geodesic without a deflection or a precession to show
// (the API's "motion": capture, escape, plunge), said in words a student reads.
function outcome(r, what) {
  const GM = r.units && r.units.GM_over_c2, b = r.conserved && r.conserved.impact_parameter;
  const bc = typeof GM === 'number' ? 3 * Math.sqrt(3) * GM : null; // a photon's critical impact parameter
  const words = {
    capture: what === 'light'
      ? `Captured: the ray falls into the centre and is not bent out again. Its impact parameter b = ${amount(b, 'm')} is below ` +
        `3√3 GM/c² = ${amount(bc, 'm')}, the photon sphere's critical value, so nothing turns it back. (The Sun is a point mass here: ` +
        'its real surface, 696,000 km from the centre, would stop any ray with b below that long before.)'
      : 'Captured: the body falls into the centre.',
    plunge: 'Plunge: no bound orbit turns at these radii; the body spirals into the centre.',
    escape: what === 'light' ? 'Escape: the ray leaves without reaching its closest approach.' : 'Escape: the body is not bound and leaves.',
    scatter: 'Scattered: the path passes and leaves again.'}[r.motion] || `Outcome: ${r.motion}.`;
  return el('div', {}, el('p', {class: 'outcome', id: what + '-outcome', 'data-motion': r.motion}, el('strong', {}, words.split(':')[0] + ': '),
    words.slice(words.indexOf(':') + 1).trim()),
    r.end && typeof r.end.r === 'number' ? el('dl', {class: 'nums'}, el('dt', {}, 'ended at r'), num(what + '-end-r', r.end.r, 'm'),
      typeof r.end.capture_radius === 'number' ? [el('dt', {}, 'capture radius 2GM/c²'), num(what + '-rcap', r.end.capture_radius, 'm')] : null) : null);
}

// A capture drawn: the ray coming in at b, the photon sphere (r = 3GM/c²) and
// the horizon (2GM/c²) to scale with each other, the ray ending on the horizon.
function capturePicture(root, r) {
  const [W, H] = plotSize(root, 640, 300); put(root); root.setAttribute('viewBox', `0 0 ${W} ${H}`);
  const GM = r.units.GM_over_c2, b = r.conserved.impact_parameter, bc = 3 * Math.sqrt(3) * GM;
  const cx = W * 0.62, cy = H / 2, k = (H * 0.32) / bc; // px per metre: the critical b drawn at a third of the height
  const yb = cy - Math.min(b, 1.4 * bc) * k, rh = 2 * GM * k;
  const path = `M 12 ${yb} L ${cx - 2.2 * bc * k} ${yb} Q ${cx - 0.4 * bc * k} ${yb} ${cx - rh * 0.7} ${cy - rh * 0.7}`;
  add(root, svg('circle', {cx, cy, r: 3 * GM * k, fill: 'none', stroke: '#a65300', 'stroke-dasharray': '5 4'}),
    svg('circle', {cx, cy, r: rh, fill: '#111'}),
    svg('line', {x1: 12, y1: cy - bc * k, x2: W - 12, y2: cy - bc * k, stroke: '#999', 'stroke-dasharray': '3 5'}),
    svg('path', {d: path, fill: 'none', stroke: '#1864ab', 'stroke-width': 3, id: 'light-captured-ray'}),
    svg('text', {x: 12, y: yb - 8, 'font-size': 14, fill: '#1864ab'}, `b = ${amount(b, 'm')}`),
    svg('text', {x: 12, y: cy - bc * k + 18, 'font-size': 14, fill: '#444'}, `critical b = 3√3 GM/c² = ${amount(bc, 'm')}`),
    svg('text', {x: cx + 3 * GM * k + 6, y: cy + 5, 'font-size': 14, fill: '#a65300'}, 'photon sphere'),
    svg('text', {x: W / 2, y: H - 12, 'font-size': 17, fill: '#c92a2a', 'font-weight': 700, 'text-anchor': 'middle',
      'data-role': 'outcome'}, 'captured: the light falls in'));
  root.setAttribute('aria-label', `light ray captured: impact parameter ${amount(b, 'm')} below the critical ${amount(bc, 'm')}`);
}

// A schematic of the ray: its two asymptotes, the angle between them drawn 30°
// (the real angle is ~1e-5 rad; the factor is labelled).
function rayPicture(root, d) {
  const [W, H] = plotSize(root, 640, 300); put(root); root.setAttribute('viewBox', `0 0 ${W} ${H}`);
  root.setAttribute('aria-label', 'light ray bent by the Sun (exaggerated)');
  const k = W / 640, shown = Math.PI / 6, cx = W / 2, cy = H / 2 + 30 * k, y0 = cy - 40 * k, L = 300 * k;
  add(root, svg('circle', {cx, cy, r: 34 * k, fill: '#f59f00'}),
    svg('line', {x1: 12, y1: y0, x2: cx, y2: y0, stroke: '#1864ab', 'stroke-width': 3}),
    svg('line', {x1: cx, y1: y0, x2: cx + L * Math.cos(shown), y2: y0 + L * Math.sin(shown), stroke: '#1864ab', 'stroke-width': 3}),
    svg('line', {x1: cx, y1: y0, x2: W - 12, y2: y0, stroke: '#999', 'stroke-dasharray': '6 5'}),
    svg('text', {x: cx + 90 * k + 10, y: y0 + 30, 'font-size': 17, fill: '#c92a2a', 'font-weight': 700}, `δ = ${fmt(d.arcsec.measured, 4)}″`),
    svg('text', {x: 12, y: H - 12, 'font-size': 14, fill: '#444'}, `angle drawn ×${fmt(shown / d.measured, 3)}`));
}

// The planet's velocity, the forces per kilogram and the energies per kilogram at radius r, from the
// orbit's constants (E/(mc²) and L/m, the API's conserved values) and the Schwarzschild radial equation
//   ½ṙ² + ½L²/r² − GM/r − GM L²/(c²r³) = ½c²(E² − 1)      (dots: proper time; E² − 1 = ε(2 + ε), ε = E − 1)
// differentiated: r̈ = −GM/r² + L²/r³ − 3GM L²/(c²r⁴): Newton's gravity and the relativistic term.
// dir: the sign of ṙ (outwards +1). Null when the answer lacks what is needed (geometric units, no GM).
function liveState(r) {
  const u = r.units || {}, cs = r.conserved || {}, GM = u.GM, c = u.c, L = cs.angular_momentum, eps = cs.energy_minus_one;
  if (u.system !== 'SI' || ![GM, c, L, eps].every(Number.isFinite) || !r.samples || !r.samples.r.length) return null;
  const total = 0.5 * c * c * eps * (2 + eps);
  const at = (rr, dir) => {
    const K = total + GM / rr + GM * L * L / (c * c * rr ** 3); // ½v² = ½ṙ² + ½L²/r²
    const vt = L / rr, vr = (dir || 0) * Math.sqrt(Math.max(0, 2 * K - vt * vt));
    return {vr, vt, K, U: -GM / rr, Ugr: -GM * L * L / (c * c * rr ** 3), g: GM / (rr * rr), gr: 3 * GM * L * L / (c * c * rr ** 4)};
  };
  // scales: the fastest speed (at the smallest r) and the strongest pull drawn half the mean radius long
  const rmin = Math.min(...r.samples.r), rmean = r.samples.r.reduce((a, b) => a + b, 0) / r.samples.r.length;
  const top = at(rmin, 0);
  return {at, vScale: rmean / 2 / top.vt, gScale: rmean / 2 / top.g, ref: Math.max(Math.abs(top.U), top.K)};
}
