// The lab's page: controls that start renders on the local server, one
// long-polling loop that shows each new snapshot, the BRDF plots and the
// path inspector. No library, no network beyond the lab's own server.
// `#selftest` in the address runs a check of the page and writes its
// findings into <pre id="selftest"> (the lab's browser test reads them).
'use strict';

const $ = (id) => document.getElementById(id);
const page = Array.from(crypto.getRandomValues(new Uint8Array(8)), (b) => b.toString(16).padStart(2, '0')).join('');
const state = {
  tab: 'render',
  job: null,        // the status of the page's render
  shown: -1,        // the snapshot version on screen
  loading: false,   // an image is loading
  again: false,     // load again once it is done (a newer snapshot or exposure)
  closed: false,    // stop polling (self-test done)
  kick: null,       // wakes the poll loop when a render starts
  onImage: [],      // self-test hooks
};

// ---- talking to the server ----

function query(params, withPage = true) {
  const q = new URLSearchParams(withPage ? { page } : {});
  for (const [k, v] of Object.entries(params)) {
    if (v !== undefined && v !== null && v !== '') q.set(k, v);
  }
  return q.toString();
}

async function call(method, path, params, withPage = true) {
  // The lab answers in the page's language (its errors, notes and verdicts).
  const headers = { 'Accept-Language': lang };
  const response = await fetch(`${path}?${query(params, withPage)}`, { method, cache: 'no-store', headers });
  const type = response.headers.get('Content-Type') || '';
  const body = type.startsWith('application/json') ? await response.json() : (await response.text()).trim();
  return { status: response.status, body };
}

function showError(id, message) {
  const el = $(id);
  el.textContent = message || '';
  el.hidden = !message;
}

// ---- starting renders ----

function formParams(form) {
  const params = {};
  for (const el of form.elements) {
    if (!el.name || el.disabled || el.dataset.display) continue;
    if (el.type === 'checkbox') { if (el.checked) params[el.name] = '1'; continue; }
    if (el.value !== '') params[el.name] = el.value;
  }
  return params;
}

function renderParams() {
  const params = formParams($('render-form'));
  delete params.exposure;
  const integrator = params.integrator;
  if (integrator === 'direct' || integrator === 'ao') delete params['max-depth'];
  if (integrator !== 'naive') { delete params.branching; delete params.roulette; }
  // The engine runs the path tracer only; the scalar one is the default
  // (the command shown names the engine only when it is the wavefront one).
  if (integrator !== 'path' || params.engine === 'scalar') delete params.engine;
  return params;
}

async function start(kind, path, params, errorId) {
  const r = await call('POST', path, params);
  if (r.status !== 200) {
    showError(errorId, typeof r.body === 'string' ? r.body : `${tr('error', 'error')} ${r.status}`);
    return null;
  }
  showError(errorId, '');
  state.job = r.body;
  state.shown = -1;
  if (state.kick) state.kick();
  updateStats();
  return r.body;
}

function startRender() {
  clearInspector();
  state.clicked = null;
  return start('render', '/api/render', renderParams(), 'r-error');
}

function stereoParams() {
  const params = formParams($('stereo-form'));
  if ($('s-focus').checked) delete params.convergence;
  return params;
}

function startStereo() {
  return start('stereo', '/api/stereo', stereoParams(), 's-error');
}

function brdfParams() {
  const params = formParams($('brdf-form'));
  const model = params.model;
  if (model === 'phong') params.exponent = exponent().toString();
  else delete params.phong;
  if (model !== 'glass') delete params.ior;
  return params;
}

function startRace() {
  const params = formParams($('race-form'));
  params.racers = [...document.querySelectorAll('#race-form .racer')].map((el) => el.value).filter((v) => v).join(',');
  $('race-plot').replaceChildren();
  $('race-images').replaceChildren();
  return start('race', '/api/race', params, 'race-error');
}

// The racers' pictures, one per integrator.
async function loadRace(job) {
  const holder = $('race-images');
  const lines = (job.race && job.race[0]) || [];
  lines.forEach((line, eye) => {
    let fig = holder.children[eye];
    if (!fig) {
      fig = document.createElement('figure');
      fig.append(document.createElement('img'), document.createElement('figcaption'));
      holder.appendChild(fig);
    }
    fig.querySelector('img').src = `/api/image.png?${query({ job: job.id, eye, v: job.version })}`;
    fig.querySelector('figcaption').textContent = line.integrator;
    fig.querySelector('figcaption').style.color = RACE_COLOURS[eye];
  });
  state.shown = job.version;
}

// RMSE against time on log–log axes, one line per racer, the reference's
// noise floor dashed.
function drawRace(job) {
  const plot = $('race-plot');
  const [lines, floor] = job.race || [[], 0];
  const points = lines.flatMap((l) => l.points).filter(([t, e]) => t > 0 && e > 0);
  plot.replaceChildren();
  if (points.length === 0) return;
  const log = Math.log10;
  const ts = points.map((p) => log(p[0]));
  const es = points.map((p) => log(p[1])).concat(floor > 0 ? [log(floor)] : []);
  const t0 = Math.floor(Math.min(...ts)), t1 = Math.max(Math.ceil(Math.max(...ts)), t0 + 1);
  const e0 = Math.floor(Math.min(...es)), e1 = Math.max(Math.ceil(Math.max(...es)), e0 + 1);
  const [L, R, T, B] = [60, 580, 15, 300];
  const X = (t) => L + (log(t) - t0) / (t1 - t0) * (R - L);
  const Y = (e) => B - (log(e) - e0) / (e1 - e0) * (B - T);
  const text = (x, y, s, anchor, fill = '#aaa') => {
    const el = svg('text', { x, y, fill, 'font-size': 11, 'text-anchor': anchor }, plot);
    el.textContent = s;
    return el;
  };
  svg('rect', { x: L, y: T, width: R - L, height: B - T, fill: 'none', stroke: '#555' }, plot);
  for (let k = t0; k <= t1; k++) {
    const x = L + (k - t0) / (t1 - t0) * (R - L);
    svg('line', { x1: x, y1: T, x2: x, y2: B, stroke: '#333' }, plot);
    text(x, B + 15, `${Number((10 ** k).toPrecision(1))} s`, 'middle');
  }
  for (let k = e0; k <= e1; k++) {
    const y = B - (k - e0) / (e1 - e0) * (B - T);
    svg('line', { x1: L, y1: y, x2: R, y2: y, stroke: '#333' }, plot);
    text(L - 5, y + 4, `1e${k}`, 'end');
  }
  text((L + R) / 2, B + 32, tr('race.x', 'time (seconds, log scale)'), 'middle');
  const label = text(14, (T + B) / 2, tr('race.y', 'RMSE against the reference (log scale)'), 'middle');
  label.setAttribute('transform', `rotate(-90 14 ${(T + B) / 2})`);
  if (floor > 0) svg('line', { x1: L, y1: Y(floor), x2: R, y2: Y(floor), stroke: '#888', 'stroke-dasharray': '5 4', class: 'floor' }, plot);
  lines.forEach((line, i) => {
    const pts = line.points.filter(([t, e]) => t > 0 && e > 0).map(([t, e]) => `${X(t)},${Y(e)}`).join(' ');
    if (pts) svg('polyline', { points: pts, fill: 'none', stroke: RACE_COLOURS[i], 'stroke-width': 2, class: 'race-line', 'data-integrator': line.integrator }, plot);
    text(R - 5, T + 15 + 14 * i, line.integrator, 'end', RACE_COLOURS[i]);
  });
}

