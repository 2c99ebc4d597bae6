// A viewer page for every shipped problem's solution, each opened offline in headless chromium and
// put through the browser test's checks (viewer_page.mjs): `adsd plan PROBLEM --seed 1 --html`
// with the problem's own planner and time limit. Prints one line per problem and the largest
// page; exits 1 when a problem is not solved or a page fails a check. Not a ctest (it takes the
// problems' time limits, a few minutes, and cow_doorway needs problems/data/fetch_meshes.sh):
//   ADSD=build/planner/app/adsd ADSD_PROBLEMS=build/problem_files ADSD_BROWSER_OUT=/tmp/viewers \
//     node tests/browser/view_all_problems.mjs
import fs from 'node:fs';
import path from 'node:path';

import { checkViewer, launchBrowser, outDir, printedMinClearance, problemsDir, run } from './viewer_page.mjs';

const problems = fs.readdirSync(problemsDir).filter((f) => f.endsWith('.cfg')).sort();
const browser = await launchBrowser();
let failed = 0, largest = { bytes: 0 };
try {
  for (const problem of problems) {
    const name = path.basename(problem, '.cfg');
    const cfg = path.join(problemsDir, problem);
    const html = path.join(outDir, `${name}.html`);
    fs.rmSync(html, { force: true });
    const started = Date.now();
    const plan = run(['plan', cfg, '--seed', '1', '--html', html]);
    const seconds = ((Date.now() - started) / 1000).toFixed(1);
    if (plan.status !== 0) {
      failed++;
      console.log(`${name}: NOT SOLVED (adsd plan exit ${plan.status}, ${seconds} s) ${plan.stderr.trim()}`);
      continue;
    }
    try {
      const state = await checkViewer(browser, {
        html, cfg, expectedMin: printedMinClearance(plan.stdout), screenshot: path.join(outDir, `${name}.png`) });
      const bytes = fs.statSync(html).size;
      if (bytes > largest.bytes) largest = { name, bytes };
      console.log(`${name}: ok, ${state.count} states, min clearance ${state.plot.min.toPrecision(6)}, ` +
                  `${(bytes / 1e6).toFixed(2)} MB, adsd plan ${seconds} s`);
    } catch (e) {
      failed++;
      console.log(`${name}: PAGE FAILED: ${e.message}`);
    }
  }
} finally {
  await browser.close();
}
console.log(`largest page: ${largest.name}, ${(largest.bytes / 1e6).toFixed(2)} MB`);
console.log(`${problems.length - failed} passed, ${failed} failed`);
process.exit(failed === 0 ? 0 : 1);
