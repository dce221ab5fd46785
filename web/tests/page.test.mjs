// The page in a real headless Chromium (scripts/test-web runs it):
// it loads from a local static server, computes the example on load, takes
// a real instrument file, runs the BEM, and every number it shows equals
// `persson run` on the scene it offers for download; bad input shows the
// command line's error next to the field; no console error; axe-core finds
// no serious accessibility issue.
//
//   node web/tests/page.test.mjs <page dir> <persson binary> <node_modules dir>
import { createServer } from "node:http";
import { readFile, writeFile, mkdtemp, copyFile, readdir } from "node:fs/promises";
import { execFileSync, spawnSync } from "node:child_process";
import { createRequire } from "node:module";
import { tmpdir } from "node:os";
import path from "node:path";
import assert from "node:assert/strict";

const [pageDir, persson, modules] = process.argv.slice(2).map((p) => path.resolve(p));
const require = createRequire(path.join(modules, "x.js"));
const { chromium } = require("playwright-core");
const axeSource = await readFile(require.resolve("axe-core/axe.min.js"), "utf8");
const repo = path.resolve(path.dirname(new URL(import.meta.url).pathname), "../..");
const TYPES = { ".html": "text/html", ".js": "text/javascript", ".css": "text/css", ".wasm": "application/wasm" };

// ------------------------------------------------------------ static server
const server = createServer(async (req, res) => {
  const name = new URL(req.url, "http://x").pathname.replace(/^\/$/, "/index.html");
  try {
    const body = await readFile(path.join(pageDir, path.normalize(name)));
    res.writeHead(200, { "content-type": TYPES[path.extname(name)] || "application/octet-stream" });
    res.end(body);
  } catch {
    res.writeHead(404);
    res.end();
  }
});
await new Promise((r) => server.listen(0, "127.0.0.1", r));
const url = `http://127.0.0.1:${server.address().port}/`;

// ------------------------------------------------------------ the browser
const browser = await chromium.launch({
  executablePath: process.env.CHROMIUM || "/usr/bin/chromium",
  args: ["--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run", "--disable-background-networking",
    "--disable-component-update", "--disable-sync"],
});
const page = await browser.newPage({ viewport: { width: 1280, height: 1600 } });
const consoleErrors = [];
page.on("console", (m) => { if (m.type() === "error") consoleErrors.push(m.text()); });
page.on("pageerror", (e) => consoleErrors.push(String(e)));

let failures = 0, dumps = 0;
async function check(name, f) {
  try {
    await f();
    console.log(`ok   ${name}`);
  } catch (e) {
    failures++;
    console.log(`FAIL ${name}\n     ${String(e.stack || e).split("\n").join("\n     ")}`);
  }
}

// `persson run scene.json` in a fresh folder holding the scene and `files`.
async function cli(sceneText, files = []) {
  const dir = await mkdtemp(path.join(tmpdir(), "persson-web-"));
  await writeFile(path.join(dir, "scene.json"), sceneText);
  for (const f of files) await copyFile(f, path.join(dir, path.basename(f)));
  const t0 = performance.now();
  const r = spawnSync(persson, ["run", "scene.json"], { cwd: dir, encoding: "utf8" });
  return { ...r, ms: performance.now() - t0 };
}

const downloaded = (name) => page.evaluate(async (n) => {
  const a = document.querySelector(`#downloads a[download="${n}"]`);
  return a ? (await fetch(a.href)).text() : null;
}, name);
const shownText = () => page.$eval("#text", (e) => e.textContent);
const status = () => page.$eval("#status", (e) => e.textContent);

// Compute the form. Two runs may end with the same status (`computed in
// 12 ms` twice), so the status is cleared first and the wait is for this
// run's: set to "computing…" by the click, then to its outcome.
async function compute() {
  await page.$eval("#status", (e) => { e.textContent = ""; });
  await page.click("#run");
  await page.waitForFunction(() => {
    const s = document.getElementById("status").textContent;
    return s !== "" && !/computing/.test(s);
  });
}

// One unit in the last digit a number is printed with (`2.8e-13` → 1e-14).
function lastDigit(token) {
  const m = token.match(/^[-+]?(\d*)\.?(\d*)(?:e([-+]?\d+))?$/);
  return m ? 10 ** (Number(m[3] || 0) - m[2].length) : 0;
}

