// hexc edit's page: loads the material, has the server compile it into WebGL programs, draws it, applies the panel's
// edits (uniforms at once, structural ones by compiling again), saves, and follows the file on disk.
import { History } from './history.js';
import { View } from './view.js';
import { Panel, effective, slotEntries } from './panel.js';

const $ = id => document.getElementById(id);
const query = new URLSearchParams(location.search);
const captureSize = query.get('capture');  // "WxH": one frame with the default camera, posted back to hexc edit

// Everything a reload keeps: the camera, the light, the split, what is shown, the selected slot.
const state = {
  doc: null, version: null, schema: null, sizes: {},  // sizes: [width, height] of each texture loaded, by name
  saved: null,     // the document as the file holds it (JSON text): the edits are what differs from it
  conflict: null,  // {version, text}: the file changed on disk while edits were not saved
  problem: null,   // why the view is not the document (it does not compile, the server is gone), or null
  refused: null,   // a value the panel refused (outside its range), shown until the next edit
  view: { shape: 'plane', output: 'split', camera: { azimuth: -70, elevation: 25, distance: 2.5 }, light: { azimuth: 45, elevation: 55 },
          split: [1 / 3, 2 / 3], rect: [0, 0, 1, 1] },
};

// What the tests and the benchmark read: how far the page is, what it shows, and its pixels.
const hexc = window.hexcEdit = { status: 'loading', compiles: 0, frames: 0, liveEdits: 0, pending: 0, shown: [], lastFrame: 0, editAt: 0 };

async function api(path, body) {
  const response = await fetch(path, body === undefined ? {} : { method: 'POST', body: JSON.stringify(body) });
  const text = await response.text();
  try { return { status: response.status, ...JSON.parse(text) }; } catch { return { status: response.status, message: text }; }
}

const dirty = () => state.doc !== null && JSON.stringify(state.doc) !== state.saved;

// The status line, always from the state: whether the edits are saved, a conflict with the file, what went wrong.
function status(doing) {
  const parts = [doing || (state.refused ?? state.problem ?? '')].filter(Boolean);
  if (state.conflict) parts.push('the file changed on disk: your edits are not saved (keep yours, take the file\'s or see both)');
  else parts.push(dirty() ? 'edited (not saved)' : 'saved');
  $('status').textContent = parts.join('; ');
  $('status').className = state.problem || state.refused || state.conflict ? 'error' : '';
  $('save').disabled = !dirty();
  $('undo').disabled = !history.past.length;
  $('redo').disabled = !history.future.length;
}

const history = new History();
const remember = (pointer = null) => history.remember(state.doc, pointer, performance.now());

function travel(doc) {
  if (doc === null) return;
  state.doc = doc;
  panel.render(state.doc);
  compile();
}
const undo = () => travel(history.undo(state.doc));
const redo = () => travel(history.redo(state.doc));

// Diagnostics over the view, never instead of it: the last program that compiled keeps drawing.
function showDiagnostics(list, kind) {
  hexc.shown = list.map(d => d.text);
  $('diagnostics').hidden = list.length === 0;
  $('diagnostics').className = kind;
  $('diagnostics').textContent = hexc.shown.join('\n');
}

function setPointer(doc, pointer, value) {
  const keys = pointer.split('/').slice(1);
  let at = doc;
  for (const k of keys.slice(0, -1)) at = at[k] ??= {};
  const last = keys[keys.length - 1];
  if (value === undefined) delete at[last]; else at[last] = value;
}

let renderer, panel;

// What the page knows of the file on disk: the latest version notified or answered (a save's own change is not looked
// at until the save has answered with its version), whether a change is being looked at, whether a save is under way.
const disk = { latest: null, busy: false, saving: false };

async function texture(name, srgb) {
  const response = await fetch(`/api/texture/${name}`);
  if (!response.ok) throw new Error(await response.text());
  const h = k => response.headers.get(k);
  return { width: Number(h('X-Hexc-Width')), height: Number(h('X-Hexc-Height')), format: h('X-Hexc-Format'), srgb,
           texels: await response.arrayBuffer() };
}

