'use strict';
// The cell's live view. One server-sent event stream (/events, realtime/web/web_server.hpp)
// brings a `summary` every status period (COSMOS_STATUS, the pose-latency histogram, the
// belt's geometry and head profile) and a `part` for each pose as it goes out (the pose and
// the part's tile of the belt strip). On (re)connecting the server replays what it keeps, so
// the page rebuilds itself from the stream alone.

const view = {
  belt: null, // summary.belt
  status: null,
  recentPoses: 20,
  parts: new Map(), // part_seq -> {pose, tile, canvas, zScale}
  zScale: 1, // mm at the top of the colour ramp: the highest part kept
  head: { profile: -1, at: 0, rate: 0 }, // profiles per ms between summaries
};

// A viridis-like ramp from low (dark blue) to high (yellow).
const RAMP = [
  [0.0, [49, 54, 149]], [0.25, [59, 82, 139]], [0.5, [33, 145, 140]],
  [0.75, [94, 201, 98]], [1.0, [253, 231, 37]],
];
function rampColour(fraction) {
  const f = Math.min(1, Math.max(0, fraction));
  for (let i = 1; i < RAMP.length; i++) {
    if (f <= RAMP[i][0]) {
      const [f0, c0] = RAMP[i - 1];
      const [f1, c1] = RAMP[i];
      const t = (f - f0) / (f1 - f0);
      return c0.map((c, k) => Math.round(c + t * (c1[k] - c)));
    }
  }
  return RAMP[RAMP.length - 1][1];
}

// The tile as an image: heights on the ramp, the part's outline (its pixels next to a pixel
// that is not the part's) in white, or red when the part was not recognized.
function tileCanvas(tile, ok, zScale) {
  const levels = Uint8Array.from(atob(tile.levels_base64), (c) => c.charCodeAt(0));
  const w = tile.width_px;
  const h = tile.height_px;
  const canvas = document.createElement('canvas');
  canvas.width = w;
  canvas.height = h;
  const context = canvas.getContext('2d');
  const image = context.createImageData(w, h);
  const at = (x, y) => (x < 0 || y < 0 || x >= w || y >= h ? 0 : levels[y * w + x]);
  const outline = ok ? [255, 255, 255] : [242, 107, 91];
  for (let y = 0; y < h; y++) {
    for (let x = 0; x < w; x++) {
      const level = levels[y * w + x];
      if (!level) continue;
      const edge = !at(x - 1, y) || !at(x + 1, y) || !at(x, y - 1) || !at(x, y + 1);
      const rgb = edge ? outline : rampColour(((level - 1) / 254) * tile.z_max_mm / zScale);
      const i = 4 * (y * w + x);
      image.data.set([rgb[0], rgb[1], rgb[2], 255], i);
    }
  }
  context.putImageData(image, 0, 0);
  return canvas;
}

function currentHead() {
  const head = view.head;
  const elapsed = Math.min(performance.now() - head.at, 1500);
  return head.profile + head.rate * elapsed;
}

function stripLengthPx() {
  const b = view.belt;
  return Math.max(1, Math.round((b.strip_length_m * 1000) / b.mm_per_pixel));
}

