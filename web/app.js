// camopt studio, the front end of `camopt serve` (docs/studio.md): plain ES module, no framework.
// Edit: a form generated from the kind's JSON Schema, checked by the server with the CLI's
// messages. Run: save, start, live progress (server-sent events), cancel. See: the headline table,
// the CSV outputs as uPlot charts, the mechanism at a crank angle (SVG, model units); Play turns it
// from one revolution fetched at once. Compare: two runs' headlines, values and limits.

const $ = (sel) => document.querySelector(sel);
const state = {
  folder: '', files: [], path: null, doc: null, schema: null,
  run: null, source: null, runs: [], shown: null, mechanismStudy: null,
  lastEdit: null, lastError: null, crossField: null,
};

async function api(method, url, body, signal) {
  const init = { method, headers: {}, signal };
  if (body !== undefined) {
    init.body = typeof body === 'string' ? body : JSON.stringify(body);
    init.headers['Content-Type'] = 'application/json';
  }
  const res = await fetch(url, init);
  const text = await res.text();
  let data = text;
  try { data = JSON.parse(text); } catch (e) { /* CSV or text */ }
  if (!res.ok && !(data && data.error !== undefined)) throw new Error(`${method} ${url}: ${res.status}`);
  return { status: res.status, data, text };
}

// ---- JSON pointers ----------------------------------------------------------------------------
const esc = (k) => String(k).replace(/~/g, '~0').replace(/\//g, '~1');
const unesc = (k) => k.replace(/~1/g, '/').replace(/~0/g, '~');
const parts = (ptr) => (ptr === '' || ptr === '/' ? [] : ptr.slice(1).split('/').map(unesc));
function getAt(doc, ptr) {
  let v = doc;
  for (const k of parts(ptr)) { if (v == null || typeof v !== 'object') return undefined; v = v[k]; }
  return v;
}
function setAt(doc, ptr, value) {
  const ks = parts(ptr);
  let v = doc;
  for (let i = 0; i < ks.length - 1; i++) {
    if (v[ks[i]] == null || typeof v[ks[i]] !== 'object') v[ks[i]] = {};
    v = v[ks[i]];
  }
  const last = ks[ks.length - 1];
  if (value === undefined) {
    delete v[last];
    // Drop objects left empty, so an untouched optional block stays absent.
    for (let n = ks.length - 1; n > 0; n--) {
      const parent = getAt(doc, '/' + ks.slice(0, n - 1).map(esc).join('/'));
      const child = parent && parent[ks[n - 1]];
      if (child && typeof child === 'object' && !Array.isArray(child) && Object.keys(child).length === 0)
        delete parent[ks[n - 1]];
      else break;
    }
  } else {
    v[last] = value;
  }
}

// ---- the form from the schema -------------------------------------------------------------------
function boundsText(s) {
  const b = [];
  if (s.exclusiveMinimum !== undefined) b.push(`> ${s.exclusiveMinimum}`);
  if (s.minimum !== undefined) b.push(`≥ ${s.minimum}`);
  if (s.exclusiveMaximum !== undefined) b.push(`< ${s.exclusiveMaximum}`);
  if (s.maximum !== undefined && s.maximum < 1e9) b.push(`≤ ${s.maximum}`);
  if (s.default !== undefined) b.push(`default ${JSON.stringify(s.default)}`);
  return b.join(', ');
}

function unitOf(s) {
  const m = /\[([^\]]+)\]\s*$/.exec(s.description || '');
  return m ? m[1] : '';
}

function fieldFor(key, s, ptr, required) {
  const row = document.createElement('div');
  row.className = 'field';
  row.dataset.path = ptr;
  const label = document.createElement('label');
  label.textContent = key + (required ? ' *' : '');
  const id = 'f' + ptr.replace(/[^A-Za-z0-9]/g, '_');
  label.htmlFor = id;
  const value = getAt(state.doc, ptr);
  let input;
  const kind = s.enum ? 'enum' : s.type;
  if (kind === 'enum' || kind === 'boolean') {
    input = document.createElement('select');
    const options = kind === 'enum' ? s.enum : [true, false];
    input.append(new Option(s.default !== undefined ? `(default ${s.default})` : '(absent)', ''));
    for (const o of options) input.append(new Option(String(o), JSON.stringify(o)));
    input.value = value === undefined ? '' : JSON.stringify(value);
    input.addEventListener('change', () =>
      edit(ptr, input.value === '' ? undefined : JSON.parse(input.value)));
  } else if (kind === 'number' || kind === 'integer' || kind === 'string') {
    input = document.createElement('input');
    input.type = 'text';
    if (kind !== 'string') input.inputMode = 'decimal';
    input.value = value === undefined ? '' : (typeof value === 'string' ? value : JSON.stringify(value));
    if (s.default !== undefined) input.placeholder = String(s.default);
    input.addEventListener('change', () => {
      const t = input.value.trim();
      if (t === '') return edit(ptr, undefined);
      if (kind === 'string') return edit(ptr, t);
      // A number when it reads as one; else the text, so that the server says what it expected.
      const n = Number(t);
      edit(ptr, t !== '' && Number.isFinite(n) ? n : t);
    });
  } else {
    input = document.createElement('textarea');
    input.rows = value !== undefined && JSON.stringify(value).length > 60 ? 3 : 1;
    input.value = value === undefined ? '' : JSON.stringify(value);
    input.placeholder = s.default !== undefined ? JSON.stringify(s.default) : 'JSON';
    input.addEventListener('change', () => {
      const t = input.value.trim();
      if (t === '') return edit(ptr, undefined);
      try { edit(ptr, JSON.parse(t)); } catch (e) { edit(ptr, t); }
    });
  }
  input.id = id;
  input.dataset.path = ptr;
  input.title = s.description || '';
  const desc = document.createElement('div');
  desc.className = 'desc';
  desc.textContent = s.description || '';
  const bounds = document.createElement('span');
  bounds.className = 'bounds';
  const unit = unitOf(s);
  bounds.textContent = [unit && `unit ${unit}`, boundsText(s)].filter(Boolean).join('; ');
  if (bounds.textContent) { desc.append(document.createElement('br'), bounds); }
  row.append(label, input, desc);
  return row;
}

