// sim.test.mjs — the labs as a simulation a student explores alone, in a real
// browser (playwright-core driving Debian's /usr/bin/chromium, never a
// downloaded one) against a real mechd on port 0, at 1280 and at 390 px:
//   - student input: the five inputs that broke the page (a light ray captured
//     by the point-mass Sun, an unknown parent particle, an empty marked point,
//     more Foucault swings than the step budget, a number echoed in 17 digits)
//     each end in a message on its field (aria-invalid, aria-describedby,
//     focus moved there), in words with the allowed range, the previous answer
//     dimmed and labelled "not updated", nothing wider than the screen;
//   - share and reset: a copied URL reproduces the inputs, the loaded worked
//     example, the view and the time; Reset restores the defaults;
//   - embedding: refused by default (frame-ancestors 'none', X-Frame-Options),
//     allowed for the origins given to --frame-ancestors, compact when framed;
//   - handles: dragging a physical object by pointer and by keyboard
//     (role="slider", arrow keys) changes the answer;
//   - axe-core: no serious or critical violation on the pages this test leaves.
// Screenshots go to SCREENSHOT_DIR/sim-*.png.
// usage: node sim.test.mjs MECHD_BINARY [SCREENSHOT_DIR]
import {chromium} from 'playwright-core';
import {spawn} from 'node:child_process';
import fs from 'node:fs';
import http from 'node:http';
import path from 'node:path';
import {createRequire} from 'node:module';

const mechd = process.argv[2];
const shots = path.resolve(process.argv[3] || 'screenshots');
if (!mechd) { console.error('usage: node sim.test.mjs MECHD_BINARY [SCREENSHOT_DIR]'); process.exit(2); }
fs.mkdirSync(shots, {recursive: true});
const webRoot = path.resolve(process.env.MECHD_WEB_ROOT || 'clients/web');

let passed = 0, failed = 0;
const check = (ok, what) => { if (ok) passed++; else { failed++; console.error('FAIL: ' + what); } };

