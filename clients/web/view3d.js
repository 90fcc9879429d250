// view3d.js — a turnable 3-D view for the labs, on three.js (vendored, see
// vendor/SHA256SUMS): a WebGL canvas with lights, z up (the physics'
// convention), and orbit controls of our own: drag with the mouse or a finger
// to turn, two fingers or the wheel to zoom, and with the canvas focused the
// arrow keys turn and + / − zoom. It draws only when something changed.
// Without WebGL it says so in words instead of leaving a blank box.
import * as THREE from './vendor/three-0.185.0/three.module.min.js';
import {el, put, plotTools} from './lib.js';

export {THREE};

// view3d(container, {label, extent, id}) -> {scene, camera, canvas, view, render(), frame(extent), aim(yaw, pitch), ok}
//   container: an element the canvas (4:3, its laid-out width) is put into;
//   extent: the scene's radius in its units, for the camera distance;
//   id: the canvas' id (one renderer per id, reused when the lab is mounted again).
// The camera (view.yaw, view.pitch, view.zoom) is part of a lab's shared state:
// canvas.camera.get() / .set({yaw, pitch, zoom}) read and put it (share.js), and
// once the student has turned or zoomed it (view.turned) a lab's aim() no
// longer moves it; each turn tells the address bar (a 'mechd:moved' event).
// One WebGL renderer per view id, kept across re-mounts of a lab (a browser
// allows only a few WebGL contexts at once; a lab is re-mounted on every tab
// change and example load). Its canvas' listeners act on the view last made.
const renderers = new Map();

export function view3d(container, {label = '3-D view', extent = 1, id = 'view3d'} = {}) {
  let entry = renderers.get(id);
  if (!entry) {
    let renderer;
    try {
      renderer = new THREE.WebGLRenderer({antialias: true, preserveDrawingBuffer: true});
    } catch (e) {
      put(container, el('p', {class: 'problem'}, 'This 3-D view needs WebGL, which this browser does not offer. ' +
        'The numbers beside it are unaffected.'));
      return {ok: false, scene: new THREE.Scene(), camera: new THREE.PerspectiveCamera(), view: {}, render() {}, frame() {}, canvas: null};
    }
    entry = {renderer, cur: null};
    renderers.set(id, entry);
    renderer.setClearColor(0xffffff, 1);
    const canvas = renderer.domElement;
    canvas.className = 'plot view3d';
    canvas.tabIndex = 0;
    canvas.id = id;
    canvas.setAttribute('role', 'img');
    canvas.dataset.render = '1';
    listen(canvas, () => entry.cur);
    canvas.camera = {
      get: () => entry.cur && {yaw: entry.cur.view.yaw, pitch: entry.cur.view.pitch, zoom: entry.cur.view.zoom, turned: !!entry.cur.view.turned},
      set: ({yaw, pitch, zoom}) => {
        const c = entry.cur; if (!c) return;
        if (Number.isFinite(yaw)) c.view.yaw = yaw;
        if (Number.isFinite(pitch)) c.view.pitch = Math.max(-1.5, Math.min(1.5, pitch));
        if (Number.isFinite(zoom)) c.view.zoom = Math.max(0.5, Math.min(5, zoom));
        c.view.turned = true; c.render();
      },
    };
    // export (lib.js plotTools) asks for a fresh frame before reading the pixels
    window.addEventListener('mechd:render', (e) => { if (e.detail === canvas && entry.cur) entry.cur.draw(); });
    if (typeof ResizeObserver === 'function') new ResizeObserver(() => entry.cur && entry.cur.render()).observe(canvas);
  }
  const {renderer} = entry, canvas = renderer.domElement;
  canvas.setAttribute('aria-label', label + ' (drag, or focus and use the arrow keys, to turn; + and − zoom)');
  put(container, canvas);
  plotTools(canvas, {name: id});

  const scene = new THREE.Scene();
  scene.add(new THREE.AmbientLight(0xffffff, 1.1));
  const sun = new THREE.DirectionalLight(0xffffff, 2.2); sun.position.set(3, -2, 5); scene.add(sun);
  const fill = new THREE.DirectionalLight(0xffffff, 0.8); fill.position.set(-4, 3, -2); scene.add(fill);
  const camera = new THREE.PerspectiveCamera(35, 4 / 3, 0.01, 1000);
  camera.up.set(0, 0, 1);
  // zoom: the distance over the framed one (4 × the scene's radius), 0.5 … 5
  const view = {yaw: -0.9, pitch: 0.45, zoom: 1, min: extent, target: new THREE.Vector3(), turned: false};
  let pending = false;
  const place = () => {
    const c = Math.cos(view.pitch), dist = 4 * view.min * view.zoom;
    camera.position.set(view.target.x + dist * c * Math.cos(view.yaw), view.target.y + dist * c * Math.sin(view.yaw),
      view.target.z + dist * Math.sin(view.pitch));
    camera.lookAt(view.target);
  };
  const size = () => {
    const w = Math.round(canvas.getBoundingClientRect().width) || 640, h = Math.round(w * 3 / 4);
    const dpr = Math.min(2, window.devicePixelRatio || 1);
    if (canvas.width !== Math.round(w * dpr) || canvas.height !== Math.round(h * dpr)) {
      renderer.setPixelRatio(dpr); renderer.setSize(w, h, false);
    }
    camera.aspect = w / h; camera.updateProjectionMatrix();
  };
  const cur = {
    view,
    draw() {
      pending = false; if (entry.cur !== cur) return; size(); place(); renderer.render(scene, camera);
      canvas.dataset.yaw = view.yaw.toFixed(3); canvas.dataset.pitch = view.pitch.toFixed(3); canvas.dataset.zoom = view.zoom.toFixed(3);
    },
    render() { if (!pending) { pending = true; requestAnimationFrame(() => cur.draw()); } },
  };
  entry.cur = cur;
  cur.render();
  return {
    ok: true, scene, camera, canvas, view, render: cur.render,
    // aim at a scene of this radius around target (the zoom the student chose kept)
    frame(extent2, target = [0, 0, 0]) { view.min = extent2; view.target.set(...target); cur.render(); },
    // the lab's own viewpoint, unless the student has turned the view (or a link has)
    aim(yaw, pitch) { if (view.turned) return; view.yaw = yaw; view.pitch = pitch; cur.render(); },
  };
}

