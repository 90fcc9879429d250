// Oscillations lab: coupled oscillations (POST /v1/coupled-oscillations) — a
// chain of masses and springs, the double pendulum, two pendulums joined by a
// spring, or any mass and stiffness matrices: the normal modes (frequencies,
// mass-normalised shapes), and the motion from q(0), q̇(0) as the sum of the
// modes, animated (the API's exact samples, nothing integrated here) with the
// kinetic and potential energy ½q̇ᵀMq̇ and ½qᵀKq as bars and q(t) growing.
// "Start in mode j" sets q(0) along one mode: the system then swings in it alone.
import {el, svg, put, add, field, val, fmt, num, amount, labLayout, runner, examplePicker, linePlot, notesBox, relWords} from '../lib.js';
import {player, lerp} from '../anim.js';
import {energyBars} from '../draw.js';
import {handle, rerun} from '../handles.js';

const OP = '/v1/coupled-oscillations';
const SAMPLES = 241;
const BUILTIN = [
  {title: 'Three equal masses between walls: ω_j = 2√(k/m) sin(jπ/8)', operation: OP,
   request: {system: {name: 'spring_chain', masses: [1, 1, 1], springs: [1, 1, 1, 1]}, initial: {q: [0.1, 0, 0]}}, tEnd: 30},
  {title: 'Double pendulum, equal bobs and rods: ω² = (2 ∓ √2) g/l', operation: OP,
   request: {system: {name: 'double_pendulum', m1: 1, m2: 1, l1: 1, l2: 1}, initial: {q: [0.1, 0]}}, tEnd: 10},
  {title: 'Two pendulums joined by a spring: beats', operation: OP,
   request: {system: {name: 'coupled_pendulums', mass: 0.5, length: 1, k: 0.2}, initial: {q: [0.1, 0]}}, tEnd: 60},
  {title: 'Two free masses on a spring: a zero mode (the chain moves off)', operation: OP,
   request: {system: {name: 'spring_chain', masses: [1, 2], springs: [3], walls: 'none'}, initial: {q: [0.1, 0], qdot: [0.05, 0]}}, tEnd: 12},
];
// the form holds the set-ups and matrices up to 12 coordinates (a picture a student can read)
const fits = (ex) => ex.request && ex.request.system && ['spring_chain', 'double_pendulum', 'coupled_pendulums', 'matrices'].includes(ex.request.system.name) &&
  (!ex.request.system.masses || ex.request.system.masses.length <= 12) && (!ex.request.system.mass_matrix || ex.request.system.mass_matrix.length <= 12);
const NAMES = [['spring_chain', 'masses and springs in a line'], ['double_pendulum', 'double pendulum'],
  ['coupled_pendulums', 'two pendulums joined by a spring'], ['matrices', 'mass and stiffness matrices']];
const COLORS = ['#c92a2a', '#1864ab', '#2b8a3e', '#a65300', '#862e9c', '#0b7285', '#5c940d', '#a61e4d', '#364fc7', '#495057', '#d9480f', '#087f5b'];
// "1, 2 3" -> [1, 2, 3]; an entry that is not a number is the lab's own error on that field, in words
// (sent, it would come back as "null" at /…/1: "masses is empty" for "1, foo, 1")
function list(s, pointer, what) {
  const words = s.trim() === '' ? [] : s.trim().split(/[\s,]+/);
  const bad = words.findIndex(x => !Number.isFinite(Number(x)));
  if (bad >= 0) throw {problem: {title: 'Not a number', status: 422, errors: [{pointer,
    detail: `“${words[bad].slice(0, 20)}” (${what} ${bad + 1}) is not a number: give numbers separated by commas.`}]}};
  return words.map(Number);
}
const matrix = (s, pointer) => s.trim() === '' ? [] : s.split(';').map((r, i) => list(r, pointer, `row ${i + 1}, entry`));
const show = (a) => a.map(x => fmt(x)).join(', ');
const showM = (m) => m.map(r => show(r)).join('; ');