// The page's text equals the command line's to the digits shown. A value
// that is rounding noise (an error bound of 1e-13) may differ by one unit
// in its last digit: the module's exp and log (Rust's libm, compiled into
// it) and the system's (glibc) round differently in the last bit. Those
// cells are counted and printed.
let lastDigitCells = 0, cellsCompared = 0;
function sameDigits(page, cli) {
  const a = page.split("\n"), b = cli.split("\n");
  assert.equal(a.length, b.length, "as many lines");
  a.forEach((line, i) => {
    if (line === b[i]) { cellsCompared += line.split(/\s+/).length; return; }
    const ta = line.trim().split(/\s+/), tb = b[i].trim().split(/\s+/);
    assert.equal(ta.length, tb.length, `line ${i + 1}: ${line} | ${b[i]}`);
    ta.forEach((t, k) => {
      cellsCompared++;
      if (t === tb[k]) return;
      const unit = lastDigit(t);
      const close = unit > 0 && unit === lastDigit(tb[k]) && Math.abs(Number(t) - Number(tb[k])) <= 1.0001 * unit;
      assert.ok(close, `line ${i + 1}: ${t} shown, persson run prints ${tb[k]}`);
      lastDigitCells++;
      console.log(`     last digit: line ${i + 1}, ${t} in the page, ${tb[k]} from persson run`);
    });
  });
}

async function sameAsCli(files = []) {
  const scene = await downloaded("scene.json");
  assert.ok(scene, "the page offers scene.json");
  const r = await cli(scene, files);
  assert.equal(r.status, 0, `persson run failed: ${r.stderr}`);
  // The solvers' times differ run to run: their column is compared as a number of digits.
  const times = (t) => t.replace(/(\d+\s+\S+e-\d+\s+)\d+\.\d+$/gm, "$1[time]");
  const shown = await shownText();
  if (process.env.PERSSON_WEB_DUMP) {
    await writeFile(`${process.env.PERSSON_WEB_DUMP}.${++dumps}.page`, shown);
    await writeFile(`${process.env.PERSSON_WEB_DUMP}.${dumps}.cli`, r.stdout);
  }
  sameDigits(times(shown), times(r.stdout));
  const warnings = await page.$$eval("#warnings li", (ls) => ls.map((l) => l.textContent));
  const cliWarnings = r.stderr.split("\n").filter((l) => l.startsWith("persson: warning: "));
  assert.deepEqual(warnings, cliWarnings);
  return r;
}

async function plotsDrawn() {
  const paths = await page.$$eval("#figures svg path.series", (ps) => ps.map((p) => p.getAttribute("d").length));
  assert.ok(paths.length > 0 && paths.every((n) => n > 20), `plots drawn: ${paths}`);
}

// ------------------------------------------------------------ the tests
const t0 = performance.now();
await page.goto(url);
await page.waitForSelector("body[data-ready=true]", { timeout: 60000 });
const loadMs = performance.now() - t0;
const firstMs = Number(await page.$eval("body", (b) => b.dataset.firstResultMs));
console.log(`     the example's A/A0 curve ${firstMs.toFixed(0)} ms after the page's script started (${loadMs.toFixed(0)} ms from navigation)`);

await check("the example on load equals persson run", async () => {
  assert.match(await status(), /^computed in/);
  await sameAsCli();
  await plotsDrawn();
  const svgs = await page.$$eval("#figures svg", (s) => s.length);
  assert.ok(svgs >= 2, `figures: ${svgs}`);
  await page.screenshot({ path: path.join(path.dirname(modules), "page.png"), fullPage: false });
});

await check("hover shows the value under the pointer", async () => {
  const svg = await page.$("#figures svg");
  const box = await svg.boundingBox();
  const circle = await page.$("#figures svg circle");
  const c = await circle.boundingBox();
  await page.mouse.move(c.x + c.width / 2, c.y + c.height / 2);
  const tip = await page.$eval("#figures svg g[visibility] text", (t) => t.textContent);
  assert.match(tip, /=/, `tooltip: ${tip}`);
  assert.ok(box.width > 100);
});

await check("a bad field shows the CLI's error next to it, nothing computed", async () => {
  await page.fill("#contact_modulus", "-1");
  await compute();
  const shown = await page.$eval("#err-for-contact_modulus", (e) => e.textContent);
  const general = await page.$eval("#err-general", (e) => e.textContent);
  // The scene the page ran: rebuild it as the form says and run it natively.
  const sceneText = await page.evaluate(async () => (await import("./app.js")).scene(false));
  const r = await cli(sceneText);
  assert.notEqual(r.status, 0);
  const cliLine = r.stderr.split("\n").find((l) => l.startsWith("persson: error: "));
  assert.equal(general, cliLine);
  assert.equal(`persson: error: ${shown}`, cliLine);
  assert.match(shown, /material\.contact_modulus/);
  assert.equal(await status(), "not computed");
});

