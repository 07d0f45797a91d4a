// Frames per second of the interactive page for a trace of 100,000 points
// (docs/plots.md, "The interactive page"), in headless Chromium with
// software rendering (SwiftShader), as the browser test runs it:
//   node bench/bench_page.mjs BUILD_DIR [POINTS]
// bench_page_trace writes the page; the view then turns (OrbitControls'
// auto-rotation, so every frame is drawn anew) while the pointer sweeps the
// view (the nearest-point search after every camera move), for SECONDS,
// once as the page is (drawn coarser while the view moves), once always
// at full resolution, and once so without the surfaces. Prints the page's size, its load time, the frames
// drawn per second of each and the machine's load average.
import { execFileSync } from 'node:child_process';
import { mkdtempSync, rmSync, statSync } from 'node:fs';
import { createRequire } from 'node:module';
import { loadavg, tmpdir } from 'node:os';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const SECONDS = 5; // of turning and pointing, measured
const VIEW = { width: 1400, height: 800 }; // CSS pixels
const source = resolve(dirname(fileURLToPath(import.meta.url)), '..');
const build = resolve(process.argv[2] || 'build');
const points = process.argv[3] || '100000';
const { chromium } = createRequire(join(source, 'web/package.json'))('playwright-core');

const tmp = mkdtempSync(join(tmpdir(), 'ic-bench-page-'));
const page = join(tmp, 'page.html');
process.stdout.write(execFileSync(join(build, 'bench/bench_page_trace'),
  [join(source, 'examples/viviani-implicit.json'), page, points]));
console.log(`page: ${(statSync(page).size / 1e6).toFixed(1)} MB`);

// Frames drawn per second over SECONDS while the pointer sweeps the middle
// of the view.
async function framesPerSecond(tab) {
  const start = await tab.evaluate(() => [performance.now(), window.intercurveScene.framesDrawn]);
  const end = Date.now() + SECONDS * 1000;
  for (let i = 0; Date.now() < end; i++) {
    const a = i * 0.05;
    await tab.mouse.move(450 + 200 * Math.cos(a), 420 + 200 * Math.sin(a));
    await tab.waitForTimeout(16);
  }
  const stop = await tab.evaluate(() => [performance.now(), window.intercurveScene.framesDrawn]);
  return ((stop[1] - start[1]) * 1000) / (stop[0] - start[0]);
}

const browser = await chromium.launch({ executablePath: '/usr/bin/chromium', headless: true,
  args: ['--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--disable-gpu-compositing',
    '--no-sandbox'] });
try {
  const tab = await browser.newPage({ viewport: VIEW });
  tab.on('pageerror', (e) => console.log('page error:', e.message));
  const t0 = Date.now();
  await tab.goto('file://' + page);
  await tab.waitForFunction(() => window.intercurveScene && window.intercurveScene.framesDrawn > 0,
    null, { timeout: 120000 });
  console.log(`loaded and first frame drawn in ${((Date.now() - t0) / 1000).toFixed(1)} s, ` +
    `${await tab.evaluate(() => window.intercurveScene.points)} points`);
  await tab.evaluate(() => window.intercurveScene.setAutoRotate(true));
  for (const adaptive of [true, false]) {
    await tab.evaluate((on) => window.intercurveScene.setAdaptive(on), adaptive);
    const fps = await framesPerSecond(tab);
    console.log(`${fps.toFixed(1)} frames per second while turning and pointing, ` +
      (adaptive ? 'drawn coarser while moving (the page as it is)' : 'always at full resolution'));
  }
  // what the curve costs without the surfaces' translucent pixels
  await tab.click('#ic-show-surfaces');
  console.log(`${(await framesPerSecond(tab)).toFixed(1)} frames per second at full resolution ` +
    'with the surfaces switched off');
  console.log(`load average ${loadavg().map((x) => x.toFixed(2)).join(' ')} on this machine`);
} finally {
  await browser.close();
  rmSync(tmp, { recursive: true, force: true });
}