export default {
  id: 'oscillations', title: 'Oscillations',
  mount(main) {
    const L = labLayout(main, {title: 'Coupled oscillations and normal modes',
      intro: 'Masses joined by springs, or pendulums, each obeying M q̈ + K q = 0 near equilibrium. mechd solves K v = ω² M v for the ' +
             'normal modes: in each, every coordinate swings at one frequency ω with a fixed shape v. Any motion is a sum of them: ' +
             'q(t) = Σ v_k (a_k cos ω_k t + (b_k/ω_k) sin ω_k t).'});
    const sys = field({label: 'System', pointer: '/system/name', value: 'spring_chain', options: NAMES, id: 'osc-system'});
    const f = {
      masses: field({label: 'masses', pointer: '/system/masses', value: '1, 1, 1', type: 'text', unit: 'kg', id: 'osc-masses', help: 'left to right'}),
      springs: field({label: 'springs', pointer: '/system/springs', value: '1, 1, 1, 1', type: 'text', unit: 'N/m', id: 'osc-springs',
        help: 'wall, between the masses, wall'}),
      walls: field({label: 'walls', pointer: '/system/walls', value: 'both', id: 'osc-walls',
        options: [['both', 'at both ends'], ['left', 'left only'], ['right', 'right only'], ['none', 'none (a free chain)']]}),
      m1: field({label: 'upper bob m₁', pointer: '/system/m1', value: 1, unit: 'kg', id: 'osc-m1'}),
      m2: field({label: 'lower bob m₂', pointer: '/system/m2', value: 1, unit: 'kg', id: 'osc-m2'}),
      l1: field({label: 'upper rod l₁', pointer: '/system/l1', value: 1, unit: 'm', id: 'osc-l1'}),
      l2: field({label: 'lower rod l₂', pointer: '/system/l2', value: 1, unit: 'm', id: 'osc-l2'}),
      mass: field({label: 'each bob', pointer: '/system/mass', value: 0.5, unit: 'kg', id: 'osc-mass'}),
      length: field({label: 'each rod', pointer: '/system/length', value: 1, unit: 'm', id: 'osc-length'}),
      k: field({label: 'spring k', pointer: '/system/k', value: 0.2, unit: 'N/m', id: 'osc-k'}),
      attach: field({label: 'spring fixed at', pointer: '/system/attach', value: '', unit: 'm', id: 'osc-attach', help: 'from the pivots; empty: at the bobs'}),
      M: field({label: 'M (rows separated by ;)', pointer: '/system/mass_matrix', value: '2, 0; 0, 1', type: 'text', id: 'osc-M'}),
      K: field({label: 'K (rows separated by ;)', pointer: '/system/stiffness_matrix', value: '6, -2; -2, 4', type: 'text', id: 'osc-K'}),
    };
    const groups = {
      spring_chain: el('fieldset', {}, el('legend', {}, 'The chain'), f.masses.wrap, f.springs.wrap, f.walls.wrap),
      double_pendulum: el('fieldset', {}, el('legend', {}, 'The double pendulum (g = 9.80665 m/s²)'), f.m1.wrap, f.m2.wrap, f.l1.wrap, f.l2.wrap),
      coupled_pendulums: el('fieldset', {}, el('legend', {}, 'Two equal pendulums and a spring (g = 9.80665 m/s²)'), f.mass.wrap, f.length.wrap, f.k.wrap, f.attach.wrap),
      matrices: el('fieldset', {}, el('legend', {}, 'M q̈ + K q = 0'), f.M.wrap, f.K.wrap,
        el('p', {class: 'muted'}, 'M symmetric and positive definite (kg), K symmetric (N/m); a K that is not positive gives unstable modes.')),
    };
    const q0 = field({label: 'q(0)', pointer: '/initial/q', value: '0.1, 0, 0', type: 'text', id: 'osc-q', help: 'm (a chain) or rad (pendulums)'});
    const qd0 = field({label: 'q̇(0)', pointer: '/initial/qdot', value: '', type: 'text', id: 'osc-qdot', help: 'empty: all at rest'});
    const tEnd = field({label: 'duration', pointer: '/initial/times', value: 30, unit: 's', id: 'osc-tend'});
    const showGroup = () => { for (const [k, g] of Object.entries(groups)) g.hidden = k !== sys.input.value; };
    sys.input.addEventListener('change', showGroup);
    add(L.form, examplePicker([OP], BUILTIN, (ex) => {
      const s = ex.request.system, ini = ex.request.initial || {};
      sys.input.value = s.name; showGroup();
      if (s.name === 'spring_chain') { f.masses.input.value = show(s.masses); f.springs.input.value = show(s.springs); f.walls.input.value = s.walls || 'both'; }
      if (s.name === 'double_pendulum') for (const k of ['m1', 'm2', 'l1', 'l2']) f[k].input.value = s[k];
      if (s.name === 'coupled_pendulums') { for (const k of ['mass', 'length', 'k']) f[k].input.value = s[k]; f.attach.input.value = s.attach ?? ''; }
      if (s.name === 'matrices') { f.M.input.value = showM(s.mass_matrix); f.K.input.value = showM(s.stiffness_matrix); }
      const n = s.masses ? s.masses.length : s.mass_matrix ? s.mass_matrix.length : 2;
      q0.input.value = show(Array.isArray(ini.q) ? ini.q : Array.from({length: n}, (_, i) => (i ? 0 : 0.1)));
      qd0.input.value = Array.isArray(ini.qdot) ? show(ini.qdot) : '';
      const ts = Array.isArray(ini.times) && ini.times.length > 1 ? ini.times[ini.times.length - 1] : null;
      tEnd.input.value = ex.tEnd || (ts > 0 ? ts : 20);
      run();
    }, {fits}), sys.wrap, Object.values(groups),
    el('fieldset', {}, el('legend', {}, 'Started from'), q0.wrap, qd0.wrap, tEnd.wrap),
    el('div', {class: 'buttons'}, el('button', {type: 'submit', id: 'osc-submit'}, 'Set it moving')));
    showGroup();

    // a group: the start of each coordinate is a handle in it (an image's children would be hidden from assistive technology)
    const scene = svg('svg', {class: 'plot', id: 'osc-scene', role: 'group', 'aria-label': 'the system moving; drag a ring to set where it starts'});
    const energy = svg('svg', {class: 'plot dial energy', id: 'osc-energy', role: 'img', 'aria-label': 'energy bars'});
    const qplot = svg('svg', {class: 'plot', id: 'osc-q-plot', role: 'img', 'aria-label': 'the coordinates against time'});
    const sceneNote = el('p', {class: 'muted', id: 'osc-scene-note'});
    const play = player({label: 'The oscillations', reverse: 'Backwards: no friction, so the same swings run back are a motion too (t → −t).'});
    add(L.figure, el('h3', {}, 'The motion: a sum of normal modes'), scene, play.root, sceneNote,
      el('h3', {}, 'Energy'), energy,
      el('p', {class: 'muted'}, 'Kinetic ½q̇ᵀMq̇ and potential ½qᵀKq from the API\'s samples and matrices: they trade as it swings, their sum stays level ',
        '(each mode keeps its own energy: no friction, no coupling between modes).'),
      el('h3', {}, 'q(t)'), qplot);
    const oscNotes = notesBox('osc-notes'); L.figure.after(oscNotes.box);

    const build = () => {
      const s = sys.input.value, system = {name: s};
      if (s === 'spring_chain') {
        system.masses = list(f.masses.input.value, '/system/masses', 'mass'); system.springs = list(f.springs.input.value, '/system/springs', 'spring');
        system.walls = f.walls.input.value;
      }
      if (s === 'double_pendulum') for (const k of ['m1', 'm2', 'l1', 'l2']) system[k] = val(f[k].input);
      if (s === 'coupled_pendulums') {
        for (const k of ['mass', 'length', 'k']) system[k] = val(f[k].input);
        if (f.attach.input.value.trim() !== '') system.attach = val(f.attach.input);
      }
      if (s === 'matrices') { system.mass_matrix = matrix(f.M.input.value, '/system/mass_matrix'); system.stiffness_matrix = matrix(f.K.input.value, '/system/stiffness_matrix'); }
      const T = val(tEnd.input), initial = {q: list(q0.input.value, '/initial/q', 'entry')};
      if (qd0.input.value.trim() !== '') initial.qdot = list(qd0.input.value, '/initial/qdot', 'entry');
      initial.times = Array.from({length: SAMPLES}, (_, i) => (i === SAMPLES - 1 ? T : T * i / (SAMPLES - 1)));
      return {system, initial};
    };
    let dragBig = null;
    const again = rerun(() => run(), 200);
    const run = runner(L, OP, build, (a, req) => {
      const modes = a.modes, n = a.coordinates.length, mo = a.motion;
      const startIn = (k) => { // q(0) along mode k, at the amplitude the start had (or 0.1), at rest
        const v = modes[k].vector, big = Math.max(...v.map(Math.abs)) || 1;
        const amp = Math.max(...(req.initial.q || []).map(x => Math.abs(x || 0)), 0) || 0.1;
        // (round-off next to zero, a node's 2·10⁻¹⁶, starts at 0)
        q0.input.value = show(v.map(x => (Math.abs(x) < 1e-12 * big ? 0 : Number((x * amp / big).toPrecision(6))))); qd0.input.value = '';
        q0.input.dispatchEvent(new Event('change', {bubbles: true}));
        run();
      };
      put(L.results, el('h3', {}, 'Normal modes'),
        el('table', {id: 'osc-modes'}, el('tr', {}, el('th', {}, 'mode'), el('th', {}, 'ω [rad/s]'), el('th', {}, 'period [s]'),
          el('th', {}, `shape v (${a.coordinates.join(', ')})`)),
        modes.map((m, k) => el('tr', {}, el('th', {}, String(k + 1)),
          el('td', {id: `osc-omega-${k}`, 'data-value': String(m.omega)}, m.kind === 'unstable' ? `grows at ${fmt(m.growth_rate, 5)}/s` : fmt(m.omega, 7)),
          el('td', {}, m.kind === 'oscillating' ? fmt(m.period, 5) : m.kind === 'zero' ? 'none (moves off)' : '—'),
          // round-off next to zero (a middle mass at rest, 2e-16) reads 0
          el('td', {class: 'vec'}, show(m.vector.map(x => (Math.abs(x) < 1e-12 * Math.max(...m.vector.map(Math.abs)) ? 0 : Number(x.toPrecision(4))))))))),
        el('div', {class: 'buttons', role: 'group', 'aria-label': 'Start in one mode'}, el('span', {}, 'Start in mode: '),
          modes.map((m, k) => el('button', {type: 'button', class: 'secondary small-btn', 'data-role': 'start-mode', id: `osc-start-${k}`,
            'aria-label': `Start in mode ${k + 1}`, onclick: () => startIn(k)}, String(k + 1)))),
        el('dl', {class: 'nums'},
          el('dt', {}, 'stable'), el('dd', {id: 'osc-stable'}, a.stable ? 'yes' : 'no: a mode grows'),
          a.degenerate ? [el('dt', {}, 'degenerate'), el('dd', {}, 'two or more modes share a frequency: any mix of them is a mode too')] : null,
          a.zero_modes ? [el('dt', {}, 'zero modes'), el('dd', {}, `${a.zero_modes} (the whole moves off at a steady speed)`)] : null,
          mo ? [el('dt', {}, 'energy'), num('osc-energy-total', mo.energy, 'J'),
            // round-off in a mode the start does not excite (10⁻¹⁷ beside 0.14) reads 0; data-value keeps the numbers
            el('dt', {}, 'modal amplitudes a_k'), el('dd', {id: 'osc-a', 'data-value': JSON.stringify(mo.modal_position)},
              show(mo.modal_position.map(x => (Math.abs(x) < 1e-12 * Math.max(...mo.modal_position.map(Math.abs)) ? 0 : Number(x.toPrecision(5)))))),
            el('dt', {}, 'energy in each mode'), el('dd', {id: 'osc-mode-energy'},
              mo.mode_energies.map(x => amount(Math.abs(x) < 1e-24 * Math.abs(mo.energy) ? 0 : x, 'J')).join(', '))] : null),
        el('p', {class: 'muted'}, 'Shapes are mass-normalised (vᵀMv = 1), their largest entry positive.'));
      teach(oscNotes, a, req);
      if (!mo || !mo.samples.length) { put(scene); put(energy); put(qplot); return; }
      const S = mo.samples, ts = S.map(s => s.t), M = a.mass_matrix, K = a.stiffness_matrix;
      const quad = (A, x) => A.reduce((s, r, i) => s + x[i] * r.reduce((t, v, j) => t + v * x[j], 0), 0) / 2;
      const E0 = quad(M, S[0].qdot) + quad(K, S[0].q);
      linePlot(qplot, a.coordinates.map((c, i) => ({points: S.map(s => [s.t, s.q[i]]), label: c, t: ts, color: COLORS[i % COLORS.length]})),
        {xlabel: 't [s]', ylabel: a.system === 'spring_chain' ? 'x [m]' : a.system === 'matrices' ? 'q' : 'θ [rad]', name: 'oscillations-q', legend: 'below'});
      const drawScene = sceneFor(scene, a, S, dragBig, req.system);
      put(sceneNote, drawScene.note);
      // the start, dragged: q(0) in the form, asked again (the scale kept while the handle is held)
      startHandles(scene, a, drawScene, req.initial.q, (i, v, done) => {
        const q = req.initial.q.slice(); q[i] = v;
        q0.input.value = show(q);
        dragBig = done ? null : drawScene.big; again(done);
      });
      play.set(ts, (i, fr) => {
        const j = Math.min(i + 1, S.length - 1), q = lerp(S[i].q, S[j].q, fr), qd = lerp(S[i].qdot, S[j].qdot, fr);
        drawScene.at(q);
        const T = quad(M, qd), U = quad(K, q);
        energyBars(energy, [['½q̇ᵀMq̇', T, '#1864ab'], ['½qᵀKq', U, '#a65300'], ['sum', T + U, '#111']], Math.abs(E0) || 1, 'energy');
        energy.dataset.energy = JSON.stringify({T, U});
      }, {grow: [qplot]});
    });
    run();
  },
};

