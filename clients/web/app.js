// app.js — the labs' shell: tabs, hash routing (#inertia …), projector mode,
// and the access token of a server started with --token-file (asked for when
// the server answers 401, kept for this tab's session only).
import {el, add, getToken, setToken} from './lib.js';
import {share, parseHash, embedded, embedBar} from './share.js';

// The labs in the course's order: rotations (ch. 0), the rotating table and
// the tides (ch. 1), … Each lab's module is loaded when it is first shown, so a
// phone opening one lab fetches and parses only that lab (and three.js only
// for the labs drawn in 3-D).
const labs = [
  ['rotations', 'Rotations'], ['table', 'Rotating table'], ['inertia', 'Inertia'], ['tops', 'Tops'], ['earth', 'Earth'],
  ['tides', 'Tides'], ['orbits', 'Orbits'], ['oscillations', 'Oscillations'], ['phase', 'Phase space'], ['spacetime', 'Spacetime'], ['particles', 'Particles'],
  ['accuracy', 'Accuracy'],
].map(([id, title]) => ({id, title, load: () => import(`./labs/${id}.js`).then(m => m.default)}));
const main = document.getElementById('lab');
const tabs = document.getElementById('tabs');
for (const lab of labs)
  add(tabs, el('li', {}, el('a', {href: '#' + lab.id, id: 'tab-' + lab.id}, lab.title)));

let showing = 0; // the latest show(): an older one whose module arrives late does not mount
async function show() {
  const {id: hashId, params} = parseHash(location.hash); // #lab?state (share.js)
  const id = hashId || labs[0].id;
  const lab = labs.find(l => l.id === id) || labs[0];
  const me = ++showing;
  for (const a of tabs.querySelectorAll('a'))
    if (a.id === 'tab-' + lab.id) {
      a.setAttribute('aria-current', 'page');
      // on a phone the tabs are one row that scrolls sideways: keep the current one in view
      if (tabs.scrollWidth > tabs.clientWidth) tabs.scrollLeft = Math.max(0, a.offsetLeft - tabs.offsetLeft - 24);
    } else a.removeAttribute('aria-current');
  document.title = `${lab.title} — mechd labs`;
  let mod;
  try { mod = await lab.load(); } catch (e) {
    if (me === showing) main.textContent = `The ${lab.title} lab could not be loaded (${e.message}); reload the page to try again.`;
    return;
  }
  if (me !== showing) return;
  main.dataset.lab = lab.id;
  mod.mount(main);
  if (isEmbedded) add(main, embedBar(lab.title));
  share(main, lab.id, lab.id === id ? params : new URLSearchParams());
}
// a hash the page wrote itself (replaceState) fires nothing; one pasted or followed re-mounts the lab
window.addEventListener('hashchange', () => { show(); main.focus(); });
// embedded in a course page (?embed=1 or inside a frame): the lab alone, compact
const isEmbedded = embedded();
document.body.classList.toggle('embedded', isEmbedded);
const proj = document.getElementById('projector');
proj.checked = localStorage.getItem('mechd-projector') === '1';
document.body.classList.toggle('projector', proj.checked);
proj.addEventListener('change', () => {
  document.body.classList.toggle('projector', proj.checked);
  localStorage.setItem('mechd-projector', proj.checked ? '1' : '0');
  window.dispatchEvent(new CustomEvent('mechd:redraw')); // plots redraw their text at the new size
});

// --- access token ------------------------------------------------------------
// A small panel in the header: a password field, "Use" and "Forget". It opens
// by itself on the first 401 (every lab then shows the problem too); using a
// token re-runs the lab. sessionStorage only: closing the tab forgets it.
const tokenBtn = el('button', {type: 'button', class: 'secondary small-btn', id: 'token-toggle',
  'aria-expanded': 'false', 'aria-controls': 'token-form'}, 'Access token');
const tokenInput = el('input', {type: 'password', id: 'token-input', autocomplete: 'off', spellcheck: 'false',
  'aria-describedby': 'token-note'});
const tokenNote = el('p', {id: 'token-note', class: 'muted'});
const tokenForm = el('form', {id: 'token-form', class: 'token', hidden: true, 'aria-label': 'Access token'},
  el('label', {for: 'token-input'}, 'Access token'), tokenInput,
  el('button', {type: 'submit', id: 'token-use'}, 'Use'),
  el('button', {type: 'button', class: 'secondary', id: 'token-forget', onclick: () => {
    setToken(''); tokenInput.value = ''; noteToken(); show();
    if (chan) chan.postMessage({forget: true});
  }}, 'Forget'), tokenNote);
function noteToken(msg) {
  tokenNote.textContent = (msg ? msg + ' ' : '') + (getToken()
    ? 'A token is in use (sent as Authorization: Bearer; shared with this browser\'s other tabs of the labs, never stored on disk, forgotten when the last one closes).'
    : 'Kept while a tab of the labs is open in this browser, never stored on disk; sent as Authorization: Bearer.');
}
function openToken(open, msg) {
  tokenForm.hidden = !open;
  tokenBtn.setAttribute('aria-expanded', String(open));
  if (open) { noteToken(msg); tokenInput.focus(); }
}
tokenBtn.addEventListener('click', () => openToken(tokenForm.hidden));
tokenForm.addEventListener('submit', (e) => {
  e.preventDefault();
  setToken(tokenInput.value.trim()); tokenInput.value = '';
  if (chan && getToken()) chan.postMessage({token: getToken()});
  openToken(false); show();
});
let asked = false; // open the panel once per page load, not on every 401 of a lab
window.addEventListener('mechd:unauthorized', (e) => {
  if (asked && !tokenForm.hidden) return;
  if (asked && !e.detail.hadToken) return;
  asked = true;
  openToken(true, e.detail.hadToken ? 'The server did not accept this token: check it and enter it again.'
                                    : 'This server needs an access token for its API.');
});
window.addEventListener('mechd:token-open', () => openToken(true));
add(document.querySelector('header'), el('div', {class: 'settings'}, tokenBtn), tokenForm);

// The token for the browser session, not just the tab: a new tab asks the
// labs' other open tabs for it on a BroadcastChannel (same origin only), and
// one that holds it answers. It lives in each tab's sessionStorage, never on
// disk: localStorage would keep the secret after the browser closes, on the
// disk of a shared lab machine; with the channel it is gone once the last tab
// of the labs closes. Forget forgets it in every tab.
const chan = typeof BroadcastChannel === 'function' ? new BroadcastChannel('mechd-token') : null;
let heard = null; // resolves the start-up wait when another tab answers
if (chan) chan.onmessage = (e) => {
  const m = e.data || {};
  if (m.ask) { if (getToken()) chan.postMessage({token: getToken()}); return; }
  if (m.forget) { setToken(''); noteToken(); return; }
  if (typeof m.token === 'string' && m.token && !getToken()) {
    setToken(m.token); noteToken();
    if (heard) heard();
    else if (!tokenForm.hidden) { openToken(false); show(); } // it came after this tab's 401: run again with it
  }
};
noteToken();
if (chan && !getToken()) { // ask, and wait a moment for an answer before the lab's first request
  await new Promise((r) => { heard = r; chan.postMessage({ask: true}); setTimeout(r, 120); });
  heard = null;
}

show();