function objectFor(key, s, ptr, required) {
  const fs = document.createElement('fieldset');
  fs.dataset.path = ptr;
  const legend = document.createElement('legend');
  legend.textContent = key + (required ? ' *' : '');
  const d = document.createElement('span');
  d.className = 'desc';
  d.textContent = s.description || '';
  legend.append(d);
  fs.append(legend);
  const req = new Set(s.required || []);
  for (const [k, sub] of Object.entries(s.properties || {})) {
    const p = `${ptr}/${esc(k)}`;
    if (sub.type === 'object' && sub.properties) fs.append(objectFor(k, sub, p, req.has(k)));
    else fs.append(fieldFor(k, sub, p, req.has(k)));
  }
  return fs;
}

function renderForm() {
  const form = $('#form');
  form.replaceChildren();
  $('#edit-hint').textContent = state.schema
    ? `${state.doc.study}: ${state.schema.title || ''} (* required; an empty field takes its default)`
    : 'This file is not a study of a known kind: edit it as JSON.';
  if (!state.schema) {
    const ta = document.createElement('textarea');
    ta.rows = 30; ta.cols = 100; ta.id = 'raw';
    ta.value = JSON.stringify(state.doc, null, 2);
    ta.addEventListener('change', () => {
      try { state.doc = JSON.parse(ta.value); validate(); } catch (e) { showValidation({ message: String(e) }); }
    });
    form.append(ta);
    return;
  }
  const req = new Set(state.schema.required || []);
  for (const [k, sub] of Object.entries(state.schema.properties || {})) {
    if (k === 'study') continue;
    const p = '/' + esc(k);
    if (sub.type === 'object' && sub.properties) form.append(objectFor(k, sub, p, req.has(k)));
    else form.append(fieldFor(k, sub, p, req.has(k)));
  }
}

let validateTimer = null;
function edit(ptr, value) {
  setAt(state.doc, ptr, value);
  state.lastEdit = ptr;
  $('#save').disabled = false;
  clearTimeout(validateTimer);
  validateTimer = setTimeout(validate, 150);
}

// The drawn element of a JSON path: the field it names, else its nearest drawn parent.
function formElementAt(path) {
  let ptr = path || '';
  let el = null;
  while (ptr && !(el = document.querySelector(`#form [data-path="${CSS.escape(ptr)}"]:not(input):not(select):not(textarea)`)))
    ptr = ptr.slice(0, ptr.lastIndexOf('/'));
  return el;
}

function showErrorAt(el, forPath, text, cls) {
  const msg = document.createElement('div');
  msg.className = cls;
  msg.dataset.for = forPath;
  msg.textContent = text;
  if (el.classList.contains('field')) { el.classList.add('invalid'); el.append(msg); }
  else el.insertBefore(msg, el.children[1] || null);
  return msg;
}

// error: the server's {message, path, …}. A cross-field rule's error names one field (its JSON
// path) though the edit of another made it (editing the eccentricity breaks the turret radius's
// rule): an error that appeared, or changed, right after the edit of a field it does not name is
// shown at that edited field too, its own path kept in the text, for as long as it stays the same.
function showValidation(error, edited = null) {
  document.querySelectorAll('.field-error').forEach((e) => e.remove());
  document.querySelectorAll('.field.invalid').forEach((e) => e.classList.remove('invalid'));
  const box = $('#validation');
  const previous = state.lastError;
  state.lastError = error ? error.message : null;
  if (!error) {
    state.crossField = null;
    box.className = 'validation ok';
    box.textContent = 'The study is valid.';
    return;
  }
  box.className = 'validation bad';
  box.textContent = error.message;
  const el = formElementAt(error.path);
  if (el) showErrorAt(el, error.path, error.message, 'field-error');
  if (error.message !== previous)
    state.crossField = edited && error.path && edited !== error.path && !edited.startsWith(error.path + '/') ? edited : null;
  const at = state.crossField && formElementAt(state.crossField);
  if (at && at !== el) {
    const m = showErrorAt(at, state.crossField, `This change breaks the rule of ${error.path}: ${error.message}`, 'field-error cross-field');
    m.dataset.errorPath = error.path;
  }
}

let validateSeq = 0;
async function validate() {
  if (!state.doc) return false;
  const seq = ++validateSeq, edited = state.lastEdit;
  const { data } = await api('POST', `/api/validate?path=${encodeURIComponent(state.path)}`, state.doc);
  if (seq !== validateSeq) return !!data.ok;  // a newer check of a newer edit is on its way
  if (state.lastEdit === edited) state.lastEdit = null;
  showValidation(data.ok ? null : data.error, edited);
  if (data.ok && typeof data.cases === 'number') $('#validation').textContent = `The sweep is valid: ${data.cases} cases (${data.note}).`;
  return !!data.ok;
}

// ---- files ------------------------------------------------------------------------------------
async function loadFiles() {
  const { data } = await api('GET', '/api/files');
  state.folder = data.folder;
  state.files = data.files;
  $('#folder').textContent = data.folder;
  const ul = $('#files');
  ul.replaceChildren();
  for (const f of data.files) {
    const li = document.createElement('li');
    li.dataset.path = f.path;
    li.textContent = f.path;
    const k = document.createElement('span');
    k.className = 'kind';
    k.textContent = [f.kind, f.name].filter(Boolean).join(' · ');
    li.append(k);
    li.classList.toggle('active', f.path === state.path);
    li.addEventListener('click', () => openFile(f.path));
    ul.append(li);
  }
}

async function openFile(path) {
  const { data } = await api('GET', `/api/file?path=${encodeURIComponent(path)}`);
  if (typeof data !== 'object' || data === null || data.error) {
    showValidation({ message: (data && data.error) || `${path}: not JSON` });
    return;
  }
  state.path = path;
  state.doc = data;
  state.schema = null;
  state.lastEdit = null;
  state.lastError = null;
  state.crossField = null;
  if (typeof data.study === 'string') {
    const r = await api('GET', `/api/schema/${encodeURIComponent(data.study)}`);
    if (r.status === 200) state.schema = r.data;
  }
  $('#current').textContent = path;
  document.querySelectorAll('#files li').forEach((li) => li.classList.toggle('active', li.dataset.path === path));
  $('#save').disabled = true;
  $('#duplicate').disabled = false;
  $('#run').disabled = false;
  renderForm();
  document.body.dataset.loaded = path;
  await validate();
}

async function save() {
  const r = await api('PUT', `/api/file?path=${encodeURIComponent(state.path)}`, JSON.stringify(state.doc, null, 2) + '\n');
  if (r.status !== 200) throw new Error(r.data.error);
  $('#save').disabled = true;
}

