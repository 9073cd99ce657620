// The live view's page: one EventSource (/events) carries every changed shm block of every robot;
// camera frames come as /camera/ID.jpg and /labels/ID.png. window.hrpView is for the tests.
'use strict';
const PALETTE = ['#ff2bd6', '#ffd60a', '#00e5ff', '#9b5de5', '#7cff4f', '#ff5c5c'];
const DEG = 180 / Math.PI;
const $ = id => document.getElementById(id);

function lighten(hex) {
  const n = parseInt(hex.slice(1), 16), m = c => Math.round(c + (255 - c) * 0.55);
  return `rgb(${m(n >> 16)},${m((n >> 8) & 255)},${m(n & 255)})`;
}
function toField(pose, x, y) {   // a robot-frame point to the field frame by pose [x, y, yaw]
  const c = Math.cos(pose[2]), s = Math.sin(pose[2]);
  return [pose[0] + c * x - s * y, pose[1] + s * x + c * y];
}
function quantile(a, q) {
  if (!a.length) return null;
  const s = [...a].sort((x, y) => x - y);
  return s[Math.min(s.length - 1, Math.floor(q * s.length))];
}
const esc = x => String(x).replace(/[&<>"]/g, c => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;' })[c]);
const fmt = (x, d = 2) => (x === null || x === undefined || !isFinite(x)) ? '–' : Number(x).toFixed(d);

const view = {
  ids: [], meta: null, sel: null, blocks: {}, field: null, plots: null, joint: 8,
  lat: { server: [], probe: [] }, lastProbe: {}, cpu: null, frames: 0, messages: 0,
  cam: { img: null, labels: null, info: null }, detections: [], walkTrail: [], dirty: true, connected: false,
};

function robotName(i) { return view.meta.config.robot.joints[i] ?? `joint ${i}`; }

function setupPlots() {
  view.plots = {
    joint: new Plot($('plot-joint'), '', [{ name: 'command', color: '#ffd60a' }, { name: 'position', color: '#4cc9f0' }]),
    imu: new Plot($('plot-imu'), 'torso (deg)', [{ name: 'roll', color: '#ff6b6b' }, { name: 'pitch', color: '#5fd38d' }]),
    ball: new Plot($('plot-ball'), 'ball range (m)', [{ name: 'seen', color: '#ff8c1a' }, { name: 'filtered', color: '#dfe3e8' }]),
    dcm: new Plot($('plot-dcm'), 'DCM jitter (ms)', [{ name: 'p50', color: '#5fd38d' }, { name: 'p99', color: '#ff6b6b' }]),
    feet: new Plot($('plot-feet'), 'feet (N)', [{ name: 'left', color: '#ff2bd6' }, { name: 'right', color: '#00e5ff' }]),
  };
  view.plots.joint.title = `${robotName(view.joint)} (rad)`;
}

function selectRobot(id) {
  view.sel = String(id);
  document.querySelectorAll('nav button').forEach(b => b.classList.toggle('sel', b.dataset.id === view.sel));
  Object.values(view.plots).forEach(p => p.clear());
  view.cam = { img: null, labels: null, info: null };
  view.detections = [];
  view.walkTrail = [];
  view.dirty = true;
}

function addSamples(rid, blk) {
  if (rid !== view.sel || !blk['dcm.sensor']) return;
  const b = view.blocks[rid], s = b['dcm.sensor'], t = s.time[0];
  if (blk.motion) keepWalk(blk.motion, t);
  const a = b['dcm.actuator'], v = b.vision, w = b.world, st = b['dcm.stats'];
  view.plots.joint.add(t, [a ? a.command[view.joint] : null, s.position[view.joint]]);
  view.plots.imu.add(t, [s.angle[0] * DEG, s.angle[1] * DEG]);
  const seen = v && v.ball_detected[0] && t - v.time[0] < 0.5 ? Math.hypot(v.ball_position[0], v.ball_position[1]) : null;
  view.plots.ball.add(t, [seen, w ? Math.hypot(w.ball[0], w.ball[1]) : null]);
  view.plots.feet.add(t, [s.foot_force[0], s.foot_force[1]]);
  view.plots.dcm.add(t, st ? [st.jitter_p50[0] * 1e3, st.jitter_p99[0] * 1e3] : [null, null]);
}

function onMessage(ev) {
  const msg = JSON.parse(ev.data), now = Date.now() / 1000;
  view.messages++;
  view.cpu = msg.cpu;
  view.lat.server.push(now - msg.wall);
  if (view.lat.server.length > 600) view.lat.server.shift();
  for (const [rid, blk] of Object.entries(msg.robots)) {
    const b = view.blocks[rid] = view.blocks[rid] || {};
    Object.assign(b, blk);
    // the latency probe: a writer stamps bench.t_send (CLOCK_MONOTONIC, as shm_now) and bumps bench.k
    if (blk.bench && blk.bench.k[0] !== view.lastProbe[rid]) {
      if (view.lastProbe[rid] !== undefined) {
        view.lat.probe.push((now - msg.wall) + (msg.mono - blk.bench.t_send[0]));
        if (view.lat.probe.length > 600) view.lat.probe.shift();
      }
      view.lastProbe[rid] = blk.bench.k[0];
    }
    if (rid === view.sel && blk.vision) keepDetection(blk.vision);
    if (rid === view.sel && blk.camera) loadCamera(rid, blk.camera);
    addSamples(rid, blk);
  }
  view.dirty = true;
}

// The vision's detections of the last frames: the one drawn over a camera frame is that frame's own
// (the vision block runs ahead of the frames shown).
function keepDetection(v) {
  view.detections.push(v);
  if (view.detections.length > 60) view.detections.shift();
}
function detectionFor(info) {
  let best = null;
  for (const v of view.detections) {
    if (v.frame[0] === info.frame) return v;
    if (Math.abs(v.time[0] - info.time) < 0.02 && (!best || Math.abs(v.time[0] - info.time) < Math.abs(best.time[0] - info.time))) best = v;
  }
  return best;
}

function loadCamera(rid, info) {
  const img = new Image(), labels = info.labels ? new Image() : null;
  let left = labels ? 2 : 1;
  const done = () => {
    if (--left > 0 || rid !== view.sel) return;
    view.cam = { img, labels, info }; view.frames++; view.dirty = true;
  };
  img.onload = done; img.onerror = () => {};
  img.src = `/camera/${rid}.jpg?f=${info.frame}`;
  if (labels) { labels.onload = done; labels.onerror = () => {}; labels.src = `/labels/${rid}.png?f=${info.frame}`; }
}

function robotsForField() {
  return view.ids.map((id, i) => {
    const b = view.blocks[String(id)] || {}, color = PALETTE[i % PALETTE.length];
    const r = { id, color, light: lighten(color) };
    if (b.sim) {
      r.truth = [b.sim.robot[0], b.sim.robot[1], b.sim.robot[3]];
      r.ballTruth = [b.sim.ball[0], b.sim.ball[1]];
    }
    const w = b.world, v = b.vision, s = b['dcm.sensor'];
    if (w && w.time[0] > 0) {
      r.belief = w.pose;
      if (w.particles && w.nparticles) r.particles = w.particles.slice(0, 3 * w.nparticles[0]);
      if (w.ball_time[0] >= 0) r.ballFiltered = toField(w.pose, w.ball[0], w.ball[1]);
      if (v && s && s.time[0] - v.time[0] < 0.5) {
        if (v.ball_detected[0]) r.ballSeen = toField(w.pose, v.ball_position[0], v.ball_position[1]);
        r.posts = [];
        for (let k = 0; k < v.goal_posts[0]; k++) r.posts.push(toField(w.pose, v.goal_position[2 * k], v.goal_position[2 * k + 1]));
      }
    }
    return r;
  });
}

function drawCamera() {
  const c = $('camera'), g = c.getContext('2d'), cam = view.cam;
  g.fillStyle = '#000'; g.fillRect(0, 0, c.width, c.height);
  if (!cam.img) { g.fillStyle = '#8a939e'; g.fillText('no camera frame yet', 10, 20); return; }
  g.drawImage(cam.img, 0, 0, c.width, c.height);
  if (cam.labels && $('show-labels').checked) {
    g.globalAlpha = 0.45; g.imageSmoothingEnabled = false;
    g.drawImage(cam.labels, 0, 0, c.width, c.height);
    g.globalAlpha = 1; g.imageSmoothingEnabled = true;
  }
  const v = detectionFor(cam.info), kx = c.width / cam.info.width, ky = c.height / cam.info.height;
  view.camBall = !!(v && v.ball_detected[0]);
  if (view.camBall) {
    g.strokeStyle = '#00e5ff'; g.lineWidth = 2; g.beginPath();
    g.arc(v.ball_image[0] * kx, v.ball_image[1] * ky, Math.max(6, v.ball_radius[0] * kx + 4), 0, 2 * Math.PI); g.stroke();
    const text = `ball ${fmt(Math.hypot(v.ball_position[0], v.ball_position[1]))} m`;
    g.font = '12px system-ui'; const tw = g.measureText(text).width;
    const tx = Math.min(c.width - tw - 6, v.ball_image[0] * kx + 10), ty = Math.max(16, v.ball_image[1] * ky - 10);
    g.fillStyle = 'rgba(0,0,0,0.6)'; g.fillRect(tx - 3, ty - 12, tw + 6, 16);
    g.fillStyle = '#00e5ff'; g.fillText(text, tx, ty);
  }
  $('cam-info').textContent = `frame ${cam.info.frame} · t ${fmt(cam.info.time)} s · head ${fmt(cam.info.head[0] * DEG, 0)}°/${fmt(cam.info.head[1] * DEG, 0)}°` +
    (v ? ` · vision ${fmt(v.fps[0], 1)} fps, posts ${v.goal_posts[0]}` : '');
}

function drawState() {
  const b = view.blocks[view.sel] || {}, S = view.meta.states;
  const name = (list, i) => (list && list[i] !== undefined) ? list[i] : '–';
  const rows = [];
  const group = (title, items) => rows.push(`<div class="card"><div class="group">${title}</div>` +
    items.map(([k, v]) => `<div class="row"><span>${k}</span><b>${v}</b></div>`).join('') + '</div>');
  const g = b.game, m = b.motion, w = b.world, s = b['dcm.sensor'], st = b['dcm.stats'], sim = b.sim;
  if (g) group('game', [['state', name(S.game, g.state[0]) + (g.penalized[0] ? ' (penalised)' : '')], ['role', name(S.role, g.role[0] - 1)],
    ['score', `${g.score[0]}:${g.score[1]}`], ['body', name(S.body, g.body_state[0])], ['head', name(S.head, g.head_state[0])], ['set play', g.setplay[0]]]);
  if (m) group('motion', [['state', name(S.motion, m.state[0])], ['walking', m.walking[0] ? 'yes' : 'no'], ['fallen', m.fallen[0] ? 'YES' : 'no'],
    ['velocity', m.walk_velocity.map(x => fmt(x)).join(' ')], ['falls', m.falls[0]], ['tick', m.tick[0]]]);
  if (w) group('world (belief)', [['pose', `${fmt(w.pose[0])} ${fmt(w.pose[1])} ${fmt(w.pose[2] * DEG, 0)}°`], ['confidence', fmt(w.pose_confidence[0])],
    ['ball', `${fmt(w.ball[0])} ${fmt(w.ball[1])}`], ['ball age', w.ball_time[0] >= 0 && s ? `${fmt(s.time[0] - w.ball_time[0], 1)} s` : '–'],
    ['particles', w.nparticles ? w.nparticles[0] : '–']]);
  if (sim) group('sim (truth)', [['pose', `${fmt(sim.robot[0])} ${fmt(sim.robot[1])} ${fmt(sim.robot[3] * DEG, 0)}°`], ['ball', `${fmt(sim.ball[0])} ${fmt(sim.ball[1])}`],
    ['fallen', sim.fallen[0] ? 'YES' : 'no'], ['pose error', w ? `${fmt(Math.hypot(w.pose[0] - sim.robot[0], w.pose[1] - sim.robot[1]))} m` : '–']]);
  if (st) group('DCM', [['rate', `${fmt(st.rate[0], 1)} Hz`], ['jitter p99', `${fmt(st.jitter_p99[0] * 1e3)} ms`], ['missed', st.missed_cycles[0]],
    ['watchdog', st.watchdog_trips[0]], ['NaN refused', st.nan_commands[0]], ['real time ×', fmt(st.realtime_factor[0])]]);
  if (s) group('sensor', [['time', `${fmt(s.time[0])} s`], ['tick', s.tick[0]], ['battery', `${fmt(s.battery[0], 1)} V`],
    ['gyro', s.gyro.map(x => fmt(x)).join(' ')], ['feet', s.foot_force.map(x => fmt(x, 0)).join(' ') + ' N']]);
  $('state').innerHTML = rows.join('');
}

function drawJoints() {
  const b = view.blocks[view.sel] || {}, s = b['dcm.sensor'], a = b['dcm.actuator'], cfg = view.meta.config.robot;
  if (!s) return;
  const rows = cfg.joints.map((j, i) => {
    const [lo, hi] = cfg.limits[j] || [-Math.PI, Math.PI], at = x => `${Math.max(0, Math.min(100, (x - lo) / (hi - lo) * 100))}%`;
    const cmd = a ? a.command[i] : null, pos = s.position[i], err = cmd === null ? null : (pos - cmd) * DEG;
    return `<div class="joint" data-i="${i}" title="click: plot it"><span>${j}</span><div class="bar">` +
      (cmd !== null ? `<i style="left:${at(cmd)}"></i>` : '') + `<b style="left:${at(pos)}"></b></div>` +
      `<span class="err${err !== null && Math.abs(err) > 5 ? ' big' : ''}">${fmt(err, 1)}°</span></div>`;
  });
  $('joints').innerHTML = rows.join('');
}

// The walk's plan in the torso frame (x forward: up the canvas): both feet (position and heading),
// the COM and the ZMP now and over the last 1.5 s (motion block: walk_feet, walk_com, walk_zmp, in the
// walk's ground frame, as odometry).
function keepWalk(m, t) {
  if (!m.walk_zmp) return;
  const h = view.walkTrail;
  if (h.length && t < h[h.length - 1].t) h.length = 0;
  h.push({ t, zmp: m.walk_zmp, com: m.walk_com });
  while (h.length && h[0].t < t - 1.5) h.shift();
}
function drawWalk() {
  const c = $('walk'), g = c.getContext('2d'), m = (view.blocks[view.sel] || {}).motion;
  g.fillStyle = '#181c22'; g.fillRect(0, 0, c.width, c.height);
  g.font = '11px system-ui'; g.fillStyle = '#8a939e';
  if (!m || !m.walk_zmp) { g.fillText('no walk fields in the motion block', 8, 20); return; }
  const o = m.odometry, co = Math.cos(o[2]), si = Math.sin(o[2]), S = 400;
  const px = p => {   // odometry frame -> torso frame -> canvas (forward up, left to the left)
    const dx = p[0] - o[0], dy = p[1] - o[1], x = co * dx + si * dy, y = -si * dx + co * dy;
    return [c.width / 2 - y * S, c.height / 2 - x * S];
  };
  g.strokeStyle = '#2c333c'; g.beginPath();
  g.moveTo(c.width / 2, 0); g.lineTo(c.width / 2, c.height); g.moveTo(0, c.height / 2); g.lineTo(c.width, c.height / 2); g.stroke();
  g.fillText('10 cm', 6, c.height - 6); g.fillRect(40, c.height - 10, 0.1 * S, 2);
  const trail = (key, color) => {
    g.strokeStyle = color; g.lineWidth = 1.2; g.beginPath();
    view.walkTrail.forEach((s, i) => { const [u, v] = px(s[key]); if (i) g.lineTo(u, v); else g.moveTo(u, v); });
    g.stroke();
  };
  trail('com', 'rgba(95,211,141,0.6)'); trail('zmp', 'rgba(255,107,107,0.6)');
  for (const f of [m.walk_feet.slice(0, 3), m.walk_feet.slice(3, 6)]) {   // a triangle pointing along the foot's heading
    const [u, v] = px(f), a = f[2] - o[2], fx = -Math.sin(a), fy = -Math.cos(a);
    g.fillStyle = '#ffd60a'; g.beginPath();
    g.moveTo(u + fx * 10, v + fy * 10); g.lineTo(u - fx * 6 - fy * 6, v - fy * 6 + fx * 6); g.lineTo(u - fx * 6 + fy * 6, v - fy * 6 - fx * 6);
    g.closePath(); g.fill();
  }
  const [cu, cv] = px(m.walk_com), [zu, zv] = px(m.walk_zmp);
  g.fillStyle = '#5fd38d'; g.beginPath(); g.arc(cu, cv, 4, 0, 2 * Math.PI); g.fill();
  g.strokeStyle = '#ff6b6b'; g.lineWidth = 2; g.beginPath();
  g.moveTo(zu - 4, zv - 4); g.lineTo(zu + 4, zv + 4); g.moveTo(zu + 4, zv - 4); g.lineTo(zu - 4, zv + 4); g.stroke();
}

// The whole-body controller (the wbc block, Player/Motion/wbc_link.lua): per task its level, error,
// feasibility, sigma_min and whether it is held; the controller's step time, the skill's state.
const WBC_KINDS = ['position', 'orientation', 'pose', 'com', 'com_xy', 'posture'];   // Modules/wbc/wbc.h
const WBC_UNIT = { position: 'mm', orientation: 'mrad', pose: 'mm|mrad', com: 'mm', com_xy: 'mm', posture: 'mrad RMS' };
function wbcTasks(x) {
  const out = [];
  for (let i = 0; i < Math.min(x.ntask[0], 16); i++) {
    out.push({ name: x.task_name.slice(i * 32, i * 32 + 32).replace(/\0.*$/s, ''), level: x.task_level[i],
      kind: WBC_KINDS[x.task_kind[i]] ?? '?', enabled: !!x.task_enabled[i], feasible: !!x.task_feasible[i],
      error: x.task_error[i], sigma: x.task_sigma[i], held: !!x.task_held[i] });
  }
  return out;
}
// a task's feasibility as shown: a posture fills whatever freedom is left (never met whole, not flagged)
function wbcFlag(t) {
  if (!t.enabled) return ['no target', 'rest'];
  if (t.kind === 'posture') return ['fills the rest', 'rest'];
  return t.feasible ? ['yes', 'yes'] : ['NO', 'no'];
}
function drawWbc() {
  const x = (view.blocks[view.sel] || {}).wbc, el = $('wbc');
  if (!x || !x.active || !x.active[0]) {
    $('wbc-info').textContent = 'not running (Motion.request(\'wbc\'))'; el.innerHTML = ''; return;
  }
  $('wbc-info').innerHTML = `<b class="${x.feasible[0] ? 'yes' : 'no'}">${x.feasible[0] ? 'feasible' : 'INFEASIBLE'}</b>` +
    ` · tick ${fmt(x.step_us[0], 0)} µs · skill ${esc(x.skill || 'default')}: ${esc(x.skill_state)} ${fmt(x.skill_time[0], 1)} s`;
  const rows = wbcTasks(x).sort((a, b) => a.level - b.level || a.name.localeCompare(b.name)).map(t =>
    `<tr data-task="${esc(t.name)}"${t.enabled ? '' : ' class="rest"'}><td>${esc(t.name)}</td><td>${esc(t.kind)}</td>` +
    `<td class="level">${t.level}</td><td class="error">${t.enabled ? fmt(t.error * 1e3, 1) : '–'}</td><td>${WBC_UNIT[t.kind] ?? ''}</td>` +
    `<td class="feasible ${wbcFlag(t)[1]}">${wbcFlag(t)[0]}</td>` +
    `<td>${fmt(t.sigma, 3)}</td><td>${t.held ? 'held' : ''}</td></tr>`);
  el.innerHTML = '<tr><th>task</th><th>kind</th><th>level</th><th>error</th><th></th><th>feasible</th><th>σ min</th><th></th></tr>' +
    rows.join('');
}

function drawRaw() {
  if (!$('raw-panel').open) return;
  const b = view.blocks[view.sel] || {};
  $('raw').innerHTML = Object.keys(b).sort().map(k => `<div class="blk"><b>${k}</b>` +
    Object.entries(b[k]).map(([f, v]) => `<div>${esc(f)}: ${Array.isArray(v) ? v.slice(0, 12).map(x => typeof x === 'number' && !Number.isInteger(x) ? x.toFixed(3) : x).join(' ') + (v.length > 12 ? ` … (${v.length})` : '') : esc(v)}</div>`).join('') + '</div>').join('');
}

function drawLink() {
  const p = view.lat.probe, sv = view.lat.server, ms = x => x === null ? '–' : (x * 1e3).toFixed(0);
  $('link').textContent = `server→page p50 ${ms(quantile(sv, 0.5))} ms` +
    (p.length ? ` · shm→page p50 ${ms(quantile(p, 0.5))} / p99 ${ms(quantile(p, 0.99))} ms` : '') +
    (view.cpu !== null ? ` · server CPU ${(view.cpu * 100).toFixed(0)}%` : '');
}

let lastDraw = 0, lastSlow = 0;
function frame(ts) {
  requestAnimationFrame(frame);
  if (!view.dirty || ts - lastDraw < 33) return;
  view.dirty = false; lastDraw = ts;
  view.field.draw(robotsForField());
  drawCamera();
  Object.values(view.plots).forEach(p => p.draw());
  drawWalk();
  if (ts - lastSlow > 250) {   // text panels: 4 Hz is enough to read
    lastSlow = ts;
    drawState(); drawJoints(); drawWbc(); drawRaw(); drawLink();
  }
}

function connect() {
  const es = new EventSource('/events');
  es.onopen = () => { view.connected = true; $('status').textContent = 'live'; $('status').className = 'ok'; };
  es.onerror = () => { view.connected = false; $('status').textContent = 'reconnecting…'; $('status').className = 'bad'; };
  es.onmessage = onMessage;
}

async function start() {
  const m = await (await fetch('/meta.json')).json();
  view.ids = m.ids; view.meta = m.meta;
  const f = Object.assign({}, view.meta.config.behavior.world.field, (view.meta.config.sim || {}).field || {});
  view.field = new FieldView($('field'), f);
  setupPlots();
  const nav = $('robots');
  view.ids.forEach((id, i) => {
    const b = document.createElement('button');
    b.textContent = `robot ${id}`; b.dataset.id = String(id); b.style.color = PALETTE[i % PALETTE.length];
    b.onclick = () => selectRobot(id);
    nav.appendChild(b);
  });
  $('joints').onclick = e => {
    const row = e.target.closest('.joint');
    if (!row) return;
    view.joint = Number(row.dataset.i); view.plots.joint.clear(); view.plots.joint.title = `${robotName(view.joint)} (rad)`;
  };
  $('show-labels').onchange = () => { view.dirty = true; };
  selectRobot(view.ids[0]);
  connect();
  requestAnimationFrame(frame);
}

window.hrpView = {
  geometry: () => view.field && view.field.geometry(),
  latency: () => ({ server: view.lat.server.slice(), probe: view.lat.probe.slice() }),
  resetLatency: () => { view.lat = { server: [], probe: [] }; },
  status: () => ({ connected: view.connected, messages: view.messages, frames: view.frames, cpu: view.cpu, camBall: !!view.camBall,
    robots: Object.keys(view.blocks) }),
  // the wbc block the page holds and the tasks in it (null: none)
  wbc: () => { const x = (view.blocks[view.sel] || {}).wbc; return x ? { tick: x.tick[0], active: x.active[0], tasks: wbcTasks(x) } : null; },
  truth: () => { const s = (view.blocks[view.sel] || {}).sim; return s ? [s.robot[0], s.robot[1], s.robot[3]] : null; },
};
start();
