// The studio end to end in Debian's Chromium, headless (puppeteer-core): `camopt serve` on a free
// port in a temporary copy of an example folder; load the LCR II example, change a field, see the
// field error of a bad value, run it, wait for the result, move the crank slider and check the drawn
// roller centres against the closed form (the centres on the turret circles, the output turret
// turned by (1 − n_A m_B/(m_A n_B)) θ, paper eq. 2) and against the study's own series.csv (the
// number of loaded rollers at that angle); a screenshot (SCREENSHOT; with SCREENSHOT_DIR set, also
// copied there: SCREENSHOT_DIR=$PWD/docs/images ctest -R Studio refreshes docs/images/studio.png);
// then runs disc_cam_min_size.json and checks its optimum drawn over its start design (the two base
// circles against the file's and result.json's, the outlines' smallest radii differing by the change),
// runs the cycloid NNM drive (coarse) and checks each pin's drawn load and pressure against the run's
// per_angle.csv (at a run angle turned by two mesh periods, and between two), then, the file moved
// away, the nominal view's pressures against Hertz by hand, and
// runs the globoidal cam (no animation: its verdict must never stand over the cycloid's drawing),
// runs the oscillating flat face and checks the drawn face tangent to the drawn profile at the contact.
// Beside those: the See tab's hint before any run; a cross-field error (the eccentricity that puts
// the pitch point outside the turret radius) shown at the eccentricity, the field edited; Compare
// listing both runs' own limits; at every change of the shown run, the drawing one animation frame
// after the verdict changed is the new study's (a MutationObserver on the verdict); and Play under
// 200 ms of emulated network latency: the drawn angle follows the slider (within one 2° step, the
// geometry at that angle by the closed form), well past its start, with never more than one
// angle request and one revolution request in flight.
//   node web/test/studio_e2e.mjs CAMOPT_BINARY SOURCE_DIR [SCREENSHOT]
// Exit 0 pass, 1 fail, 77 skipped (no Chromium or no web/node_modules: run `npm ci` in web/).
import { spawn } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import readline from 'node:readline';

const [camopt, sourceDir, screenshot] = process.argv.slice(2);
const chromium = process.env.CAMOPT_CHROMIUM || '/usr/bin/chromium';
if (!fs.existsSync(chromium)) { console.log(`SKIP: no Chromium at ${chromium}`); process.exit(77); }
let puppeteer;
try {
  puppeteer = (await import('puppeteer-core')).default;
} catch (e) {
  console.log('SKIP: puppeteer-core is not installed (run `npm ci` in web/)');
  process.exit(77);
}

const failures = [];
const check = (ok, what) => { if (!ok) { failures.push(what); console.log(`FAIL: ${what}`); } else console.log(`ok: ${what}`); };

const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'camopt-studio-'));
fs.copyFileSync(path.join(sourceDir, 'studies/examples/lcr_ii.json'), path.join(dir, 'lcr_ii.json'));
// LCR I with limits of its own (the example has none; LCR II's are 1500 MPa and 1050 N): Compare
// must show each run's.
const lcrI = JSON.parse(fs.readFileSync(path.join(sourceDir, 'studies/examples/lcr_i.json'), 'utf8'));
lcrI.limits = { contact_stress_MPa: 1725, roller_load_N: 1175 };
fs.writeFileSync(path.join(dir, 'lcr_i.json'), JSON.stringify(lcrI, null, 2));
fs.copyFileSync(path.join(sourceDir, 'studies/examples/globoidal_cam_paper.json'), path.join(dir, 'globoidal.json'));
fs.copyFileSync(path.join(sourceDir, 'studies/examples/disc_cam_min_size.json'), path.join(dir, 'disc_cam_min_size.json'));
// The cycloid NNM drive on a coarse grid (the run takes well under a second; the drawing does not
// depend on it).
const cycloid = JSON.parse(fs.readFileSync(path.join(sourceDir, 'studies/examples/cycloid_ltca_nnm_none.json'), 'utf8'));
cycloid.analysis = { crank_angles_per_mesh_period: 2, grid: [8, 8], estimate_error: false };
fs.writeFileSync(path.join(dir, 'cycloid.json'), JSON.stringify(cycloid, null, 2));
fs.copyFileSync(path.join(sourceDir, 'studies/examples/disc_cam_oscillating_flat_faced.json'), path.join(dir, 'flat_arm.json'));
const study = JSON.parse(fs.readFileSync(path.join(dir, 'lcr_ii.json'), 'utf8'));
const r0 = study.reducer;

const server = spawn(camopt, ['serve', '--port', '0', dir], { stdio: ['ignore', 'pipe', 'inherit'] });
const url = await new Promise((resolve, reject) => {
  const rl = readline.createInterface({ input: server.stdout });
  rl.once('line', (line) => {
    const m = /^camopt studio: (http:\/\/\S+)$/.exec(line);
    m ? resolve(m[1]) : reject(new Error(`unexpected first line: ${line}`));
  });
  server.once('exit', (code) => reject(new Error(`camopt serve exited with ${code}`)));
  setTimeout(() => reject(new Error('camopt serve printed no address in 20 s')), 20000);
});
console.log(`studio at ${url} on ${dir}`);