async function duplicate() {
  const to = prompt('Copy to (a new .json file in the folder):', state.path.replace(/\.json$/, '_copy.json'));
  if (!to) return;
  await save();
  const r = await api('POST', '/api/duplicate', { from: state.path, to });
  if (r.status !== 200) return alert(r.data.error);
  await loadFiles();
  await openFile(r.data.saved);
}

// ---- runs -------------------------------------------------------------------------------------
function setRunState(s) {
  $('#run-state').textContent = s;
  $('#run-state').dataset.state = s;
}

async function startRun() {
  if (!(await validate())) { showTab('edit'); return; }
  await save();
  $('#run-log').textContent = '';
  $('#progress').value = 0;
  const r = await api('POST', '/api/runs', { path: state.path });
  if (r.status !== 201) { setRunState('error'); $('#run-log').textContent = r.data.error; return; }
  state.run = r.data;
  setRunState('running');
  $('#cancel').disabled = false;
  $('#run').disabled = true;
  const source = new EventSource(`/api/runs/${r.data.id}/events`);
  state.source = source;
  source.addEventListener('progress', (ev) => {
    const p = JSON.parse(ev.data);
    $('#progress').value = p.fraction;
    const eta = p.eta_s >= 0 ? `, ETA ${p.eta_s.toFixed(1)} s` : '';
    $('#progress-text').textContent =
      `${p.label}: ${(100 * p.fraction).toFixed(1)} %  ${p.elapsed_s.toFixed(1)} s${eta}  ${p.detail || ''}`;
  });
  source.addEventListener('message', (ev) => { $('#run-log').textContent += JSON.parse(ev.data).text + '\n'; });
  source.addEventListener('end', async (ev) => {
    source.close();
    const end = JSON.parse(ev.data);
    $('#cancel').disabled = true;
    $('#run').disabled = false;
    if (end.state === 'done' || end.state === 'incomplete') $('#progress').value = 1;
    setRunState(end.state);
    if (end.messages.length) $('#run-log').textContent = end.messages.join('\n');
    await loadRuns();
    if (end.state === 'done' || end.state === 'incomplete') { await showResult(state.run.id); showTab('see'); }
  });
}

async function cancelRun() {
  if (state.run) await api('POST', `/api/runs/${state.run.id}/cancel`);
}

async function loadRuns() {
  const { data } = await api('GET', '/api/runs');
  state.runs = data;
  const ul = $('#runs');
  ul.replaceChildren();
  for (const r of [...data].reverse()) {
    const li = document.createElement('li');
    li.textContent = `#${r.id} ${r.study}`;
    const k = document.createElement('span');
    k.className = 'kind';
    k.textContent = r.state;
    li.append(k);
    if (r.finished) li.addEventListener('click', () => { showResult(r.id); showTab('see'); });
    ul.append(li);
  }
  for (const sel of [$('#compare-a'), $('#compare-b')]) {
    const keep = sel.value;
    sel.replaceChildren(new Option('—', ''));
    for (const r of data.filter((x) => x.state === 'done' || x.state === 'incomplete'))
      sel.append(new Option(`#${r.id} ${r.study}`, r.id));
    sel.value = keep;
  }
}

// ---- see: headlines, charts, mechanism ---------------------------------------------------------
function headlineTable(table, rows) {
  table.replaceChildren();
  const head = table.insertRow();
  for (const h of ['', 'value', 'limit', 'margin', '']) head.append(Object.assign(document.createElement('th'), { textContent: h }));
  for (const row of rows) {
    const tr = table.insertRow();
    for (const key of ['label', 'value', 'limit', 'margin', 'status']) {
      const td = tr.insertCell();
      td.textContent = row[key];
      if (key === 'status') td.className = row.status;
    }
  }
}

// The See tab shows one run: its verdict, headlines, mechanism and charts change together. Each
// shown run is a generation (view.gen); the run's result, its study and its mechanism at the
// slider's angle are fetched first, then verdict, table and drawing are replaced in one go (one
// frame: never the previous study's mechanism under this verdict); whatever still arrives for an
// older generation is dropped. Then its charts, and its revolution for Play.
async function showResult(id) {
  const gen = newGeneration();
  const { data } = await api('GET', `/api/runs/${id}/result`);
  if (gen !== view.gen) return;
  const file = await api('GET', `/api/file?path=${encodeURIComponent(data.study)}`);
  if (gen !== view.gen) return;
  const study = file.status === 200 && typeof file.data === 'object' && file.data !== null ? file.data : null;
  const angle = Number($('#crank').value);
  const first = study ? await fetchMechanism(study, data.out, angle, '&points=720').catch(() => null) : null;
  if (gen !== view.gen) return;
  state.shown = data;
  state.mechanismStudy = study;
  Object.assign(view, { study, out: data.out, run: String(id), path: data.study, wanted: angle });
  $('#see-hint').hidden = true;
  $('#play').disabled = !study;
  const verdict = $('#verdict');
  verdict.textContent = data.headlines ? `${data.study}: ${data.headlines.verdict}` : `${data.study}: ${data.state}`;
  verdict.dataset.run = String(id);
  verdict.dataset.study = data.study;
  headlineTable($('#headlines'), data.headlines ? data.headlines.rows : []);
  if (first) renderMechanism(first, angle, 'angle');
  else renderNothing(study ? `${data.study}: its mechanism could not be drawn` : `${data.study}: not a study file`);
  if (Number($('#crank').value) !== angle) askAngle(Number($('#crank').value));  // moved meanwhile
  $('#charts').replaceChildren();
  await drawCharts(data, gen);
  if (gen !== view.gen) return;
  document.body.dataset.result = String(id);
  if (first && first.status === 200 && first.data.supported) fetchRevolution(gen);
}

const UNITS = ['deg', 'N', 'MPa', 'Nm', 'mm', 'GPa', 'W', 'h', 'rpm', 'um', 'rad', 's'];
function unitGroup(name) {
  const m = /_([A-Za-z]+)$/.exec(name);
  return m && UNITS.includes(m[1]) ? m[1] : '';
}

function parseCsv(text) {
  const lines = text.trim().split(/\r?\n/);
  const header = lines[0].split(',');
  const cols = header.map(() => []);
  for (const line of lines.slice(1)) {
    const cells = line.split(',');
    cells.forEach((c, i) => { if (i < cols.length) cols[i].push(c === '' ? null : Number(c)); });
  }
  return { header, cols };
}

