// The interactive page of `intercurve plot -o FIGURE.html` (docs/plots.md,
// "The interactive page"): the surfaces as translucent meshes, the curves
// coloured by curvature, the singular points labelled, Frenet frames on
// demand, and the values of the traced point nearest the pointer, marked on
// the curvature and torsion chart beside the view. The data come from two
// JSON elements the library writes: ic-scene (title, names, region, meshes)
// and ic-trace (the trace document of `intercurve trace`).
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';

// The colours of the pictures (src/io/plot_view.c).
const VIRIDIS = [[0.267, 0.005, 0.329], [0.278, 0.175, 0.483], [0.229, 0.322, 0.546],
  [0.173, 0.449, 0.558], [0.128, 0.567, 0.551], [0.153, 0.683, 0.502],
  [0.369, 0.789, 0.383], [0.678, 0.864, 0.190], [0.993, 0.906, 0.144]];
const SURFACE_RGB = [[0.55, 0.70, 0.85], [0.93, 0.72, 0.50]];
const FRAME_RGB = { t: [0.839, 0.153, 0.157], n: [0.173, 0.627, 0.173], b: [0.122, 0.467, 0.706] };
const CURVE_PALETTE = ['#1f77b4', '#ff7f0e', '#2ca02c', '#d62728', '#9467bd', '#8c564b'];
const SURFACE_OPACITY = 0.4;
// Frenet arrows: this fraction of the region's diagonal, but at most
// ARROW_CURVE of the diagonal of the curve's own bounding box (as in the pictures)
const ARROW_BOX = 0.08;
const ARROW_CURVE = 0.2;
const MARKER_SIZE = 0.012; // fraction of the region's diagonal: singular points, hover mark
const CURVE_POINT_PX = 3; // CSS pixels: the traced points drawn along the curves
const LINE_STEP_PX = 0.5; // CSS pixels: the vertices of a curve's line drawn at least this far apart
const DOT_STEP_PX = 2; // CSS pixels: its dots drawn at least this far apart
const DETAIL_CHANGE = 1.25; // the drawn vertices are chosen anew when the zoom changed by this factor
const HOVER_RADIUS_PX = 12; // CSS pixels: a traced point this close to the pointer is picked
const GRID_CELL_PX = 16; // CSS pixels: a cell of the screen grid the projected points are sorted into
const DIGITS = 10; // significant digits of the values shown

const sceneData = JSON.parse(document.getElementById('ic-scene').textContent);
const traceText = document.getElementById('ic-trace').textContent;
const trace = JSON.parse(traceText) || { curves: [], points: [] };
const curves = trace.curves || [];
const specials = trace.points || [];

// three.js works in linear RGB: the sRGB colours above are converted
const srgb = (c) => new THREE.Color().setRGB(c[0], c[1], c[2], THREE.SRGBColorSpace);
const rgbCss = (c) => `rgb(${c.map((x) => Math.round(255 * x)).join(',')})`;

function viridis(t) {
  const x = Math.min(Math.max(t, 0), 1) * (VIRIDIS.length - 1);
  const i = Math.min(Math.floor(x), VIRIDIS.length - 2), f = x - i;
  return VIRIDIS[i].map((v, k) => v + f * (VIRIDIS[i + 1][k] - v));
}

function fmt(x) {
  return x === null || x === undefined ? 'undefined' : Number(x).toPrecision(DIGITS);
}
const fmtVec = (v) => (v ? v.map(fmt).join('  ') : 'undefined');

// The range of one value over every point (finite ones): the 2nd to 98th
// percentile widened by a fifth where a few values run far outside the rest
// (the curvature at a cusp), as in the pictures' chart; clipped says so.
function valueRange(key) {
  const v = [];
  for (const c of curves) for (const p of c.points) if (Number.isFinite(p[key])) v.push(p[key]);
  if (v.length === 0) return { lo: -1, hi: 1, clipped: false };
  v.sort((a, b) => a - b);
  let lo = v[0], hi = v[v.length - 1], clipped = false;
  const p2 = v[Math.floor(0.02 * (v.length - 1))], p98 = v[Math.floor(0.98 * (v.length - 1))];
  const core = p98 - p2;
  if (core > 0 && hi - lo > 3 * core) {
    lo = p2 - 0.2 * core; hi = p98 + 0.2 * core; clipped = true;
  }
  if (hi - lo <= 1e-9 * Math.max(Math.abs(lo), Math.abs(hi), 1e-300)) { // constant
    const pad = Math.max(0.1 * Math.abs(lo), 1e-3);
    lo -= pad; hi += pad;
  }
  return { lo, hi, clipped };
}

