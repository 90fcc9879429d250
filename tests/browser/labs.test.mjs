// labs.test.mjs — the classroom front end in a real browser: playwright-core
// drives Debian's /usr/bin/chromium (headless, never a downloaded browser)
// against a real mechd started on port 0. For each lab: the page loads, the
// default request is submitted, the numbers the API returns are shown (checked
// against closed forms), and an invalid input shows its error next to the
// field it names. Then, as a user would: every worked example in
// every lab's picker loads, computes and leaves the picker showing it, with no
// error box and no "null", "undefined" or "NaN" on the page; at 390 px no lab
// scrolls sideways, plot text reads at >= 10 px and the spacetime β slider
// sits by its diagram; the Foucault pendulum at the equator says there is no
// precession; a request at work shows a busy state, disables its button and
// can be cancelled; and against a mechd started with --token-file the 401
// leads to an access-token field that makes the labs work. Screenshots of
// every lab at 1280×800 and 390×844 go to the directory given (default
// ./screenshots). Motion, 3-D and plots: animations play and pause, the time slider moves
// the time, 3-D views are drawn and turn on drag and keys (and keep their
// WebGL context over many visits), ticks are round, the orbit has equal
// aspect, log axes read 10ⁿ, and the CSV export holds the API's numbers;
// the Foucault pendulum's swing plane turns 360° sin λ on the floor in a
// sidereal day over a 3-D Earth, from the stars and from the ground; the
// players work by keyboard; the orbit and top labs predict a run's cost from
// the operation's dry run, and a cancelled run stops the server's work (its
// /metrics: no answer, no worker busy, before the deadline would end it); the
// cannonball's animated flight lands where the scene says; the twins' clocks
// read their proper times as they are played; no table overflows at 390 px;
// and axe-core (pinned in package.json) finds no serious or critical
// accessibility violation in any lab at either size.
// Prints "N passed, M failed"; exits non-zero on a failure.
//
// usage: node labs.test.mjs MECHD_BINARY [SCREENSHOT_DIR]
// env:   MECHD_WEB_PROXY=1   serve clients/web (MECHD_WEB_ROOT) from a small
//                            Node server that forwards everything else to
//                            mechd — only for before mechd serves static files.
//        CHROMIUM            browser binary (default /usr/bin/chromium)
import {chromium} from 'playwright-core';
import {spawn, execFileSync} from 'node:child_process';
import fs from 'node:fs';
import http from 'node:http';
import path from 'node:path';
import {createRequire} from 'node:module';

const mechd = process.argv[2];
const shots = path.resolve(process.argv[3] || 'screenshots');
if (!mechd) { console.error('usage: node labs.test.mjs MECHD_BINARY [SCREENSHOT_DIR]'); process.exit(2); }
fs.mkdirSync(shots, {recursive: true});

let passed = 0, failed = 0;
const check = (ok, what) => { if (ok) passed++; else { failed++; console.error('FAIL: ' + what); } };
const close = (got, want, rtol, what) => check(Number.isFinite(got) && Math.abs(got - want) <= rtol * Math.abs(want),
  `${what}: got ${got}, want ${want} (rtol ${rtol})`);

// --- start mechd on a free port ----------------------------------------------
// --static-dir: the front end of this source tree (run.sh sets MECHD_WEB_ROOT),
// whatever default the binary was compiled with.
const webRoot = path.resolve(process.env.MECHD_WEB_ROOT || 'clients/web');
// --deadline-ms 60000: a heavy worked example on a loaded machine (ctest -j with
// the sanitizer suites) must not run into the default 10 s deadline.
function startMechd(extra = []) {
  const proc = spawn(mechd, ['--port', '0', '--deadline-ms', '60000',
    ...(process.env.MECHD_WEB_PROXY === '1' ? [] : ['--static-dir', webRoot]), ...extra],
    {stdio: ['ignore', 'pipe', 'pipe']});
  proc.stderr.on('data', () => {});
  const url = new Promise((resolve, reject) => {
    let out = '';
    const t = setTimeout(() => reject(new Error('mechd did not print its address: ' + out)), 10000);
    proc.stdout.on('data', (d) => {
      out += d;
      const m = out.match(/listening on (http:\/\/\S+)/);
      if (m) { clearTimeout(t); resolve(m[1].replace(/\/$/, '')); }
    });
    proc.on('exit', (code) => reject(new Error('mechd exited with ' + code + ': ' + out)));
  });
  return {proc, url};
}
const mainServer = startMechd();
const server = mainServer.proc;
const base = await mainServer.url;

let origin = base, proxy = null;
if (process.env.MECHD_WEB_PROXY === '1') {
  const root = webRoot;
  const types = {'.html': 'text/html; charset=utf-8', '.js': 'text/javascript', '.css': 'text/css', '.svg': 'image/svg+xml'};
  proxy = http.createServer((req, res) => {
    const u = new URL(req.url, 'http://x');
    const p = u.pathname === '/' ? '/index.html' : u.pathname;
    const file = path.join(root, p);
    if (!p.startsWith('/v1') && file.startsWith(root + path.sep) && fs.existsSync(file) && fs.statSync(file).isFile()) {
      res.writeHead(200, {'Content-Type': types[path.extname(file)] || 'application/octet-stream'});
      return res.end(fs.readFileSync(file));
    }
    const f = http.request(base + req.url, {method: req.method, headers: req.headers}, (r) => {
      res.writeHead(r.statusCode, r.headers); r.pipe(res);
    });
    req.pipe(f);
  });
  await new Promise((r) => proxy.listen(0, '127.0.0.1', r));
  origin = `http://127.0.0.1:${proxy.address().port}`;
  console.log('NOTE: MECHD_WEB_PROXY=1: static files served by the test\'s own server, not mechd');
}

// --- static file serving through mechd ----------------------------------------
{
  const r = await fetch(origin + '/');
  const html = await r.text();
  check(r.status === 200 && html.includes('/app.js'), `GET / serves clients/web/index.html (status ${r.status})`);
  if (!proxy) {
    check((r.headers.get('content-security-policy') || '').includes("default-src 'self'"), 'GET / has a Content-Security-Policy');
    check(r.headers.get('x-content-type-options') === 'nosniff', 'GET / has X-Content-Type-Options: nosniff');
    const js = await fetch(origin + '/app.js');
    check(js.status === 200 && /javascript/.test(js.headers.get('content-type') || ''), 'GET /app.js is JavaScript');
    for (const bad of ['/../CMakeLists.txt', '/%2e%2e/CMakeLists.txt', '/labs/../../README.md', '/.gitignore'])
      check((await fetch(origin + bad)).status === 404, `GET ${bad} is refused with 404`);
  }
}

// --- the root of "null" on the page: the DOM's append/replaceChildren print a null
// child as the text "null"; outside lib.js (whose put/add/el skip null) they are not used
{
  const files = ['app.js', ...fs.readdirSync(path.join(webRoot, 'labs')).filter(f => f.endsWith('.js')).map(f => 'labs/' + f)];
  const raw = files.flatMap(f => fs.readFileSync(path.join(webRoot, f), 'utf8').split('\n')
    .map((line, i) => [f, i + 1, line]).filter(([, , line]) => /\.(append|replaceChildren|prepend)\(/.test(line)));
  check(raw.length === 0, `labs build the DOM through lib.js put/add/el, never append/replaceChildren (${raw.slice(0, 3)
    .map(([f, n, l]) => `${f}:${n}: ${l.trim().slice(0, 60)}`).join(' | ')}${raw.length > 3 ? ` … ${raw.length} in all` : ''})`);
}

// --- the browser ---------------------------------------------------------------
// Playwright gives every launch() a new empty profile directory of its own (the
// fresh --user-data-dir machine.md asks for; passing one explicitly is refused).
const browser = await chromium.launch({
  executablePath: process.env.CHROMIUM || '/usr/bin/chromium', headless: true,
  args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking',
         '--disable-component-update', '--disable-sync'],
});
const page = await browser.newPage({viewport: {width: 1280, height: 900}});
const consoleErrors = [];
// 4xx answers to the deliberately invalid requests (and a 404 for /v1/examples
// while it does not exist) are logged by Chromium as "Failed to load resource":
// expected; anything else (a script error, a CSP violation) fails the lab.
page.on('console', (m) => {
  if (m.type() === 'error' && !/Failed to load resource: the server responded with a status of 4\d\d/.test(m.text()))
    consoleErrors.push(m.text());
});
page.on('pageerror', (e) => consoleErrors.push(String(e)));
// too many WebGL contexts (a 3-D view made anew on every visit) is only a warning in the console: count it
page.on('console', (m) => { if (m.type() === 'warning' && /WebGL context/.test(m.text())) consoleErrors.push(m.text()); });

const value = async (sel) => Number(await page.getAttribute(sel, 'data-value', {timeout: 15000}));
const state = (form, s) => page.waitForSelector(`${form}[data-state="${s}"]`, {timeout: 20000});
async function invalid(form, input, bad, submit, contains) {
  await page.fill(input, String(bad));
  await page.click(submit);
  await state(form, 'error');
  check(await page.getAttribute(input, 'aria-invalid') === 'true', `${input} = ${bad} is marked invalid`);
  const msg = await page.textContent(input + '-err');
  check(msg && msg.includes(contains), `${input} = ${bad} shows its error next to it (got "${msg}")`);
}
async function lab(id, body, name = 'lab-' + id) {
  try {
    consoleErrors.length = 0;
    await page.goto('about:blank'); // a fresh page load for every lab
    await page.goto(`${origin}/#${id}`);
    await page.waitForSelector(`main[data-lab]`, {timeout: 10000});
    await body();
    check(consoleErrors.length === 0, `${id}: no console errors (${consoleErrors.join(' | ')})`);
  } catch (e) {
    check(false, `${id}: ${e.message.split('\n')[0]}`);
  } finally {
    await page.screenshot({path: path.join(shots, `${name}.png`), fullPage: true}).catch(() => {});
  }
}

await lab('inertia', async () => {
  await state('main form', 'done');
  // notes §2.4: unit cube of unit mass about a corner: 1/6, 11/12, 11/12
  close(await value('#inertia-moment-0'), 1 / 6, 1e-12, 'cube: I1 = 1/6');
  close(await value('#inertia-moment-1'), 11 / 12, 1e-12, 'cube: I2 = 11/12');
  close(await value('#inertia-moment-2'), 11 / 12, 1e-12, 'cube: I3 = 11/12');
  check((await page.textContent('.curl pre')).includes('/v1/rigid/inertia'), 'inertia: curl command shown');
  await invalid('main form', '#inertia-mass-0', -1, '#inertia-submit', 'more than 0');
  // keyboard: the view rotates with the arrow keys without an error
  await page.focus('#inertia-view'); await page.keyboard.press('ArrowLeft');
  // every worked example offered loads and computes without an error
  const n = await page.$$eval('.examples select option', (o) => o.length);
  check(n >= 1, `inertia: worked examples offered (${n})`);
  for (let i = 0; i < n; i++) {
    await page.selectOption('.examples select', String(i));
    await page.click('.examples button');
    await page.waitForFunction(() => document.querySelector('main form')?.dataset.state, null, {timeout: 20000});
    await state('main form', 'done').catch(() => {});
    const st = await page.getAttribute('main form', 'data-state');
    check(st === 'done', `inertia: worked example ${i + 1} of ${n} computes (state ${st}: ${await page.textContent('[data-role=problem]')})`);
  }
});

await lab('keyboard', async () => {
  await page.keyboard.press('Tab');
  check(await page.evaluate(() => document.activeElement.className) === 'skip', 'keyboard: Tab reaches the skip link first');
  await page.keyboard.press('Tab');
  const tabIds = await page.$$eval('#tabs a', (as) => as.map(a => a.id.replace(/^tab-/, '')));
  check(await page.evaluate(() => document.activeElement.id) === 'tab-' + tabIds[0], 'keyboard: then the lab tabs');
  await page.keyboard.press('Tab'); await page.keyboard.press('Enter');
  await page.waitForSelector(`main[data-lab="${tabIds[1]}"]`, {timeout: 10000});
  check(true, 'keyboard: Enter on a tab opens its lab');
});

