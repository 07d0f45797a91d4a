// The interactive page in a real browser (docs/plots.md, "The interactive
// page"; docs/testing.md): Debian's Chromium, headless with software
// WebGL, driven by playwright-core from web/node_modules.
//   node tests/browser/page.test.mjs BUILD_DIR SOURCE_DIR
// Then every bundled example's page must load without error, drawn and
// labelled. Exit 0 when every check passes, 1 otherwise, 77 (ctest: skipped) when
// Chromium or web/node_modules is missing. Writes BUILD_DIR/tests/browser/
// page.png, the screenshot docs/interactive-page.png is a copy of.
import { execFileSync } from 'node:child_process';
import { existsSync, mkdirSync, mkdtempSync, readdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';

const CHROMIUM = '/usr/bin/chromium';
const DIGITS = 10; // significant digits the page shows (web/page.js)
const INK_FRACTION = 0.02; // of the view's pixels: at least this many drawn (not background)
const COLOUR_SLACK = 8; // per channel, 0..255: how near a pixel must be to a drawn colour
const LOAD_TIMEOUT_MS = 30000;

const [build, source] = process.argv.slice(2).map((d) => d && resolve(d));
if (!build || !source) {
  console.error('usage: page.test.mjs BUILD_DIR SOURCE_DIR');
  process.exit(2);
}
const skip = (why) => {
  console.log(`browser test skipped: ${why} (make deps installs both)`);
  process.exit(77);
};
if (!existsSync(CHROMIUM)) skip(`no ${CHROMIUM} (Debian package chromium)`);
if (!existsSync(join(source, 'web/node_modules/playwright-core'))) skip('no web/node_modules (npm ci in web/)');
const { chromium } = createRequire(join(source, 'web/package.json'))('playwright-core');

let pass = 0, fail = 0;
function check(what, ok, detail = '') {
  if (ok) pass++;
  else {
    fail++;
    console.log(`FAIL: ${what}${detail ? ': ' + detail : ''}`);
  }
}

const tmp = mkdtempSync(join(tmpdir(), 'ic-page-'));
const bin = join(build, 'intercurve');
const example = join(source, 'examples/viviani-implicit.json');
const run = (...args) => execFileSync(bin, args, { stdio: ['ignore', 'pipe', 'inherit'] });

// The pages: Viviani's curve, and the same problem titled so as to close
// the script elements the data are in.
const vivianiPage = join(tmp, 'viviani.html');
run('plot', example, '-o', vivianiPage);
run('trace', example, '-o', join(tmp, 'trace.json'));
const traced = JSON.parse(readFileSync(join(tmp, 'trace.json'), 'utf8'));
const HOSTILE_TITLE = 'A </script><script>window.injected = 1</script> <!-- & "quotes" </SCRIPT';
const hostile = JSON.parse(readFileSync(example, 'utf8'));
hostile.title = HOSTILE_TITLE;
writeFileSync(join(tmp, 'hostile.json'), JSON.stringify(hostile));
const hostilePage = join(tmp, 'hostile.html');
run('plot', join(tmp, 'hostile.json'), '-o', hostilePage, '--mesh', '8');

const browser = await chromium.launch({
  executablePath: CHROMIUM,
  headless: true,
  // WebGL on the CPU (a CI machine has no GPU), the page composited in
  // software: much faster there than through the emulated GPU
  args: ['--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--disable-gpu-compositing',
    '--no-sandbox'],
});

async function open(path) {
  const page = await browser.newPage({ viewport: { width: 1400, height: 800 }, acceptDownloads: true });
  const errors = [];
  page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
  page.on('pageerror', (e) => errors.push(e.message));
  await page.goto('file://' + path);
  await page.waitForFunction(() => window.intercurveScene && window.intercurveScene.framesDrawn > 0,
    null, { timeout: LOAD_TIMEOUT_MS });
  return { page, errors };
}

// Pixels of the WebGL canvas: how many differ from the white background,
// and how many are near the colour rgb (0..255).
async function canvasPixels(page, rgb) {
  return page.evaluate(([rgb, slack]) => {
    const gl = document.querySelector('#ic-view canvas');
    const c = document.createElement('canvas');
    c.width = gl.width; c.height = gl.height;
    const ctx = c.getContext('2d');
    ctx.drawImage(gl, 0, 0);
    const d = ctx.getImageData(0, 0, c.width, c.height).data;
    let ink = 0, near = 0;
    for (let i = 0; i < d.length; i += 4) {
      if (d[i] < 250 || d[i + 1] < 250 || d[i + 2] < 250) ink++;
      if (Math.abs(d[i] - rgb[0]) <= slack && Math.abs(d[i + 1] - rgb[1]) <= slack &&
          Math.abs(d[i + 2] - rgb[2]) <= slack) near++;
    }
    return { ink, near, total: d.length / 4 };
  }, [rgb, COLOUR_SLACK]);
}

// Red pixels of the chart (its marker, #e01010).
async function chartMarkerPixels(page) {
  return page.evaluate(() => {
    const c = document.getElementById('ic-chart');
    const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    let n = 0;
    for (let i = 0; i < d.length; i += 4) if (d[i] > 200 && d[i + 1] < 60 && d[i + 2] < 60) n++;
    return n;
  });
}

// The panel's lines "name  v1  v2 ..." as numbers (null for "undefined").
function panelValues(text) {
  const out = {};
  for (const line of text.split('\n')) {
    const m = line.match(/^(s|xyz|t|n|b|kappa|tau)\s+(.*)$/);
    if (m) out[m[1]] = m[2].trim().split(/\s+/).map((w) => (w === 'undefined' ? null : Number(w)));
  }
  return out;
}

// shown agrees with the JSON's value to the DIGITS significant digits shown
function agrees(shown, value) {
  if (value === null || shown === null) return value === shown;
  if (value === 0) return shown === 0;
  const half = 0.5 * 10 ** (Math.floor(Math.log10(Math.abs(value))) - DIGITS + 1);
  return Math.abs(shown - value) <= 1.01 * half;
}

try {
  // ---- Viviani's curve
  const { page, errors } = await open(vivianiPage);
  const px = await canvasPixels(page, [0, 0, 0]);
  check('the view is drawn', px.ink > INK_FRACTION * px.total, `${px.ink} of ${px.total} pixels`);

  // the page's trace is the trace's document: downloaded whole
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#ic-download')]);
  const got = JSON.parse(readFileSync(await download.path(), 'utf8'));
  check('downloaded: as many curves as intercurve trace', got.curves.length === traced.curves.length);
  got.curves.forEach((c, i) => check(`downloaded curve ${i}: the points of intercurve trace`,
    JSON.stringify(c.points) === JSON.stringify(traced.curves[i].points)));
  check('downloaded: the singular points', JSON.stringify(got.points) === JSON.stringify(traced.points));

  // the singular points labelled by type
  const labels = await page.$$eval('.ic-label', (els) => els.map((e) => e.textContent));
  check('a label per singular point', labels.length === traced.points.length, labels.join(', '));
  for (const sp of traced.points) check(`label ${sp.type}`, labels.some((l) => l.startsWith(sp.type)));

  // pointing at a traced point shows its values and marks the chart
  const curve = traced.curves[0], k = Math.floor(curve.points.length / 3), p = curve.points[k];
  check('no chart marker before pointing', (await chartMarkerPixels(page)) === 0);
  const at = await page.evaluate(([c, i]) => window.intercurveScene.project(c, i), [0, k]);
  await page.mouse.move(at.x, at.y);
  await page.waitForFunction((i) => window.intercurveScene.hovered.index === i, k, { timeout: 5000 })
    .catch(() => {});
  const info = await page.textContent('#ic-info');
  check(`the panel names point ${k} of curve 0`, info.includes(`curve 0 `) && info.includes(`point ${k} of`), info.split('\n')[0]);
  const shown = panelValues(info);
  for (const key of ['s', 'kappa', 'tau']) {
    check(`${key} shown as in the trace`, shown[key] && agrees(shown[key][0], p[key]), `${shown[key]} vs ${p[key]}`);
  }
  for (const key of ['xyz', 't', 'n', 'b']) {
    check(`${key} shown as in the trace`, shown[key] && shown[key].length === 3 &&
      shown[key].every((v, d) => agrees(v, p[key][d])), `${shown[key]} vs ${p[key]}`);
  }
  check('the chart marks the point', (await chartMarkerPixels(page)) > 0);

  // the Frenet frames: off at first, in t's colour once switched on
  const T_RGB = [214, 39, 40]; // web/page.js FRAME_RGB.t
  const before = await canvasPixels(page, T_RGB);
  const drawn = await page.evaluate(() => window.intercurveScene.framesDrawn);
  await page.check('#ic-show-frames');
  await page.waitForFunction((n) => window.intercurveScene.framesDrawn > n, drawn, { timeout: 5000 });
  const after = await canvasPixels(page, T_RGB);
  check('frames switched on draw t', after.near > before.near + 50, `${before.near} -> ${after.near} pixels`);

  mkdirSync(join(build, 'tests/browser'), { recursive: true });
  await page.screenshot({ path: join(build, 'tests/browser/page.png') });
  check('no console error or page error (Viviani)', errors.length === 0, errors.join(' | '));

  // ---- a title that tries to close the script elements
  const h = await open(hostilePage);
  check('the hostile title shown as it is', (await h.page.textContent('#ic-title')) === HOSTILE_TITLE);
  check('the hostile title in the tab', (await h.page.title()) === HOSTILE_TITLE);
  check('nothing injected', (await h.page.evaluate(() => window.injected)) === undefined);
  check('its trace read whole', (await h.page.evaluate(() => window.intercurveScene.points)) ===
    traced.curves.reduce((a, c) => a + c.points.length, 0));
  check('no console error or page error (hostile title)', h.errors.length === 0, h.errors.join(' | '));

  // ---- nothing to trace: two spheres apart
  writeFileSync(join(tmp, 'apart.json'), JSON.stringify({
    title: 'two spheres apart',
    surfaces: [{ name: 'a', type: 'implicit', f: 'x^2 + y^2 + z^2 - 1' },
      { name: 'b', type: 'implicit', f: '(x - 3)^2 + y^2 + z^2 - 1' }],
    box: [[-1.5, 4.5], [-1.5, 1.5], [-1.5, 1.5]],
  }));
  run('plot', join(tmp, 'apart.json'), '-o', join(tmp, 'apart.html'), '--mesh', '12');
  const apart = await open(join(tmp, 'apart.html'));
  const said = await apart.page.textContent('#ic-info');
  check('two spheres apart: "no intersection"', said.startsWith('no intersection'), said);
  check('no console error or page error (apart)', apart.errors.length === 0, apart.errors.join(' | '));
  await apart.page.close();

  // ---- every bundled example's page: loads without error, drawn, labelled
  for (const name of readdirSync(join(source, 'examples')).filter((f) => f.endsWith('.json'))) {
    const out = join(tmp, name.replace(/\.json$/, '.html'));
    run('plot', join(source, 'examples', name), '-o', out);
    const e = await open(out);
    const ink = await canvasPixels(e.page, [0, 0, 0]);
    check(`${name}: drawn`, ink.ink > INK_FRACTION * ink.total, `${ink.ink} of ${ink.total} pixels`);
    const [nlabels, nspecials] = await e.page.evaluate(() => [document.querySelectorAll('.ic-label').length,
      JSON.parse(document.getElementById('ic-trace').textContent).points.length]);
    check(`${name}: a label per singular point`, nlabels === nspecials, `${nlabels} labels, ${nspecials} points`);
    check(`${name}: no console error or page error`, e.errors.length === 0, e.errors.join(' | '));
    await e.page.close();
  }
} catch (e) {
  check('the browser test ran', false, e.stack || String(e));
} finally {
  await browser.close();
  rmSync(tmp, { recursive: true, force: true });
}
console.log(`browser: ${pass} passed, ${fail} failed`);
process.exit(fail === 0 ? 0 : 1);
