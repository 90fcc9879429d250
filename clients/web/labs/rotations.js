// Rotations lab (chapter 0 and §2.6): a body turned by z-x-z Euler angles set
// with sliders, drawn in 3-D with its own axes; its rotation matrix,
// quaternion and axis-angle from POST /v1/rotation/convert, with the notes'
// R = Rψ Rθ Rφ entries beside the API's; gimbal lock at θ = 0 (and 180°) said
// in words; and two turns composed in both orders (POST /v1/batch of two
// /v1/rotation/compose) to show that rotations do not commute.
import {el, put, add, fmt, num, api, labLayout, labSection, runner, examplePicker, notesBox} from '../lib.js';
import {player} from '../anim.js';
import {THREE, view3d, axesArrows, sceneAxes} from '../view3d.js';

const D = Math.PI / 180;
const st = {phi: 30, theta: 40, psi: 20, a: ['x', 90], b: ['z', 90]};
const BUILTIN = [
  {title: 'Euler angles φ = 30°, θ = 40°, ψ = 20°', operation: '/v1/rotation/convert', section: '2.6 Euler Angles',
   request: {euler_zxz: [30 * D, 40 * D, 20 * D]}},
  {title: 'Gimbal lock: θ = 0, φ = 50°, ψ = 20° (only φ + ψ counts)', operation: '/v1/rotation/convert', section: '2.6 Euler Angles',
   request: {euler_zxz: [50 * D, 0, 20 * D]}},
];
const AXES = {x: [1, 0, 0], y: [0, 1, 0], z: [0, 0, 1]};
const deg = (r) => fmt(r / D, 4) + '°';

// the notes' passive z-x-z matrix R = Rψ Rθ Rφ, entry by entry (§2.6)
function notesMatrix(f, t, p) {
  const [cf, sf, ct, stt, cp, sp] = [Math.cos(f), Math.sin(f), Math.cos(t), Math.sin(t), Math.cos(p), Math.sin(p)];
  return [[cp * cf - ct * sf * sp, cp * sf + ct * cf * sp, sp * stt],
          [-sp * cf - ct * sf * cp, -sp * sf + ct * cf * cp, cp * stt],
          [stt * sf, -stt * cf, ct]];
}

const matrixTable = (id, m) => el('table', {id, class: 'matrix', 'aria-label': 'rotation matrix'},
  m.map((row, i) => el('tr', {}, row.map((v, j) => el('td', {id: `${id}-${i}${j}`, 'data-value': v}, fmt(Math.abs(v) < 5e-16 ? 0 : v, 5))))));