async function drawCharts(result, gen) {
  const host = $('#charts');
  host.replaceChildren();
  if (typeof uPlot === 'undefined') { host.textContent = 'uPlot is not installed (npm ci in web/): no charts.'; return; }
  const limits = (state.mechanismStudy && state.mechanismStudy.limits) || {};
  for (const name of (result.files || []).filter((f) => f.endsWith('.csv'))) {
    const { text } = await api('GET', `/api/file?path=${encodeURIComponent(result.out + '/' + name)}`);
    if (gen !== view.gen) return;  // another run is shown now
    const { header, cols } = parseCsv(text);
    if (cols.length < 2 || cols[0].length < 2 || cols[0].some((v) => v === null || Number.isNaN(v))) continue;
    const groups = new Map();
    header.slice(1).forEach((h, i) => {
      if (cols[i + 1].some((v) => Number.isNaN(v))) return;  // a text column
      const g = unitGroup(h) || 'other';
      if (!groups.has(g)) groups.set(g, []);
      groups.get(g).push(i + 1);
    });
    for (const [unit, idx] of groups) {
      const div = document.createElement('div');
      div.className = 'chart';
      div.append(Object.assign(document.createElement('h4'), { textContent: `${name}: ${unit === 'other' ? '' : '[' + unit + ']'}` }));
      host.append(div);
      const palette = ['#1f77b4', '#ff7f0e', '#2ca02c', '#d62728', '#9467bd', '#8c564b', '#e377c2', '#7f7f7f'];
      const series = [{ label: header[0] }];
      const data = [cols[0]];
      idx.slice(0, 8).forEach((i, n) => { series.push({ label: header[i], stroke: palette[n % 8], width: 1.2 }); data.push(cols[i]); });
      // The study's limits drawn as dashed lines on the charts of their unit.
      const limit = unit === 'MPa' ? limits.contact_stress_MPa : unit === 'N' ? limits.roller_load_N : undefined;
      if (typeof limit === 'number') {
        series.push({ label: 'limit', stroke: '#c62828', dash: [6, 4], width: 1.5 });
        data.push(cols[0].map(() => limit));
      }
      new uPlot({ width: Math.min(900, host.clientWidth || 900), height: 240, series, scales: { x: { time: false } },
                  axes: [{ label: header[0] }, { label: unit === 'other' ? '' : unit }] }, data, div);
    }
  }
}

const SVG = 'http://www.w3.org/2000/svg';
function svgEl(tag, attrs) {
  const e = document.createElementNS(SVG, tag);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
  return e;
}

function stressColour(s, top) {
  if (s < 0) return '#000';
  const t = Math.max(0, Math.min(1, s / top));
  // yellow (low) → red (at the limit)
  return `rgb(255, ${Math.round(230 * (1 - t))}, ${Math.round(120 * (1 - t))})`;
}

// ---- the mechanism's requests: generations, one angle in flight, one revolution per run ---------
// view.gen: the shown run's generation (showResult). Angle requests (the slider) go one at a time:
// while one is in flight the newest angle asked for waits in view.wanted and is asked when it
// returns; each carries the id GEN.SEQ (the server echoes it as request_id) and an answer is drawn
// only if it is the shown generation's newest request. A new generation aborts what is in flight.
// The revolution (frames=180: every 2°, in one answer) is fetched once per shown run; Play and the
// slider draw its frames at once, so the drawing follows the slider whatever the latency.
const PLAY_STEP_DEG = 2, PLAY_TICK_MS = 60, REVOLUTION_FRAMES = 360 / PLAY_STEP_DEG;
const view = {
  gen: 0, study: null, out: null, run: null, path: null,
  seq: 0, inflight: null, wanted: null, drawnAngle: null,
  revolution: null, revolutionInflight: null, playing: null,
};

function newGeneration() {
  view.gen += 1;
  for (const r of [view.inflight, view.revolutionInflight]) if (r) r.controller.abort();
  Object.assign(view, { inflight: null, revolutionInflight: null, revolution: null, study: null });
  return view.gen;
}

// POST /api/mechanism for a study (a sizing's optimum and a cycloid's loads: its run's folder).
function fetchMechanism(study, out, angle, extra, signal) {
  const result = out ? `&result=${encodeURIComponent(out)}` : '';
  return api('POST', `/api/mechanism?angle=${angle}${result}${extra}`, study, signal);
}

function frameAt(angle) {
  const rev = view.revolution;
  if (!rev || rev.gen !== view.gen) return null;
  const k = (((angle - rev.start) / rev.step) % rev.frames.length + rev.frames.length) % rev.frames.length;
  return Number.isInteger(k) ? { status: 200, data: rev.frames[k] } : null;
}

// The slider asks for an angle: a revolution frame drawn at once when there is one, and the angle
// asked of the server (finer outlines; the only way before the revolution is there).
function askAngle(angle) {
  view.wanted = angle;
  const frame = frameAt(angle);
  if (frame) renderMechanism(frame, angle, 'revolution');
  pumpAngle();
}

async function pumpAngle() {
  if (view.inflight || view.wanted === null || !view.study) return;
  if (view.playing && frameAt(view.wanted)) return;  // Play draws the revolution's frames: no requests
  const angle = view.wanted, gen = view.gen, id = `${gen}.${++view.seq}`;
  const controller = new AbortController();
  view.inflight = { id, controller };
  let r = null;
  try {
    r = await fetchMechanism(view.study, view.out, angle, `&points=720&id=${id}`, controller.signal);
  } catch (e) {
    // Aborted: a newer run is shown. Else said where the drawing was (Play does not wait for ever).
    if (e.name !== 'AbortError') r = { status: 0, data: { request_id: id, error: { message: `the mechanism at ${angle}°: ${e.message}` } } };
  }
  if (view.inflight && view.inflight.id === id) view.inflight = null;
  if (gen !== view.gen) return;  // an older run's: dropped (the new one pumps its own)
  const newest = id === `${view.gen}.${view.seq}` && r && r.data && r.data.request_id === id;
  // Drawn when it is the angle wanted, or when the drawing lags behind anyway (a slider dragged
  // faster than the answers: the drawing moves with each answer instead of waiting).
  if (newest && (angle === view.wanted || view.drawnAngle !== view.wanted)) renderMechanism(r, angle, 'angle');
  if (view.wanted !== angle) pumpAngle();
}