// "What the notes say" (the notes have no chapter on normal modes: the standard results are cited):
// the frequencies from a closed form where one applies — equal masses and springs between two walls,
// ω_j = 2√(k/m) sin(jπ/(2(n + 1))); any two coordinates, the roots of det(K − ω²M) = 0 — else the motion
// at the end as the sum of the modes, computed here from the API's modes and modal amplitudes.
function teach(box, a, req) {
  const s = req.system, n = a.coordinates.length, om = a.modes.map(m => m.omega);
  const equalChain = s.name === 'spring_chain' && (s.walls || 'both') === 'both' && n >= 1 &&
    s.masses.every(m => m === s.masses[0]) && s.springs.every(k => k === s.springs[0]);
  if (equalChain && om.every(Number.isFinite)) {
    const w0 = Math.sqrt(s.springs[0] / s.masses[0]), want = om.map((_, j) => 2 * w0 * Math.sin((j + 1) * Math.PI / (2 * (n + 1))));
    const d = om.map((w, j) => Math.abs(w - want[j])), worst = d.indexOf(Math.max(...d));
    box.update({section: 'LL 23', cite: 'Landau & Lifshitz, Mechanics §23', heading: 'Small oscillations: a chain of equal masses and springs',
      formula: ['ω', el('sub', {}, 'j'), ' = 2 √(k/m) sin(jπ / 2(n + 1)),  v', el('sub', {}, 'ij'), ' ∝ sin(ijπ / (n + 1))'],
      what: 'the closed form', formulaValue: want[worst], apiValue: om[worst], unit: 'rad/s',
      how: `Mode ${worst + 1} of ${n} (the largest difference of the ${n}): the formula from k = ${fmt(s.springs[0])} N/m and m = ${fmt(s.masses[0])} kg ` +
        'against the API\'s root of K v = ω² M v.', sourceText: 'computed in this page from your inputs',
      note: 'The course notes meet coupled oscillators only in passing (the free symmetric top\'s ω₁, ω₂, §2.8); normal modes are in ' +
        'every mechanics text (Landau & Lifshitz §23, Goldstein ch. 6, Taylor ch. 11).'});
    return;
  }
  if (n === 2 && om.every(Number.isFinite) && a.stable) {
    // det(K − ω²M) = 0: det M ω⁴ − (M11 K22 + M22 K11 − 2 M12 K12) ω² + det K = 0, its roots taken without cancellation
    const [M, K] = [a.mass_matrix, a.stiffness_matrix];
    const A = M[0][0] * M[1][1] - M[0][1] * M[1][0], B = -(M[0][0] * K[1][1] + M[1][1] * K[0][0] - M[0][1] * K[1][0] - M[1][0] * K[0][1]);
    const C = K[0][0] * K[1][1] - K[0][1] * K[1][0], disc = Math.max(0, B * B - 4 * A * C), qq = -0.5 * (B + Math.sign(B || 1) * Math.sqrt(disc));
    const r = [qq / A, qq !== 0 ? C / qq : 0].sort((x, y) => x - y).map(x => Math.sqrt(Math.max(0, x)));
    const d = om.map((w, j) => Math.abs(w - r[j])), worst = d.indexOf(Math.max(...d));
    box.update({section: 'LL 23', cite: 'Landau & Lifshitz, Mechanics §23', heading: 'Small oscillations: two coordinates',
      formula: ['det(K − ω²M) = 0:  (det M) ω⁴ − (M₁₁K₂₂ + M₂₂K₁₁ − 2M₁₂K₁₂) ω² + det K = 0'],
      what: 'the quadratic\'s root', formulaValue: r[worst], apiValue: om[worst], unit: 'rad/s',
      how: `Mode ${worst + 1}: the root of the characteristic equation from the API's M and K (${s.name === 'double_pendulum' ? 'equal bobs and rods give ω² = (2 ∓ √2) g/l' :
        s.name === 'coupled_pendulums' ? 'g/l in phase, g/l + 2k a²/(m l²) in antiphase' : 'any two coordinates'}) against the generalised eigenproblem's.`,
      sourceText: 'computed in this page from the API\'s M and K',
      note: 'The course notes meet coupled oscillators only in passing (the free symmetric top\'s ω₁, ω₂, §2.8); normal modes are in ' +
        'every mechanics text (Landau & Lifshitz §23, Goldstein ch. 6, Taylor ch. 11).'});
    return;
  }
  const mo = a.motion;
  if (!mo || !mo.samples.length) { put(box.box); return; }
  // q(t_end) = Σ_k v_k (a_k cos ω_k t + (b_k/ω_k) sin ω_k t) (a_k + b_k t for a zero mode, cosh/sinh for an unstable one)
  const last = mo.samples[mo.samples.length - 1], t = last.t;
  const sum = a.coordinates.map((_, i) => a.modes.reduce((acc, m, k) => {
    const ak = mo.modal_position[k], bk = mo.modal_velocity[k], w = m.kind === 'unstable' ? m.growth_rate : m.omega;
    const c = m.kind === 'zero' ? ak + bk * t : m.kind === 'unstable' ? ak * Math.cosh(w * t) + bk * Math.sinh(w * t) / w : ak * Math.cos(w * t) + bk * Math.sin(w * t) / w;
    return acc + m.vector[i] * c;
  }, 0));
  const abs = Math.max(...sum.map((x, i) => Math.abs(x - last.q[i]))), big = Math.max(...last.q.map(Math.abs)) || 1;
  box.update({section: 'LL 23', cite: 'Landau & Lifshitz, Mechanics §23', heading: 'The motion as a sum of normal modes',
    formula: ['q(t) = Σ', el('sub', {}, 'k'), ' v', el('sub', {}, 'k'), ' (a', el('sub', {}, 'k'), ' cos ω', el('sub', {}, 'k'), 't + (b', el('sub', {}, 'k'),
      '/ω', el('sub', {}, 'k'), ') sin ω', el('sub', {}, 'k'), 't),  a', el('sub', {}, 'k'), ' = v', el('sub', {}, 'k'), 'ᵀM q(0),  b', el('sub', {}, 'k'),
      ' = v', el('sub', {}, 'k'), 'ᵀM q̇(0)'],
    what: 'the sum of the modes', formulaShown: show(sum.map(x => Number(x.toPrecision(8)))), apiShown: show(last.q.map(x => Number(x.toPrecision(8)))),
    abs, rel: abs / big, unit: '', how: `q at the end (t = ${fmt(t)} s), summed in this page from the API's modes and amplitudes, against the API's sample.`,
    sourceText: 'computed in this page from the API\'s modes',
    note: 'The course notes meet coupled oscillators only in passing (the free symmetric top\'s ω₁, ω₂, §2.8).'});
}