export default {
  id: 'rotations', title: 'Rotations',
  mount(main) {
    const L = labLayout(main, {title: 'Rotations and Euler angles',
      intro: 'Three turns make any orientation: φ about z, then θ about the new x (the line of nodes), then ψ about ' +
             'the new z. The grey axes stay put; the coloured ones are the body\'s. The rotation is passive, as in the ' +
             'notes: R turns the components of a vector from the fixed axes to the body\'s.'});
    // the 3-D body sits right under its sliders (on a phone too), the numbers beside
    const box3d = el('div', {class: 'view3d-box'});
    const turns = player({label: 'The three turns'});
    const stage = el('p', {id: 'rot-stage', class: 'muted', 'aria-live': 'off'});
    const figure = el('div', {class: 'rot-figure'}, box3d, turns.root, stage,
      el('p', {class: 'muted'}, el('span', {class: 'c1'}, 'red: body x′'), ', ', el('span', {class: 'c2'}, 'green: y′'), ', ',
        el('span', {class: 'c3'}, 'blue: z′'), '; grey: the fixed x, y, z. Drag (or focus and use the arrow keys) to turn the view.'));
    const sliders = {};
    const row = (name, sym, min, max) => {
      const id = 'rot-' + name, input = el('input', {type: 'range', min, max, step: 1, value: st[name], id, 'data-pointer': '/euler_zxz'});
      const out = el('output', {for: id, id: id + '-shown'}, st[name] + '°');
      input.addEventListener('input', () => { out.textContent = input.value + '°'; st[name] = Number(input.value); pending = null; run(); });
      sliders[name] = {input, out};
      return el('div', {class: 'figure-control'}, el('label', {for: id}, sym), input, out);
    };
    const setAngles = (f, t, p) => {
      for (const [k, v] of [['phi', f], ['theta', t], ['psi', p]]) {
        const d = Math.round(v / D * 100) / 100; st[k] = d; sliders[k].input.value = d; sliders[k].out.textContent = fmt(d, 5) + '°';
      }
    };
    let pending = null; // an example's own request, sent as it is (then the sliders follow its Euler angles)
    add(L.form, examplePicker(['/v1/rotation/convert', '/v1/rotation/compose'], BUILTIN, (ex) => {
      pending = ex; run();
    }, {fits: (ex) => ex.request && !ex.request.vectors}),
      row('phi', 'φ (about z)', -180, 180), row('theta', 'θ (about the line of nodes)', 0, 180), row('psi', 'ψ (about the body\'s z)', -180, 180),
      figure,
      el('div', {class: 'buttons'}, el('button', {type: 'submit', id: 'rot-submit'}, 'Turn'),
        el('button', {type: 'button', class: 'secondary', id: 'rot-lock', onclick: () => {
          sliders.theta.input.value = 0; sliders.theta.out.textContent = '0°'; st.theta = 0; pending = null; run();
        }}, 'θ = 0: gimbal lock')));
    const V = view3d(box3d, {label: 'The body turned by the Euler angles', id: 'rotations-view', extent: 1.3});
    const body = new THREE.Group();
    if (V.ok) {
      V.scene.add(sceneAxes(1.6));
      const hull = new THREE.Mesh(new THREE.BoxGeometry(1.6, 0.7, 0.22), new THREE.MeshStandardMaterial({color: 0x9aa6b5}));
      const nose = new THREE.Mesh(new THREE.ConeGeometry(0.25, 0.45, 24), new THREE.MeshStandardMaterial({color: 0xe67700}));
      nose.rotation.z = -Math.PI / 2; nose.position.x = 1.02;
      const fin = new THREE.Mesh(new THREE.BoxGeometry(0.4, 0.05, 0.45), new THREE.MeshStandardMaterial({color: 0x5c7cfa}));
      fin.position.set(-0.6, 0, 0.32);
      body.add(hull, nose, fin, new THREE.LineSegments(new THREE.EdgesGeometry(hull.geometry), new THREE.LineBasicMaterial({color: 0x333333})),
        axesArrows([[1, 0, 0], [0, 1, 0], [0, 0, 1]], [1.95, 1.3, 1.1], [0, 0, 0], undefined, false));
      body.matrixAutoUpdate = false;
      V.scene.add(body);
    }
    const orient = (R) => { // passive R: its rows are the body's axes in the fixed frame
      body.matrix.set(R[0][0], R[1][0], R[2][0], 0, R[0][1], R[1][1], R[2][1], 0, R[0][2], R[1][2], R[2][2], 0, 0, 0, 0, 1);
      body.matrixWorldNeedsUpdate = true; V.render();
      if (V.canvas) V.canvas.dataset.bodyX = R[0].map(v => v.toFixed(4)).join(',');
    };

    // Play the three turns one after the other: the body after φ, after φ and θ, and after all
    // three, each from POST /v1/rotation/convert (one /v1/batch); between two of them the
    // orientation turns along the shortest way (slerp), which is the turn about the
    // axis of that stage (z, the line of nodes, the body's z).
    let stageCtl = null, stageTimer = 0;
    const toQ = (R) => new THREE.Quaternion().setFromRotationMatrix(new THREE.Matrix4().set(
      R[0][0], R[1][0], R[2][0], 0, R[0][1], R[1][1], R[2][1], 0, R[0][2], R[1][2], R[2][2], 0, 0, 0, 0, 1));
    const names = ['φ about z', 'θ about the line of nodes (the new x)', 'ψ about the body\'s z'];
    const stages = ([f, t, p]) => {
      clearTimeout(stageTimer);
      stageTimer = setTimeout(async () => { // after the sliders rest a moment
        if (stageCtl) stageCtl.abort();
        const mine = stageCtl = new AbortController();
        const r = await api('/v1/batch', {operations: [[f, 0, 0], [f, t, 0], [f, t, p]].map(e => ({operation: '/v1/rotation/convert', request: {euler_zxz: e}}))},
          {signal: mine.signal});
        if (mine !== stageCtl || !r.ok || !r.body.results.every(x => x.status === 200)) return;
        const Rs = [[[1, 0, 0], [0, 1, 0], [0, 0, 1]], ...r.body.results.map(x => x.body.matrix)], Q = Rs.map(toQ);
        turns.set([0, 1, 2, 3], (i, fr) => {
          const j = Math.min(i + 1, 3), q = Q[i].clone().slerp(Q[j], fr), m = new THREE.Matrix4().makeRotationFromQuaternion(q).elements;
          // back to the passive R (rows = the body's axes) for orient(): R[i][k] = m's column i, row k
          orient([0, 1, 2].map(c => [m[4 * c], m[4 * c + 1], m[4 * c + 2]]));
          stage.textContent = i >= 3 || (i === 2 && fr >= 1) ? 'All three turns done: the orientation set by the sliders.'
            : `Turn ${i + 1} of 3: ${names[i]}, ${deg([f, t, p][i] * fr)} of ${deg([f, t, p][i])}.`;
        });
        turns.seek(3);
      }, 250);
    };

    const rotNotes = notesBox('rot-notes');
    const run = runner(L, () => (pending ? pending.operation : '/v1/rotation/convert'),
      () => (pending ? pending.request : {euler_zxz: [st.phi * D, st.theta * D, st.psi * D]}),
      (a, req) => {
        const from = pending; pending = null;
        const [f, t, p] = a.euler_zxz;
        if (from) setAngles(f, t, p);
        const asked = req.euler_zxz || [f, t, p];
        const N = notesMatrix(asked[0], asked[1], asked[2]);
        const diff = Math.max(...N.flatMap((r, i) => r.map((v, j) => Math.abs(v - a.matrix[i][j]))));
        const g = a.gimbal || {};
        const sum = g.combination === 'phi-psi' ? 'φ − ψ' : 'φ + ψ';
        const lock = a.gimbal_lock
          ? el('p', {class: 'note lock', id: 'rot-gimbal'}, el('strong', {}, 'Gimbal lock. '),
              `At θ = ${asked[1] > 1 ? '180°' : '0'} the first turn (φ about z) and the third (ψ about the body's z) are turns about the same axis, ` +
              `so φ and ψ do the same thing: only ${sum} = ${deg(g.value)} matters, and one degree of freedom is lost. ` +
              'Move the φ or the ψ slider: the body turns the same way about z. The API reports the angles as ' +
              `(${deg(f)}, ${deg(t)}, ${deg(p)}).`)
          : el('p', {class: 'muted', id: 'rot-gimbal'}, `No gimbal lock: θ is ${deg(g.lock_distance)} from the nearest lock ` +
              `(θ = 0 or 180°, where only ${sum} would count).`);
        put(L.results, el('h3', {}, 'Rotation matrix R = Rψ Rθ Rφ (passive)'), matrixTable('rot-matrix', a.matrix), lock,
          el('dl', {class: 'nums'},
            el('dt', {}, 'quaternion (w, x, y, z)'), el('dd', {id: 'rot-quat', 'data-value': a.quaternion.join(',')}, '(' + a.quaternion.map(v => fmt(v, 5)).join(', ') + ')'),
            el('dt', {}, 'axis'), el('dd', {id: 'rot-axis'}, '(' + a.axis_angle.axis.map(v => fmt(v, 4)).join(', ') + ')'),
            el('dt', {}, 'angle about it'), num('rot-angle', a.axis_angle.angle / D, '°')),
          rotNotes.box);
        // notes §2.6: R = Rψ Rθ Rφ multiplied out (the notes' matrix, its minus signs restored from the product)
        const show = (M) => `R₁₁ = ${fmt(M[0][0], 7)}, R₁₃ = ${fmt(M[0][2], 7)}, R₃₂ = ${fmt(M[2][1], 7)}`;
        rotNotes.update({section: '2.6', heading: 'Euler Angles',
          formula: ['R = R', el('sub', {}, 'ψ'), ' R', el('sub', {}, 'θ'), ' R', el('sub', {}, 'φ'), ' = ',
            el('table', {class: 'matrix formula-matrix', 'aria-label': 'the notes\' matrix'}, [
              ['cos ψ cos φ − cos θ sin φ sin ψ', 'cos ψ sin φ + cos θ cos φ sin ψ', 'sin ψ sin θ'],
              ['−sin ψ cos φ − cos θ sin φ cos ψ', '−sin ψ sin φ + cos θ cos φ cos ψ', 'cos ψ sin θ'],
              ['sin θ sin φ', '−sin θ cos φ', 'cos θ']].map(r => el('tr', {}, r.map(c => el('td', {}, c)))))],
          what: 'the notes\' matrix', formulaShown: show(N), apiShown: show(a.matrix), abs: diff, rel: diff,
          how: 'All nine entries by the formula (in this page, from the angles asked) against the API\'s matrix; the difference is ' +
            'the largest of the nine (entries are at most 1, so it is also the relative one).',
          note: 'The quaternion is (cos(α/2), n sin(α/2)) for the turn α about the axis n; a quaternion never locks, which is ' +
            'why attitude is integrated with one.'});
        orient(a.matrix);
        stages([f, t, p]);
      });
    run();

    // --- order matters ---
    const form = el('form', {novalidate: true, 'aria-label': 'Two turns inputs', id: 'order-form'});
    const pick = (k, i) => {
      const id = `order-${k}-${i ? 'angle' : 'axis'}`;
      return i ? el('input', {id, type: 'number', step: 'any', value: st[k][1], 'data-pointer': `/operations/0/request/rotations/${k === 'a' ? 0 : 1}/axis_angle/angle`, inputmode: 'decimal'})
        : el('select', {id, 'aria-label': `${k === 'a' ? 'First' : 'Second'} turn: axis`,
          'data-pointer': `/operations/0/request/rotations/${k === 'a' ? 0 : 1}/axis_angle/axis`},
          ['x', 'y', 'z'].map(n => el('option', {value: n, selected: st[k][0] === n}, n)));
    };
    const ctl = {a: [pick('a', 0), pick('a', 1)], b: [pick('b', 0), pick('b', 1)]};
    add(form, ['a', 'b'].map((k, n) => el('div', {class: 'field'}, el('label', {for: `order-${k}-angle`}, `${n ? 'Second' : 'First'} turn: about`),
      ctl[k][0], ctl[k][1], el('span', {class: 'unit'}, '°'))),
    el('div', {class: 'buttons'}, el('button', {type: 'submit', id: 'order-submit'}, 'Compose both ways')));
    const O = labSection(main, {title: 'Order matters: A then B is not B then A', form, id: 'order',
      intro: 'Two turns about fixed-size angles, applied in both orders (each about the body\'s moved axes, as in the notes). ' +
             'Finite rotations do not commute: the two products differ, unless both turns share an axis.'});
    const turn = (k) => ({axis_angle: {axis: AXES[ctl[k][0].value], angle: Number(ctl[k][1].value) * D}});
    const orun = runner(O, '/v1/batch', () => {
      st.a = [ctl.a[0].value, Number(ctl.a[1].value)]; st.b = [ctl.b[0].value, Number(ctl.b[1].value)];
      for (const k of ['a', 'b']) if (ctl[k][1].value.trim() === '' || !isFinite(Number(ctl[k][1].value))) throw new Error(`Give the ${k === 'a' ? 'first' : 'second'} angle in degrees.`);
      return {operations: [{operation: '/v1/rotation/compose', request: {rotations: [turn('a'), turn('b')]}},
        {operation: '/v1/rotation/compose', request: {rotations: [turn('b'), turn('a')]}}]};
    }, (a) => {
      const r = a.results || a.operations || [];
      const ans = r.map(x => x.answer || x.body || x.result);
      if (ans.length !== 2 || !ans.every(x => x && x.matrix)) { put(O.results, el('p', {class: 'problem'}, 'The server could not compose one of the orders.')); return false; }
      const [ab, ba] = ans;
      const d = Math.max(...ab.matrix.flatMap((row, i) => row.map((v, j) => Math.abs(v - ba.matrix[i][j]))));
      const name = (k) => `${st[k][1]}° about ${st[k][0]}`;
      const show = (x, lbl) => el('button', {type: 'button', class: 'secondary', onclick: () => {
        setAngles(...x.euler_zxz); run(); document.getElementById('rotations-view')?.scrollIntoView({block: 'nearest'});
      }}, lbl);
      put(O.results,
        el('div', {class: 'pair'},
          el('div', {}, el('h3', {}, `A then B: ${name('a')}, then ${name('b')}`), matrixTable('order-ab', ab.matrix), show(ab, 'Show A then B in 3-D')),
          el('div', {}, el('h3', {}, `B then A: ${name('b')}, then ${name('a')}`), matrixTable('order-ba', ba.matrix), show(ba, 'Show B then A in 3-D'))),
        el('p', {id: 'order-verdict', 'data-value': d}, d > 1e-12
          ? `The two orders differ: the largest entry differs by ${fmt(d, 4)}. The body's x′ axis ends along (${ab.matrix[0].map(v => fmt(Math.abs(v) < 5e-16 ? 0 : v, 3)).join(', ')}) one way ` +
            `and (${ba.matrix[0].map(v => fmt(Math.abs(v) < 5e-16 ? 0 : v, 3)).join(', ')}) the other.`
          : 'The two orders agree here (to 10⁻¹²): turns about one axis commute.'));
    });
    orun();
  },
};