async function fetchRevolution(gen) {
  if (gen !== view.gen || view.revolutionInflight || (view.revolution && view.revolution.gen === gen) || !view.study) return;
  const id = `${gen}.revolution`, controller = new AbortController();
  view.revolutionInflight = { id, controller };
  let r = null;
  try {
    r = await fetchMechanism(view.study, view.out, 0, `&points=360&frames=${REVOLUTION_FRAMES}&id=${id}`, controller.signal);
  } catch (e) {
    if (e.name !== 'AbortError') throw e;
  }
  if (view.revolutionInflight && view.revolutionInflight.id === id) view.revolutionInflight = null;
  if (gen !== view.gen || !r || r.status !== 200 || r.data.request_id !== id || !r.data.supported) return;
  view.revolution = { gen, start: r.data.angles_deg[0], step: r.data.frame_step_deg, frames: r.data.frames };
  document.body.dataset.revolution = String(gen);
}

// One answer drawn: the svg says whose (data-run, data-study, data-kind: the study's kind), at which
// angle (data-angle) and from what (data-frames: "revolution" or "angle").
function renderMechanism(r, angle, from) {
  const svg = $('#mechanism');
  view.drawnAngle = angle;
  Object.assign(svg.dataset, { run: view.run, study: view.path, kind: (view.study && view.study.study) || '', frames: from });
  const { status, data } = r;
  if (status !== 200 || !data.supported) {
    $('#mechanism-note').textContent = status !== 200 ? (data.error && data.error.message) || `error ${status}`
      : `the animation of ${data.kind || 'this kind'} is not there yet (${data.why || 'LCR, disc cam, cycloid and their sizings only'})`;
    $('#stress-legend').textContent = '';
    svg.replaceChildren();
    svg.dataset.angle = String(angle);
    return;
  }
  if (data.kind === 'sizing') return drawSizing(svg, data, angle);
  drawDesign(svg, data, view.study, angle);
}

function renderNothing(note) {
  const svg = $('#mechanism');
  svg.replaceChildren();
  Object.assign(svg.dataset, { run: view.run || '', study: view.path || '', kind: '', frames: '', angle: '' });
  view.drawnAngle = null;
  $('#mechanism-note').textContent = note;
  $('#stress-legend').textContent = '';
}

// Play: driven by requestAnimationFrame, a 2° step every 60 ms. With the revolution, each step's
// frame is drawn at once (steps skipped by a slow frame are caught up, not waited for); before it
// is there, the next step is taken only once this one is drawn (one request in flight), so the
// slider never runs ahead of the drawing.
function togglePlay() {
  if (view.playing) {
    cancelAnimationFrame(view.playing.raf);
    view.playing = null;
    $('#play').textContent = '▶ Play';
    askAngle(Number($('#crank').value));  // where it stopped, at the finer outlines
    return;
  }
  $('#play').textContent = '❚❚ Pause';
  view.playing = { last: performance.now(), raf: requestAnimationFrame(playTick) };
  fetchRevolution(view.gen);
}

function setCrank(angle) {
  $('#crank').value = String(angle);
  $('#crank-value').textContent = `${angle}°`;
}

function playTick(now) {
  const p = view.playing;
  if (!p) return;
  p.raf = requestAnimationFrame(playTick);
  if (now - p.last < PLAY_TICK_MS) return;
  const here = Math.round(Number($('#crank').value) / PLAY_STEP_DEG) * PLAY_STEP_DEG;
  if (view.revolution && view.revolution.gen === view.gen) {
    const steps = Math.min(10, Math.floor((now - p.last) / PLAY_TICK_MS));
    p.last = steps === 10 ? now : p.last + steps * PLAY_TICK_MS;
    const next = (here + steps * PLAY_STEP_DEG) % 360;
    setCrank(next);
    view.wanted = next;
    renderMechanism(frameAt(next), next, 'revolution');
    return;
  }
  if (view.inflight || view.drawnAngle !== Number($('#crank').value)) return;  // this step not drawn yet
  p.last = now;
  const next = (here + PLAY_STEP_DEG) % 360;
  setCrank(next);
  askAngle(next);
}

function drawDesign(svg, data, study, angle) {
  if (data.kind === 'disc_cam') return drawDiscCam(svg, data, study, angle);
  if (data.kind === 'cycloid') return drawCycloid(svg, data, study, angle);
  return drawLcr(svg, data, study, angle);
}

// The size a sizing changes, for the legend: the base circle, the turret radii or the pin circle.
function sizeText(d) {
  if (d.kind === 'disc_cam') return `base circle ${d.base_radius_mm.toFixed(3)} mm`;
  if (d.kind === 'cycloid') return `pin circle ${d.roller_position_radius_mm.toFixed(3)} mm, pins ${d.roller_radius_mm.toFixed(3)} mm`;
  return `turrets ${d.sides.map((s) => s.turret_radius_mm.toFixed(3)).join(' / ')} mm, e ${d.eccentricity_mm.toFixed(3)} mm`;
}

// A sizing: its start design grey and dashed under the optimum of its run, each drawn as its
// analysis kind (the server's start and the run's best_*.json), in one frame holding both.
function drawSizing(svg, data, angle) {
  const drawn = [];
  const why = [];
  for (const which of ['start', 'optimum']) {
    const d = data[which];
    if (!d) { why.push('no optimum yet: run the study'); continue; }
    if (!d.supported) { why.push(`${which}: ${d.why}`); continue; }
    const tmp = document.createElementNS(SVG, 'svg');
    drawDesign(tmp, d, d.study, angle);
    const g = tmp.firstChild;
    g.classList.add(`design-${which}`);
    g.dataset.design = which;
    drawn.push({ which, g, d, vb: tmp.getAttribute('viewBox').split(' ').map(Number),
                 note: $('#mechanism-note').textContent, legend: $('#stress-legend').textContent });
  }
  if (!drawn.length) {
    svg.replaceChildren();
    $('#mechanism-note').textContent = why.join('; ');
    return;
  }
  const x0 = Math.min(...drawn.map((v) => v.vb[0])), y0 = Math.min(...drawn.map((v) => v.vb[1]));
  const x1 = Math.max(...drawn.map((v) => v.vb[0] + v.vb[2])), y1 = Math.max(...drawn.map((v) => v.vb[1] + v.vb[3]));
  svg.setAttribute('viewBox', `${x0} ${y0} ${x1 - x0} ${y1 - y0}`);
  svg.replaceChildren(...drawn.map((v) => v.g));  // the start first: under the optimum
  svg.dataset.angle = String(angle);
  const top = drawn[drawn.length - 1];
  $('#mechanism-note').textContent = `${data.sizing_kind}, ${top.which}: ${top.note}${why.length ? ' (' + why.join('; ') + ')' : ''}`;
  const legend = $('#stress-legend');
  legend.replaceChildren();
  for (const v of drawn) {
    const row = document.createElement('div');
    row.className = `legend-${v.which}`;
    const key = svgEl('svg', { width: 28, height: 8 });
    key.append(svgEl('line', { x1: 0, y1: 4, x2: 28, y2: 4, class: v.which === 'start' ? 'key-start' : 'key-optimum' }));
    row.append(key, ` ${v.which === 'start' ? 'start design (grey, dashed)' : 'optimum of the run'}: ${sizeText(v.d)}`);
    legend.append(row);
  }
  legend.append(Object.assign(document.createElement('div'), { textContent: top.legend }));
}

