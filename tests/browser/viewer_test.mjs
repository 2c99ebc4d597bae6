// The browser viewer in a real browser (issues 18 and 17): pages written by `adsd plan --html` and
// `adsd view`, for rigid robots and arms, opened from file:// URLs by headless Debian chromium. Run
// by ctest (browser_viewer), or by hand from the source folder after a build:
//   ADSD=build/planner/app/adsd ADSD_PROBLEMS=build/problem_files node --test tests/browser/viewer_test.mjs
// The arm tests are skipped, naming problems/data/fetch_robots.sh, when the robots are not cached.
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { after, before, test } from 'node:test';

import {
  armRobotFile, checkArmViewer, checkViewer, launchBrowser, openViewer, outDir, printedMinClearance, problemsDir, run,
} from './viewer_page.mjs';

let browser;
before(async () => { browser = await launchBrowser(); });
after(async () => { await browser?.close(); });

const out = (name) => path.join(outDir, name);
const here = path.dirname(new URL(import.meta.url).pathname);
const armProblemsDir = process.env.ADSD_ARM_PROBLEMS ?? path.join(here, '..', '..', 'problems', 'arm');
const armCfg = (name) => path.join(armProblemsDir, name, 'problem.cfg');
/** The reason to skip an arm test, or false when its robot is cached. */
const withoutRobot = (cfg) =>
  !fs.existsSync(armRobotFile(cfg)) && `the robots are not cached: run problems/data/fetch_robots.sh (${armRobotFile(cfg)})`;

test('office (SE(2)): adsd plan --html, checked in chromium; the README screenshot', async () => {
  const cfg = path.join(problemsDir, 'office.cfg');
  const html = out('office.html');
  fs.rmSync(html, { force: true });
  const plan = run(['plan', cfg, '--seed', '1', '--html', html]);
  assert.equal(plan.status, 0, plan.stderr);
  const state = await checkViewer(browser, {
    html, cfg, expectedMin: printedMinClearance(plan.stdout), screenshot: out('viewer_office.png') });
  assert.ok(state.count > 2, 'the path is shown at the validity-checking resolution');
  const bytes = fs.statSync(html).size;
  console.log(`office.html: ${bytes} bytes, ${state.count} states, min clearance ${state.plot.min}`);
});

test('twisted_passage (SE(3)): adsd view of the path file adsd plan wrote', async () => {
  const cfg = path.join(problemsDir, 'twisted_passage.cfg');
  const pathFile = out('twisted_passage.path');
  const html = out('twisted_passage.html');
  fs.rmSync(html, { force: true });
  // RRTConnect stops at its first path: the long limit only matters in the sanitizer builds.
  const plan = run(['plan', cfg, '--seed', '1', '--time', '300', '--path', pathFile]);
  assert.equal(plan.status, 0, plan.stderr);
  const view = run(['view', cfg, '--path', pathFile, '--html', html]);
  assert.equal(view.status, 0, view.stderr);
  // The same states as adsd plan measured, so the same minimum.
  assert.equal(printedMinClearance(view.stdout), printedMinClearance(plan.stdout));
  await checkViewer(browser, {
    html, cfg, expectedMin: printedMinClearance(plan.stdout), screenshot: out('viewer_twisted_passage.png') });
});

// A wall with a 2 cm gap, 1 cm thick, 1.2e6 from the origin: the page sent the environment as
// float32 in world coordinates, and the wall was drawn 12.5 cm thick with its gap closed (an
// adversarial review). Each vertex as drawn is now within a micrometre of the file's.
test('a scene far from the origin is drawn where it is', async () => {
  const offset = 1234567.891, s = 0.01;
  const box = (lo, hi) => [0, 1].flatMap((i) => [0, 1].flatMap((j) => [0, 1].map((k) =>
    [i ? hi[0] : lo[0], j ? hi[1] : lo[1], k ? hi[2] : lo[2]])));
  const faces = [[1, 3, 7], [1, 7, 5], [2, 6, 8], [2, 8, 4], [1, 5, 6], [1, 6, 2], [3, 4, 8], [3, 8, 7], [1, 2, 4],
    [1, 4, 3], [5, 7, 8], [5, 8, 6]];
  const obj = (boxes) => boxes.map((b, n) => b.map((v) => `v ${v.join(' ')}`).join('\n') + '\n' +
    faces.map((f) => `f ${f.map((i) => i + 8 * n).join(' ')}`).join('\n')).join('\n') + '\n';
  const walls = [box([offset + 4 * s, offset - 10 * s, -s], [offset + 5 * s, offset - s, s]),
    box([offset + 4 * s, offset + s, -s], [offset + 5 * s, offset + 10 * s, s])];
  fs.writeFileSync(out('far_env.obj'), obj(walls));
  fs.writeFileSync(out('far_robot.obj'), obj([box([-s / 2, -s / 2, -s / 2], [s / 2, s / 2, s / 2])]));
  fs.writeFileSync(out('far.cfg'), ['[problem]', 'name = far', 'robot = far_robot.obj', 'world = far_env.obj',
    `start.x = ${offset}`, `start.y = ${offset}`, 'start.theta = 0', `goal.x = ${offset + 9 * s}`,
    `goal.y = ${offset}`, 'goal.theta = 0', `volume.min.x = ${offset - 2 * s}`, `volume.min.y = ${offset - 10 * s}`,
    `volume.max.x = ${offset + 11 * s}`, `volume.max.y = ${offset + 10 * s}`, ''].join('\n'));
  const html = out('far.html');
  const view = run(['view', out('far.cfg'), '--html', html]);
  assert.equal(view.status, 0, view.stderr);
  const { page, errors } = await openViewer(browser, html);
  try {
    assert.deepEqual(errors, []);
    const drawn = await page.evaluate(() => Array.from({ length: 16 }, (_, i) => adsdViewer.environmentVertex(i)));
    // The reader numbers vertices as the faces first use them: each drawn one is matched with the
    // nearest of the file's.
    drawn.forEach((d, i) => {
      const off = Math.min(...walls.flat().map((v) => Math.hypot(...v.map((x, k) => x - d[k]))));
      assert.ok(off <= 1e-6, `environment vertex ${i} drawn ${off} from the nearest the file has`);
    });
    // The ghost the robot stands on is hidden, the other shown.
    assert.deepEqual(await page.evaluate(() => adsdViewer.ghostsShown()), [false, true]);
  } finally {
    await page.close();
  }
  // A path of one state, at neither end: both ghosts were hidden, as if it stood on both.
  fs.writeFileSync(out('far_one.path'), `${offset + 2 * s} ${offset} 0\n`);
  const one = run(['view', out('far.cfg'), '--path', out('far_one.path'), '--html', out('far_one.html')]);
  assert.equal(one.status, 0, one.stderr);
  const opened = await openViewer(browser, out('far_one.html'));
  try {
    assert.deepEqual(await opened.page.evaluate(() => adsdViewer.ghostsShown()), [true, true]);
  } finally {
    await opened.page.close();
  }
});