// The controls, attached once per canvas: pointer (mouse, pen, one finger)
// turns; two fingers or the wheel zoom; arrow keys turn and + / − zoom.
function listen(canvas, current) {
  let told = 0; // the address bar hears of a turn once it rests (share.js keeps the camera in the link)
  const moved = () => { clearTimeout(told); told = setTimeout(() => window.dispatchEvent(new Event('mechd:moved')), 300); };
  const turn = (dyaw, dpitch) => {
    const c = current(); if (!c) return;
    c.view.yaw += dyaw; c.view.pitch = Math.max(-1.5, Math.min(1.5, c.view.pitch + dpitch)); c.view.turned = true; c.render(); moved();
  };
  const zoom = (k) => {
    const c = current(); if (!c) return;
    c.view.zoom = Math.max(0.5, Math.min(5, c.view.zoom * k)); c.view.turned = true; c.render(); moved();
  };
  const pts = new Map();
  let pinch = 0;
  canvas.addEventListener('pointerdown', (e) => { pts.set(e.pointerId, [e.clientX, e.clientY]); canvas.setPointerCapture(e.pointerId); });
  canvas.addEventListener('pointermove', (e) => {
    const p = pts.get(e.pointerId);
    if (!p) return;
    if (pts.size === 1) turn(-(e.clientX - p[0]) * 0.01, (e.clientY - p[1]) * 0.01);
    pts.set(e.pointerId, [e.clientX, e.clientY]);
    if (pts.size === 2) {
      const [a, b] = [...pts.values()], d = Math.hypot(a[0] - b[0], a[1] - b[1]);
      if (pinch && d) zoom(pinch / d);
      pinch = d;
    }
  });
  const up = (e) => { pts.delete(e.pointerId); pinch = 0; };
  canvas.addEventListener('pointerup', up); canvas.addEventListener('pointercancel', up);
  canvas.addEventListener('wheel', (e) => { e.preventDefault(); zoom(e.deltaY > 0 ? 1.1 : 1 / 1.1); }, {passive: false});
  canvas.addEventListener('keydown', (e) => {
    const d = {ArrowLeft: [0.1, 0], ArrowRight: [-0.1, 0], ArrowUp: [0, 0.1], ArrowDown: [0, -0.1]}[e.key];
    if (d) { e.preventDefault(); turn(d[0], d[1]); }
    else if (e.key === '+' || e.key === '=') { e.preventDefault(); zoom(1 / 1.15); }
    else if (e.key === '-' || e.key === '_') { e.preventDefault(); zoom(1.15); }
  });
}

// Coloured principal-axis arrows from origin o (arrays), lengths L[k]; returns a Group.
export function axesArrows(axes, L, o = [0, 0, 0], colors = [0xc92a2a, 0x2b8a3e, 0x1864ab], both = true) {
  const g = new THREE.Group();
  axes.forEach((a, k) => {
    const d = new THREE.Vector3(...a).normalize(), len = L[k];
    g.add(new THREE.ArrowHelper(d, new THREE.Vector3(...o), len, colors[k], 0.12 * len, 0.06 * len));
    if (both) g.add(new THREE.ArrowHelper(d.clone().negate(), new THREE.Vector3(...o), len, colors[k], 0.001, 0.001));
  });
  return g;
}

// Thin grey x, y, z axes of length L with small labels drawn as sprites.
export function sceneAxes(L) {
  const g = new THREE.Group();
  const mat = new THREE.LineBasicMaterial({color: 0x999999});
  ['x', 'y', 'z'].forEach((name, k) => {
    const e = [0, 0, 0]; e[k] = L;
    g.add(new THREE.Line(new THREE.BufferGeometry().setFromPoints([new THREE.Vector3(), new THREE.Vector3(...e)]), mat));
    const s = label(name, '#555'); s.position.set(...e.map(v => v * 1.08)); s.scale.multiplyScalar(L * 0.12); g.add(s);
  });
  return g;
}

// A text label that always faces the camera (a sprite of a small canvas).
export function label(text, color = '#111') {
  const c = document.createElement('canvas'); c.width = 128; c.height = 64;
  const g = c.getContext('2d'); g.font = 'bold 44px system-ui, sans-serif'; g.fillStyle = color;
  g.textAlign = 'center'; g.textBaseline = 'middle'; g.fillText(text, 64, 32);
  const s = new THREE.Sprite(new THREE.SpriteMaterial({map: new THREE.CanvasTexture(c), depthTest: false}));
  s.scale.set(2, 1, 1);
  return s;
}

// A polyline through points [[x, y, z], …] (drawn up to count, when given).
export function polyline(points, color = 0x1864ab) {
  const geo = new THREE.BufferGeometry().setFromPoints(points.map(p => new THREE.Vector3(...p)));
  return new THREE.Line(geo, new THREE.LineBasicMaterial({color}));
}