// The LCR: both cams, both turrets, the rollers coloured by their Hertz stress, the forces.
function drawLcr(svg, data, study, angle) {
  const R = Math.max(...data.sides.map((s) => s.turret_radius_mm + s.roller_radius_mm)) * 1.08;
  svg.setAttribute('viewBox', `${-R} ${-R} ${2 * R} ${2 * R}`);
  const g = svgEl('g', { transform: 'scale(1,-1)' });
  const limit = (study.limits && study.limits.contact_stress_MPa) || data.max_stress_MPa || 1;
  let maxForce = 1;
  for (const side of data.sides) for (const r of side.rollers_at) maxForce = Math.max(maxForce, r.force_N);
  for (const side of data.sides) {
    g.append(svgEl('circle', { class: 'turret', cx: 0, cy: 0, r: side.turret_radius_mm }));
    const d = 'M' + side.profile_mm.map((p) => `${p[0]},${p[1]}`).join('L') + 'Z';
    g.append(svgEl('path', { class: `cam-${side.name}`, d }));
  }
  for (const side of data.sides) {
    side.rollers_at.forEach((r, i) => {
      const c = svgEl('circle', {
        class: 'roller', cx: r.x, cy: r.y, r: side.roller_radius_mm,
        fill: r.loaded ? stressColour(r.stress_MPa, limit) : '#e0e0e0',
        'data-side': side.name, 'data-index': i, 'data-x': r.x, 'data-y': r.y,
        'data-force': r.force_N, 'data-stress': r.stress_MPa,
      });
      const t = svgEl('title', {});
      t.textContent = `${side.name} roller ${i}: F = ${r.force_N.toFixed(1)} N, p = ${r.stress_MPa.toFixed(0)} MPa`;
      c.append(t);
      g.append(c);
      if (r.loaded) {
        // The force on the roller (opposite to the cam's), its length in proportion.
        const len = 0.6 * side.roller_radius_mm + 8 * r.force_N / maxForce;
        g.append(svgEl('line', { class: 'force', x1: r.x, y1: r.y, x2: r.x - len * r.dx, y2: r.y - len * r.dy }));
      }
    });
  }
  g.append(svgEl('circle', { cx: data.cam_centre_mm[0], cy: data.cam_centre_mm[1], r: 0.8, fill: '#23395d' }));
  svg.replaceChildren(g);
  svg.dataset.angle = String(angle);
  $('#mechanism-note').textContent =
    `cam centre (${data.cam_centre_mm.map((v) => v.toFixed(3)).join(', ')}) mm, cam turned ${data.cam_rotation_deg.toFixed(2)}°, ` +
    `output turret ${data.output_turret_rotation_deg.toFixed(3)}°; largest contact stress ${data.max_stress_MPa.toFixed(0)} MPa`;
  $('#stress-legend').innerHTML = '';
  $('#stress-legend').append(
    `rollers coloured by Hertz contact stress: yellow 0 → red ${limit.toFixed(0)} MPa` +
    `${study.limits && study.limits.contact_stress_MPa ? ' (the limit)' : ''}; grey unloaded; red lines: roller forces`);
}

// The disc cam with its follower standing (the cam turned by −θ); the roller coloured by the
// pressure angle against its limit.
function drawDiscCam(svg, data, study, angle) {
  if (data.flat_face) return drawFlatFace(svg, data, study, angle);
  let R = 0;
  for (const p of data.profile_mm) R = Math.max(R, Math.hypot(p[0], p[1]));
  const c = data.roller_centre_mm;
  R = Math.max(R, Math.hypot(c[0], c[1]) + data.roller_radius_mm);
  if (data.pivot_mm) R = Math.max(R, Math.hypot(data.pivot_mm[0], data.pivot_mm[1]));
  const left = -R * 1.1, width = R * 2.9;
  svg.setAttribute('viewBox', `${left} ${-R * 1.45} ${width} ${R * 2.9}`);
  const g = svgEl('g', { transform: 'scale(1,-1)' });
  const d = 'M' + data.profile_mm.map((p) => `${p[0]},${p[1]}`).join('L') + 'Z';
  g.append(svgEl('circle', { class: 'turret', cx: 0, cy: 0, r: data.base_radius_mm }));
  g.append(svgEl('path', { class: 'cam-input', d }));
  g.append(svgEl('circle', { cx: 0, cy: 0, r: R * 0.02, fill: '#23395d' }));
  const limits = study.limits || {};
  const limit = limits.pressure_angle_deg || (data.oscillating ? 45 : 30);
  const fill = stressColour(Math.abs(data.pressure_angle_deg), limit);
  if (data.oscillating) {
    g.append(svgEl('line', { class: 'force', x1: data.pivot_mm[0], y1: data.pivot_mm[1], x2: c[0], y2: c[1], style: 'stroke:#333;stroke-width:' + R * 0.025 }));
    g.append(svgEl('circle', { cx: data.pivot_mm[0], cy: data.pivot_mm[1], r: R * 0.03, fill: '#333' }));
  } else {
    const len = R * 1.2, u = data.follower_direction;
    g.append(svgEl('line', { x1: c[0], y1: c[1], x2: c[0] + len * u[0], y2: c[1] + len * u[1], style: 'stroke:#333;stroke-width:' + R * 0.04 }));
  }
  const rr = Math.max(data.roller_radius_mm, R * 0.01);
  const roller = svgEl('circle', { class: 'roller', cx: c[0], cy: c[1], r: rr, fill,
                                   'data-side': 'follower', 'data-index': 0, 'data-x': c[0], 'data-y': c[1] });
  g.append(roller);
  g.append(svgEl('circle', { cx: data.contact_mm[0], cy: data.contact_mm[1], r: R * 0.012, fill: '#c62828' }));
  svg.replaceChildren(g);
  svg.dataset.angle = String(angle);
  $('#mechanism-note').textContent =
    `${data.follower}: lift ${data.lift.toFixed(4)} ${data.oscillating ? 'rad' : 'mm'}, pressure angle ${data.pressure_angle_deg.toFixed(2)}°`;
  $('#stress-legend').textContent = `roller coloured by |pressure angle|: yellow 0 → red ${limit}° (the limit); red dot: the contact point`;
}

