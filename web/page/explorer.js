// The explorer page (docs/explorer.md): every number comes from the library
// built to WebAssembly (web/explorer_api.cpp); this script only draws and
// wires the controls. Errors from the library arrive as {"error": message}
// and are shown in #message; the page keeps its last good state.
'use strict';

(function () {
  const $ = (id) => document.getElementById(id);
  const state = {
    api: null, info: null,
    pattern: null,      // the pattern file's JSON (docs/pattern-format.md)
    catalogName: null,  // while the pattern is an unedited catalog pattern
    objective: 'recommended',
    evaluation: null,
    drag: null,
    kernel: 0,
    worker: null, optimizing: false,
    sequence: null, frame: 0, playTimer: null,
  };
  // What the browser test and the benchmarks read (docs/benchmarks.md).
  const stats = window.aapatStats = {
    ready: false, dragLatencyMs: [], frameLatencyMs: [], optimizeSeconds: null, updates: 0,
  };

  // ---- messages and calls into the library --------------------------------
  function showMessage(text) {
    const m = $('message');
    m.textContent = text || '';
    m.hidden = !text;
  }
  // The library's answer as it is, {"error": ...} included.
  function ask(name, request) {
    return JSON.parse(state.api[name](JSON.stringify(request)));
  }
  // The answer, or null with its error shown.
  function call(name, request) {
    const doc = ask(name, request);
    if (doc.error) {
      showMessage(doc.error);
      return null;
    }
    return doc;
  }
  // Every handler runs guarded: a bug shows in the page as well as the console.
  function on(element, event, handler) {
    element.addEventListener(event, (e) => {
      try {
        handler(e);
      } catch (err) {
        showMessage('explorer: ' + err.message);
        throw err;
      }
    });
  }

  // ---- loading the module ---------------------------------------------------
  function moduleSource() {
    const b64 = $('module-source').textContent.trim();
    const bytes = Uint8Array.from(atob(b64), (c) => c.charCodeAt(0));
    return new TextDecoder().decode(bytes);
  }

  // The optimization worker: the same module, in a worker made from a blob,
  // so the page works from a file with no server.
  function workerMain() {
    const ready = createAapatModule();
    onmessage = (e) => {
      ready.then((m) => {
        const t0 = performance.now();
        const text = m.optimize(JSON.stringify(e.data), (done, total, note) => {
          postMessage({ progress: [done, total, note] });
        });
        postMessage({ result: text, seconds: (performance.now() - t0) / 1000 });
      });
    };
  }

  // ---- the objective -------------------------------------------------------
  function objectiveText() {
    if ($('objective').value !== 'custom') return $('objective').value;
    return `filter=${$('filter').value} acuity=${$('acuity').value.trim()} norm=${$('norm').value.trim()}`;
  }

  // ---- drawing the pattern --------------------------------------------------
  function setIndex(tx, ty) {
    const [w, h] = state.pattern.tile;
    return (((ty % h) + h) % h) * w + (((tx % w) + w) % w);
  }
  function geometry() {
    const c = $('pattern-canvas');
    const [w, h] = state.pattern.tile;
    const s = c.width / (Math.max(w, h) + 2);
    return {
      s, w, h,
      X: (wx) => (wx + 1) * s,
      Y: (wy) => (h + 1 - wy) * s,
      world: (px, py) => [px / s - 1, h + 1 - py / s],
    };
  }
  // The weight a set's sample has in its own pixel's kernel (1-pixel footprints).
  function sampleWeight(set, i) {
    const p = state.pattern;
    if (p.footprint === '1' || p.footprint === '1+') return p.kernels[set][i];
    return 1 / p.sets[set].length;
  }
  function drawPattern() {
    const c = $('pattern-canvas');
    const g = c.getContext('2d');
    const { s, w, h, X, Y } = geometry();
    g.clearRect(0, 0, c.width, c.height);
    for (let ty = -1; ty <= h; ++ty) {
      for (let tx = -1; tx <= w; ++tx) {
        const inside = tx >= 0 && ty >= 0 && tx < w && ty < h;
        g.fillStyle = inside ? '#fff' : '#f1f1f1';
        g.fillRect(X(tx), Y(ty + 1), s, s);
        g.strokeStyle = '#bbb';
        g.strokeRect(X(tx), Y(ty + 1), s, s);
      }
    }
    if ($('lattice').checked && s / 16 >= 4) {
      g.strokeStyle = '#eef';
      g.beginPath();
      for (let k = -16; k <= 16 * (Math.max(w, h) + 1); ++k) {
        g.moveTo(k * s / 16 + s, 0); g.lineTo(k * s / 16 + s, c.height);
        g.moveTo(0, k * s / 16 + s); g.lineTo(c.width, k * s / 16 + s);
      }
      g.stroke();
    }
    g.strokeStyle = '#223';
    g.lineWidth = 2;
    g.strokeRect(X(0), Y(h), w * s, h * s);
    g.lineWidth = 1;
    for (let ty = -1; ty <= h; ++ty) {
      for (let tx = -1; tx <= w; ++tx) {
        const inside = tx >= 0 && ty >= 0 && tx < w && ty < h;
        const set = setIndex(tx, ty);
        const samples = state.pattern.sets[set];
        samples.forEach(([x, y], i) => {
          const wt = sampleWeight(set, i);
          const r = Math.max(2.5, Math.sqrt(Math.abs(wt) * samples.length) * s * 0.045);
          g.beginPath();
          g.arc(X(tx + 0.5 + x), Y(ty + 0.5 + y), r, 0, 2 * Math.PI);
          if (wt < 0) {
            g.strokeStyle = inside ? '#c22' : '#d99';
            g.stroke();
          } else {
            g.fillStyle = inside ? (set === state.kernel ? '#1a5fc0' : '#4f86d9') : '#a8bcd6';
            g.fill();
          }
        });
      }
    }
  }

  function drawPolar(e) {
    const c = $('polar');
    const g = c.getContext('2d');
    const cx = c.width / 2, cy = c.height / 2, R = c.width / 2 - 14;
    g.clearRect(0, 0, c.width, c.height);
    g.strokeStyle = '#ddd';
    for (const f of [0.5, 1]) { g.beginPath(); g.arc(cx, cy, R * f, 0, 2 * Math.PI); g.stroke(); }
    const angles = e.angles_deg, values = e.profile;
    const max = Math.max(...values, 1e-12);
    const pt = (deg, v) => [cx + R * (v / max) * Math.cos(deg * Math.PI / 180),
      cy - R * (v / max) * Math.sin(deg * Math.PI / 180)];
    g.strokeStyle = '#1a5fc0';
    g.fillStyle = '#1a5fc0';
    if (angles.length > 8) {
      g.beginPath();
      for (const half of [0, 180]) {
        angles.forEach((a, i) => {
          const [x, y] = pt(a + half, values[i]);
          if (half === 0 && i === 0) g.moveTo(x, y); else g.lineTo(x, y);
        });
      }
      g.closePath();
      g.stroke();
    } else {
      angles.forEach((a, i) => {
        for (const half of [0, 180]) {
          const [x, y] = pt(a + half, values[i]);
          g.beginPath(); g.moveTo(cx, cy); g.lineTo(x, y); g.stroke();
          g.beginPath(); g.arc(x, y, 3, 0, 2 * Math.PI); g.fill();
        }
      });
    }
    const worst = e.eval.rows[0].worst_angle_deg;
    g.strokeStyle = '#c22';
    g.setLineDash([4, 3]);
    g.beginPath();
    g.moveTo(...pt(worst + 180, max)); g.lineTo(...pt(worst, max));
    g.stroke();
    g.setLineDash([]);
    g.fillStyle = '#555';
    g.font = '11px sans-serif';
    g.fillText('W·E1(θ), worst kernel', 4, 12);
  }

  function drawGrey(canvasId, width, height, value) {
    const off = document.createElement('canvas');
    off.width = width; off.height = height;
    const og = off.getContext('2d');
    const img = og.createImageData(width, height);
    for (let j = 0; j < height; ++j) {
      for (let i = 0; i < width; ++i) {
        const rgb = value((height - 1 - j) * width + i);  // rows from the bottom
        const o = 4 * (j * width + i);
        img.data[o] = rgb[0]; img.data[o + 1] = rgb[1]; img.data[o + 2] = rgb[2]; img.data[o + 3] = 255;
      }
    }
    og.putImageData(img, 0, 0);
    const c = $(canvasId), g = c.getContext('2d');
    g.imageSmoothingEnabled = false;
    g.drawImage(off, 0, 0, c.width, c.height);
  }

  function sceneSpec() {
    const v = $('scene').value;
    if (!v.startsWith('halfplane')) return v;
    return `halfplane:angle=${Number($('edge-angle').value)},offset=0`;
  }

  function renderView() {
    const r = call('render', { pattern: state.pattern, scene: sceneSpec(), size: 64, reference_samples: 256 });
    if (!r) return;
    const level = (v) => Math.max(0, Math.min(255, Math.round(255 * v)));
    drawGrey('render-image', r.width, r.height, (k) => { const l = level(r.image[k]); return [l, l, l]; });
    drawGrey('render-error', r.width, r.height, (k) => {
      const d = Math.min(255, Math.round(4 * 255 * Math.abs(r.image[k] - r.reference_image[k])));
      return [255, 255 - d, 255 - d];
    });
    $('rmse').textContent = r.rmse.toFixed(3);
    $('flip').textContent = r.flip.toFixed(4);
    $('reference').textContent = `(against ${r.reference}; error ×4)`;
  }

  // ---- weights --------------------------------------------------------------
  function drawWeights() {
    const p = state.pattern;
    const kernels = p.kernels.length;
    const sel = $('kernel');
    if (sel.options.length !== kernels) {
      sel.innerHTML = '';
      for (let k = 0; k < kernels; ++k) sel.add(new Option(String(k), String(k)));
    }
    state.kernel = Math.min(state.kernel, kernels - 1);
    sel.value = String(state.kernel);
    const box = $('weights');
    box.innerHTML = '';
    p.kernels[state.kernel].forEach((w, i) => {
      const label = document.createElement('label');
      label.textContent = `w${i} `;
      const input = document.createElement('input');
      input.type = 'text';
      input.value = String(Number(w.toPrecision(6)));
      input.dataset.index = String(i);
      label.appendChild(input);
      box.appendChild(label);
    });
  }

  // ---- the update after any change -----------------------------------------
  function evaluateNow() {
    const e = call('evaluate', { pattern: state.pattern, objective: objectiveText() });
    if (!e) {  // an objective that does not parse: no number rather than a stale one
      $('e2').textContent = '—';
      $('e2').dataset.value = '';
      return false;
    }
    state.evaluation = e;
    $('perceptual').textContent = '—';  // on request: it renders its charts
    $('perceptual').dataset.value = '';
    const row = e.eval.rows[0];
    $('e2').textContent = row.e2.toFixed(4);
    $('e2').dataset.value = String(row.e2);
    $('worst-angle').textContent = String(row.worst_angle_deg);
    $('family').textContent = row.family;
    $('cost').textContent = String(row.n);
    $('objective-caption').textContent = e.caption;
    drawPolar(e);
    return true;
  }
  function update(options) {
    const quick = options && options.quick;
    drawPattern();
    if (!evaluateNow()) return;
    renderView();
    if (!quick) {
      drawWeights();
      refreshExport();
      // A comparison shown is kept current: every change to the pattern or
      // the objective (an optimization's result included) redraws it.
      if ($('compare-table').rows.length > 0) compare();
      writeHash();
    }
    stats.updates += 1;
  }
  // The export profile: the one chosen if it can take the pattern, else the
  // first that can (FLIPQUAD's shared samples need a 2x2 grid: not tier 1).
  function fitExportProfile(pattern) {
    const fits = (api) => !ask('exportText', { pattern, api, snap: true, objective: objectiveText() }).error;
    if (fits($('api').value)) return;
    const first = [...$('api').options].map((o) => o.value).find(fits);
    if (first) $('api').value = first;
  }
  function setPattern(pattern, catalogName) {
    fitExportProfile(pattern);
    state.pattern = pattern;
    state.catalogName = catalogName || null;
    $('catalog').value = catalogName && [...$('catalog').options].some((o) => o.value === catalogName)
      ? catalogName : '';
    update();
  }
  function loadByName(name) {
    const d = call('loadPattern', { name });
    if (d) { showMessage(''); setPattern(d.pattern, name); }
    return !!d;
  }

  // ---- dragging -------------------------------------------------------------
  function canvasPoint(e) {
    const c = $('pattern-canvas');
    const b = c.getBoundingClientRect();
    return [(e.clientX - b.left) * c.width / b.width, (e.clientY - b.top) * c.height / b.height];
  }
  function pick(px, py) {
    const { w, h, X, Y } = geometry();
    let best = null, bestD = 14 * 14;
    for (let ty = -1; ty <= h; ++ty) {
      for (let tx = -1; tx <= w; ++tx) {
        const set = setIndex(tx, ty);
        state.pattern.sets[set].forEach(([x, y], index) => {
          const dx = X(tx + 0.5 + x) - px, dy = Y(ty + 0.5 + y) - py;
          if (dx * dx + dy * dy < bestD) { bestD = dx * dx + dy * dy; best = { set, index, tx, ty }; }
        });
      }
    }
    return best;
  }
  function dragTo(e) {
    const t0 = performance.now();
    const { world } = geometry();
    const [wx, wy] = world(...canvasPoint(e));
    const d = state.drag;
    const moved = call('moveSample', {
      pattern: d.base, set: d.set, index: d.index,
      x: wx - (d.tx + 0.5), y: wy - (d.ty + 0.5), lattice: $('lattice').checked,
    });
    if (!moved) return;
    showMessage('');
    state.pattern = moved.pattern;
    state.catalogName = null;
    $('catalog').value = '';
    update({ quick: true });
    const t1 = performance.now();
    stats.dragLatencyMs.push(t1 - t0);
    requestAnimationFrame(() => {
      const t2 = performance.now();
      stats.frameLatencyMs.push(t2 - t0);
      $('latency').textContent = `update ${(t1 - t0).toFixed(1)} ms`;
    });
  }

  // ---- the link ------------------------------------------------------------
  const kHashKeys = ['pattern', 'design', 'objective', 'tab', 'scene'];
  function writeHash() {
    const q = new URLSearchParams();
    if (state.catalogName) {
      q.set('pattern', state.catalogName);
    } else {
      const p = state.pattern;
      q.set('design', JSON.stringify({ name: p.name, tile: p.tile, footprint: p.footprint, sets: p.sets, kernels: p.kernels }));
    }
    if (objectiveText() !== state.info.default_objective) q.set('objective', objectiveText());
    const tab = document.querySelector('.tab.active').dataset.tab;
    if (tab !== 'pattern') q.set('tab', tab);
    if (sceneSpec() !== 'halfplane:angle=30,offset=0') q.set('scene', sceneSpec());
    const link = q.toString();
    if (link.length > state.info.limits.link_bytes) {
      // Past what a browser opens: the link keeps the rest, the design goes to a file.
      q.delete('design');
      history.replaceState(null, '', '#' + q.toString());
      showMessage(`this design's link would be ${link.length} characters, past the limit of ` +
        `${state.info.limits.link_bytes} (docs/limits.md): save it as a file to share it`);
      return;
    }
    history.replaceState(null, '', '#' + link);
  }
  // Sets the objective controls from the library's reading of an objective
  // (readLink's objective_json): a registered name, or its three components.
  function setObjective(parsed) {
    const names = state.info.objectives.map((o) => o.name);
    if (names.includes(parsed.objective)) {
      $('objective').value = parsed.objective;
      $('custom-objective').hidden = true;
      return;
    }
    $('objective').value = 'custom';
    $('custom-objective').hidden = false;
    if (![...$('filter').options].some((o) => o.value === parsed.filter)) {
      $('filter').add(new Option(parsed.filter, parsed.filter));
    }
    $('filter').value = parsed.filter;
    $('acuity').value = parsed.acuity;
    $('norm').value = parsed.norm;
  }
  // Returns false (with the message shown) when the link does not parse.
  function readHash() {
    const text = location.hash.replace(/^#/, '');
    if (!text) return false;
    const limit = state.info.limits.link_bytes;
    if (text.length > limit) {
      showMessage(`link: ${text.length} characters, past the limit of ${limit} (docs/limits.md); open the design as a file`);
      return false;
    }
    let q;
    try {
      q = new URLSearchParams(text);
    } catch (err) {
      showMessage(`link: '${text}' does not parse`);
      return false;
    }
    const seen = new Set();
    for (const key of q.keys()) {
      if (!kHashKeys.includes(key)) {
        showMessage(`link: unknown key '${key}' (known: ${kHashKeys.join(', ')})`);
        return false;
      }
      if (seen.has(key)) {
        showMessage(`link: '${key}' is given more than once`);
        return false;
      }
      seen.add(key);
    }
    // The objective and the scene are read by the library's parsers (the
    // CLI's), never split here: what the page writes, it reads back.
    const request = {};
    if (q.has('objective')) request.objective = q.get('objective');
    if (q.has('scene')) request.scene = q.get('scene');
    const parsed = ask('readLink', request);
    if (parsed.error) {
      showMessage(`link: ${parsed.error}`);
      return false;
    }
    if (parsed.objective) setObjective(parsed.objective);
    if (q.has('scene')) {
      const s = q.get('scene');
      if (parsed.scene_name === 'halfplane' && parsed.offset === 0) {
        $('scene').value = 'halfplane:angle=30,offset=0';
        $('edge-angle').value = String(parsed.angle);
      } else if ([...$('scene').options].some((o) => o.value === s)) {
        $('scene').value = s;
      } else {
        showMessage(`link: scene '${s}' is not one of the page's views`);
        return false;
      }
    }
    if (q.has('tab')) selectTab(q.get('tab'));
    if (q.has('pattern')) {
      const d = ask('loadPattern', { name: q.get('pattern') });
      if (d.error) {
        showMessage(`link: ${d.error}`);
        return false;
      }
      setPattern(d.pattern, q.get('pattern'));
      return true;
    }
    if (q.has('design')) {
      let design;
      try {
        design = JSON.parse(q.get('design'));
      } catch (err) {
        showMessage('link: the design is not valid JSON');
        return false;
      }
      if (typeof design !== 'object' || design === null || Array.isArray(design)) {
        showMessage('link: the design is not a JSON object');
        return false;
      }
      const doc = Object.assign({ format: 'aapat-pattern', version: 1, name: 'linked' }, design);
      const d = call('loadPattern', { text: JSON.stringify(doc), source: 'link' });
      if (!d) return false;
      setPattern(d.pattern, null);
      return true;
    }
    return false;
  }

  // ---- export, files, compare -----------------------------------------------
  function refreshExport() {
    const d = ask('exportText', {
      pattern: state.pattern, api: $('api').value, shader: $('shader').value,
      snap: $('export-snap').checked, objective: objectiveText(),
    });
    $('export-text').value = d.error ? `(not exportable: ${d.error})` : d.text;
  }
  function download(name, text) {
    const a = document.createElement('a');
    a.href = URL.createObjectURL(new Blob([text], { type: 'text/plain' }));
    a.download = name;
    a.click();
    setTimeout(() => URL.revokeObjectURL(a.href), 1000);
  }
  function compare() {
    const table = $('compare-table');
    const names = [...$('compare-select').selectedOptions].map((o) => o.value);
    const rows = [['this pattern', state.pattern]].concat(names.map((n) => [n, n]));
    let html = '<tr><th>pattern</th><th>family</th><th>n</th><th>E2</th><th>worst °</th></tr>';
    for (const [label, pattern] of rows) {
      const e = call('evaluate', { pattern, objective: objectiveText() });
      if (!e) continue;
      const r = e.eval.rows[0];
      html += `<tr><td>${label === 'this pattern' ? 'this pattern' : r.pattern}</td><td>${r.family}</td>` +
        `<td>${r.n}</td><td>${r.e2.toFixed(4)}</td><td>${r.worst_angle_deg}</td></tr>`;
    }
    table.innerHTML = html;
  }

  // ---- optimize ------------------------------------------------------------
  function optimizeRequest() {
    const r = {
      objective: objectiveText(), starts: Number($('opt-starts').value),
      seed: Number($('opt-seed').value), method: $('opt-method').value,
    };
    if ($('opt-mode').value === 'polish') r.pattern = state.pattern; else r.family = $('opt-family').value.trim();
    return r;
  }
  function stopWorker() {
    if (state.worker) state.worker.terminate();
    state.worker = null;
    state.optimizing = false;
    $('opt-run').disabled = false;
    $('opt-cancel').disabled = true;
  }
  function runOptimize() {
    stopWorker();
    const src = state.moduleSource + '\n;(' + workerMain.toString() + ')();';
    const url = URL.createObjectURL(new Blob([src], { type: 'text/javascript' }));
    state.worker = new Worker(url);
    URL.revokeObjectURL(url);
    state.optimizing = true;
    $('opt-run').disabled = true;
    $('opt-cancel').disabled = false;
    $('opt-progress').value = 0;
    $('opt-status').textContent = 'starting…';
    const started = performance.now();
    state.worker.onmessage = (e) => {
      try {
        if (e.data.progress) {
          const [done, total, note] = e.data.progress;
          $('opt-progress').max = total; $('opt-progress').value = done;
          $('opt-status').textContent = `${done} of ${total} ${note || ''}`;
          return;
        }
        const doc = JSON.parse(e.data.result);
        stopWorker();
        if (doc.error) { showMessage(doc.error); $('opt-status').textContent = 'failed'; return; }
        stats.optimizeSeconds = e.data.seconds;
        stats.optimizeWallSeconds = (performance.now() - started) / 1000;
        const rep = doc.report;
        $('opt-progress').value = $('opt-progress').max;
        $('opt-status').textContent = `done in ${e.data.seconds.toFixed(1)} s: ${rep.description || ''} E2 ${Number(rep.e2).toFixed(4)}`;
        $('opt-status').dataset.e2 = String(rep.e2);
        setPattern(doc.pattern, null);
      } catch (err) {
        showMessage('explorer: ' + err.message);
      }
    };
    state.worker.onerror = (e) => { stopWorker(); showMessage('optimizer worker: ' + e.message); };
    state.worker.postMessage(optimizeRequest());
  }

  // ---- point sets ------------------------------------------------------------
  function runPoints() {
    const d = call('points', {
      generator: $('generator').value.trim(), n: Number($('points-n').value),
      seed: Number($('points-seed').value), spectrum_size: 128,
    });
    if (!d) return;
    showMessage('');
    const c = $('points-canvas'), g = c.getContext('2d');
    g.clearRect(0, 0, c.width, c.height);
    g.fillStyle = '#1a5fc0';
    const r = Math.max(1, Math.min(3, 60 / Math.sqrt(d.points.length)));
    for (const [x, y] of d.points) { g.beginPath(); g.arc(x * c.width, (1 - y) * c.height, r, 0, 2 * Math.PI); g.fill(); }
    const n = d.spectrum.size, pw = d.spectrum.power;
    const logs = pw.map((v) => Math.log10(Math.max(v, 1e-6)));
    const lo = -1, hi = 1;  // power 0.1 .. 10 (1 is white noise)
    drawGrey('spectrum-canvas', n, n, (k) => {
      const l = Math.round(255 * Math.min(1, Math.max(0, (logs[k] - lo) / (hi - lo))));
      return [l, l, l];
    });
    const rc = $('radial-canvas'), rg = rc.getContext('2d');
    rg.clearRect(0, 0, rc.width, rc.height);
    const rad = d.radial.radius.slice(1), pr = d.radial.power.slice(1);
    const maxP = Math.max(2, ...pr), maxR = Math.max(...rad);
    rg.strokeStyle = '#ccc';
    rg.beginPath(); rg.moveTo(0, rc.height * (1 - 1 / maxP)); rg.lineTo(rc.width, rc.height * (1 - 1 / maxP)); rg.stroke();
    rg.strokeStyle = '#1a5fc0';
    rg.beginPath();
    rad.forEach((f, i) => {
      const x = f / maxR * rc.width, y = rc.height * (1 - pr[i] / maxP);
      if (i === 0) rg.moveTo(x, y); else rg.lineTo(x, y);
    });
    rg.stroke();
    rg.fillStyle = '#555'; rg.font = '11px sans-serif';
    rg.fillText('radial average (grey line: power 1)', 4, 12);
    let html = '';
    for (const [k, v] of Object.entries(d.discrepancy)) {
      if (k === 'command' || k === 'schema') continue;
      html += `<tr><td>${k}</td><td>${typeof v === 'number' && !Number.isInteger(v) ? v.toPrecision(6) : v}</td></tr>`;
    }
    $('discrepancy-table').innerHTML = html;
  }

  // ---- sequences --------------------------------------------------------------
  function runSequence() {
    const model = $('model').value;
    const d = call('sequence', {
      sequence: $('sequence').value.trim(), model, alpha: Number($('alpha').value), objective: objectiveText(),
    });
    if (!d) return;
    showMessage('');
    state.sequence = d;
    state.frame = 0;
    $('frame').max = String(d.frames.length - 1);
    $('frame').value = '0';
    const rep = d.report;
    let html = '';
    for (const k of ['sequence', 'frames', 'family', 'worst_e2', 'mean_e2', 'flicker', 'worst_flicker', 'settle_frame']) {
      if (!(k in rep)) continue;
      const v = rep[k];
      html += `<tr><td>${k}</td><td>${typeof v === 'number' && !Number.isInteger(v) ? v.toFixed(4) : v}</td></tr>`;
    }
    $('sequence-table').innerHTML = html;
    drawSequencePlot();
    drawSequence();
  }
  function drawSequence() {
    const d = state.sequence;
    if (!d) return;
    const c = $('sequence-canvas'), g = c.getContext('2d');
    const s = c.width * 0.8, o = c.width * 0.1;
    const X = (x) => o + (x + 0.5) * s, Y = (y) => o + (0.5 - y) * s;
    g.clearRect(0, 0, c.width, c.height);
    g.strokeStyle = '#223'; g.strokeRect(o, o, s, s);
    const K = d.frames.length, f = state.frame;
    const alpha = Number($('alpha').value), ema = $('model').value === 'ema';
    // The accumulated kernel at frame f: frame f - k weighs alpha (1 - alpha)^k
    // (EMA, summed over periods) or 1/K (box).
    for (let k = 0; k < K; ++k) {
      const frame = d.frames[((f - k) % K + K) % K];
      const wFrame = ema ? alpha * Math.pow(1 - alpha, k) / (1 - Math.pow(1 - alpha, K)) : 1 / K;
      for (const [x, y, w] of frame) {
        g.beginPath();
        g.arc(X(x), Y(y), Math.max(2, Math.sqrt(Math.abs(w * wFrame)) * s * 0.12), 0, 2 * Math.PI);
        g.fillStyle = k === 0 ? '#c22' : 'rgba(26,95,192,0.55)';
        g.fill();
      }
    }
    $('frame-number').textContent = String(f);
  }
  function drawSequencePlot() {
    const rep = state.sequence.report;
    const c = $('sequence-plot'), g = c.getContext('2d');
    g.clearRect(0, 0, c.width, c.height);
    const e2 = rep.steady_e2 || [], fl = rep.flicker_per_transition || [];
    const max = Math.max(...e2, ...fl, 1e-9) * 1.1;
    const bw = c.width / Math.max(1, e2.length);
    g.fillStyle = 'rgba(200,40,40,0.35)';
    fl.forEach((v, i) => g.fillRect(i * bw + bw * 0.2, c.height * (1 - v / max), bw * 0.6, c.height * v / max));
    g.strokeStyle = '#1a5fc0';
    g.beginPath();
    e2.forEach((v, i) => { const x = (i + 0.5) * bw, y = c.height * (1 - v / max); if (i) g.lineTo(x, y); else g.moveTo(x, y); });
    g.stroke();
    g.fillStyle = '#555'; g.font = '11px sans-serif';
    g.fillText('line: steady E2 per frame; bars: flicker into each frame', 4, 12);
  }

  // The sequence against a baseline under an engine preset: the library's
  // document of `aapat sequence compare --json`; per measure, the scenes where
  // the sequence is lower, the ratio of the means and the paired interval of
  // the difference, as the CLI prints them.
  function runEngineCompare() {
    const d = call('engineCompare', {
      sequence: $('sequence').value.trim(), against: $('engine-baseline').value.trim(),
      taa: $('engine-taa').value, ratio: Number($('engine-ratio').value), motion: $('engine-motion').value,
      random_scenes: Number($('engine-scenes').value), size: Number($('engine-size').value),
      frames: 8, warmup: 16, reference_samples: 16,
    });
    if (!d) return;
    showMessage('');
    state.engine = d;
    let html = `<tr><th colspan="5">${d.taa_settings}, ${d.motion}, ${d.scenes.length} scenes of ${d.width}x${d.height}</th></tr>`;
    html += '<tr><th>measure</th><th>lower in</th><th>ratio</th><th>difference</th><th>interval</th></tr>';
    const rows = [['', d.against_first]].concat(d.against_first_worst ? [['worst ', d.against_first_worst]] : []);
    for (const [what, list] of rows) {
      for (const m of d.measures) {
        const p = list[0][m];
        html += `<tr data-measure="${what}${m}"><td>${what}${m}</td><td>${p.lower} of ${p.scenes}</td>` +
          `<td>${p.mean_ratio.toFixed(4)}</td><td>${p.mean_difference.toFixed(5)}</td>` +
          `<td>[${p.low.toFixed(5)}, ${p.high.toFixed(5)}]</td></tr>`;
      }
    }
    $('engine-table').innerHTML = html;
  }

  // ---- tabs ----------------------------------------------------------------
  function selectTab(name) {
    if (!['pattern', 'points', 'sequences'].includes(name)) {
      showMessage(`link: tab '${name}' is not one of pattern, points, sequences`);
      return;
    }
    for (const b of document.querySelectorAll('.tab')) b.classList.toggle('active', b.dataset.tab === name);
    for (const p of document.querySelectorAll('.tab-page')) p.hidden = p.id !== 'tab-' + name;
    if (name === 'points' && !$('discrepancy-table').innerHTML) runPoints();
    if (name === 'sequences' && !state.sequence) runSequence();
  }

  // ---- wiring ----------------------------------------------------------------
  function fillControls() {
    const reg = state.info.registry;
    $('version').textContent = `aapat ${state.info.version} · WebAssembly (${state.info.simd})`;
    const cat = $('catalog');
    cat.add(new Option('(edited)', ''));
    // The library's one answer per cost first (its summary says the cost), then every pattern.
    const best = document.createElement('optgroup');
    best.label = 'best per cost';
    for (const e of reg.best_patterns) best.appendChild(new Option(`${e.summary.split(':')[0]}: ${e.name}`, e.name));
    cat.appendChild(best);
    const groups = [['patterns', 'published'], ['aapat_patterns', 'aapat catalog']];
    for (const [key, label] of groups) {
      const og = document.createElement('optgroup');
      og.label = label;
      for (const e of reg[key]) if (!e.name.includes('NxN')) og.appendChild(new Option(e.name, e.name));
      cat.appendChild(og);
      for (const e of reg[key]) if (!e.name.includes('NxN')) $('compare-select').add(new Option(e.name, e.name));
    }
    for (const o of state.info.objectives) $('objective').add(new Option(`${o.name}`, o.name));
    $('objective').add(new Option('custom…', 'custom'));
    $('objective').value = state.info.default_objective;
    for (const f of reg.filters) $('filter').add(new Option(f.usage, f.usage));
    $('filter').value = 'mitchell:b=1/3,c=1/3';
    for (const a of reg.api_profiles) $('api').add(new Option(a.name, a.name));
    for (const g of reg.generators) $('generators').appendChild(new Option(g.usage));
    for (const s of reg.sequences.concat(reg.aapat_sequences)) $('sequences').appendChild(new Option(s.usage));
    for (const p of reg.taa_presets) $('engine-taa').add(new Option(p.name, p.name));
    for (const m of state.info.comparison_motions) {
      const o = new Option(m.name, m.name);
      o.title = m.summary;
      $('engine-motion').add(o);
    }
  }

  function wire() {
    for (const b of document.querySelectorAll('.tab')) on(b, 'click', () => { selectTab(b.dataset.tab); writeHash(); });
    on($('catalog'), 'change', () => { if ($('catalog').value) loadByName($('catalog').value); });
    on($('lattice'), 'change', () => drawPattern());
    on($('perceptual-button'), 'click', () => {
      const p = call('perceptual', { pattern: state.pattern });
      if (!p) return;
      $('perceptual').textContent = p.rows[0].perceptual.toFixed(4);
      $('perceptual').dataset.value = String(p.rows[0].perceptual);
    });
    on($('objective'), 'change', () => {
      $('custom-objective').hidden = $('objective').value !== 'custom';
      update();
    });
    for (const id of ['filter', 'acuity', 'norm']) on($(id), 'change', () => update());
    on($('scene'), 'change', () => { renderView(); writeHash(); });
    on($('edge-angle'), 'input', () => { renderView(); writeHash(); });
    on($('kernel'), 'change', () => { state.kernel = Number($('kernel').value); drawWeights(); drawPattern(); });
    on($('weights'), 'change', (e) => {
      const input = e.target;
      const value = input.value.trim() === '' || isNaN(Number(input.value)) ? input.value : Number(input.value);
      const d = call('setWeight', { pattern: state.pattern, kernel: state.kernel, index: Number(input.dataset.index), value });
      if (!d) { drawWeights(); return; }
      showMessage('');
      state.catalogName = null;
      setPattern(d.pattern, null);
    });
    const c = $('pattern-canvas');
    on(c, 'pointerdown', (e) => {
      const hit = pick(...canvasPoint(e));
      if (!hit) return;
      state.drag = Object.assign(hit, { base: state.pattern });
      c.setPointerCapture(e.pointerId);
    });
    on(c, 'pointermove', (e) => { if (state.drag) dragTo(e); });
    const end = () => { if (state.drag) { state.drag = null; update(); } };
    on(c, 'pointerup', end);
    on(c, 'pointercancel', end);
    on($('download-json'), 'click', () => {
      const d = call('patternFile', { pattern: state.pattern });
      if (d) download(`${state.pattern.name || 'pattern'}.json`, d.text);
    });
    on($('upload'), 'change', (e) => {
      const file = e.target.files[0];
      if (!file) return;
      file.text().then((text) => {
        const d = call('loadPattern', { text, source: file.name });
        if (d) { showMessage(''); setPattern(d.pattern, null); }
        e.target.value = '';
      });
    });
    on($('copy-link'), 'click', () => { writeHash(); navigator.clipboard && navigator.clipboard.writeText(location.href).catch(() => {}); });
    for (const id of ['api', 'shader', 'export-snap']) on($(id), 'change', refreshExport);
    on($('copy-export'), 'click', () => { navigator.clipboard && navigator.clipboard.writeText($('export-text').value).catch(() => {}); });
    on($('download-export'), 'click', () => download(`${state.pattern.name}-${$('api').value}.txt`, $('export-text').value));
    on($('compare'), 'click', compare);
    on($('opt-run'), 'click', runOptimize);
    on($('opt-cancel'), 'click', () => { stopWorker(); $('opt-status').textContent = 'cancelled'; });
    on($('points-run'), 'click', runPoints);
    on($('sequence-run'), 'click', runSequence);
    on($('engine-run'), 'click', runEngineCompare);
    on($('frame'), 'input', () => { state.frame = Number($('frame').value); drawSequence(); });
    on($('play'), 'click', () => {
      if (state.playTimer) { clearInterval(state.playTimer); state.playTimer = null; $('play').textContent = 'Play'; return; }
      $('play').textContent = 'Pause';
      state.playTimer = setInterval(() => {
        if (!state.sequence) return;
        state.frame = (state.frame + 1) % state.sequence.frames.length;
        $('frame').value = String(state.frame);
        drawSequence();
      }, 400);
    });
    window.addEventListener('hashchange', () => { try { readHash(); } catch (err) { showMessage('link: ' + err.message); } });
  }

  // Read-only hooks for the browser test: the pattern shown, and where on
  // the screen a sample of the base tile is drawn.
  window.aapatExplorer = {
    pattern: () => JSON.parse(JSON.stringify(state.pattern)),
    samplePoint: (set, index) => {
      const { w, X, Y } = geometry();
      const [x, y] = state.pattern.sets[set][index];
      const c = $('pattern-canvas'), b = c.getBoundingClientRect();
      const tx = set % w, ty = Math.floor(set / w);
      return [b.left + X(tx + 0.5 + x) * b.width / c.width, b.top + Y(ty + 0.5 + y) * b.height / c.height];
    },
    pixelSize: () => { const c = $('pattern-canvas'); return geometry().s * c.getBoundingClientRect().width / c.width; },
  };

  function start() {
    state.moduleSource = moduleSource();
    const factory = new Function(state.moduleSource + '\n;return createAapatModule;')();
    factory().then((api) => {
      state.api = api;
      state.info = JSON.parse(api.info());
      fillControls();
      wire();
      if (!readHash()) {
        const first = ask('loadPattern', { name: 'aapat-8' });
        const d = first.error ? call('loadPattern', { name: 'msaa-8' }) : first;
        setPattern(d.pattern, d.pattern.name);
      }
      stats.ready = true;
      document.body.dataset.ready = 'true';
    });
  }
  start();
})();