await check("a field that is not a number: the CLI's message, under that field", async () => {
  await page.fill("#hurst", "0.8x");
  try {
    await compute();
    const shown = await page.$eval("#err-for-hurst", (e) => e.textContent);
    const sceneText = await page.evaluate(async () => (await import("./app.js")).scene(false));
    const r = await cli(sceneText);
    const cliLine = r.stderr.split("\n").find((l) => l.startsWith("persson: error: "));
    assert.equal(`persson: error: ${shown}`, cliLine);
    assert.match(shown, /^scene\.json:\d+:\d+: invalid type: string "0\.8x"/);
  } finally {
    await page.fill("#hurst", "0.8");
  }
});

await check("the page is usable after an error", async () => {
  await page.fill("#contact_modulus", "1e9");
  await compute();
  assert.match(await status(), /^computed in/);
  assert.equal(await page.$$eval(".field-error", (e) => e.length), 0);
  await sameAsCli();
});

const frt = path.join(repo, "tests/data/frt-2.frt");
await check("a real instrument file (FRT MicroProf .frt): its error, then its numbers", async () => {
  await page.check("input[name=kind][value=height_map]");
  await page.setInputFiles("#map_file", frt);
  await page.check("#out-spectrum");
  await compute();
  const shown = await page.$eval("#err-for-map_file", (e) => e.textContent);
  assert.match(shown, /undefined/);
  await page.check("#fill_undefined");
  await compute();
  assert.match(await status(), /^computed in/);
  const r = await sameAsCli([frt]);
  assert.match(r.stdout, /frt-2\.frt/);
  await plotsDrawn();
});

await check("every file of tests/data reads in the browser as persson run reads it", async () => {
  const dir = path.join(repo, "tests/data");
  const names = (await readdir(dir)).filter((n) => !/^(README|LICENSE)/.test(n)).sort();
  let read = 0;
  const refused = [];
  // Each file as it is, and where that is refused, with a unit and a size given.
  const tries = names.flatMap((name) => [[name, {}], [name, { height_unit: "um", size: 1e-4 }]]);
  const readNames = new Set();
  for (const [name, extra] of tries) {
    if (readNames.has(name)) continue;
    const file = path.join(dir, name);
    const scene = JSON.stringify({ schema: 1, spectrum: { kind: "height_map", file: name, fill_undefined: true, ...extra }, outputs: { spectrum: {} } }, null, 2) + "\n";
    const bytes = (await readFile(file)).toString("base64");
    const { outcome } = await page.evaluate(async ({ scene, name, bytes }) => {
      const raw = Uint8Array.from(atob(bytes), (c) => c.charCodeAt(0));
      return (await import("./app.js")).compute(scene, [{ name, bytes: raw.buffer }]);
    }, { scene, name, bytes });
    const r = await cli(scene, [file]);
    if (r.status === 0) {
      assert.equal(outcome.status, "ok", `${name}: ${outcome.error}`);
      sameDigits(outcome.text, r.stdout);
      read++;
      readNames.add(name);
    } else {
      const cliLine = r.stderr.split("\n").find((l) => l.startsWith("persson: error: "));
      assert.equal(`persson: error: ${outcome.error}`, cliLine, name);
      if (Object.keys(extra).length) refused.push(name);
    }
  }
  console.log(`     ${names.length} files: ${read} read alike, ${refused.length} refused with the same message (${refused.join(", ")})`);
  assert.ok(read >= 40, `read: ${read}`);
});

await check("a truncated file is an error naming it; the page stays usable", async () => {
  const bytes = await readFile(frt);
  const cut = path.join(await mkdtemp(path.join(tmpdir(), "persson-web-")), "truncated.frt");
  await writeFile(cut, bytes.subarray(0, 3000));
  await page.setInputFiles("#map_file", cut);
  await compute();
  const shown = await page.$eval("#err-for-map_file", (e) => e.textContent);
  const sceneText = await page.evaluate(async () => (await import("./app.js")).scene(false));
  const r = await cli(sceneText, [cut]);
  const cliLine = r.stderr.split("\n").find((l) => l.startsWith("persson: error: "));
  assert.equal(`persson: error: ${shown}`, cliLine);
  assert.match(shown, /truncated\.frt/);
  // A format no reader knows: the CLI's message, naming the file.
  const odd = path.join(path.dirname(cut), "scan.vk4");
  await writeFile(odd, Buffer.from("VK4_\0\0\0\0 not really a Keyence file"));
  await page.setInputFiles("#map_file", odd);
  await compute();
  const unknown = await page.$eval("#err-for-map_file", (e) => e.textContent);
  const r2 = await cli(await page.evaluate(async () => (await import("./app.js")).scene(false)), [odd]);
  assert.equal(`persson: error: ${unknown}`, r2.stderr.split("\n").find((l) => l.startsWith("persson: error: ")));
  assert.match(unknown, /scan\.vk4/);
  await page.setInputFiles("#map_file", frt);
  await compute();
  assert.match(await status(), /^computed in/);
});