// ---- the 3D view
const box = sceneData.box;
const centre = new THREE.Vector3(...box.map((r) => 0.5 * (r[0] + r[1])));
const diagonal = Math.hypot(...box.map((r) => r[1] - r[0]));
const view = document.getElementById('ic-view');
const renderer = new THREE.WebGLRenderer({ antialias: false, preserveDrawingBuffer: true });
renderer.setPixelRatio(window.devicePixelRatio);
renderer.setClearColor(0xffffff, 1);
view.prepend(renderer.domElement);
const scene = new THREE.Scene();
const camera = new THREE.PerspectiveCamera(30, 1, diagonal * 1e-3, diagonal * 100);
camera.up.set(0, 0, 1);
{
  const az = THREE.MathUtils.degToRad(sceneData.view[0]);
  const el = THREE.MathUtils.degToRad(sceneData.view[1]);
  const dir = new THREE.Vector3(Math.cos(el) * Math.cos(az), Math.cos(el) * Math.sin(az), Math.sin(el));
  const dist = (0.55 * diagonal) / Math.tan(THREE.MathUtils.degToRad(camera.fov / 2));
  camera.position.copy(centre).addScaledVector(dir, dist);
}
scene.add(camera);
scene.add(new THREE.AmbientLight(0xffffff, 1.6));
const light = new THREE.DirectionalLight(0xffffff, 1.4);
light.position.set(0.3, 0.6, 1);
camera.add(light); // a head light: the side looked at is lit
const controls = new OrbitControls(camera, renderer.domElement);
controls.target.copy(centre);
controls.update();

scene.add(new THREE.Box3Helper(new THREE.Box3(
  new THREE.Vector3(box[0][0], box[1][0], box[2][0]),
  new THREE.Vector3(box[0][1], box[1][1], box[2][1])), 0xb0b0b0));

const surfaces = new THREE.Group();
for (const m of sceneData.meshes) {
  if (m.positions.length === 0) continue;
  const g = new THREE.BufferGeometry();
  g.setAttribute('position', new THREE.Float32BufferAttribute(m.positions, 3));
  // flat: each triangle's own normal (marching tetrahedra do not orient
  // neighbouring triangles alike, so averaged normals would cancel)
  g.computeVertexNormals();
  const material = new THREE.MeshLambertMaterial({
    color: srgb(SURFACE_RGB[m.surface]), transparent: true,
    opacity: SURFACE_OPACITY, side: THREE.DoubleSide, depthWrite: false,
    // pushed back a little: a curve lying on the surface is not dimmed by it
    polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1,
    forceSinglePass: true, // both sides in one pass: half the work of software rendering
  });
  surfaces.add(new THREE.Mesh(g, material));
}
scene.add(surfaces);

