// screenshots.mjs — the README's pictures of the classroom front end, taken
// from the real pages: mechd started on port 0 with this tree's clients/web,
// Debian's /usr/bin/chromium driven by playwright-core (no browser download),
// each lab loaded, its requests answered, then a picture of the window.
// Desktop pictures are taken at 1280×800 and scaled to 3/4 (960×600) in the
// browser's own canvas (no image tools needed); phone pictures at 390×844.
// PNG throughout, each checked to be a PNG under 400 kB.
//
// usage: node screenshots.mjs MECHD_BINARY OUT_DIR   (scripts/readme-screenshots.sh)
import {chromium} from 'playwright-core';
import {spawn} from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';

const [mechd, outArg] = process.argv.slice(2);
if (!mechd || !outArg) { console.error('usage: node screenshots.mjs MECHD_BINARY OUT_DIR'); process.exit(2); }
const out = path.resolve(outArg);
fs.mkdirSync(out, {recursive: true});
const webRoot = path.resolve(process.env.MECHD_WEB_ROOT || 'clients/web');

// [file, lab, viewport, what to show: a selector scrolled to the top (a select with its heading), and an optional action]
const SHOTS = [
  ['desktop-tops.png', 'tops', 'desktop', 'main h2', async (p) => { await p.click('#top-3d-box ~ .player [data-role=play]');
    await p.waitForTimeout(900); await p.click('#top-3d-box ~ .player [data-role=play]'); }],
  ['desktop-foucault.png', 'earth', 'desktop', '#fou-frame', async (p) => {
    await p.focus('#fou-3d-box ~ .player [data-role=time]');
    for (let i = 0; i < 60; i++) await p.keyboard.press('ArrowRight'); }],
  ['desktop-orbits.png', 'orbits', 'desktop', 'main h2', null],
  // the chain of three masses mid-swing beside its normal modes and energy bars
  ['desktop-oscillations.png', 'oscillations', 'desktop', 'main .results h3', async (p) => {
    await p.focus('#osc-scene ~ .player [data-role=time]');
    for (let i = 0; i < 9; i++) await p.keyboard.press('.'); }],
  ['desktop-notes.png', 'earth', 'desktop', 'main h2', null], // the falling object beside "What the notes say"
  ['phone-tides.png', 'tides', 'phone', 'main svg.plot', null],
  ['phone-rotations.png', 'rotations', 'phone', 'canvas.view3d', null],
];
const SIZES = {desktop: {width: 1280, height: 800}, phone: {width: 390, height: 844}};

const proc = spawn(mechd, ['--port', '0', '--static-dir', webRoot], {stdio: ['ignore', 'pipe', 'ignore']});
const base = await new Promise((resolve, reject) => {
  let s = '';
  const t = setTimeout(() => reject(new Error('mechd did not start: ' + s)), 10000);
  proc.stdout.on('data', (d) => { s += d; const m = s.match(/listening on (http:\/\/\S+)/); if (m) { clearTimeout(t); resolve(m[1].replace(/\/$/, '')); } });
});
const browser = await chromium.launch({executablePath: process.env.CHROMIUM || '/usr/bin/chromium', headless: true,
  args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking',
         '--disable-component-update', '--disable-sync']});
let bad = 0;
try {
  for (const [file, lab, size, top, act] of SHOTS) {
    const page = await browser.newPage({viewport: SIZES[size]});
    await page.goto(`${base}/#${lab}`);
    await page.waitForSelector('main[data-lab]');
    await page.waitForFunction(() => { const f = [...document.querySelectorAll('main form')];
      return f.length && f.every(x => x.dataset.state && x.dataset.state !== 'busy'); }, null, {timeout: 30000});
    if (act) await act(page);
    await page.evaluate((sel) => { const e = document.querySelector(sel); // its heading too, when it has one just above
      if (e) window.scrollTo(0, e.getBoundingClientRect().top + scrollY - (e.tagName === 'SELECT' ? 70 : 8)); }, top);
    await page.waitForTimeout(400);
    let png = await page.screenshot();
    if (size === 'desktop') { // 3/4 size, drawn by the browser into a canvas
      const b64 = await page.evaluate(async (src) => {
        const img = new Image(); img.src = 'data:image/png;base64,' + src; await img.decode();
        const c = document.createElement('canvas'); c.width = img.width * 3 / 4; c.height = img.height * 3 / 4;
        const g = c.getContext('2d'); g.imageSmoothingQuality = 'high'; g.drawImage(img, 0, 0, c.width, c.height);
        return c.toDataURL('image/png').split(',')[1];
      }, png.toString('base64'));
      png = Buffer.from(b64, 'base64');
    }
    const ok = png.toString('latin1', 1, 4) === 'PNG' && png.length < 400000;
    if (!ok) bad++;
    fs.writeFileSync(path.join(out, file), png);
    console.log(`${ok ? 'ok  ' : 'BAD '} ${path.join(out, file)} (${(png.length / 1024).toFixed(0)} kB)`);
    await page.close();
  }
} finally {
  await browser.close();
  proc.kill('SIGTERM');
}
process.exit(bad ? 1 : 0);