await check("every output of the form computes and equals persson run", async () => {
  await page.check("input[name=kind][value=self_affine]");
  for (const o of ["stress", "separation", "conductance", "leakage", "adhesion", "friction"]) await page.check(`#out-${o}`);
  await compute();
  assert.match(await status(), /^computed in/, await page.$eval("#err-general", (e) => e.textContent));
  await sameAsCli();
  await plotsDrawn();
  for (const name of ["stress", "separation", "conductance", "leakage", "adhesion", "friction"]) {
    const has = await page.$$eval("#figures figure", (fs, n) => fs.some((f) => f.dataset.figure.startsWith(n)), name);
    assert.ok(has, `a figure of ${name}`);
  }
  for (const s of ["hertz", "cylinder"]) {
    await page.selectOption("#stress_start", s);
    await compute();
    assert.match(await status(), /^computed in/, await page.$eval("#err-general", (e) => e.textContent));
    await sameAsCli();
  }
  for (const o of ["stress", "separation", "conductance", "leakage", "adhesion", "friction"]) await page.uncheck(`#out-${o}`);
});

await check("a tabulated spectrum and a master curve, from files", async () => {
  const psd = path.join(repo, "tests/reference/data/psd_second_body.csv");
  const curve = path.join(repo, "tests/reference/data/rubber_master_curve.csv");
  await page.check("input[name=kind][value=tabulated]");
  await page.setInputFiles("#psd_file", psd);
  await page.check("#out-friction");
  await page.check("input[name=rubber][value=master_curve]");
  await page.setInputFiles("#mc_file", curve);
  await compute();
  assert.match(await status(), /^computed in/, await page.$eval("#err-general", (e) => e.textContent));
  await sameAsCli([psd, curve]);
  await plotsDrawn();
  await page.uncheck("#out-friction");
  await page.check("input[name=kind][value=self_affine]");
});

await check("a BEM grid too large for the browser is refused next to the field", async () => {
  await page.fill("#bem_grid", "512");
  await page.click("#bem_run");
  const shown = await page.$eval("#err-for-bem_grid", (e) => e.textContent);
  assert.match(shown, /outputs\.bem\.grid = 512: at most 256/);
});

let bemBrowserMs = null, bemNativeMs = null;
await check("the BEM at 128² with progress equals persson run", async () => {
  await page.fill("#bem_grid", "128");
  const progressSeen = page.waitForFunction(() => /iteration/.test(document.getElementById("bem_status").textContent), null, { timeout: 60000 });
  await page.click("#bem_run");
  await progressSeen;
  await page.waitForFunction(() => /solved|stopped/.test(document.getElementById("bem_status").textContent) || document.getElementById("err-general").textContent, null, { timeout: 120000 });
  assert.match(await page.$eval("#bem_status", (e) => e.textContent), /solved/);
  await sameAsCli();
  // The solves' own times (the report's `seconds`), browser against native.
  const solves = (report) => 1e3 * report.bem.points.reduce((s, p) => s + p.seconds, 0);
  const scene = await downloaded("scene.json");
  const dir = await mkdtemp(path.join(tmpdir(), "persson-web-"));
  await writeFile(path.join(dir, "scene.json"), scene);
  bemBrowserMs = solves(JSON.parse(await downloaded("report.json")));
  bemNativeMs = solves(JSON.parse(execFileSync(persson, ["run", "scene.json", "--json"], { cwd: dir, encoding: "utf8", stdio: ["ignore", "pipe", "ignore"] })));
  // PERSSON_WEB_BENCH=K: the same scene K more times each way, the best and the median.
  const k = Number(process.env.PERSSON_WEB_BENCH || 0);
  if (k > 0) {
    const web = [], native = [];
    for (let i = 0; i < k; i++) {
      const { outcome } = await page.evaluate(async (s) => (await import("./app.js")).compute(s, []), scene);
      web.push(solves(outcome.report));
      native.push(solves(JSON.parse(execFileSync(persson, ["run", "scene.json", "--json"], { cwd: dir, encoding: "utf8", stdio: ["ignore", "pipe", "ignore"] }))));
    }
    const stat = (v) => { const s = [...v].sort((a, b) => a - b); return [s[0], s[s.length >> 1]]; };
    const [wb, wm] = stat(web), [nb, nm] = stat(native);
    console.log(`     bench, ${k} runs each: browser best ${wb.toFixed(0)} ms, median ${wm.toFixed(0)} ms; native best ${nb.toFixed(0)} ms, median ${nm.toFixed(0)} ms; ratio of bests ${(wb / nb).toFixed(2)}, of medians ${(wm / nm).toFixed(2)}`);
  }
  await plotsDrawn();
  const titles = await page.$$eval("#figures svg title", (ts) => ts.map((t) => t.textContent));
  assert.ok(titles.some((t) => /theory and the FFT-BEM/.test(t)), titles.join("; "));
});