// ---- the curves, coloured by curvature
const kappaRange = valueRange('kappa');
const tauRange = valueRange('tau');
const curveViews = []; // per curve: arc lengths, the line's and the dots' geometry
let npoints = 0;
for (const c of curves) npoints += c.points.length;
// every traced point in one list: its curve, its index and where it is
const pointCurve = new Int32Array(npoints);
const pointIndex = new Int32Array(npoints);
const pointXyz = new Float64Array(3 * npoints);
{
  let g = 0;
  curves.forEach((c, ci) => {
    const pos = new Float32Array(3 * c.points.length), col = new Float32Array(3 * c.points.length);
    c.points.forEach((p, k) => {
      pointCurve[g] = ci; pointIndex[g] = k;
      for (let d = 0; d < 3; d++) pointXyz[3 * g + d] = pos[3 * k + d] = p.xyz[d];
      const rgb = Number.isFinite(p.kappa)
        ? viridis((p.kappa - kappaRange.lo) / (kappaRange.hi - kappaRange.lo)) : [0.5, 0.5, 0.5];
      const lin = srgb(rgb);
      col[3 * k] = lin.r; col[3 * k + 1] = lin.g; col[3 * k + 2] = lin.b;
      g++;
    });
    const position = new THREE.BufferAttribute(pos, 3), color = new THREE.BufferAttribute(col, 3);
    const view = (n) => {
      const geometry = new THREE.BufferGeometry();
      geometry.setAttribute('position', position);
      geometry.setAttribute('color', color);
      geometry.setIndex(new THREE.BufferAttribute(new Uint32Array(n), 1));
      return geometry;
    };
    const line = view(c.points.length), dots = view(c.points.length);
    const material = new THREE.LineBasicMaterial({ vertexColors: true });
    scene.add(c.closed ? new THREE.LineLoop(line, material) : new THREE.Line(line, material));
    // WebGL draws lines 1 px wide: the points drawn over them make the curve
    // thicker where they are dense and show where they are
    scene.add(new THREE.Points(dots, new THREE.PointsMaterial({
      vertexColors: true, size: CURVE_POINT_PX, sizeAttenuation: false })));
    curveViews.push({ s: Float64Array.from(c.points, (p) => p.s), line, dots });
  });
}

// The vertices drawn: of a long trace, only points at least `step` apart in
// arc length (and the ends), so that the view draws about what the screen
// can show (LINE_STEP_PX and DOT_STEP_PX apart) whatever the trace's length;
// remade when the zoom changed by a quarter. The search of the point
// pointed at uses every point.
function thin(geometry, s, step) {
  const index = geometry.index.array;
  let m = 0, last = -Infinity;
  for (let k = 0; k < s.length; k++) {
    if (s[k] - last >= step || k === s.length - 1) {
      index[m++] = k;
      last = s[k];
    }
  }
  geometry.index.needsUpdate = true;
  geometry.setDrawRange(0, m);
}

let detailScale = 0; // pixels per unit length the drawn vertices were chosen for
function updateDetail() {
  const d = camera.position.distanceTo(controls.target);
  // the scale at the nearest the curves can be: the front of the region
  const near = Math.max(d - 0.5 * diagonal, 0.1 * d);
  const scale = renderer.domElement.clientHeight / (2 * near * Math.tan(THREE.MathUtils.degToRad(camera.fov / 2)));
  if (detailScale > 0 && Math.abs(Math.log(scale / detailScale)) < Math.log(DETAIL_CHANGE)) return;
  detailScale = scale;
  for (const v of curveViews) {
    thin(v.line, v.s, LINE_STEP_PX / scale);
    thin(v.dots, v.s, DOT_STEP_PX / scale);
  }
}

// ---- Frenet frames at points equally spaced in arc length over all curves
function curveExtent(c) {
  const lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
  for (const p of c.points) for (let d = 0; d < 3; d++) {
    lo[d] = Math.min(lo[d], p.xyz[d]); hi[d] = Math.max(hi[d], p.xyz[d]);
  }
  return Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
}

function framePoints(count) {
  const lengths = curves.map((c) => (c.points.length ? c.points[c.points.length - 1].s - c.points[0].s : 0));
  const total = lengths.reduce((a, b) => a + b, 0);
  const at = [];
  if (!(total > 0)) return at;
  for (let j = 0; j < count; j++) {
    let s = ((j + 0.5) * total) / count, ci = 0;
    while (ci < curves.length - 1 && s > lengths[ci]) s -= lengths[ci++];
    const pts = curves[ci].points;
    const target = pts[0].s + s;
    let lo = 0, hi = pts.length - 1; // the first point at or past target
    while (lo < hi) {
      const mid = (lo + hi) >> 1;
      if (pts[mid].s < target) lo = mid + 1; else hi = mid;
    }
    at.push([ci, lo]);
  }
  return at;
}

