// What the browser tests share: running `adsd`, headless Debian chromium through playwright-core,
// and the checks every viewer page must pass (tests/browser/README.md).
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import { createRequire } from 'node:module';
import os from 'node:os';
import path from 'node:path';
import { pathToFileURL } from 'node:url';

const here = path.dirname(new URL(import.meta.url).pathname);
// playwright-core is installed with three by `npm ci` in viewer/ (cmake/install-debian-deps.sh).
const require = createRequire(path.join(here, '..', '..', 'viewer', 'package.json'));
const { chromium } = require('playwright-core');

export const adsd = process.env.ADSD ?? 'build/planner/app/adsd';
export const problemsDir = process.env.ADSD_PROBLEMS ?? 'build/problem_files';
export const outDir = process.env.ADSD_BROWSER_OUT ?? fs.mkdtempSync(path.join(os.tmpdir(), 'adsd-browser-'));
fs.mkdirSync(outDir, { recursive: true });

/** Runs adsd; returns { status, stdout, stderr }. */
export function run(args) {
  const r = spawnSync(adsd, args, { encoding: 'utf8', timeout: 600_000 });
  if (r.error) throw r.error;
  return { status: r.status, stdout: r.stdout, stderr: r.stderr };
}

/** The "clearance   min X" that `adsd plan` and `adsd view` print. */
export function printedMinClearance(stdout) {
  const m = /^clearance\s+min\s+(\S+?),?\s/m.exec(stdout);
  assert.ok(m, `no clearance line in:\n${stdout}`);
  return Number(m[1]);
}

/**
 * Start or goal of a .cfg, read here from the file itself (not through adsd): position and the
 * quaternion [x, y, z, w] of yaw theta about z (SE(2)) or of angle theta about the axis (SE(3)).
 */
export function cfgPose(cfgFile, which) {
  const values = {};
  for (const line of fs.readFileSync(cfgFile, 'utf8').split('\n')) {
    const m = /^\s*(start|goal)\.([\w.]+)\s*=\s*(\S+)/.exec(line);
    if (m && m[1] === which) values[m[2]] = Number(m[3]);
  }
  const half = values.theta / 2;
  let axis = [0, 0, 1];
  if ('axis.x' in values) {
    const n = Math.hypot(values['axis.x'], values['axis.y'], values['axis.z']);
    axis = [values['axis.x'] / n, values['axis.y'] / n, values['axis.z'] / n];
  }
  return {
    position: [values.x, values.y, values.z ?? 0],
    quaternion: [axis[0] * Math.sin(half), axis[1] * Math.sin(half), axis[2] * Math.sin(half), Math.cos(half)],
  };
}

/** Asserts that pose \p actual (from the page) is \p expected: same position (to rounding), same rotation. */
export function assertSamePose(actual, expected, what) {
  const gap = Math.hypot(...actual.position.map((v, i) => v - expected.position[i]));
  const tolerance = 1e-9 * (1 + Math.hypot(...expected.position));
  assert.ok(gap <= tolerance, `${what}: position ${actual.position} is ${gap} from ${expected.position}`);
  // q and -q are the same rotation.
  const dot = Math.abs(actual.quaternion.reduce((s, v, i) => s + v * expected.quaternion[i], 0));
  assert.ok(dot >= 1 - 1e-9, `${what}: quaternion ${actual.quaternion} is not ${expected.quaternion} (|dot| ${dot})`);
}

/** Headless Debian chromium with a fresh profile, no network of its own; WebGL through SwiftShader. */
export async function launchBrowser() {
  const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'adsd-chromium-'));
  const context = await chromium.launchPersistentContext(profile, {
    executablePath: '/usr/bin/chromium',
    headless: true,
    viewport: { width: 1100, height: 760 },
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
           '--disable-background-networking', '--disable-component-update', '--disable-sync',
           // WebGL on the CPU (SwiftShader): chromium 156 falls back to it by itself under --disable-gpu,
           // later versions only when asked.
           '--enable-unsafe-swiftshader', '--use-angle=swiftshader'],
  });
  return {
    context,
    async close() {
      await context.close();
      fs.rmSync(profile, { recursive: true, force: true });
    },
  };
}

/**
 * Opens a viewer page from its file:// URL and waits for it to be ready; collects console errors,
 * page errors and every request it makes.
 */
export async function openViewer(browser, htmlFile) {
  const page = await browser.context.newPage();
  const errors = [];
  const requests = [];
  page.on('console', (m) => { if (m.type() === 'error') errors.push(`console: ${m.text()}`); });
  page.on('pageerror', (e) => errors.push(`page: ${e.message}`));
  page.on('request', (r) => requests.push(r.url()));
  await page.goto(pathToFileURL(path.resolve(htmlFile)).href);
  await page.waitForFunction(() => window.adsdViewer?.ready === true, null, { timeout: 60_000 })
    .catch((e) => { throw new Error(`${htmlFile}: the viewer did not get ready (${errors.join('; ')}): ${e.message}`); });
  // Two frames, so that the animation loop has drawn the first state.
  await page.evaluate(() => new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(done))));
  return { page, errors, requests };
}