// Fetches the textures the programs read that are not loaded yet (all of them after a change on disk).
async function loadTextures(programs, fresh) {
  const slots = programs.views?.manifest?.slots || [];
  for (const name of renderer.textureSources()) {
    if (!fresh && renderer.textures[name]) continue;
    const slot = slots.find(s => s.name === name), t = await texture(name, !!slot && slot.colorspace === 'srgb' && slot.decode !== 'shader');
    renderer.setTexture(name, t);
    state.sizes[name] = [t.width, t.height];
  }
}

// The cost of the shader as it ships, asked for once the new frame is drawn (its compile is not the page's).
async function costLine(seq) {
  $('cost').textContent = 'cost: compiling the shipped shader…';
  const r = await api('/api/cost', { document: state.doc });
  if (seq !== compileSeq) return;
  const c = r.cost;
  // A layered material adds its blend's fetches per pixel: expected over its splat maps (unknown, null, when vertex
  // colours alone weigh the layers), and at worst.
  const expected = c && c.layer_fetches && c.layer_fetches.expected !== null ? c.layer_fetches.expected.toFixed(1) : 'unknown';
  const layers = c && c.layer_fetches
    ? ` · layers ${expected} expected / ${c.layer_fetches.worst} worst fetches/pixel` : '';
  $('cost').textContent = c ? `${c.fetches} fetches/pixel${layers} · ${c.instructions} SPIR-V instructions · compiled in ${c.compile_ms.toFixed(0)} ms` : '';
}

// The last compile's answer, and its programs linked for the selected slot: selecting another links them again, with
// no compile (templates/edit/views.glsl), or nothing if they were linked before. Resolves false if a later link
// superseded this one; the frames drawn meanwhile show the programs before.
let compiled = null;
const shownSlot = () => (state.doc ? slotEntries(state.doc)[panel.slot] : undefined);
// The splat map and layer weight views are linked only while shown (two more programs of a layered material).
const layerViews = () => ['splat', 'layer'].includes(state.view.output);
async function linkPrograms() {
  const shown = { slot: shownSlot()?.name, layer: layerViews() && state.doc?.layers ? panel.layer : undefined };
  if (!await renderer.setPrograms(compiled.programs, compiled.slots, shown)) return false;
  hexc.programs = Object.keys(renderer.programs);
  return true;
}

let compileSeq = 0;
async function compile(freshTextures = false) {
  const seq = ++compileSeq;
  hexc.pending++;
  status('compiling…');
  try {
    const timing = { sent: performance.now() };  // where a structural edit's time goes (bench/edit_latency.py)
    const r = await api('/api/compile', { document: state.doc });
    if (seq !== compileSeq) return;  // a later edit is being compiled
    timing.answered = performance.now();
    hexc.compiles++;
    if (!r.ok) {
      showDiagnostics(r.diagnostics || [{ text: r.message }], 'error');
      state.problem = 'the material does not compile: the view shows its last version';
      hexc.status = 'error';
      status();
      return draw();
    }
    compiled = r;
    renderer.live.clear();  // its manifests hold the document's values
    timing.server = r.server;  // the server's own milliseconds and compiles: the rest of the answer's time is the transfer
    await linkPrograms();  // false: a slot selected meanwhile linked this answer's programs for its slot
    if (seq !== compileSeq) return;
    timing.linked = performance.now();
    const known = Object.keys(state.sizes).length;
    await loadTextures(r.programs, freshTextures);
    if (Object.keys(state.sizes).length !== known) panel.render(state.doc);  // the tiling lock needs the texture's size
    timing.textures = performance.now();
    hexc.timing = timing;
    const failed = Object.entries(r.programs).flatMap(([name, p]) => p.fragment ? [] : p.diagnostics.map(d => ({ text: `${name}: ${d.text}` })));
    showDiagnostics([...r.diagnostics, ...failed], 'warning');
    $('template').textContent = r.note ? `shown with template ${r.template}: ${r.note}` : `template ${r.template}`;
    state.problem = null;
    hexc.status = 'ready';
    status();
    draw();
    costLine(seq);
  } catch (e) {
    showDiagnostics([{ text: String(e.message || e) }], 'error');
    hexc.status = 'error';
    state.problem = String(e.message || e);
    status();
    draw();
  } finally {
    hexc.pending--;
  }
}