// The system drawn at q: a chain (blocks and zig-zag springs between walls, the displacements drawn large,
// the factor said), pendulums (rods and bobs, the angles drawn true unless tiny), or bars for matrices.
// Each returns {note, at(q), place(i, q) -> [x, y], value(i, x, y, q) -> q_i}: where coordinate i's start handle
// sits for the start q, and the value a handle dragged to (x, y) gives it (picture units). big: the scale
// (the largest |q| of the run), kept while a handle is dragged.
function sceneFor(root, a, S, keep, sysReq) {
  const W = 640, H = 230, n = a.coordinates.length, sys = a.system;
  put(root); root.setAttribute('viewBox', `0 0 ${W} ${H}`);
  const big = keep || Math.max(...S.flatMap(s => s.q.map(Math.abs)), 1e-300);
  const g = svg('g', {id: 'osc-moving'}); add(root, g);
  const zig = (x1, y1, x2, y2) => { // a spring: a zig-zag of 8 teeth
    const pts = [[x1, y1]], L = Math.hypot(x2 - x1, y2 - y1) || 1, ux = (x2 - x1) / L, uy = (y2 - y1) / L;
    for (let k = 1; k < 16; k++) { const s = k / 16, side = k % 2 ? 7 : -7; pts.push([x1 + (x2 - x1) * s - uy * side, y1 + (y2 - y1) * s + ux * side]); }
    pts.push([x2, y2]);
    return svg('polyline', {points: pts.map(p => p.join(',')).join(' '), fill: 'none', stroke: '#555', 'stroke-width': 2});
  };
  if (sys === 'spring_chain') {
    const gap = (W - 40) / (n + 1), y = H / 2, k = 0.35 * gap / big, box = Math.min(30, gap * 0.5), wl = 20, wr = W - 20;
    const wantL = hasWall(a, 'left'), wantR = hasWall(a, 'right');
    add(root, svg('rect', {x: wl - 10, y: y - 40, width: 10, height: 80, fill: '#adb5bd'}), svg('rect', {x: wr, y: y - 40, width: 10, height: 80, fill: '#adb5bd'}));
    return {big, note: `Displacements drawn large: the largest of the run (${amount(big, 'm')}) is drawn a third of the spacing between the masses. ` +
      'Grey: the walls (a spring to a wall is drawn only where the chain has one). The rings below are where the masses start: drag one.',
    place: (i, q) => [20 + gap * (i + 1) + k * q[i], y + 48], value: (i, x) => (x - 20 - gap * (i + 1)) / k,
    at: (q) => {
      const xs = q.map((x, i) => 20 + gap * (i + 1) + k * x);
      put(g, wantL ? zig(wl, y, xs[0] - box / 2, y) : null,
        xs.slice(1).map((x, i) => zig(xs[i] + box / 2, y, x - box / 2, y)),
        wantR ? zig(xs[n - 1] + box / 2, y, wr, y) : null,
        xs.map((x, i) => svg('rect', {x: x - box / 2, y: y - box / 2, width: box, height: box, fill: COLORS[i % COLORS.length], 'data-x': String(q[i])})));
      root.setAttribute('aria-label', 'the chain: displacements ' + q.map(x => amount(x, 'm')).join(', '));
    }};
  }
  if (sys === 'double_pendulum' || sys === 'coupled_pendulums') {
    const ex = big < 0.35 ? 0.35 / big : 1; // tiny angles drawn larger, said
    const note = ex > 1 ? `Angles drawn ×${fmt(ex, 3)} (the largest, ${fmt(big * 180 / Math.PI, 3)}°, drawn at 20°).` : 'Angles drawn true.';
    if (sys === 'double_pendulum') {
      // the rods to scale with each other, 170 units together
      const l1 = sysReq.l1 > 0 ? sysReq.l1 : 1, l2 = sysReq.l2 > 0 ? sysReq.l2 : 1, px = W / 2, py = 24, L1 = 170 * l1 / (l1 + l2), L2 = 170 * l2 / (l1 + l2);
      const bob1 = (q) => [px + L1 * Math.sin(q[0] * ex), py + L1 * Math.cos(q[0] * ex)];
      return {big, note: note + ' The rings are where the bobs start: drag one round its rod\'s pivot.',
        place: (i, q) => { const b = bob1(q); return i === 0 ? b : [b[0] + L2 * Math.sin(q[1] * ex), b[1] + L2 * Math.cos(q[1] * ex)]; },
        value: (i, x, y, q) => { const o = i === 0 ? [px, py] : bob1(q); return Math.atan2(x - o[0], y - o[1]) / ex; },
        at: (q) => {
        const t1 = q[0] * ex, t2 = q[1] * ex, x1 = px + L1 * Math.sin(t1), y1 = py + L1 * Math.cos(t1), x2 = x1 + L2 * Math.sin(t2), y2 = y1 + L2 * Math.cos(t2);
        put(g, svg('line', {x1: px - 40, y1: py, x2: px + 40, y2: py, stroke: '#555', 'stroke-width': 3}),
          svg('line', {x1: px, y1: py, x2: x1, y2: y1, stroke: '#333', 'stroke-width': 3}), svg('line', {x1, y1, x2, y2, stroke: '#333', 'stroke-width': 3}),
          svg('circle', {cx: x1, cy: y1, r: 11, fill: COLORS[0]}), svg('circle', {cx: x2, cy: y2, r: 11, fill: COLORS[1]}));
        root.setAttribute('aria-label', `the double pendulum: θ1 = ${fmt(q[0] * 180 / Math.PI, 3)}°, θ2 = ${fmt(q[1] * 180 / Math.PI, 3)}°`);
      }};
    }
    const L = 170, py = 24, p1 = W / 2 - 90, p2 = W / 2 + 90;
    return {big, note: note + ' The spring (grey) joins the rods. The rings are where the bobs start: drag one round its pivot.',
      place: (i, q) => [(i ? p2 : p1) + L * Math.sin(q[i] * ex), py + L * Math.cos(q[i] * ex)],
      value: (i, x, y) => Math.atan2(x - (i ? p2 : p1), y - py) / ex,
      at: (q) => {
      const t1 = q[0] * ex, t2 = q[1] * ex, b1 = [p1 + L * Math.sin(t1), py + L * Math.cos(t1)], b2 = [p2 + L * Math.sin(t2), py + L * Math.cos(t2)];
      const fa = sysReq.attach > 0 && sysReq.length > 0 ? Math.min(1, sysReq.attach / sysReq.length) : 1, s1 = [p1 + fa * L * Math.sin(t1), py + fa * L * Math.cos(t1)], s2 = [p2 + fa * L * Math.sin(t2), py + fa * L * Math.cos(t2)];
      put(g, svg('line', {x1: p1 - 40, y1: py, x2: p2 + 40, y2: py, stroke: '#555', 'stroke-width': 3}),
        svg('line', {x1: p1, y1: py, x2: b1[0], y2: b1[1], stroke: '#333', 'stroke-width': 3}), svg('line', {x1: p2, y1: py, x2: b2[0], y2: b2[1], stroke: '#333', 'stroke-width': 3}),
        zig(s1[0], s1[1], s2[0], s2[1]),
        svg('circle', {cx: b1[0], cy: b1[1], r: 12, fill: COLORS[0]}), svg('circle', {cx: b2[0], cy: b2[1], r: 12, fill: COLORS[1]}));
      root.setAttribute('aria-label', `two pendulums: θ1 = ${fmt(q[0] * 180 / Math.PI, 3)}°, θ2 = ${fmt(q[1] * 180 / Math.PI, 3)}°`);
    }};
  }
  // matrices: one bar per coordinate, heights against the largest |q| of the run
  const w = Math.min(60, (W - 40) / n - 8), base = H / 2, k = (H / 2 - 20) / big;
  add(root, svg('line', {x1: 10, y1: base, x2: W - 10, y2: base, stroke: '#555'}));
  return {big, note: 'Each coordinate as a bar, against the largest value of the run; the rings are where each starts: drag one up or down.',
    place: (i, q) => [20 + (i + 0.5) * (W - 40) / n, base - k * q[i]], value: (i, x, y) => (base - y) / k,
    at: (q) => {
    put(g, q.map((x, i) => { const h = k * x, cx = 20 + (i + 0.5) * (W - 40) / n;
      return [svg('rect', {x: cx - w / 2, y: h >= 0 ? base - h : base, width: w, height: Math.abs(h), fill: COLORS[i % COLORS.length]}),
        svg('text', {x: cx, y: H - 6, 'font-size': 14, 'text-anchor': 'middle', fill: '#333'}, a.coordinates[i])]; }).flat());
    root.setAttribute('aria-label', 'the coordinates: ' + q.map(x => fmt(x, 4)).join(', '));
  }};
}
// A chain's wall at that end: a spring to it makes the end row of K larger than the springs to neighbours.
// K_00 = k_wall + k_01 with a left wall, k_01 alone without: read from K (k_01 = −K_01).
function hasWall(a, end) {
  const K = a.stiffness_matrix, n = K.length;
  if (n === 1) return K[0][0] > 0; // one mass: both walls drawn when it is held at all
  const i = end === 'left' ? 0 : n - 1, j = end === 'left' ? 1 : n - 2;
  return K[i][i] + K[i][j] > 1e-12 * Math.abs(K[i][i]);
}