/**
 * Pixels of the 3D view that differ from the clear colour, and pixels that change when the robot
 * is hidden (the robot really is drawn, wherever it is and whatever covers it).
 */
export async function countPixels(page) {
  return page.evaluate(() => {
    const viewer = window.adsdViewer;
    const source = document.querySelector('#view canvas');
    const copy = document.createElement('canvas');
    copy.width = source.width;
    copy.height = source.height;
    const g = copy.getContext('2d', { willReadFrequently: true });
    const grab = () => {
      g.drawImage(source, 0, 0);
      return g.getImageData(0, 0, copy.width, copy.height).data;
    };
    viewer.showRobot(true);
    const withRobot = grab();
    viewer.showRobot(false);
    const withoutRobot = grab();
    viewer.showRobot(true);
    const [br, bg, bb] = viewer.backgroundColor;
    let drawn = 0, robot = 0;
    for (let i = 0; i < withRobot.length; i += 4) {
      const [r, gr, b] = [withRobot[i], withRobot[i + 1], withRobot[i + 2]];
      if (Math.abs(r - br) + Math.abs(gr - bg) + Math.abs(b - bb) > 24) drawn++;
      if (Math.abs(r - withoutRobot[i]) + Math.abs(gr - withoutRobot[i + 1]) + Math.abs(b - withoutRobot[i + 2]) > 24) robot++;
    }
    return { total: withRobot.length / 4, drawn, robot };
  });
}

/**
 * The checks every viewer page must pass (issues 18 and 17): opens offline without errors, draws
 * the scene and the robot, the slider's End key shows the last state, Play moves along the path
 * and Pause stops it, the plot's minimum is \p expectedMin (as printed, six significant digits),
 * and the witness points are as far apart as the clearance says. \p atStart(page, state) checks
 * the robot at state 0 and \p atEnd(page, state) at the last state. Leaves the robot at the
 * minimum and saves a screenshot to \p screenshot.
 */
export async function checkPage(browser, { html, expectedMin, screenshot, atStart, atEnd }) {
  const { page, errors, requests } = await openViewer(browser, html);
  try {
    const offline = requests.filter((u) => !/^(file|blob|data):/.test(u));
    assert.deepEqual(offline, [], 'the page asked the network');

    const state = await page.evaluate(() => ({
      count: adsdViewer.count, plot: adsdViewer.plot, clearance: adsdViewer.clearance,
      witnessGaps: adsdViewer.clearance.map((c, i) => adsdViewer.witnessDistance(i) - c),
      triangles: adsdViewer.renderedTriangles(), start: adsdViewer.robotPose(),
      sliderMax: Number(document.getElementById('slider').max), diagonal: adsdViewer.sceneDiagonal,
    }));
    assert.ok(state.triangles > 0, 'WebGL drew no triangles');
    const pixels = await countPixels(page);
    assert.ok(pixels.drawn > 0.02 * pixels.total, `only ${pixels.drawn} of ${pixels.total} pixels differ from the background`);
    assert.ok(pixels.robot > 20, `hiding the robot changes only ${pixels.robot} pixels`);

    await atStart(page, state);
    // As a person would: the End key on the focused slider moves it to its last value.
    await page.locator('#slider').press('End');
    assert.equal(await page.evaluate(() => adsdViewer.index), state.count - 1, 'the slider at its end shows the last state');
    await atEnd(page, state);

    // Play from the start: the robot moves along the path by itself.
    if (state.count > 2) {
      await page.evaluate(() => adsdViewer.setIndex(0));
      await page.locator('#play').click();
      await page.waitForFunction(() => adsdViewer.index > 0, null, { timeout: 10_000 });
      await page.locator('#play').click();  // pause
      const paused = await page.evaluate(() => adsdViewer.index);
      await page.waitForTimeout(300);
      assert.equal(await page.evaluate(() => adsdViewer.index), paused, 'Pause stops the robot');
    }

    const least = Math.min(...state.clearance);
    assert.equal(state.plot.min, least, 'the plot marks the least clearance');
    assert.equal(state.clearance[state.plot.minIndex], least);
    assert.ok(Math.abs(state.plot.min - expectedMin) <= 5e-6 * Math.abs(expectedMin) + 1e-300,
              `plot minimum ${state.plot.min}, adsd printed ${expectedMin}`);
    // The witnesses come from adsd's exact distance; the clearance from the checker. Same engine:
    // the same number, to the core's accuracy (1e-10 of the scene's size).
    const worstGap = Math.max(...state.witnessGaps.map(Math.abs));
    assert.ok(worstGap <= 1e-8 * state.diagonal, `witness points are up to ${worstGap} off the clearance`);

    await page.evaluate(() => adsdViewer.setIndex(adsdViewer.plot.minIndex));
    await page.evaluate(() => new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(done))));
    if (screenshot) await page.screenshot({ path: screenshot });
    assert.deepEqual(errors, [], 'console or page errors');
    return state;
  } finally {
    await page.close();
  }
}

/**
 * checkPage() on a rigid robot's page: the robot at the cfg's start at state 0 and at its goal at
 * the last state.
 */
