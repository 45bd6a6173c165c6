// skytrack display page: draws the picture `skytrack display` streams (docs/display.md).
// Transport: server-sent events by default; ?transport=poll fetches /api/frame twice a second,
// ?transport=once fetches it once (screenshots). ?report=1 posts the page's state (#state) to
// /api/page-state every second, for the browser test and the frame-rate measurement.
'use strict';
const PROVISIONAL = 2 ** 40;               // provisional (tentative) numbers start here
const TRAIL = 40;                           // positions kept per track
const COLORS = { c: '#66bb6a', k: '#4fc3f7', t: '#ffb300', d: '#ef5350' };
const SENSOR_COLORS = ['#b0bec5', '#ffcc80', '#80cbc4', '#f48fb1', '#9fa8da', '#e6ee9c'];
const params = new URLSearchParams(location.search);
const canvas = document.getElementById('scope');
const ctx = canvas.getContext('2d');
const $ = (id) => document.getElementById(id);

let picture = null;                 // the last frame document received
let view = null;                    // {cx, cy, scale [px/m]}; null: fit to the picture
let userMoved = false;
let dirty = true;
const trails = new Map();           // "sensor:id" -> [[x, y], ...]
const lastScan = new Map();         // sensor -> scan whose positions are in the trails
const hidden = new Set();           // sensors switched off
let selected = null;                // {sensor, id}
const stats = { frames: 0, scans: 0, scansMissed: 0, rafs: 0, fps: 0, drawMs: 0, drawMsMax: 0 };
let rafWindow = { start: performance.now(), count: 0 };

function label(id) { return id >= PROVISIONAL ? 'T' + (id - PROVISIONAL) : String(id); }

// ---- receiving --------------------------------------------------------------------------
function receive(doc) {
  picture = doc;
  stats.frames++;
  for (const s of doc.sensors) {
    if (s.scan === undefined || lastScan.get(s.sensor) === s.scan) continue;
    // Scans the page never saw: the server sends the newest picture when the page is ready.
    const prev = lastScan.get(s.sensor);
    if (prev !== undefined && s.scan > prev + 1) stats.scansMissed += s.scan - prev - 1;
    stats.scans++;
    lastScan.set(s.sensor, s.scan);
    const alive = new Set();
    for (const t of s.tracks) {
      const key = s.sensor + ':' + t.i;
      alive.add(key);
      let trail = trails.get(key);
      if (!trail) trails.set(key, trail = []);
      trail.push([t.x, t.y]);
      if (trail.length > TRAIL) trail.shift();
    }
    for (const key of trails.keys()) if (key.startsWith(s.sensor + ':') && !alive.has(key)) trails.delete(key);
  }
  if (doc.sensors.length === 0) { trails.clear(); lastScan.clear(); }
  updatePanel();
  dirty = true;
}

function connect() {
  const transport = params.get('transport') || 'sse';
  const setConn = (ok, text) => { $('conn').className = ok ? 'ok' : 'bad'; $('conn').textContent = text; };
  if (transport === 'sse') {
    const source = new EventSource('api/events');
    source.onmessage = (e) => { setConn(true, 'live'); receive(JSON.parse(e.data)); };
    source.onerror = () => setConn(false, 'reconnecting');
    return;
  }
  const once = transport === 'once';
  const poll = () => fetch('api/frame').then((r) => r.json())
    .then((doc) => { setConn(true, once ? 'snapshot' : 'polling'); receive(doc); })
    .catch(() => setConn(false, 'no server'))
    .finally(() => { if (!once) setTimeout(poll, 500); });
  poll();
}

// ---- view -------------------------------------------------------------------------------
function resize() {
  const r = canvas.getBoundingClientRect();
  canvas.width = Math.max(1, Math.round(r.width));
  canvas.height = Math.max(1, Math.round(r.height));
  dirty = true;
}