await lab('spacetime', async () => {
  await state('main form', 'done');
  // beta = 0.6: gamma = 1.25; (ct, x) = (1, 0) -> (gamma, -gamma beta) = (1.25, -0.75)
  close(await value('#st-gamma'), 1.25, 1e-14, 'boost: gamma(0.6) = 1.25');
  close(await value('#st-ctp-0'), 1.25, 1e-14, "boost: ct' = 1.25");
  close(await value('#st-xp-0'), -0.75, 1e-14, "boost: x' = -0.75");
  await state('#twin-form', 'done');
  // 8 ly out and back at 0.8 c: home 2*8/0.8 = 20 yr, traveller 20/gamma = 12 yr
  close(await value('#tw-home'), 20, 1e-12, 'twins: stay-at-home 20 yr');
  close(await value('#tw-proper'), 12, 1e-12, 'twins: traveller 12 yr');
  await invalid('main form', '#st-beta', 1.5, '#st-submit', 'beta');
  await invalid('#twin-form', '#tw-dist', -8, '#tw-submit', 'more than 0');
  const general = await page.textContent('#twin-form + .problem');
  check(!general.includes('/legs/'), `twins: both legs' errors sit at the distance field (box: "${general}")`);
});

await lab('earth', async () => {
  await state('#fall-form', 'done');
  const w = 7.292115e-5, g = 9.80665, h = 100, lat = 32 * Math.PI / 180;
  const east = w * Math.cos(lat) * Math.sqrt(8 * h ** 3 / g) / 3; // notes: x_east = (1/3) w cos(lat) sqrt(8h^3/g)
  close(await value('#fall-east-1'), east, 1e-9, 'falling object: first-order east deflection');
  close(await value('#fall-east'), east, 1e-6, 'falling object: numerical east deflection (second order ~ 1e-7 relative)');
  close(await value('#fall-t'), Math.sqrt(2 * h / g), 1e-6, 'falling object: fall time sqrt(2h/g)');
  await state('#fou-form', 'done');
  const wsin = w * Math.sin(48.846 * Math.PI / 180) * 180 / Math.PI * 3600; // deg/hour
  close(Math.abs(await value('#fou-first')), wsin, 1e-9, 'Foucault: omega sin(lat) in deg/h');
  close(Math.abs(await value('#fou-rate')), wsin, 2e-3, 'Foucault: measured rate within the Airy correction');
  await state('#can-form', 'done');
  check((await value('#can-right')) > 0, 'cannonball: deflected to the right in the northern hemisphere');
  check(['coriolis', 'coriolis_centrifugal'].includes(await page.getAttribute('#fall-model-used', 'data-value')), 'falling object: the answer names the model auto solved');
  // the textbooks' model asked for by name: the run solves r'' = g - 2 w x r' and names it; its exact
  // landing (the linear equation's matrix exponential, mpmath) is 0.018618187559714791 m east
  await page.selectOption('#fall-model', 'coriolis');
  await page.evaluate(() => { delete document.querySelector('#fall-form').dataset.state; });
  await page.click('#fall-submit');
  await state('#fall-form', 'done');
  check((await page.getAttribute('#fall-model-used', 'data-value')) === 'coriolis', 'falling object: the model chosen is the one solved and named');
  close(await value('#fall-east'), 0.018618187559714791, 1e-6, 'falling object: Coriolis only, against the exact landing');
  await page.selectOption('#fall-model', 'auto');
  await invalid('#fall-form', '#fall-height', -5, '#fall-submit', 'more than 0');
  await invalid('#can-form', '#can-lat', 95, '#can-submit', '90');
});

await lab('tops', async () => {
  await state('main form', 'done');
  close(await value('#top-thmin'), 0.5, 1e-12, 'top: released at rest in theta, theta_min = theta0');
  // sleeping-top test I3^2 w3^2 > 4 I1 M g h: 0.36 > 0.0784532 -> stable
  check((await page.textContent('#top-sleeping')) === 'true', 'top: the sleeping-top condition holds');
  await state('#dz-form', 'done');
  check(Number.isFinite(await value('#dz-flip')), 'Dzhanibekov: the exact flip interval is shown');
  await invalid('main form', '#top-I1', 0, '#top-submit', 'more than 0');
});

await lab('orbits', async () => {
  await state('main form', 'done');
  const GM = 1.32712440041279419e20, c = 299792458, a = 57909050000, e = 0.20563593;
  close(await value('#orb-first'), 6 * Math.PI * GM / (c * c * a * (1 - e * e)), 1e-9, 'Mercury: 6 pi GM/(c^2 a (1-e^2))');
  close(await value('#orb-century'), 42.98, 1e-3, 'Mercury: 43 arcsec per century');
  await invalid('main form', '#orb-e', 1.5, '#orb-submit', 'less than 1');
  await state('#light-form', 'done');
  const b = 696340000, arcsec = 180 / Math.PI * 3600;
  close(await value('#light-first'), 4 * GM / (c * c * b) * arcsec, 1e-9, 'light bending: 4GM/(c^2 b) at the limb');
  close(await value('#light-measured'), 1.75, 1e-3, 'light bending: 1.75 arcsec measured');
  await invalid('#light-form', '#light-b', -1, '#light-submit', 'at least 0');
});

await lab('accuracy', async () => {
  await state('main form', 'done');
  const rows = await page.$$('#acc-table tr');
  check(rows.length > 4, `accuracy: the runs are listed (${rows.length - 1})`);
  check(await page.$('#acc-plot polyline') !== null, 'accuracy: the work-precision plot is drawn');
  await invalid('main form', '#acc-t', -20, '#acc-submit', 'more than 0');
});

// --- the labs as a user meets them ----------------------------------------------
const LABS = ['inertia', 'spacetime', 'earth', 'tops', 'orbits', 'accuracy', 'rotations', 'table', 'tides', 'phase', 'particles'];

// Wait until every form of the lab has answered (done, error or cancelled) and
// none is busy; forms whose state was cleared must answer again.
const settled = () => page.waitForFunction(() => {
  const forms = [...document.querySelectorAll('main form')];
  return forms.length > 0 && forms.every(f => f.dataset.state && f.dataset.state !== 'busy');
}, null, {timeout: 20000});

// What a reader sees that should not be there: "null", "undefined" or "NaN"
// (outside the curl command, whose JSON may say "kind":"null"), an error box
// or a field error. Returns a list of findings.
const blemishes = () => page.evaluate(() => {
  const found = [];
  let text = document.body.innerText;
  for (const pre of document.querySelectorAll('.curl pre')) text = text.split(pre.innerText).join(' ');
  // (not \b: "for /v1null" and "10000000null" have no word boundary before "null")
  for (const m of text.matchAll(/(?<![A-Za-z])(null|undefined|NaN)(?![A-Za-z])/g))
    found.push(`"${m[1]}" in "…${text.slice(Math.max(0, m.index - 40), m.index + 20).replace(/\s+/g, ' ')}…"`);
  for (const b of document.querySelectorAll('.problem, .err'))
    if (b.textContent.trim() && b.getClientRects().length) found.push(`error shown: "${b.textContent.trim().slice(0, 120)}"`);
  return found;
});

// Every worked example in the lab's picker: load it, let it compute, look.
async function everyExample(id) {
  const n = await page.$$eval('.examples select option', (o) => o.length);
  check(n >= 1, `${id}: worked examples offered (${n})`);
  for (let i = 0; i < n; i++) {
    const title = await page.$eval('.examples select', (s, i) => s.options[i].textContent, i);
    await page.evaluate(() => { for (const f of document.querySelectorAll('main form')) delete f.dataset.state; });
    await page.selectOption('.examples select', String(i));
    await page.click('.examples button');
    // a loaded example runs one of the lab's forms; wait for it (the others keep no state)
    await page.waitForFunction(() => [...document.querySelectorAll('main form')].some(f => f.dataset.state &&
      f.dataset.state !== 'busy') && ![...document.querySelectorAll('main form')].some(f => f.dataset.state === 'busy'),
      null, {timeout: 20000}).catch(() => {});
    const states = await page.$$eval('main form', (fs) => fs.map(f => f.dataset.state || '-').join(','));
    check(!states.includes('error'), `${id}: example "${title}" computes (form states ${states})`);
    const bad = await blemishes();
    check(bad.length === 0, `${id}: example "${title}" leaves a clean page (${bad.join(' | ')})`);
    const shown = await page.$eval('.examples select', (s) => s.selectedOptions[0] ? s.selectedOptions[0].textContent : '(none)');
    check(shown === title, `${id}: the picker still shows the loaded example "${title}" (shows "${shown}")`);
  }
}


