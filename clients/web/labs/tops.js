// Tops lab: the heavy symmetric top (POST /v1/rigid/top): the symmetry axis
// tracing nutation loops on the unit sphere and θ(t); and the Dzhanibekov flip
// of an asymmetric free body (POST /v1/rigid/rotate).
import {el, svg, put, add, field, val, fmt, num, labLayout, labSection, runner, examplePicker, linePlot, costPreview, notesBox} from '../lib.js';
import {player} from '../anim.js';
import {handle, rerun} from '../handles.js';
import {energyBars} from '../draw.js';
import {THREE, view3d, polyline, sceneAxes, axesArrows, label} from '../view3d.js';

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
      run(); cost.predict();
    }, {fits: (ex) => ex.operation !== '/v1/rigid/rotate' || (Array.isArray(ex.request.moments) && Array.isArray(ex.request.omega) &&
        typeof ex.request.t_end === 'number' && !ex.request.orientation)}),
    Object.values(f).map(c => c.wrap));
    // the chooser's predicted cost at the chosen accuracy (and at draft) before the run: a dry run
    const topBody = () => { const b = {}; for (const [k, c] of Object.entries(f)) b[k] = val(c.input); b.samples = 801; return b; };
    const cost = costPreview(L.form, '/v1/rigid/top', topBody, {id: 'top-cost'});
    // direct manipulation: the top's tilt (drag its axis round the pivot) and its spin (drag along the spin bar)
    const dial = svg('svg', {class: 'plot dial', id: 'top-dial', role: 'group',
      'aria-label': 'The top at release: drag its axis (tilt θ0) or the spin bar (ψ̇), or focus them and use the arrow keys'});
    add(L.form, el('div', {class: 'dial-box'}, el('p', {class: 'muted'}, 'Or drag the top\'s tilt and spin:'), dial));
    const again = rerun(() => { run(); cost.predict(); }, 250);
    const drawDial = () => topDial(dial, val(f.theta.input), val(f.psi_dot.input), (th, ps, done) => {
      if (th !== null) f.theta.input.value = th;
      if (ps !== null) f.psi_dot.input.value = ps;
      drawDial(); again(done);
    });
    for (const c of [f.theta.input, f.psi_dot.input]) c.addEventListener('input', drawDial);
    drawDial();
    add(L.form, cost.wrap, el('div', {class: 'buttons'}, el('button', {type: 'submit', id: 'top-submit'}, 'Spin')));
    const box3d = el('div', {class: 'view3d-box', id: 'top-3d-box'});
    const theta = svg('svg', {class: 'plot', id: 'top-theta-plot', role: 'img', 'aria-label': 'theta against time'});
    const vecNote = el('p', {id: 'top-vectors', 'aria-live': 'off'});
    const topEnergy = svg('svg', {class: 'plot dial energy', id: 'top-energy', role: 'img', 'aria-label': 'energy bars'});
    const play = player({label: 'The top', reverse: 'Backwards: a top run backwards is a top too, spinning and precessing the other way (no friction: the equations are the same with t → −t, ψ̇ → −ψ̇, φ̇ → −φ̇).'});
    add(L.figure, el('h3', {}, 'The top in 3-D'), box3d, play.root,
      el('p', {class: 'muted'}, 'Tip fixed at the origin, z up. The blue curve is the path of the symmetry axis\' end ',
        '(nutation loops); the stripes on the disc show the spin ψ. Drawn from the API\'s θ, φ, ψ samples.'),
      vecNote, el('h3', {}, 'Energy'), topEnergy,
      el('p', {class: 'muted'}, 'The notes\' E′ = E − ½I₃ω₃² (the spin\'s own energy is constant and left out): as the top dips, Mgh cos θ falls and the wobble\'s kinetic energy rises by as much; the sum stays level.'),
      el('h3', {}, 'θ(t)'), theta,
      el('p', {class: 'muted'}, 'Dotted: whole nutation periods T from the release (the closed form 4K(k)/√(β(u₃ − u₁))): θ is back at its start at each.'));
    const V = view3d(box3d, {label: 'The top in 3-D', id: 'top-view'});
    const topGroup = new THREE.Group(), world = new THREE.Group();
    V.scene.add(world);
    let trace = null;
    const topNotes = notesBox('top-notes'); L.figure.after(topNotes.box); // under the figure: the picture stays by the answer
    const run = runner(L, '/v1/rigid/top', () => cost.withAccuracy(topBody()), (a, req) => {
      cost.after(a);
      put(L.results, el('dl', {class: 'nums'},
        el('dt', {}, 'θ min'), num('top-thmin', a.nutation.theta_min, 'rad'),
        el('dt', {}, 'θ max'), num('top-thmax', a.nutation.theta_max, 'rad'),
        el('dt', {}, 'nutation period'), num('top-nut-period', a.nutation.period, 's'),
        el('dt', {}, 'precession averaged over a nutation'), num('top-prec-avg', a.precession.nutation_averaged_rate, 'rad/s'),
        el('dt', {}, 'mean precession (measured over the run)'), num('top-prec', a.precession.measured_mean_rate, 'rad/s'),
        el('dt', {}, 'steady precession rates at θ0 (slow, fast)'), el('dd', {id: 'top-steady'},
          [a.precession.steady_precession_rate_slow, a.precession.steady_precession_rate_fast].map(v => typeof v === 'number' ? fmt(v, 5) : '—').join(', ') + ' rad/s'),
        el('dt', {}, 'sleeping top stable'), el('dd', {id: 'top-sleeping'}, String(a.sleeping_top.stable)),
        el('dt', {}, 'energy drift'), num('top-drift', a.conserved.energy.max_relative_drift)));
      // notes (Lagrange Equations for Top with One Fixed Point): p_φ and p_ψ conserved, and the energy
      // E′ = ½ I₁₂ θ̇² + V(θ): θ nutates between the turning points where V(θ) = E′ (θ̇ = 0). The API solves
      // the notes' cubic in u = cos θ for them (nutation.theta_min/max) and measures θ's extremes in its samples.
      const N = a.nutation, th0 = req.theta, D = 180 / Math.PI;
      const other = Math.abs(N.theta_max - th0) >= Math.abs(N.theta_min - th0); // the turning point the top is not released at
      topNotes.update({section: '2.10', inferred: true, heading: 'Lagrange Equations for Top with One Fixed Point',
        formula: ['E − p', el('sub', {}, 'ψ'), '²/2I', el('sub', {}, '3'), ' = ½ I', el('sub', {}, '12'), ' (dθ/dt)² + (p', el('sub', {}, 'φ'),
          ' − p', el('sub', {}, 'ψ'), ' cos θ)² / (2 I', el('sub', {}, '12'), ' sin²θ) + M g h cos θ;  θ turns where dθ/dt = 0'],
        what: 'the notes\' turning point', formulaValue: (other ? N.theta_max : N.theta_min) * D,
        apiValue: (other ? N.measured_theta_max : N.measured_theta_min) * D, unit: '°',
        sourceText: 'the root of the notes\' cubic in cos θ, as the API solves it',
        how: `The ${other ? 'largest' : 'smallest'} θ of the nutation: from the conserved p_φ, p_ψ and E (the formula), against ` +
          'the extreme of θ in the integrated samples.',
        note: 'Between two samples the integrated θ may pass its extreme unseen: more samples bring the two closer.'});
      const d = req.distance > 0 ? req.distance : 0.1, Lx = d * 1.5;
      const cursor = svg('line', {stroke: '#111', 'stroke-width': 1.5, 'stroke-dasharray': '4 3'});
      let Xs = null, tCur = 0;
      linePlot(theta, [{points: a.t.map((t, i) => [t, a.theta[i]]), label: 'θ', t: a.t}], {xlabel: 't [s]', ylabel: 'θ [rad]', name: 'top-theta',
        marks: [({X, top, bottom}) => { Xs = X; cursor.setAttribute('y1', top); cursor.setAttribute('y2', bottom);
          cursor.setAttribute('x1', X(tCur)); cursor.setAttribute('x2', X(tCur)); return cursor; },
        // whole nutation periods from the release (the closed form's T): released at a turning point, θ is back there at each
        ({X, top, bottom}) => {
          const T = a.nutation.period, g = svg('g', {'data-role': 'nutation-periods'}), end = a.t[a.t.length - 1];
          if (typeof T === 'number' && T > 0 && end / T <= 40)
            for (let n = 1; n * T <= end; n++) add(g, svg('line', {x1: X(n * T), x2: X(n * T), y1: top, y2: bottom, stroke: '#a65300', 'stroke-dasharray': '2 4'}));
          return g;
        }]});
      // the top: a cone from the tip to a disc at the centre of mass, striped to show the spin
      world.clear();
      world.add(sceneAxes(Lx * 0.9));
      topGroup.clear();
      const r = d * 0.55;
      const cone = new THREE.Mesh(new THREE.ConeGeometry(r * 0.35, d, 32), new THREE.MeshStandardMaterial({color: 0xb08d57}));
      cone.rotation.x = -Math.PI / 2; cone.position.z = d / 2; // apex at the tip (origin), base up the axis
      const disc = new THREE.Mesh(new THREE.CylinderGeometry(r, r, d * 0.12, 48), new THREE.MeshStandardMaterial({color: 0x1864ab}));
      disc.rotation.x = Math.PI / 2; disc.position.z = d;
      topGroup.add(cone, disc);
      for (let k = 0; k < 4; k++) { // stripes across the disc: the spin shows
        const st = new THREE.Mesh(new THREE.BoxGeometry(r * 2.02, r * 0.16, d * 0.13),
          new THREE.MeshStandardMaterial({color: k % 2 ? 0xffd43b : 0xc92a2a}));
        st.rotation.z = k * Math.PI / 4; st.position.z = d; topGroup.add(st);
      }
      const stem = new THREE.Mesh(new THREE.CylinderGeometry(r * 0.06, r * 0.06, d * 0.5, 12), new THREE.MeshStandardMaterial({color: 0x444444}));
      stem.rotation.x = Math.PI / 2; stem.position.z = d * 1.25; topGroup.add(stem);
      world.add(topGroup);
      trace = polyline(a.axis.map(v => v.map(c => c * d * 1.5)), 0x1864ab);
      world.add(trace);
      const floor = new THREE.Mesh(new THREE.CircleGeometry(Lx, 64), new THREE.MeshBasicMaterial({color: 0xeeeeee, side: THREE.DoubleSide}));
      floor.position.z = -0.001; world.add(floor);
      V.frame(Lx * 0.8, [0, 0, d * 0.6]);
      // L, ω and τ on the top as it plays: ω = φ̇ ẑ + θ̇ n̂ + ψ̇ ê3 (n̂ the line of nodes (cos φ, sin φ, 0), the
      // rates from the samples), L = I1 (ω − ω3 ê3) + I3 ω3 ê3, τ = h ê3 × (−M g ẑ); each arrow scaled to its
      // size at the release, its value said under the view
      const I1 = req.I1, I3 = req.I3, Mgh = req.mass * (req.g ?? 9.80665) * req.distance;
      const rate = (arr, k) => { const a0 = Math.max(0, k - 1), a1 = Math.min(a.t.length - 1, k + 1); return (arr[a1] - arr[a0]) / (a.t[a1] - a.t[a0]); };
      const vectorsAt = (k) => {
        const th = a.theta[k], ph = a.phi[k], e3 = [Math.sin(th) * Math.sin(ph), -Math.sin(th) * Math.cos(ph), Math.cos(th)];
        const nn = [Math.cos(ph), Math.sin(ph), 0], pd = rate(a.phi, k), td = rate(a.theta, k), sd = rate(a.psi, k);
        const w = [0, 1, 2].map(c => pd * (c === 2 ? 1 : 0) + td * nn[c] + sd * e3[c]);
        const w3 = w[0] * e3[0] + w[1] * e3[1] + w[2] * e3[2];
        const Lv = w.map((x, c) => I1 * (x - w3 * e3[c]) + I3 * w3 * e3[c]);
        const tau = [-Mgh * e3[1], Mgh * e3[0], 0];
        // the notes' E′ = E − p_ψ²/2I3: the wobble's kinetic energy ½ I1 (θ̇² + φ̇² sin²θ) and M g h cos θ, their sum
        // conserved (the spin's ½ I3 ω3², constant, left out: it would dwarf the exchange)
        const K = 0.5 * I1 * (td * td + pd * pd * Math.sin(th) ** 2), U = Mgh * Math.cos(th);
        return {w, L: Lv, tau, K, U};
      };
      const v0 = vectorsAt(0), mag = (v) => Math.hypot(v[0], v[1], v[2]);
      const arrows = [['L', 0xc92a2a], ['ω', 0x2b8a3e], ['τ', 0xa65300]].map(([nm, col]) => {
        const h = new THREE.ArrowHelper(new THREE.Vector3(0, 0, 1), new THREE.Vector3(0, 0, 0), d, col, 0.15 * d, 0.08 * d);
        const s = label(nm, '#' + col.toString(16).padStart(6, '0')); s.scale.multiplyScalar(d * 0.25);
        world.add(h, s); return [h, s];
      });
      const place = (k) => {
        const v = vectorsAt(k);
        [[v.L, v0.L], [v.w, v0.w], [v.tau, v0.tau]].forEach(([x, x0], n) => {
          // L and ω out past the stem (1.5 d), L the longer; τ from the tip along the floor
          const m = mag(x), len = Math.min(2.5, m / (mag(x0) || m || 1)) * d * [2.4, 1.9, 1.3][n];
          const [h, s] = arrows[n];
          h.visible = s.visible = m > 0;
          if (!m) return;
          const dir = new THREE.Vector3(...x).normalize();
          h.setDirection(dir); h.setLength(Math.max(len, d * 0.1), 0.15 * d, 0.08 * d);
          s.position.copy(dir.multiplyScalar(Math.max(len, d * 0.1) * 1.1));
        });
        vecNote.dataset.vectors = JSON.stringify(v);
        energyBars(topEnergy, [['½I₁(θ̇²+φ̇²sin²θ)', v.K, '#1864ab'], ['Mgh cos θ', v.U, '#a65300'], ['E′ = sum', v.K + v.U, '#111']],
          v0.K + v0.U, 'the top\'s energy E′ = E − ½I₃ω₃²');
        put(vecNote, el('strong', {}, 'On the top: '), el('span', {class: 'c1'}, `L = ${fmt(mag(v.L), 4)} kg m²/s`), ', ',
          el('span', {class: 'c2'}, `ω = ${fmt(mag(v.w), 4)} rad/s`), ', ', el('span', {class: 'c4'}, `τ = ${fmt(mag(v.tau), 4)} N m`),
          ' (τ = dL/dt turns L round the vertical: the precession; each arrow drawn against its size at the release).');
      };
      const qz = (ang) => new THREE.Quaternion().setFromAxisAngle(new THREE.Vector3(0, 0, 1), ang);
      const qx = (ang) => new THREE.Quaternion().setFromAxisAngle(new THREE.Vector3(1, 0, 0), ang);
      play.set(a.t, (i, fr, t) => {
        const j = Math.min(i + 1, a.t.length - 1), at = (arr) => arr[i] + (arr[j] - arr[i]) * fr;
        // z-x-z Euler angles: R = Rz(φ) Rx(θ) Rz(ψ) (symmetry axis (sin θ sin φ, −sin θ cos φ, cos θ), as the API's axis samples)
        topGroup.quaternion.copy(qz(at(a.phi)).multiply(qx(at(a.theta))).multiply(qz(at(a.psi))));
        trace.geometry.setDrawRange(0, i + 1);
        place(fr > 0.5 ? j : i);
        V.render();
        tCur = t; if (Xs) { cursor.setAttribute('x1', Xs(t)); cursor.setAttribute('x2', Xs(t)); }
      }, {grow: [theta]}); // θ(t) grows as it plays
    });
    run(); cost.predict();

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
    const dbox = el('div', {class: 'view3d-box', id: 'dz-3d-box'});
    const dplot = svg('svg', {class: 'plot', id: 'dz-plot', role: 'img', 'aria-label': 'omega components against time'});
    const dplay = player({label: 'The free body'});
    const dzVec = el('p', {id: 'dz-vectors'});
    const dzEnergy = svg('svg', {class: 'plot dial energy', id: 'dz-energy', role: 'img', 'aria-label': 'energy bars'});
    add(D.figure, el('h3', {}, 'The body in 3-D'), dbox, dplay.root,
      el('p', {class: 'muted'}, 'A uniform box with the same principal moments (thickness kept visible), its axes ',
        el('span', {class: 'c1'}, 'e₁'), ', ', el('span', {class: 'c2'}, 'e₂ (the middle one, spun about)'), ', ',
        el('span', {class: 'c3'}, 'e₃'), '; grey: the angular momentum L, fixed in space. Drawn from the API\'s attitude quaternions.'),
      dzVec, el('h3', {}, 'Energy of each turn'), dzEnergy,
      el('p', {class: 'muted'}, 'No torque: T = ½ Σ Iₖωₖ² stays what it was, while the share of each principal axis changes as the body flips.'),
      el('h3', {}, 'ω in the body frame'), dplot);
    const DV = view3d(dbox, {label: 'The free rigid body in 3-D', id: 'dz-view'});
    const body = new THREE.Group(), dworld = new THREE.Group();
    DV.scene.add(dworld);
    const dzNotes = notesBox('dz-notes'); D.figure.after(dzNotes.box); // under the figure: the picture stays by the answer
    const drun = runner(D, '/v1/rigid/rotate', () => ({moments: dm.map(c => val(c.input)), omega: dw.map(c => val(c.input)),
      t_end: val(dt.input), samples: 601}), (a, req) => {
      const om = a.omega || (a.samples && a.samples.omega) || [];
      const t = a.t || (a.samples && a.samples.t) || [];
      const q = a.orientation || (a.samples && a.samples.orientation) || [];
      put(D.results, el('dl', {class: 'nums'}, a.flip ? [
        el('dt', {}, 'flip interval (exact)'), num('dz-flip', a.flip.exact_flip_interval, 's'),
        el('dt', {}, 'period (exact, elliptic)'), num('dz-period', a.flip.exact_period, 's'),
        el('dt', {}, 'flips seen'), el('dd', {id: 'dz-seen'}, String(a.flip.sign_changes_seen))]
        : [el('dt', {}, 'flips'), el('dd', {id: 'dz-seen'}, 'none: not spun near the middle axis')]));
      // notes §2.8 Euler's equations, no torque: T = ½ Σ I₍ₖ₎ ωₖ² stays what it was at the start; and
      // (Stability of Rigid Body Rotations) about axis k a small wobble obeys ε̈ = (I_j − I_k)(I_k − I_i)/(I_i I_j) ω_k² ε
      const I0 = req.moments, w0 = req.omega;
      const T0 = 0.5 * I0.reduce((sum, Ik, k) => sum + Ik * w0[k] * w0[k], 0);
      const KE = Array.isArray(a.kinetic_energy) ? a.kinetic_energy[a.kinetic_energy.length - 1] : a.kinetic_energy;
      const k = [0, 1, 2].reduce((b, j) => Math.abs(w0[j]) > Math.abs(w0[b]) ? j : b, 0), i = (k + 1) % 3, j = (k + 2) % 3;
      const c = (I0[j] - I0[k]) * (I0[k] - I0[i]) / (I0[i] * I0[j]) * w0[k] * w0[k];
      dzNotes.update({section: '2.8', heading: 'Euler\'s Equations (no torque)',
        formula: ['I', el('sub', {}, '(1)'), ' dω', el('sub', {}, '1'), '/dt + (I', el('sub', {}, '(3)'), ' − I', el('sub', {}, '(2)'), ') ω',
          el('sub', {}, '2'), 'ω', el('sub', {}, '3'), ' = 0 (and cyclic)  ⇒  T = ½ Σ I', el('sub', {}, '(k)'), ' ω', el('sub', {}, 'k'), '² is constant'],
        what: 'the kinetic energy at the start', formulaValue: T0, apiValue: KE, unit: 'J',
        how: 'The kinetic energy from your moments and ω at the start, against the API\'s at the end of the run.',
        note: Number.isFinite(c) ? `Stability (the notes' next section): about axis ${k + 1} a small wobble obeys d²ε/dt² = ` +
          `(I${j + 1} − I${k + 1})(I${k + 1} − I${i + 1})/(I${i + 1} I${j + 1}) ω${k + 1}² ε = ${fmt(c, 3)} s⁻² ε: ` +
          (c > 0 ? `positive, so it grows like e^(${fmt(Math.sqrt(c), 3)} t) — the flip.` : 'negative, so it only oscillates: no flip.') : null});
      const cursor = svg('line', {stroke: '#111', 'stroke-width': 1.5, 'stroke-dasharray': '4 3'});
      let Xs = null, tCur = 0;
      if (t.length && om.length) linePlot(dplot, [0, 1, 2].map(k => ({points: t.map((tt, i) => [tt, om[i][k]]), label: `ω${k + 1}`})),
        {xlabel: 't [s]', ylabel: 'ω (body) [rad/s]', name: 'free-body-omega', marks: [({X, top, bottom}) => { Xs = X; cursor.setAttribute('y1', top); cursor.setAttribute('y2', bottom);
          cursor.setAttribute('x1', X(tCur)); cursor.setAttribute('x2', X(tCur)); return cursor; }]});
      // a box with these principal moments: side² ∝ I_j + I_k − I_i
      const I = a.moments || dm.map(c => val(c.input));
      const side = [0, 1, 2].map(k => Math.sqrt(Math.max(0, I[(k + 1) % 3] + I[(k + 2) % 3] - I[k])));
      const big = Math.max(...side) || 1, dims = side.map(v => Math.max(v / big, 0.12));
      dworld.clear(); body.clear();
      const faces = [0xf08c00, 0xf08c00, 0x74b816, 0x74b816, 0x4dabf7, 0x4dabf7]
        .map(c => new THREE.MeshStandardMaterial({color: c, transparent: true, opacity: 0.85}));
      body.add(new THREE.Mesh(new THREE.BoxGeometry(...dims), faces));
      body.add(axesArrows([[1, 0, 0], [0, 1, 0], [0, 0, 1]], [0.9, 0.9, 0.9], [0, 0, 0], undefined, false));
      dworld.add(body);
      const Ls = a.angular_momentum && a.angular_momentum[0];
      if (Ls && Math.hypot(...Ls) > 0)
        dworld.add(new THREE.ArrowHelper(new THREE.Vector3(...Ls).normalize(), new THREE.Vector3(), 1.3, 0x555555, 0.15, 0.07));
      // ω on the body (green): its body components turned into space by the attitude, drawn against its size at the start
      const wArrow = new THREE.ArrowHelper(new THREE.Vector3(0, 0, 1), new THREE.Vector3(), 1, 0x2b8a3e, 0.15, 0.07);
      const wTag = label('ω', '#2b8a3e'); wTag.scale.multiplyScalar(0.25);
      dworld.add(wArrow, wTag);
      const w0n = om.length ? Math.hypot(...om[0]) || 1 : 1;
      DV.frame(0.9);
      const qa = new THREE.Quaternion(), qb = new THREE.Quaternion();
      if (q.length === t.length) dplay.set(t, (i, fr, tt) => {
        const j = Math.min(i + 1, q.length - 1); // API: [w, x, y, z], body to space
        qa.set(q[i][1], q[i][2], q[i][3], q[i][0]); qb.set(q[j][1], q[j][2], q[j][3], q[j][0]);
        body.quaternion.slerpQuaternions(qa, qb, fr);
        const wb = om[i].map((x, k) => x + (om[j][k] - x) * fr), ws = new THREE.Vector3(...wb).applyQuaternion(body.quaternion);
        const len = 1.2 * Math.hypot(...wb) / w0n;
        if (len > 0) { wArrow.setDirection(ws.clone().normalize()); wArrow.setLength(len, 0.15, 0.07); wTag.position.copy(ws.normalize().multiplyScalar(len * 1.1)); }
        const parts = wb.map((x, k) => 0.5 * I[k] * x * x);
        energyBars(dzEnergy, [['½I₁ω₁²', parts[0], '#c92a2a'], ['½I₂ω₂²', parts[1], '#2b8a3e'], ['½I₃ω₃²', parts[2], '#1864ab'],
          ['T = sum', parts[0] + parts[1] + parts[2], '#111']], T0, 'the kinetic energy by principal axis');
        dzEnergy.dataset.parts = JSON.stringify(parts);
        put(dzVec, el('strong', {}, 'On the body: '), el('span', {class: 'c2'}, `ω = ${fmt(Math.hypot(...wb), 4)} rad/s`),
          ' (green; in the body (', wb.map(x => fmt(x, 3)).join(', '), ') rad/s), L fixed in space (grey): ω wanders round L as the body flips.');
        DV.render();
        tCur = tt; if (Xs) { cursor.setAttribute('x1', Xs(tt)); cursor.setAttribute('x2', Xs(tt)); }
      });
    });
    drun();
  },
};

