// Relativistic kinematics lab (§3.14, §3.16): two- and three-body decays
// (/v1/relativity/kinematics/decay) with the rest-frame momentum beside the
// notes' formula; Compton scattering drawn with the scattered photon and the
// recoiling electron (/v1/relativity/kinematics/compton) beside
// λ′ − λ = (h/mc)(1 − cos θ); and the Doppler shift of light with its colour
// before and after (/v1/relativity/doppler).
import {el, svg, put, add, field, val, fmt, num, labLayout, labSection, runner, examplePicker, plotSize, notesBox} from '../lib.js';

const D = Math.PI / 180;
const st = {parent: 'pi0', daughters: 'photon, photon', T: 200, E: 100, lambda: '', angle: 90, beta: 0.1, nm: 500};
const BUILTIN = [
  {title: 'π⁰ → γγ in flight (T = 200 MeV)', operation: '/v1/relativity/kinematics/decay', section: '3.16 Kinematics Problems in Electron Volts',
   request: {parent: {particle: 'pi0', kinetic_energy: 200}, daughters: ['photon', 'photon']}},
  {title: 'Green light from a source coming at β = 0.1 looks blue', operation: '/v1/relativity/doppler', section: '3.14 The Relativistic Doppler Effect',
   request: {source_velocity: {beta: [0.1, 0, 0]}, arrival_direction: [1, 0, 0], wavelength: 500e-9}},
];

// The colour of light of wavelength nm (380–750 nm), as CSS rgb(): the usual
// piecewise fit to the CIE curves, dimmed towards the ends of the eye's range.
export function lightColour(nm) {
  if (!(nm >= 380 && nm <= 750)) return null;
  let r = 0, g = 0, b = 0;
  if (nm < 440) { r = (440 - nm) / 60; b = 1; } else if (nm < 490) { g = (nm - 440) / 50; b = 1; }
  else if (nm < 510) { g = 1; b = (510 - nm) / 20; } else if (nm < 580) { r = (nm - 510) / 70; g = 1; }
  else if (nm < 645) { r = 1; g = (645 - nm) / 65; } else r = 1;
  const k = nm < 420 ? 0.3 + 0.7 * (nm - 380) / 40 : nm > 700 ? 0.3 + 0.7 * (750 - nm) / 50 : 1;
  const c = (x) => Math.round(255 * Math.pow(x * k, 0.8));
  return `rgb(${c(r)}, ${c(g)}, ${c(b)})`;
}
const band = (nm) => nm < 380 ? (nm < 10 ? 'X-ray' : 'ultraviolet') : nm > 750 ? (nm > 1e6 ? 'microwave or radio' : 'infrared') : null;
// a swatch of that colour (set through the CSSOM: the page's CSP allows no style attributes)
const swatch = (id, nm) => {
  const c = lightColour(nm);
  const box = el('span', {class: 'swatch' + (c ? '' : ' invisible'), id, 'data-colour': c || band(nm), role: 'img',
    'aria-label': c ? `the colour of ${fmt(nm, 4)} nm light` : `${band(nm)}: invisible`});
  if (c) box.style.background = c;
  return el('span', {class: 'light'}, box, ' ', `${fmt(nm, 4)} nm` + (c ? '' : ` (${band(nm)}: invisible)`));
};