// A slider's drag waits 120 ms for more of it (one compile for the burst); any other edit compiles at once.
let compileTimer = null;
function scheduleCompile(drag) {
  clearTimeout(compileTimer);
  if (drag) compileTimer = setTimeout(compile, 120);
  else compile();
}

// A panel edit: the document changes; a setting that is a uniform in every program is set there and drawn at once,
// anything else compiles again. `drag`: the edit is a step of a slider's drag.
function onEdit(pointer, value, target, drag = false) {
  hexc.editAt = performance.now();
  state.refused = null;
  remember(value === undefined ? null : pointer);  // a reset is a step of its own
  setPointer(state.doc, pointer, value);
  status();
  const entries = slotEntries(state.doc), names = target.slots.map(i => `${entries[i].name}_${target.key}`);
  if (target.param && renderer.member(target.param)) {  // the layers' blend: one parameter of its own
    renderer.setParam(target.param, value ?? state.schema.properties.layer_blend.properties[target.key].default);
    hexc.liveEdits++;
    draw();
  } else if (!target.param && names.every(n => renderer.member(n))) {
    const p = state.schema.$defs.hextiling.properties[target.key];
    target.slots.forEach((i, k) => {
      const v = target.key === 'heightwidth' ? entries[i].slot.height_blend.width : effective(state.doc, i, target.key, p.default);
      renderer.setParam(names[k], v);
    });
    hexc.liveEdits++;
    draw();
  } else {
    scheduleCompile(drag);
  }
  if (value === undefined) panel.render(state.doc);  // a reset shows the default again
}

// Another slot, layer or view selected: its views linked again (nothing compiled; nothing at all for programs linked
// before) and drawn, the distance in its repeats.
function selectSlot() {
  if (compiled)
    linkPrograms().then(linked => linked && loadTextures(compiled.programs)).then(draw, e => showDiagnostics([{ text: String(e.message || e) }], 'error'));
  draw();
}

function regions() {
  const [a, b] = state.view.split;
  return state.view.output === 'split' ? [['plain', 0, a], ['hex', a, b], ['weights', b, 1]] : [[state.view.output, 0, 1]];
}

function labels() {
  const names = { plain: 'plain tiling', hex: 'hex-tiling', weights: 'weights', values: 'slot values' };
  const slot = shownSlot()?.name, layers = state.doc?.layers || [], map = Math.floor(panel.layer / 4);
  // The splat map's channels r, g, b, a weigh layers 4k to 4k + 3; the display shows r, g, b (the layer weight view
  // shows the fourth).
  const splatLayers = layers.slice(4 * map, 4 * map + 4).map((l, i) => `${'rgba'[i]} ${l.name}${i === 3 ? ' not shown' : ''}`).join(', ');
  Object.assign(names, { splat: `splat map ${map} (${splatLayers})`, layer: `layer weight (${layers[panel.layer]?.name})` });
  $('labels').replaceChildren(...regions().map(([name, left]) => {
    const span = document.createElement('span');
    span.style.left = `calc(${left * 100}% + 8px)`;
    span.textContent = name === 'weights' || name === 'values' ? `${names[name]} (${slot})` : names[name];
    return span;
  }));
  state.view.split.forEach((x, i) => { $(`divider-${i}`).style.left = `${x * 100}%`; $(`divider-${i}`).hidden = state.view.output !== 'split'; });
}