// --- each lab teaches: the notes' formula, its section, its value beside the API's, the
// difference in words; "Copy as curl" and "Copy as Python" put the request on the clipboard; changing an
// input changes the answer; at desktop and at phone size (where every worked example is loaded again) ----
// For each lab: an input, a new value for it, the button that runs it, and a number the answer shows.
const CHANGE = {
  rotations: ['#rot-phi', '61', '#rot-submit', '#rot-matrix-00'], table: ['#table-omega', '2.3', '#table-submit', '#table-total'],
  inertia: ['#inertia-mass-0', '2.7', '#inertia-submit', '#inertia-moment-0'], tops: ['#top-psidot', '83', '#top-submit', '#top-prec'],
  earth: ['#fall-height', '217', '#fall-submit', '#fall-east'], tides: ['#tides-point', '33', '#tides-submit', '#tides-moon-radial'],
  orbits: ['#orb-e', '0.31', '#orb-submit', '#orb-measured'], phase: ['#ph-b', '0.27', '#ph-submit', '#ph-area0'],
  spacetime: ['#st-beta', '0.77', '#st-submit', '#st-gamma'], particles: ['#dk-T', '123', '#dk-submit', '#dk-gamma'],
  accuracy: ['#acc-v', '1.13', '#acc-submit', '#acc-table'],
};
await page.context().grantPermissions(['clipboard-read', 'clipboard-write'], {origin});
// What every "What the notes say" box on the page shows: its formula, section and difference.
const teachBoxes = () => page.$$eval('[data-role=teach]', (bs) => bs.filter(b => b.querySelector('h3')).map(b => ({
  id: b.id, formula: (b.querySelector('[data-role=formula]') || {}).innerText || '',
  section: (b.querySelector('[data-role=section]') || {}).textContent || '',
  abs: Number(b.dataset.abs), rel: Number(b.dataset.rel),
  words: (b.querySelector('[data-role=diff]') || {}).innerText || '',
  shown: !!b.getClientRects().length,
})));
async function teaches(where, id) {
  const boxes = await teachBoxes();
  check(boxes.length >= 1, `${where} ${id}: a "What the notes say" section (${boxes.length})`);
  for (const b of boxes) {
    check(b.shown && b.formula.trim().length > 5, `${where} ${id}: #${b.id} shows a formula ("${b.formula.slice(0, 60)}")`);
    check(/^§\d+(\.\d+)?$/.test(b.section.trim()), `${where} ${id}: #${b.id} names the notes' section ("${b.section}")`);
    check(Number.isFinite(b.abs) && b.abs >= 0 && Number.isFinite(b.rel) && b.rel >= 0 && /\d/.test(b.words),
      `${where} ${id}: #${b.id} gives the difference as a finite number (abs ${b.abs}, rel ${b.rel}: "${b.words}")`);
  }
}
// The copy buttons of the lab's first request box: the clipboard then holds the text shown (or, where
// the clipboard is refused, the text is selected for Ctrl+C and the button says so).
async function copies(where, id) {
  const curlBox = page.locator('main section.curl').first();
  await curlBox.scrollIntoViewIfNeeded();
  for (const kind of ['curl', 'python']) {
    if (kind === 'python') await curlBox.locator('details.python > summary').click();
    const pre = curlBox.locator(kind === 'curl' ? 'pre[aria-label="curl command"]' : 'pre[data-role=python]');
    const want = await pre.textContent();
    await page.evaluate(() => navigator.clipboard.writeText('').catch(() => {}));
    await curlBox.locator(`button[data-copy=${kind}]`).click();
    await page.waitForFunction((k) => /Copied|Selected/.test(document.querySelector(`main section.curl button[data-copy=${k}]`).textContent),
      kind, {timeout: 5000}).catch(() => {});
    const said = await curlBox.locator(`button[data-copy=${kind}]`).textContent();
    // the clipboard, or (the clipboard refused) the selection the button made for Ctrl+C
    const clip = await page.evaluate(() => navigator.clipboard.readText()).catch(() => null);
    const got = clip === want ? clip : await page.evaluate(() => String(getSelection()));
    // the operation, from the curl line (its URL's path); the Python calls its method (or Client.batch)
    const curlText = await curlBox.locator('pre[aria-label="curl command"]').textContent();
    const path0 = (curlText.match(/'https?:\/\/[^/']+(\/v1\/[a-z/-]+)'$/) || [])[1] || '';
    const call = (want.match(/^answers? = m\.([a-z_]+)\(/m) || [])[1];
    check(got === want && path0 !== '' && (kind === 'curl' ? /^curl -s .*--json '\{/.test(want)
      : call === (path0 === '/v1/batch' ? 'batch' : path0.slice(4).replace(/[/-]/g, '_'))),
      `${where} ${id}: Copy as ${kind} puts the request (${path0}) on the clipboard ("${said}"; ${got.length} of ${want.length} characters)`);
    // at desktop size the copied Python runs, with the real client, against this server
    if (kind === 'python' && where === 'desktop') {
      let out = '';
      try {
        out = execFileSync('/usr/bin/python3', ['-c', got + '\nimport json\nr = answers if "answers" in dir() else answer\n' +
          'print(json.dumps(isinstance(r, dict) or (isinstance(r, list) and all(isinstance(a, dict) for a in r))))'],
          {env: {...process.env, PYTHONPATH: path.resolve(webRoot, '..', 'python')}, encoding: 'utf8', timeout: 60000}).trim();
      } catch (e) { out = String(e.stderr || e).trim().split('\n').slice(-1)[0]; }
      check(out === 'true', `${where} ${id}: the copied Python runs with clients/python/mechd.py and gets its answer (${out.slice(0, 160)})`);
    }
  }
  await curlBox.locator('details.python > summary').click(); // folded again
}
// Change one input, run, and the number shown changes.
async function changes(where, id) {
  const [input, v, submit, out] = CHANGE[id];
  const before = (await page.textContent(out)).trim();
  const isRange = await page.$eval(input, (e) => e.type === 'range');
  if (isRange) await page.$eval(input, (e, x) => { e.value = x; e.dispatchEvent(new Event('input', {bubbles: true})); }, v);
  else await page.fill(input, v);
  await page.evaluate((s) => { delete document.querySelector(s).closest('form').dataset.state; }, submit);
  await page.click(submit);
  await page.waitForFunction((s) => document.querySelector(s).closest('form').dataset.state === 'done', submit, {timeout: 30000}).catch(() => {});
  const after = (await page.textContent(out)).trim();
  check(after !== before && !/NaN|undefined|null/.test(after), `${where} ${id}: ${input} = ${v} changes ${out} ("${before.slice(0, 40)}" → "${after.slice(0, 40)}")`);
}
// the teaching sections against closed forms: the value each shows for the notes' formula is the formula's,
// and the difference it states is the one between the two numbers it shows
await lab('earth', async () => {
  await settled();
  const w = 7.292115e-5, g = 9.80665, D = Math.PI / 180;
  const box = async (id) => page.$eval(id, (b) => ({f: Number(b.querySelector('[data-role=formula-value]').dataset.value),
    a: Number(b.querySelector('[data-role=api-value]').dataset.value), abs: Number(b.dataset.abs), rel: Number(b.dataset.rel),
    words: b.querySelector('[data-role=diff]').textContent, section: b.dataset.section}));
  const fall = await box('#fall-notes');
  // notes §1.4: x_east = (1/3) ω cos λ √(8h³/g) = 1.862 cm for 100 m at 32° ("about 1.9 cm")
  close(fall.f, w * Math.cos(32 * D) / 3 * Math.sqrt(8 * 100 ** 3 / g), 1e-12, 'teach: the falling object\'s formula value is (1/3) ω cos λ √(8h³/g)');
  close(fall.abs, Math.abs(fall.a - fall.f), 1e-6, 'teach: the falling object\'s stated difference is numerical − first order');
  close(fall.rel, fall.abs / Math.abs(fall.a), 1e-12, 'teach: its relative difference is |difference| / numerical');
  check(fall.section === '1.4' && /pm, \d parts? in 10⁸/.test(fall.words),
    `teach: the falling object cites §1.4 (the notes' text) and says the difference in pm and parts in 10⁸ ("${fall.words}", §${fall.section})`);
  const fou = await box('#fou-notes');
  // notes §1.4: the plane turns at ω_z = ω sin λ, clockwise in the north: −11.3 °/h at 48.846° N
  close(fou.f, -w * Math.sin(48.846 * D) / D * 3600, 1e-9, 'teach: the Foucault formula value is −ω sin λ in °/h');
  check(fou.abs > 0 && fou.rel < 0.01, `teach: the measured Foucault rate is within 1 % of ω sin λ (rel ${fou.rel})`);
}, 'teach-earth');
await lab('spacetime', async () => {
  await settled();
  const f = Number(await page.getAttribute('#tw-notes [data-role=formula-value]', 'data-value'));
  close(f, 12, 1e-12, 'teach: the twins\' τ = t/γ summed over the legs is 12 yr (8 ly at β = 0.8 and back)');
  check(await page.getAttribute('#tw-notes', 'data-section') === '3.15', 'teach: the twins cite §3.15 (from the contents)');
  check(/lost it/.test(await page.textContent('#tw-notes')), 'teach: and say that number is not in the extracted text');
  check(Number(await page.getAttribute('#st-notes', 'data-abs')) < 1e-14, 'teach: the boost formula agrees with the API to round-off');
  // near the cancellation: β = 1 − 10⁻¹⁰ and an event on the light cone, ct′ = x′ = γ(1 − β) = √((1 − β)/(1 + β)) = 7.07·10⁻⁶,
  // beside an event off it (2, 1) whose ct′ is 7·10⁴: the page's formula takes 1 − β² as (1 − β)(1 + β) and keeps the digits
  const b = 0.9999999999;
  await page.fill('#st-events', '1, 1; 2, 1'); await page.fill('#st-beta', String(b));
  await page.evaluate(() => { delete document.querySelector('#st-submit').closest('form').dataset.state; });
  await page.click('#st-submit');
  await page.waitForFunction(() => document.querySelector('#st-submit').closest('form').dataset.state === 'done', null, {timeout: 20000});
  const want = Math.sqrt((1 - b) / (1 + b)), gam = 1 / Math.sqrt((1 - b) * (1 + b));
  close(await value('#st-ctp-0'), want, 1e-12, 'teach: on the light cone at β = 1 − 10⁻¹⁰ the API\'s ct′ is √((1 − β)/(1 + β))');
  close(await value('#st-ctp-1'), gam * (2 - b), 1e-12, 'teach: and off it ct′ = γ(2 − β)');
  const near = await page.$eval('#st-notes [data-role=formula-value]', (d) => d.textContent);
  check(/ct′ = 7\.071068e-6, x′ = 7\.071068e-6/.test(near), `teach: the page's formula gives the light-cone event's 7.071068·10⁻⁶ too ("${near}")`);
  check(Number(await page.getAttribute('#st-notes', 'data-rel')) < 1e-14, 'teach: and agrees with the API to round-off at β = 1 − 10⁻¹⁰');
}, 'teach-spacetime');
await lab('accuracy', async () => {
  await settled();
  // H = v²/2 − GM/r = 0.72 − 1 = −0.28 for the Kepler scene (m = 1, GM = 1, r = 1, v = 1.2)
  check(/H = −?-?0\.28\b/.test(await page.textContent('#acc-notes [data-role=formula-value]')), 'teach: the Kepler scene\'s energy is −0.28');
  const rel = Number(await page.getAttribute('#acc-notes', 'data-rel'));
  check(rel > 0 && rel < 1e-6, `teach: the best run keeps the energy to better than 10⁻⁶ (${rel})`);
}, 'teach-accuracy');

// no form of the lab busy (after the examples, the forms no example ran keep no state)
const quiet = () => page.waitForFunction(() => ![...document.querySelectorAll('main form')].some(f => f.dataset.state === 'busy'),
  null, {timeout: 30000});
for (const [where, size] of [['desktop', {width: 1280, height: 900}], ['phone', {width: 390, height: 844}]]) {
  await page.setViewportSize(size);
  for (const id of LABS) await lab(id, async () => {
    await settled();
    const bad = await blemishes();
    check(bad.length === 0, `${where} ${id}: the default page is clean (${bad.join(' | ')})`);
    await teaches(where, id);
    await everyExample(where === 'desktop' ? id : `phone ${id}`);
    await quiet();
    await teaches(where, id); // after the last example too
    await copies(where, id);
    await changes(where, id);
  }, where === 'desktop' ? `examples-${id}` : `examples-phone-${id}`);
}
await page.setViewportSize({width: 1280, height: 900});

// a body whose principal moments all differ: a 1 × 2 × 3 m box of 1 kg about its
// centre has I = M(b² + c²)/12 … = 5/12, 10/12, 13/12 kg m², no "degenerate" note
// (whose absence left the text "null" on the page)
await lab('inertia', async () => {
  await settled();
  await page.selectOption('#inertia-origin', 'center_of_mass');
  for (const [j, v] of [[0, 1], [1, 2], [2, 3]]) await page.fill(`#inertia-size-0-${j}`, String(v));
  await page.evaluate(() => { delete document.querySelector('main form').dataset.state; });
  await page.click('#inertia-submit');
  await state('main form', 'done');
  const I = [await value('#inertia-moment-0'), await value('#inertia-moment-1'), await value('#inertia-moment-2')].sort((a, b) => a - b);
  close(I[0], 5 / 12, 1e-12, 'box 1×2×3: I1 = M(a² + b²)/12 = 5/12');
  close(I[1], 10 / 12, 1e-12, 'box 1×2×3: I2 = M(a² + c²)/12 = 10/12');
  close(I[2], 13 / 12, 1e-12, 'box 1×2×3: I3 = M(b² + c²)/12 = 13/12');
  const bad = await blemishes();
  check(bad.length === 0, `inertia with distinct moments: a clean page (${bad.join(' | ')})`);
  // ω = (1, 2, 3) along the box's edges: T = ½ Σ I_k ω_k² = ½ (13/12 + 4·10/12 + 9·5/12) = 49/12
  for (const [j, v] of [[0, 1], [1, 2], [2, 3]]) await page.fill(`#inertia-omega-${j}`, String(v), {timeout: 5000});
  await page.evaluate(() => { delete document.querySelector('main form').dataset.state; });
  await page.click('#inertia-submit');
  await state('main form', 'done');
  close(await value('#inertia-T'), 49 / 12, 1e-12, 'box 1×2×3 turning at ω = (1, 2, 3): T = ½ ω·Iω = 49/12');
}, 'inertia-distinct');

// a problem without field errors is shown as its title and detail, nothing appended: the
// server's answer when a run exhausts its step budget (answered here by the test: a real
// one takes seconds of CPU)
await lab('tops', async () => {
  await settled();
  await page.route('**/v1/rigid/top', (route) => route.fulfill({status: 422, contentType: 'application/problem+json',
    body: JSON.stringify({type: '/problems/compute-budget-exceeded', title: 'Compute budget exceeded', status: 422,
      detail: 'step budget of 10000000 steps exhausted', progress: {limit: 'max_steps', steps: 10000001}})}));
  await page.click('#top-submit');
  await state('main form', 'error');
  const box = (await page.textContent('main .problem')).trim();
  check(box === '422 Compute budget exceeded: step budget of 10,000,000 steps exhausted',
    `a problem's detail is shown as it is, nothing appended (got "${box}")`);
  await page.unrouteAll({behavior: 'ignoreErrors'});
}, 'problem-detail');

// the Foucault pendulum at the equator: ω sin λ = 0, no turn and nothing exaggerated
await lab('earth', async () => {
  await settled();
  await page.fill('#fou-lat', '0');
  await page.evaluate(() => { delete document.getElementById('fou-form').dataset.state; });
  await page.click('#fou-submit');
  await state('#fou-form', 'done');
  close(await value('#fou-first'), 0, 0, 'Foucault at the equator: ω sin λ = 0');
  const bad = await blemishes();
  check(bad.length === 0, `Foucault at the equator: a clean page (${bad.join(' | ')})`);
  const hours = await page.textContent('#fou-hours');
  check(/no precession/.test(hours), `Foucault at the equator: "no precession" where the full turn would be (got "${hours}")`);
  const label = await page.$eval('#fou-plot', (s) => s.textContent);
  check(!/×/.test(label) && /to scale/.test(label), `Foucault at the equator: the trace is drawn to scale, not exaggerated ("${label}")`);
}, 'foucault-equator');

// a request at work: busy state, disabled button, old results marked stale, Cancel aborts it.
// The compare request is held by the test (never answered) until the page cancels it.
await lab('accuracy', async () => {
  await settled();
  let held = null;
  const failedReq = new Promise((resolve) => page.on('requestfailed', (r) => { if (r.url().endsWith('/v1/compare')) resolve(r); }));
  await page.route('**/v1/compare', (route) => { held = route; });
  await page.click('#acc-submit');
  const busy = await page.waitForSelector('main form[data-state="busy"] [data-role="cancel"]', {timeout: 5000}).then(() => true, () => false);
  check(busy, 'busy: the form shows that work is running, with a Cancel button');
  if (busy) {
    check(await page.isDisabled('#acc-submit'), 'busy: the Compare button is disabled while it runs');
    const stale = await page.$eval('main .results', (r) => r.classList.contains('stale') && r.getAttribute('aria-busy') === 'true');
    check(stale, 'busy: the previous results are dimmed and marked aria-busy');
    await page.screenshot({path: path.join(shots, 'busy-accuracy.png')});
    await page.click('main [data-role="cancel"]');
    await state('main form', 'cancelled');
    const r = await Promise.race([failedReq, new Promise((res) => setTimeout(() => res(null), 5000))]);
    check(r !== null, 'busy: Cancel aborts the HTTP request (the server then stops the work)');
    check(!(await page.isDisabled('#acc-submit')), 'busy: after Cancel the button works again');
  }
  await page.unrouteAll({behavior: 'ignoreErrors'});
  if (held) held.abort().catch(() => {});
  await page.click('#acc-submit');
  await state('main form', 'done');
  const bad = await blemishes();
  check(bad.length === 0, `busy: after Cancel a new request computes cleanly (${bad.join(' | ')})`);
}, 'cancel-accuracy');

// a sweep cut short by its budget: the finished runs are shown, the rest say "not run" and why.
// The partial answer is a real one, from a second mechd with a step budget of 3000 per run.
{
  const small = startMechd(['--max-steps', '3000']);
  try {
    const sbase = await small.url;
    const body = {operation: '/v1/trajectory', request: {particle: {mass: 1, position: [1, 0, 0], velocity: [0, 1.2, 0]},
      forces: [{type: 'central_gravity', gm: 1}], t_end: 20, samples: 21},
      sweep: {methods: ['rk8pd', 'verlet'], tolerances: [1e-4], dts: [0.01, 0.001]}};
    const res = await fetch(sbase + '/v1/compare', {method: 'POST', headers: {'Content-Type': 'application/json'}, body: JSON.stringify(body)});
    const text = await res.text();
    const partial = res.status === 200 && JSON.parse(text).partial === true;
    check(partial, `partial compare: a step budget of 3000 cuts the dt 0.001 run (status ${res.status})`);
    if (partial) await lab('accuracy', async () => {
      await settled();
      await page.route('**/v1/compare', (route) => route.fulfill({status: 200, contentType: 'application/json', body: text}));
      await page.evaluate(() => { delete document.querySelector('main form').dataset.state; });
      await page.click('#acc-submit');
      await state('main form', 'done');
      const rows = await page.$$eval('#acc-table tr', (trs) => trs.slice(1).map(tr => tr.innerText.replace(/\s+/g, ' ').trim()));
      check(rows.length === 3 && /verlet dt 0\.01 \d/.test(rows[1]) && /^verlet dt 0\.001 not run: /.test(rows[2]),
        `partial compare: two finished rows and one "not run" row with its setting and reason (${rows.join(' | ')})`);
      const note = await page.textContent('main .results p');
      check(/not run/.test(note), `partial compare: the summary says the sweep was cut short ("${note}")`);
      const bad = await blemishes();
      check(bad.length === 0, `partial compare: a clean page (${bad.join(' | ')})`);
      await page.unrouteAll({behavior: 'ignoreErrors'});
    }, 'partial-accuracy');
  } finally { small.proc.kill(); }
}

// --- motion you can watch, 3-D you can turn, plots that read --------------------
// A 3-D canvas' pixels: how many are not the white background, and a digest
// to tell two frames apart (WebGL with preserveDrawingBuffer: readable).
const pixels = (sel) => page.$eval(sel, (c) => {
  const g = document.createElement('canvas'); g.width = c.width; g.height = c.height;
  const x = g.getContext('2d'); x.drawImage(c, 0, 0);
  const d = x.getImageData(0, 0, g.width, g.height).data;
  let ink = 0, h = 0;
  for (let i = 0; i < d.length; i += 4) {
    if (d[i] < 235 || d[i + 1] < 235 || d[i + 2] < 235) ink++;
    h = (h * 31 + d[i] + 7 * d[i + 1] + 13 * d[i + 2]) % 1000000007;
  }
  return {ink: ink / (d.length / 4), h, w: g.width};
});
const frameAfter = () => page.evaluate(() => new Promise(r => requestAnimationFrame(() => requestAnimationFrame(r))));
// Pause a player that is still playing. On a loaded machine the run may have
// reached its end (and stopped by itself) before the test's second click; a
// click then would play it again from the start, so the test clicks only a
// player that is playing, in the page, in one step.
const pauseIfPlaying = (btn) => page.evaluate((sel) => {
  const b = document.querySelector(sel), root = b.closest('[data-playing]');
  if (root && root.dataset.playing === 'true') b.click();
  return root ? root.dataset.playing : null;
}, btn);
// Are these tick labels round numbers, evenly spaced by 1, 2 or 5 × 10^k?
function roundTicks(labels) {
  const v = labels.map(s => Number(s.replace('−', '-')));
  if (v.length < 2 || v.some(x => !Number.isFinite(x))) return false;
  const step = v[1] - v[0], e = Math.floor(Math.log10(Math.abs(step))), m = Math.abs(step) / 10 ** e;
  return [1, 2, 5, 10].some(k => Math.abs(m - k) < 1e-9) &&
    v.every((x, i) => i === 0 || Math.abs(x - v[i - 1] - step) < 1e-9 * Math.abs(step) * 10) &&
    v.every(x => Math.abs(x / step - Math.round(x / step)) < 1e-6);
}
const tickLabels = (plot, axis) => page.$$eval(`${plot} text.tick-${axis}`, (ts) => ts.map(t => t.textContent));

await lab('tops', async () => {
  await settled();
  // the animation: Play advances the time shown, Pause stops it
  const player = '#top-3d-box ~ .player';
  const time = async () => Number(await page.getAttribute(player, 'data-time'));
  check(await page.$(player + ' [data-role=play]') !== null, 'animation: the top has a Play button');
  const t0 = await time();
  const before = await pixels('#top-view');
  await page.click(player + ' [data-role=play]');
  await page.waitForTimeout(700);
  const t1 = await time();
  check(t1 > t0, `animation: Play advances the top's time (${t0} -> ${t1})`);
  // Pause stops it: if the 2 s run has already ended (a loaded machine), play it
  // again and pause it in the same step
  const paused = await page.evaluate((sel) => {
    const b = document.querySelector(sel), root = b.closest('[data-playing]');
    if (root.dataset.playing !== 'true') b.click();
    b.click();
    return root.dataset.playing;
  }, player + ' [data-role=play]');
  check(paused === 'false', 'animation: Pause stops it');
  const t2 = await time(); await page.waitForTimeout(500);
  check(await time() === t2, `animation: paused, the time stays (${t2} -> ${await time()})`);
  await frameAfter();
  check((await pixels('#top-view')).h !== before.h, 'animation: the top in 3-D moved while playing');
  // the slider moves the time: End goes to the last sample (t_end = 2 s), Home back to 0
  await page.focus(player + ' [data-role=time]'); await page.keyboard.press('End');
  close(await time(), 2, 1e-12, 'animation: the time slider\'s End shows t = t_end');
  check((await page.textContent(player + ' [data-role=now]')).includes('t = 2 s'), 'animation: the time is written beside the slider');
  await page.keyboard.press('Home');
  check(await time() === 0, 'animation: Home goes back to t = 0');
  // 3-D: non-blank, turns on drag and on the arrow keys
  const p0 = await pixels('#top-view');
  check(p0.ink > 0.02, `3-D: the top's canvas shows something (${(p0.ink * 100).toFixed(1)} % inked)`);
  const box = await page.$eval('#top-view', (c) => { const r = c.getBoundingClientRect(); return [r.x, r.y, r.width, r.height]; });
  const yaw0 = await page.getAttribute('#top-view', 'data-yaw');
  await page.mouse.move(box[0] + box[2] / 2, box[1] + box[3] / 2); await page.mouse.down();
  await page.mouse.move(box[0] + box[2] / 2 + 120, box[1] + box[3] / 2 + 20, {steps: 6}); await page.mouse.up();
  await frameAfter();
  const p1 = await pixels('#top-view');
  check(await page.getAttribute('#top-view', 'data-yaw') !== yaw0 && p1.h !== p0.h, '3-D: dragging turns the view of the top');
  await page.focus('#top-view'); await page.keyboard.press('ArrowRight'); await frameAfter();
  check((await pixels('#top-view')).h !== p1.h, '3-D: the arrow keys turn the view of the top');
  // the free body in 3-D, animated from the attitude quaternions
  const d0 = await pixels('#dz-view');
  check(d0.ink > 0.02, `3-D: the free body's canvas shows something (${(d0.ink * 100).toFixed(1)} % inked)`);
  await page.focus('#dz-3d-box ~ .player [data-role=time]'); await page.keyboard.press('End'); await frameAfter();
  check((await pixels('#dz-view')).h !== d0.h, '3-D: the free body turns when the time slider moves');
  // plots that read: round ticks with units; export of the data as CSV holds the API's numbers
  const xt = await tickLabels('#top-theta-plot', 'x'), yt = await tickLabels('#top-theta-plot', 'y');
  check(roundTicks(xt) && roundTicks(yt), `plots: θ(t) ticks are round numbers (x: ${xt.join(' ')}; y: ${yt.join(' ')})`);
  const axis = await page.$$eval('#top-theta-plot text', (ts) => ts.map(t => t.textContent));
  check(axis.includes('t [s]') && axis.includes('θ [rad]'), 'plots: the axes carry their units');
  const [dl] = await Promise.all([page.waitForEvent('download', {timeout: 10000}),
    page.click('#top-theta-plot + .plot-tools [data-export=csv]')]);
  const csv = fs.readFileSync(await dl.path(), 'utf8').trim().split('\n');
  const req = {I1: 0.02, I3: 0.01, mass: 1, distance: 0.1, theta: 0.5, phi_dot: 0, psi_dot: 60, t_end: 2, samples: 801};
  const api = await (await fetch(base + '/v1/rigid/top', {method: 'POST', headers: {'Content-Type': 'application/json'},
    body: JSON.stringify(req)})).json();
  const rows = csv.slice(1).map(l => l.split(','));
  check(csv[0] === 'series,t [s],θ [rad]' && rows.length === api.t.length &&
    rows.every((r, i) => Number(r[1]) === api.t[i] && Number(r[2]) === api.theta[i]),
    `export: the θ(t) CSV holds the API's ${api.t.length} samples exactly (${csv.length - 1} rows; ${csv.slice(0, 2).join(' | ')})`);
  const [png] = await Promise.all([page.waitForEvent('download', {timeout: 10000}),
    page.click('#top-theta-plot + .plot-tools [data-export=png]')]);
  const head = fs.readFileSync(await png.path()).subarray(0, 8);
  check(head.toString('latin1', 1, 4) === 'PNG', 'export: PNG of the θ(t) plot is a PNG file');
  // hover read-out
  const pb = await page.$eval('#top-theta-plot', (c) => { const r = c.getBoundingClientRect(); return [r.x, r.y, r.width, r.height]; });
  await page.mouse.move(pb[0] + pb[2] * 0.5, pb[1] + pb[3] * 0.5);
  await page.mouse.move(pb[0] + pb[2] * 0.52, pb[1] + pb[3] * 0.3, {steps: 3});
  const ro = await page.getAttribute('#top-theta-plot', 'data-readout');
  check(/^θ: t = [\d.]+ s, θ = [\d.]+ rad$/.test(ro || ''), `plots: hovering reads out the nearest sample ("${ro}")`);
  check((await blemishes()).length === 0, `tops: a clean page after playing (${(await blemishes()).join(' | ')})`);
  // back and forth between labs 20 times: the WebGL renderers are reused (a browser allows only ~16 contexts)
  for (let i = 0; i < 20; i++) {
    await page.evaluate(() => { location.hash = '#inertia'; }); await page.waitForSelector('main[data-lab="inertia"]');
    await page.evaluate(() => { location.hash = '#tops'; }); await page.waitForSelector('main[data-lab="tops"]');
  }
  await settled(); await frameAfter();
  const again = await pixels('#dz-view');
  check(again.ink > 0.02, `3-D: after 20 visits the free body is still drawn (${(again.ink * 100).toFixed(1)} % inked)`);
  check(!consoleErrors.some(e => /WebGL context/.test(e)), `3-D: no WebGL context lost over 20 visits (${consoleErrors.join(' | ')})`);
}, 'anim-tops');

await lab('orbits', async () => {
  await settled();
  // equal aspect: one metre across is one metre up, and both axes share their power of ten
  const aspect = await page.$eval('#orb-plot', (svg) => {
    const num = (t) => Number(t.textContent.replace('−', '-'));
    const xs = [...svg.querySelectorAll('text.tick-x')], ys = [...svg.querySelectorAll('text.tick-y')];
    const kx = (Number(xs[1].getAttribute('x')) - Number(xs[0].getAttribute('x'))) / (num(xs[1]) - num(xs[0]));
    const ky = (Number(ys[0].getAttribute('y')) - Number(ys[1].getAttribute('y'))) / (num(ys[1]) - num(ys[0]));
    return [kx, ky, [...svg.querySelectorAll('text')].map(t => t.textContent).filter(t => /\[/.test(t))];
  });
  check(Math.abs(aspect[0] / aspect[1] - 1) < 0.02, `plots: the orbit is drawn with equal aspect (px per unit ${aspect[0].toFixed(3)} across, ${aspect[1].toFixed(3)} up)`);
  check(aspect[2].length === 2 && aspect[2][0].replace(/^x/, '') === aspect[2][1].replace(/^y/, '') && /×10/.test(aspect[2][0]),
    `plots: both orbit axes say the same power of ten once (${aspect[2].join(', ')})`);
  check(roundTicks(await tickLabels('#orb-plot', 'x')) && roundTicks(await tickLabels('#orb-plot', 'y')), 'plots: the orbit\'s ticks are round numbers');
  // the precession made visible: the exaggeration says by how much, and ×1 is offered
  const opts = await page.$$eval('#orb-exaggerate option', (o) => o.map(x => x.textContent));
  check(opts.some(o => /×1\)/.test(o)) && opts.some(o => /^×10[⁰-⁹]+$/.test(o)), `orbit: exaggeration choices say the factor (${opts.join(', ')})`);
  const note = await page.textContent('#orb-ex-note');
  check(/real advance 0\.10\d″ per orbit, drawn \d/.test(note), `orbit: the real advance and the drawn angle are written ("${note}")`);
  // the planet moves when played
  const cx0 = await page.getAttribute('#orb-planet', 'cx');
  await page.click('#orb-plot ~ .player [data-role=play]'); await page.waitForTimeout(600);
  await pauseIfPlaying('#orb-plot ~ .player [data-role=play]');
  check(await page.getAttribute('#orb-planet', 'cx') !== cx0, 'animation: Mercury moves along its orbit when played');
  // projector mode: the plot's text grows with the page's (4/3), redrawn at once
  const tickPx = () => page.$eval('#orb-plot text.tick-x', (t) => parseFloat(getComputedStyle(t).fontSize) * t.getScreenCTM().a);
  const before = await tickPx();
  await page.check('#projector');
  const big = await tickPx();
  await page.uncheck('#projector');
  check(big >= before * 1.3 && big >= 17, `projector mode: plot ticks grow with the page (${before.toFixed(1)} px -> ${big.toFixed(1)} px)`);
}, 'anim-orbits');

await lab('accuracy', async () => {
  await settled();
  const xt = await tickLabels('#acc-plot', 'x'), yt = await tickLabels('#acc-plot', 'y');
  check([...xt, ...yt].every(t => /^10[⁻]?[⁰¹²³⁴⁵⁶⁷⁸⁹]+$/.test(t)) && yt.length >= 2,
    `plots: log axes are labelled as powers of ten (x: ${xt.join(' ')}; y: ${yt.join(' ')})`);
}, 'ticks-accuracy');

await lab('spacetime', async () => {
  await settled();
  // the Minkowski diagram has tick values: round numbers on x and ct, the boosted axes numbered too
  const xt = await tickLabels('#st-diagram', 'x'), yt = await tickLabels('#st-diagram', 'y');
  const and0 = (l) => [...l, '0'].sort((a, b) => Number(a.replace('−', '-')) - Number(b.replace('−', '-'))); // the origin is not labelled
  check(roundTicks(and0(xt)) && roundTicks(and0(yt)) && xt.includes('1') && yt.includes('1'), `Minkowski: x and ct carry round tick values (x: ${xt.join(' ')}; ct: ${yt.join(' ')})`);
  const bt = await page.$$eval('#st-diagram text.tick-ctp, #st-diagram text.tick-xp', (ts) => ts.map(t => t.textContent));
  check(bt.includes('1') && bt.includes('−1'), `Minkowski: the boosted axes' marks are numbered (${bt.join(' ')})`);
  const [dl] = await Promise.all([page.waitForEvent('download', {timeout: 10000}),
    page.click('#st-diagram + .plot-tools [data-export=csv]')]);
  const rows = fs.readFileSync(await dl.path(), 'utf8').trim().split('\n');
  // beta = 0.6: (ct, x) = (1, 0) -> (1.25, -0.75), the numbers exactly as the API gave them (the table's data-value)
  const r1 = rows[1].split(','), api = [await page.getAttribute('#st-ctp-0', 'data-value'), await page.getAttribute('#st-xp-0', 'data-value')];
  check(r1[0] === '1' && r1[1] === '1' && r1[2] === '0' && r1[3] === api[0] && r1[4] === api[1] && r1[5] === '0.6',
    `export: the Minkowski CSV holds the events and the API's boosted values ("${rows[1]}", API ${api.join(', ')})`);
  close(Number(r1[3]), 1.25, 1e-14, "export: the CSV's ct' = 1.25"); close(Number(r1[4]), -0.75, 1e-14, "export: the CSV's x' = -0.75");
}, 'ticks-spacetime');

await lab('inertia', async () => {
  await settled();
  const p0 = await pixels('#inertia-view');
  check(p0.ink > 0.02, `3-D: the inertia body is drawn (${(p0.ink * 100).toFixed(1)} % inked)`);
  await page.focus('#inertia-view'); await page.keyboard.press('ArrowLeft'); await page.keyboard.press('ArrowUp'); await frameAfter();
  check((await pixels('#inertia-view')).h !== p0.h, '3-D: the arrow keys turn the inertia body');
}, 'turn-inertia');

await lab('earth', async () => {
  await settled();
  const cx0 = await page.getAttribute('#fou-bob', 'cx');
  await page.click('#fou-plot ~ .player [data-role=play]');
  // (a loaded machine may draw few frames in a moment: wait for the bob to leave its start, up to 5 s)
  await page.waitForFunction((c) => document.getElementById('fou-bob').getAttribute('cx') !== c, cx0, {timeout: 5000}).catch(() => {});
  await pauseIfPlaying('#fou-plot ~ .player [data-role=play]');
  check(await page.getAttribute('#fou-bob', 'cx') !== cx0, 'animation: the Foucault bob swings when played');
  // the falling object falls when played (from /v1/trajectory's samples), and lands where the scene says
  await page.waitForSelector('#fall-dot', {timeout: 15000});
  const cy0 = Number(await page.getAttribute('#fall-dot', 'cy'));
  await page.click('#fall-path ~ .player [data-role=play]'); await page.waitForTimeout(700);
  check(Number(await page.getAttribute('#fall-dot', 'cy')) > cy0, 'animation: the falling object falls when played');
  const [dl] = await Promise.all([page.waitForEvent('download', {timeout: 10000}),
    page.click('#fall-path + .plot-tools [data-export=csv]')]);
  const last = fs.readFileSync(await dl.path(), 'utf8').trim().split('\n').filter(l => l.startsWith('with Coriolis')).pop().split(',');
  close(Number(last[1]) / 100, await value('#fall-east'), 1e-6, 'falling object: the animated path lands where the scene says (east)');
  check(Math.abs(Number(last[2])) < 1e-9, `falling object: the animated path ends on the ground (z = ${last[2]})`);
}, 'anim-earth');

// --- the newer labs (rotations, rotating table, tides,
// phase space, particles), each against closed forms computed here ------------
const clearStates = () => page.evaluate(() => { for (const f of document.querySelectorAll('main form')) delete f.dataset.state; });
const setRange = (sel, v) => page.$eval(sel, (e, v) => { e.value = String(v); e.dispatchEvent(new Event('input', {bubbles: true})); }, v);
const num2 = async (sel) => (await page.getAttribute(sel, 'data-value', {timeout: 15000})).split(',').map(Number);
// the passive z-x-z matrix R = Rψ Rθ Rφ as a product of the three elementary turns
function zxz(f, t, p) {
  const Rz = (a) => [[Math.cos(a), Math.sin(a), 0], [-Math.sin(a), Math.cos(a), 0], [0, 0, 1]];
  const Rx = (a) => [[1, 0, 0], [0, Math.cos(a), Math.sin(a)], [0, -Math.sin(a), Math.cos(a)]];
  const mul = (A, B) => A.map((r, i) => B[0].map((_, j) => r.reduce((s, _, k) => s + A[i][k] * B[k][j], 0)));
  return mul(Rz(p), mul(Rx(t), Rz(f)));
}
const rotMatrix = async (id) => { const m = []; for (let i = 0; i < 3; i++) { m.push([]); for (let j = 0; j < 3; j++) m[i].push(await value(`#${id}-${i}${j}`)); } return m; };
const maxDiff = (A, B) => Math.max(...A.flatMap((r, i) => r.map((v, j) => Math.abs(v - B[i][j]))));

await lab('rotations', async () => {
  await settled();
  const D = Math.PI / 180;
  const R = await rotMatrix('rot-matrix');
  const want = zxz(30 * D, 40 * D, 20 * D);
  check(maxDiff(R, want) < 1e-12, `rotations: R for φ, θ, ψ = 30°, 40°, 20° is Rψ Rθ Rφ (largest difference ${maxDiff(R, want)})`);
  const q = await num2('#rot-quat'), tr = R[0][0] + R[1][1] + R[2][2];
  close(Math.abs(q[0]), Math.sqrt(1 + tr) / 2, 1e-12, 'rotations: quaternion w = √(1 + tr R)/2');
  close(Math.hypot(...q), 1, 1e-12, 'rotations: the quaternion is a unit one');
  check(/No gimbal lock: θ is 40° from/.test(await page.textContent('#rot-gimbal')), 'rotations: at θ = 40° no gimbal lock, and how far from it');
  // the body in 3-D: drawn, its x′ axis along R's first row, and it turns on drag
  await frameAfter();
  const p0 = await pixels('#rotations-view');
  check(p0.ink > 0.02, `rotations: the body is drawn in 3-D (${(p0.ink * 100).toFixed(1)} % inked)`);
  const bx = (await page.getAttribute('#rotations-view', 'data-body-x')).split(',').map(Number);
  check(bx.every((v, k) => Math.abs(v - want[0][k]) < 1e-4), `rotations: the body's x′ axis points along R's first row (${bx})`);
  await page.$eval('#rotations-view', (c) => c.scrollIntoView({block: 'center'}));
  const box = await page.$eval('#rotations-view', (c) => { const r = c.getBoundingClientRect(); return [r.x, r.y, r.width, r.height]; });
  const yaw0 = await page.getAttribute('#rotations-view', 'data-yaw');
  await page.mouse.move(box[0] + box[2] / 2, box[1] + box[3] / 2); await page.mouse.down();
  await page.mouse.move(box[0] + box[2] / 2 + 100, box[1] + box[3] / 2, {steps: 5}); await page.mouse.up(); await frameAfter();
  check(await page.getAttribute('#rotations-view', 'data-yaw') !== yaw0 && (await pixels('#rotations-view')).h !== p0.h, 'rotations: dragging turns the 3-D view');
  // the three turns played one after the other: after the first, the body's x′ is (cos φ, sin φ, 0)
  await page.waitForSelector('.rot-figure .player[data-time="3"]', {timeout: 15000});
  await setRange('.rot-figure [data-role=time]', 333);
  const x1 = (await page.getAttribute('#rotations-view', 'data-body-x')).split(',').map(Number);
  check(Math.abs(x1[0] - Math.cos(30 * D)) < 2e-3 && Math.abs(x1[1] - Math.sin(30 * D)) < 2e-3 && Math.abs(x1[2]) < 2e-3 &&
    /^Turn 1 of 3: φ about z/.test(await page.textContent('#rot-stage')), `rotations: after the first turn the body's x′ is (cos φ, sin φ, 0) (${x1})`);
  await page.click('.rot-figure [data-role=play]'); await page.waitForTimeout(500); await pauseIfPlaying('.rot-figure [data-role=play]');
  const tp = await page.getAttribute('.rot-figure .player', 'data-time'); await page.waitForTimeout(300);
  check(Number(tp) > 1 && await page.getAttribute('.rot-figure .player', 'data-time') === tp, `rotations: play advances the turns (t = ${tp}), pause stops them`);
  // a slider changes the answer
  await clearStates(); await setRange('#rot-psi', 80); await state('main form', 'done');
  check(maxDiff(await rotMatrix('rot-matrix'), zxz(30 * D, 40 * D, 80 * D)) < 1e-12, 'rotations: moving the ψ slider to 80° gives Rψ Rθ Rφ at ψ = 80°');
  // gimbal lock at θ = 0: φ and ψ do the same thing
  await clearStates(); await page.click('#rot-lock'); await state('main form', 'done');
  const lockText = await page.textContent('#rot-gimbal');
  check(/Gimbal lock/.test(lockText) && /φ \+ ψ = 110°/.test(lockText) && /same axis/.test(lockText),
    `rotations: θ = 0 says gimbal lock, that only φ + ψ (= 110°) matters ("${lockText.slice(0, 160)}")`);
  const L1 = await rotMatrix('rot-matrix');
  await clearStates(); await setRange('#rot-phi', 80); await state('main form', 'done');
  await clearStates(); await setRange('#rot-psi', 30); await state('main form', 'done');
  const L2 = await rotMatrix('rot-matrix');
  check(maxDiff(L1, L2) < 1e-12 && maxDiff(L1, zxz(110 * D, 0, 0)) < 1e-12,
    `rotations: at θ = 0, (φ, ψ) = (30°, 80°) and (80°, 30°) are the same turn by 110° about z (${maxDiff(L1, L2)})`);
  // two turns composed both ways: x then z differs from z then x; x then x commutes
  const AB = await rotMatrix('order-ab'), BA = await rotMatrix('order-ba');
  const Rx90 = zxz(0, Math.PI / 2, 0), Rz90 = zxz(Math.PI / 2, 0, 0);
  const mul = (A, B) => A.map((r, i) => B[0].map((_, j) => r.reduce((s, _, k) => s + A[i][k] * B[k][j], 0)));
  check(maxDiff(AB, mul(Rz90, Rx90)) < 1e-12 && maxDiff(BA, mul(Rx90, Rz90)) < 1e-12,
    'rotations: 90° about x then 90° about z is Rz Rx (passive), the other order Rx Rz');
  check(await value('#order-verdict') > 0.9 && /differ/.test(await page.textContent('#order-verdict')), 'rotations: the two orders are said to differ');
  await page.selectOption('#order-b-axis', 'x'); await page.evaluate(() => delete document.getElementById('order-form').dataset.state);
  await page.click('#order-submit'); await state('#order-form', 'done');
  check(await value('#order-verdict') < 1e-12 && /agree/.test(await page.textContent('#order-verdict')), 'rotations: two turns about x commute, and it says so');
  // copy as Python: the shown call runs with the Python client and gives the page's numbers
  const py = await page.textContent('main [data-role=python]');
  check(/m\.rotation_convert\(\s*euler_zxz=\[/.test(py), `rotations: the Python box calls the client's m.rotation_convert(euler_zxz=…) (${py.split('\n')[2]})`);
  let out = '';
  try {
    out = execFileSync('/usr/bin/python3', ['-c', py + '\nimport json\nprint(json.dumps(answer["matrix"]))'],
      {env: {...process.env, PYTHONPATH: path.resolve(webRoot, '..', 'python')}, encoding: 'utf8', timeout: 20000});
  } catch (e) { out = String(e.stderr || e); }
  let pm = null; try { pm = JSON.parse(out); } catch (e) { /* shown below */ }
  check(pm && maxDiff(pm, await rotMatrix('rot-matrix')) === 0, `rotations: the Python call runs and answers the page's matrix (${out.slice(0, 120)})`);
  check((await blemishes()).length === 0, `rotations: a clean page (${(await blemishes()).join(' | ')})`);
}, 'new-rotations');

await lab('table', async () => {
  await settled();
  // through the centre, ω = 1, r1 = 1, m = 1: F' = −m ω² r1 (4/π, 1) at the start
  const F = await num2('#table-total');
  close(F[0], -4 / Math.PI, 1e-12, 'table: effective force x = −(4/π) m ω² r1'); close(F[1], -1, 1e-12, 'table: effective force y = −m ω² r1');
  close(await value('#table-t'), Math.PI, 1e-12, 'table: the run lasts half a turn, π/ω');
  const puck = async (id) => (await page.getAttribute(id, 'data-puck')).split(',').map(Number);
  const a0 = await puck('#table-room'), b0 = await puck('#table-table');
  await page.click('main [data-role=play]'); await page.waitForTimeout(800);
  await pauseIfPlaying('main [data-role=play]');
  const a1 = await puck('#table-room'), b1 = await puck('#table-table');
  check(a1[1] < a0[1] && b1[1] < b0[1], `table: play moves the puck in both frames (room y ${a0[1]} → ${a1[1]}, table y ${b0[1]} → ${b1[1]})`);
  check(Math.abs(a1[0]) < 1e-9 && Math.abs(b1[0]) > 1e-3, `table: from the room the puck goes straight (x = ${a1[0]}), on the table it curves (x′ = ${b1[0]})`);
  const t1 = await page.getAttribute('main .player', 'data-time'); await page.waitForTimeout(300);
  check(await page.getAttribute('main .player', 'data-time') === t1, 'table: pause stops the animation');
  await setRange('main [data-role=time]', 1000);
  const a2 = await puck('#table-room'), b2 = await puck('#table-table');
  check(Math.abs(a2[0]) < 1e-3 && Math.abs(a2[1] + 1) < 1e-3 && Math.abs(b2[0]) < 1e-3 && Math.abs(b2[1] - 1) < 1e-3,
    `table: after half a turn the puck is across the room (${a2}) but back at its start on the table (${b2})`);
  // a faster table: half a turn in π/2 s
  await page.fill('#table-omega', '2'); await clearStates(); await page.click('#table-submit'); await state('main form', 'done');
  close(await value('#table-t'), Math.PI / 2, 1e-12, 'table: at ω = 2 rad/s the run lasts π/2 s');
  await invalid('main form', '#table-omega', 0, '#table-submit', 'must rotate');
}, 'new-table');

await lab('tides', async () => {
  await settled();
  // equilibrium tide range 3 GM r⁴ / (2 GM_E d³) with the constants the operation documents (DE440 GM of the Moon and the Sun)
  const r = 6371008.8, GME = 3.986004418e14;
  const moon = 3 * 4.902800118e12 * r ** 4 / (2 * GME * 3.844e8 ** 3), sun = 3 * 1.32712440041279419e20 * r ** 4 / (2 * GME * 1.495978707e11 ** 3);
  close(await value('#tides-moon-range'), moon, 1e-9, 'tides: the Moon\'s range 3 GM r⁴/(2 GM_E d³)');
  close(await value('#tides-sun-range'), sun, 1e-9, 'tides: the Sun\'s range');
  close(await value('#tides-spring'), moon + sun, 1e-9, 'tides: spring range = sum'); close(await value('#tides-neap'), moon - sun, 1e-9, 'tides: neap range = difference');
  const constants = await page.textContent('#tides-constants');
  check(/DE440/.test(constants) && constants.includes('4.902800118e12') && constants.includes('1.32712440041279419e20'),
    `tides: the lab states the named bodies' values and their source ("${constants.slice(0, 80)}")`);
  // the arrows: 24, outwards below the Moon (+x), inwards at 90° (down the screen is towards the centre)
  const arrows = await page.$$eval('#tides-field [data-role=tide-arrow]', (ls) => ls.map(l => ['x1', 'y1', 'x2', 'y2'].map(k => Number(l.getAttribute(k)))));
  check(arrows.length === 24 && arrows[0][2] > arrows[0][0] + 5 && arrows[6][3] > arrows[6][1] + 2 && arrows[12][2] < arrows[12][0] - 5,
    `tides: 24 arrows, outwards towards and away from the Moon, inwards at 90° (${arrows.length})`);
  // spring: the highest water is both highs added; neap (Sun at 90°): the Moon's high plus the Sun's low
  const hm = 2 / 3 * moon, hs = 2 / 3 * sun; // high water = (2/3) range, low = −(1/3) range
  close(Number(await page.getAttribute('#tides-field', 'data-max-height')), hm + hs, 1e-9, 'tides: spring high water = Moon\'s high + Sun\'s high');
  // a month of tides: a quarter of the way (the Sun at 90°) is neap, half way (full Moon) spring again
  await page.click('#tides-field ~ .player [data-role=play]'); await page.waitForTimeout(600); await pauseIfPlaying('#tides-field ~ .player [data-role=play]');
  check(Math.abs(Number(await page.getAttribute('#tides-field', 'data-max-height')) - (hm + hs)) > 1e-4, 'tides: playing the month changes the tide');
  await setRange('#tides-field ~ .player [data-role=time]', 250);
  close(Number(await page.getAttribute('#tides-field', 'data-max-height')), hm - hs / 2, 1e-9, 'tides: a quarter of a month on, neap high water');
  check(/neap tide \(quarter Moon\)/.test(await page.textContent('#tides-phase')), `tides: the quarter Moon is said to be neap ("${await page.textContent('#tides-phase')}")`);
  await setRange('#tides-field ~ .player [data-role=time]', 500);
  close(Number(await page.getAttribute('#tides-field', 'data-max-height')), hm + hs, 1e-9, 'tides: half a month on (full Moon), spring high water again');
  await clearStates(); await page.selectOption('#tides-sun', '90'); await state('main form', 'done');
  close(Number(await page.getAttribute('#tides-field', 'data-max-height')), hm - hs / 2, 1e-9, 'tides: neap high water = Moon\'s high + Sun\'s low');
  check(/Sun and Moon|Moon and Sun/.test(await page.textContent('#tides-note')) && /times larger/.test(await page.textContent('#tides-note')),
    'tides: the note says what the arrows add and how much the heights are exaggerated');
  await page.fill('#tides-point', '200'); await page.click('#tides-submit'); await state('main form', 'error');
  check(await page.getAttribute('#tides-point', 'aria-invalid') === 'true' && /180/.test(await page.textContent('#tides-point-err')),
    `tides: a marked point beyond 180° is refused at its field ("${await page.textContent('#tides-point-err')}")`);
}, 'new-tides');

await lab('phase', async () => {
  await settled();
  close(await value('#ph-area0'), Math.PI * 0.35 * 0.6, 1e-9, 'phase: the loop\'s area at the start is π a b');
  check(await value('#ph-drift-0') < 1e-9, `phase: the symplectic method keeps the area (${await value('#ph-drift-0')})`);
  check(await value('#ph-drift-1') > 1e-6, `phase: rk4 at a coarse step lets it drift (${await value('#ph-drift-1')})`);
  const pts = () => page.getAttribute('#ph-loop [data-role=loop]', 'points');
  const l0 = await pts();
  await page.click('#ph-loop ~ .player [data-role=play]'); await page.waitForTimeout(700); await pauseIfPlaying('#ph-loop ~ .player [data-role=play]');
  const l1 = await pts(); await page.waitForTimeout(300);
  check(l1 !== l0 && await pts() === l1, 'phase: play moves the loop, pause stops it');
  check(/area 0\.65973\d* \(gauss4/.test(await page.textContent('#ph-area-now')), `phase: the area is read out as it plays ("${await page.textContent('#ph-area-now')}")`);
  check(await value('#pc-crossings') > 500 && await value('#pc-drift') < 1e-6, 'phase: the Poincaré section has its crossings, energy kept');
  const dots0 = await page.$$eval('#pc-plot circle', (c) => c.length);
  await page.fill('#pc-energy', '0.08'); await page.evaluate(() => delete document.getElementById('poincare-form').dataset.state);
  await page.click('#pc-submit'); await state('#poincare-form', 'done');
  check(await page.$$eval('#pc-plot circle', (c) => c.length) !== dots0 || await value('#pc-crossings') !== dots0, 'phase: a new energy gives a new section');
  await page.fill('#ph-a', '-1'); await page.click('#ph-submit'); await state('main form', 'error');
  check(/half-width/.test(await page.textContent('#ph-a-err')) && await page.getAttribute('#ph-a', 'aria-invalid') === 'true', 'phase: a negative half-width is refused at its field');
}, 'new-phase');

await lab('particles', async () => {
  await settled();
  const M = 134.9768; // π⁰, MeV
  close(await value('#dk-pstar'), M / 2, 1e-12, 'particles: π⁰ → γγ at rest: each photon carries M/2');
  close(await value('#dk-gamma'), 1 + 200 / M, 1e-12, 'particles: γ = 1 + T/M');
  close(await value('#dk-open'), 2 * Math.asin(1 / (1 + 200 / M)) * 180 / Math.PI, 1e-9, 'particles: smallest opening angle 2 arcsin(1/γ)');
  // Compton at 90°: the shift is one Compton wavelength; at 180°, two
  const lc = 2.42631023867e-12 * 1e12; // pm, CODATA 2018
  close(await value('#cp-shift'), lc, 1e-9, 'particles: Compton shift at 90° = h/mc');
  await page.evaluate(() => delete document.getElementById('compton-form').dataset.state);
  await setRange('#cp-angle', 180); await state('#compton-form', 'done');
  close(await value('#cp-shift'), 2 * lc, 1e-9, 'particles: Compton shift at 180° = 2h/mc');
  // Doppler of 500 nm light coming at β = 0.1: bluer; going at β = 0.5: infrared
  close(await value('#dp-factor'), Math.sqrt(1.1 / 0.9), 1e-12, 'particles: Doppler factor √((1+β)/(1−β))');
  const rgb = (await page.getAttribute('#dp-swatch-seen', 'data-colour')).match(/\d+/g).map(Number);
  close(await value('#dp-seen'), 500 / Math.sqrt(1.1 / 0.9), 1e-9, 'particles: seen wavelength 500 nm / factor');
  check(rgb[2] > rgb[0] && rgb[2] > rgb[1], `particles: 452 nm looks blue (${rgb})`);
  // seen at right angles (in the observer's frame): redder by 1/γ, the transverse Doppler effect
  await page.evaluate(() => delete document.getElementById('doppler-form').dataset.state);
  await setRange('#dp-angle', 90); await state('#doppler-form', 'done');
  close(await value('#dp-factor'), Math.sqrt(1 - 0.01), 1e-12, 'particles: at 90° the Doppler factor is 1/γ');
  await page.evaluate(() => delete document.getElementById('doppler-form').dataset.state);
  await setRange('#dp-angle', 0); await state('#doppler-form', 'done');
  await page.evaluate(() => delete document.getElementById('doppler-form').dataset.state);
  await setRange('#dp-beta', -0.5); await state('#doppler-form', 'done');
  check(await page.getAttribute('#dp-swatch-seen', 'data-colour') === 'infrared' && /infrared: invisible/.test(await page.textContent('#doppler-results')),
    'particles: receding at β = 0.5, 500 nm light is seen in the infrared, and it says so');
  await invalid('main form', '#dk-T', -5, '#dk-submit', 'cannot be negative');
}, 'new-particles');

// --- the Foucault pendulum's swing plane over the Earth in 3-D -----
// Over one sidereal day the plane turns on the floor by the measured rate × the
// day, which is 360° sin λ to first order (ω sin λ × 2π/ω): at the Panthéon's
// 48.846° N, 271.1° clockwise. From the stars the Earth turns a full 360°;
// from the ground it is held still and the plane turns just the same.
await lab('earth', async () => {
  await settled();
  const box = '#fou-3d-box', player = '#fou-3d-box ~ .player';
  const attr = async (a) => Number(await page.getAttribute(box, a));
  check(await page.$('#fou-view') !== null, 'Foucault: the swing plane is drawn over the Earth in 3-D');
  const p0 = await pixels('#fou-view');
  check(p0.ink > 0.05, `Foucault 3-D: the Earth is drawn (${(p0.ink * 100).toFixed(1)} % inked)`);
  // the player by keyboard alone: Space on the focused Play button plays, again pauses
  await page.focus(player + ' [data-role=play]'); await page.keyboard.press('Space');
  await page.waitForTimeout(600);
  check(await page.getAttribute(player, 'data-playing') === 'true', 'keyboard: Space on the focused Play button plays');
  await page.keyboard.press('Space');
  check(await page.getAttribute(player, 'data-playing') === 'false', 'keyboard: Space again pauses');
  const t1 = Number(await page.getAttribute(player, 'data-time'));
  check(t1 > 0, `Foucault 3-D: playing advanced the day (t = ${t1} h)`);
  await frameAfter();
  check((await pixels('#fou-view')).h !== p0.h, 'Foucault 3-D: the picture changed while the day played');
  // the time slider by keyboard: ArrowRight steps on, End is one sidereal day
  await page.focus(player + ' [data-role=time]'); await page.keyboard.press('Home'); await page.keyboard.press('ArrowRight');
  const t2 = Number(await page.getAttribute(player, 'data-time'));
  check(t2 > 0 && t2 < 0.1, `keyboard: ArrowRight on the time slider steps the time on (t = ${t2} h)`);
  await page.keyboard.press('End');
  const lat = 48.846 * Math.PI / 180;
  close(Number(await page.getAttribute(player, 'data-time')), 86164.0905 / 3600, 1e-3, 'Foucault 3-D: the day played is one sidereal day, in hours');
  close(await attr('data-earth-deg'), 360, 1e-3, 'Foucault 3-D: seen from the stars the Earth turns 360° in the day');
  close(-await attr('data-swing-deg'), 360 * Math.sin(lat), 5e-3, 'Foucault 3-D: the swing plane turns 360° sin λ clockwise on the floor in a day');
  check(/270\.\d°|271\.\d°/.test(await page.textContent('#fou-3d-note')), `Foucault 3-D: the turn in a day is written (${await page.textContent('#fou-3d-note')})`);
  // from the ground (the rotating frame): the Earth still, the plane's turn the same
  const swing = await attr('data-swing-deg');
  await page.selectOption('#fou-frame', 'ground'); await frameAfter();
  check(await attr('data-earth-deg') === 0 && await attr('data-swing-deg') === swing,
    `Foucault 3-D: seen from the ground the Earth stays still and the plane turns the same (${await attr('data-earth-deg')}°, ${await attr('data-swing-deg')}°)`);
  // and the view turns by keyboard
  const k0 = await pixels('#fou-view');
  await page.focus('#fou-view'); await page.keyboard.press('ArrowLeft'); await frameAfter();
  check((await pixels('#fou-view')).h !== k0.h, '3-D: the arrow keys turn the view of the Earth');
  // the cannonball's flight, animated from POST /v1/trajectory: where the ball lands at the slider's End is where
  // the scene (its own integration, POST /v1/scenes/cannonball) says: 22.17 km downrange, 58.55 m to the right
  const scene = await (await fetch(base + '/v1/scenes/cannonball', {method: 'POST', headers: {'Content-Type': 'application/json'},
    body: JSON.stringify({speed: 500, elevation_deg: 30, azimuth_deg: 0, latitude_deg: 45})})).json();
  const cplayer = '#can-path ~ .player';
  const bx0 = await page.getAttribute('#can-ball', 'cx');
  await page.click(cplayer + ' [data-role=play]'); await page.waitForTimeout(600); await pauseIfPlaying(cplayer + ' [data-role=play]');
  check(await page.getAttribute('#can-ball', 'cx') !== bx0, 'animation: the cannonball flies when played');
  await page.focus(cplayer + ' [data-role=time]'); await page.keyboard.press('End');
  close(Number(await page.getAttribute('#can-path-note', 'data-right')), scene.numerical.right, 1e-5,
    'cannonball: the animated flight lands as far to the right as the scene says');
  close(Number(await page.getAttribute('#can-path-note', 'data-down')), scene.numerical.range, 1e-6,
    'cannonball: and as far downrange');
  // at the equator: no turn at all
  await page.fill('#fou-lat', '0');
  await page.evaluate(() => { delete document.getElementById('fou-form').dataset.state; });
  await page.click('#fou-submit'); await state('#fou-form', 'done');
  await page.focus(player + ' [data-role=time]'); await page.keyboard.press('End');
  check(Math.abs(await attr('data-swing-deg')) < 1e-6 && /nothing: at the equator/.test(await page.textContent('#fou-3d-note')),
    `Foucault 3-D: at the equator the plane does not turn on the floor (${await attr('data-swing-deg')}°)`);
}, 'foucault-3d');

// --- the twin paradox played: at ct = 10 yr (the turn-round, 8 ly at β = 0.8) the traveller's clock
// reads 10 √(1 − 0.64) = 6 yr, at the end 12 yr against the home clock's 20 yr
await lab('spacetime', async () => {
  await settled();
  const player = '#tw-diagram ~ .player', clocks = '#tw-clocks';
  const y0 = await page.getAttribute('#tw-trav-dot', 'cy');
  await page.click(player + ' [data-role=play]'); await page.waitForTimeout(600); await pauseIfPlaying(player + ' [data-role=play]');
  check(await page.getAttribute('#tw-trav-dot', 'cy') !== y0, 'animation: the twins move up their worldlines when played');
  await page.$eval(player + ' [data-role=time]', (s) => { s.value = 500; s.dispatchEvent(new Event('input')); });
  close(Number(await page.getAttribute(clocks, 'data-home')), 10, 1e-12, 'twins: halfway the home clock reads 10 yr');
  close(Number(await page.getAttribute(clocks, 'data-traveller')), 6, 1e-12, 'twins: at the turn-round the traveller\'s clock reads 6 yr');
  await page.focus(player + ' [data-role=time]'); await page.keyboard.press('End');
  close(Number(await page.getAttribute(clocks, 'data-traveller')), 12, 1e-12, 'twins: at the end the traveller\'s clock reads 12 yr');
  check(/home 20 yr, traveller 12 yr/.test(await page.textContent(clocks)), `twins: the clocks are written (${await page.textContent(clocks)})`);
}, 'anim-twins');

// --- the predicted cost of a run before it runs: the operation's dry run ------
// The lab shows the chooser's prediction (diagnostics.selection of the same
// request with "dry_run": true) at the chosen accuracy and at draft. Checked
// against the API's own dry run of that request, fetched here; machine costs
// more than draft; a hundred times the orbits is predicted to cost more than
// ten times as much (evaluations grow with the span); nothing integrated.
async function dryRun(p, body) {
  const r = await fetch(base + p, {method: 'POST', headers: {'Content-Type': 'application/json'}, body: JSON.stringify({...body, dry_run: true})});
  const j = await r.json();
  const c = j.diagnostics.selection.candidates.find(x => x.verdict === 'chosen');
  return {cpu: c.predicted_cpu_s, steps: j.diagnostics.steps};
}
await lab('orbits', async () => {
  await settled();
  const cost = '#orb-cost';
  await page.waitForSelector(`${cost}[data-state=done]`, {timeout: 10000});
  const orbit = (n, acc) => ({M: 'sun', kind: 'timelike', initial: {semi_major_axis: 57909050000, eccentricity: 0.20563593},
    orbits: n, samples: 600, integrator: {accuracy: acc}});
  const want = await dryRun('/v1/gr/geodesic', orbit(3, 'balanced'));
  check(want.steps === 0, 'cost: the dry run integrates nothing (0 steps)');
  close(Number(await page.getAttribute(cost, 'data-cpu')), want.cpu, 1e-12, 'cost: the orbit lab shows the dry run\'s predicted CPU at balanced');
  close(Number(await page.getAttribute(cost, 'data-draft-cpu')), (await dryRun('/v1/gr/geodesic', orbit(3, 'draft'))).cpu, 1e-12,
    'cost: and the predicted CPU at draft');
  const text = await page.textContent(cost);
  check(/Predicted cost: about [\d.]+ (µs|ms|s) at balanced \(rk8pd, rtol .*\), [\d.]+ (µs|ms|s) at draft/.test(text),
    `cost: the prediction is said in words before the run ("${text}")`);
  const dry = [], onRequest = (r) => { if (r.url().endsWith('/v1/gr/geodesic')) dry.push(JSON.parse(r.postData() || '{}')); };
  page.on('request', onRequest);
  await page.selectOption('#orb-cost-acc', 'machine');
  await page.waitForSelector(`${cost}[data-state=done]`, {timeout: 10000});
  await page.waitForFunction((s) => document.querySelector(s).textContent.includes('at machine'), cost, {timeout: 10000});
  const machine = Number(await page.getAttribute(cost, 'data-cpu')), draft = Number(await page.getAttribute(cost, 'data-draft-cpu'));
  check(machine > draft, `cost: machine is predicted to cost more than draft (${machine} s against ${draft} s)`);
  close(machine, (await dryRun('/v1/gr/geodesic', orbit(3, 'machine'))).cpu, 1e-12, 'cost: the machine prediction is the dry run\'s');
  await page.fill('#orb-n', '300');
  await page.waitForFunction(([s, m]) => Number(document.querySelector(s).dataset.cpu) !== m, [cost, machine], {timeout: 10000});
  const longer = Number(await page.getAttribute(cost, 'data-cpu'));
  check(longer > 10 * machine, `cost: 100 times the orbits is predicted to cost over 10 times as much (${machine} s -> ${longer} s)`);
  page.off('request', onRequest);
  check(dry.length >= 2 && dry.every(b => b.dry_run === true), `cost: predicting sent only dry runs (${dry.length} requests)`);
  // the run itself: the accuracy chosen is sent, and the cost taken is said beside the prediction
  await page.fill('#orb-n', '3');
  await page.evaluate(() => { delete document.querySelector('main form').dataset.state; });
  const sent = page.waitForRequest((r) => r.url().endsWith('/v1/gr/geodesic') && !JSON.parse(r.postData() || '{}').dry_run);
  await page.click('#orb-submit');
  const body = JSON.parse((await sent).postData());
  await state('main form', 'done');
  check(body.integrator && body.integrator.accuracy === 'machine', `cost: the run asks for the accuracy chosen (${JSON.stringify(body.integrator)})`);
  const said = await page.textContent(cost);
  check(/The last run took [\d.]+ (µs|ms|s) of CPU \(predicted/.test(said), `cost: after the run, its CPU is said beside the prediction ("${said}")`);
  close(await value('#orb-measured'), 6 * Math.PI * 1.32712440018e20 / (299792458 ** 2 * 57909050000 * (1 - 0.20563593 ** 2)), 2e-3,
    'cost: at machine the advance per orbit is still 6πGM/(c²a(1−e²))');
  // Cancel stops the server's work, as its metrics show: 10⁵ orbits at machine take well over 9 s (the
  // deadline, 60 s here, would end them with a 422); cancelled, the job ends without an answer (neither 200
  // nor 422) and no worker stays busy within the 9 s the test waits.
  const geodesic = async () => {
    const m = await (await fetch(base + '/metrics')).text(), by = {};
    for (const [, st, n] of m.matchAll(/^mechd_requests_total\{route="\/v1\/gr\/geodesic",status="(\w+)"\} (\d+)$/gm)) by[st] = Number(n);
    return {by, busy: Number((/^mechd_workers_busy (\d+)$/m.exec(m) || [])[1])};
  };
  const cpuLong = String((await dryRun('/v1/gr/geodesic', orbit(100000, 'machine'))).cpu);
  await page.fill('#orb-n', '100000'); // its cost predicted (dry runs, answered 200) before the count starts
  await page.waitForFunction(([s, c]) => document.querySelector(s).dataset.cpu === c && document.querySelector(s).dataset.state === 'done',
    [cost, cpuLong], {timeout: 10000});
  { // said in words exactly when the dry run's chosen candidate is predicted to miss the target
    const r = await (await fetch(base + '/v1/gr/geodesic', {method: 'POST', headers: {'Content-Type': 'application/json'},
      body: JSON.stringify({...orbit(100000, 'machine'), dry_run: true})})).json();
    const sel = r.diagnostics.selection, c = sel.candidates.find(x => x.verdict === 'chosen');
    const misses = await page.$(cost + ' [data-role=misses]') !== null;
    check(misses === (c.predicted_error > sel.target_error), `cost: a predicted miss of the target is said exactly when the dry run predicts one ` +
      `(predicted ${c.predicted_error} against ${sel.target_error}; said: ${misses})`);
  }
  const m0 = await geodesic();
  await page.evaluate(() => { delete document.querySelector('main form').dataset.state; });
  await page.click('#orb-submit');
  await page.waitForSelector('main form[data-state="busy"] [data-role="cancel"]', {timeout: 5000});
  await page.waitForTimeout(300);
  await page.click('main [data-role="cancel"]');
  await state('main form', 'cancelled');
  let m1 = m0;
  for (let i = 0; i < 90; i++) { // until the job has ended (at most 9 s)
    m1 = await geodesic();
    const ended = Object.values(m1.by).reduce((a, b) => a + b, 0) > Object.values(m0.by).reduce((a, b) => a + b, 0);
    if (ended && m1.busy === 0) break;
    await page.waitForTimeout(100);
  }
  const grew = Object.keys(m1.by).filter(st => (m1.by[st] || 0) > (m0.by[st] || 0));
  check(grew.length === 1 && grew[0] !== '200' && grew[0] !== '422' && m1.busy === 0,
    `cancel: the server stopped the cancelled run (its metrics: the job ended with status ${grew.join(',') || 'none yet'}, not 200 or the deadline's 422; ${m1.busy} workers busy)`);
  await page.fill('#orb-n', '3');
}, 'cost-orbits');
await lab('tops', async () => {
  await settled();
  await page.waitForSelector('#top-cost[data-state=done]', {timeout: 10000});
  const want = await dryRun('/v1/rigid/top', {I1: 0.02, I3: 0.01, mass: 1, distance: 0.1, theta: 0.5, phi_dot: 0, psi_dot: 60,
    t_end: 2, samples: 801, integrator: {accuracy: 'balanced'}});
  close(Number(await page.getAttribute('#top-cost', 'data-cpu')), want.cpu, 1e-12, 'cost: the top lab shows the dry run\'s predicted CPU');
}, 'cost-tops');


// --- accessibility: axe-core (pinned in package.json, run.sh installs it) -----
// Injected through the DevTools protocol (page.evaluate), so the page's
// Content-Security-Policy stays as it is. Serious and critical violations fail.
const axeSource = fs.readFileSync(createRequire(import.meta.url).resolve('axe-core/axe.min.js'), 'utf8');
async function axeCheck(where) {
  if (!await page.evaluate(() => typeof window.axe === 'object')) await page.evaluate(axeSource);
  const found = await page.evaluate(async () => (await window.axe.run(document, {resultTypes: ['violations']})).violations
    .filter(v => v.impact === 'serious' || v.impact === 'critical')
    .map(v => `${v.impact} ${v.id} (${v.nodes.length}: ${v.nodes.slice(0, 2).map(n => n.target.join(' ')).join(', ')})`));
  check(found.length === 0, `${where}: axe-core finds no serious or critical accessibility violation (${found.join(' | ')})`);
}

// phone width: one column, no sideways scrolling, readable plot text, the β slider by its diagram
await page.setViewportSize({width: 390, height: 844});
for (const id of LABS) await lab(id, async () => {
  await settled();
  const [sw, cw] = await page.evaluate(() => [document.documentElement.scrollWidth, document.documentElement.clientWidth]);
  check(sw <= cw, `phone ${id}: no horizontal scrolling (scrollWidth ${sw}, clientWidth ${cw})`);
  const small = await page.$$eval('svg.plot text', (ts) => ts.map(t => {
    const m = t.getScreenCTM();
    return [t.textContent, parseFloat(getComputedStyle(t).fontSize) * (m ? Math.hypot(m.a, m.b) : 1)];
  }).filter(([, px]) => px < 10));
  check(small.length === 0, `phone ${id}: plot text at >= 10 px (${small.slice(0, 3).map(([t, px]) => `"${t}" ${px.toFixed(1)} px`).join(', ')})`);
  const bad = await blemishes();
  check(bad.length === 0, `phone ${id}: a clean page (${bad.join(' | ')})`);
  for (const v of await page.$$eval('canvas.view3d', (cs) => cs.map(c => '#' + c.id))) {
    const p = await pixels(v);
    check(p.ink > 0.02 && p.w >= 300, `phone ${id}: the 3-D view ${v} is drawn (${(p.ink * 100).toFixed(1)} % inked, ${p.w} px wide)`);
  }
  if (id === 'spacetime') {
    const gap = await page.evaluate(() => {
      const s = document.getElementById('st-beta-slider').getBoundingClientRect();
      const d = document.getElementById('st-diagram').getBoundingClientRect();
      return Math.max(s.top - d.bottom, d.top - s.bottom);
    });
    check(gap < 100, `phone spacetime: the β slider sits by the diagram it moves (${Math.round(gap)} px away)`);
  }
  const wide = await page.$$eval('main table', (ts) => ts.filter(t => t.scrollWidth > t.clientWidth + 1 || t.getBoundingClientRect().right > innerWidth)
    .map(t => `${t.id || t.className || 'table'} ${t.scrollWidth}/${t.clientWidth} px`));
  check(wide.length === 0, `phone ${id}: every table reads without sideways scrolling (${wide.join(', ')})`);
  await axeCheck(`phone ${id}`);
}, `phone-${id}`);
// a table with words in it (the accuracy table's "not run" rows say why): wrapped within 390 px
await lab('accuracy', async () => {
  await settled();
  await page.route('**/v1/compare', (route) => route.fulfill({status: 200, contentType: 'application/json', body: JSON.stringify({
    reference: {kind: 'exact', name: 'kepler'}, partial: true, runs: [
      {method: 'rk8pd', rtol: 1e-8, status: 'ok', rhs_evaluations: 800, max_position_error: 3.4e-8},
      {requested: {method: 'rkf45', rtol: 1e-10}, status: 'not_run', reason: 'the request\'s budget of 2 s ran out before this run could start'}]})}));
  await page.evaluate(() => { delete document.querySelector('main form').dataset.state; });
  await page.click('#acc-submit'); await state('main form', 'done');
  await page.unrouteAll({behavior: 'ignoreErrors'});
  const t = await page.$eval('#acc-table', (x) => [x.scrollWidth, x.clientWidth, x.getBoundingClientRect().right, innerWidth]);
  check(/budget of 2 s ran out/.test(await page.textContent('#acc-table')) && t[0] <= t[1] + 1 && t[2] <= t[3],
    `phone accuracy: a "not run" row's reason wraps within the screen (table ${t[0]}/${t[1]} px, right edge ${t[2]} of ${t[3]})`);
}, 'phone-accuracy-not-run');
// and the screenshots at 1280×800 of every lab
await page.setViewportSize({width: 1280, height: 800});
for (const id of LABS) await lab(id, async () => { await settled(); await axeCheck(`desktop ${id}`); }, `desktop-${id}`);

// --- a server with --token-file: the 401 leads to a token field, and the token works
{
  const tokenDir = fs.mkdtempSync(path.join(process.env.TMPDIR || '/tmp', 'mechd-token-'));
  const token = 'classroom-' + Math.random().toString(36).slice(2);
  fs.writeFileSync(path.join(tokenDir, 'token'), token + '\n', {mode: 0o600});
  const guarded = startMechd(['--token-file', path.join(tokenDir, 'token')]);
  try {
    const gbase = await guarded.url;
    check((await fetch(gbase + '/app.js')).status === 200, 'token: the front end itself is served without a token');
    check((await fetch(gbase + '/v1/examples')).status === 401, 'token: /v1 answers 401 without it');
    const ctx = await browser.newContext({viewport: {width: 1280, height: 800}});
    const tp = await ctx.newPage();
    const errs = [];
    tp.on('pageerror', (e) => errs.push(String(e)));
    const auth = [];
    tp.on('request', (r) => { if (r.url().includes('/v1/')) auth.push(r.headers().authorization || ''); });
    try {
      await tp.goto(`${gbase}/#spacetime`);
      const asked = await tp.waitForSelector('#token-input', {state: 'visible', timeout: 5000}).then(() => true, () => false);
      check(asked, 'token: a 401 opens an access-token field');
      const text = await tp.evaluate(() => document.body.innerText);
      check(!/(?<![A-Za-z])(null|undefined)(?![A-Za-z])/.test(text), `token: the 401 message has no "null" or "undefined" ("${text.slice(0, 300)}")`);
      await tp.screenshot({path: path.join(shots, 'token-asked.png')});
      if (asked) {
        await tp.fill('#token-input', 'not-the-token');
        await tp.click('#token-use');
        await tp.waitForSelector('main form[data-state="error"]', {timeout: 10000});
        const note = await tp.waitForSelector('#token-input', {state: 'visible', timeout: 5000}).then(() => tp.textContent('#token-note'), () => '');
        check(/did not accept/.test(note), `token: a wrong token is refused and the field asks again ("${note}")`);
        auth.length = 0;
        await tp.fill('#token-input', token);
        await tp.click('#token-use');
        await tp.waitForFunction(() => { const f = [...document.querySelectorAll('main form')];
          return f.length && f.every(x => x.dataset.state === 'done'); }, null, {timeout: 20000});
        const bad = await tp.evaluate(() => [...document.querySelectorAll('.problem')].map(b => b.textContent.trim()).filter(Boolean));
        check(bad.length === 0, `token: with the token every form of the lab computes (${bad.join(' | ')})`);
        check(auth.length > 0 && auth.every(a => a === 'Bearer ' + token), 'token: sent as Authorization: Bearer on every /v1 request');
        const [ss, ls] = await tp.evaluate(() => [JSON.stringify(sessionStorage), JSON.stringify(localStorage)]);
        check(ss.includes(token) && !ls.includes(token), 'token: kept in sessionStorage, never in localStorage');
        const curl = await tp.textContent('main .curl pre');
        check(!curl.includes(token) && curl.includes('$MECHD_TOKEN'), 'token: the curl command names $MECHD_TOKEN, never the token');
        await tp.goto(`${gbase}/#orbits`); // another lab, same tab: still works
        await tp.waitForSelector('main form[data-state="done"]', {timeout: 20000});
        check(true, 'token: kept across labs in the tab');
      }
      check(errs.length === 0, `token: no script errors (${errs.join(' | ')})`);
    } catch (e) {
      check(false, `token: ${e.message.split('\n')[0]}`);
    } finally {
      await tp.screenshot({path: path.join(shots, 'token-done.png')}).catch(() => {});
      await ctx.close();
    }
  } finally {
    guarded.proc.kill('SIGTERM');
    fs.rmSync(tokenDir, {recursive: true, force: true});
  }
}

await browser.close();
if (proxy) proxy.close();
server.kill('SIGTERM');
console.log(`screenshots: ${shots}`);
console.log(`${passed} passed, ${failed} failed`);
process.exit(failed ? 1 : 0);