export default {
  id: 'particles', title: 'Particles',
  mount(main) {
    const L = labLayout(main, {title: 'Relativistic kinematics: decays',
      intro: 'Energies, masses and momenta in MeV (c = 1). A particle decays at rest or in flight along +z; in its rest frame ' +
             'two daughters fly apart back to back with a fixed momentum, and the lab sees them boosted.'});
    const parent = field({label: 'Parent', pointer: '/parent/particle', value: st.parent, type: 'text', id: 'dk-parent',
      help: 'pi0, K+, neutron, muon, Lambda, Z …'});
    const daughters = field({label: 'Daughters', pointer: '/daughters', value: st.daughters, type: 'text', id: 'dk-daughters',
      help: 'two or three names (or masses in MeV), separated by commas'});
    const T = field({label: 'Parent\'s kinetic energy', pointer: '/parent/kinetic_energy', value: st.T, unit: 'MeV', id: 'dk-T', min: 0});
    let pendingDecay = null;
    // one picker for the lab's three sections
    add(L.form, examplePicker(['/v1/relativity/kinematics/decay', '/v1/relativity/kinematics/compton', '/v1/relativity/doppler'], BUILTIN, (ex) => {
      const r = ex.request;
      if (ex.operation === '/v1/relativity/kinematics/compton') {
        if (r.energy) { cE.input.value = r.energy * (r.energy_unit === 'MeV' || !r.energy_unit ? 1000 : r.energy_unit === 'keV' ? 1 : r.energy_unit === 'eV' ? 1e-3 : 1e3); cL.input.value = ''; }
        if (r.wavelength) { cL.input.value = r.wavelength * 1e12; cE.input.value = ''; }
        setAngle(r.angle_deg ?? (r.angle !== undefined ? r.angle / D : 90)); crun(); C.form.scrollIntoView({block: 'nearest'}); return;
      }
      if (ex.operation === '/v1/relativity/doppler') {
        const b = r.source_velocity && r.source_velocity.beta, dir = r.arrival_direction || [1, 0, 0];
        if (b) setBeta(b[0] * Math.sign(dir[0] || 1)); // the source's velocity along the light's path
        as.value = 0; aOut.textContent = '0°';
        if (r.wavelength) dL.input.value = r.wavelength * 1e9;
        drun(); Dp.form.scrollIntoView({block: 'nearest'}); return;
      }
      parent.input.value = r.parent.particle; daughters.input.value = r.daughters.join(', ');
      T.input.value = r.parent.kinetic_energy ?? 0;
      pendingDecay = (r.parent.energy !== undefined || r.parent.momentum !== undefined || r.parent.velocity !== undefined || r.energy_unit) ? r : null;
      run();
    }, {fits: (ex) => ex.operation !== '/v1/relativity/doppler' || (ex.request.source_velocity && ex.request.source_velocity.beta &&
      !ex.request.observer_velocity && Array.isArray(ex.request.arrival_direction) && !ex.request.arrival_direction[1] && !ex.request.arrival_direction[2])}),
    parent.wrap, daughters.wrap, T.wrap, el('div', {class: 'buttons'}, el('button', {type: 'submit', id: 'dk-submit'}, 'Decay')));
    const dkNotes = notesBox('dk-notes'), EV = {eV: 1, keV: 1e3, MeV: 1e6, GeV: 1e9, TeV: 1e12}; L.figure.after(dkNotes.box); // under the figure: the picture stays by the answer
    const run = runner(L, '/v1/relativity/kinematics/decay', () => {
      if (pendingDecay) return pendingDecay;
      const ds = daughters.input.value.split(',').map(s => s.trim()).filter(Boolean).map(s => (isFinite(Number(s)) ? Number(s) : s));
      const p = parent.input.value.trim();
      return {parent: {particle: isFinite(Number(p)) && p !== '' ? Number(p) : p, kinetic_energy: val(T.input)}, daughters: ds};
    }, (a, req) => {
      pendingDecay = null;
      const u = a.energy_unit, rf = a.rest_frame, two = rf && rf.energies && rf.energies.length === 2;
      const masses = rf ? rf.energies.map((e, i) => e - rf.kinetic_energies[i]) : [];
      const M = a.parent.mass;
      const notes = two ? Math.sqrt(Math.max(0, (M * M - (masses[0] + masses[1]) ** 2) * (M * M - (masses[0] - masses[1]) ** 2))) / (2 * M) : null;
      const items = [el('dt', {}, 'parent: γ, β'), el('dd', {id: 'dk-gamma', 'data-value': a.parent.gamma}, `${fmt(a.parent.gamma, 6)}, ${fmt(a.parent.beta, 6)}`),
        el('dt', {}, 'Q (mass released)'), num('dk-q', a.q_value, u)];
      if (two) items.push(el('dt', {}, 'rest frame: each momentum'), num('dk-pstar', rf.momentum, u + '/c'),
        ...rf.energies.map((e, i) => [el('dt', {}, `rest frame: daughter ${i + 1} energy`), num(`dk-e${i}`, e, u)]).flat());
      (a.lab_energy_ranges || []).forEach((r, i) => { if (Array.isArray(r) && r.every(Number.isFinite)) items.push(el('dt', {}, `lab: daughter ${i + 1} energy`), el('dd', {id: `dk-range-${i}`}, `${fmt(r[0], 5)} to ${fmt(r[1], 5)} ${u}`)); });
      (a.maximum_energies || []).forEach((m, i) => { if (m && Number.isFinite(m.kinetic_energy)) items.push(el('dt', {}, `daughter ${i + 1}: largest kinetic energy`), num(`dk-tmax-${i}`, m.kinetic_energy, u)); });
      (a.maximum_lab_angles || []).forEach((m, i) => { if (Number.isFinite(m)) items.push(el('dt', {}, `daughter ${i + 1}: widest lab angle`), num(`dk-maxang-${i}`, m / D, '°')); });
      if (a.minimum_opening_angle && Number.isFinite(a.minimum_opening_angle.angle))
        items.push(el('dt', {}, 'smallest opening angle'), num('dk-open', a.minimum_opening_angle.angle / D, '°'));
      put(L.results, el('h3', {}, 'Answer'), el('dl', {class: 'nums'}, items));
      // notes, Kinematics Problems in Electron Volts (π⁰ decay, neutron decay; after §3.14, numbered 3.16 in the contents):
      // two bodies at rest share p* = √[(M² − (m₁ + m₂)²)(M² − (m₁ − m₂)²)] / 2M. With three, daughter k gets the most
      // when the other two fly off together as one of mass m_i + m_j: E_k = (M² + m_k² − (m_i + m_j)²) / 2M.
      const mx = a.maximum_energies || [];
      if (two) dkNotes.update({section: '3.16', inferred: true, heading: 'Kinematics Problems in Electron Volts',
        formula: ['p* = √[(M² − (m', el('sub', {}, '1'), ' + m', el('sub', {}, '2'), ')²)(M² − (m', el('sub', {}, '1'), ' − m', el('sub', {}, '2'),
          ')²)] / 2M,  E', el('sub', {}, '1'), ' = (M² + m', el('sub', {}, '1'), '² − m', el('sub', {}, '2'), '²) / 2M  (c = 1)'],
        what: 'the formula', formulaValue: notes, apiValue: rf.momentum, unit: u, diffUnit: 'eV', diffScale: EV[u] || 1,
        how: `Each daughter's momentum in the parent's rest frame, M = ${fmt(M, 7)} and m = ${fmt(masses[0], 6)}, ${fmt(masses[1], 6)} ${u}.`});
      else if (mx.length === 3 && mx.every(e => e && Number.isFinite(e.energy))) {
        const m3 = mx.map(e => e.energy - e.kinetic_energy), k = 1, [i1, i2] = [0, 2];
        const Ek = (M * M + m3[k] ** 2 - (m3[i1] + m3[i2]) ** 2) / (2 * M);
        dkNotes.update({section: '3.16', inferred: true, heading: 'Kinematics Problems in Electron Volts: Neutron Decay',
          formula: ['E', el('sub', {}, '2, max'), ' = (M² + m', el('sub', {}, '2'), '² − (m', el('sub', {}, '1'), ' + m', el('sub', {}, '3'), ')²) / 2M',
            '  (daughters 1 and 3 fly off together, c = 1)'],
          what: 'the formula', formulaValue: Ek - m3[k], apiValue: mx[k].kinetic_energy, unit: u, diffUnit: 'eV', diffScale: EV[u] || 1,
          how: `Daughter 2's largest kinetic energy E − m: three bodies share the energy in a continuous spectrum, and it is ` +
            'largest when the other two move as one.'});
      } else put(dkNotes.box);
      drawDecay(decayPlot, a, two, req);
    });
    const decayPlot = svg('svg', {class: 'plot', id: 'dk-plot', role: 'img', 'aria-label': 'The decay in the rest frame and in the lab'});
    add(L.figure, el('h3', {}, 'Rest frame and lab at the smallest opening angle'), decayPlot);
    run();

    // --- Compton ---
    const C = labSection(main, {title: 'Compton scattering', id: 'compton',
      intro: 'A photon bounces off a free electron at rest. The scattered photon has less energy — a longer wavelength — and the ' +
             'electron recoils; energy and momentum are both conserved.'});
    const cE = field({label: 'Photon energy', pointer: '/energy', value: st.E, unit: 'keV', id: 'cp-energy', help: 'or give the wavelength'});
    const cL = field({label: 'or wavelength', pointer: '/wavelength', value: st.lambda, unit: 'pm', id: 'cp-lambda'});
    const ang = el('input', {type: 'range', min: 0, max: 180, step: 1, value: st.angle, id: 'cp-angle', 'data-pointer': '/angle_deg'});
    const angOut = el('output', {for: 'cp-angle', id: 'cp-angle-shown'}, st.angle + '°');
    const setAngle = (d) => { ang.value = d; angOut.textContent = fmt(d, 4) + '°'; st.angle = d; };
    ang.addEventListener('input', () => { setAngle(Number(ang.value)); crun(); });
    add(C.form, cE.wrap, cL.wrap, el('div', {class: 'figure-control'}, el('label', {for: 'cp-angle'}, 'Scattering angle θ'), ang, angOut),
      el('div', {class: 'buttons'}, el('button', {type: 'submit', id: 'cp-submit'}, 'Scatter')));
    const cplot = svg('svg', {class: 'plot', id: 'cp-plot', role: 'img', 'aria-label': 'Compton scattering: photon in, photon out and the recoiling electron'});
    add(C.figure, cplot);
    const cpNotes = notesBox('cp-notes'); C.figure.after(cpNotes.box); // under the figure: the picture stays by the answer
    const crun = runner(C, '/v1/relativity/kinematics/compton', () => {
      const lam = cL.input.value.trim();
      return lam !== '' ? {wavelength: Number(lam) * 1e-12, angle_deg: Number(ang.value)} : {energy: val(cE.input), energy_unit: 'keV', angle_deg: Number(ang.value)};
    }, (a) => {
      const u = a.energy_unit, th = a.angle;
      const notes = a.compton_wavelength * (1 - Math.cos(th));
      put(C.results, el('dl', {class: 'nums'},
        el('dt', {}, 'incident: energy, λ'), el('dd', {id: 'cp-in'}, `${fmt(a.incident.energy, 6)} ${u}, ${fmt(a.incident.wavelength * 1e12, 6)} pm`),
        el('dt', {}, 'scattered: energy, λ′'), el('dd', {id: 'cp-out', 'data-value': a.scattered.wavelength}, `${fmt(a.scattered.energy, 6)} ${u}, ${fmt(a.scattered.wavelength * 1e12, 6)} pm`),
        el('dt', {}, 'λ′ − λ'), num('cp-shift', a.wavelength_shift * 1e12, 'pm'),
        el('dt', {}, 'electron: kinetic energy'), num('cp-recoil', a.recoil.kinetic_energy, u),
        el('dt', {}, 'electron: angle'), num('cp-recoil-angle', a.recoil.angle / D, '°')));
      // notes, Compton Scattering (in the section numbered 3.16 in the contents): λ′ − λ = (h / m c)(1 − cos θ)
      cpNotes.update({section: '3.16', inferred: true, heading: 'Kinematics Problems in Electron Volts: Compton Scattering',
        formula: ['λ′ − λ = (h / m c)(1 − cos θ),  h / m c = ' + fmt(a.compton_wavelength * 1e12, 6) + ' pm for the electron'],
        what: 'the formula', formulaValue: notes * 1e12, apiValue: a.wavelength_shift * 1e12, unit: 'pm', diffUnit: 'm', diffScale: 1e-12,
        how: 'The scattered photon\'s wavelength shift at this angle: the formula in this page from h/mc and θ; the API from energy ' +
          'and momentum conservation.'});
      drawCompton(cplot, a);
    });
    crun();

    // --- Doppler ---
    const Dp = labSection(main, {title: 'The Doppler effect: the colour of light', id: 'doppler',
      intro: 'A source moves with velocity β. Coming towards you its light is bluer, going away redder: along the line of sight ' +
             'f′ = f √((1 + β)/(1 − β)). Seen at right angles (in your frame) it is still redder, by 1/γ: the source\'s clocks run slow. ' +
             'Slide β and the angle and watch the colour.'});
    const bs = el('input', {type: 'range', min: -0.95, max: 0.95, step: 0.01, value: st.beta, id: 'dp-beta', 'data-pointer': '/source_velocity/beta'});
    const bOut = el('output', {for: 'dp-beta', id: 'dp-beta-shown'}, 'β = ' + st.beta);
    const setBeta = (b) => { bs.value = b; st.beta = Number(bs.value); bOut.textContent = 'β = ' + fmt(st.beta, 3); };
    const dL = field({label: 'Emitted wavelength', pointer: '/wavelength', value: st.nm, unit: 'nm', id: 'dp-lambda', help: 'visible: 380 to 750 nm'});
    bs.addEventListener('input', () => { setBeta(Number(bs.value)); drun(); });
    // the angle, in the observer's frame, between the source's velocity and the light reaching you
    const as = el('input', {type: 'range', min: 0, max: 180, step: 1, value: 0, id: 'dp-angle', 'data-pointer': '/arrival_direction'});
    const aOut = el('output', {for: 'dp-angle', id: 'dp-angle-shown'}, '0°');
    as.addEventListener('input', () => { aOut.textContent = as.value + '°'; drun(); });
    add(Dp.form, el('div', {class: 'figure-control'}, el('label', {for: 'dp-beta'}, 'β (positive: coming towards you)'), bs, bOut),
      el('div', {class: 'figure-control'}, el('label', {for: 'dp-angle'}, 'angle from head-on (your frame)'), as, aOut), dL.wrap,
      el('div', {class: 'buttons'}, el('button', {type: 'submit', id: 'dp-submit'}, 'Shift')));
    const dpNotes = notesBox('dp-notes'); Dp.figure.after(dpNotes.box); // under the figure: the picture stays by the answer
    const drun = runner(Dp, '/v1/relativity/doppler', () => {
      st.nm = val(dL.input);
      const t = Number(as.value) * D, c = Math.abs(Math.cos(t)) < 1e-15 ? 0 : Math.cos(t), s = Math.abs(Math.sin(t)) < 1e-15 ? 0 : Math.sin(t);
      return {source_velocity: {beta: [Number(bs.value), 0, 0]}, arrival_direction: [Number(c.toPrecision(15)), Number(s.toPrecision(15)), 0],
        wavelength: Number((val(dL.input) * 1e-9).toPrecision(12))};
    }, (a, req) => {
      const b = a.source_velocity.beta[0], f = a.doppler_factor, n = req.arrival_direction;
      const cosA = n[0] / Math.hypot(...n), notes = Math.sqrt(1 - b * b) / (1 - b * cosA); // 1 / (γ (1 − β cos α))
      put(Dp.results, el('div', {class: 'pair'},
        el('div', {}, el('h3', {}, 'Emitted'), swatch('dp-swatch-emitted', a.wavelength_emitted * 1e9)),
        el('div', {}, el('h3', {}, 'Seen'), swatch('dp-swatch-seen', a.wavelength_observed * 1e9))),
        el('dl', {class: 'nums'}, el('dt', {}, 'f′ / f'), num('dp-factor', f), el('dt', {}, 'seen wavelength'), num('dp-seen', a.wavelength_observed * 1e9, 'nm'),
          el('dt', {}, 'case'), el('dd', {id: 'dp-case'}, a.case.replace(/_/g, ' '))));
      // notes §3.14 The Relativistic Doppler Effect: along the line of sight f′ = f √((1 + β)/(1 − β)); at an
      // angle α in the observer's frame f′ = f / (γ (1 − β cos α)) (the phase k·x − ωt is invariant)
      dpNotes.update({section: '3.14', heading: 'The Relativistic Doppler Effect',
        formula: ['f′ = f / (γ (1 − β cos α)):  √((1 + β)/(1 − β)) head-on (α = 0),  1/γ at α = 90°  (α in your frame)'],
        what: 'the formula', formulaValue: notes, apiValue: f, unit: '',
        how: 'The factor f′/f: the formula in this page from β and α; the API boosts the light\'s 4-momentum.'});
    });
    drun();
  },
};

