// A viewer page for every shipped problem's solution, each opened offline in headless chromium and
// put through the browser test's checks (viewer_page.mjs): `adsd plan PROBLEM --seed 1 --html`
// with the problem's own planner and time limit. Prints one line per problem and the largest
// and smallest page; exits 1 when a problem is not solved or a page fails a check. Not a ctest (it takes the
// problems' time limits, a few minutes, and cow_doorway needs problems/data/fetch_meshes.sh):
//   ADSD=build/planner/app/adsd ADSD_PROBLEMS=build/problem_files ADSD_BROWSER_OUT=/tmp/viewers \
//     node tests/browser/view_all_problems.mjs [rigid | arm]
// `rigid` takes only the rigid-body problems (ADSD_PROBLEMS), `arm` only the arm problems
// (problems/arm, or ADSD_ARM_PROBLEMS; they need problems/data/fetch_robots.sh); both by default.
import fs from 'node:fs';
import path from 'node:path';

import {
  checkArmViewer, checkViewer, launchBrowser, outDir, printedMinClearance, problemsDir, run,
} from './viewer_page.mjs';

const only = process.argv[2];
if (only !== undefined && only !== 'rigid' && only !== 'arm') {
  console.error(`usage: node view_all_problems.mjs [rigid | arm] (got '${only}')`);
  process.exit(2);
}
const here = path.dirname(new URL(import.meta.url).pathname);
const armProblemsDir = process.env.ADSD_ARM_PROBLEMS ?? path.join(here, '..', '..', 'problems', 'arm');
// [name, cfg, check]: the rigid problems' .cfg files, then each arm problem's folder.
const problems = [
  ...(only === 'arm' ? [] : fs.readdirSync(problemsDir).filter((f) => f.endsWith('.cfg')).sort()
    .map((f) => [path.basename(f, '.cfg'), path.join(problemsDir, f), checkViewer])),
  ...(only === 'rigid' ? [] : fs.readdirSync(armProblemsDir).sort()
    .filter((d) => fs.existsSync(path.join(armProblemsDir, d, 'problem.cfg')))
    .map((d) => [d, path.join(armProblemsDir, d, 'problem.cfg'), checkArmViewer])),
];
const browser = await launchBrowser();
let failed = 0, largest = { bytes: 0 }, smallest = { bytes: Infinity };
try {
  for (const [name, cfg, check] of problems) {
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
      const state = await check(browser, {
        html, cfg, expectedMin: printedMinClearance(plan.stdout), screenshot: path.join(outDir, `${name}.png`) });
      const bytes = fs.statSync(html).size;
      if (bytes > largest.bytes) largest = { name, bytes };
      if (bytes < smallest.bytes) smallest = { name, bytes };
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
console.log(`smallest page: ${smallest.name}, ${(smallest.bytes / 1e6).toFixed(2)} MB; ` +
            `largest page: ${largest.name}, ${(largest.bytes / 1e6).toFixed(2)} MB`);
console.log(`${problems.length - failed} passed, ${failed} failed`);
process.exit(failed === 0 ? 0 : 1);