const frames = new THREE.Group();
{
  const extents = curves.map(curveExtent);
  for (const [ci, k] of framePoints(sceneData.frames)) {
    const p = curves[ci].points[k];
    const len = Math.min(ARROW_BOX * diagonal, ARROW_CURVE * extents[ci]);
    for (const key of ['t', 'n', 'b']) {
      if (!p[key]) continue; // n and b where kappa = 0: undefined
      frames.add(new THREE.ArrowHelper(new THREE.Vector3(...p[key]), new THREE.Vector3(...p.xyz),
        len, srgb(FRAME_RGB[key]), 0.25 * len, 0.12 * len));
    }
  }
}
frames.visible = false;
scene.add(frames);

// ---- singular points: white balls with their type beside them
const labels = document.getElementById('ic-labels');
const specialLabels = specials.map((sp) => {
  const ball = new THREE.Mesh(new THREE.SphereGeometry(MARKER_SIZE * diagonal, 16, 12),
    new THREE.MeshLambertMaterial({ color: 0xffffff, emissive: 0x444444 }));
  ball.position.set(...sp.xyz);
  scene.add(ball);
  const el = document.createElement('div');
  el.className = 'ic-label';
  el.textContent = sp.type + (sp.approximate ? ' (approximate)' : '');
  labels.append(el);
  return { el, at: new THREE.Vector3(...sp.xyz) };
});

const hoverMark = new THREE.Mesh(new THREE.SphereGeometry(0.8 * MARKER_SIZE * diagonal, 16, 12),
  new THREE.MeshBasicMaterial({ color: 0xe01010 }));
hoverMark.visible = false;
scene.add(hoverMark);

// ---- title, legend, colour bar
document.getElementById('ic-title').textContent = sceneData.title || 'intercurve';
{
  const legend = document.getElementById('ic-legend');
  const row = (rgb, text) => {
    const line = document.createElement('div');
    const sw = document.createElement('span');
    sw.className = 'sw';
    sw.style.background = rgbCss(rgb);
    line.append(sw, text);
    legend.append(line);
  };
  sceneData.names.forEach((name, s) => row(SURFACE_RGB[s], (sceneData.self ? 'surface: ' : `surface ${'AB'[s]}: `) + (name || '')));
  for (const key of ['t', 'n', 'b']) row(FRAME_RGB[key], key);
  const bar = document.getElementById('ic-colorbar');
  if (curves.length === 0) bar.hidden = true;
  const stops = VIRIDIS.map((c, i) => `${rgbCss(c)} ${(100 * i) / (VIRIDIS.length - 1)}%`);
  document.getElementById('ic-bar').style.background = `linear-gradient(to top, ${stops.join(', ')})`;
  document.getElementById('ic-bar-max').textContent = kappaRange.hi.toPrecision(4) + (kappaRange.clipped ? ' (clipped)' : '');
  document.getElementById('ic-bar-min').textContent = kappaRange.lo.toPrecision(4);
}

// ---- the chart: kappa (top) and tau (bottom) against arc length
const chart = document.getElementById('ic-chart');
const chartState = { base: null, panels: null };

function niceTicks(lo, hi, n) {
  const raw = (hi - lo) / n, mag = 10 ** Math.floor(Math.log10(raw));
  const step = [1, 2, 5, 10].map((m) => m * mag).find((s) => s >= raw) || 10 * mag;
  const ticks = [];
  for (let v = Math.ceil(lo / step) * step; v <= hi + 1e-9 * step; v += step) ticks.push(Math.abs(v) < 1e-12 * step ? 0 : v);
  return ticks;
}

function drawPanel(ctx, panel, key, range) {
  const { x, y, w, h } = panel;
  ctx.strokeStyle = '#999'; ctx.lineWidth = 1; ctx.strokeRect(x, y, w, h);
  ctx.fillStyle = '#222'; ctx.font = 'bold 12px sans-serif'; ctx.textAlign = 'left';
  ctx.fillText((key === 'kappa' ? 'curvature \u03ba' : 'torsion \u03c4') + (range.clipped ? ' (clipped)' : ''), x, y - 6);
  ctx.font = '11px sans-serif'; ctx.textAlign = 'right'; ctx.textBaseline = 'middle';
  for (const v of niceTicks(range.lo, range.hi, 4)) {
    const py = panel.py(v);
    ctx.fillText(+v.toPrecision(6) + '', x - 4, py);
    ctx.strokeStyle = '#eee'; ctx.beginPath(); ctx.moveTo(x, py); ctx.lineTo(x + w, py); ctx.stroke();
  }
  ctx.save();
  ctx.beginPath(); ctx.rect(x, y, w, h); ctx.clip();
  ctx.lineWidth = 1.5;
  curves.forEach((c, ci) => {
    ctx.strokeStyle = CURVE_PALETTE[ci % CURVE_PALETTE.length];
    ctx.beginPath();
    let pen = false;
    for (const p of c.points) {
      if (!Number.isFinite(p[key])) { pen = false; continue; } // a break where undefined
      const px = panel.px(p.s), py = panel.py(p[key]);
      if (pen) ctx.lineTo(px, py); else ctx.moveTo(px, py);
      pen = true;
    }
    ctx.stroke();
  });
  ctx.restore();
}