let drawRequested = false;
function draw() {
  if (drawRequested) return;
  drawRequested = true;
  requestAnimationFrame(() => {
    drawRequested = false;
    const canvas = $('canvas');
    if (!captureSize) {
      canvas.width = Math.max(1, Math.round(canvas.clientWidth * devicePixelRatio));
      canvas.height = Math.max(1, Math.round(canvas.clientHeight * devicePixelRatio));
    }
    renderer.draw(state.view, regions());
    labels();
    showDistance();
    // The browser calls the next animation frame once it has taken this one: that is when the frame counts as drawn
    // (reading a pixel back to know it would stall the pipeline every frame).
    requestAnimationFrame(() => {
      hexc.frames++;
      hexc.lastFrame = performance.now();
      if (captureSize && hexc.status !== 'loading') postCapture();
    });
  });
}

let captured = false;
async function postCapture() {
  if (captured || hexc.pending) return;
  captured = true;
  const [w, h] = captureSize.split('x').map(Number);
  const headers = { 'X-Hexc-Width': String(w), 'X-Hexc-Height': String(h) };
  if (hexc.status === 'error') headers['X-Hexc-Error'] = '1';  // the body is then what the page shows
  await fetch('/api/capture', { method: 'POST', headers, body: hexc.status === 'error' ? hexc.shown.join('\n') : renderer.readCanvas() });
}

async function load() {
  const r = await api('/api/material');
  $('title').textContent = `hexc edit: ${r.file}`;
  let doc;
  try {
    doc = JSON.parse(r.text);
  } catch {
    showDiagnostics(r.diagnostics?.length ? r.diagnostics : [{ text: `${r.file} is not JSON` }], 'error');
    hexc.status = 'error';
    return draw();
  }
  if (state.doc !== null && JSON.stringify(doc) !== JSON.stringify(state.doc)) remember();  // a reload can be undone
  Object.assign(state, { doc, version: r.version, saved: JSON.stringify(doc), conflict: null });
  disk.latest = r.version;  // newer than any change notified before it was asked for
  conflictBar();
  panel.render(state.doc);
  document.querySelectorAll('#output .layered').forEach(o => { o.hidden = !Array.isArray(doc.layers); });
  await compile(true);
}

async function save(retry = true) {
  if (!dirty() || state.conflict) return;
  status('saving…');
  let r;
  disk.saving = true;
  try {
    r = await api('/api/save', { document: state.doc, version: state.version });
  } catch (e) {
    return status(`not saved: ${e.message || e}`);
  } finally {
    disk.saving = false;
  }
  if (r.ok) {
    Object.assign(state, { version: r.version, saved: JSON.stringify(state.doc) });
    disk.latest = r.version;
    status();
  } else if (r.conflict) {
    await changedOnDisk();
    if (!state.conflict && retry) return save(false);  // only a texture changed: the edits still apply
  } else {
    showDiagnostics(r.diagnostics || [], 'error');
    status(`not saved: ${r.message || 'the material does not compile'}`);
  }
  look();  // a change on disk that came while saving (the save's own is its version now)
}

// The file or a texture changed on disk. Without unsaved edits the page reloads the material (the view and the panel's
// slot stay). With them nothing is dropped: the page shows the conflict and the artist keeps theirs, takes the file's or
// sees both. A change of a texture alone reloads the textures and keeps the edits.
async function changedOnDisk() {
  const r = await api('/api/material');
  if (!dirty() || r.text === undefined) return load();
  let same = false;
  try { same = JSON.stringify(JSON.parse(r.text)) === state.saved; } catch { /* not JSON now: a conflict */ }
  if (same) {
    state.version = disk.latest = r.version;
    return compile(true);
  }
  state.conflict = { version: r.version, text: r.text };
  disk.latest = r.version;
  conflictBar();
  status();
}

function conflictBar() {
  $('conflict').hidden = !state.conflict;
  $('both').hidden = true;
}

