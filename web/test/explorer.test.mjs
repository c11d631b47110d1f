// The explorer page in Debian's headless Chromium, driven by puppeteer-core
// (scripts/test-web.sh runs it), and the WebAssembly module in node, both
// checked against the native CLI:
//   - E2 of every catalog pattern under both named objectives, module == CLI to 1e-12;
//   - #pattern=flipquad shows the recommended objective's E2, and with
//     &objective=laine-aila 0.3643 (Laine & Aila 2006, Table 2);
//   - a sample dragged with the mouse: the page's E2 == the CLI's for the pattern it shows;
//   - a sample dropped on a border becomes shared (the family gains its '+');
//   - every seeded point generator and a seeded optimization: module == CLI, bit for bit;
//   - engine TAA comparisons (UE4 still, FSR 2 after a cut, Godot at the
//     resonances): module == CLI (FLIP to 1e-4), and the sequences tab's table;
//   - an optimization run to the end in the worker == `aapat optimize` with the same seed;
//   - cancel stops it and the page keeps working;
//   - every objective form in a link: the CLI's E2, and the same again from the
//     link the page writes;
//   - a bad upload, a NaN weight, a hash that does not parse, a link's bad
//     scene, a key given twice, a link too long and a pattern over the limits
//     each show a message naming the problem;
//   - no console message of any kind, no uncaught error.
// Usage: node explorer.test.mjs PAGE.html AAPAT_BINARY MODULE.js [--bench] [--screenshot PNG]
import { execFileSync } from 'node:child_process';
import { mkdtempSync, writeFileSync, rmSync } from 'node:fs';
import { createRequire } from 'node:module';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import puppeteer from 'puppeteer-core';

const [pagePath, aapat, modulePath, ...rest] = process.argv.slice(2);
if (!pagePath || !aapat || !modulePath) {
  console.error('usage: node explorer.test.mjs PAGE.html AAPAT_BINARY MODULE.js [--bench] [--screenshot PNG]');
  process.exit(2);
}
const bench = rest.includes('--bench');
const shotAt = rest.indexOf('--screenshot');
const screenshot = shotAt >= 0 ? rest[shotAt + 1] : null;
const url = 'file://' + resolve(pagePath);
const tmp = mkdtempSync(join(tmpdir(), 'aapat-explorer-'));

let failures = 0;
function check(ok, what) {
  console.log(`${ok ? 'ok  ' : 'FAIL'} ${what}`);
  if (!ok) failures += 1;
}
function cli(...args) {
  return JSON.parse(execFileSync(aapat, args, { encoding: 'utf8', maxBuffer: 1 << 26 }));
}
function near(a, b, tol) {
  return Math.abs(a - b) <= tol;
}

// ---- the module in node against the CLI: every catalog pattern ------------
const module = await createRequire(import.meta.url)(resolve(modulePath))();
const info = JSON.parse(module.info());
const names = info.registry.patterns.concat(info.registry.aapat_patterns)
  .map((e) => e.name).filter((n) => !n.includes('NxN'));
for (const objective of ['recommended', 'laine-aila']) {
  const native = cli('eval', ...names, '--objective', objective, '--json').rows;
  let worst = 0;
  for (const [i, name] of names.entries()) {
    const web = JSON.parse(module.evaluate(JSON.stringify({ pattern: name, objective }))).eval.rows[0];
    worst = Math.max(worst, Math.abs(web.e2 - native[i].e2));
  }
  check(worst <= 1e-12, `${names.length} catalog patterns, objective ${objective}: module E2 == CLI E2 (largest difference ${worst.toExponential(2)})`);
}

// The perceptual objective in the module and the CLI: the same charts, the
// same FLIP to a millionth of the value (FLIP computes in float with each
// platform's powf, expf and cbrtf: the module and the CLI differ in the
// seventh digit; docs/perceptual.md).
{
  const objective = 'perceptual:angles=2,patch=16,reference=16';
  for (const name of ['msaa-4', 'aapat-8', 'hasselgren-f']) {
    const web = JSON.parse(module.perceptual(JSON.stringify({ pattern: name, objective }))).rows[0];
    const native = cli('eval', name, '--objective', objective, '--json').rows[0];
    check(near(web.perceptual, native.perceptual, 1e-6 * native.perceptual) && web.family === native.family,
      `${name} under ${objective}: module ${web.perceptual} within a millionth of the CLI's ${native.perceptual}`);
  }
  const bad = JSON.parse(module.perceptual(JSON.stringify({ pattern: 'msaa-4', objective: 'perceptual:ppd=0' })));
  check(typeof bad.error === 'string' && bad.error.includes('ppd'), `a bad perceptual spec is refused naming ppd: ${bad.error}`);
}