export async function checkViewer(browser, { html, cfg, expectedMin, screenshot }) {
  return checkPage(browser, {
    html, expectedMin, screenshot,
    atStart: async (page, state) => assertSamePose(state.start, cfgPose(cfg, 'start'), 'robot at state 0 vs the cfg start'),
    atEnd: async (page) => assertSamePose(await page.evaluate(() => adsdViewer.robotPose()), cfgPose(cfg, 'goal'),
                                          'robot at the slider end vs the cfg goal'),
  });
}

/**
 * An arm problem's request (MotionBenchMaker's request YAML, as problems/arm/make_arm_problems.py
 * writes it), read here from the file itself: the start's joint positions by name, and each goal
 * joint's position and tolerances.
 */
export function armRequest(cfgFile) {
  const cfg = fs.readFileSync(cfgFile, 'utf8');
  const request = /^\s*request\s*=\s*(.+?)\s*$/m.exec(cfg);
  assert.ok(request, `${cfgFile}: no request key`);
  const text = fs.readFileSync(path.resolve(path.dirname(cfgFile), request[1]), 'utf8');
  const startState = /start_state:[\s\S]*?name:\s*\[([^\]]*)\][\s\S]*?position:\s*\[([^\]]*)\]/.exec(text);
  assert.ok(startState, `${request[1]}: no start_state with name and position lists`);
  const names = startState[1].split(',').map((n) => n.trim().replace(/^'|'$/g, ''));
  const positions = startState[2].split(',').map(Number);
  const start = Object.fromEntries(names.map((n, i) => [n, positions[i]]));
  const goal = {};
  const constraint = /joint_name:\s*'([^']*)'\s*\n\s*position:\s*(\S+)\s*\n\s*tolerance_above:\s*(\S+)\s*\n\s*tolerance_below:\s*(\S+)/g;
  for (const m of text.matchAll(constraint)) goal[m[1]] = { position: Number(m[2]), tolerance: Math.min(Number(m[3]), Number(m[4])) };
  return { start, goal };
}

/** The URDF an arm cfg names, ${ADSD_ROBOTS} expanded as adsd does (default ~/.cache/adsd/robots). */
export function armRobotFile(cfgFile) {
  const robot = /^\s*robot\s*=\s*(.+?)\s*$/m.exec(fs.readFileSync(cfgFile, 'utf8'));
  assert.ok(robot, `${cfgFile}: no robot key`);
  const robots = process.env.ADSD_ROBOTS ?? path.join(os.homedir(), '.cache', 'adsd', 'robots');
  return path.resolve(path.dirname(cfgFile), robot[1].replace('${ADSD_ROBOTS}', robots));
}

/**
 * checkPage() on an arm's page: at state 0 the joints are the request's start and every link is
 * drawn where the start (green) arm is; at the last state the joints are within the goal's
 * tolerance (the path ends within the smallest tolerance in the sum of the joints' changes) and
 * every link's origin within 2 mm of the goal (blue) arm's (0.001 rad in all at most 2 m from the
 * axes: these arms reach about 1 m).
 */
export async function checkArmViewer(browser, { html, cfg, expectedMin, screenshot }) {
  const request = armRequest(cfg);
  const drawn = (page, i) => page.evaluate((k) => ({
    names: adsdViewer.jointNames, joints: adsdViewer.joints(k), links: adsdViewer.bodyPoses(),
    start: adsdViewer.startPoses(), goal: adsdViewer.goalPoses(), bodies: adsdViewer.bodyNames,
  }), i);
  return checkPage(browser, {
    html, expectedMin, screenshot,
    atStart: async (page) => {
      const s = await drawn(page, 0);
      assert.ok(s.bodies.length > 1, `only ${s.bodies.length} link drawn`);
      assert.deepEqual(s.joints, s.names.map((n) => request.start[n]), 'joints at state 0 vs the request start');
      s.links.forEach((p, b) => assertSamePose(p, s.start[b], `link ${s.bodies[b]} at state 0 vs the start arm`));
      // The closest pair is named: a link, or the collision object an obstacle part belongs to
      // (the page said 'obstacle' for every one of them: outside review).
      const names = await page.evaluate(() => adsdViewer.clearance.flatMap((c, i) => adsdViewer.closestBodies(i)));
      assert.ok(names.every((name) => name !== 'obstacle' && name.length > 0), `closest pairs named ${names}`);
    },
    atEnd: async (page, state) => {
      const s = await drawn(page, state.count - 1);
      const off = s.names.reduce((sum, n, j) => sum + Math.abs(s.joints[j] - request.goal[n].position), 0);
      const tolerance = Math.min(...Object.values(request.goal).map((g) => g.tolerance));
      assert.ok(off <= tolerance + 1e-12, `last state's joints ${s.joints} are ${off} from the goal (tolerance ${tolerance})`);
      s.links.forEach((p, b) => {
        const gap = Math.hypot(...p.position.map((v, k) => v - s.goal[b].position[k]));
        assert.ok(gap <= 0.002, `link ${s.bodies[b]} at the last state is ${gap} m from the goal arm's`);
      });
    },
  });
}