function drawChart() {
  const dpr = window.devicePixelRatio || 1;
  const W = chart.clientWidth, H = chart.clientHeight;
  chart.width = Math.max(1, Math.round(W * dpr)); chart.height = Math.max(1, Math.round(H * dpr));
  const ctx = chart.getContext('2d');
  ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
  ctx.fillStyle = '#fff'; ctx.fillRect(0, 0, W, H);
  if (curves.length === 0 || !sceneData.chart) { chartState.base = null; return; }
  let smax = 0;
  for (const c of curves) if (c.points.length) smax = Math.max(smax, c.points[c.points.length - 1].s);
  if (!(smax > 0)) smax = 1;
  const left = 64, right = 12, top = 24, gap = 38, bottom = 30;
  const ph = (H - top - gap - bottom) / 2, pw = W - left - right;
  const panel = (y, range) => ({
    x: left, y, w: pw, h: ph, range,
    px: (s) => left + (s / smax) * pw,
    py: (v) => y + ph - ((v - range.lo) / (range.hi - range.lo)) * ph,
  });
  const panels = { kappa: panel(top, kappaRange), tau: panel(top + ph + gap, tauRange) };
  drawPanel(ctx, panels.kappa, 'kappa', kappaRange);
  drawPanel(ctx, panels.tau, 'tau', tauRange);
  ctx.textAlign = 'center'; ctx.textBaseline = 'top'; ctx.fillStyle = '#222';
  for (const s of niceTicks(0, smax, 5)) ctx.fillText(+s.toPrecision(6) + '', panels.tau.px(s), top + 2 * ph + gap + 4);
  ctx.fillText('arc length s', left + pw / 2, H - 13);
  chartState.base = ctx.getImageData(0, 0, chart.width, chart.height);
  chartState.panels = panels;
}

function markChart(p) {
  if (!chartState.base) return;
  const ctx = chart.getContext('2d');
  ctx.putImageData(chartState.base, 0, 0);
  if (!p) return;
  for (const key of ['kappa', 'tau']) {
    const panel = chartState.panels[key];
    const px = panel.px(p.s);
    ctx.strokeStyle = '#e01010'; ctx.lineWidth = 1; ctx.setLineDash([4, 3]);
    ctx.beginPath(); ctx.moveTo(px, panel.y); ctx.lineTo(px, panel.y + panel.h); ctx.stroke();
    ctx.setLineDash([]);
    if (Number.isFinite(p[key])) {
      ctx.fillStyle = '#e01010';
      ctx.beginPath(); ctx.arc(px, panel.py(p[key]), 4, 0, 2 * Math.PI); ctx.fill();
    }
  }
}

// ---- the traced point nearest the pointer: the points projected to the
// screen into a grid of cells, rebuilt only after the camera moved
const picker = { dirty: true, sx: new Float32Array(npoints), sy: new Float32Array(npoints),
  start: null, items: new Int32Array(npoints), cols: 0, rows: 0 };