// Engine TAA in the module and the CLI (`sequence compare --json`): the same
// document, RMSE and flicker to the bit; FLIP, in float with each platform's
// powf, expf and cbrtf, to 1e-4 of its value or of 0.01 (its powers below 1 amplify a
// last-digit difference where a pixel's difference is near 0); a cut and
// the resonances, and a preset or motion the library refuses, named.
function compareDocuments(web, native, path, flipTolerance) {
  if (typeof native === 'number') {  // FLIP's numbers: a path through a key "flip"
    return /\.flip(\.|$)/.test(path) ? near(web, native, flipTolerance * Math.max(Math.abs(native), 1e-2))
      : web === native;
  }
  if (native && typeof native === 'object') {
    return Object.keys(native).every((k) => compareDocuments(web?.[k], native[k], `${path}.${k}`, flipTolerance));
  }
  return web === native;
}
for (const [taa, ratio, motion, sequences] of [
  ['ue4', 1, 'static', ['ue4-halton:frames=8', 'aapat-ue4-8']],
  ['fsr2', 1.5, 'cut', ['halton:frames=18', 'aapat-upscale-1.5']],
  ['godot', 1, 'resonant', ['halton:frames=16', 'aapat-taa-16']]]) {
  const size = motion === 'resonant' ? 8 : 16;
  const request = { sequences, taa, ratio, motion, random_scenes: 2, size, frames: 4, warmup: 8, reference_samples: 16, resamples: 200 };
  const web = JSON.parse(module.engineCompare(JSON.stringify(request)));
  const native = cli('sequence', 'compare', ...sequences, '--taa', taa, '--ratio', String(ratio), '--motion', motion,
    '--random-scenes', '2', '--size', String(size), '--frames', '4', '--warmup', '8', '--reference-samples', '16',
    '--resamples', '200', '--json');
  check(!web.error && compareDocuments(web, native, '', 1e-4),
    `engine TAA ${taa} at ${ratio}, ${motion}: module == CLI (${web.error || native.sequences.join(' against ')})`);
}
{
  const base = { sequences: ['halton:frames=8', 'r2:frames=8'], random_scenes: 1, size: 8 };
  const badPreset = JSON.parse(module.engineCompare(JSON.stringify({ ...base, taa: 'ue5' })));
  check(/unknown TAA preset 'ue5'/.test(badPreset.error || ''), `engine TAA: an unknown preset is refused: ${badPreset.error}`);
  const badMotion = JSON.parse(module.engineCompare(JSON.stringify({ ...base, taa: 'ue4', motion: 'sideways' })));
  check(/motion/.test(badMotion.error || ''), `engine TAA: an unknown motion is refused naming it: ${badMotion.error}`);
  const one = JSON.parse(module.engineCompare(JSON.stringify({ ...base, taa: 'ue4', sequences: ['halton:frames=8'] })));
  check(typeof one.error === 'string', `engine TAA: one sequence is refused: ${one.error}`);
  // One sequence against the preset's own jitter by default.
  const own = JSON.parse(module.engineCompare(JSON.stringify({ taa: 'bevy', sequence: 'aapat-taa-8', random_scenes: 1, size: 8, frames: 2, warmup: 2, reference_samples: 4 })));
  check(!own.error && own.sequences[0].startsWith('bevy-halton') && own.sequences[1] === 'aapat-taa-8',
    `engine TAA: a sequence against the preset's own jitter by default: ${own.error || own.sequences.join(' against ')}`);
}

// Same seed, same output on every platform: each point generator, seeded, in
// the module (libc++, emscripten's libm) and the CLI (libstdc++, glibc) gives
// the same points to the last bit, and so does a seeded optimization.
for (const g of info.registry.generators.map((e) => e.name)) {
  const n = g === 'n-queens' ? 16 : 64;  // squares, for the stratified generators; n-queens stops at 20
  const web = JSON.parse(module.points(JSON.stringify({ generator: g, n, seed: 3, spectrum_size: 8 }))).points;
  const native = cli('generate', g, '--n', String(n), '--seed', '3', '--json').rows.map((r) => [r.x, r.y]);
  check(JSON.stringify(web) === JSON.stringify(native), `generate ${g} --n ${n} --seed 3: the module's points == the CLI's, bit for bit`);
}
{
  const family = 'P(1,1,8)';
  const web = JSON.parse(module.optimize(JSON.stringify({ family, starts: 4, seed: 1, method: 'descent', objective: 'recommended' }), null));
  const native = cli('optimize', '--family', family, '--starts', '4', '--seed', '1', '--method', 'descent', '--json');
  check(web.report.e2 === native.e2, `optimize ${family} from 4 starts, seed 1: the module's E2 ${web.report.e2} == the CLI's ${native.e2}, bit for bit`);
}