function fit() {
  let x0 = Infinity, x1 = -Infinity, y0 = Infinity, y1 = -Infinity;
  const add = (x, y) => { if (x === null || y === null) return; x0 = Math.min(x0, x); x1 = Math.max(x1, x); y0 = Math.min(y0, y); y1 = Math.max(y1, y); };
  for (const s of picture ? picture.sensors : []) {
    for (const t of s.tracks || []) add(t.x, t.y);
    if (s.plots.length) add(s.plots[0].platform[0], s.plots[0].platform[1]);
  }
  if (!isFinite(x0)) return { cx: 0, cy: 0, scale: canvas.width / 100000 };
  const span = Math.max(x1 - x0, y1 - y0, 2000) * 1.15;
  return { cx: (x0 + x1) / 2, cy: (y0 + y1) / 2, scale: Math.min(canvas.width, canvas.height) / span };
}

const sx = (x) => canvas.width / 2 + (x - view.cx) * view.scale;
const sy = (y) => canvas.height / 2 - (y - view.cy) * view.scale;

// ---- drawing ----------------------------------------------------------------------------
function niceStep(metres) {
  const p = 10 ** Math.floor(Math.log10(metres));
  return [1, 2, 5, 10].map((m) => m * p).find((s) => s >= metres);
}

function drawRings(sensors) {
  const origins = sensors.filter((s) => s.plots.length).map((s) => s.plots[0].platform);
  if (!origins.length) origins.push([0, 0]);
  const step = niceStep(120 / view.scale);
  ctx.strokeStyle = '#1f2c36'; ctx.fillStyle = '#455a64'; ctx.lineWidth = 1;
  const far = Math.hypot(canvas.width, canvas.height) / view.scale;
  for (const [ox, oy] of origins) {
    const dist = Math.hypot(view.cx - ox, view.cy - oy);
    for (let r = step; r < dist + far; r += step) {
      ctx.beginPath(); ctx.arc(sx(ox), sy(oy), r * view.scale, 0, 2 * Math.PI); ctx.stroke();
      ctx.fillText((r / 1000) + ' km', sx(ox) + 3, sy(oy + r) - 3);
    }
    ctx.fillStyle = '#90a4ae'; ctx.fillRect(sx(ox) - 3, sy(oy) - 3, 6, 6);
  }
}

function drawPlots(s, color) {
  const n = s.plots.length;
  ctx.fillStyle = color;
  s.plots.forEach((layer, age) => {
    ctx.globalAlpha = 0.9 * (1 - age / (n + 1));    // the newest scan brightest
    const xy = layer.xy;
    for (let k = 0; k < xy.length; k += 2) ctx.fillRect(sx(xy[k]) - 1, sy(xy[k + 1]) - 1, 2, 2);
  });
  ctx.globalAlpha = 1;
}

// Ellipse {p : (p-c)^T M^-1 (p-c) <= k^2} of the symmetric [a b; b c], in screen space.
function ellipse(x, y, m, k) {
  const [a, b, c] = m;
  const h = Math.sqrt(((a - c) / 2) ** 2 + b * b);
  const l1 = Math.max((a + c) / 2 + h, 0), l2 = Math.max((a + c) / 2 - h, 0);
  const angle = 0.5 * Math.atan2(2 * b, a - c);
  ctx.beginPath();
  ctx.ellipse(sx(x), sy(y), Math.max(k * Math.sqrt(l1) * view.scale, 1),
              Math.max(k * Math.sqrt(l2) * view.scale, 1), -angle, 0, 2 * Math.PI);
  ctx.stroke();
}