// The top at release seen from the side: its axis at θ0 from the vertical from the pivot, the axis' end a
// handle moved round the pivot (arrow keys 0.05 rad, Shift 0.5); beside it the spin ψ̇ on a bar from −200 to
// 200 rad/s, a handle moved up and down (5 rad/s, Shift 50). onMove(θ0 or null, ψ̇ or null, done).
function topDial(root, theta, psi, onMove) {
  const W = 300, H = 190, px = 90, py = 165, L = 130;
  put(root); root.setAttribute('viewBox', `0 0 ${W} ${H}`);
  const th = Number.isFinite(theta) ? Math.min(Math.PI, Math.max(0, theta)) : 0.5, ps = Number.isFinite(psi) ? psi : 60;
  const X = (x) => px + L * x, Y = (y) => py - L * y;
  X.invert = (p) => (p - px) / L; Y.invert = (p) => (py - p) / L;
  const tip = [Math.sin(th), Math.cos(th)];
  const thetaOf = (x, y) => Math.min(Math.PI - 0.01, Math.max(0.01, Math.round(Math.atan2(Math.max(0, x), y) * 100) / 100));
  add(root, svg('line', {x1: 10, y1: py, x2: 190, y2: py, stroke: '#555', 'stroke-width': 2}),
    svg('line', {x1: px, y1: py, x2: px, y2: py - L - 10, stroke: '#999', 'stroke-dasharray': '4 4'}),
    svg('path', {d: `M ${px} ${py - 40} A 40 40 0 0 1 ${px + 40 * tip[0]} ${py - 40 * tip[1]}`, fill: 'none', stroke: '#1864ab', 'stroke-width': 2}),
    svg('line', {x1: px, y1: py, x2: X(tip[0]), y2: Y(tip[1]), stroke: '#1864ab', 'stroke-width': 5}),
    svg('text', {x: 8, y: 16, 'font-size': 14, fill: '#1864ab', 'font-weight': 700}, `θ0 = ${fmt(th, 3)} rad (${fmt(th * 180 / Math.PI, 3)}°)`),
    handle(root, {id: 'top-tilt', X, Y, at: tip, color: '#1864ab', label: 'the top\'s tilt θ0 (its axis)',
      text: (x, y) => `tilt θ0 = ${fmt(thetaOf(x, y), 3)} rad from the vertical`,
      nudge: (sign, big, at) => { const t = Math.min(Math.PI - 0.01, Math.max(0.01, thetaOf(at[0], at[1]) + sign * (big ? 0.5 : 0.05)));
        return [Math.sin(t), Math.cos(t)]; },
      onMove: (x, y, done) => onMove(thetaOf(x, y), null, done)}));
  // the spin bar: y from −200 (bottom) to 200 rad/s (top)
  const bx = 250, b0 = 175, b1 = 25, S = (v) => b0 + (v + 200) / 400 * (b1 - b0);
  const SX = () => bx; SX.invert = () => 0;
  const SY = (v) => S(v); SY.invert = (p) => (p - b0) / (b1 - b0) * 400 - 200;
  const spinOf = (v) => Math.max(-200, Math.min(200, Math.round(v)));
  add(root, svg('line', {x1: bx, y1: b0, x2: bx, y2: b1, stroke: '#555', 'stroke-width': 3}),
    svg('line', {x1: bx - 6, y1: S(0), x2: bx + 6, y2: S(0), stroke: '#555', 'stroke-width': 2}),
    svg('text', {x: bx - 10, y: S(0) + 4, 'font-size': 11, 'text-anchor': 'end', fill: '#444'}, '0'),
    svg('text', {x: bx - 10, y: b1 + 4, 'font-size': 11, 'text-anchor': 'end', fill: '#444'}, '200'),
    svg('text', {x: bx - 10, y: b0 + 4, 'font-size': 11, 'text-anchor': 'end', fill: '#444'}, '−200'),
    svg('text', {x: W - 4, y: 16, 'font-size': 14, fill: '#5c3b00', 'font-weight': 700, 'text-anchor': 'end'}, `ψ̇ = ${fmt(ps, 4)} rad/s`),
    handle(root, {id: 'top-spin', X: SX, Y: SY, at: [0, ps], axes: 'y', step: [0, 5], color: '#5c3b00', label: 'the top\'s spin ψ̇',
      text: (x, y) => `spin ψ̇ = ${fmt(spinOf(y), 4)} rad/s`, onMove: (x, y, done) => onMove(null, spinOf(y), done)}));
}
