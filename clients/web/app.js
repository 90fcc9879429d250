// app.js — the labs' shell: tabs, hash routing (#inertia …), projector mode.
import inertia from './labs/inertia.js';
import spacetime from './labs/spacetime.js';
import earth from './labs/earth.js';
import tops from './labs/tops.js';
import orbits from './labs/orbits.js';
import accuracy from './labs/accuracy.js';
import {el} from './lib.js';

const labs = [inertia, spacetime, earth, tops, orbits, accuracy];
const main = document.getElementById('lab');
const tabs = document.getElementById('tabs');
for (const lab of labs)
  tabs.append(el('li', {}, el('a', {href: '#' + lab.id, id: 'tab-' + lab.id}, lab.title)));

function show() {
  const id = location.hash.slice(1) || labs[0].id;
  const lab = labs.find(l => l.id === id) || labs[0];
  for (const a of tabs.querySelectorAll('a'))
    if (a.id === 'tab-' + lab.id) a.setAttribute('aria-current', 'page'); else a.removeAttribute('aria-current');
  document.title = `${lab.title} — mechd labs`;
  main.dataset.lab = lab.id;
  lab.mount(main);
}
window.addEventListener('hashchange', () => { show(); main.focus(); });
const proj = document.getElementById('projector');
proj.checked = localStorage.getItem('mechd-projector') === '1';
document.body.classList.toggle('projector', proj.checked);
proj.addEventListener('change', () => {
  document.body.classList.toggle('projector', proj.checked);
  localStorage.setItem('mechd-projector', proj.checked ? '1' : '0');
});
show();