function drawTrack(s, t, branch) {
  const x = sx(t.x), y = sy(t.y), color = COLORS[t.s] || '#fff';
  ctx.strokeStyle = color; ctx.fillStyle = color; ctx.lineWidth = 1.5;
  if ($('show-leaders').checked) {
    ctx.beginPath(); ctx.moveTo(x, y); ctx.lineTo(sx(t.x + 60 * t.vx), sy(t.y + 60 * t.vy)); ctx.stroke();
  }
  if (t.e) { ctx.setLineDash([4, 3]); ellipse(t.x, t.y, t.e, 1); ctx.setLineDash([]); }
  if (t.c && $('show-cov').checked) { ctx.globalAlpha = 0.6; ellipse(t.x, t.y, t.c, 2); ctx.globalAlpha = 1; }
  ctx.beginPath();
  if (t.f) {
    ctx.strokeStyle = '#ce93d8';
    ctx.moveTo(x, y - 6); ctx.lineTo(x + 6, y); ctx.lineTo(x, y + 6); ctx.lineTo(x - 6, y); ctx.closePath(); ctx.stroke();
  } else if (t.s === 't') {
    ctx.rect(x - 3.5, y - 3.5, 7, 7); ctx.stroke();
  } else {
    ctx.arc(x, y, 4, 0, 2 * Math.PI);
    if (t.s === 'c') ctx.fill(); else ctx.stroke();
  }
  if (branch) { ctx.strokeStyle = '#ff4081'; ctx.beginPath(); ctx.arc(x, y, 9, 0, 2 * Math.PI); ctx.stroke(); }
  if (selected && selected.sensor === s.sensor && selected.id === t.i) {
    ctx.strokeStyle = '#fff'; ctx.strokeRect(x - 10, y - 10, 20, 20);
  }
  ctx.fillStyle = '#eceff1';
  ctx.fillText(label(t.i) + (t.m ? ' (' + t.m + ')' : ''), x + 7, y - 6);
}

function drawTrails(s) {
  ctx.lineWidth = 1; ctx.globalAlpha = 0.5;
  for (const t of s.tracks || []) {
    const trail = trails.get(s.sensor + ':' + t.i);
    if (!trail || trail.length < 2) continue;
    ctx.strokeStyle = COLORS[t.s] || '#fff';
    ctx.beginPath(); ctx.moveTo(sx(trail[0][0]), sy(trail[0][1]));
    for (const [x, y] of trail) ctx.lineTo(sx(x), sy(y));
    ctx.stroke();
  }
  ctx.globalAlpha = 1;
}

function drawTruth(truth) {
  ctx.strokeStyle = '#78909c'; ctx.lineWidth = 1;
  for (const o of truth.objects) {
    const x = sx(o.x), y = sy(o.y);
    ctx.beginPath(); ctx.moveTo(x - 4, y - 4); ctx.lineTo(x + 4, y + 4); ctx.moveTo(x - 4, y + 4); ctx.lineTo(x + 4, y - 4); ctx.stroke();
  }
}

function draw() {
  const start = performance.now();
  if (!view || !userMoved) view = fit();
  ctx.fillStyle = '#0b1016'; ctx.fillRect(0, 0, canvas.width, canvas.height);
  ctx.font = '11px monospace';
  if (!picture) return;
  const sensors = picture.sensors.filter((s) => !hidden.has(s.sensor));
  drawRings(sensors);
  sensors.forEach((s, i) => { if ($('show-plots').checked) drawPlots(s, SENSOR_COLORS[i % SENSOR_COLORS.length]); });
  if (picture.truth && $('show-truth').checked) drawTruth(picture.truth);
  for (const s of sensors) {
    if ($('show-trails').checked) drawTrails(s);
    const branched = new Set((s.events || []).filter((e) => e[0].startsWith('branch')).map((e) => e[1]));
    for (const t of s.tracks || []) {
      if (t.s === 'd' || (t.s === 't' && !$('show-tentative').checked)) continue;
      drawTrack(s, t, branched.has(t.i));
    }
  }
  stats.drawMs = performance.now() - start;
  stats.drawMsMax = Math.max(stats.drawMsMax, stats.drawMs);
}

function frameLoop(now) {
  stats.rafs++; rafWindow.count++;
  if (now - rafWindow.start >= 2000) {
    stats.fps = Math.round(rafWindow.count * 10000 / (now - rafWindow.start)) / 10;
    rafWindow = { start: now, count: 0 };
  }
  if (dirty) { dirty = false; draw(); }
  requestAnimationFrame(frameLoop);
}