// Rest frame (left: back to back at θ* of the smallest opening angle, or along
// the axis) and lab (right: both thrown forwards), arrows scaled by momentum.
function drawDecay(root, a, two, req) {
  const [W, H] = plotSize(root, 560, 240);
  put(root); root.setAttribute('viewBox', `0 0 ${W} ${H}`);
  const cx1 = W * 0.25, cx2 = W * 0.72, cy = H / 2 + 6, L = Math.min(W * 0.2, H * 0.38);
  add(root, svg('text', {x: cx1, y: 18, 'text-anchor': 'middle', 'font-size': 14}, 'parent\'s rest frame'),
    svg('text', {x: cx2, y: 18, 'text-anchor': 'middle', 'font-size': 14}, 'lab (parent moving →)'),
    svg('circle', {cx: cx1, cy, r: 6, fill: '#333'}), svg('circle', {cx: cx2 - L * 0.9, cy, r: 6, fill: '#333'}));
  if (!two || !a.minimum_opening_angle) {
    add(root, svg('text', {x: W / 2, y: H - 10, 'text-anchor': 'middle', 'font-size': 13, fill: '#555'}, 'drawn for two-body decays'));
    return;
  }
  const ts = a.minimum_opening_angle.theta_star, g = a.parent.gamma, b = a.parent.beta;
  const rf = a.rest_frame, ms = rf.energies.map((e, i) => e - rf.kinetic_energies[i]);
  // daughter i in the rest frame: momentum p* at θ* (i = 0) and θ* + π (i = 1); boosted along the parent's direction
  const mom = [0, 1].map(i => {
    const th = ts + i * Math.PI, pz = rf.momentum * Math.cos(th), px = rf.momentum * Math.sin(th), E = rf.energies[i];
    return {rest: [pz, px], lab: [g * (pz + b * E), px], m: ms[i]};
  });
  const pmax = Math.max(...mom.flatMap(m => [Math.hypot(...m.rest), Math.hypot(...m.lab)])) || 1;
  const colors = ['#c92a2a', '#1864ab'];
  const arrow = (x, y, v, c) => add(root, svg('line', {x1: x, y1: y, x2: x + L * v[0] / pmax, y2: y - L * v[1] / pmax, stroke: c, 'stroke-width': 3}),
    svg('circle', {cx: x + L * v[0] / pmax, cy: y - L * v[1] / pmax, r: 4, fill: c}));
  mom.forEach((m, i) => { arrow(cx1, cy, m.rest, colors[i]); arrow(cx2 - L * 0.9, cy, m.lab, colors[i]); });
  add(root, svg('text', {x: W / 2, y: H - 8, 'text-anchor': 'middle', 'font-size': 13, fill: '#555'},
    `arrows: momenta to scale (longest ${fmt(pmax, 4)} ${a.energy_unit}/c); opening angle in the lab ${fmt(a.minimum_opening_angle.angle / D, 4)}°`));
}