// The start handles: one ring per coordinate at its q(0) (sceneFor's place), dragged or moved by the arrow keys
// (a tenth of the run's scale, rounded; Shift ten times): onMove(i, q_i, done).
function startHandles(root, a, sc, q0, onMove) {
  const id = (x) => x; id.invert = id;
  const step = 10 ** Math.floor(Math.log10(sc.big)) / 10, unit = a.system === 'spring_chain' ? 'm' : a.system === 'matrices' ? '' : 'rad';
  const round = (v) => Number((Math.round(v / step * 10) * step / 10).toPrecision(6));
  const g = svg('g', {id: 'osc-start'});
  a.coordinates.forEach((c, i) => {
    if (!Number.isFinite(q0[i])) return;
    const say = (v) => `${c} starts at ${fmt(v, 4)}${unit ? ' ' + unit : ''}` + (unit === 'rad' ? ` (${fmt(v * 180 / Math.PI, 3)}°)` : '');
    add(g, handle(root, {id: `osc-start-q${i}`, X: id, Y: id, at: sc.place(i, q0), color: COLORS[i % COLORS.length], label: `where ${c} starts`,
      text: (x, y) => say(sc.value(i, x, y, q0)),
      nudge: (sign, big, at) => { const v = round(sc.value(i, at[0], at[1], q0) + sign * step * (big ? 10 : 1)); const q = q0.slice(); q[i] = v; return sc.place(i, q); },
      onMove: (x, y, done) => onMove(i, round(sc.value(i, x, y, q0)), done)}));
  });
  add(root, g);
}