function startMechd(extra = []) {
  const proc = spawn(mechd, ['--port', '0', '--deadline-ms', '60000', '--static-dir', webRoot, ...extra],
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
const main = startMechd();
const base = await main.url;

const browser = await chromium.launch({
  executablePath: process.env.CHROMIUM || '/usr/bin/chromium', headless: true,
  args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking',
         '--disable-component-update', '--disable-sync'],
});
const axeSource = fs.readFileSync(createRequire(import.meta.url).resolve('axe-core/axe.min.js'), 'utf8');

// a page of its own at a width, failing on any script error or CSP violation
async function newPage(width) {
  const page = await browser.newPage({viewport: {width, height: width < 500 ? 844 : 900}});
  page.errors = [];
  page.on('console', (m) => {
    if (m.type() === 'error' && !/Failed to load resource: the server responded with a status of 4\d\d/.test(m.text())) page.errors.push(m.text());
  });
  page.on('pageerror', (e) => page.errors.push(String(e)));
  return page;
}
const settled = (page, form = 'main form') => page.waitForFunction((f) => {
  const x = document.querySelector(f); return x && x.dataset.state && x.dataset.state !== 'busy';
}, form, {timeout: 30000});
const value = async (page, sel) => Number(await page.getAttribute(sel, 'data-value', {timeout: 15000}));
async function axe(page, what) {
  const cdp = await page.context().newCDPSession(page);
  await cdp.send('Runtime.evaluate', {expression: axeSource});
  const {result} = await cdp.send('Runtime.evaluate', {awaitPromise: true, returnByValue: true,
    expression: 'axe.run(document, {resultTypes: ["violations"]}).then(r => r.violations.filter(v => v.impact === "serious" || v.impact === "critical").map(v => v.id + ": " + v.nodes.slice(0, 3).map(n => n.target.join(" ")).join(", ")))'});
  check(Array.isArray(result.value) && result.value.length === 0, `${what}: axe-core finds no serious or critical violation (${JSON.stringify(result.value)})`);
  await cdp.detach();
}
const wide = (page) => page.evaluate(() => document.documentElement.scrollWidth - document.documentElement.clientWidth);
// the error state every failing input must leave: the field marked, described, focused; the old answer labelled
async function errorOnField(page, sel, what, re) {
  const st = await page.evaluate((s) => {
    const c = document.querySelector(s), box = document.getElementById((c.getAttribute('aria-describedby') || '').split(' ')[0]);
    const col = c.form.closest('.grid').children[1];
    return {invalid: c.getAttribute('aria-invalid'), msg: box ? box.textContent : '', focus: document.activeElement === c,
      stale: col.classList.contains('stale'), label: (col.querySelector(':scope > [data-role=not-updated]') || {}).textContent || '',
      shown: box ? box.getBoundingClientRect().right <= document.documentElement.clientWidth + 1 : false};
  }, sel);
  check(st.invalid === 'true', `${what}: the field is marked aria-invalid`);
  check(re.test(st.msg), `${what}: the message on the field says it in words (got "${st.msg}")`);
  check(!/\d\.\d{9,}|e\+\d|NaN|null|undefined|TypeError|rk8pd|rkf45|\[object/.test(st.msg), `${what}: no 17-digit echo, NaN, null or solver name ("${st.msg}")`);
  check(st.focus, `${what}: focus moved to the field`);
  check(st.shown, `${what}: the message fits the screen`);
  check(st.stale && /not updated/i.test(st.label), `${what}: the previous answer is dimmed and labelled "not updated" ("${st.label}")`);
  return st.msg;
}

for (const width of [1280, 390]) {
  const tag = width < 500 ? 'phone' : 'desktop';
  // --- the five inputs that broke the page -----------------------------------
  {
    const page = await newPage(width);
    try {
      // 1. a light ray captured: the API answers "motion": "capture" (no deflection); drawn and said
      await page.goto(`${base}/#orbits`);
      await settled(page, '#light-form');
      for (const b of ['5000', '1']) {
        await page.fill('#light-b', b);
        // (the previous b's capture is still shown: wait for this run's answer, not that one)
        await page.evaluate(() => { delete document.getElementById('light-form').dataset.state; });
        await page.click('#light-submit');
        await settled(page, '#light-form');
        await page.waitForSelector('#light-outcome[data-motion=capture]', {timeout: 20000});
        const text = await page.textContent('#light-outcome');
        // the photon's critical impact parameter 3√3 GM/c² for the Sun: 7.67 km
        check(/Captured/.test(text) && /7\.7 km/.test(text), `${tag}: b = ${b} m: the capture is said, with 3√3 GM/c² = 7.7 km ("${text.slice(0, 90)}…")`);
        check(await page.$('#light-captured-ray') !== null, `${tag}: b = ${b} m: the capture is drawn`);
        check(await page.getAttribute('#light-form', 'data-state') === 'done', `${tag}: b = ${b} m: no error state`);
      }
      await page.locator('#light-form').scrollIntoViewIfNeeded();
      await page.screenshot({path: path.join(shots, `sim-${tag}-capture.png`)});
      // 2. an unknown parent: its field says so, the known names wrap within the screen
      await page.goto(`${base}/#particles`);
      await settled(page);
      await page.fill('#dk-parent', 'foo');
      await page.click('#dk-submit');
      await page.waitForSelector('main form[data-state=error]', {timeout: 20000});
      const msg = await errorOnField(page, '#dk-parent', `${tag}: parent "foo"`, /“foo” is not a name.*pi0/);
      check(await wide(page) <= 0, `${tag}: parent "foo": nothing wider than the screen (${await wide(page)} px)`);
      check(msg.includes('K+') && msg.includes('neutron'), `${tag}: parent "foo": the known names are listed`);
      await page.locator('#dk-parent').scrollIntoViewIfNeeded();
      await page.screenshot({path: path.join(shots, `sim-${tag}-parent.png`)});
      await axe(page, `${tag}: particles with an error standing`);
      // a good input takes the error and the "not updated" label away
      await page.fill('#dk-parent', 'pi0'); await page.click('#dk-submit'); await settled(page);
      check(await page.getAttribute('#dk-parent', 'aria-invalid') === null && await page.$('[data-role=not-updated]') === null,
        `${tag}: a good input clears the error and the "not updated" label`);
      // 3. the tides with an empty marked point: the picture stays (dimmed), no "NaN", focus on the field
      await page.goto(`${base}/#tides`);
      await settled(page);
      await page.fill('#tides-point', '');
      await page.click('#tides-submit');
      await page.waitForSelector('main form[data-state=error]', {timeout: 20000});
      await errorOnField(page, '#tides-point', `${tag}: empty marked point`, /empty.*between 0° and 180°/);
      check(await page.$eval('#tides-field', (s) => s.childElementCount) > 10, `${tag}: empty marked point: the picture stays`);
      check(!/NaN/.test(await page.textContent('main')), `${tag}: empty marked point: no NaN on the page`);
      await page.screenshot({path: path.join(shots, `sim-${tag}-tides-empty.png`)});
      // 4. 100,000 Foucault swings: 18.3 million steps against the 10 million budget: at most about 54,000
      await page.goto(`${base}/#earth`);
      await settled(page, '#fou-form');
      await page.fill('#fou-swings', '100000');
      await page.click('#fou-submit');
      await page.waitForSelector('#fou-form[data-state=error]', {timeout: 30000});
      const fm = await errorOnField(page, '#fou-swings', `${tag}: 100000 swings`, /100,000 swings is more than this server runs at once \(at most about 5\d,000\); try fewer/);
      check(!/step budget|steps needed/.test(fm), `${tag}: 100000 swings: said in swings, not in integrator steps`);
      await page.locator('#fou-swings').scrollIntoViewIfNeeded();
      await page.screenshot({path: path.join(shots, `sim-${tag}-swings.png`)});
      // 5. a number echoed: 1e300 swings is read back as 10³⁰⁰, with the allowed range
      await page.fill('#fou-swings', '1e300');
      await page.click('#fou-submit');
      await page.waitForFunction(() => /10³⁰⁰/.test(document.getElementById('fou-swings-err').textContent), null, {timeout: 20000});
      await errorOnField(page, '#fou-swings', `${tag}: 1e300 swings`, /swings is 10³⁰⁰: it must be between 1 and 1,000,000/);
      // the integrator's words, as a numerical failure brings them (answered here by the test: a real one needs a
      // pathological scene): no method name, the step size in a reader's form, what to try
      await page.goto('about:blank');
      await page.route('**/v1/scenes/rotating-table', (route) => route.fulfill({status: 422, contentType: 'application/problem+json',
        body: JSON.stringify({type: '/problems/numerical-failure', title: 'Numerical failure', status: 422,
          detail: 'rk8pd: cannot reach the requested tolerance at t = 1.2345678901234567 s (step size 1.93e-16 s cannot shrink further)'})}));
      await page.goto(`${base}/#table`);
      await page.waitForSelector('main form[data-state=error]', {timeout: 20000});
      const box = await page.textContent('main .problem');
      check(!/rk8pd|tolerance/.test(box) && /1\.9·10⁻¹⁶ s/.test(box) && /t = 1\.2 s/.test(box) && /Try/.test(box),
        `${tag}: solver words translated ("${box.slice(0, 160)}…")`);
      await page.unrouteAll({behavior: 'ignoreErrors'});
      check(page.errors.length === 0, `${tag}: repros: no script errors (${page.errors.join(' | ')})`);
    } catch (e) {
      check(false, `${tag}: repros: ${e.message.split('\n')[0]}`);
      await page.screenshot({path: path.join(shots, `sim-${tag}-repro-failed.png`)}).catch(() => {});
    } finally { await page.close(); }
  }
  // --- share and reset -------------------------------------------------------
  {
    const page = await newPage(width);
    try {
      // β = 0.9 typed: the address bar says so; the copied link opens a page with β = 0.9 and γ = 1/√(1 − 0.81)
      await page.goto(`${base}/#spacetime`);
      await settled(page);
      await page.fill('#st-beta', '0.9');
      await page.click('#st-submit');
      await page.waitForFunction(() => Math.abs(Number(document.getElementById('st-gamma').dataset.value) - 2.294) < 1e-3, null, {timeout: 20000});
      await page.waitForFunction(() => location.hash.includes('st-beta=0.9'), null, {timeout: 5000});
      check(true, `${tag}: share: the address bar carries β = 0.9 (${page.url()})`);
      await page.click('[data-role=copy-link]');
      const link = await page.inputValue('.share-link');
      check(/#spacetime\?.*st-beta=0\.9/.test(link), `${tag}: share: Copy link gives the lab and β ("${link}")`);
      const p2 = await newPage(width);
      await p2.goto(link);
      await p2.waitForSelector('main[data-restored=done]', {timeout: 20000});
      await settled(p2);
      await p2.waitForFunction(() => document.getElementById('st-beta').value === '0.9' &&
        Math.abs(Number(document.getElementById('st-gamma').dataset.value) - 2.294) < 1e-3, null, {timeout: 20000}).catch(() => {});
      check(await p2.inputValue('#st-beta') === '0.9', `${tag}: share: the link opens with β = 0.9 (got ${await p2.inputValue('#st-beta')})`);
      const g = await value(p2, '#st-gamma');
      check(Math.abs(g - 1 / Math.sqrt(1 - 0.81)) < 1e-12, `${tag}: share: and computes γ(0.9) = 1/√0.19 = 2.2941573… (got ${g})`);
      await p2.screenshot({path: path.join(shots, `sim-${tag}-shared.png`)});
      // Reset: the defaults again (β = 0.6, γ = 1.25), the address bar without state
      await p2.click('[data-role=reset]');
      await p2.waitForFunction(() => document.getElementById('st-beta') && document.getElementById('st-beta').value === '0.6' &&
        document.getElementById('st-gamma') && document.getElementById('st-gamma').dataset.value === '1.25', null, {timeout: 20000}).catch(() => {});
      check(await p2.inputValue('#st-beta') === '0.6' && await value(p2, '#st-gamma') === 1.25 && !p2.url().includes('?'),
        `${tag}: reset: β back to 0.6, γ = 1.25, no state in the URL (${p2.url()})`);
      check(p2.errors.length === 0, `${tag}: share: no script errors on the opened link (${p2.errors.join(' | ')})`);
      await p2.close();
      // a worked example, the view (the exaggeration drawn) and the time (the player's slider) travel too
      await page.goto(`${base}/#orbits`);
      await settled(page);
      await page.waitForFunction(() => document.querySelector('.examples select').options.length > 2, null, {timeout: 10000});
      await page.waitForTimeout(300); // the server's examples merged into the picker (it renders again once)
      // an orbit example other than the one shown (not a light ray: that one goes to the light-bending form)
      const exIndex = await page.$eval('.examples select', (s) => {
        const ok = (o, i) => i !== s.selectedIndex && !/light|Deflection|Starlight|ray/i.test(o.textContent);
        const k = [...s.options].findIndex((o, i) => /Mercury/.test(o.textContent) && ok(o, i));
        return k >= 0 ? k : [...s.options].findIndex(ok);
      });
      const exTitle = await page.$eval('.examples select', (s, i) => s.options[i].textContent, exIndex);
      await page.selectOption('.examples select', {index: exIndex});
      await page.click('.examples button');
      await settled(page);
      await page.waitForFunction(() => document.getElementById('orb-exaggerate').options.length > 1, null, {timeout: 20000});
      const exView = await page.$eval('#orb-exaggerate', (s) => s.options[s.options.length - 2].value);
      await page.selectOption('#orb-exaggerate', exView);
      const slider = page.locator('.player [data-role=time]').first();
      await slider.focus();
      for (let k = 0; k < 5; k++) await page.keyboard.press('PageUp');
      await page.keyboard.press('ArrowRight');
      const tWas = await slider.inputValue();
      const e0 = await page.getAttribute('#orb-measured', 'data-value');
      await page.click('[data-role=copy-link]');
      const link2 = await page.inputValue('.share-link');
      const p3 = await newPage(width);
      await p3.goto(link2);
      await p3.waitForSelector('main[data-restored=done]', {timeout: 30000});
      const got = await p3.evaluate(() => ({ex: document.querySelector('.examples select').selectedOptions[0].textContent,
        view: document.getElementById('orb-exaggerate').value, t: document.querySelector('.player [data-role=time]').value,
        measured: document.getElementById('orb-measured').dataset.value}));
      check(got.ex === exTitle && got.view === exView && got.t === tWas && got.measured === e0,
        `${tag}: share: example "${exTitle}", view ×${exView} and time ${tWas} come back (got ${JSON.stringify(got)}; ${link2})`);
      await p3.close();
      check(page.errors.length === 0, `${tag}: share: no script errors (${page.errors.join(' | ')})`);
    } catch (e) {
      check(false, `${tag}: share: ${e.message.split('\n')[0]}`);
    } finally { await page.close(); }
  }
}

// --- handles: dragging a physical object, by pointer and by keyboard, changes the answer ---
// drag(page, sel, dx, dy): press on the handle's centre and move by (dx, dy) CSS px in steps, as a hand does
async function drag(page, sel, dx, dy) {
  const h = page.locator(sel);
  await h.scrollIntoViewIfNeeded();
  const b = await h.boundingBox();
  const x = b.x + b.width / 2, y = b.y + b.height / 2;
  await page.mouse.move(x, y); await page.mouse.down();
  for (let k = 1; k <= 8; k++) { await page.mouse.move(x + dx * k / 8, y + dy * k / 8); await page.waitForTimeout(25); }
  await page.mouse.up();
}
// the handle's accessible slider: role, a name, a value in words with units
const sliderOk = (page, sel) => page.$eval(sel, (g) => g.getAttribute('role') === 'slider' && g.tabIndex === 0 &&
  !!g.getAttribute('aria-label') && /\d/.test(g.getAttribute('aria-valuetext') || '') && g.getAttribute('aria-valuenow') !== null);
for (const width of [1280, 390]) {
  const tag = width < 500 ? 'phone' : 'desktop';
  const page = await newPage(width);
  try {
    // Spacetime: event 2 dragged up and left: x′ = γ(x − βct) from the field's new (ct, x), β = 0.6, γ = 1.25
    await page.goto(`${base}/#spacetime`);
    await settled(page);
    check(await sliderOk(page, '#st-event-1'), `${tag}: spacetime: event 2 is a slider with its (ct, x) in words`);
    const x0 = await page.getAttribute('#st-xp-1', 'data-value');
    await drag(page, '#st-event-1', -40, -25);
    await page.waitForFunction((b) => document.getElementById('st-xp-1').dataset.value !== b && !/^1, 1;|; 1, 1;/.test(document.getElementById('st-events').value), x0, {timeout: 20000});
    await settled(page);
    const evp = async () => { const e = (await page.inputValue('#st-events')).split(';')[1].split(',').map(Number);
      return [e, await value(page, '#st-xp-1'), await value(page, '#st-ctp-1')]; };
    let [e, xp, ctp] = await evp();
    check(Math.abs(xp - 1.25 * (e[1] - 0.6 * e[0])) < 1e-12 && Math.abs(ctp - 1.25 * (e[0] - 0.6 * e[1])) < 1e-12 && e[0] > 1,
      `${tag}: spacetime: dragged by pointer to (ct, x) = (${e}), the boost answers x′ = γ(x − βct) = ${xp}, ct′ = ${ctp}`);
    await page.focus('#st-event-1');
    for (let k = 0; k < 3; k++) await page.keyboard.press('ArrowRight');
    await page.waitForFunction((x) => Number(document.getElementById('st-events').value.split(';')[1].split(',')[1]) > x + 0.25, e[1], {timeout: 5000});
    await settled(page);
    await page.waitForTimeout(300);
    const [e2, xp2] = await evp();
    check(Math.abs(e2[1] - (Math.round(e[1] * 10) / 10 + 0.3)) < 1e-9 && Math.abs(xp2 - 1.25 * (e2[1] - 0.6 * e2[0])) < 1e-12,
      `${tag}: spacetime: three ArrowRight presses move the event by 0.3 along x (${e[1]} -> ${e2[1]}) and the answer follows (x′ = ${xp2})`);
    check(await page.evaluate(() => document.activeElement && document.activeElement.id) === 'st-event-1', `${tag}: spacetime: the focus stays on the handle through the redraw`);
    check(/ct = [\d.]+, x = [\d.]+/.test(await page.getAttribute('#st-event-1', 'aria-valuetext')), `${tag}: spacetime: the handle says where it is`);
    // the dragged state is in the address bar too, so a copied link holds it
    const inUrl = await page.waitForFunction(() => new URLSearchParams(location.hash.split('?')[1] || '').get('st-events') ===
      document.getElementById('st-events').value, null, {timeout: 5000}).then(() => true, () => false);
    check(inUrl, `${tag}: spacetime: the moved event is in the URL (${page.url()})`);
    await page.screenshot({path: path.join(shots, `sim-${tag}-drag-event.png`)});
    // Rotating table: the launch velocity dragged: the puck's start Coriolis force follows (−2mω × v′ at t = 0)
    await page.goto('about:blank');
    await page.goto(`${base}/#table`);
    await settled(page);
    check(await sliderOk(page, '#table-velocity') && await sliderOk(page, '#table-start'), `${tag}: table: the start and the velocity are sliders`);
    const c0 = await page.getAttribute('#table-cor', 'data-value');
    await drag(page, '#table-velocity', 30, 20);
    await page.waitForFunction((c) => document.getElementById('table-cor') && document.getElementById('table-cor').dataset.value !== c &&
      document.getElementById('table-experiment').value === 'custom', c0, {timeout: 20000});
    await settled(page);
    await page.waitForTimeout(300);
    // Coriolis at the start, seen from the table: −2m ω ẑ × v′ with v′ = v − ω ẑ × r (m = 1 kg, ω = 1 rad/s)
    const corOk = async () => {
      const [rx, ry, ux, uy] = await Promise.all(['#table-px', '#table-py', '#table-vx', '#table-vy'].map(s => page.inputValue(s).then(Number)));
      const vpx = ux + ry, vpy = uy - rx, want = [2 * vpy, -2 * vpx];
      const got = (await page.getAttribute('#table-cor', 'data-value')).split(',').map(Number);
      return [Math.abs(got[0] - want[0]) < 1e-9 && Math.abs(got[1] - want[1]) < 1e-9, got, want, [rx, ry, ux, uy]];
    };
    let [ok, got, want, inp] = await corOk();
    check(ok, `${tag}: table: velocity dragged to (${inp.slice(2)}) m/s: Coriolis at the start ${got} = −2mω×v′ ${want}`);
    const c1 = await page.getAttribute('#table-cor', 'data-value');
    await page.focus('#table-start');
    await page.keyboard.press('ArrowLeft'); await page.keyboard.press('ArrowLeft');
    await page.waitForFunction((c) => document.getElementById('table-cor').dataset.value !== c, c1, {timeout: 20000});
    await settled(page);
    await page.waitForTimeout(300);
    [ok, got, want, inp] = await corOk();
    check(ok, `${tag}: table: the start moved by the arrow keys to (${inp.slice(0, 2)}) m: Coriolis ${got} = ${want}`);
    await page.screenshot({path: path.join(shots, `sim-${tag}-drag-table.png`)});
    await axe(page, `${tag}: table with handles`);

    // Earth: the launch velocity's tip dragged (speed and elevation), then ArrowUp adds 10 m/s upwards: the
    // range on a non-rotating Earth would be v² sin 2α / g; the scene's differs from it only by the Coriolis
    // and centrifugal terms (well under 1 % at 45°N)
    await page.goto('about:blank');
    await page.goto(`${base}/#earth`);
    await settled(page, '#can-form');
    check(await sliderOk(page, '#can-aim-tip') && await sliderOk(page, '#fou-lat-handle'), `${tag}: earth: the launch velocity and the latitude are sliders`);
    const range = async () => { await settled(page, '#can-form'); await page.waitForTimeout(200);
      const v = Number(await page.inputValue('#can-speed')), a = Number(await page.inputValue('#can-elev')) * Math.PI / 180;
      return [v, a, await value(page, '#can-range'), v * v * Math.sin(2 * a) / 9.80665]; };
    const r0 = await page.getAttribute('#can-range', 'data-value');
    await drag(page, '#can-aim-tip', 30, -15);
    await page.waitForFunction((r) => document.getElementById('can-range').dataset.value !== r, r0, {timeout: 20000});
    let [v1, a1, got1, flat1] = await range();
    check(v1 !== 500 && Math.abs(got1 - flat1) < 0.01 * flat1, `${tag}: cannonball: dragged to ${v1} m/s at ${(a1 * 180 / Math.PI).toFixed(1)}°: range ${got1.toFixed(0)} m, v² sin 2α / g = ${flat1.toFixed(0)} m`);
    await page.focus('#can-aim-tip'); await page.keyboard.press('ArrowUp');
    await page.waitForFunction((r) => document.getElementById('can-range').dataset.value !== r, String(got1), {timeout: 20000});
    const [v2, a2, got2, flat2] = await range();
    check(Math.abs(v2 * Math.sin(a2) - (v1 * Math.sin(a1) + 10)) < 1.5 && Math.abs(got2 - flat2) < 0.01 * flat2,
      `${tag}: cannonball: ArrowUp adds 10 m/s upwards (${(v1 * Math.sin(a1)).toFixed(1)} -> ${(v2 * Math.sin(a2)).toFixed(1)} m/s), range ${got2.toFixed(0)} m against ${flat2.toFixed(0)} m`);
    // the pendulum dragged round the meridian: its first-order rate is −ω sin λ (ω = 7.292115e-5 rad/s, in °/h)
    const w = 7.292115e-5 * 180 / Math.PI * 3600;
    const f0 = await page.getAttribute('#fou-first', 'data-value');
    await drag(page, '#fou-lat-handle', 25, 40);
    await page.waitForFunction((f) => document.getElementById('fou-first').dataset.value !== f, f0, {timeout: 30000});
    await settled(page, '#fou-form'); await page.waitForTimeout(200);
    let lat = Number(await page.inputValue('#fou-lat')), fr = await value(page, '#fou-first');
    check(lat < 48 && Math.abs(fr + w * Math.sin(lat * Math.PI / 180)) < 1e-3 * w, `${tag}: foucault: dragged to λ = ${lat}°: ω sin λ = ${fr} °/h`);
    await page.focus('#fou-lat-handle'); await page.keyboard.press('Shift+ArrowUp');
    await page.waitForFunction((l) => Number(document.getElementById('fou-lat').value) > l + 5, lat, {timeout: 5000});
    await page.waitForFunction((f) => document.getElementById('fou-first').dataset.value !== f, String(fr), {timeout: 30000});
    await settled(page, '#fou-form'); await page.waitForTimeout(200);
    const lat2 = Number(await page.inputValue('#fou-lat')); fr = await value(page, '#fou-first');
    check(Math.abs(lat2 - Math.round(lat + 10)) < 1e-9 && Math.abs(fr + w * Math.sin(lat2 * Math.PI / 180)) < 1e-3 * w,
      `${tag}: foucault: Shift+ArrowUp turns it 10° north (λ = ${lat2}°, rate ${fr} °/h)`);

    // Orbits: the perihelion dragged in: a and e from r_p and r_a, the first-order advance 6πGM/(c²a(1−e²)), GM/c² = 1476.6250 m
    await page.goto('about:blank');
    await page.goto(`${base}/#orbits`);
    await page.waitForFunction(() => document.querySelector('#orb-submit')?.form.dataset.state === 'done', null, {timeout: 30000});
    check(await sliderOk(page, '#orb-peri') && await sliderOk(page, '#orb-apo'), `${tag}: orbits: perihelion and aphelion are sliders`);
    const o0 = await page.getAttribute('#orb-first', 'data-value');
    const rp0 = 57909050000 * (1 - 0.20563593), ra0 = 57909050000 * (1 + 0.20563593);
    await drag(page, '#orb-peri', -25, 0);
    await page.waitForFunction((o) => document.getElementById('orb-first').dataset.value !== o &&
      document.querySelector('#orb-submit')?.form.dataset.state === 'done', o0, {timeout: 30000});
    await page.waitForTimeout(300);
    const oa = Number(await page.inputValue('#orb-a')), oe = Number(await page.inputValue('#orb-e')), of = await value(page, '#orb-first');
    check(oa * (1 - oe) < rp0 * 0.99 && Math.abs(oa * (1 + oe) - ra0) < 1e-5 * ra0 &&
      Math.abs(of - 6 * Math.PI * 1476.6250385094204 / (oa * (1 - oe * oe))) < 1e-6 * of,
      `${tag}: orbits: perihelion dragged to ${(oa * (1 - oe) / 1e9).toFixed(2)} million km, aphelion kept: 6πGM/(c²a(1−e²)) = ${of}`);
    await page.focus('#orb-apo'); await page.keyboard.press('ArrowLeft');
    await page.waitForFunction((a) => Number(document.getElementById('orb-a').value) > a, oa, {timeout: 5000});
    check(true, `${tag}: orbits: ArrowLeft moves the aphelion out (a grows)`);

    // Tops: the tilt dragged, then the spin raised by the arrow keys: the form and the answer follow
    await page.goto('about:blank');
    await page.goto(`${base}/#tops`);
    await page.waitForFunction(() => document.querySelector('#top-submit')?.form.dataset.state === 'done', null, {timeout: 30000});
    check(await sliderOk(page, '#top-tilt') && await sliderOk(page, '#top-spin'), `${tag}: tops: tilt and spin are sliders`);
    const th0 = await page.getAttribute('#top-thmin', 'data-value');
    await drag(page, '#top-tilt', 25, 10);
    await page.waitForFunction((t) => document.getElementById('top-thmin').dataset.value !== t, th0, {timeout: 30000});
    await page.waitForFunction(() => document.querySelector('#top-submit')?.form.dataset.state === 'done', null, {timeout: 30000});
    const th = Number(await page.inputValue('#top-theta'));
    // released with φ̇0 = 0 the axis starts at a turning point: θ0 is the smallest θ (the top falls from it)
    check(th > 0.5 && Math.abs(await value(page, '#top-thmin') - th) < 1e-6, `${tag}: tops: tilt dragged to θ0 = ${th} rad, the smallest θ is θ0`);
    await page.focus('#top-spin'); await page.keyboard.press('ArrowUp'); await page.keyboard.press('ArrowUp');
    await page.waitForFunction(() => document.getElementById('top-psidot').value === '70', null, {timeout: 5000});
    check(true, `${tag}: tops: two ArrowUp presses spin it 10 rad/s faster (60 -> 70)`);

    // Inertia: the unit cube (1 kg) moved: about the corner its moments are 1/6 and 1/6 + |c|² twice (c its centre)
    await page.goto('about:blank');
    await page.goto(`${base}/#inertia`);
    await settled(page);
    check(await sliderOk(page, '#inertia-part-0'), `${tag}: inertia: the part is a slider`);
    const m0 = await page.getAttribute('#inertia-moment-1', 'data-value');
    await drag(page, '#inertia-part-0', -30, 0);
    await page.waitForFunction((m) => document.getElementById('inertia-moment-1').dataset.value !== m, m0, {timeout: 20000});
    await settled(page); await page.waitForTimeout(300);
    const cpos = await Promise.all([0, 1, 2].map(j => page.inputValue(`#inertia-pos-0-${j}`).then(Number)));
    const c2 = cpos.reduce((s2, v) => s2 + v * v, 0);
    check(Math.abs(await value(page, '#inertia-moment-1') - (1 / 6 + c2)) < 1e-12 && Math.abs(await value(page, '#inertia-moment-0') - 1 / 6) < 1e-12,
      `${tag}: inertia: the cube dragged to (${cpos}): moments 1/6 and 1/6 + |c|² = ${1 / 6 + c2}`);
    await page.screenshot({path: path.join(shots, `sim-${tag}-drag-inertia.png`)});
    check(page.errors.length === 0, `${tag}: handles: no script errors (${page.errors.join(' | ')})`);
  } catch (e) {
    check(false, `${tag}: handles: ${e.message.split('\n')[0]}`);
    await page.screenshot({path: path.join(shots, `sim-${tag}-handles-failed.png`)}).catch(() => {});
  } finally { await page.close(); }
}

// --- a live view: step, frame keys, backwards, graphs that grow, vectors and energy bars ---
for (const width of [1280, 390]) {
  const tag = width < 500 ? 'phone' : 'desktop';
  const page = await newPage(width);
  try {
    // the rotating table: one step is one sample (161 samples over the run), the key . another
    await page.goto(`${base}/#table`);
    await settled(page);
    const pl = page.locator('main .player').first(); // the table's one player
    await pl.locator('[data-role=step]').click();
    const t1 = Number(await pl.getAttribute('data-time'));
    await page.keyboard.press('.'); await page.keyboard.press('.');
    const t3 = Number(await pl.getAttribute('data-time'));
    const T = Number(await page.getAttribute('#table-t', 'data-value'));
    check(Math.abs(t1 - T / 160) < 1e-9 * T && Math.abs(t3 - 3 * T / 160) < 1e-9 * T,
      `${tag}: table: |▶ steps one sample (t = ${t1}, T/160 = ${T / 160}) and the key . two more (t = ${t3})`);
    await page.keyboard.press(',');
    check(Math.abs(Number(await pl.getAttribute('data-time')) - 2 * T / 160) < 1e-9 * T, `${tag}: table: the key , steps one back`);
    // the forces drawn on the puck: centrifugal mω²r′ and Coriolis −2mω×v′ (m = 1 kg, ω = 1 rad/s), net their sum;
    // the energy bars' sum ½mv′² − ½mω²r′² (the Jacobi integral) stays level as it plays
    const F = JSON.parse(await page.getAttribute('#table-table', 'data-forces'));
    const q = (await page.getAttribute('#table-table', 'data-puck')).split(',').map(Number);
    check(Math.abs(F.cf[0] - q[0]) < 1e-3 && Math.abs(F.cf[1] - q[1]) < 1e-3 && Math.abs(F.net[0] - F.cf[0] - F.co[0]) < 1e-12 &&
      await page.$$eval('#table-vectors [data-role=vector]', (v) => v.map(x => x.dataset.name).join(',')) === 'cf,Cor,net,v′',
      `${tag}: table: v′, centrifugal (mω²r′ = ${F.cf.map(x => x.toFixed(4))} at r′ = ${q}), Coriolis and net drawn on the puck`);
    const sum = () => page.$eval('#table-energy [data-role=bar]:last-of-type', (r) => Number(r.dataset.value));
    const E1 = await sum();
    for (let k = 0; k < 60; k++) await page.keyboard.press('.');
    const E2 = await sum();
    const bars = await page.$$eval('#table-energy [data-role=bar]', (rs) => rs.map(r => Number(r.dataset.value)));
    check(Math.abs(E2 - E1) < 1e-6 * Math.abs(E1) && Math.abs(bars[0] + bars[1] - bars[2]) < 1e-12 && Math.abs(bars[0] - E1) > 1e-3,
      `${tag}: table: the energy bars trade (½mv′² = ${bars[0].toFixed(4)} J now) while their sum stays level (${E1} -> ${E2} J)`);
    // backwards: Play runs time the other way; the reverse note says what the reversed film is
    await pl.locator('[data-role=reverse]').click();
    check(await pl.getAttribute('data-backwards') === 'true' && /turning the other way/.test(await pl.locator('[data-role=reverse-note]').textContent()),
      `${tag}: table: Backwards is on and says what the reversed motion is`);
    const tb = Number(await pl.getAttribute('data-time'));
    await pl.locator('[data-role=play]').click(); await page.waitForTimeout(400);
    await page.evaluate(() => { const b = document.querySelector('main .player [data-role=play]');
      if (b.getAttribute('aria-pressed') === 'true') b.click(); });
    check(Number(await pl.getAttribute('data-time')) < tb, `${tag}: table: played backwards, the time runs down (${tb} -> ${await pl.getAttribute('data-time')})`);
    await page.locator('#table-room').scrollIntoViewIfNeeded();
    await page.screenshot({path: path.join(shots, `sim-${tag}-live-table.png`)});
    // the top's θ(t) grows as the top plays: after stepping, only the samples up to t are drawn (801 in all)
    await page.goto('about:blank');
    await page.goto(`${base}/#tops`);
    await page.waitForFunction(() => document.querySelector('#top-submit')?.form.dataset.state === 'done', null, {timeout: 30000});
    const n = () => page.$eval('#top-theta-plot g.data polyline', (p) => p.getAttribute('points').trim().split(/\s+/).length);
    const full = await n();
    const tpl = page.locator('#top-3d-box ~ .player');
    await tpl.locator('[data-role=time]').focus(); await page.keyboard.press('Home');
    for (let k = 0; k < 5; k++) await page.keyboard.press('ArrowRight'); // 5/1000 of the run: 2 s → 0.01 s, between samples 4 and 5
    const grown = await n();
    check(full === 801 && grown >= 2 && grown <= 8, `${tag}: tops: θ(t) drawn whole (${full} points) until played, then only its past (${grown} points at t = ${await tpl.getAttribute('data-time')} s)`);
    await page.keyboard.press('End');
    check(await n() === 801, `${tag}: tops: at the end θ(t) is whole again`);
    // L, ω and τ on the top: L·ẑ = p_φ and L·ê3 = I3 ω3 are conserved (released with φ̇0 = 0: p_φ = I3 ψ̇ cos θ0 = 0.01·60·cos 0.5),
    // τ = Mgh ẑ × ê3 is horizontal, of size Mgh sin θ (M = 1 kg, h = 0.1 m)
    const vec = JSON.parse(await page.getAttribute('#top-vectors', 'data-vectors'));
    const pphi = 0.01 * 60 * Math.cos(0.5), tauMag = Math.hypot(...vec.tau);
    check(Math.abs(vec.L[2] - pphi) < 2e-3 * pphi && vec.tau[2] === 0 && Math.abs(vec.tau[0] * vec.L[0] + vec.tau[1] * vec.L[1]) < 0.05 * tauMag * Math.hypot(...vec.L),
      `${tag}: tops: L, ω, τ drawn at the end: L·ẑ = ${vec.L[2]} against p_φ = ${pphi}, τ horizontal (${tauMag.toFixed(4)} N m) and across L`);
    // the energy bars: E′ = ½I1(θ̇² + φ̇² sin²θ) + Mgh cos θ level: at the release (θ̇ = φ̇ = 0) Mgh cos θ0 = 0.98066 cos 0.5 J
    const E0 = 1 * 9.80665 * 0.1 * Math.cos(0.5), Eend = vec.K + vec.U;
    check(Math.abs(Eend - E0) < 1e-3 * E0 && vec.K > 1e-3, `${tag}: tops: the energy bars trade (wobble ${vec.K.toFixed(4)} J at the end) and E′ stays ${Eend.toFixed(5)} J against Mgh cos θ0 = ${E0.toFixed(5)} J`);
    check(page.errors.length === 0, `${tag}: live view: no script errors (${page.errors.join(' | ')})`);
  } catch (e) {
    check(false, `${tag}: live view: ${e.message.split('\n')[0]}`);
    await page.screenshot({path: path.join(shots, `sim-${tag}-live-failed.png`)}).catch(() => {});
  } finally { await page.close(); }
}

// --- the whole state in a link: a body's parts and a 3-D view's camera; rolling down an incline ---
// The solid sphere (2 kg, R = 0.5 m) on a 30° slope: k = I/(mR²) = 2/5, a = g sin α/(1 + k) = 3.50238 m/s²,
// over 2 m t = √(2L/a), v = √(2aL). A point of 1 kg added at (0, 0, 1): the centre of mass moves up the z axis,
// the moment about z stays the sphere's 0.2 kg m², so k = 0.2/(3 · 0.25) and the mass is 3 kg.
for (const width of [1280, 390]) {
  const tag = width < 500 ? 'phone' : 'desktop';
  const page = await newPage(width);
  try {
    await page.goto(`${base}/#inertia`);
    await settled(page);
    await page.waitForFunction(() => [...document.querySelector('.examples select').options].some(o => /Solid sphere/.test(o.textContent)), null, {timeout: 10000});
    await page.waitForTimeout(300);
    const idx = await page.$eval('.examples select', (s) => [...s.options].findIndex(o => /Solid sphere/.test(o.textContent)));
    await page.selectOption('.examples select', {index: idx});
    await page.click('.examples button');
    await settled(page);
    const g = 9.80665, incline = async (k, m) => {
      const a = g * 0.5 / (1 + k);
      const got = {k: await value(page, '#inertia-inc-k'), a: await value(page, '#inertia-inc-a'), t: await value(page, '#inertia-inc-time'),
        v: await value(page, '#inertia-inc-speed'), m: await value(page, '#inertia-total-mass')};
      return [Math.abs(got.k - k) < 1e-12 && Math.abs(got.a - a) < 1e-12 * a && Math.abs(got.t - Math.sqrt(4 / a)) < 1e-12 * got.t &&
        Math.abs(got.v - Math.sqrt(4 * a)) < 1e-12 * got.v && got.m === m, got, a];
    };
    await page.fill('#inertia-inc-angle', '30'); await page.fill('#inertia-inc-radius', '0.5'); await page.fill('#inertia-inc-length', '2');
    await page.click('#inertia-submit');
    await page.waitForSelector('#inertia-inc-a', {timeout: 20000}); await settled(page);
    let [ok, got, a] = await incline(0.4, 2);
    check(ok, `${tag}: incline: the solid sphere rolls at g sin 30°/(1 + 2/5) = ${a} m/s², 2 m in √(2L/a) (got ${JSON.stringify(got)})`);
    await page.click('#inertia-add-part');
    await page.fill('#inertia-pos-1-2', '1');
    await page.click('#inertia-submit');
    await page.waitForFunction(() => document.getElementById('inertia-total-mass')?.dataset.value === '3', null, {timeout: 20000});
    await settled(page);
    [ok, got, a] = await incline(0.2 / 0.75, 3);
    check(ok, `${tag}: incline: a point of 1 kg added on the axis: k = 0.2/(3 · 0.5²), a = ${a} m/s² (got ${JSON.stringify(got)})`);
    // the 3-D view turned by the keys: 0.1 rad a press
    const view = page.locator('#inertia-view');
    await view.scrollIntoViewIfNeeded(); await view.focus();
    const yaw0 = Number(await view.getAttribute('data-yaw'));
    for (let k = 0; k < 3; k++) await page.keyboard.press('ArrowLeft');
    await page.keyboard.press('ArrowUp');
    await page.waitForFunction((y) => Math.abs(Number(document.getElementById('inertia-view').dataset.yaw) - y - 0.3) < 1e-3, yaw0, {timeout: 5000});
    const cam = await view.evaluate((c) => [c.dataset.yaw, c.dataset.pitch]);
    await page.waitForFunction(() => /[?&]v0=/.test(location.hash) && /inertia-parts=/.test(location.hash), null, {timeout: 5000}).catch(() => {});
    check(/[?&]v0=/.test(page.url()) && /inertia-parts=/.test(page.url()), `${tag}: share: the address bar keeps the parts and the camera (${page.url().length} characters)`);
    await page.click('[data-role=copy-link]');
    const link = await page.inputValue('.share-link');
    const p2 = await newPage(width);
    await p2.goto(link);
    await p2.waitForSelector('main[data-restored=done]', {timeout: 30000});
    await settled(p2);
    await p2.waitForFunction(() => document.getElementById('inertia-total-mass')?.dataset.value === '3', null, {timeout: 20000}).catch(() => {});
    const got2 = await p2.evaluate(() => ({parts: document.querySelectorAll('#parts fieldset.part').length,
      shapes: [...document.querySelectorAll('#parts select')].map(s => s.value).join(','),
      a: document.getElementById('inertia-inc-a')?.dataset.value, cam: [document.getElementById('inertia-view').dataset.yaw, document.getElementById('inertia-view').dataset.pitch]}));
    check(got2.parts === 2 && got2.shapes === 'sphere,point' && Number(got2.a) === got.a && got2.cam[0] === cam[0] && got2.cam[1] === cam[1],
      `${tag}: share: the link rebuilds both parts, the incline and the camera (${JSON.stringify(got2)} against a = ${got.a}, camera ${cam})`);
    await p2.locator('#inertia-incline').scrollIntoViewIfNeeded();
    await p2.screenshot({path: path.join(shots, `sim-${tag}-inertia-link.png`)});
    check(p2.errors.length === 0, `${tag}: share: no script errors on the opened inertia link (${p2.errors.join(' | ')})`);
    await p2.close();
    // the Earth's 3-D view keeps its camera through a link too (the lab's own viewpoint does not override it)
    await page.goto('about:blank');
    await page.goto(`${base}/#earth?v0=1.234,0.321,1.5`);
    await page.waitForSelector('main[data-restored=done]', {timeout: 30000});
    await page.waitForFunction(() => document.getElementById('fou-view')?.dataset.yaw === '1.234', null, {timeout: 20000}).catch(() => {});
    const fc = await page.$eval('#fou-view', (c) => [c.dataset.yaw, c.dataset.pitch, c.dataset.zoom]);
    check(fc.join() === '1.234,0.321,1.500', `${tag}: share: the Foucault view opens at the linked camera (${fc})`);
    check(page.errors.length === 0, `${tag}: inertia and camera links: no script errors (${page.errors.join(' | ')})`);
  } catch (e) {
    check(false, `${tag}: inertia link: ${e.message.split('\n')[0]}`);
    await page.screenshot({path: path.join(shots, `sim-${tag}-inertia-link-failed.png`)}).catch(() => {});
  } finally { await page.close(); }
}

// --- the orbit's live view: v, gravity and the relativistic term on the planet, energy bars ---
// Mercury (a = 57.909 Gm, e = 0.2056): at perihelion the speed is Newton's vis-viva √(GM(1 + e)/(a(1 − e))) to the
// relativistic order GM/(c²a) ~ 10⁻⁸, the pull GM/r², and ½v² − GM/r (+ the tiny relativistic term) is −GM/2a.
for (const width of [1280, 390]) {
  const tag = width < 500 ? 'phone' : 'desktop';
  const page = await newPage(width);
  try {
    await page.goto(`${base}/#orbits`);
    await page.waitForFunction(() => document.querySelector('#orb-submit')?.form.dataset.state === 'done' && document.getElementById('orb-plot').dataset.state,
      null, {timeout: 30000});
    const GM = 1476.6250385094204 * 299792458 ** 2, A = 57909050000, E = 0.20563593, rp = A * (1 - E);
    const st = async () => JSON.parse(await page.getAttribute('#orb-plot', 'data-state'));
    const s0 = await st(), v0 = Math.hypot(s0.vr, s0.vt), visviva = Math.sqrt(GM * (1 + E) / (A * (1 - E)));
    const sum = (s) => s.K + s.U + s.Ugr;
    check(Math.abs(s0.r - rp) < 1e-9 * rp && Math.abs(v0 - visviva) < 1e-6 * visviva && Math.abs(s0.g - GM / (rp * rp)) < 1e-9 * s0.g &&
      Math.abs(sum(s0) + GM / (2 * A)) < 1e-6 * GM / (2 * A),
      `${tag}: orbits: at perihelion v = ${v0} m/s (vis-viva ${visviva}), g = GM/r², energy ${sum(s0)} J/kg against −GM/2a = ${-GM / (2 * A)}`);
    const pl = page.locator('.player').first();
    await pl.locator('[data-role=time]').focus();
    for (let k = 0; k < 60; k++) await page.keyboard.press('.');
    const s1 = await st();
    check(s1.r > rp * 1.05 && s1.K < s0.K * 0.95 && Math.abs(sum(s1) - sum(s0)) < 1e-9 * Math.abs(sum(s0)) && Math.abs(s1.vt * s1.r - s0.vt * s0.r) < 1e-9 * s0.vt * s0.r,
      `${tag}: orbits: 60 samples on, the kinetic bar has fallen (${s0.K.toExponential(4)} → ${s1.K.toExponential(4)} J/kg), the sum stays level and r v_φ = L`);
    const names = await page.$$eval('#orb-vectors [data-role=vector]', (v) => v.map(x => x.dataset.name));
    const bars = await page.$$eval('#orb-energy [data-role=bar]', (rs) => rs.map(r => Number(r.dataset.value)));
    check(names[0] === 'v' && names[1] === 'g' && /^GR ×/.test(names[2] || '') && bars.length === 4 && Math.abs(bars[3] - sum(s1)) < 1e-6 * Math.abs(bars[3]),
      `${tag}: orbits: v, g and the relativistic term (exaggerated like the precession) drawn on the planet, four energy bars (${names}; ${bars.map(b => b.toExponential(3))})`);
    check(/relativistic term 3GML²\/\(c²r⁴\)/.test(await page.textContent('#orb-vec-note')), `${tag}: orbits: the forces said in words`);
    await page.locator('#orb-plot').scrollIntoViewIfNeeded();
    await page.screenshot({path: path.join(shots, `sim-${tag}-orbit-vectors.png`)});
    // Tops: the nutation period and the precession averaged over one nutation, against the integrated motion: the
    // top released at θ0 with φ̇0 = 0 is back at θ0 one period later, having precessed by the averaged rate × T
    await page.goto('about:blank');
    await page.goto(`${base}/#tops`);
    await page.waitForFunction(() => document.querySelector('#top-submit')?.form.dataset.state === 'done', null, {timeout: 30000});
    const T = await value(page, '#top-nut-period'), avg = await value(page, '#top-prec-avg');
    const run = await (await fetch(base + '/v1/rigid/top', {method: 'POST', headers: {'Content-Type': 'application/json'},
      body: JSON.stringify({I1: 0.02, I3: 0.01, mass: 1, distance: 0.1, theta: 0.5, psi_dot: 60, phi_dot: 0, t_end: T, samples: 3,
        integrator: {accuracy: 'precise'}})})).json();
    const thEnd = run.theta[run.theta.length - 1], dphi = run.phi[run.phi.length - 1] - run.phi[0];
    check(Math.abs(thEnd - 0.5) < 1e-6 && Math.abs(dphi / T - avg) < 1e-6 * avg,
      `${tag}: tops: after the nutation period T = ${T} s the integrated top is back at θ0 (${thEnd}) and has precessed at the averaged rate (${dphi / T} against ${avg} rad/s)`);
    // the free body (I = 1, 2, 3 kg m², ω = (0.01, 1, 0.01) rad/s): ω drawn on it, T = ½ΣIₖωₖ² = 1.0002 J by axis; the sum
    // stays level while the middle axis' share falls as the body flips
    await page.waitForFunction(() => document.querySelector('#dz-submit')?.form.dataset.state === 'done', null, {timeout: 30000});
    const shares = await page.evaluate(async () => {
      const s = document.querySelector('#dz-3d-box ~ .player [data-role=time]'), out = [];
      for (let v = 0; v <= 1000; v += 20) {
        s.value = String(v); s.dispatchEvent(new Event('input', {bubbles: true}));
        out.push(JSON.parse(document.getElementById('dz-energy').dataset.parts));
      }
      return out;
    });
    const T0 = 0.5 * (1 * 1e-4 + 2 * 1 + 3 * 1e-4), sums = shares.map(p => p[0] + p[1] + p[2]);
    const level = Math.max(...sums.map(x => Math.abs(x - T0))) / T0, low = Math.min(...shares.map(p => p[1])) / T0;
    check(level < 1e-6 && low < 0.5 && /ω = [\d.]+ rad\/s/.test(await page.textContent('#dz-vectors')),
      `${tag}: tops: the free body's energy by axis sums to ½ΣIω² = ${T0} J (within ${level.toExponential(1)}) while the middle axis' share falls to ${low.toFixed(3)} in the flip`);
    check(page.errors.length === 0, `${tag}: orbit vectors, tops: no script errors (${page.errors.join(' | ')})`);
  } catch (e) {
    check(false, `${tag}: orbit vectors: ${e.message.split('\n')[0]}`);
    await page.screenshot({path: path.join(shots, `sim-${tag}-orbit-vectors-failed.png`)}).catch(() => {});
  } finally { await page.close(); }
}

// --- the oscillations lab: normal modes against closed forms, the motion as a sum of modes, energy level ---
for (const width of [1280, 390]) {
  const tag = width < 500 ? 'phone' : 'desktop';
  const page = await newPage(width);
  try {
    await page.goto(`${base}/#oscillations`);
    await settled(page);
    // three equal masses (1 kg) and springs (1 N/m) between walls: ω_j = 2 sin(jπ/8) rad/s
    const om = async () => Promise.all([0, 1, 2].map(k => value(page, `#osc-omega-${k}`)));
    const w = await om();
    check(w.every((x, j) => Math.abs(x - 2 * Math.sin((j + 1) * Math.PI / 8)) < 1e-12), `${tag}: oscillations: ω_j = 2√(k/m) sin(jπ/8) (${w})`);
    check(Number(await page.getAttribute('#osc-notes', 'data-abs')) < 1e-12, `${tag}: oscillations: the closed form's box agrees to round-off`);
    // the start q = (0.1, 0, 0) m: E = ½ qᵀKq = ½ · 2 N/m · 0.01 m² = 0.01 J; the bars trade and their sum stays level
    check(Math.abs(await value(page, '#osc-energy-total') - 0.01) < 1e-15, `${tag}: oscillations: E = ½qᵀKq = 0.01 J`);
    const en = async () => JSON.parse(await page.getAttribute('#osc-energy', 'data-energy'));
    await page.locator('#osc-scene ~ .player [data-role=time]').focus();
    for (let k = 0; k < 7; k++) await page.keyboard.press('.');
    const e1 = await en();
    check(e1.T > 1e-4 && Math.abs(e1.T + e1.U - 0.01) < 1e-12, `${tag}: oscillations: ½q̇ᵀMq̇ = ${e1.T} J and ½qᵀKq = ${e1.U} J sum to 0.01 J`);
    // started in mode 2 (v ∝ (1, 0, −1)): only that mode is excited and the middle mass stays still
    await page.click('#osc-start-1');
    await page.waitForFunction(() => document.getElementById('osc-q').value.startsWith('0.1, 0, -0.1'), null, {timeout: 5000});
    await settled(page);
    await page.waitForFunction(() => document.getElementById('osc-a') && JSON.parse(document.getElementById('osc-a').dataset.value)[1] !== 0.05 &&
      document.querySelector('#osc-submit').form.dataset.state === 'done', null, {timeout: 20000});
    const am = JSON.parse(await page.getAttribute('#osc-a', 'data-value'));
    await page.locator('#osc-scene ~ .player [data-role=time]').focus();
    for (let k = 0; k < 9; k++) await page.keyboard.press('.');
    const mid = await page.$$eval('#osc-scene rect[data-x]', (r) => r.map(x => Number(x.dataset.x)));
    check(Math.abs(am[0]) < 1e-12 * Math.abs(am[1]) && Math.abs(am[2]) < 1e-12 * Math.abs(am[1]) && Math.abs(mid[1]) < 1e-12 && Math.abs(mid[0] + mid[2]) < 1e-12,
      `${tag}: oscillations: started in mode 2, a_k = (${am}), the middle mass still (${mid[1]}) and the outer ones opposite (${mid[0]}, ${mid[2]})`);
    // the start dragged: the first mass's ring moved right by pointer, the middle one's by ArrowUp (0.01 m); the energy
    // answered is ½qᵀKq with K = [[2, −1, 0], [−1, 2, −1], [0, −1, 2]] N/m for the new start, at rest
    const qNow = async () => (await page.inputValue('#osc-q')).split(',').map(Number);
    const Eof = (q) => 0.5 * (2 * q[0] * q[0] + 2 * q[1] * q[1] + 2 * q[2] * q[2] - 2 * q[0] * q[1] - 2 * q[1] * q[2]);
    check(await sliderOk(page, '#osc-start-q0'), `${tag}: oscillations: each start is a slider with its value in words`);
    const before = await qNow();
    // (sliderOk and drag are defined with the handles' section below: hoisted functions)
    await drag(page, '#osc-start-q0', 40, 0);
    await page.waitForFunction((q) => document.getElementById('osc-q').value !== q, before.join(', '), {timeout: 10000});
    await settled(page); await page.waitForTimeout(400); await settled(page);
    let qs = await qNow();
    check(qs[0] > before[0] && Math.abs(await value(page, '#osc-energy-total') - Eof(qs)) < 1e-14,
      `${tag}: oscillations: the first mass's start dragged to ${qs[0]} m: E = ½qᵀKq = ${Eof(qs)} J`);
    await page.focus('#osc-start-q1'); await page.keyboard.press('ArrowUp');
    await page.waitForFunction(() => Number(document.getElementById('osc-q').value.split(',')[1]) === 0.01, null, {timeout: 10000});
    await settled(page); await page.waitForTimeout(400); await settled(page);
    qs = await qNow();
    check(Math.abs(await value(page, '#osc-energy-total') - Eof(qs)) < 1e-14, `${tag}: oscillations: ArrowUp starts the middle mass at 0.01 m: E = ${Eof(qs)} J`);
    check(/x1 starts at 0\.01 m/.test(await page.getAttribute('#osc-start-q1', 'aria-valuetext')), `${tag}: oscillations: the handle says where it starts`);
    await page.locator('#osc-scene').scrollIntoViewIfNeeded();
    await page.screenshot({path: path.join(shots, `sim-${tag}-oscillations.png`)});
    // every worked example computes, clean; the double pendulum's ω² = (2 ∓ √2) g/l
    const titles = await page.$$eval('.examples select option', (o) => o.map(x => x.textContent));
    for (let i = 0; i < titles.length; i++) {
      await page.selectOption('.examples select', {index: i});
      await page.click('.examples button');
      await page.waitForTimeout(100); await settled(page);
      const bad = await page.evaluate(() => { const t = document.querySelector('main').innerText;
        return [/(?<![A-Za-z])(NaN|undefined)(?![A-Za-z])/.test(t), [...document.querySelectorAll('.problem, .err')].some(b => b.textContent.trim())]; });
      check(!bad[0] && !bad[1] && await page.getAttribute('main form', 'data-state') === 'done', `${tag}: oscillations: the example "${titles[i]}" computes, clean`);
      if (/Double pendulum/.test(titles[i])) {
        const d = await Promise.all([0, 1].map(k => value(page, `#osc-omega-${k}`)));
        check(Math.abs(d[0] ** 2 - (2 - Math.SQRT2) * 9.80665) < 1e-12 * 9.80665 && Math.abs(d[1] ** 2 - (2 + Math.SQRT2) * 9.80665) < 1e-12 * 9.80665,
          `${tag}: oscillations: the equal double pendulum's ω² = (2 ∓ √2) g/l (${d.map(x => x * x)})`);
      }
    }
    check(await wide(page) <= 0, `${tag}: oscillations: nothing wider than the screen (${await wide(page)} px)`);
    // a mass that is not a number: said on its field
    await page.selectOption('#osc-system', 'spring_chain');
    await page.fill('#osc-masses', '1, foo, 1'); await page.fill('#osc-springs', '1, 1, 1, 1'); await page.fill('#osc-q', '0.1, 0, 0');
    await page.click('#osc-submit');
    await page.waitForSelector('main form[data-state=error]', {timeout: 20000});
    await errorOnField(page, '#osc-masses', `${tag}: oscillations: a mass "foo"`, /“foo” \(mass 2\) is not a number/);
    await axe(page, `${tag}: oscillations`);
    check(page.errors.length === 0, `${tag}: oscillations: no script errors (${page.errors.join(' | ')})`);
  } catch (e) {
    check(false, `${tag}: oscillations: ${e.message.split('\n')[0]}`);
    await page.screenshot({path: path.join(shots, `sim-${tag}-oscillations-failed.png`)}).catch(() => {});
  } finally { await page.close(); }
}

// --- the smaller things --------------------------------------------------------
for (const width of [1280, 390]) {
  const tag = width < 500 ? 'phone' : 'desktop';
  const page = await newPage(width);
  try {
    // every "What the notes say" box has a name of its own (two boxes in one lab differ)
    for (const lab of ['orbits', 'particles', 'spacetime', 'earth', 'tops']) {
      await page.goto('about:blank');
      await page.goto(`${base}/#${lab}`);
      await page.waitForFunction(() => [...document.querySelectorAll('main form[data-state]')].length > 0 &&
        [...document.querySelectorAll('main form[data-state]')].every(f => f.dataset.state !== 'busy') &&
        document.querySelectorAll('[data-role=teach] h3').length > 0, null, {timeout: 30000});
      await page.waitForTimeout(300);
      const names = await page.$$eval('[data-role=teach]', (bs) => bs.filter(b => b.childElementCount).map(b => {
        const id = b.getAttribute('aria-labelledby'), h = id && document.getElementById(id);
        return h ? h.textContent : b.getAttribute('aria-label');
      }));
      check(names.length > 0 && new Set(names).size === names.length && names.every(n => /^What the notes say: §/.test(n)),
        `${tag}: ${lab}: each notes box has its own name (${JSON.stringify(names)})`);
      // legend text on the plots: at least 4.5:1 on white (WCAG relative luminance)
      const fills = await page.$$eval('svg text.legend', (ts) => ts.map(t => t.getAttribute('fill')));
      const lum = (hex) => { const v = [1, 3, 5].map(i => parseInt(hex.slice(i, i + 2), 16) / 255)
        .map(c => c <= 0.03928 ? c / 12.92 : ((c + 0.055) / 1.055) ** 2.4); return 0.2126 * v[0] + 0.7152 * v[1] + 0.0722 * v[2]; };
      const low = fills.filter(f => /^#[0-9a-f]{6}$/i.test(f) && 1.05 / (lum(f) + 0.05) < 4.5);
      check(low.length === 0, `${tag}: ${lab}: legend text at 4.5:1 or more on white (below: ${low.join(', ')})`);
    }
    if (width < 500) { // the phone's header leaves the lab the first screen
      await page.goto('about:blank');
      await page.goto(`${base}/#spacetime`);
      await page.waitForSelector('main h2');
      const h = await page.$eval('header', (e) => e.getBoundingClientRect().height);
      check(h <= 0.2 * 844, `phone: the header takes ${Math.round(h)} px, at most a fifth of the 844 px screen`);
      check(await wide(page) <= 0, 'phone: the one-row tabs scroll inside the header, not the page');
      await page.screenshot({path: path.join(shots, 'sim-phone-header.png')});
    }
    check(page.errors.length === 0, `${tag}: smaller items: no script errors (${page.errors.join(' | ')})`);
  } catch (e) {
    check(false, `${tag}: smaller items: ${e.message.split('\n')[0]}`);
  } finally { await page.close(); }
}
// 100,000 orbits: 600 samples are 1 per 167 orbits: drawn as dots (no chords), the exaggeration at most a quarter turn over the run
{
  const page = await newPage(1280);
  try {
    await page.goto(`${base}/#orbits`);
    await settled(page);
    await page.fill('#orb-n', '100000');
    await page.selectOption('#orb-cost-acc', 'draft');
    await page.click('#orb-submit');
    await page.waitForFunction(() => document.querySelector('#orb-submit')?.form.dataset.state === 'done', null, {timeout: 120000});
    const st = await page.evaluate(() => ({lines: document.querySelectorAll('#orb-plot g.data polyline').length,
      dots: document.querySelectorAll('#orb-plot g.data circle').length,
      top: Math.max(...[...document.getElementById('orb-exaggerate').options].map(o => Number(o.value))),
      advance: Number(document.getElementById('orb-measured').dataset.value)}));
    // the drawn turn over the run, k δ N, stays under π/2 (δ = 5.0e-7 rad: 10⁶ would be 50 rad, eight turns)
    check(st.lines === 0 && st.dots >= 600 && st.top * st.advance * 1e5 <= Math.PI / 2,
      `100,000 orbits: drawn as ${st.dots} dots, no chords (${st.lines} lines), largest exaggeration ×${st.top}: ${(st.top * st.advance * 1e5).toFixed(2)} rad over the run`);
    await page.locator('#orb-plot').scrollIntoViewIfNeeded();
    await page.screenshot({path: path.join(shots, 'sim-desktop-100000-orbits.png')});
  } catch (e) {
    check(false, `100,000 orbits: ${e.message.split('\n')[0]}`);
  } finally { await page.close(); }
}

// --- the token for the browser session -------------------------------------------
// a second tab of the same browser does not ask again; nothing in localStorage
{
  const dir = fs.mkdtempSync(path.join(fs.realpathSync(process.env.TMPDIR || '/tmp'), 'mechd-sim-token-'));
  const token = 'sim-' + Math.random().toString(36).slice(2);
  fs.writeFileSync(path.join(dir, 'token'), token + '\n', {mode: 0o600});
  const guarded = startMechd(['--token-file', path.join(dir, 'token')]);
  const gbase = await guarded.url;
  const ctx = await browser.newContext({viewport: {width: 1280, height: 900}});
  try {
    const t1 = await ctx.newPage();
    await t1.goto(`${gbase}/#spacetime`);
    await t1.waitForSelector('#token-input', {state: 'visible', timeout: 15000});
    await t1.fill('#token-input', token);
    await t1.click('#token-use');
    await t1.waitForSelector('#st-gamma', {timeout: 20000});
    const t2 = await ctx.newPage(); // a new tab, as a student opens one
    await t2.goto(`${gbase}/#tides`);
    const ok = await t2.waitForFunction(() => { const f = document.querySelector('main form'); return f && f.dataset.state === 'done'; },
      null, {timeout: 20000}).then(() => true, () => false);
    const asked = await t2.isVisible('#token-input');
    check(ok && !asked, `token: a new tab computes without asking for the token again (computed ${ok}, asked ${asked})`);
    const ls = await t2.evaluate(() => JSON.stringify(localStorage));
    check(!ls.includes(token), 'token: never in localStorage');
    await t2.click('#token-toggle'); await t2.click('#token-forget');
    await t1.waitForFunction(() => !sessionStorage.getItem('mechd-token'), null, {timeout: 5000}).then(() => check(true, 'token: Forget forgets it in every tab'),
      () => check(false, 'token: Forget forgets it in every tab'));
  } catch (e) {
    check(false, `token: ${e.message.split('\n')[0]}`);
  } finally {
    await ctx.close();
    guarded.proc.kill('SIGTERM');
    fs.rmSync(dir, {recursive: true, force: true});
  }
}

// --- embedding -------------------------------------------------------------------
// A course page on another origin frames the lab: refused by default, shown
// (compact) with --frame-ancestors naming that origin.
{
  const host = http.createServer((req, res) => {
    const target = new URL(req.url, 'http://x').searchParams.get('src');
    res.writeHead(200, {'Content-Type': 'text/html; charset=utf-8'});
    res.end(`<!doctype html><title>Course page</title><h1>Week 3</h1><iframe id="lab" title="mechd Spacetime lab" width="900" height="700" src="${target}"></iframe>`);
  });
  await new Promise((r) => host.listen(0, '127.0.0.1', r));
  const hostOrigin = `http://127.0.0.1:${host.address().port}`;
  const allowed = startMechd(['--frame-ancestors', hostOrigin]);
  const abase = await allowed.url;
  try {
    const h0 = await fetch(base + '/'), h1 = await fetch(abase + '/');
    check(h0.headers.get('x-frame-options') === 'DENY' && /frame-ancestors 'none'/.test(h0.headers.get('content-security-policy')),
      'embed: by default the page says X-Frame-Options: DENY and frame-ancestors \'none\'');
    check(h1.headers.get('x-frame-options') === null && h1.headers.get('content-security-policy').includes(`frame-ancestors ${hostOrigin}`),
      `embed: with --frame-ancestors the CSP names the course site (${h1.headers.get('content-security-policy')})`);
    const api = await fetch(abase + '/v1');
    check(/frame-ancestors 'none'/.test(api.headers.get('content-security-policy') || ''), 'embed: the API\'s answers stay unframeable');
    for (const [what, src, ok] of [['refused without the option', `${base}/#spacetime`, false],
                                   ['shown with the option', `${abase}/?embed=1#spacetime`, true]]) {
      const page = await newPage(1280);
      await page.goto(`${hostOrigin}/?src=${encodeURIComponent(src)}`);
      await page.waitForTimeout(ok ? 0 : 2500);
      const frame = page.frame({url: (u) => u.href.startsWith(ok ? abase : base)});
      const lab = frame ? await frame.waitForSelector(ok ? 'main[data-lab=spacetime] #st-gamma' : 'main[data-lab]', {timeout: ok ? 20000 : 3000}).then(() => true, () => false) : false;
      check(lab === ok, `embed: ${what} (the lab ${lab ? 'shows' : 'does not show'} in the course page's frame)`);
      if (ok) {
        const st = await frame.evaluate(() => ({embedded: document.body.classList.contains('embedded'),
          header: getComputedStyle(document.querySelector('header')).display, out: !!document.querySelector('.embed-bar a')}));
        check(st.embedded && st.header === 'none' && st.out, `embed: compact inside the frame (no header, a link out): ${JSON.stringify(st)}`);
        await page.screenshot({path: path.join(shots, 'sim-embedded.png')});
      }
      await page.close();
    }
  } catch (e) {
    check(false, `embed: ${e.message.split('\n')[0]}`);
  } finally {
    allowed.proc.kill('SIGTERM');
    host.close();
  }
}

await browser.close();
main.proc.kill('SIGTERM');
console.log(`screenshots: ${shots}`);
console.log(`${passed} passed, ${failed} failed`);
process.exit(failed ? 1 : 0);
