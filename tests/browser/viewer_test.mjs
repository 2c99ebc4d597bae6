// The browser viewer in a real browser (issue 18): pages written by `adsd plan --html` and
// `adsd view`, opened from file:// URLs by headless Debian chromium. Run by ctest (browser_viewer),
// or by hand from the source folder after a build:
//   ADSD=build/planner/app/adsd ADSD_PROBLEMS=build/problem_files node --test tests/browser/viewer_test.mjs
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { after, before, test } from 'node:test';

import { checkViewer, launchBrowser, outDir, printedMinClearance, problemsDir, run } from './viewer_page.mjs';

let browser;
before(async () => { browser = await launchBrowser(); });
after(async () => { await browser?.close(); });

const out = (name) => path.join(outDir, name);

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
