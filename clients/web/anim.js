// anim.js — the labs' shared animation control: Play/Pause, a time slider and a
// speed choice (real time, or a time scale that says how long the whole run
// takes to watch) over the sample times the API returned. Nothing is
// integrated in the browser: a frame is the sample at (or linearly between the
// two samples around) the time shown. Keyboard: the controls are a native
// button, range input and select (Space/Enter, arrow keys, Home/End).
// The root carries data-time (the time shown) and data-playing for tests.
import {el, put, fmt, pow10} from './lib.js';

let uid = 0;

// Nice time scales (simulated seconds per real second) that play the whole
// duration T in about 3, 10 and 30 s, plus real time (1) when it is not absurd.
function scales(T) {
  const nice = (x) => { const e = 10 ** Math.floor(Math.log10(x)), m = x / e; return (m < 1.5 ? 1 : m < 3.5 ? 2 : m < 7.5 ? 5 : 10) * e; };
  const out = new Set([nice(T / 10), nice(T / 30), nice(T / 3)]);
  if (T / 1 <= 3600) out.add(1); // real time, when the run lasts under an hour
  return [...out].sort((a, b) => a - b);
}
const human = (s) => s < 120 ? `${fmt(s, 3)} s` : s < 7200 ? `${fmt(s / 60, 3)} min` : s < 172800 ? `${fmt(s / 3600, 3)} h`
  : s < 3.156e7 * 2 ? `${fmt(s / 86400, 3)} days` : `${fmt(s / 3.156e7, 3)} years`;