// The disc cam with a flat-faced follower standing: the face (coloured by |pressure angle| against
// its limit: 0 for a translating face, atan(d/ℓ) on an arm), its stem or arm, the contact point.
function drawFlatFace(svg, data, study, angle) {
  let R = 0;
  for (const p of [...data.profile_mm, ...data.face_mm]) R = Math.max(R, Math.hypot(p[0], p[1]));
  if (data.pivot_mm) R = Math.max(R, Math.hypot(data.pivot_mm[0], data.pivot_mm[1]));
  svg.setAttribute('viewBox', `${-R * 1.1} ${-R * 1.45} ${R * 2.9} ${R * 2.9}`);
  const g = svgEl('g', { transform: 'scale(1,-1)' });
  g.append(svgEl('circle', { class: 'turret', cx: 0, cy: 0, r: data.base_radius_mm }));
  g.append(svgEl('path', { class: 'cam-input', d: 'M' + data.profile_mm.map((p) => `${p[0]},${p[1]}`).join('L') + 'Z' }));
  g.append(svgEl('circle', { cx: 0, cy: 0, r: R * 0.02, fill: '#23395d' }));
  const limit = (study.limits && study.limits.pressure_angle_deg) || (data.oscillating ? 45 : 30);
  const foot = data.face_foot_mm, w = R * 0.025;
  const [a, b] = data.face_mm;
  if (data.oscillating) {
    // The arm: from the pivot along its line, the face on its cam side at the offset d.
    const o = data.pivot_mm, back = [b[0] - (foot[0] - o[0]), b[1] - (foot[1] - o[1])];
    const body = [o, foot, a, b, back];
    g.append(svgEl('path', { class: 'arm', d: 'M' + body.map((p) => `${p[0]},${p[1]}`).join('L') + 'Z',
                             style: `fill:rgba(60,60,60,0.15);stroke:#333;stroke-width:${w * 0.3}` }));
    g.append(svgEl('circle', { cx: o[0], cy: o[1], r: R * 0.03, fill: '#333' }));
  } else {
    const n = data.face_normal, len = R * 1.2;
    g.append(svgEl('line', { x1: foot[0], y1: foot[1], x2: foot[0] + len * n[0], y2: foot[1] + len * n[1], style: `stroke:#333;stroke-width:${w * 1.6}` }));
  }
  g.append(svgEl('line', { class: 'face', x1: a[0], y1: a[1], x2: b[0], y2: b[1],
                           style: `stroke:${stressColour(Math.abs(data.pressure_angle_deg), limit)};stroke-width:${w * 1.4}`,
                           'data-x1': a[0], 'data-y1': a[1], 'data-x2': b[0], 'data-y2': b[1] }));
  g.append(svgEl('circle', { class: 'contact', cx: data.contact_mm[0], cy: data.contact_mm[1], r: R * 0.012, fill: '#c62828' }));
  svg.replaceChildren(g);
  svg.dataset.angle = String(angle);
  $('#mechanism-note').textContent =
    `${data.follower}: lift ${data.lift.toFixed(4)} ${data.oscillating ? 'rad' : 'mm'}, contact ${data.contact_on_face_mm.toFixed(3)} mm along the face, ` +
    `pressure angle ${data.pressure_angle_deg.toFixed(2)}°, profile radius of curvature ${data.radius_of_curvature_mm.toFixed(2)} mm`;
  $('#stress-legend').textContent = `face coloured by |pressure angle|: yellow 0 → red ${limit}°` +
    `${data.oscillating ? ' (atan(d/ℓ))' : ' (0 for a face across the line of motion)'}; red dot: the contact point`;
}

// The cycloid disc on its pins, each pin coloured by its pair's pressure: with the shown run, the
// run's loaded tooth contact analysis at this crank angle (its per_angle.csv: each pair's load and
// own peak pressure); without one, the rigid disc's Hertz pressure on the nominal tooth (by force
// when the study has no material: an unloaded-only study).
function drawCycloid(svg, data, study, angle) {
  const R = (data.roller_position_radius_mm + data.roller_radius_mm) * 1.08;
  svg.setAttribute('viewBox', `${-R} ${-R} ${2 * R} ${2 * R}`);
  const g = svgEl('g', { transform: 'scale(1,-1)' });
  g.append(svgEl('circle', { class: 'turret', cx: 0, cy: 0, r: data.roller_position_radius_mm }));
  g.append(svgEl('path', { class: 'cam-input', d: 'M' + data.profile_mm.map((p) => `${p[0]},${p[1]}`).join('L') + 'Z' }));
  const pressures = typeof data.max_pressure_MPa === 'number';
  const run = data.pin_source === 'run';
  const limit = study && study.limits && study.limits.contact_stress_MPa;
  const top = pressures ? (limit || data.max_pressure_MPa || 1) : (data.max_pin_force_N || 1);
  data.pins.forEach((p, i) => {
    const value = pressures ? p.pressure_MPa : p.force_N;
    const c = svgEl('circle', {
      class: 'roller', cx: p.x, cy: p.y, r: data.roller_radius_mm,
      fill: p.loaded ? stressColour(value, top) : '#e0e0e0',
      'data-side': 'pins', 'data-index': i, 'data-x': p.x, 'data-y': p.y, 'data-force': p.force_N,
      'data-pressure': pressures ? p.pressure_MPa : '', 'data-source': data.pin_source });
    const t = svgEl('title', {});
    t.textContent = `pin ${i}: F = ${p.force_N.toFixed(1)} N` +
      (pressures && p.loaded ? `, ${run ? 'peak pressure' : 'p0'} = ${p.pressure_MPa.toFixed(0)} MPa` : '') +
      (run && typeof p.nominal_force_N === 'number' ? ` (nominal rigid disc: ${p.nominal_force_N.toFixed(1)} N)` : '');
    c.append(t);
    g.append(c);
  });
  const c = data.disc_centre_mm;
  g.append(svgEl('circle', { cx: c[0], cy: c[1], r: R * 0.012, fill: '#23395d' }));
  g.append(svgEl('circle', { cx: 0, cy: 0, r: R * 0.008, fill: '#888' }));
  // A mark on the disc shows its slow turn (−φ/n2).
  const t = data.disc_rotation_deg * Math.PI / 180, m = data.roller_position_radius_mm * 0.6;
  g.append(svgEl('line', { x1: c[0], y1: c[1], x2: c[0] + m * Math.cos(t), y2: c[1] + m * Math.sin(t), class: 'force' }));
  svg.replaceChildren(g);
  svg.dataset.angle = String(angle);
  svg.dataset.source = data.pin_source;
  $('#mechanism-note').textContent =
    `${data.teeth} teeth on ${data.rollers} pins: disc centre (${c.map((v) => v.toFixed(3)).join(', ')}) mm, disc turned ${data.disc_rotation_deg.toFixed(3)}°` +
    (pressures ? `; largest pair pressure ${data.max_pressure_MPa.toFixed(0)} MPa` : '') +
    `, largest pin force ${data.max_pin_force_N.toFixed(0)} N` + (data.run_note ? `. ${data.run_note}` : '');
  const T = `T = ${(data.disc_torque_Nmm / 1000).toFixed(1)} N·m per disc`;
  const source = `pins from: ${data.pin_source_label}`;
  const scale = `yellow 0 → red ${top.toFixed(0)} ${pressures ? 'MPa' : 'N'}${pressures ? (limit ? ' (the limit)' : ' (the largest)') : ''}; grey unloaded`;
  $('#stress-legend').textContent = `${source}. ` + (run
    ? (pressures ? `Pins coloured by each pair's own peak pressure of the run's loaded tooth contact analysis (modified, crowned tooth; ${T}): ${scale}`
      : `Pins coloured by the run's pair loads (${T}): ${scale}`)
    : (pressures ? `Pins coloured by their pair's Hertz pressure p0 = √(F E*/(π B R')) (rigid disc, nominal tooth, ${T}): ${scale}. Run the study for the modified tooth's loaded pressures`
      : `Pins coloured by contact force (rigid disc, nominal tooth, ${T}): ${scale}`));
}