function showStudentControls() {
  const integrator = $('y-integrator').value;
  document.querySelectorAll('#student-form .y-depth').forEach((el) => { el.hidden = integrator === 'direct'; });
  document.querySelectorAll('#student-form .y-naive').forEach((el) => { el.hidden = integrator !== 'naive'; });
}

function startStudent() {
  const params = formParams($('student-form'));
  if (params.integrator === 'direct') delete params['max-depth'];
  if (params.integrator !== 'naive') delete params.branching;
  for (const id of ['y-mine', 'y-theirs', 'y-zmap']) $(id).removeAttribute('src');
  $('y-verdict').textContent = '';
  return start('student', '/api/student', params, 'y-error');
}

function startSphere() {
  const params = brdfParams();
  delete params.theta;
  params.spp = '256';
  return start('brdf', '/api/brdf-sphere', params, 'b-error');
}

// ---- the poll loop: one long poll at a time, a new picture when there is one ----

const sleep = (ms) => new Promise((resolve) => setTimeout(resolve, ms));

async function pollLoop() {
  while (!state.closed) {
    let status = null;
    try {
      const after = state.job ? state.job.version : 0;
      const r = await call('GET', '/api/status', state.job ? { after } : {});
      status = r.status === 200 ? r.body : null;
    } catch (e) {
      await sleep(1000);
      continue;
    }
    const job = status && status.job;
    if (job && (!state.job || job.id >= state.job.id)) {
      state.job = job;
      updateStats();
      if (job.version !== state.shown) loadPicture();
    }
    if (!job || job.done) {
      // Nothing will change until a new render starts.
      await Promise.race([sleep(1000), new Promise((resolve) => { state.kick = resolve; })]);
      state.kick = null;
    }
  }
}

function pictureUrl(job) {
  const v = job.version;
  const id = job.id;
  if (job.kind === 'stereo') {
    return `/api/stereo.png?${query({ job: id, mode: $('s-mode').value, desaturate: $('s-desaturate').value, exposure: $('s-exposure').value, v })}`;
  }
  const exposure = job.kind === 'render' ? $('r-exposure').value : 0;
  return `/api/image.png?${query({ job: id, exposure, v })}`;
}

const imageOf = { render: 'r-image', stereo: 's-image', brdf: 'b-image', student: 'y-mine' };
const TABS = ['render', 'stereo', 'brdf', 'student', 'race'];
const RACE_COLOURS = ['#ffcc33', '#66ccff', '#ff77aa'];

// Loads the newest snapshot into a hidden image and swaps it in when whole
// (no flicker); one load at a time.
function loadPicture() {
  const job = state.job;
  // A build (photon maps, …) or Metropolis's bootstrap shows no picture yet.
  if (!job || job.version === 0 || !job.picture) return;
  if (state.loading) { state.again = true; return; }
  state.loading = true;
  if (job.kind === 'student' || job.kind === 'race') {
    (job.kind === 'student' ? loadStudent(job) : loadRace(job)).finally(() => {
      state.loading = false;
      if (state.again) { state.again = false; loadPicture(); }
    });
    return;
  }
  const img = new Image();
  const done = () => {
    state.loading = false;
    if (state.again) { state.again = false; loadPicture(); }
  };
  img.onload = () => {
    const target = $(imageOf[job.kind]);
    target.src = img.src;
    // The picture is as large as the window allows at its own aspect ratio.
    target.parentElement.style.setProperty('--aspect', img.naturalWidth / img.naturalHeight);
    target.dataset.version = job.version;
    state.shown = job.version;
    sizeOverlay(job);
    for (const hook of state.onImage) hook(job, target);
    done();
  };
  img.onerror = done;
  img.src = pictureUrl(job);
}

// The z-test's verdict in the page's language, from the lab's numbers.
function showZVerdict() {
  const v = state.zVerdict;
  if (!v || !v.numbers) return;
  const [z, x, y, threshold, tile] = v.numbers.split(',').map(Number);
  const text = tr('y.verdict', 'Tile z-test: largest |z| = {z} in tile ({x}, {y}) (threshold {threshold}, {tile}-pixel tiles): {verdict}')
    .replace('{z}', z.toFixed(1)).replace('{x}', x).replace('{y}', y).replace('{threshold}', threshold.toFixed(1)).replace('{tile}', tile)
    .replace('{verdict}', v.consistent ? tr('y.consistent', 'consistent with the renderer’s') : tr('y.differs', 'DIFFERS from the renderer’s (red tiles)'));
  $('y-verdict').textContent = text;
}

// The "Your code" tab: both pictures and the z-map between them, with its
// verdict (in the z-map's headers).
async function loadStudent(job) {
  const v = job.version;
  const blob = async (path, params) => {
    const r = await fetch(`${path}?${query({ job: job.id, v, ...params })}`, { cache: 'no-store' });
    return r.ok ? { url: URL.createObjectURL(await r.blob()), headers: r.headers } : null;
  };
  const [mine, theirs, zmap] = await Promise.all([
    blob('/api/image.png', { eye: 0 }), blob('/api/image.png', { eye: 1 }), blob('/api/zmap.png', {}),
  ]);
  for (const [id, got] of [['y-mine', mine], ['y-theirs', theirs], ['y-zmap', zmap]]) {
    if (!got) continue;
    const img = $(id);
    if (img.src.startsWith('blob:')) URL.revokeObjectURL(img.src);
    img.src = got.url;
  }
  if (zmap) {
    const verdict = $('y-verdict');
    const consistent = zmap.headers.get('X-Lab-Consistent') === 'true';
    state.zVerdict = { numbers: zmap.headers.get('X-Lab-Verdict-Numbers'), consistent };
    showZVerdict();
    verdict.className = `verdict ${consistent ? 'good' : 'bad'}`;
    verdict.dataset.consistent = consistent;
    verdict.dataset.version = v;
  }
  state.shown = v;
  for (const hook of state.onImage) hook(job, $('y-mine'));
}

function fmt(x) {
  if (x >= 1e9) return `${(x / 1e9).toFixed(2)} G`;
  if (x >= 1e6) return `${(x / 1e6).toFixed(2)} M`;
  if (x >= 1e3) return `${(x / 1e3).toFixed(1)} k`;
  return x.toFixed(0);
}