const resolve = {
  // The edits stay and become the version to save over the file's.
  keep() {
    state.version = state.conflict.version;
    state.conflict = null;
    conflictBar();
    status();
  },
  take() {
    const text = state.conflict.text;
    state.conflict = null;
    try { remember(); state.doc = JSON.parse(text); } catch { /* load() shows why */ }
    return load();
  },
  // The two documents side by side, written alike (so that only what differs is marked), the lines only one has marked.
  both() {
    let theirs = state.conflict.text.trimEnd();
    try { theirs = JSON.stringify(JSON.parse(theirs), null, 2); } catch { /* not JSON: shown as it is */ }
    const mine = JSON.stringify(state.doc, null, 2).split('\n'), file = theirs.split('\n');
    const pane = (lines, other) => {
      const set = new Set(other.map(l => l.trim().replace(/,$/, '')));
      return lines.map(l => Object.assign(document.createElement('div'), { textContent: l, className: set.has(l.trim().replace(/,$/, '')) ? '' : 'differs' }));
    };
    $('both-mine').replaceChildren(...pane(mine, file));
    $('both-file').replaceChildren(...pane(file, mine));
    $('both').hidden = !$('both').hidden;
  },
};

// Acts on the latest version of the file on disk unless the page already has it (or shows it as a conflict).
async function look() {
  if (disk.busy || disk.saving) return;
  disk.busy = true;
  while (disk.latest !== null && disk.latest !== state.version && disk.latest !== state.conflict?.version) {
    const seen = disk.latest;
    await changedOnDisk();
    if (disk.latest === seen) break;
  }
  disk.busy = false;
}

// The file and its textures on disk: the server pushes their version when they change (server-sent events; the
// browser reconnects when the server ends a stream).
function watch() {
  const events = new EventSource('/api/events');
  events.onmessage = e => {
    disk.latest = e.data;
    hexc.notified = performance.now();
    if (state.problem === 'hexc edit is not running') state.problem = null;
    status();
    look();
  };
  events.onerror = async () => {  // the stream ended (it reconnects) or the server is gone
    try { await fetch('/api/version'); } catch { state.problem = 'hexc edit is not running'; status(); }
  };
}

// Ctrl+S saves, Ctrl+Z undoes, Ctrl+Shift+Z and Ctrl+Y redo (Cmd on a Mac); closing the tab with unsaved edits warns.
function keys() {
  document.addEventListener('keydown', e => {
    if (!(e.ctrlKey || e.metaKey) || e.altKey) return;
    const key = e.key.toLowerCase();
    const act = { s: () => save(), z: e.shiftKey ? redo : undo, y: redo }[key];
    if (!act) return;
    e.preventDefault();
    act();
  });
  window.addEventListener('beforeunload', e => {
    if (!dirty()) return;
    e.preventDefault();
    e.returnValue = '';  // older browsers show the warning only when this is set
  });
  $('undo').addEventListener('click', undo);
  $('redo').addEventListener('click', redo);
  $('keep').addEventListener('click', resolve.keep);
  $('take').addEventListener('click', resolve.take);
  $('see-both').addEventListener('click', resolve.both);
}

// The camera distance in repeats of the selected slot's texture (uv units times its tiling), on a logarithmic slider:
// each 1/12 of it doubles the distance, from an eighth of a repeat (a few texels) to 256 repeats.
const kRepeats = [1 / 8, 256];
function tilingX() {
  const slot = shownSlot() ? panel.slot : null;
  const t = state.doc ? effective(state.doc, slot, 'tiling', state.schema?.$defs.hextiling.properties.tiling.default ?? 1) : 1;
  return Array.isArray(t) ? t[0] : t;
}
function showDistance() {
  const repeats = state.view.camera.distance * tilingX();
  $('distance').value = String(Math.log(repeats / kRepeats[0]) / Math.log(kRepeats[1] / kRepeats[0]));
  $('distance-value').textContent = `${Number(repeats.toPrecision(2))} repeats`;
}

function controls() {
  const distance = $('distance');
  distance.addEventListener('input', () => {
    state.view.camera.distance = kRepeats[0] * Math.pow(kRepeats[1] / kRepeats[0], Number(distance.value)) / tilingX();
    draw();
  });
  const bind = (id, get, set) => { $(id).value = String(get()); $(id).addEventListener('input', () => { set(Number($(id).value)); draw(); }); };
  bind('elevation', () => state.view.camera.elevation, v => { state.view.camera.elevation = v; });
  bind('light-azimuth', () => state.view.light.azimuth, v => { state.view.light.azimuth = v; });
  bind('light-elevation', () => state.view.light.elevation, v => { state.view.light.elevation = v; });
  for (const id of ['shape', 'output']) {
    $(id).value = state.view[id];
    $(id).addEventListener('change', () => { state.view[id] = $(id).value; selectSlot(); });
  }
  $('save').addEventListener('click', () => save());
  keys();
  $('screenshot').addEventListener('click', () => $('canvas').toBlob(b => {
    const a = document.createElement('a');
    a.href = URL.createObjectURL(b);
    a.download = `${state.doc?.name || 'material'}.png`;
    a.click();
  }));
  interaction();
}