// One definition: the page's registries are `aapat list --json`'s.
const listed = cli('list', '--json');
delete listed.command;
delete listed.schema;
check(JSON.stringify(info.registry) === JSON.stringify(listed), `the module's registries == aapat list --json (${Object.keys(listed).length} sections)`);

// ---- the page --------------------------------------------------------------
const browser = await puppeteer.launch({
  executablePath: '/usr/bin/chromium',
  headless: true,
  args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
    '--disable-background-networking', '--disable-component-update', '--disable-sync'],
});
const consoleMessages = [];
const page = await browser.newPage();
await page.setViewport({ width: 1400, height: 1000 });
page.on('console', (m) => consoleMessages.push(`${m.type()}: ${m.text()}`));
page.on('pageerror', (e) => consoleMessages.push(`uncaught: ${e.message}`));

async function open(hash) {
  await page.goto('about:blank');
  await page.goto(url + hash, { waitUntil: 'load' });
  await page.waitForFunction(() => window.aapatStats && window.aapatStats.ready, { timeout: 60000 });
}
const e2Shown = () => page.$eval('#e2', (e) => Number(e.dataset.value));
const message = () => page.$eval('#message', (e) => (e.hidden ? '' : e.textContent));

try {
  // Shared links: a catalog name, with and without an objective.
  await open('#pattern=flipquad');
  const flipquad = cli('eval', 'flipquad', '--json').rows[0].e2;
  check(near(await e2Shown(), flipquad, 1e-12), `#pattern=flipquad shows the recommended objective's E2 ${flipquad.toFixed(4)}`);
  // The perceptual objective on request, the module's value to a millionth of the CLI's.
  await page.click('#perceptual-button');
  await page.waitForFunction(() => document.querySelector('#perceptual').dataset.value !== '', { timeout: 60000 });
  const shownPerceptual = await page.$eval('#perceptual', (e) => Number(e.dataset.value));
  const nativePerceptual = cli('eval', 'flipquad', '--objective', 'perceptual', '--json').rows[0].perceptual;
  check(near(shownPerceptual, nativePerceptual, 1e-6 * nativePerceptual),
    `#pattern=flipquad, perceptual on request: ${shownPerceptual.toFixed(6)} (CLI ${nativePerceptual.toFixed(6)})`);
  await open('#pattern=flipquad&objective=laine-aila');
  const text = await page.$eval('#e2', (e) => e.textContent);
  const la = cli('eval', 'flipquad', '--objective', 'laine-aila', '--json').rows[0].e2;
  check(text === '0.3643' && near(await e2Shown(), la, 1e-12), `#pattern=flipquad&objective=laine-aila shows ${text} (Laine & Aila Table 2: 0.3643)`);

  // The best pattern at 2 samples per pixel: the page's one answer is aapat list's.
  const listedBest = cli('list', '--json').best_patterns.find((e) => e.summary.startsWith('cost 2:'));
  const shownBest = await page.$eval('#catalog', (c) => [...c.querySelectorAll('optgroup[label="best per cost"] option')]
    .filter((o) => o.textContent.startsWith('cost 2:')).map((o) => o.value));
  check(listedBest && shownBest.length === 1 && shownBest[0] === listedBest.name,
    `the best pattern at cost 2 is one answer on the page and in aapat list: ${shownBest.join(', ')}`);

  // Export opens on a profile that takes the pattern: FLIPQUAD's shared
  // samples need a 2x2 grid, so not the first profile (D3D12 tier 1).
  await open('#pattern=flipquad');
  const exportText = await page.$eval('#export-text', (e) => e.value);
  const api = await page.$eval('#api', (e) => e.value);
  check(!exportText.startsWith('(not exportable') && exportText.includes(`profile=${api}`),
    `FLIPQUAD's export opens on a profile that takes it: ${api}`);
  // The Compare table follows every change: compare with RGSS, then change
  // the pattern, and its first row is the new pattern's E2.
  await page.$eval('#compare-select', (e) => { for (const o of e.options) o.selected = o.value === 'rgss'; });
  await page.click('#compare');
  await page.select('#catalog', 'msaa-4');
  const firstRow = await page.$eval('#compare-table', (t) => Number(t.rows[1].cells[3].textContent));
  const msaa4 = cli('eval', 'msaa-4', '--json').rows[0].e2;
  check(firstRow === Number(msaa4.toFixed(4)), `the Compare table follows a change of pattern: ${firstRow} (msaa-4's E2)`);

  // Every objective form a link can hold: the page shows the CLI's E2 for it,
  // and the link the page writes reopens the same objective (read by the
  // library's parser, never split on '=' in the page).
  for (const o of ['laine-aila norm=2', 'recommended norm=4', 'filter=lanczos:lobes=2 acuity=uniform:step=1 norm=2',
    'norm=inf', 'filter=gaussian acuity=laine-aila']) {
    await open('#pattern=flipquad&objective=' + encodeURIComponent(o));
    const native = cli('eval', 'flipquad', '--objective', o, '--json').rows[0].e2;
    const first = await e2Shown();
    const m0 = await message();
    const written = await page.evaluate(() => location.hash);
    await open(written);
    const again = await e2Shown();
    check(m0 === '' && (await message()) === '' && near(first, native, 1e-12) && again === first,
      `objective '${o}' in a link: E2 ${first.toFixed(6)} (CLI ${native.toFixed(6)}), and again from the link the page wrote (${decodeURIComponent(written)})`);
  }
  await open('#pattern=flipquad&scene=halfplane:angle=e,offset=0');
  const badAngle = await message();
  check(/^link: /.test(badAngle) && /angle/.test(badAngle) && /not a finite number/.test(badAngle), `a link's scene with angle 'e': "${badAngle}"`);
  await open('#pattern=flipquad&pattern=rgss');
  const twice = await message();
  check(twice === "link: 'pattern' is given more than once", `a key given twice: "${twice}"`);
  const limit = info.limits.link_bytes;
  await open('#design=' + 'x'.repeat(limit));
  const long = await message();
  check(new RegExp(`past the limit of ${limit}`).test(long), `a link past ${limit} characters: "${long.slice(0, 100)}"`);

  // A drag with the mouse; the CLI evaluates the pattern the page shows.
  await open('#pattern=msaa-16');
  const [x0, y0] = await page.evaluate(() => window.aapatExplorer.samplePoint(0, 2));
  const px = await page.evaluate(() => window.aapatExplorer.pixelSize());
  await page.mouse.move(x0, y0);
  await page.mouse.down();
  const steps = 24;
  for (let k = 1; k <= steps; ++k) await page.mouse.move(x0 + 0.13 * px * k / steps, y0 + 0.07 * px * k / steps);
  await page.mouse.up();
  const dragged = await page.evaluate(() => window.aapatExplorer.pattern());
  const file = join(tmp, 'dragged.json');
  writeFileSync(file, JSON.stringify(dragged));
  const nativeDragged = cli('eval', file, '--json').rows[0].e2;
  const shown = await e2Shown();
  check(dragged.name === 'msaa-16-edited' && near(shown, nativeDragged, 1e-12),
    `dragged sample: page E2 ${shown.toFixed(6)} == CLI E2 ${nativeDragged.toFixed(6)} of ${dragged.name}`);
  const latencies = await page.evaluate(() => window.aapatStats.dragLatencyMs);
  const frames = await page.evaluate(() => window.aapatStats.frameLatencyMs);
  const median = (v) => [...v].sort((a, b) => a - b)[Math.floor(v.length / 2)];
  console.log(`     drag-to-update latency (16 samples) over ${latencies.length} moves: median ${median(latencies).toFixed(1)} ms, ` +
    `largest ${Math.max(...latencies).toFixed(1)} ms; to the next frame: median ${median(frames).toFixed(1)} ms`);

  // Dropped on the left border: shared, so P(1,1,16) becomes P(1,1+,16).
  const [x1, y1] = await page.evaluate(() => window.aapatExplorer.samplePoint(0, 3));
  await page.mouse.move(x1, y1);
  await page.mouse.down();
  const left = await page.evaluate(() => {
    const c = document.getElementById('pattern-canvas').getBoundingClientRect();
    return c.left + c.width * (1 / (1 + 2)) - 1;  // just outside the base pixel's left edge
  });
  await page.mouse.move(left, y1, { steps: 8 });
  await page.mouse.up();
  const shared = await page.evaluate(() => window.aapatExplorer.pattern());
  const family = await page.$eval('#family', (e) => e.textContent);
  const [dx, dy] = shared.sets[0][3];
  const copy = shared.sets[0].some(([x, y]) => x === 0.5 && y === dy);
  check(shared.footprint === '1+' && family === 'P(1,1+,16)' && dx === -0.5 && copy,
    `a sample dropped on a border is shared: family ${family}, at (${dx}, ${dy.toFixed(3)}) and (0.5, ${dy.toFixed(3)}); ` +
    `${shared.sets[0].length} samples read (MSAA 16x's own border samples shared too)`);

  // An optimization to the end in the worker: the same result as the module
  // run in node with the same settings, as the CLI's own search with the same
  // seed (aapat's own cos/sin and distributions: the same bits everywhere),
  // and its pattern's E2 as the CLI evaluates it.
  await open('#pattern=msaa-4');
  await page.select('#opt-mode', 'search');
  const starts = bench ? 64 : 4;
  const searched = bench ? 'P(1,1,16)' : 'P(1,1,8)';
  await page.$eval('#opt-family', (e, v) => { e.value = v; }, searched);
  await page.$eval('#opt-starts', (e, v) => { e.value = String(v); }, starts);
  await page.click('#opt-run');
  await page.waitForFunction(() => window.aapatStats.optimizeSeconds !== null, { timeout: 600000 });
  const optE2 = Number(await page.$eval('#opt-status', (e) => e.dataset.e2));
  const seconds = await page.evaluate(() => window.aapatStats.optimizeSeconds);
  const inNode = JSON.parse(module.optimize(JSON.stringify({ family: searched, starts, seed: 1, method: 'descent', objective: 'recommended' }), null));
  const found = await page.evaluate(() => window.aapatExplorer.pattern());
  const foundFile = join(tmp, 'found.json');
  writeFileSync(foundFile, JSON.stringify(found));
  const foundNative = cli('eval', foundFile, '--json').rows[0].e2;
  const nativeOpt = cli('optimize', '--family', searched, '--starts', String(starts), '--seed', '1', '--json');
  check(optE2 === inNode.report.e2 && optE2 === nativeOpt.e2 && near(await e2Shown(), optE2, 1e-12) &&
    near(foundNative, optE2, 1e-12),
    `optimize ${searched} from ${starts} starts in the worker (${seconds.toFixed(1)} s): E2 ${optE2.toFixed(6)}, ` +
    `the module's in node, the CLI's own search's and the CLI's E2 of the pattern found`);

  // Cancel: a long search stopped, and the page still answers.
  await page.$eval('#opt-starts', (e) => { e.value = '1024'; });
  await page.$eval('#opt-family', (e) => { e.value = 'P(1,1,16)'; });
  await page.click('#opt-run');
  await page.waitForFunction(() => document.getElementById('opt-status').textContent.includes('of 1024'), { timeout: 60000 });
  await page.click('#opt-cancel');
  const cancelled = await page.$eval('#opt-status', (e) => e.textContent);
  await page.select('#catalog', 'flipquad');
  const after = await e2Shown();
  check(cancelled === 'cancelled' && near(after, flipquad, 1e-12), `cancel stops the worker (status '${cancelled}') and the page goes on`);

  // The point-set and sequence tabs show the CLI's numbers.
  await open('#pattern=flipquad&tab=points');
  await page.waitForFunction(() => document.getElementById('discrepancy-table').rows.length > 0, { timeout: 30000 });
  const l2Shown = await page.$eval('#discrepancy-table', (t) => [...t.rows].find((r) => r.cells[0].textContent === 'l2_star').cells[1].textContent);
  const l2Native = cli('discrepancy', 'jittered', '--n', '256', '--seed', '1', '--json').l2_star;
  check(Number(l2Shown) === Number(l2Native.toPrecision(6)), `point sets tab: jittered, 256 points: L2-star ${l2Shown} (CLI ${l2Native})`);
  await open('#pattern=flipquad&tab=sequences');
  await page.waitForFunction(() => document.getElementById('sequence-table').rows.length > 0, { timeout: 30000 });
  const worstShown = await page.$eval('#sequence-table', (t) => [...t.rows].find((r) => r.cells[0].textContent === 'worst_e2').cells[1].textContent);
  const worstNative = cli('sequence', 'eval', 'aapat-taa-8', '--json').rows[0].worst_e2;
  check(worstShown === worstNative.toFixed(4), `sequences tab: aapat-taa-8 under EMA 0.1: worst E2 ${worstShown} (CLI ${worstNative.toFixed(6)})`);

  // The sequences tab's engine comparison: the CLI's paired comparison.
  await page.$eval('#engine-scenes', (e) => { e.value = '2'; });
  await page.$eval('#engine-size', (e) => { e.value = '16'; });
  await page.select('#engine-taa', 'ue4');
  await page.click('#engine-run');
  await page.waitForFunction(() => document.getElementById('engine-table').rows.length > 2, { timeout: 60000 });
  const rmseRow = await page.$eval('#engine-table', (t) => [...t.rows].find((r) => r.dataset.measure === 'rmse').cells[2].textContent);
  const nativeRatio = cli('sequence', 'compare', 'ue4-halton:frames=8', 'aapat-taa-8', '--taa', 'ue4', '--random-scenes', '2',
    '--size', '16', '--frames', '8', '--warmup', '16', '--reference-samples', '16', '--json').against_first[0].rmse.mean_ratio;
  check(rmseRow === nativeRatio.toFixed(4), `sequences tab under UE4: aapat-taa-8 against UE4's jitter, RMSE ratio ${rmseRow} (CLI ${nativeRatio.toFixed(6)})`);

  // Bad input: each shows a message naming the problem.
  const bad = join(tmp, 'not-a-pattern.json');
  writeFileSync(bad, '{"format": "aapat-pattern", "version": 1, "name": "bad", "tile": [1, 1], "footprint": "1", "sets": [[[0.7, 0]]], "kernels": [[1]]}');
  const input = await page.$('#upload');
  await input.uploadFile(bad);
  await page.waitForFunction(() => !document.getElementById('message').hidden, { timeout: 10000 });
  const m1 = await message();
  check(/not-a-pattern\.json/.test(m1) && /outside the pixel/.test(m1), `bad upload: "${m1}"`);
  const garbage = join(tmp, 'garbage.json');
  writeFileSync(garbage, 'this is not JSON');
  await input.uploadFile(garbage);
  await page.waitForFunction(() => /not valid JSON/.test(document.getElementById('message').textContent), { timeout: 10000 });
  check(true, `upload of a file that is not JSON: "${await message()}"`);

  await page.$eval('#weights input', (e) => { e.value = 'NaN'; e.dispatchEvent(new Event('change', { bubbles: true })); });
  const m2 = await message();
  check(/^weight 0 of kernel 0: 'NaN' is not a number$/.test(m2), `NaN weight: "${m2}"`);

  await open('#pattern=flipqaud');
  const m3 = await message();
  check(/^link: /.test(m3) && /flipquad/.test(m3) && /aapat-8/.test(m3),
    `misspelt catalog name in the link, the aapat names listed as the CLI lists them: "${m3.slice(0, 120)}..."`);
  await open('#design={"tile":[1,1],');
  const m4 = await message();
  check(/link: the design is not valid JSON/.test(m4), `a link whose design does not parse: "${m4}"`);
  const many = Array.from({ length: 1025 }, (_, i) => [((i % 32) + 0.5) / 32 - 0.5, (Math.floor(i / 32) + 0.5) / 33 - 0.5]);
  await open('#design=' + encodeURIComponent(JSON.stringify({ tile: [1, 1], footprint: '1', sets: [many], kernels: [many.map(() => 1 / 1025)] })));
  const m5 = await message();
  check(/1025 samples exceed the limit of 1024/.test(m5), `a pattern over the limits: "${m5}"`);
  await open('#design=' + encodeURIComponent(`{"name":${'['.repeat(3000)}${']'.repeat(3000)}}`));
  const m6 = await message();
  check(/nested 3001 deep, past the limit of 256/.test(m6), `a design nested 3000 deep: "${m6}"`);
  check(await e2Shown() > 0, 'after every bad input the page still shows a pattern and its E2');

  if (screenshot) {
    await open('#pattern=aapat-8');
    await page.screenshot({ path: screenshot });
    console.log(`     wrote ${screenshot}`);
  }
} finally {
  await browser.close();
  rmSync(tmp, { recursive: true, force: true });
}

check(consoleMessages.length === 0, `no console message${consoleMessages.length ? ':\n  ' + consoleMessages.join('\n  ') : ''}`);
console.log(failures ? `explorer: ${failures} check(s) failed` : 'explorer: every check passed');
process.exit(failures ? 1 : 0);