const escapeHtml = (t) => String(t).replace(/[&<>"]/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;' }[c]));

function updateStats() {
  const job = state.job;
  if (!job) return;
  const spp = job.spp >= 10 ? job.spp.toFixed(0) : job.spp.toFixed(1);
  // spp counts passes for SPPM and mutations per pixel for Metropolis.
  const unit = tr(`u.${job.unit || 'spp'}`, job.unit || 'spp');
  const samples = tr(`u.${job.samples_unit || 'samples'}`, job.samples_unit || 'samples');
  let text = `<strong>${spp}</strong> ${tr('st.of', 'of')} ${job.target_spp} ${escapeHtml(unit)} · ${fmt(job.samples_per_second)} ${escapeHtml(samples)}/s · ${job.elapsed.toFixed(1)} s · ${job.width}×${job.height}`;
  if (job.phase === 'building') text += ` · ${tr('st.building', 'building')}`;
  if (job.done) text += ` · ${job.error ? tr('st.failed', 'failed') : job.interrupted ? tr('st.stopped', 'stopped') : tr('st.done', 'done')}`;
  if (job.nonfinite > 0) text += ` · ${job.nonfinite} ${tr('st.nonfinite', 'NaN/negative samples dropped')}`;
  if (job.note) text += `<br><span class="note">${escapeHtml(job.note)}</span>`;
  if (job.kind === 'race') drawRace(job);
  const ids = { race: ['race-stats', null, 'race-error'], render: ['r-stats', 'r-command', 'r-error'], stereo: ['s-stats', 's-command', 's-error'], brdf: ['b-stats', null, 'b-error'], student: ['y-stats', 'y-command', 'y-error'] };
  if (job.kind === 'student' && job.nonfinite_by_eye && job.nonfinite_by_eye[0] > 0) {
    text += `<br><span class="bad">${tr('y.nonfinite', 'your integrator returned {n} samples that are NaN, infinite or negative (dropped from its picture)').replace('{n}', job.nonfinite_by_eye[0])}</span>`;
  }
  const [stats, command, error] = ids[job.kind];
  $(stats).innerHTML = text;
  if (job.error) showError(error, job.error);
  if (command) {
    let line = job.command;
    if (job.kind === 'render' && Number($('r-exposure').value) !== 0) line += ` --exposure ${$('r-exposure').value}`;
    if (job.kind === 'stereo') line += ` --mode ${$('s-mode').value} --desaturate ${$('s-desaturate').value}`;
    showCommand($(command), line);
  }
  if (job.kind === 'render') $('r-exr').href = `/api/image.exr?${query({ job: job.id, v: job.version })}`;
}

// A command line that wraps between its arguments, never inside one: each
// `--option value` (and `-p lesson11`) is one unbreakable piece.
function showCommand(el, line) {
  const pieces = [];
  for (const word of line.split(' ')) {
    const last = pieces[pieces.length - 1];
    const option = last && last.startsWith('-') && last !== '--' && !last.includes(' ');
    if (option && !word.startsWith('-')) pieces[pieces.length - 1] = `${last} ${word}`;
    else pieces.push(word);
  }
  el.replaceChildren();
  pieces.forEach((piece, i) => {
    if (i > 0) el.append(' ');
    const span = document.createElement('span');
    span.className = 'arg';
    span.textContent = piece;
    el.append(span);
  });
}

// ---- the path inspector ----

function sizeOverlay(job) {
  if (job.kind !== 'render') return;
  $('r-overlay').setAttribute('viewBox', `0 0 ${job.width} ${job.height}`);
}

function clearInspector() {
  $('r-overlay').replaceChildren();
  $('inspector-table').hidden = true;
  $('inspector-segments').hidden = true;
  $('inspector-note').textContent = '';
  $('inspector-why').hidden = true;
  $('i-depth-label').hidden = true;
}

const SVG = 'http://www.w3.org/2000/svg';
function svg(name, attrs, parent) {
  const el = document.createElementNS(SVG, name);
  for (const [k, v] of Object.entries(attrs)) el.setAttribute(k, v);
  if (parent) parent.appendChild(el);
  return el;
}

function inspect(event) {
  const job = state.job;
  if (!job || job.kind !== 'render') return;
  const img = $('r-image');
  const box = img.getBoundingClientRect();
  const x = Math.floor(((event.clientX - box.left) / box.width) * job.width);
  const y = Math.floor(((event.clientY - box.top) / box.height) * job.height);
  if (x < 0 || y < 0 || x >= job.width || y >= job.height) return;
  state.clicked = [x, y];
  return inspectPixel(x, y);
}

// What the drawing cannot say: why light tracing's and BDPT's paths need
// not pass through the pixel, and why a strategy's share can be small.
const WHY = {
  light: 'Light tracing starts its paths on the lights, not at this pixel: the path shown is the light path numbered like this pixel sample. Each of its vertices is joined to the lens, and what it brings is added where that vertex is seen (the rings), usually on other pixels; this pixel\'s value comes from the rings of all the other light paths that land on it.',
  bdpt: 'Bidirectional tracing builds a camera path through this pixel and a light path from a light, and joins their vertices in every way: (s, t) takes s light and t camera vertices. Each (s, t) is a different estimator of the same pixel; multiple importance sampling (the power heuristic) gives each the weight w = p_st² / Σ p_ij² over the strategies that could have made the same path, and the weights of one path add up to 1. A strategy whose density is small for a path keeps little of it, so its weighted contribution can be small where the path tracer (always its own strategy) adds a lot. Connections with t = 1 land on other pixels (rings).',
  naive: 'Naive recursion traces N rays at every hit, a tree of up to 1 + N + … + N^(D−1) rays; the drawing and the tables show its first levels (tree depth shown).',
};

async function inspectPixel(x, y) {
  clearInspector();
  const overlay = $('r-overlay');
  svg('rect', { x, y, width: 1, height: 1, class: 'clicked', fill: 'none', stroke: '#fff', 'stroke-width': 2 }, overlay);
  const r = await call('GET', '/api/paths', { x, y, sample: $('i-sample').value });
  const note = $('inspector-note');
  note.className = 'note';
  state.record = r.status === 200 ? r.body : null;
  if (r.status === 200) {
    const hidden = drawPaths(r.body);
    note.textContent = tr('i.note', 'pixel ({x}, {y}), sample {k}: estimate {estimate}')
      .replace('{x}', x).replace('{y}', y).replace('{k}', r.body.sample).replace('{estimate}', rgb(r.body.estimate)) +
      (r.body.truncated ? ` (${r.body.truncated})` : '') + hidden;
    const why = WHY[r.body.integrator] && tr(`why.${r.body.integrator}`, WHY[r.body.integrator]);
    $('inspector-why').textContent = why || '';
    $('inspector-why').hidden = !why;
  } else {
    note.textContent = `${tr('t.pixel', 'pixel')} (${x}, ${y}): ${r.body}`;
  }
  note.dataset.status = r.status;
}

const ROLE_COLOUR = { camera: '#ffcc33', light: '#66ccff', branch: '#cc88ff' };

function rgb(c) { return c ? `(${c.map((v) => Number(v).toPrecision(3)).join(', ')})` : '—'; }

// A density with its measure: per steradian, per square metre, or a probability.
function pdfText(pdf) {
  if (!pdf) return '—';
  const v = Number(pdf.value).toPrecision(4);
  if (pdf.measure === 'discrete') return `P = ${v}`;
  return `${v} ${pdf.measure === 'area' ? '/m²' : '/sr'}`;
}

const ref = (r) => `p${r.path} v${r.vertex}`;

// Each path's depth in naive recursion's tree (0 for a path without a parent).
function depths(record) {
  const d = [];
  record.paths.forEach((path, p) => { d[p] = path.parent ? (d[path.parent.path] || 0) + 1 : 0; });
  return d;
}

function fillTable(table, rows) {
  table.replaceChildren(...rows.map((row, r) => {
    const tr = document.createElement('tr');
    if (row.blocked) tr.className = 'blocked';
    for (const cell of row.cells || row) {
      const td = document.createElement(r === 0 ? 'th' : 'td');
      // A name from the scene file (a material) is shown as it is written.
      if (cell && cell.name) td.className = 'name';
      td.textContent = cell && cell.name ? cell.name : cell;
      tr.appendChild(td);
    }
    return tr;
  }));
  table.hidden = rows.length < 2;
}

// Draws a path record (see paths.rs for its shape) over the picture and
// lists its vertices and segments; naive recursion's tree only to the depth
// chosen. Returns what it left out, as a sentence for the note.
function drawPaths(record) {
  const overlay = $('r-overlay');
  // Lines 2.5 px wide on screen whatever the picture's size (non-scaling
  // strokes); marks sized in screen pixels too.
  const box = $('r-image').getBoundingClientRect();
  const unit = box.width > 0 ? jobWidth() / box.width : 1;
  const centre = [record.pixel[0] + 0.5, record.pixel[1] + 0.5];
  const at = (v, i) => v.raster || (v.kind === 'camera' || i === 0 ? centre : null);
  const vertexAt = (r) => record.paths[r.path] && record.paths[r.path].vertices[r.vertex];
  const point = (r) => { const v = vertexAt(r); return v ? at(v, r.vertex) : null; };
  const naive = record.integrator === 'naive';
  $('i-depth-label').hidden = !naive;
  const limit = naive ? Math.max(1, Number($('i-depth').value) || 1) : Infinity;
  const depth = depths(record);
  const shown = (p) => depth[p] < limit;
  let hiddenPaths = 0, hiddenVertices = 0;
  record.paths.forEach((path, p) => {
    if (!shown(p)) { hiddenPaths += 1; hiddenVertices += path.vertices.length; return; }
    const pts = [];
    if (path.parent) { const q = point(path.parent); if (q) pts.push(q); }
    path.vertices.forEach((v, i) => { const q = at(v, i); if (q) pts.push(q); });
    const colour = ROLE_COLOUR[path.role] || '#fff';
    svg('polyline', { points: pts.map((q) => q.join(',')).join(' '), fill: 'none', stroke: colour, 'stroke-width': 2.5, 'stroke-linejoin': 'round', class: `path ${path.role}`, 'data-path': p }, overlay);
    for (const q of pts) svg('circle', { cx: q[0], cy: q[1], r: 3 * unit, fill: colour, class: 'vertex' }, overlay);
  });
  const segments = record.segments.filter((s) => shown(s.from.path));
  for (const s of segments) {
    const a = point(s.from);
    const b = s.to.vertex ? point(s.to.vertex) : s.to.point && s.to.point.raster;
    if (!a || !b) continue;
    const colour = s.occluded ? '#f66' : s.kind === 'shadow-ray' ? '#6f6' : '#6ff';
    svg('line', { x1: a[0], y1: a[1], x2: b[0], y2: b[1], stroke: colour, 'stroke-width': 2, 'stroke-dasharray': '6 4', class: `segment ${s.kind}${s.occluded ? ' blocked' : ''}` }, overlay);
  }
  // Connections to the lens (t = 1) land on other pixels: a ring where each was splatted.
  for (const s of segments) {
    if (s.splat) svg('circle', { cx: s.splat[0], cy: s.splat[1], r: 5 * unit, fill: 'none', stroke: '#6ff', 'stroke-width': 2, class: 'splat' }, overlay);
  }
  // BDPT: a column with every strategy's weight for the same path.
  const everyWeight = record.segments.some((s) => s.strategy_weights) ||
    record.paths.some((p) => p.vertices.some((v) => v.strategy_weights));
  const weightsHeading = everyWeight ? [tr('t.weights', 'every strategy’s weight for this path (i, n − i), and their sum')] : [];
  const weightsCell = (x) => (everyWeight ? [x.strategy_weights ? weightsText(x.strategy_weights) : '—'] : []);
  const vertexRows = [[tr('t.vertex', 'vertex'), tr('t.path', 'path'), tr('t.kind', 'kind'), tr('t.position', 'position'), 'BRDF', 'pdf',
    tr('t.beta', 'β (throughput)'), tr('t.mis', 'MIS weight'), ...weightsHeading, tr('t.contribution', 'contribution')]];
  record.paths.forEach((path, p) => {
    if (!shown(p)) return;
    path.vertices.forEach((v, i) => vertexRows.push([
      ref({ path: p, vertex: i }), naive ? `${word('role', path.role)}, ${tr('t.depth', 'depth')} ${depth[p]}` : word('role', path.role),
      word('kind', v.kind), rgb(v.position), v.brdf ? { name: v.brdf } : '—',
      pdfText(v.pdf), rgb(v.throughput), v.mis_weight == null ? '—' : Number(v.mis_weight).toFixed(3), ...weightsCell(v), rgb(v.contribution),
    ]));
  });
  fillTable($('inspector-table'), vertexRows);
  const segmentRows = [[tr('t.segment', 'segment'), tr('t.fromto', 'from → to'), tr('t.strategy', 'strategy (s, t)'), tr('t.visible', 'visible?'),
    tr('t.addedat', 'added at'), tr('t.mis', 'MIS weight'), ...weightsHeading, tr('t.contribution', 'contribution')]];
  for (const s of segments) {
    segmentRows.push({
      blocked: s.occluded,
      cells: [
        word('segment', s.kind), `${ref(s.from)} → ${s.to.vertex ? ref(s.to.vertex) : `${tr('t.point', 'point')} ${rgb(s.to.point.position)}`}`,
        s.strategy ? `(${s.strategy[0]}, ${s.strategy[1]})` : '—', s.occluded ? tr('t.blocked', 'blocked') : tr('t.seen', 'visible'),
        s.occluded ? '—' : s.splat ? `${tr('t.pixel', 'pixel')} (${Math.floor(s.splat[0])}, ${Math.floor(s.splat[1])})` : tr('t.thispixel', 'this pixel'),
        s.mis_weight == null ? '—' : Number(s.mis_weight).toFixed(3), ...weightsCell(s), rgb(s.contribution),
      ],
    });
  }
  fillTable($('inspector-segments'), segmentRows);
  if (hiddenPaths === 0) return '';
  return tr('t.hidden', ' · {paths} deeper rays ({vertices} vertices) not shown: raise “tree depth shown”')
    .replace('{paths}', hiddenPaths).replace('{vertices}', hiddenVertices);
}

// Every strategy's MIS weight for one path of n vertices, as the integrator
// computed them (entry i: strategy (i, n − i)), and their sum, which is 1:
// "(0, 3) 0.012 + (1, 2) 0.950 + (2, 1) 0.038 = 1.000000".
function weightsText(all) {
  const n = all.length;
  const sum = all.reduce((a, w) => a + Number(w), 0);
  return `${all.map((w, i) => `(${i}, ${n - i}) ${Number(w).toFixed(3)}`).join(' + ')} = ${sum.toFixed(4)}`;
}

// The record's words (path roles, vertex kinds, segment kinds) in the page's language.
const WORDS = {
  role: { camera: 'camera', light: 'light', branch: 'branch' },
  kind: { camera: 'camera', surface: 'surface', light: 'light', escaped: 'escaped' },
  segment: { 'shadow-ray': 'shadow ray', connection: 'connection' },
};
function word(group, value) { return tr(`w.${group}.${value}`, (WORDS[group] || {})[value] || value); }

function jobWidth() { return state.job ? state.job.width : 1; }

// ---- the BRDF tab ----

const exponent = () => Math.round(Math.pow(10, Number($('b-exponent-slider').value)) - 1);
let brdfBusy = false, brdfAgain = false;

async function updateBrdf() {
  if (brdfBusy) { brdfAgain = true; return; }
  brdfBusy = true;
  const r = await call('GET', '/api/brdf', brdfParams(), false);
  brdfBusy = false;
  if (r.status !== 200) showError('b-error', r.body);
  else { showError('b-error', ''); plotBrdf(r.body); }
  if (brdfAgain) { brdfAgain = false; updateBrdf(); }
}

function plotBrdf(a) {
  state.brdf = a;
  $('b-formula').textContent = a.formula;
  const verdict = $('b-verdict');
  verdict.textContent = tr('b.verdict', 'Directional albedo at θ = {theta}°: {albedo}. The BRDF {verdict}.')
    .replace('{theta}', a.theta).replace('{albedo}', a.albedo_at_theta.toFixed(3)).replace('{verdict}', a.verdict);
  verdict.className = `verdict ${a.conserves_energy ? 'good' : 'bad'}`;
  verdict.dataset.conserves = a.conserves_energy;
  // Lobe: polar, the normal up, θ measured from it (+ to the right).
  const lobe = $('b-lobe');
  lobe.replaceChildren();
  // Below the surface only glass sends light.
  const refracts = a.deltas.some(([d]) => Math.abs(d) > 90);
  lobe.setAttribute('viewBox', refracts ? '-110 -110 220 220' : '-110 -110 220 120');
  svg('line', { x1: -105, y1: 0, x2: 105, y2: 0, stroke: '#666', 'stroke-width': 0.8 }, lobe);
  svg('line', { x1: 0, y1: 0, x2: 0, y2: -100, stroke: '#444', 'stroke-dasharray': '2 2', 'stroke-width': 0.6 }, lobe);
  const polar = (deg, r) => [r * Math.sin(deg * Math.PI / 180), -r * Math.cos(deg * Math.PI / 180)];
  const [lx, ly] = polar(-a.theta, 100);
  svg('line', { x1: lx, y1: ly, x2: 0, y2: 0, stroke: '#fc3', 'stroke-width': 1.5 }, lobe);
  const [mx, my] = polar(a.theta, 100);
  svg('line', { x1: 0, y1: 0, x2: mx, y2: my, stroke: '#666', 'stroke-dasharray': '3 3', 'stroke-width': 0.8 }, lobe);
  const peak = Math.max(...a.lobe.map((p) => p[1]));
  if (peak > 0) {
    const pts = a.lobe.map(([d, f]) => polar(d, 95 * f / peak).join(',')).join(' ');
    svg('polyline', { points: `0,0 ${pts} 0,0`, fill: 'rgba(136,204,255,0.25)', stroke: '#8cf', 'stroke-width': 1.2 }, lobe);
  }
  for (const [d, w] of a.deltas) {
    const [x, y] = polar(d, 95 * Math.min(1, w));
    svg('line', { x1: 0, y1: 0, x2: x, y2: y, stroke: '#8cf', 'stroke-width': 2 }, lobe);
  }
  $('b-peak').textContent = peak > 0 ? `(${tr('b.peak', 'peak')} f_r = ${peak.toPrecision(4)} sr⁻¹)` : a.deltas.length ? tr('b.deltas', '(delta lobes: arrows show each lobe’s share)') : '';
  // Albedo against θ_o, y up to max(1.2, the largest value).
  const plot = $('b-albedo-plot');
  plot.replaceChildren();
  const top = Math.max(1.2, a.max_albedo * 1.1);
  const X = (d) => 30 + d * 260 / 90, Y = (v) => 180 - v * 170 / top;
  svg('line', { x1: 30, y1: 180, x2: 290, y2: 180, stroke: '#666' }, plot);
  svg('line', { x1: 30, y1: 10, x2: 30, y2: 180, stroke: '#666' }, plot);
  svg('line', { x1: 30, y1: Y(1), x2: 290, y2: Y(1), stroke: '#f77', 'stroke-dasharray': '4 3' }, plot);
  for (const [v, label] of [[0, '0'], [1, '1']]) {
    const t = svg('text', { x: 24, y: Y(v) + 4, 'text-anchor': 'end', fill: '#aaa', 'font-size': 10 }, plot);
    t.textContent = label;
  }
  for (const d of [0, 30, 60, 90]) {
    const t = svg('text', { x: X(d), y: 195, 'text-anchor': 'middle', fill: '#aaa', 'font-size': 10 }, plot);
    t.textContent = `${d}°`;
  }
  svg('polyline', { points: a.albedo.map(([d, v]) => `${X(d)},${Y(v)}`).join(' '), fill: 'none', stroke: a.conserves_energy ? '#7d7' : '#f77', 'stroke-width': 1.5 }, plot);
  svg('circle', { cx: X(a.theta), cy: Y(a.albedo_at_theta), r: 3, fill: '#fc3' }, plot);
}

// ---- controls ----

function showFor(integrator) {
  const uses = (cls, yes) => document.querySelectorAll(`#render-form .${cls}`).forEach((el) => { el.hidden = !yes; });
  uses('depth', integrator !== 'direct' && integrator !== 'ao');
  uses('naive', integrator === 'naive');
  uses('engine', integrator === 'path');
  const entry = (window.catalogue.integrators || []).find((i) => i[0] === integrator);
  $('r-integrator-help').textContent = entry ? tr(`int.${integrator}`, entry[1]) : '';
}

function showBrdfControls() {
  const model = $('b-model').value;
  document.querySelectorAll('#brdf-form .phong').forEach((el) => { el.hidden = model !== 'phong'; });
  document.querySelectorAll('#brdf-form .glass').forEach((el) => { el.hidden = model !== 'glass'; });
}

function fill(select, items, chosen) {
  select.replaceChildren(...items.map(([value, label]) => {
    const o = document.createElement('option');
    o.value = value;
    o.textContent = label;
    o.selected = value === chosen;
    return o;
  }));
}

// Calls `f` at most once per animation frame, with the latest state.
function perFrame(f) {
  let queued = false;
  return () => {
    if (queued) return;
    queued = true;
    requestAnimationFrame(() => { queued = false; f(); });
  };
}

function selectTab(tab) {
  state.tab = tab;
  for (const name of TABS) {
    $(`tab-${name}`).setAttribute('aria-selected', String(name === tab));
    $(`panel-${name}`).hidden = name !== tab;
  }
  if (location.hash !== '#selftest') history.replaceState(null, '', tab === 'render' ? location.pathname : `#${tab}`);
  // One render at a time per page: the tab shown is the one rendering.
  if (tab === 'render') return startRender();
  if (tab === 'stereo') return startStereo();
  if (tab === 'student') return startStudent();
  if (tab === 'race') return startRace();
  updateBrdf();
  return startSphere();
}

// Each way of showing the pair, in a line.
const MODE_HELP = {
  'red-cyan': 'Anaglyph for red–cyan glasses: the left eye’s red channel, the right eye’s green and blue.',
  'half-color': 'Red–cyan, half colour: the left eye’s brightness in red (less rivalry on red objects), the right eye’s green and blue.',
  grey: 'Red–cyan from grey pictures: no colour, no rivalry.',
  'red-blue': 'Anaglyph for red (left) – blue (right) glasses.',
  'red-green': 'Anaglyph for red (left) – green (right) glasses.',
  'amber-blue': 'Anaglyph for amber (left) – blue (right) glasses (ColorCode 3-D).',
  'green-magenta': 'Anaglyph for green (left) – magenta (right) glasses.',
  dubois: 'Red–cyan with Dubois’ least-squares matrices: the truest colours through red–cyan glasses.',
  'side-by-side': 'Left eye’s picture on the left: look straight through (parallel viewing) or use a stereoscope.',
  'cross-eyed': 'Right eye’s picture on the left: cross your eyes until the two merge into a third in the middle.',
  'over-under': 'Left eye’s picture above the right one: for mirror viewers (fits the window’s height).',
  left: 'The left eye’s picture alone.',
  right: 'The right eye’s picture alone.',
};

function showModeHelp() {
  const mode = $('s-mode').value;
  $('s-mode-help').textContent = tr(`mode.${mode}`, MODE_HELP[mode] || '');
}

function echo(id, text) { $(`${id}-out`).textContent = text; }

// A scene list's tooltip: what the chosen scene is.
function sceneTitles() {
  for (const el of document.querySelectorAll('select')) {
    const title = ((window.catalogue.scenes || []).find((s) => s.name === el.value) || {}).description;
    if (title) el.title = tr(`scene.${el.value}`, title);
  }
}

// The other language, and what the script wrote again in it.
function switchLanguage() {
  applyLanguage(lang === 'bg' ? 'en' : 'bg', () => {
    showModeHelp();
    for (const o of $('s-mode').options) o.textContent = tr(`m.${o.value}`, o.value);
    sceneTitles();
    showFor($('r-integrator').value);
    updateStats();
    showZVerdict();
    if (state.tab === 'brdf') updateBrdf();
    if (state.job && state.job.kind === 'race') drawRace(state.job);
    if (state.clicked) inspectPixel(...state.clicked);
  });
}

async function setup() {
  applyLanguage(initialLanguage());
  $('lang').addEventListener('click', switchLanguage);
  const r = await call('GET', '/api/scenes', {}, false);
  window.catalogue = r.body;
  const scenes = r.body.scenes.map((s) => [s.name, s.builtin ? s.name : `${s.name} (${tr('file', 'file')})`]);
  fill($('r-scene'), scenes, 'cornell');
  fill($('s-scene'), scenes, 'stereo');
  fill($('y-scene'), scenes, 'cornell');
  const integrators = r.body.integrators.map((i) => [i[0], i[0]]);
  fill($('r-integrator'), integrators, 'path');
  // SPPM and Metropolis render whole images, not the pixel samples of a stereo pair.
  const whole = r.body.whole_image || [];
  fill($('s-integrator'), integrators.filter(([name]) => !whole.includes(name)), 'path');
  fill($('s-mode'), r.body.composites.map((c) => [c, tr(`m.${c}`, c)]), 'red-cyan');
  showModeHelp();
  sceneTitles();
  showFor('path');
  showBrdfControls();

  const restartRender = perFrame(startRender);
  $('render-form').addEventListener('input', (e) => {
    if (e.target.id === 'r-exposure') { echo('r-exposure', e.target.value); updateStats(); loadPicture(); return; }
    if (e.target.name === 'integrator') showFor(e.target.value);
    if (e.target.type === 'number' || e.target.type === 'text') return; // on change
    restartRender();
  });
  $('render-form').addEventListener('change', (e) => {
    if (e.target.type === 'number' || e.target.type === 'text') restartRender();
  });
  $('render-form').addEventListener('submit', (e) => { e.preventDefault(); restartRender(); });
  $('r-stop').addEventListener('click', () => call('POST', '/api/stop', {}));
  $('r-picture').addEventListener('click', inspect);
  // A new sample k (or tree depth) shows the same pixel again.
  for (const id of ['i-sample', 'i-depth']) {
    $(id).addEventListener('change', () => { if (state.clicked) inspectPixel(...state.clicked); });
  }

  const restartStereo = perFrame(startStereo);
  $('stereo-form').addEventListener('input', (e) => {
    const id = e.target.id;
    if (id === 's-separation') echo('s-separation', e.target.value);
    if (id === 's-convergence') echo('s-convergence', `${e.target.value} m`);
    if (id === 's-mode') showModeHelp();
    if (id === 's-desaturate') echo('s-desaturate', e.target.value);
    if (id === 's-exposure') echo('s-exposure', e.target.value);
    if (id === 's-focus') {
      $('s-convergence').disabled = e.target.checked;
      echo('s-convergence', e.target.checked ? tr('s.focusdistance', 'focus distance') : `${$('s-convergence').value} m`);
    }
    // The composite, desaturation and exposure only show the same pair anew.
    if (e.target.dataset.display && id !== 's-focus') { updateStats(); loadPicture(); return; }
    if (e.target.type === 'number') return; // on change
    restartStereo();
  });
  $('stereo-form').addEventListener('change', (e) => { if (e.target.type === 'number') restartStereo(); });
  $('stereo-form').addEventListener('submit', (e) => { e.preventDefault(); restartStereo(); });

  const restartSphere = perFrame(startSphere);
  $('brdf-form').addEventListener('input', (e) => {
    const id = e.target.id;
    if (id === 'b-albedo') echo('b-albedo', e.target.value);
    if (id === 'b-exponent-slider') echo('b-exponent', exponent());
    if (id === 'b-ior') echo('b-ior', e.target.value);
    if (id === 'b-theta') echo('b-theta', e.target.value);
    if (id === 'b-model') showBrdfControls();
    updateBrdf();
    if (!e.target.dataset.plotOnly) restartSphere();
  });
  $('brdf-form').addEventListener('submit', (e) => e.preventDefault());

  $('race-start').addEventListener('click', startRace);
  $('race-stop').addEventListener('click', () => call('POST', '/api/stop', {}));
  $('race-form').addEventListener('submit', (e) => { e.preventDefault(); startRace(); });
  const restartStudent = perFrame(startStudent);
  $('student-form').addEventListener('input', (e) => {
    if (e.target.name === 'integrator') showStudentControls();
    if (e.target.type === 'number' || e.target.type === 'text') return; // on change
    restartStudent();
  });
  $('student-form').addEventListener('change', (e) => { if (e.target.type === 'number' || e.target.type === 'text') restartStudent(); });
  $('student-form').addEventListener('submit', (e) => { e.preventDefault(); restartStudent(); });
  $('y-stop').addEventListener('click', () => call('POST', '/api/stop', {}));
  showStudentControls();

  for (const name of TABS) {
    $(`tab-${name}`).addEventListener('click', () => selectTab(name));
  }
  pollLoop();
  // `#stereo` or `#brdf` opens that tab (links from the tour page and the slides).
  const tab = location.hash.slice(1);
  if (tab === 'selftest') selftest();
  else if (tab === 'layout') layoutCheck();
  else if (tab === 'bulgarian') bulgarianCheck();
  else selectTab(TABS.includes(tab) ? tab : 'render');
}

// ---- the self-test (#selftest) ----

function checksum(img) {
  const canvas = document.createElement('canvas');
  canvas.width = img.naturalWidth;
  canvas.height = img.naturalHeight;
  const ctx = canvas.getContext('2d');
  ctx.drawImage(img, 0, 0);
  const data = ctx.getImageData(0, 0, canvas.width, canvas.height).data;
  let sum = 0;
  for (let i = 0; i < data.length; i += 4) sum += data[i] + data[i + 1] + data[i + 2];
  return sum;
}

async function until(check, ms) {
  const end = performance.now() + ms;
  while (performance.now() < end) {
    const value = check();
    if (value) return value;
    await sleep(50);
  }
  return null;
}

async function selftest() {
  const out = { errors: [], step: 'start' };
  const step = (name) => { out.step = name; $('selftest').textContent = JSON.stringify(out); };
  try {
    const form = $('render-form');
    form.elements.scene.value = 'cornell';
    form.elements.integrator.value = 'path';
    form.elements.width.value = '64';
    form.elements.height.value = '64';
    form.elements.spp.value = '4096';
    const seen = [];
    state.onImage.push((job, img) => {
      if (job.kind === 'render') seen.push({ version: job.version, spp: job.spp, sum: checksum(img), width: img.naturalWidth });
    });
    step('render');
    await selectTab('render');
    await until(() => seen.length >= 4, 60000);
    step('inspector');
    out.render = seen;
    out.stats = $('r-stats').textContent;
    out.command = $('r-command').textContent;
    // The inspector: a click in the middle of the picture.
    const box = $('r-image').getBoundingClientRect();
    inspect({ clientX: box.left + box.width / 2, clientY: box.top + box.height / 2 });
    out.inspector = await until(() => {
      const note = $('inspector-note');
      const table = $('inspector-table');
      return note.dataset.status ? {
        status: Number(note.dataset.status), text: note.textContent, marks: $('r-overlay').childElementCount,
        polylines: $('r-overlay').querySelectorAll('polyline.path').length,
        circles: $('r-overlay').querySelectorAll('circle.vertex').length,
        lines: $('r-overlay').querySelectorAll('line.segment').length,
        rows: (table.hidden ? 0 : table.rows.length - 1) + ($('inspector-segments').hidden ? 0 : $('inspector-segments').rows.length - 1),
        record: state.record && {
          paths: state.record.paths.length,
          vertices: state.record.paths.reduce((n, p) => n + p.vertices.length, 0),
          segments: state.record.segments.length,
        },
      } : null;
    }, 20000);
    step('stereo');
    // The Stereo tab: a pair appears.
    const pair = [];
    state.onImage.push((job, img) => { if (job.kind === 'stereo') pair.push({ width: img.naturalWidth, height: img.naturalHeight, sum: checksum(img) }); });
    $('stereo-form').elements.spp.value = '16';
    $('stereo-form').elements.width.value = '80';
    $('stereo-form').elements.height.value = '60';
    $('s-mode').value = 'side-by-side';
    $('s-mode').dispatchEvent(new Event('input', { bubbles: true }));
    await selectTab('stereo');
    await until(() => pair.length >= 1 && state.job && state.job.kind === 'stereo' && state.job.done, 60000);
    out.stereo = { images: pair, job: state.job && { width: state.job.width, height: state.job.height, done: state.job.done } };
    step('brdf');
    // The BRDF tab: original Phong with n = 1 creates energy.
    $('b-phong').value = 'original';
    $('b-exponent-slider').value = String(Math.log10(2));
    await selectTab('brdf');
    out.brdf = await until(() => $('b-verdict').dataset.conserves ? { conserves: $('b-verdict').dataset.conserves, verdict: $('b-verdict').textContent, lobe: $('b-lobe').childElementCount } : null, 20000);
    await call('POST', '/api/stop', {});
  } catch (e) {
    out.errors.push(String(e && e.stack || e));
  }
  out.step = 'done';
  state.closed = true;
  if (state.kick) state.kick();
  const pre = $('selftest');
  pre.textContent = JSON.stringify(out);
  pre.hidden = false;
  document.title = 'selftest done';
}

// ---- the layout check (#layout): where things are in this window ----

function rect(el) {
  const r = el.getBoundingClientRect();
  return { left: r.left, top: r.top, right: r.right, bottom: r.bottom, width: r.width, height: r.height };
}

async function layoutCheck() {
  const out = { errors: [], step: 'start' };
  try {
    const form = $('render-form');
    form.elements.scene.value = 'cornell';
    form.elements.integrator.value = 'bdpt';
    showFor('bdpt');
    form.elements.spp.value = '16';
    let shown = false;
    state.onImage.push((job) => { if (job.kind === 'render') shown = true; });
    await selectTab('render');
    await until(() => shown, 60000);
    const box = $('r-image').getBoundingClientRect();
    await inspect({ clientX: box.left + box.width / 2, clientY: box.top + box.height * 0.8 });
    await until(() => $('inspector-note').dataset.status, 20000);
    await sleep(100);
    const line = $('r-overlay').querySelector('polyline.path');
    const style = line ? getComputedStyle(line) : null;
    out.window = { width: window.innerWidth, height: window.innerHeight, scrollWidth: document.documentElement.scrollWidth };
    out.rects = {
      picture: rect($('r-picture')), stats: rect($('r-stats')), inspector: rect($('inspector')),
      drawing: rect($('r-overlay')), tables: rect(document.querySelector('.inspector .tables')),
      controls: rect($('render-form')), table: rect($('inspector-table')),
    };
    out.tables_overflow = getComputedStyle(document.querySelector('.inspector .tables')).overflowY;
    out.line = style && { vector_effect: style.vectorEffect, width: parseFloat(style.strokeWidth) };
    out.status = Number($('inspector-note').dataset.status);
    out.rows = $('inspector-table').rows.length;
    out.why = !$('inspector-why').hidden;
    out.favicon = !!document.querySelector('link[rel="icon"]');
    // A new sample k redraws the pixel clicked.
    $('i-sample').value = '1';
    $('i-sample').dispatchEvent(new Event('change'));
    out.resampled = await until(() => $('inspector-note').textContent.includes('sample 1:') && $('inspector-note').textContent, 20000);
    // Naive recursion's tree (8 rays a hit, D = 4: 585 rays) is shown to
    // the depth chosen, with a count of what is hidden; the page keeps its length.
    form.elements.integrator.value = 'naive';
    showFor('naive');
    form.elements['max-depth'].value = '4';
    form.elements.spp.value = '1';
    shown = false;
    await startRender();
    await until(() => shown, 60000);
    $('i-sample').value = '0';
    await inspect({ clientX: box.left + box.width / 2, clientY: box.top + box.height * 0.8 });
    out.naive = {
      note: $('inspector-note').textContent,
      rows: $('inspector-table').rows.length - 1,
      page_height: document.documentElement.scrollHeight,
      depth_control: !$('i-depth-label').hidden,
    };
    await call('POST', '/api/stop', {});
  } catch (e) {
    out.errors.push(String(e && e.stack || e));
  }
  out.step = 'done';
  state.closed = true;
  if (state.kick) state.kick();
  const pre = $('selftest');
  pre.textContent = JSON.stringify(out);
  pre.hidden = false;
}

// ---- the Bulgarian check (#bulgarian, opened with ?lang=bg) ----

// Latin words a Bulgarian text keeps: the names the Bulgarian deck keeps in
// English (algorithms, BRDF models, quantities), the integrators', scenes',
// engines' and exercises' names, units, file types and symbols, and the
// command line's flags a message names (--force).
const KEPT_IN_ENGLISH = new Set(`path tracing light bidirectional tracer monte carlo mis multiple importance
  sampling brdf phong lambert rmse exr png spp seed toe ambient occlusion photon mapping instant radiosity
  irradiance caching cache metropolis transport sppm mlt vpl bdpt naive direct nee brdf ao cornell door caustic
  stereo furnace white gallery veach mitsuba box wavefront throughput pdf fresnel dubois colorcode ward nan
  toe-in rightdir rgb
  lesson11 render student cargo todo exercises src lab cutoff mib sin cos max min tile brdf-gallery
  white-furnace veach-mis path-brdf path-nee irradiance-cache
  force`.split(/\s+/).filter(Boolean));

// The page's texts with an English word left (a text with Latin words
// outside KEPT_IN_ENGLISH): every text node but code and the scene's own
// names (materials), and the alt,
// aria-label, placeholder and title attributes.
function englishLeft(found) {
  const check = (text) => {
    const t = text.replace(/\s+/g, ' ').trim();
    const words = t.match(/[A-Za-z][A-Za-z-]*[A-Za-z]/g) || [];
    if (words.some((w) => w.length >= 3 && !KEPT_IN_ENGLISH.has(w.toLowerCase()))) found.add(t.slice(0, 80));
  };
  const walker = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT);
  for (let n = walker.nextNode(); n; n = walker.nextNode()) {
    if (!n.parentElement.closest('code, script, style, #selftest, .name')) check(n.textContent);
  }
  for (const el of document.querySelectorAll('[alt], [aria-label], [placeholder], [title]')) {
    if (el.id === 'lang') continue; // "Български / English"
    for (const a of ['alt', 'aria-label', 'placeholder', 'title']) if (el.hasAttribute(a)) check(el.getAttribute(a));
  }
  return found;
}

async function bulgarianCheck() {
  const out = { errors: [], step: 'start' };
  const found = new Set();
  try {
    const form = $('render-form');
    let shown = 0;
    state.onImage.push((job) => { if (job.kind === 'render') shown += 1; });
    const render = async () => {
      shown = 0;
      await startRender();
      await until(() => shown > 0 && state.job && state.job.done, 60000);
      return { command: $('r-command').textContent, error: $('r-error').hidden ? null : $('r-error').textContent, engine_shown: !$('r-engine').closest('label').hidden };
    };
    form.elements.scene.value = 'cornell';
    form.elements.width.value = '32';
    form.elements.height.value = '32';
    form.elements.spp.value = '4';
    // The engine control: the path tracer on the wavefront engine, then BDPT (no engine).
    form.elements.integrator.value = 'path';
    showFor('path');
    $('r-engine').value = 'wavefront';
    out.wavefront = await render();
    englishLeft(found);
    form.elements.integrator.value = 'bdpt';
    showFor('bdpt');
    out.bdpt = await render();
    // BDPT's inspector: every strategy's weight for each contribution.
    await inspectPixel(16, 26);
    await until(() => $('inspector-note').dataset.status, 20000);
    const heading = [...$('inspector-segments').rows[0].cells].findIndex((c) => c.textContent === tr('t.weights', ''));
    out.weights = [...$('inspector-segments').rows].slice(1).map((row) => row.cells[heading] && row.cells[heading].textContent)
      .filter((t) => t && t.includes('='));
    englishLeft(found);
    // The BRDF verdict, a stereo mode's help.
    updateBrdf();
    await until(() => $('b-verdict').dataset.conserves, 20000);
    englishLeft(found);
    // Errors: the lab's own limit and a value the command line refuses.
    form.elements.spp.value = '100000';
    await startRender();
    out.spp_error = $('r-error').textContent;
    englishLeft(found);
    form.elements.spp.value = '4';
    form.elements.seed.value = '-1';
    await startRender();
    out.seed_error = $('r-error').textContent;
    englishLeft(found);
    form.elements.seed.value = '0';
    // A render the command line refuses (naive recursion over its ray budget).
    form.elements.integrator.value = 'naive';
    showFor('naive');
    form.elements.spp.value = '16';
    form.elements['max-depth'].value = '12';
    await startRender();
    out.naive_error = $('r-error').textContent;
    englishLeft(found);
    form.elements['max-depth'].value = '';
    // A build's note (photon mapping's maps).
    form.elements.integrator.value = 'photon';
    showFor('photon');
    form.elements.spp.value = '1';
    out.photon = await render();
    out.photon.stats = $('r-stats').textContent;
    englishLeft(found);
    // The "Your code" tab's first message (not started, or its picture).
    $('student-form').elements.spp.value = '1';
    $('student-form').elements.width.value = '16';
    $('student-form').elements.height.value = '16';
    await startStudent();
    await until(() => state.job && state.job.done, 20000);
    englishLeft(found);
    await call('POST', '/api/stop', {});
  } catch (e) {
    out.errors.push(String(e && e.stack || e));
  }
  out.english = [...found].sort();
  out.step = 'done';
  state.closed = true;
  if (state.kick) state.kick();
  const pre = $('selftest');
  pre.textContent = JSON.stringify(out);
  pre.hidden = false;
}

setup().catch((e) => { document.body.insertAdjacentHTML('afterbegin', '<p class="error" role="alert"></p>'); document.querySelector('.error').textContent = `${tr('nostart', 'the lab cannot start')}: ${e}`; });