function projectPoints() {
  const w = renderer.domElement.clientWidth, h = renderer.domElement.clientHeight;
  const m = new THREE.Matrix4().multiplyMatrices(camera.projectionMatrix, camera.matrixWorldInverse).elements;
  const cols = Math.ceil(w / GRID_CELL_PX) + 1, rows = Math.ceil(h / GRID_CELL_PX) + 1;
  const cell = new Int32Array(npoints), start = new Int32Array(cols * rows + 1);
  for (let g = 0; g < npoints; g++) {
    const x = pointXyz[3 * g], y = pointXyz[3 * g + 1], z = pointXyz[3 * g + 2];
    const cw = m[3] * x + m[7] * y + m[11] * z + m[15];
    const sx = ((m[0] * x + m[4] * y + m[8] * z + m[12]) / cw + 1) * 0.5 * w;
    const sy = (1 - (m[1] * x + m[5] * y + m[9] * z + m[13]) / cw) * 0.5 * h;
    picker.sx[g] = sx; picker.sy[g] = sy;
    const cx = Math.floor(sx / GRID_CELL_PX), cy = Math.floor(sy / GRID_CELL_PX);
    cell[g] = cw > 0 && cx >= 0 && cy >= 0 && cx < cols && cy < rows ? cy * cols + cx : -1;
    if (cell[g] >= 0) start[cell[g] + 1]++;
  }
  for (let c = 0; c < cols * rows; c++) start[c + 1] += start[c];
  const fill = start.slice(0, cols * rows);
  for (let g = 0; g < npoints; g++) if (cell[g] >= 0) picker.items[fill[cell[g]]++] = g;
  Object.assign(picker, { start, cols, rows, dirty: false });
}

function nearestPoint(px, py) {
  if (picker.dirty) projectPoints();
  const cx = Math.floor(px / GRID_CELL_PX), cy = Math.floor(py / GRID_CELL_PX);
  const reach = Math.ceil(HOVER_RADIUS_PX / GRID_CELL_PX);
  let best = -1, bestD = HOVER_RADIUS_PX * HOVER_RADIUS_PX;
  for (let j = cy - reach; j <= cy + reach; j++) {
    if (j < 0 || j >= picker.rows) continue;
    for (let i = cx - reach; i <= cx + reach; i++) {
      if (i < 0 || i >= picker.cols) continue;
      const c = j * picker.cols + i;
      for (let q = picker.start[c]; q < picker.start[c + 1]; q++) {
        const g = picker.items[q];
        const d = (picker.sx[g] - px) ** 2 + (picker.sy[g] - py) ** 2;
        if (d <= bestD) { bestD = d; best = g; }
      }
    }
  }
  return best;
}

const info = document.getElementById('ic-info');
const hover = { x: 0, y: 0, moved: false, curve: -1, index: -1 };

// The values of traced point g (a global index) in the panel, its mark in
// the view and on the chart; g < 0 keeps the last point shown, so that its
// values can be read while the pointer goes elsewhere.
function showPoint(g) {
  if (g < 0) return;
  hover.curve = pointCurve[g];
  hover.index = pointIndex[g];
  const c = curves[hover.curve], p = c.points[hover.index];
  hoverMark.position.set(...p.xyz);
  hoverMark.visible = true;
  info.textContent = [
    `curve ${hover.curve} (${c.closed ? 'closed' : 'open'}, ${c.type}), point ${hover.index} of ${c.points.length}`,
    `s      ${fmt(p.s)}`,
    `xyz    ${fmtVec(p.xyz)}`,
    `t      ${fmtVec(p.t)}`,
    `n      ${fmtVec(p.n)}`,
    `b      ${fmtVec(p.b)}`,
    `kappa  ${fmt(p.kappa)}`,
    `tau    ${fmt(p.tau)}`,
    `type   ${p.type}`,
  ].join('\n');
  markChart(p);
}

// Nothing traced: said where the values would go, with what was not
// proven (as the pictures say it).
if (trace.report && curves.length === 0 && specials.length === 0) {
  const r = trace.report;
  info.textContent = 'no intersection';
  if (!r.exclusion_proven || r.uncovered_cells > 0 || r.unproven_cells > 0)
    info.textContent += `\nfound: not proven (${r.exclusion_proven ? '' : 'sampled only, '}` +
      `${r.uncovered_cells} cells uncovered, ${r.unproven_cells} unproven)`;
  info.classList.add('ic-none');
}

renderer.domElement.addEventListener('pointermove', (e) => {
  const r = renderer.domElement.getBoundingClientRect();
  Object.assign(hover, { x: e.clientX - r.left, y: e.clientY - r.top, moved: true });
});