test('adsd view without a path shows the start and the goal', async () => {
  const cfg = path.join(problemsDir, 'bug_trap.cfg');
  const html = out('bug_trap_problem.html');
  const view = run(['view', cfg, '--html', html]);
  assert.equal(view.status, 0, view.stderr);
  const state = await checkViewer(browser, { html, cfg, expectedMin: printedMinClearance(view.stdout) });
  assert.equal(state.count, 2);
});

test('adsd view refuses a bad path file with one line naming it, and writes nothing', async () => {
  const cfg = path.join(problemsDir, 'office.cfg');
  const bad = out('bad.path');
  fs.writeFileSync(bad, '# x y yaw\n-6 2.5 0\n-5 2.5\n');
  const html = out('bad.html');
  fs.rmSync(html, { force: true });
  const view = run(['view', cfg, '--path', bad, '--html', html]);
  assert.equal(view.status, 2);
  assert.match(view.stderr, /^adsd view: error: .*bad\.path:3: expected 3 numbers \(x y yaw\).*got 2\n$/);
  assert.equal(view.stdout, '');
  assert.ok(!fs.existsSync(html) && !fs.existsSync(`${html}.partial`));
  const noHtml = run(['view', cfg]);
  assert.equal(noHtml.status, 2);
  assert.match(noHtml.stderr, /--html OUT.html is required/);
});

test('kr5_table_pick (arm): adsd plan --html, checked in chromium; the arm screenshot', { skip: withoutRobot(armCfg('kr5_table_pick')) }, async () => {
  const cfg = armCfg('kr5_table_pick');
  const html = out('kr5_table_pick.html');
  fs.rmSync(html, { force: true });
  const plan = run(['plan', cfg, '--seed', '1', '--html', html]);
  assert.equal(plan.status, 0, plan.stderr);
  assert.match(plan.stdout, /^viewer\s+\S*kr5_table_pick\.html$/m);
  const state = await checkArmViewer(browser, {
    html, cfg, expectedMin: printedMinClearance(plan.stdout), screenshot: out('viewer_kr5_table_pick.png') });
  assert.ok(state.count > 2);
  const bytes = fs.statSync(html).size;
  console.log(`kr5_table_pick.html: ${bytes} bytes, ${state.count} states, min clearance ${state.plot.min}`);
});

test('wam_box (arm): adsd view of the path file adsd plan wrote', { skip: withoutRobot(armCfg('wam_box')) }, async () => {
  const cfg = armCfg('wam_box');
  const pathFile = out('wam_box.txt');
  const html = out('wam_box.html');
  fs.rmSync(html, { force: true });
  const plan = run(['plan', cfg, '--seed', '1', '--path', pathFile]);
  assert.equal(plan.status, 0, plan.stderr);
  const view = run(['view', cfg, '--path', pathFile, '--html', html]);
  assert.equal(view.status, 0, view.stderr);
  // The path file holds every digit: the same states as adsd plan measured, so the same minimum.
  assert.equal(printedMinClearance(view.stdout), printedMinClearance(plan.stdout));
  const state = await checkArmViewer(browser, {
    html, cfg, expectedMin: printedMinClearance(plan.stdout), screenshot: out('viewer_wam_box.png') });
  const bytes = fs.statSync(html).size;
  console.log(`wam_box.html: ${bytes} bytes, ${state.count} states, min clearance ${state.plot.min}`);
});

test('adsd view of an arm problem without a path shows its start and goal', { skip: withoutRobot(armCfg('kr5_shelf')) }, async () => {
  const cfg = armCfg('kr5_shelf');
  const html = out('kr5_shelf_problem.html');
  const view = run(['view', cfg, '--html', html]);
  assert.equal(view.status, 0, view.stderr);
  const state = await checkArmViewer(browser, { html, cfg, expectedMin: printedMinClearance(view.stdout) });
  assert.equal(state.count, 2);
});