// ---- panel ------------------------------------------------------------------------------
function escapeHtml(s) { return String(s).replace(/[&<>"]/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;' }[c])); }

function updatePanel() {
  const ms = (s) => (s * 1000).toFixed(2) + ' ms';
  const reasons = (counts) => Object.entries(counts).map(([r, n]) => escapeHtml(r) + ': ' + n).join('<br>') || 'none';
  $('status').innerHTML = picture.status.map((st) => `<table>
    <tr><td>instance</td><td class="num">${escapeHtml(st.instance)} (${escapeHtml(st.profile)})</td></tr>
    <tr><td>latency p50/p99</td><td class="num">${ms(st.latency.p50)} / ${ms(st.latency.p99)}</td></tr>
    <tr><td>queue</td><td class="num">${st.queue_depth}</td></tr>
    <tr><td>scans</td><td class="num">${st.scans_processed} (dropped ${st.scans_dropped})</td></tr>
    <tr><td>tracks</td><td class="num"><span class="c">${st.tracks.confirmed}</span> / <span class="k">${st.tracks.coasting}</span> / <span class="t">${st.tracks.tentative}</span></td></tr>
    <tr><td>plots rejected</td><td class="num">${reasons(st.plots_rejected)}</td></tr>
    <tr><td>scans rejected</td><td class="num">${reasons(st.scans_rejected)}</td></tr></table>`).join('<hr>') || 'no TrackerStatus';
  const box = $('sensors');
  box.innerHTML = '';
  for (const s of picture.sensors) {
    const n = { c: 0, k: 0, t: 0 };
    for (const t of s.tracks || []) if (n[t.s] !== undefined) n[t.s]++;
    const fused = (s.tracks || []).some((t) => t.f);
    const plots = s.plots.length ? s.plots[0].xy.length / 2 : 0;
    const row = document.createElement('label');
    row.innerHTML = `<input type="checkbox" ${hidden.has(s.sensor) ? '' : 'checked'}> ${fused ? 'fusion' : 'sensor'} ${s.sensor}: scan ${s.scan ?? '-'}, ` +
      `<span class="c">${n.c}</span>/<span class="k">${n.k}</span>/<span class="t">${n.t}</span> tracks, ${plots} plots`;
    row.firstChild.onchange = (e) => { if (e.target.checked) hidden.delete(s.sensor); else hidden.add(s.sensor); dirty = true; };
    box.appendChild(row);
  }
  const r = picture.replay;
  $('replay').hidden = picture.mode !== 'replay';
  if (r && document.activeElement !== $('rate')) $('rate').value = String(r.rate);
  if (r) $('replay-pos').textContent = `frame ${r.frame}/${r.frames}, t = ${r.time.toFixed(1)} s, ${r.playing ? 'playing' : 'paused'} x${r.rate}`;
  writeState();
}

// The page's state for tests and measurements: what it shows, and how fast it draws.
function pageState() {
  const sensors = {};
  for (const s of picture ? picture.sensors : []) {
    const ids = (st) => (s.tracks || []).filter((t) => t.s === st).map((t) => t.i);
    sensors[s.sensor] = { scan: s.scan ?? null, confirmed: ids('c'), coasting: ids('k'), tentative: ids('t').length,
                          plots: s.plots.reduce((n, l) => n + l.xy.length / 2, 0) };
  }
  return { version: picture ? picture.version : 0, mode: picture ? picture.mode : null, frames: stats.frames,
           scans: stats.scans, scans_missed: stats.scansMissed, fps: stats.fps, rafs: stats.rafs,
           draw_ms: Math.round(stats.drawMs * 10) / 10, draw_ms_max: Math.round(stats.drawMsMax * 10) / 10,
           sensors, status: picture ? picture.status.map((s) => s.instance) : [] };
}
function writeState() {
  const state = $('state');
  state.textContent = JSON.stringify(pageState());
  state.dataset.frames = stats.frames;
}

// ---- interaction ------------------------------------------------------------------------
function pick(px, py) {
  let best = null, bestD = 12;
  for (const s of picture ? picture.sensors : []) {
    if (hidden.has(s.sensor)) continue;
    for (const t of s.tracks || []) {
      const d = Math.hypot(sx(t.x) - px, sy(t.y) - py);
      if (d < bestD) { bestD = d; best = { sensor: s.sensor, id: t.i }; }
    }
  }
  return best;
}

function showDetails() {
  if (!selected) { $('details').textContent = 'none selected'; return; }
  fetch(`api/track?sensor=${selected.sensor}&id=${selected.id}`).then((r) => r.ok ? r.json() : null).then((f) => {
    if (!f) { $('details').textContent = `track ${label(selected.id)}: not in the latest frame`; return; }
    const t = f.tracks[0];
    const lines = [`track ${label(t.id)} (sensor ${f.sensor}, scan ${f.scan})`, `status ${t.status}, ${t.kind}`,
      `position ${t.position.map((v) => v.toFixed(0)).join(', ')} m`, `velocity ${t.velocity.map((v) => v.toFixed(1)).join(', ')} m/s`,
      `speed ${Math.hypot(t.velocity[0], t.velocity[1]).toFixed(1)} m/s`];
    if (t.quality !== undefined) lines.push(`quality ${t.quality.toFixed(3)}`);
    if (t.modes) lines.push('modes ' + Object.entries(t.modes).map(([m, p]) => `${m} ${p.toFixed(2)}`).join(', '));
    if (t.members) lines.push(`members ${t.members}`);
    if (t.sources) lines.push('fuses ' + t.sources.map((s) => `${s.sensor}:${s.track}`).join(', '));
    lines.push('associations ' + (f.associations.map((a) => `plot ${a.plot} (${a.probability.toFixed(2)})`).join(', ') || 'none'));
    for (const e of f.events) lines.push(`event ${e.type} ${e.detail || ''}`);
    $('details').textContent = lines.join('\n');
  });
}

function setupInput() {
  let drag = null;
  canvas.addEventListener('mousedown', (e) => { drag = { x: e.offsetX, y: e.offsetY, moved: false }; });
  window.addEventListener('mouseup', (e) => {
    if (drag && !drag.moved && picture) { selected = pick(e.offsetX, e.offsetY); showDetails(); dirty = true; }
    drag = null;
  });
  canvas.addEventListener('mousemove', (e) => {
    if (!drag || !view) return;
    const dx = e.offsetX - drag.x, dy = e.offsetY - drag.y;
    if (Math.abs(dx) + Math.abs(dy) < 3 && !drag.moved) return;
    drag.moved = true; userMoved = true;
    view.cx -= dx / view.scale; view.cy += dy / view.scale;
    drag.x = e.offsetX; drag.y = e.offsetY; dirty = true;
  });
  canvas.addEventListener('wheel', (e) => {
    e.preventDefault();
    if (!view) return;
    userMoved = true;
    const k = Math.exp(-e.deltaY * 0.0015);
    const wx = view.cx + (e.offsetX - canvas.width / 2) / view.scale;
    const wy = view.cy - (e.offsetY - canvas.height / 2) / view.scale;
    view.scale *= k;
    view.cx = wx - (e.offsetX - canvas.width / 2) / view.scale;
    view.cy = wy + (e.offsetY - canvas.height / 2) / view.scale;
    dirty = true;
  }, { passive: false });
  canvas.addEventListener('dblclick', () => { userMoved = false; dirty = true; });
  for (const id of ['show-plots', 'show-trails', 'show-leaders', 'show-cov', 'show-tentative', 'show-truth']) {
    $(id).addEventListener('change', () => { dirty = true; });
  }
  const control = (cmd) => fetch(`api/control?cmd=${cmd}&rate=${$('rate').value}`, { method: 'POST' });
  for (const cmd of ['play', 'pause', 'step', 'restart']) $(cmd).onclick = () => control(cmd);
  $('rate').onchange = () => control('');
  window.addEventListener('resize', resize);
}

function reportLoop() {
  if (params.get('report') !== '1') return;
  setInterval(() => {
    writeState();
    fetch('api/page-state', { method: 'POST', body: JSON.stringify(pageState()) }).catch(() => {});
  }, 1000);
}

resize();
setupInput();
connect();
reportLoop();
setInterval(() => { if (picture) writeState(); }, 1000);
requestAnimationFrame(frameLoop);