const browser = await puppeteer.launch({
  executablePath: chromium, headless: true,
  args: ['--no-sandbox', '--disable-gpu', '--disable-dev-shm-usage', '--window-size=1400,1500'],
});
let status = 0;
try {
  const page = await browser.newPage();
  await page.setViewport({ width: 1400, height: 1500 });
  const consoleErrors = [];
  page.on('console', (m) => { if (m.type() === 'error') consoleErrors.push(m.text()); });
  page.on('pageerror', (e) => consoleErrors.push(String(e)));
  await page.goto(url, { waitUntil: 'networkidle0' });
  await page.waitForSelector('body[data-ready="1"]');

  // Every change of the verdict logged with what the mechanism's SVG holds then and one animation
  // frame later: whose (data-run, data-kind) and what is drawn (pins, LCR rollers by side, sizing
  // designs, anything at all).
  await page.evaluate(() => {
    const svg = document.querySelector('#mechanism'), verdict = document.querySelector('#verdict');
    const snap = () => ({
      run: svg.dataset.run, kind: svg.dataset.kind, angle: svg.dataset.angle,
      pins: svg.querySelectorAll('circle[data-side="pins"]').length,
      input: svg.querySelectorAll('circle[data-side="input"]').length,
      output: svg.querySelectorAll('circle[data-side="output"]').length,
      designs: svg.querySelectorAll('g[data-design]').length,
      faces: svg.querySelectorAll('line.face').length,
      shapes: svg.querySelectorAll('path, circle, line').length,
    });
    window.verdictLog = [];
    new MutationObserver(() => {
      const entry = { text: verdict.textContent, run: verdict.dataset.run, now: snap() };
      window.verdictLog.push(entry);
      requestAnimationFrame(() => { entry.nextFrame = snap(); });
    }).observe(verdict, { childList: true, characterData: true, subtree: true, attributes: true });
  });
  // The first verdict logged since `mark` (a log length) of the study file `file`, once its next
  // frame was seen; {} when none comes within 10 s.
  const mark = () => page.evaluate(() => window.verdictLog.length);
  const verdictAfter = async (since, file) => {
    const find = (m, f) => window.verdictLog.slice(m).find((e) => e.text.startsWith(f + ':') && e.nextFrame);
    try {
      await page.waitForFunction(find, { timeout: 10000 }, since, file);
    } catch (e) {
      return { text: '', now: {}, nextFrame: {} };
    }
    return page.evaluate(find, since, file);
  };

  // Before any run the See tab says what to do, in the mechanism's panel too; Play waits.
  await page.click('#tabs button[data-tab="see"]');
  const empty = await page.evaluate(() => ({
    hint: [...document.querySelectorAll('#tab-see .hint')].filter((e) => !e.hidden).map((e) => e.innerText).join(' '),
    inSvg: [...document.querySelectorAll('#mechanism text')].map((t) => t.textContent).join(' '),
    note: document.querySelector('#mechanism-note').innerText,
    play: document.querySelector('#play').disabled,
  }));
  const beforeFirst = await mark();
  check(/run the study/i.test(empty.hint), `See before any run: "${empty.hint}"`);
  check(/run the study to see its mechanism/i.test(empty.inSvg) && /run the study/i.test(empty.note),
        `the empty mechanism panel says "${empty.inSvg}" (note "${empty.note}")`);
  check(empty.play, 'Play is disabled before any run');
  await page.click('#tabs button[data-tab="edit"]');

  // Load the example.
  await page.click('#files li[data-path="lcr_ii.json"]');
  await page.waitForSelector('body[data-loaded="lcr_ii.json"]');
  await page.waitForSelector('.validation.ok');
  check(true, 'lcr_ii.json loaded and valid');

  // Change a field: fewer angle steps (the run is faster; the form writes it into the study).
  const setField = async (ptr, text) => {
    const sel = `input[data-path="${ptr}"]`;
    await page.$eval(sel, (el, t) => { el.value = t; el.dispatchEvent(new Event('change')); }, text);
  };
  await setField('/analysis/angle_steps', '720');
  await page.waitForSelector('.validation.ok');

  // A bad value: the CLI's message next to the field.
  await setField('/reducer/eccentricity_mm', '-2');
  await page.waitForSelector('.field-error[data-for="/reducer/eccentricity_mm"]', { timeout: 10000 });
  const fieldError = await page.$eval('.field.invalid', (el) => ({ path: el.dataset.path, text: el.querySelector('.field-error').textContent }));
  check(fieldError.path === '/reducer/eccentricity_mm', `the error is shown at the field ${fieldError.path}`);
  check(fieldError.text.includes('/reducer/eccentricity_mm: expected a number > 0, found -2'),
        `the CLI's message: ${fieldError.text}`);
  await setField('/reducer/eccentricity_mm', '2');
  await page.waitForSelector('.validation.ok');
  check((await page.$$('.field-error')).length === 0, 'the error goes when the value is fixed');

  // A cross-field rule: e = 5 mm puts the input's pitch point e n/(n − m) outside its turret radius;
  // the server names the turret radius, the eccentricity was edited: the error is shown there too.
  const eBad = 5, inA = study.reducer.input, pitch = eBad * inA.rollers / (inA.rollers - inA.lobes);
  await setField('/reducer/eccentricity_mm', String(eBad));
  await page.waitForSelector('.field-error[data-for="/reducer/input/turret_radius_mm"]', { timeout: 10000 });
  await page.waitForSelector('.field-error[data-for="/reducer/eccentricity_mm"]', { timeout: 2000 }).catch(() => {});
  const cross = await page.evaluate(() => [...document.querySelectorAll('.field')].filter((f) => f.querySelector('.field-error'))
    .map((f) => ({ path: f.dataset.path, invalid: f.classList.contains('invalid'), text: f.querySelector('.field-error').textContent })));
  const atEcc = cross.find((c) => c.path === '/reducer/eccentricity_mm');
  const atTurret = cross.find((c) => c.path === '/reducer/input/turret_radius_mm');
  check(atEcc && atEcc.invalid && atEcc.text.includes('/reducer/input/turret_radius_mm') &&
        atEcc.text.includes(`e·n/(n−m) = ${pitch} mm`) && atEcc.text.includes(`${inA.turret_radius_mm} mm turret radius`),
        `the cross-field error at the edited eccentricity, the rule's path and pitch point ${pitch} mm in it: ${atEcc && atEcc.text}`);
  check(atTurret && atTurret.invalid, `and at the field it names, ${atTurret && atTurret.path}`);
  await setField('/reducer/eccentricity_mm', '2');
  await page.waitForSelector('.validation.ok');
  check((await page.$$('.field-error')).length === 0, 'the cross-field error goes when the eccentricity is fixed');

  // Run it and wait for the result.
  await page.click('#tabs button[data-tab="run"]');
  await page.click('#run');
  await page.waitForSelector('#run-state[data-state="done"]', { timeout: 120000 });
  await page.waitForSelector('body[data-result]');
  const saved = JSON.parse(fs.readFileSync(path.join(dir, 'lcr_ii.json'), 'utf8'));
  check(saved.analysis.angle_steps === 720, 'the changed field was saved before the run');
  const out = path.join(dir, 'results', 'lcr_ii');
  check(fs.existsSync(path.join(out, 'result.json')), 'the run wrote results/lcr_ii/result.json');
  const headlineRows = await page.$$eval('#headlines tr', (rows) => rows.length);
  check(headlineRows > 3, `headline table with ${headlineRows - 1} rows`);
  const charts = await page.$$eval('#charts .uplot', (c) => c.length);
  check(charts >= 2, `${charts} uPlot charts of series.csv`);
  const shown = await page.evaluate(() => ({ hint: !document.querySelector('#see-hint') || document.querySelector('#see-hint').hidden,
    text: document.querySelectorAll('#mechanism text.empty-hint').length, play: document.querySelector('#play').disabled }));
  check(shown.hint && shown.text === 0 && !shown.play, 'after the run: the hint gone, Play enabled');
  const first = await verdictAfter(beforeFirst, 'lcr_ii.json');
  check(first.nextFrame.run === '1' && first.nextFrame.input === r0.input.rollers && first.nextFrame.output === r0.output.rollers,
        `a frame after run 1's verdict: ${first.nextFrame.input} + ${first.nextFrame.output} LCR rollers of run ${first.nextFrame.run}`);

  // Move the crank slider; the drawn rollers against the closed form.
  const angle = 90;
  await page.$eval('#crank', (el, a) => { el.value = String(a); el.dispatchEvent(new Event('input')); }, angle);
  await page.waitForSelector(`#mechanism[data-angle="${angle}"]`, { timeout: 10000 });
  const drawn = await page.$$eval('#mechanism circle.roller', (cs) => cs.map((c) => ({
    side: c.dataset.side, i: Number(c.dataset.index), x: Number(c.dataset.x), y: Number(c.dataset.y),
    cx: Number(c.getAttribute('cx')), cy: Number(c.getAttribute('cy')), loaded: c.getAttribute('fill') !== '#e0e0e0',
  })));
  const r = study.reducer;
  const theta = angle * Math.PI / 180;
  // (r0: the same, used above for the first verdict's drawing)
  const turnOut = (1 - (r.input.rollers * r.output.lobes) / (r.input.lobes * r.output.rollers)) * theta;
  let worst = 0;
  for (const [name, side, turn] of [['input', r.input, 0], ['output', r.output, turnOut]]) {
    const rollers = drawn.filter((d) => d.side === name);
    check(rollers.length === side.rollers, `${rollers.length} ${name} rollers drawn (expected ${side.rollers})`);
    for (const d of rollers) {
      const a = 2 * Math.PI * d.i / side.rollers + turn;
      worst = Math.max(worst, Math.hypot(d.x - side.turret_radius_mm * Math.cos(a), d.y - side.turret_radius_mm * Math.sin(a)),
                       Math.hypot(d.cx - d.x, d.cy - d.y));
    }
  }
  check(worst < 1e-6, `roller centres at ${angle}° within ${worst.toExponential(2)} mm of the closed form`);
  // The loaded rollers drawn at that angle: as many as series.csv of the run counts there.
  const csv = fs.readFileSync(path.join(out, 'series.csv'), 'utf8').trim().split('\n');
  const header = csv[0].split(',');
  const row = csv.slice(1).map((l) => l.split(',').map(Number)).find((v) => Math.abs(v[0] - angle) < 1e-9);
  for (const name of ['input', 'output']) {
    const want = row[header.indexOf(`${name}_actuating_rollers`)];
    const got = drawn.filter((d) => d.side === name && d.loaded).length;
    check(got === want, `${got} loaded ${name} rollers drawn at ${angle}°, series.csv says ${want}`);
  }
  check(consoleErrors.length === 0, `no console errors ${consoleErrors.join(' | ')}`);
  if (screenshot) {
    fs.mkdirSync(path.dirname(screenshot), { recursive: true });
    await page.screenshot({ path: screenshot, fullPage: false });
    console.log(`screenshot: ${screenshot}`);
    // As tests/report_render_test.py: SCREENSHOT_DIR=docs/images refreshes the documented one.
    if (process.env.SCREENSHOT_DIR) {
      fs.copyFileSync(screenshot, path.join(process.env.SCREENSHOT_DIR, 'studio.png'));
      console.log(`copied to ${path.join(process.env.SCREENSHOT_DIR, 'studio.png')}`);
    }
  }
  // Compare: a second run (LCR I), the two headline tables side by side and a curve overlaid.
  await page.click('#files li[data-path="lcr_i.json"]');
  await page.waitForSelector('body[data-loaded="lcr_i.json"]');
  await page.click('#tabs button[data-tab="run"]');
  await page.click('#run');
  await page.waitForSelector('body[data-result="2"]', { timeout: 120000 });
  await page.click('#tabs button[data-tab="compare"]');
  await page.select('#compare-a', '1');
  await page.select('#compare-b', '2');
  await page.waitForSelector('#compare-charts .uplot', { timeout: 10000 });
  const compared = await page.$$eval('#compare-table tr', (rows) => rows.map((r) => [...r.cells].map((c) => c.textContent)));
  check(compared.length > 3 && compared[0][1].includes('lcr_ii') && compared[0][2].includes('lcr_i.json'),
        `compare table of ${compared.length - 1} rows, ${compared[0].slice(1, 3).join(' | ')}`);
  const stressRow = compared.find((r) => r[0] === 'largest contact stress, input cam');
  check(stressRow && stressRow[1] !== stressRow[2], `the two runs differ: ${stressRow && stressRow.slice(1, 3).join(' vs ')}`);
  // Each run's own limits (the files': LCR II 1500 MPa and 1050 N, LCR I as written above).
  check(compared[0][3] === 'limit #1' && compared[0][4] === 'limit #2', `limit columns: ${compared[0].slice(3).join(' | ')}`);
  const limitCells = (want) => compared.filter((row) => row.length === 5 && row[3].includes(String(want[0])) && row[4].includes(String(want[1])));
  const stressLimits = limitCells([study.limits.contact_stress_MPa, lcrI.limits.contact_stress_MPa]);
  const loadLimits = limitCells([study.limits.roller_load_N, lcrI.limits.roller_load_N]);
  check(stressRow && String(stressRow[3]).includes(String(study.limits.contact_stress_MPa)) && String(stressRow[4]).includes(String(lcrI.limits.contact_stress_MPa)),
        `the contact stress row's limits, A ${stressRow && stressRow[3]} and B ${stressRow && stressRow[4]}`);
  check(stressLimits.length >= 2 && loadLimits.length >= 1,
        `${stressLimits.length} rows with both stress limits (${study.limits.contact_stress_MPa} | ${lcrI.limits.contact_stress_MPa}), ` +
        `${loadLimits.length} with both roller load limits (${study.limits.roller_load_N} | ${lcrI.limits.roller_load_N})`);
  check(consoleErrors.length === 0, `still no console errors ${consoleErrors.join(' | ')}`);

  // A sizing: disc_cam_min_size run, its optimum drawn over its start. The start's base circle is
  // the file's (40 mm), the optimum's result.json's best; each profile's smallest radius is its
  // base circle (the low dwell), so the two outlines differ there by the change of r_b.
  await page.click('#files li[data-path="disc_cam_min_size.json"]');
  await page.waitForSelector('body[data-loaded="disc_cam_min_size.json"]');
  await page.click('#tabs button[data-tab="run"]');
  await page.click('#run');
  await page.waitForSelector('body[data-result="3"]', { timeout: 120000 });
  await page.click('#tabs button[data-tab="see"]').catch(() => {});
  const sizingAngle = 200;
  await page.$eval('#crank', (el, a) => { el.value = String(a); el.dispatchEvent(new Event('input')); }, sizingAngle);
  await page.waitForSelector(`#mechanism[data-angle="${sizingAngle}"] g.design-optimum`, { timeout: 10000 });
  const best = JSON.parse(fs.readFileSync(path.join(dir, 'results', 'disc_cam_min_size', 'result.json'), 'utf8')).best;
  const outlines = await page.$$eval('#mechanism g[data-design]', (gs) => gs.map((g) => {
    const base = g.querySelector('circle.turret');
    const pts = g.querySelector('path.cam-input').getAttribute('d').slice(1).replace('Z', '').split('L')
      .map((p) => p.split(',').map(Number));
    return { which: g.dataset.design, base: Number(base.getAttribute('r')), smallest: Math.min(...pts.map((p) => Math.hypot(p[0], p[1]))) };
  }));
  const start = outlines.find((o) => o.which === 'start'), opt = outlines.find((o) => o.which === 'optimum');
  check(start && opt, `two outlines drawn: ${outlines.map((o) => o.which).join(', ')}`);
  if (start && opt) {
    check(Math.abs(start.base - 40) < 1e-9 && Math.abs(opt.base - best.base_circle_radius_mm) < 1e-9,
          `base circles ${start.base} (start, the file's 40) and ${opt.base} (optimum, result.json ${best.base_circle_radius_mm})`);
    const drop = start.smallest - opt.smallest, want = 40 - best.base_circle_radius_mm;
    check(Math.abs(drop - want) < 1e-4,
          `the outlines' smallest radii differ by ${drop.toFixed(6)} mm, 40 − r_b,best = ${want.toFixed(6)} mm`);
  }
  const legend = await page.$eval('#stress-legend', (el) => el.textContent);
  check(legend.includes('start design') && legend.includes('optimum of the run'), `legend: ${legend.slice(0, 160)}`);
  check(consoleErrors.length === 0, `no console errors after the sizing ${consoleErrors.join(' | ')}`);
  if (screenshot) {  // beside the first: the sizing's two designs
    const sizingShot = path.join(path.dirname(screenshot), 'studio-sizing.png');
    await page.screenshot({ path: sizingShot, fullPage: false });
    console.log(`screenshot: ${sizingShot}`);
    if (process.env.SCREENSHOT_DIR) fs.copyFileSync(sizingShot, path.join(process.env.SCREENSHOT_DIR, 'studio-sizing.png'));
  }

  // The cycloid drive, run: the pins follow the run's loaded tooth contact analysis (its
  // per_angle.csv, read here). Its angles are 0° and 11.25° (two per mesh period τ = 22.5°); pin i
  // at φ + mτ carries what pin i − m carries at φ (docs/studio.md), so at 45° every pin i is row 0's
  // pin i − 2, and at 50° the rows 0 and 1 (pins i − 2) interpolated with weight 5/11.25.
  const beforeCycloid = await mark();
  await page.click('#files li[data-path="cycloid.json"]');
  await page.waitForSelector('body[data-loaded="cycloid.json"]');
  await page.click('#tabs button[data-tab="run"]');
  await page.click('#run');
  await page.waitForSelector('body[data-result="4"]', { timeout: 120000 });
  // From the sizing's two disc cams to the cycloid: a frame after its verdict, its pins and nothing else.
  const toCycloid = await verdictAfter(beforeCycloid, 'cycloid.json');
  check(toCycloid.text.startsWith('cycloid.json') && toCycloid.nextFrame.run === '4' && toCycloid.nextFrame.kind === 'cycloid_ltca' &&
        toCycloid.nextFrame.pins === cycloid.drive.rollers && toCycloid.nextFrame.designs === 0,
        `a frame after the cycloid's verdict: ${toCycloid.nextFrame.pins} pins (${cycloid.drive.rollers} in the file), ` +
        `${toCycloid.nextFrame.designs} sizing designs, run ${toCycloid.nextFrame.run} (${toCycloid.nextFrame.kind})`);
  const dr = cycloid.drive, n1 = dr.rollers, n2 = dr.teeth, a = dr.roller_position_radius_mm, ecc = dr.eccentricity_mm;
  const perAngle = path.join(dir, 'results', 'cycloid', 'per_angle.csv');
  const lines = fs.readFileSync(perAngle, 'utf8').trim().split('\n').map((l) => l.split(','));
  const col = (name) => lines[0].indexOf(name);
  const cell = (row, name) => Number(lines[row + 1][col(name)]);
  check(lines.length === 3 && cell(0, 'crank_angle_deg') === 0 && cell(1, 'crank_angle_deg') === 11.25,
        `the run's per_angle.csv has the rows 0° and 11.25° (${lines.length - 1} rows)`);
  const readPins = () => page.$$eval('#mechanism circle[data-side="pins"]', (cs) => cs.map((c) => ({
    i: Number(c.dataset.index), f: Number(c.dataset.force), p: Number(c.dataset.pressure), fill: c.getAttribute('fill'),
    source: c.dataset.source })));
  const setCrank = async (deg, source) => {
    await page.$eval('#crank', (el, v) => { el.value = String(v); el.dispatchEvent(new Event('input')); }, deg);
    await page.waitForSelector(`#mechanism[data-angle="${deg}"][data-source="${source}"] circle[data-side="pins"]`, { timeout: 10000 });
    return readPins();
  };
  for (const [deg, t] of [[45, 0], [50, 5 / 11.25]]) {
    const drawn = await setCrank(deg, 'run');
    let worst = 0, want = [];
    for (const pin of drawn) {
      const j = (pin.i - 2 + n1) % n1 + 1;
      const wf = (1 - t) * cell(0, `load_roller_${j}_N`) + t * cell(1, `load_roller_${j}_N`);
      const wp = (1 - t) * cell(0, `max_pressure_roller_${j}_MPa`) + t * cell(1, `max_pressure_roller_${j}_MPa`);
      want.push({ i: pin.i, p: wp });
      worst = Math.max(worst, Math.abs(pin.f - wf) / Math.max(1, wf), Math.abs(pin.p - wp) / Math.max(1, wp));
    }
    check(drawn.length === n1 && drawn.every((q) => q.source === 'run'), `${drawn.length} pins drawn from the run at ${deg}°`);
    check(worst < 1e-9, `at ${deg}° every pin's load and pressure within ${worst.toExponential(2)} (relative) of per_angle.csv (weight ${t.toFixed(4)})`);
    const hottest = drawn.reduce((x, y) => (y.p > x.p ? y : x)), top = want.reduce((x, y) => (y.p > x.p ? y : x));
    check(hottest.i === top.i && hottest.fill === 'rgb(255, 0, 0)',
          `at ${deg}° the largest drawn pressure is pin ${hottest.i} (${hottest.p.toFixed(1)} MPa, ${hottest.fill}), per_angle.csv's pin ${top.i}`);
    const legend = await page.$eval('#stress-legend', (el) => el.textContent);
    check(legend.includes(`loaded run results/cycloid/per_angle.csv, crank angle ${deg}°`), `legend: ${legend.slice(0, 160)}`);
  }
  if (screenshot) {  // the cycloid drawn from its run at 50°
    const cycloidShot = path.join(path.dirname(screenshot), 'studio-cycloid.png');
    await page.screenshot({ path: cycloidShot, fullPage: false });
    console.log(`screenshot: ${cycloidShot}`);
    if (process.env.SCREENSHOT_DIR) fs.copyFileSync(cycloidShot, path.join(process.env.SCREENSHOT_DIR, 'studio-cycloid.png'));
  }
  // Without the run's per_angle.csv: the nominal rigid disc, each loaded pin's pressure against
  // p0 = sqrt(F E*/(π B R')) by hand, the tooth's curvature at the nominal contact from docs/cycloid.md (C1).
  fs.renameSync(perAngle, perAngle + '.away');
  const crank = 50;
  await page.$eval('#crank', (el) => { el.value = '0'; el.dispatchEvent(new Event('input')); });
  await page.waitForSelector('#mechanism[data-angle="0"][data-source="nominal"]', { timeout: 10000 });
  const pins = await setCrank(crank, 'nominal');
  fs.renameSync(perAngle + '.away', perAngle);
  const rho = dr.roller_radius_mm, B = dr.face_width_mm, nu = cycloid.material.poisson_ratio;
  const eStar = cycloid.material.youngs_modulus_GPa * 1000 / (2 * (1 - nu * nu)), lam = ecc * n1 / a;
  let worstP = 0, loadedPins = 0;
  for (const pin of pins.filter((q) => q.f > 0)) {
    ++loadedPins;
    const t = 2 * Math.PI * pin.i / n1 + crank * Math.PI / 180 / n2, c = Math.cos((n1 - 1) * t);
    const kx = (1 + n1 * lam * lam - (n1 + 1) * lam * c) / (a * Math.pow(1 + lam * lam - 2 * lam * c, 1.5));
    const rEff = 1 / (kx / (1 - rho * kx) + 1 / rho);
    worstP = Math.max(worstP, Math.abs(pin.p / Math.sqrt(pin.f * eStar / (Math.PI * B * rEff)) - 1));
  }
  check(pins.length === n1 && loadedPins === 8, `${pins.length} pins drawn, ${loadedPins} loaded at ${crank}° (nominal)`);
  check(worstP < 1e-9, `the nominal pins' pressures within ${worstP.toExponential(2)} (relative) of Hertz by hand`);
  const hottest = pins.reduce((x, y) => (y.p > x.p ? y : x));
  check(hottest.fill === 'rgb(255, 0, 0)', `the largest pressure (pin ${hottest.i}, ${hottest.p.toFixed(1)} MPa) drawn red: ${hottest.fill}`);
  const cycloidLegend = await page.$eval('#stress-legend', (el) => el.textContent);
  check(cycloidLegend.includes('Hertz pressure') && cycloidLegend.includes('nominal rigid disc, no run'), `legend: ${cycloidLegend.slice(0, 160)}`);
  check(consoleErrors.length === 0, `no console errors after the cycloid ${consoleErrors.join(' | ')}`);

  // The globoidal cam after the cycloid (the issue: the cycloid stayed drawn under the globoidal
  // cam's verdict for seconds): a frame after its verdict, nothing of the cycloid drawn, and why.
  const beforeGloboidal = await mark();
  await page.click('#files li[data-path="globoidal.json"]');
  await page.waitForSelector('body[data-loaded="globoidal.json"]');
  await page.click('#tabs button[data-tab="run"]');
  await page.click('#run');
  await page.waitForSelector('body[data-result="5"]', { timeout: 120000 });
  const toGloboidal = await verdictAfter(beforeGloboidal, 'globoidal.json');
  const globoidalNote = await page.$eval('#mechanism-note', (el) => el.textContent);
  check(toGloboidal.text.startsWith('globoidal.json') && toGloboidal.nextFrame.run === '5' && toGloboidal.nextFrame.kind === 'globoidal_cam' &&
        toGloboidal.nextFrame.shapes === 0 && toGloboidal.now.shapes === 0,
        `a frame after the globoidal cam's verdict: ${toGloboidal.nextFrame.shapes} shapes drawn (run ${toGloboidal.nextFrame.run}, ${toGloboidal.nextFrame.kind})`);
  check(/globoidal_cam is not there yet/.test(globoidalNote), `and why: ${globoidalNote}`);

  // The flat face on an arm at 60°: by hand ξ = asin((r_b + d)/f) + 5° = 35°, the pivot drawn at
  // (f, 0), the face the line (P − O₃)·m = d with m = (−sin ξ, −cos ξ) through both drawn ends and
  // the contact, and no profile point on the arm's side of it.
  const beforeFlat = await mark();
  await page.click('#files li[data-path="flat_arm.json"]');
  await page.waitForSelector('body[data-loaded="flat_arm.json"]');
  await page.click('#tabs button[data-tab="run"]');
  await page.click('#run');
  await page.waitForSelector('body[data-result="6"]', { timeout: 120000 });
  const toFlat = await verdictAfter(beforeFlat, 'flat_arm.json');
  check(toFlat.nextFrame.run === '6' && toFlat.nextFrame.faces === 1 && toFlat.nextFrame.pins === 0,
        `a frame after the flat face's verdict: ${toFlat.nextFrame.faces} face drawn (run ${toFlat.nextFrame.run})`);
  await page.$eval('#crank', (el) => { el.value = '60'; el.dispatchEvent(new Event('input')); });
  await page.waitForSelector('#mechanism[data-angle="60"] line.face', { timeout: 10000 });
  const flat = await page.$eval('#mechanism', (svg) => {
    const f = svg.querySelector('line.face'), c = svg.querySelector('circle.contact');
    const pts = svg.querySelector('path.cam-input').getAttribute('d').slice(1).replace('Z', '').split('L').map((p) => p.split(',').map(Number));
    return { ends: [[f.dataset.x1, f.dataset.y1], [f.dataset.x2, f.dataset.y2]].map((e) => e.map(Number)),
             contact: [Number(c.getAttribute('cx')), Number(c.getAttribute('cy'))], pts };
  });
  const xi = Math.asin((40 + 10) / 100) + 5 * Math.PI / 180, mx = -Math.sin(xi), my = -Math.cos(xi);
  const sideOf = (p) => (p[0] - 100) * mx + p[1] * my - 10;
  const onLine = Math.max(...[...flat.ends, flat.contact].map((p) => Math.abs(sideOf(p))));
  const armSide = Math.min(...flat.pts.map(sideOf));
  check(onLine < 1e-5, `the face's ends and the contact on the line (P − O₃)·m = d within ${onLine.toExponential(2)} mm`);
  check(armSide > -1e-5, `no profile point on the arm's side of the face (closest ${armSide.toExponential(2)} mm)`);
  check(consoleErrors.length === 0, `no console errors after the flat face ${consoleErrors.join(' | ')}`);
  if (screenshot) {
    const flatShot = path.join(path.dirname(screenshot), 'studio-flat-face.png');
    await page.screenshot({ path: flatShot, fullPage: false });
  }

  // Play under 200 ms of network latency (Chromium's emulation: every request waits 200 ms). Run 1
  // (LCR II) picked from the Runs list with the crank at 0°, Play pressed at once: after 3 s the
  // drawn angle is the slider's (within one 2° step), past 20° (one step per round trip alone
  // would reach ~26°; from the revolution ~90°), and the drawing is the LCR at
  // that angle (output roller 0 at r_dB u((1 − n_A m_B/(m_A n_B)) θ), paper eq. 2); a second later
  // it has moved on. Never more than one angle request and one revolution request in flight.
  const inFlight = { angle: new Set(), revolution: new Set(), maxAngle: 0, maxRevolution: 0, total: 0 };
  const kindOf = (req) => (req.url().includes('frames=') ? 'revolution' : 'angle');
  const onRequest = (req) => {
    if (!req.url().includes('/api/mechanism')) return;
    inFlight[kindOf(req)].add(req);
    inFlight.total += 1;
    inFlight.maxAngle = Math.max(inFlight.maxAngle, inFlight.angle.size);
    inFlight.maxRevolution = Math.max(inFlight.maxRevolution, inFlight.revolution.size);
  };
  const onDone = (req) => { if (req.url().includes('/api/mechanism')) inFlight[kindOf(req)].delete(req); };
  await page.$eval('#crank', (el) => { el.value = '0'; el.dispatchEvent(new Event('input')); });
  await page.waitForSelector('#mechanism[data-angle="0"]', { timeout: 10000 });
  const cdp = await page.target().createCDPSession();
  await cdp.send('Network.enable');
  await cdp.send('Network.emulateNetworkConditions', { offline: false, latency: 200, downloadThroughput: -1, uploadThroughput: -1 });
  page.on('request', onRequest);
  page.on('requestfinished', onDone);
  page.on('requestfailed', onDone);
  const beforeBack = await mark(), t0 = Date.now();
  await page.evaluate(() => [...document.querySelectorAll('#runs li')].find((li) => li.textContent.startsWith('#1 ')).click());
  const back = await verdictAfter(beforeBack, 'lcr_ii.json');
  const switchMs = Date.now() - t0;
  check(back.nextFrame.run === '1' && back.nextFrame.input === r0.input.rollers && back.nextFrame.faces === 0,
        `back to run 1: a frame after its verdict, ${back.nextFrame.input} LCR input rollers, ${back.nextFrame.faces} faces (switch ${switchMs} ms under the latency)`);
  await page.click('#tabs button[data-tab="see"]');
  await page.click('#play');
  const sample = () => page.evaluate(() => {
    const svg = document.querySelector('#mechanism');
    const c = svg.querySelector('circle[data-side="output"][data-index="0"]');
    return { slider: Number(document.querySelector('#crank').value), drawn: Number(svg.dataset.angle), frames: svg.dataset.frames,
             run: svg.dataset.run, x: c && Number(c.dataset.x), y: c && Number(c.dataset.y) };
  });
  await new Promise((res) => setTimeout(res, 3000));
  const p1 = await sample();
  await new Promise((res) => setTimeout(res, 1000));
  const p2 = await sample();
  await page.click('#play');  // pause
  page.off('request', onRequest);
  page.off('requestfinished', onDone);
  page.off('requestfailed', onDone);
  await cdp.send('Network.emulateNetworkConditions', { offline: false, latency: 0, downloadThroughput: -1, uploadThroughput: -1 });
  const outTurn = (deg) => (1 - (r0.input.rollers * r0.output.lobes) / (r0.input.lobes * r0.output.rollers)) * deg * Math.PI / 180;
  for (const [when, p] of [['3 s', p1], ['4 s', p2]]) {
    const gap = Math.min(Math.abs(p.slider - p.drawn), 360 - Math.abs(p.slider - p.drawn));
    const miss = Math.hypot(p.x - r0.output.turret_radius_mm * Math.cos(outTurn(p.drawn)), p.y - r0.output.turret_radius_mm * Math.sin(outTurn(p.drawn)));
    check(p.run === '1' && gap <= 2 && p.drawn >= 20 && miss < 1e-6,
          `Play at 200 ms latency, after ${when}: slider ${p.slider}°, drawn ${p.drawn}° (from the ${p.frames}), output roller 0 within ${miss.toExponential(2)} mm of the closed form there`);
  }
  check(p2.drawn !== p1.drawn, `the drawing moves on: ${p1.drawn}° then ${p2.drawn}°`);
  check(p2.frames === 'revolution', `after 4 s Play draws from the run's revolution (one request): ${p2.frames}`);
  check(inFlight.maxAngle <= 1 && inFlight.maxRevolution <= 1,
        `at most ${inFlight.maxAngle} angle and ${inFlight.maxRevolution} revolution request(s) in flight (${inFlight.total} mechanism requests in all)`);
  check(consoleErrors.length === 0, `no console errors after Play ${consoleErrors.join(' | ')}`);
} catch (e) {
  failures.push(String(e));
  console.log(`FAIL: ${e.stack || e}`);
} finally {
  await browser.close();
  server.kill('SIGINT');
  fs.rmSync(dir, { recursive: true, force: true });
}
status = failures.length ? 1 : 0;
console.log(failures.length ? `${failures.length} failure(s)` : 'studio end to end: all checks pass');
process.exit(status);