// ---- controls of the page
document.getElementById('ic-show-frames').addEventListener('change', (e) => { frames.visible = e.target.checked; needsRender = true; });
document.getElementById('ic-show-surfaces').addEventListener('change', (e) => { surfaces.visible = e.target.checked; needsRender = true; });
// the trace document as the library wrote it: each \u003c the page's
// writer put for '<' (one not after an escaping backslash) made '<' again
function originalTrace() {
  return traceText.replace(/(\\*)\\u003c/g, (m, bs) => (bs.length % 2 === 0 ? bs + '<' : m));
}
document.getElementById('ic-download').addEventListener('click', () => {
  const a = document.createElement('a');
  a.href = URL.createObjectURL(new Blob([originalTrace()], { type: 'application/json' }));
  a.download = 'trace.json';
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(a.href), 10000);
});

// ---- drawing: only when something changed
let needsRender = true;
let framesDrawn = 0;
// While the view moves it is drawn at MOVING_RESOLUTION of the full one in
// each direction (half the pixels: software rendering spends its time on
// the translucent surfaces' pixels), and again in full SETTLE_MS after the
// last move.
const MOVING_RESOLUTION = 0.7;
const SETTLE_MS = 200;
const motion = { adaptive: true, moving: false, timer: 0 };
function moved() {
  if (!motion.adaptive) return;
  if (!motion.moving) {
    motion.moving = true;
    renderer.setPixelRatio(window.devicePixelRatio * MOVING_RESOLUTION);
  }
  clearTimeout(motion.timer);
  motion.timer = setTimeout(() => {
    motion.moving = false;
    renderer.setPixelRatio(window.devicePixelRatio);
    needsRender = true;
  }, SETTLE_MS);
}
controls.addEventListener('change', () => { needsRender = true; picker.dirty = true; moved(); });

function resize() {
  const w = view.clientWidth, h = view.clientHeight;
  renderer.setSize(w, h);
  camera.aspect = w / Math.max(h, 1);
  camera.updateProjectionMatrix();
  picker.dirty = true;
  needsRender = true;
  drawChart();
  showPoint(hover.curve < 0 ? -1 : curves.slice(0, hover.curve).reduce((a, c) => a + c.points.length, 0) + hover.index);
}
window.addEventListener('resize', resize);

const projected = new THREE.Vector3();
function placeLabels() {
  const w = renderer.domElement.clientWidth, h = renderer.domElement.clientHeight;
  for (const l of specialLabels) {
    projected.copy(l.at).project(camera);
    l.el.style.left = `${(projected.x + 1) * 0.5 * w}px`;
    l.el.style.top = `${(1 - projected.y) * 0.5 * h}px`;
    l.el.hidden = projected.z > 1;
  }
}

function animate() {
  requestAnimationFrame(animate);
  controls.update();
  if (hover.moved) {
    hover.moved = false;
    showPoint(nearestPoint(hover.x, hover.y));
    needsRender = true;
  }
  if (!needsRender) return;
  needsRender = false;
  updateDetail();
  placeLabels();
  renderer.render(scene, camera);
  framesDrawn++;
}

resize();
animate();

// A small hook for the tests and the benchmark (tests/browser, bench/):
// where a traced point is on the page, and what is shown.
window.intercurveScene = {
  ready: true,
  points: npoints,
  get framesDrawn() { return framesDrawn; },
  get hovered() { return { curve: hover.curve, index: hover.index }; },
  // client coordinates (CSS px) of point `index` of curve `curve`
  project(curve, index) {
    const v = new THREE.Vector3(...curves[curve].points[index].xyz).project(camera);
    const r = renderer.domElement.getBoundingClientRect();
    return { x: r.left + (v.x + 1) * 0.5 * r.width, y: r.top + (1 - v.y) * 0.5 * r.height };
  },
  setAutoRotate(on) { controls.autoRotate = on; controls.autoRotateSpeed = 30; },
  // on (the default): drawn coarser while the view moves
  setAdaptive(on) { motion.adaptive = on; },
  showFrames(on) { frames.visible = on; needsRender = true; },
};