// Dragging the view orbits the camera; dragging a divider moves the split; the wheel changes the distance.
function interaction() {
  let drag = null;
  const viewport = $('viewport');
  viewport.addEventListener('pointerdown', e => {
    if (e.target.closest('#conflict, #diagnostics')) return;  // their buttons and text, not the view
    drag = e.target.classList.contains('divider') ? { divider: Number(e.target.id.slice(-1)) } : { x: e.clientX, y: e.clientY };
    viewport.setPointerCapture(e.pointerId);
  });
  viewport.addEventListener('pointermove', e => {
    if (!drag) return;
    const box = viewport.getBoundingClientRect();
    if (drag.divider !== undefined) {
      const s = state.view.split, x = Math.min(1, Math.max(0, (e.clientX - box.left) / box.width));
      s[drag.divider] = drag.divider === 0 ? Math.min(x, s[1]) : Math.max(x, s[0]);
    } else {
      state.view.camera.azimuth -= (e.clientX - drag.x) * 0.4;
      state.view.camera.elevation = Math.min(89, Math.max(2, state.view.camera.elevation + (e.clientY - drag.y) * 0.3));
      Object.assign(drag, { x: e.clientX, y: e.clientY });
    }
    draw();
  });
  viewport.addEventListener('pointerup', () => { drag = null; });
  viewport.addEventListener('wheel', e => {
    e.preventDefault();
    const t = tilingX(), repeats = state.view.camera.distance * t * Math.exp(e.deltaY * 0.001);
    state.view.camera.distance = Math.min(kRepeats[1], Math.max(kRepeats[0], repeats)) / t;
    draw();
  }, { passive: false });
}

// For tests and the benchmark: the view state, and the pixels of the current view as floats (rows bottom first).
hexc.drawPending = () => drawRequested;
hexc.view = () => state.view;
hexc.document = () => state.doc;
hexc.setView = v => { Object.assign(state.view, v); if (v.output) selectSlot(); else draw(); };
hexc.selectLayer = i => { panel.layer = i; panel.render(state.doc); selectSlot(); };
hexc.readFloat = (w, h) => Array.from(renderer.readFloat(state.view, regions(), w, h));
hexc.selectSlot = name => { panel.slot = slotEntries(state.doc).findIndex(s => s.name === name); panel.render(state.doc); selectSlot(); };

async function start() {
  if (captureSize) {
    document.body.classList.add('capture');
    const [w, h] = captureSize.split('x').map(Number);
    Object.assign($('canvas'), { width: w, height: h });
  }
  try {
    const names = ['view.vert.glsl', 'display.vert.glsl', 'display.frag.glsl'];
    const [schema, ...sources] = await Promise.all([api('/api/schema'), ...names.map(n => fetch(`/api/shader/${n}`).then(r => r.text()))]);
    state.schema = schema;
    renderer = new View($('canvas'), Object.fromEntries(names.map((n, i) => [n, sources[i]])));
    panel = new Panel($('panel'), schema, onEdit);
    panel.onSlot = selectSlot;
    panel.onLayer = selectSlot;
    panel.onRefuse = message => { state.refused = message; status(); };
    panel.textureSize = i => state.sizes[slotEntries(state.doc)[i]?.name];
    controls();
    await load();
  } catch (e) {
    showDiagnostics([{ text: String(e.message || e) }], 'error');
    hexc.status = 'error';
    if (captureSize) postCapture();
  }
  if (!captureSize) watch();
}

start();
