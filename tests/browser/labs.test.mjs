// labs.test.mjs — the classroom front end in a real browser: playwright-core
// drives Debian's /usr/bin/chromium (headless, never a downloaded browser)
// against a real mechd started on port 0. For each lab: the page loads, the
// default request is submitted, the numbers the API returns are shown (checked
// against closed forms), and an invalid input shows its error next to the
// field it names. Screenshots go to the directory given (default
// ./screenshots). Prints "N passed, M failed"; exits non-zero on a failure.
//
// usage: node labs.test.mjs MECHD_BINARY [SCREENSHOT_DIR]
// env:   MECHD_WEB_PROXY=1   serve clients/web (MECHD_WEB_ROOT) from a small
//                            Node server that forwards everything else to
//                            mechd — only for before mechd serves static files.
//        CHROMIUM            browser binary (default /usr/bin/chromium)
import {chromium} from 'playwright-core';
import {spawn} from 'node:child_process';
import fs from 'node:fs';
import http from 'node:http';
import path from 'node:path';

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
const server = spawn(mechd, ['--port', '0', ...(process.env.MECHD_WEB_PROXY === '1' ? [] : ['--static-dir', webRoot])],
  {stdio: ['ignore', 'pipe', 'pipe']});
server.stderr.on('data', () => {});
const base = await new Promise((resolve, reject) => {
  let out = '';
  const t = setTimeout(() => reject(new Error('mechd did not print its address: ' + out)), 10000);
  server.stdout.on('data', (d) => {
    out += d;
    const m = out.match(/listening on (http:\/\/\S+)/);
    if (m) { clearTimeout(t); resolve(m[1].replace(/\/$/, '')); }
  });
  server.on('exit', (code) => reject(new Error('mechd exited with ' + code + ': ' + out)));
});

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
  await invalid('main form', '#inertia-mass-0', -1, '#inertia-submit', '> 0');
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
  check(await page.evaluate(() => document.activeElement.id) === 'tab-inertia', 'keyboard: then the lab tabs');
  await page.keyboard.press('Tab'); await page.keyboard.press('Enter');
  await page.waitForSelector('main[data-lab="spacetime"]', {timeout: 10000});
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
  await invalid('#twin-form', '#tw-dist', -8, '#tw-submit', '> 0');
  const general = await page.textContent('#twin-form + .problem');
  check(!general.includes('/legs/'), `twins: both legs' errors sit at the distance field (box: "${general}")`);
});

await lab('earth', async () => {
  await state('#fall-form', 'done');
  const w = 7.2921159e-5, g = 9.80665, h = 100, lat = 32 * Math.PI / 180;
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
  await invalid('#fall-form', '#fall-height', -5, '#fall-submit', '> 0');
  await invalid('#can-form', '#can-lat', 95, '#can-submit', '90');
});

await lab('tops', async () => {
  await state('main form', 'done');
  close(await value('#top-thmin'), 0.5, 1e-12, 'top: released at rest in theta, theta_min = theta0');
  // sleeping-top test I3^2 w3^2 > 4 I1 M g h: 0.36 > 0.0784532 -> stable
  check((await page.textContent('#top-sleeping')) === 'true', 'top: the sleeping-top condition holds');
  await state('#dz-form', 'done');
  check(Number.isFinite(await value('#dz-flip')), 'Dzhanibekov: the exact flip interval is shown');
  await invalid('main form', '#top-I1', 0, '#top-submit', '> 0');
});

await lab('orbits', async () => {
  await state('main form', 'done');
  const GM = 1.32712440018e20, c = 299792458, a = 57909050000, e = 0.20563593;
  close(await value('#orb-first'), 6 * Math.PI * GM / (c * c * a * (1 - e * e)), 1e-9, 'Mercury: 6 pi GM/(c^2 a (1-e^2))');
  close(await value('#orb-century'), 42.98, 1e-3, 'Mercury: 43 arcsec per century');
  await invalid('main form', '#orb-e', 1.5, '#orb-submit', '< 1');
  await state('#light-form', 'done');
  const b = 696340000, arcsec = 180 / Math.PI * 3600;
  close(await value('#light-first'), 4 * GM / (c * c * b) * arcsec, 1e-9, 'light bending: 4GM/(c^2 b) at the limb');
  close(await value('#light-measured'), 1.75, 1e-3, 'light bending: 1.75 arcsec measured');
  await invalid('#light-form', '#light-b', -1, '#light-submit', '>= 0');
});

await lab('accuracy', async () => {
  await state('main form', 'done');
  const rows = await page.$$('#acc-table tr');
  check(rows.length > 4, `accuracy: the runs are listed (${rows.length - 1})`);
  check(await page.$('#acc-plot polyline') !== null, 'accuracy: the work-precision plot is drawn');
  await invalid('main form', '#acc-t', -20, '#acc-submit', '> 0');
});

// phone width: the page reflows to one column and stays usable
await page.setViewportSize({width: 390, height: 844});
await lab('inertia', async () => {
  await state('main form', 'done');
  const w = await page.evaluate(() => document.documentElement.scrollWidth);
  check(w <= 400, `phone: no horizontal scrolling (scrollWidth ${w})`);
}, 'phone-inertia');

await browser.close();
if (proxy) proxy.close();
server.kill('SIGTERM');
console.log(`screenshots: ${shots}`);
console.log(`${passed} passed, ${failed} failed`);
process.exit(failed ? 1 : 0);