// ---- compare ----------------------------------------------------------------------------------
async function compare() {
  const a = $('#compare-a').value, b = $('#compare-b').value;
  const table = $('#compare-table');
  table.replaceChildren();
  if (!a || !b) return;
  const [ra, rb] = await Promise.all([api('GET', `/api/runs/${a}/result`), api('GET', `/api/runs/${b}/result`)]);
  // Every row of either run (A's order, then B's own), each run's value and each run's own limit:
  // two studies may have different limits, and a value passes or fails against its own.
  const rowsA = new Map(((ra.data.headlines && ra.data.headlines.rows) || []).map((r) => [r.label, r]));
  const rowsB = new Map(((rb.data.headlines && rb.data.headlines.rows) || []).map((r) => [r.label, r]));
  const head = table.insertRow();
  for (const h of ['', `#${a} ${ra.data.study}`, `#${b} ${rb.data.study}`, `limit #${a}`, `limit #${b}`])
    head.append(Object.assign(document.createElement('th'), { textContent: h }));
  for (const label of new Set([...rowsA.keys(), ...rowsB.keys()])) {
    const tr = table.insertRow();
    const x = rowsA.get(label), y = rowsB.get(label);
    tr.insertCell().textContent = label;
    Object.assign(tr.insertCell(), { textContent: x ? x.value : '—', className: x ? x.status : '' });
    Object.assign(tr.insertCell(), { textContent: y ? y.value : '—', className: y ? y.status : '' });
    Object.assign(tr.insertCell(), { textContent: x ? x.limit : '—', className: 'limit-a' });
    Object.assign(tr.insertCell(), { textContent: y ? y.limit : '—', className: 'limit-b' });
  }
  await compareCurves(ra.data, rb.data, a, b);
}

// One column of a CSV output both runs wrote, the two curves overlaid (uPlot.join aligns the x).
async function compareCurves(ra, rb, a, b) {
  const host = $('#compare-charts');
  host.replaceChildren();
  const common = (ra.files || []).filter((f) => f.endsWith('.csv') && (rb.files || []).includes(f));
  if (!common.length || typeof uPlot === 'undefined') return;
  const name = common.includes('series.csv') ? 'series.csv' : common[0];
  const [ta, tb] = await Promise.all([
    api('GET', `/api/file?path=${encodeURIComponent(ra.out + '/' + name)}`),
    api('GET', `/api/file?path=${encodeURIComponent(rb.out + '/' + name)}`)]);
  const A = parseCsv(ta.text), B = parseCsv(tb.text);
  const columns = A.header.slice(1).filter((h) => B.header.includes(h));
  if (!columns.length) return;
  const select = document.createElement('select');
  select.id = 'compare-column';
  for (const c of columns) select.append(new Option(c, c));
  const chart = document.createElement('div');
  chart.className = 'chart';
  host.append(Object.assign(document.createElement('label'), { textContent: `${name}: ` }), select, chart);
  const draw = () => {
    chart.replaceChildren();
    const col = select.value;
    const data = uPlot.join([[A.cols[0], A.cols[A.header.indexOf(col)]], [B.cols[0], B.cols[B.header.indexOf(col)]]]);
    new uPlot({ width: Math.min(900, host.clientWidth || 900), height: 280, scales: { x: { time: false } },
                series: [{ label: A.header[0] },
                         { label: `#${a} ${col}`, stroke: '#1f77b4', width: 1.2, spanGaps: true },
                         { label: `#${b} ${col}`, stroke: '#d62728', width: 1.2, spanGaps: true }] }, data, chart);
  };
  select.addEventListener('change', draw);
  draw();
}

// ---- wiring -----------------------------------------------------------------------------------
function showTab(name) {
  document.querySelectorAll('#tabs button').forEach((b) => b.classList.toggle('active', b.dataset.tab === name));
  document.querySelectorAll('.tab').forEach((t) => t.classList.toggle('active', t.id === `tab-${name}`));
}

document.querySelectorAll('#tabs button').forEach((b) => b.addEventListener('click', () => showTab(b.dataset.tab)));
$('#save').addEventListener('click', save);
$('#duplicate').addEventListener('click', duplicate);
$('#run').addEventListener('click', startRun);
$('#cancel').addEventListener('click', cancelRun);
$('#crank').addEventListener('input', () => {
  $('#crank-value').textContent = `${$('#crank').value}°`;
  askAngle(Number($('#crank').value));
});
$('#play').addEventListener('click', togglePlay);
$('#compare-a').addEventListener('change', compare);
$('#compare-b').addEventListener('change', compare);

loadFiles().then(loadRuns).then(() => { document.body.dataset.ready = '1'; });