// Photon in from the left, the scattered photon at θ above the axis and the
// electron at its recoil angle below, arrows scaled by momentum.
function drawCompton(root, a) {
  const [W, H] = plotSize(root, 560, 300);
  put(root); root.setAttribute('viewBox', `0 0 ${W} ${H}`);
  const cx = W * 0.45, cy = H * 0.5, L = Math.min(W * 0.4, H * 0.42);
  const pin = a.incident.energy, pmax = Math.max(pin, a.scattered.energy, a.recoil.momentum) || 1;
  const line = (x1, y1, x2, y2, c, dash) => add(root, svg('line', {x1, y1, x2, y2, stroke: c, 'stroke-width': 3, 'stroke-dasharray': dash || null}),
    svg('circle', {cx: x2, cy: y2, r: 4, fill: c}));
  add(root, svg('line', {x1: 10, y1: cy, x2: W - 10, y2: cy, stroke: '#dee2e6'}));
  line(cx - L * pin / pmax, cy, cx, cy, '#e67700', '7 4');
  const th = a.angle, phi = a.recoil.angle;
  line(cx, cy, cx + L * a.scattered.energy / pmax * Math.cos(th), cy - L * a.scattered.energy / pmax * Math.sin(th), '#e67700', '7 4');
  line(cx, cy, cx + L * a.recoil.momentum / pmax * Math.cos(phi), cy + L * a.recoil.momentum / pmax * Math.sin(phi), '#1864ab');
  add(root, svg('circle', {cx, cy, r: 7, fill: '#1864ab'}),
    svg('text', {x: 12, y: cy - 10, 'font-size': 14, fill: '#b35900'}, 'photon in'),
    svg('text', {x: cx + 10, y: 22, 'font-size': 14, fill: '#b35900'}, `photon out, θ = ${fmt(th / D, 4)}°`),
    svg('text', {x: cx + 10, y: H - 12, 'font-size': 14, fill: '#1864ab'}, `electron, ${fmt(phi / D, 4)}° below`));
}