await check("the BEM can be stopped, and the page computes again", async () => {
  await page.fill("#bem_grid", "256");
  await page.fill("#bem_tol", "1e-12");
  await page.click("#bem_run");
  await page.waitForFunction(() => /iteration/.test(document.getElementById("bem_status").textContent), null, { timeout: 60000 });
  await page.click("#bem_stop");
  assert.equal(await page.$eval("#bem_status", (e) => e.textContent), "stopped");
  await page.fill("#bem_grid", "128");
  await page.fill("#bem_tol", "1e-10");
  await compute();
  assert.match(await status(), /^computed in/);
});

await check("the BEM on the user's own map (WSxM .top, 256²) equals persson run", async () => {
  const top = path.join(repo, "tests/data/top-1.top");
  await page.check("input[name=kind][value=height_map]");
  await page.setInputFiles("#map_file", top);
  await page.uncheck("#fill_undefined");
  await page.click("#bem_run");
  await page.waitForFunction(() => /solved|stopped/.test(document.getElementById("bem_status").textContent) || document.getElementById("err-general").textContent, null, { timeout: 120000 });
  assert.match(await page.$eval("#bem_status", (e) => e.textContent), /solved/, await page.$eval("#err-general", (e) => e.textContent));
  try {
    const r = await sameAsCli([top]);
    assert.match(r.stdout, /top-1\.top/);
  } finally {
    await page.check("input[name=kind][value=self_affine]");
  }
});

await check("downloads: scene, report and CSV", async () => {
  const report = JSON.parse(await downloaded("report.json"));
  assert.ok(report.area, "report.json has the area");
  const csv = await downloaded("area.csv");
  assert.match(csv, /^nominal_pressure,/);
});

await check("axe-core: no serious or critical accessibility finding", async () => {
  await page.addScriptTag({ content: axeSource });
  const result = await page.evaluate(async () => await window.axe.run(document));
  const bad = result.violations.filter((v) => v.impact === "serious" || v.impact === "critical");
  assert.deepEqual(bad.map((v) => `${v.id}: ${v.nodes.map((n) => n.target.join(" ")).join(", ")}`), []);
});

await check("every input has a label (keyboard and screen reader)", async () => {
  const unlabelled = await page.$$eval("input, select, button", (els) => els
    .filter((e) => !e.closest("[hidden]") && !(e.labels && e.labels.length) && !e.getAttribute("aria-label") && !e.textContent.trim())
    .map((e) => e.id || e.outerHTML));
  assert.deepEqual(unlabelled, []);
  await page.focus("#hurst");
  await page.keyboard.press("Tab");
  const next = await page.evaluate(() => document.activeElement.id);
  assert.equal(next, "q_l");
});

await check("no console error", async () => assert.deepEqual(consoleErrors, []));

console.log(`     ${cellsCompared} cells compared with persson run; ${lastDigitCells} differ by one unit in the last digit`);
if (bemBrowserMs !== null) {
  console.log(`     BEM 128², its six solves: ${bemBrowserMs.toFixed(0)} ms in the browser, ${bemNativeMs.toFixed(0)} ms in the native persson run, ratio ${(bemBrowserMs / bemNativeMs).toFixed(2)}`);
}
await browser.close();
server.close();
console.log(failures ? `${failures} failed` : "all passed");
process.exit(failures ? 1 : 0);