function drawStrip() {
  const b = view.belt;
  if (!b || !b.width_px) return;
  const canvas = document.getElementById('strip-canvas');
  const length = stripLengthPx();
  if (canvas.width !== length || canvas.height !== b.width_px) {
    canvas.width = length;
    canvas.height = b.width_px;
    drawScale();
  }
  const context = canvas.getContext('2d');
  context.fillStyle = '#262b33';
  context.fillRect(0, 0, canvas.width, canvas.height);
  const step = tickStepM();
  context.fillStyle = '#323843';
  for (let m = step; m < b.strip_length_m; m += step) {
    context.fillRect(Math.round((m * 1000) / b.mm_per_pixel), 0, 1, canvas.height);
  }
  context.fillStyle = '#e04040'; // the laser sheet
  context.fillRect(0, 0, 2, canvas.height);

  const head = currentHead();
  const labels = document.getElementById('strip-labels');
  const shown = new Set();
  for (const [seq, part] of view.parts) {
    const tile = part.tile;
    if (!tile) continue;
    if (part.zScale !== view.zScale || !part.canvas) {
      part.canvas = tileCanvas(tile, part.pose.status === 'OK', view.zScale);
      part.zScale = view.zScale;
    }
    const left = (head - tile.last_profile) / b.decimation;
    if (left > length || left + tile.width_px < 0) continue;
    context.drawImage(part.canvas, Math.round(left), Math.round(tile.top_px));
    shown.add(seq);
    let label = labels.querySelector(`[data-seq="${seq}"]`);
    if (!label) {
      label = document.createElement('div');
      label.dataset.seq = seq;
      labels.appendChild(label);
    }
    label.className = 'strip-label' + (part.pose.status === 'OK' ? '' : ' rejected');
    label.textContent = part.pose.status === 'OK' ? part.pose.part_name : part.pose.status.toLowerCase();
    // Above the part, or below it for every other part, so neighbours' names do not collide;
    // kept inside the strip.
    const below = seq % 2 === 1;
    const half = label.offsetWidth / 2 / labels.clientWidth;
    const centre = (left + tile.width_px / 2) / length;
    label.style.left = `${Math.min(1 - half, Math.max(half, centre)) * 100}%`;
    const edge = below ? tile.top_px + tile.height_px : tile.top_px;
    label.style.top = `${(edge / b.width_px) * 100}%`;
    label.style.transform = below ? 'translate(-50%, 2px)' : 'translate(-50%, calc(-100% - 2px))';
  }
  for (const label of [...labels.children]) {
    if (!shown.has(Number(label.dataset.seq))) label.remove();
  }
}

function tickStepM() {
  const length = view.belt.strip_length_m;
  return length > 4 ? 1 : length > 1 ? 0.5 : 0.1;
}

function drawScale() {
  const scale = document.getElementById('strip-scale');
  scale.replaceChildren();
  const length = view.belt.strip_length_m;
  const step = tickStepM();
  for (let m = 0; m <= length + 1e-9; m += step) {
    const mark = document.createElement('span');
    mark.style.left = `${(m / length) * 100}%`;
    mark.textContent = `${+m.toFixed(1)} m`;
    if (m === 0) mark.style.transform = 'none';
    if (m + step > length + 1e-9) mark.style.transform = 'translateX(-100%)';
    scale.appendChild(mark);
  }
  document.getElementById('belt-caption').textContent =
    `last ${length} m behind the laser sheet (left), seen from above, ` +
    `${view.belt.mm_per_pixel} mm per pixel`;
}

function cell(row, text, className) {
  const td = document.createElement('td');
  td.textContent = text;
  if (className) td.className = className;
  row.appendChild(td);
}

function renderPoses() {
  const body = document.querySelector('#poses tbody');
  const rows = [...view.parts.values()]
    .map((p) => p.pose)
    .sort((a, b) => b.part_seq - a.part_seq)
    .slice(0, view.recentPoses);
  body.replaceChildren();
  for (const pose of rows) {
    const row = document.createElement('tr');
    row.dataset.seq = pose.part_seq;
    cell(row, pose.part_seq);
    cell(row, pose.status === 'OK' ? pose.part_name : pose.reason ? `- (${pose.reason})` : '-', 'name');
    cell(row, pose.status, `status ${pose.status}`);
    for (const v of pose.translation_mm) cell(row, v.toFixed(1));
    for (const v of pose.rotation_deg) cell(row, v.toFixed(1));
    cell(row, pose.score.toFixed(3));
    cell(row, pose.latency_ms.toFixed(1));
    cell(row, pose.encoder_ticks);
    body.appendChild(row);
  }
}

const BAD_WHEN_NONZERO = /dropped|overruns|rejected|failures|errors|timeouts/;