// player({label, unit, seconds, reverse}) -> {root, set(times, onFrame, {grow}), seek(t), pause()}
//   times: increasing sample times (the API's t array, in `unit`, seconds by default);
//   onFrame(i, f, t): draw the state between sample i and i + 1 (fraction f in [0, 1)).
//   grow: plots (lib.js linePlot roots whose series carry times) that grow with the
//   animation — the past drawn, the future not — once it is played or stepped (until
//   then the whole answer shows, to be read).
//   reverse: where the physics allows time to run backwards (no friction), the words
//   that say what the reversed film shows; a "Backwards" toggle then plays it so.
// Frame by frame: the ◀| and |▶ buttons, and on the player (any of its controls
// focused) the keys , and . step one sample back and forward.
// Nothing plays until Play is pressed (no motion a reader did not ask for).
export function player({label = 'Animation', unit = 's', seconds = 1, reverse} = {}) {
  const id = 'anim' + (++uid);
  let times = [], frame = () => {}, tNow = 0, playing = false, last = 0, raf = 0, grows = [], growing = false, backwards = false;
  const btn = el('button', {type: 'button', class: 'play', id: id + '-play', 'aria-pressed': 'false', 'data-role': 'play'}, '▶ Play');
  const slider = el('input', {type: 'range', id: id + '-time', min: 0, max: 1000, step: 1, value: 0, 'data-role': 'time',
    'aria-label': label + ': time'});
  const out = el('output', {for: slider.id, id: id + '-now', 'data-role': 'now'}, '');
  const speed = el('select', {id: id + '-speed', 'data-role': 'speed'});
  const back = el('button', {type: 'button', class: 'secondary step', 'data-role': 'step-back', 'aria-label': 'One frame back (key ,)',
    title: 'One frame back (,)'}, '◀|');
  const fwd = el('button', {type: 'button', class: 'secondary step', 'data-role': 'step', 'aria-label': 'One frame forward (key .)',
    title: 'One frame forward (.)'}, '|▶');
  const rev = reverse ? el('button', {type: 'button', class: 'secondary step', 'data-role': 'reverse', 'aria-pressed': 'false',
    title: reverse}, '⇆ Backwards') : null;
  const revNote = reverse ? el('span', {class: 'muted reverse-note', 'data-role': 'reverse-note', hidden: true}, reverse) : null;
  const root = el('div', {class: 'player', role: 'group', 'aria-label': label + ' controls', 'data-playing': 'false', 'data-time': '0'},
    btn, back, fwd, rev, el('label', {for: slider.id, class: 'sr-only'}, 'Time'), slider, out,
    el('span', {class: 'speed'}, el('label', {for: speed.id}, 'Speed'), ' ', speed), revNote);
  // nothing to play until the first samples arrive (set): say so, not an empty list
  put(speed, el('option', {value: 1}, 'waiting for the run'));
  btn.disabled = slider.disabled = speed.disabled = back.disabled = fwd.disabled = true;
  if (rev) rev.disabled = true;
  const T = () => (times.length ? times[times.length - 1] - times[0] : 0);
  const show = () => {
    if (!times.length) return;
    const t0 = times[0];
    let lo = 0, hi = times.length - 1;
    while (hi - lo > 1) { const mid = (lo + hi) >> 1; if (times[mid] <= tNow) lo = mid; else hi = mid; }
    const span = times[hi] - times[lo], f = hi > lo && span > 0 ? Math.min(1, Math.max(0, (tNow - times[lo]) / span)) : 0;
    slider.value = String(Math.round(1000 * (tNow - t0) / (T() || 1)));
    slider.setAttribute('aria-valuetext', `t = ${fmt(tNow, 4)} ${unit}`);
    out.textContent = `t = ${fmt(tNow, 4)} ${unit}`;
    root.dataset.time = String(tNow);
    for (const g of grows) if (g._grow) g._grow(growing ? tNow : Infinity);
    if (f >= 1 && hi === times.length - 1) frame(hi, 0, tNow); else frame(lo, f, tNow);
  };
  // one sample back or forward (from between two samples: to the nearer one on that side)
  const step = (dir) => {
    if (!times.length) return;
    setPlaying(false); growing = true;
    const eps = 1e-12 * (Math.abs(T()) || 1);
    if (dir > 0) { const k = times.findIndex(x => x > tNow + eps); tNow = k < 0 ? times[times.length - 1] : times[k]; }
    else { let k = -1; for (let i = times.length - 1; i >= 0; i--) if (times[i] < tNow - eps) { k = i; break; } tNow = k < 0 ? times[0] : times[k]; }
    show();
  };
  back.addEventListener('click', () => step(-1));
  fwd.addEventListener('click', () => step(1));
  root.addEventListener('keydown', (e) => {
    if (e.key === ',' || e.key === '.') { e.preventDefault(); step(e.key === '.' ? 1 : -1); }
  });
  if (rev) rev.addEventListener('click', () => {
    backwards = !backwards;
    rev.setAttribute('aria-pressed', String(backwards));
    revNote.hidden = !backwards;
    root.dataset.backwards = String(backwards);
  });
  const setPlaying = (p) => {
    playing = p;
    btn.textContent = p ? '⏸ Pause' : '▶ Play';
    btn.setAttribute('aria-pressed', String(p));
    root.dataset.playing = String(p);
    if (p) { last = performance.now(); raf = requestAnimationFrame(tick); } else cancelAnimationFrame(raf);
  };
  const tick = (now) => {
    if (!playing) return;
    const dt = Math.min(0.1, (now - last) / 1000); last = now;
    tNow += (backwards ? -1 : 1) * dt * Number(speed.value) / seconds;
    const end = times[times.length - 1];
    if (tNow >= end) { tNow = end; show(); setPlaying(false); return; }
    if (backwards && tNow <= times[0]) { tNow = times[0]; show(); setPlaying(false); return; }
    show();
    raf = requestAnimationFrame(tick);
  };
  btn.addEventListener('click', () => {
    if (!times.length) return;
    growing = true;
    if (!playing && !backwards && tNow >= times[times.length - 1]) tNow = times[0]; // play again from the start
    if (!playing && backwards && tNow <= times[0]) tNow = times[times.length - 1]; // backwards: from the end
    setPlaying(!playing);
  });
  slider.addEventListener('input', () => { growing = true; tNow = times[0] + T() * Number(slider.value) / 1000; show(); });
  const api = {
    root,
    // new samples: keep the speed when it still fits, start at the beginning
    set(ts, onFrame, {grow = []} = {}) {
      setPlaying(false);
      times = ts.filter(Number.isFinite); frame = onFrame; tNow = times.length ? times[0] : 0;
      grows = grow; growing = false;
      const prev = Number(speed.value), opts = scales(T() * seconds || 1);
      const pick = opts.includes(prev) ? prev : opts[Math.min(1, opts.length - 1)];
      put(speed, opts.map(s => el('option', {value: s, selected: s === pick},
        s === 1 ? `real time (${human(T() * seconds)})` : `×${times10(s)} (whole run in ${human(T() * seconds / s)})`)));
      btn.disabled = slider.disabled = speed.disabled = back.disabled = fwd.disabled = !times.length;
      if (rev) rev.disabled = !times.length;
      show();
    },
    seek(t) { tNow = t; show(); },
    step,
    pause() { setPlaying(false); },
  };
  return api;
}

// 2000000 -> 2·10⁶ (a time scale read at a glance)
const times10 = (s) => { if (s < 1e4) return fmt(s, 3); const e = Math.floor(Math.log10(s)), m = Number((s / 10 ** e).toPrecision(2));
  return (m === 1 ? '' : m + '·') + pow10(e); };

// Linear interpolation of two samples (numbers or equal-length arrays).
export const lerp = (a, b, f) => Array.isArray(a) ? a.map((v, k) => v + (b[k] - v) * f) : a + (b - a) * f;