function renderStatus() {
  const status = view.status;
  const state = document.getElementById('state');
  state.textContent = status ? status.state : 'no status yet';
  state.className = `state ${status ? status.state : ''}`;
  document.getElementById('state-text').textContent = status ? status.state_text : '';
  const body = document.querySelector('#counters tbody');
  body.replaceChildren();
  if (!status) return;
  for (const [key, value] of Object.entries(status)) {
    if (key === 'state' || key === 'state_text') continue;
    const row = document.createElement('tr');
    if (BAD_WHEN_NONZERO.test(key) && value) row.className = 'nonzero-bad';
    cell(row, key);
    cell(row, Number.isInteger(value) ? value : Number(value).toFixed(1));
    body.appendChild(row);
  }
}

function renderHistogram(latency) {
  const histogram = document.getElementById('histogram');
  histogram.replaceChildren();
  const most = Math.max(1, ...latency.bins.map((b) => b.count));
  let lower = 0;
  for (const bin of latency.bins) {
    const row = document.createElement('div');
    row.className = 'bin';
    const edge = document.createElement('span');
    edge.className = 'edge';
    edge.textContent = bin.upper_ms === null ? `\u2265 ${lower} ms` : `${lower}\u2013${bin.upper_ms} ms`;
    const bar = document.createElement('span');
    bar.className = 'bar';
    bar.style.width = `${(bin.count / most) * 10}em`;
    const count = document.createElement('span');
    count.className = 'count';
    count.textContent = bin.count;
    row.append(edge, bar, count);
    histogram.appendChild(row);
    if (bin.upper_ms !== null) lower = bin.upper_ms;
  }
  document.getElementById('latency-caption').textContent =
    `end of part \u2192 pose published, ${latency.count} poses`;
}

// Parts leave the page once they are off the strip and out of the table.
function trimParts() {
  if (!view.belt) return;
  const newest = [...view.parts.keys()].sort((a, b) => b - a).slice(0, view.recentPoses);
  const keep = new Set(newest);
  const stripProfiles = (view.belt.strip_length_m * 1000) / view.belt.grid_mm;
  for (const [seq, part] of view.parts) {
    if (keep.has(seq)) continue;
    if (part.tile && currentHead() - part.tile.last_profile <= stripProfiles) continue;
    view.parts.delete(seq);
  }
}

function onSummary(summary) {
  const now = performance.now();
  const belt = summary.belt;
  const scanning = summary.status && summary.status.state === 'SCANNING';
  // The belt's speed from the head's advance between summaries; a summary sent for a new
  // part may repeat the head, which keeps the last speed.
  const head = view.head;
  if (belt.head_profile !== head.profile) {
    head.rate = scanning && head.profile >= 0 && belt.head_profile > head.profile
      ? (belt.head_profile - head.profile) / (now - head.at) : 0;
    head.profile = belt.head_profile;
    head.at = now;
  } else if (!scanning) {
    head.rate = 0;
  }
  const resized = !view.belt || view.belt.strip_length_m !== belt.strip_length_m;
  view.belt = belt;
  view.recentPoses = summary.recent_poses || view.recentPoses;
  view.status = summary.status;
  if (resized) drawScale();
  renderStatus();
  renderHistogram(summary.pose_latency_ms);
  trimParts();
  drawStrip();
}

function onPart(part) {
  view.parts.set(part.pose.part_seq, { pose: part.pose, tile: part.tile, canvas: null, zScale: 0 });
  if (part.tile && part.tile.z_max_mm > view.zScale) view.zScale = part.tile.z_max_mm;
  trimParts();
  renderPoses();
  drawStrip();
}

function connect() {
  const connection = document.getElementById('connection');
  const events = new EventSource('/events');
  events.addEventListener('open', () => {
    view.parts.clear(); // the server replays what it keeps
    connection.textContent = 'live';
    connection.className = 'connection live';
  });
  events.addEventListener('error', () => {
    connection.textContent = 'not connected: showing the last state received';
    connection.className = 'connection';
    view.head.rate = 0;
  });
  events.addEventListener('summary', (e) => onSummary(JSON.parse(e.data)));
  events.addEventListener('part', (e) => onPart(JSON.parse(e.data)));
}

connect();
setInterval(drawStrip, 100);
