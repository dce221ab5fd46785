// The page: a form that builds a scene, the module (in a worker) that runs
// it as `persson run` does, and the report drawn as tables and plots.
import { draw, format, suitsLog } from "./plot.js";

const $ = (id) => document.getElementById(id);
const form = $("form");
let worker = null, ready = null, pending = new Map(), nextId = 1, onProgress = null;

// ---------------------------------------------------------------- the module
function startWorker() {
  worker = new Worker("worker.js");
  ready = new Promise((resolve) => {
    worker.onmessage = (e) => {
      const m = e.data;
      if (m.type === "ready") resolve();
      else if (m.type === "progress" && onProgress) onProgress(m);
      else if (m.type === "result") {
        const done = pending.get(m.id);
        pending.delete(m.id);
        if (done) done.resolve(m);
      }
    };
  });
  worker.onerror = (e) => showGeneral(`the module could not be loaded: ${e.message || e}`);
}

// Run `scene` (its text) with `files` ([{name, bytes}]) in the module.
export function compute(scene, files) {
  const id = nextId++;
  return ready.then(() => new Promise((resolve, reject) => {
    pending.set(id, { resolve, reject });
    worker.postMessage({ id, files, scene });
  }));
}

function stopWorker() {
  worker.terminate();
  for (const p of pending.values()) p.reject(new Error("stopped"));
  pending.clear();
  startWorker();
}

// ---------------------------------------------------------------- the form
function shown(group, value) {
  for (const d of document.querySelectorAll(`[data-${group}]`)) d.hidden = d.dataset[group] !== value;
}
for (const [name, group] of [["kind", "kind"], ["material", "material"], ["rubber", "rubber"]]) {
  for (const r of document.getElementsByName(name)) r.addEventListener("change", () => shown(group, r.value));
}
const radio = (name) => document.querySelector(`input[name=${name}]:checked`).value;

// A number when the text is one, else the text itself: the module then
// refuses it with the message `persson run` gives for the same scene.
function value(text) {
  const t = text.trim();
  if (t === "") return undefined;
  const n = Number(t);
  return Number.isFinite(n) && /^[-+]?[\d.]/.test(t) ? n : t;
}
const field = (id) => value($(id).value);
const list = (id) => $(id).value.split(/[,;\s]+/).filter((s) => s !== "").map(value);
const choice = (id) => $(id).value || undefined;

// Leave out what the form leaves empty: the scene then says only what the
// user gave, and the module's defaults (the command line's) fill the rest.
function clean(o) {
  if (Array.isArray(o)) return o.length ? o.map(clean) : undefined;
  if (o && typeof o === "object") {
    const r = {};
    for (const [k, v] of Object.entries(o)) {
      const c = clean(v);
      if (c !== undefined) r[k] = c;
    }
    return r;
  }
  return o;
}

function spectrum() {
  const kind = radio("kind");
  if (kind === "self_affine") {
    return { kind, hurst: field("hurst"), q_l: field("q_l"), q_r: field("q_r"), q_s: field("q_s"), [$("amplitude").value]: field("amplitude_value") };
  }
  if (kind === "tabulated") {
    return { kind, file: fileName("psd_file"), convention: choice("convention"), size: field("psd_size") };
  }
  const size = list("map_size");
  return {
    kind, file: fileName("map_file"), size: size.length > 1 ? size : size[0],
    height_unit: choice("height_unit"), channel: $("channel").value.trim() || undefined,
    detrend: choice("detrend"), periodic: $("periodic").checked || undefined,
    fill_undefined: $("fill_undefined").checked || undefined,
  };
}

function material() {
  if (radio("material") === "contact_modulus") return { contact_modulus: field("contact_modulus") };
  return { young: field("young"), poisson: field("poisson"), young2: field("young2"), poisson2: field("poisson2") };
}

function rubber() {
  if (radio("rubber") === "sls") {
    return { standard_linear_solid: { instantaneous_modulus: field("sls_e0"), relaxed_modulus: field("sls_einf"), relaxation_time: field("sls_tau") } };
  }
  return { master_curve: fileName("mc_file"), frequency_unit: choice("mc_unit") };
}

const checked = (name) => $(`out-${name}`).checked;

function theoryOutputs() {
  const o = {};
  if (checked("area")) o.area = { theory: choice("area_theory"), yield_stress: field("area_yield") };
  if (checked("magnification")) o.magnification = { nominal_pressure: field("mag_pressure"), points: field("mag_points") };
  if (checked("stress")) o.stress = { start: choice("stress_start"), peak_pressure: field("stress_peak"), zeta: list("stress_zeta"), yield_stress: field("stress_yield") };
  if (checked("separation")) o.separation = {};
  if (checked("conductance")) o.conductance = { conductivity: list("cond_k"), resistivity: list("cond_rho"), gas_conductivity: field("cond_gas"), mean_free_path: field("cond_mfp") };
  if (checked("leakage")) o.leakage = { viscosity: field("leak_eta"), pressure_drop: field("leak_dp"), seal_width: field("leak_w"), seal_length: field("leak_l") };
  if (checked("adhesion")) o.adhesion = { work_of_adhesion: field("adh_dg"), adhesion_range: field("adh_range") };
  if (checked("friction")) o.friction = { velocity_range: { velocity_min: field("fr_vmin"), velocity_max: field("fr_vmax"), points: field("fr_points") } };
  if (checked("spectrum")) o.spectrum = { points: field("sp_points") };
  return o;
}

function bemOutputs() {
  const synthesised = radio("kind") !== "height_map";
  return {
    bem: { grid: synthesised ? field("bem_grid") : undefined, seed: synthesised ? field("bem_seed") : undefined, boundary: choice("bem_boundary"), tolerance: field("bem_tol") },
    area: {},
  };
}

// The scene of the form: `bem` selects the BEM's outputs instead of the theory's.
export function scene(bem = false) {
  const outputs = bem ? bemOutputs() : theoryOutputs();
  const s = { schema: 1, material: material(), spectrum: spectrum(), nominal_pressure: list("nominal_pressure"), outputs };
  if (!bem && outputs.friction) s.rubber = rubber();
  return JSON.stringify(clean(s), null, 2) + "\n";
}

function fileName(id) {
  const f = $(id).files[0];
  return f ? f.name : undefined;
}

async function files() {
  const out = [];
  for (const id of ["psd_file", "map_file", "mc_file"]) {
    const f = $(id).files[0];
    if (f && !$(id).closest("[hidden]")) out.push({ name: f.name, bytes: await f.arrayBuffer() });
  }
  return out;
}

// ---------------------------------------------------------------- errors
function clearErrors() {
  for (const e of document.querySelectorAll(".error")) e.textContent = "";
  for (const e of document.querySelectorAll("[aria-invalid]")) e.removeAttribute("aria-invalid");
  for (const e of document.querySelectorAll(".field-error")) e.remove();
}

function showGeneral(text) {
  $("err-general").textContent = text;
}

// The error next to the input of the field it names (the longest field
// named), else under the results' heading.
function showError(message) {
  let best = null, length = 0;
  // A type error quotes the text it could not read: the field that holds it.
  const quoted = message.match(/^scene\.json:\d+:\d+: invalid type: string "(.*)"/);
  const byKey = (input) => quoted && input.type !== "file" && input.value.trim() === quoted[1];
  for (const input of form.querySelectorAll("[data-field]")) {
    if (input.closest("[hidden]")) continue;
    for (const f of input.dataset.field.split(" ")) {
      const names = [f];
      if (input.type === "file" && input.files[0]) names.push(input.files[0].name);
      for (const n of names) if (message.includes(n) && n.length > length) { best = input; length = n.length; }
    }
    if (!best && byKey(input)) best = input;
  }
  showGeneral(`persson: error: ${message}`);
  if (!best) return;
  const p = document.createElement("p");
  p.className = "error field-error";
  p.id = `err-for-${best.id}`;
  p.setAttribute("role", "alert");
  p.textContent = message;
  best.setAttribute("aria-invalid", "true");
  best.setAttribute("aria-describedby", p.id);
  best.insertAdjacentElement("afterend", p);
}

// ---------------------------------------------------------------- results
const PREFERRED = ["contact_fraction", "scaled_density", "density", "c", "friction_coefficient", "mean_separation",
  "thermal_conductance", "electrical_conductance", "gap_conductance", "leak_rate_critical_junction", "effective_interfacial_energy"];
const EXTRA = {
  area: ["contact_fraction_bush_linear", "contact_fraction_persson_linear"],
  leakage: ["leak_rate_effective_medium"],
  conductance: ["electrical_conductance", "gap_conductance"],
};

// Quantities of a table drawn in a figure of their own (another scale).
const ALSO = { magnification: ["g"], separation: ["stiffness"], friction: ["contact_fraction"] };

// The x axis of a table: its first column, or the one named here; the
// columns before it (temperature, pressure) make one curve per value.
const X = { friction: "velocity", friction_decades: "velocity" };
// The y axis where the first preferred quantity is not the table's point.
const Y = { friction: "friction_coefficient", friction_decades: "friction_coefficient" };

// A table's curves of column `k`: one per value of the columns before x.
function curves(t, k, name) {
  const xi = Math.max(0, t.keys.indexOf(X[t.name] || t.keys[0]));
  const yi = t.keys.indexOf(k);
  const by = new Map();
  for (const r of t.rows) {
    const key = r.slice(0, xi).map((v) => (typeof v === "number" ? format(v) : v)).join(", ");
    const label = r.slice(0, xi).map((v, i) => `${t.headings[i].split(" ")[0]} ${typeof v === "number" ? format(v) : v}`).join(", ");
    if (!by.has(key)) by.set(key, { name: key ? label : name, x: [], y: [] });
    const c = by.get(key);
    c.x.push(typeof r[xi] === "number" ? r[xi] : NaN);
    c.y.push(typeof r[yi] === "number" ? r[yi] : NaN);
  }
  return { xLabel: t.headings[xi], series: [...by.values()] };
}

// The figures of a report: a table's curve (or a family of tables with the
// same columns), and A/A0 of the theory beside the BEM's.
function figures(tables) {
  const figs = [];
  const groups = new Map();
  for (const t of tables) {
    if (t.rows.length < 2 || !t.rows[0].some((v) => typeof v === "number")) continue;
    const stem = t.name.split("_")[0];
    const key = `${stem}|${t.keys.join(",")}`;
    if (!groups.has(key)) groups.set(key, []);
    groups.get(key).push(t);
  }
  for (const group of groups.values()) {
    const t = group[0], stem = t.name.split("_")[0], family = group.length > 1;
    const xKey = X[t.name] || t.keys[0];
    const yKey = Y[t.name] || PREFERRED.find((k) => t.keys.includes(k) && k !== xKey) || t.keys.find((k) => k !== xKey);
    if (!yKey) continue;
    const heading = (k) => t.headings[t.keys.indexOf(k)];
    const keys = family ? [yKey] : [yKey, ...(EXTRA[t.name] || []).filter((k) => t.keys.includes(k))];
    const parts = family
      ? group.map((g) => curves(g, yKey, g.name.slice(stem.length + 1)))
      : keys.map((k) => curves(t, k, heading(k)));
    // A title's last line says what the table holds (the first may name the surface).
    const title = family ? stem : t.title.trim().split("\n").pop();
    figs.push({ name: family ? stem : t.name, title, xLabel: parts[0].xLabel, yLabel: heading(yKey), series: parts.flatMap((p) => p.series) });
    for (const k of family ? [] : (ALSO[t.name] || []).filter((k) => t.keys.includes(k) && k !== yKey)) {
      const c = curves(t, k, heading(k));
      figs.push({ name: `${t.name}_${k}`, title, xLabel: c.xLabel, yLabel: heading(k), series: c.series });
    }
  }
  const area = tables.find((t) => t.name === "area"), bem = tables.find((t) => t.name === "bem_rough");
  if (area && bem) {
    figs.unshift({
      name: "area_theory_bem", title: "A/A0: Persson's theory and the FFT-BEM", xLabel: area.headings[0], yLabel: "A/A0",
      series: [curves(area, "contact_fraction", "theory").series[0], curves(bem, "contact_fraction", "BEM").series[0]],
    });
  }
  for (const f of figs) {
    f.logX = suitsLog(f.series.flatMap((s) => s.x));
    f.logY = suitsLog(f.series.flatMap((s) => s.y));
  }
  return figs;
}

function download(name, text, type) {
  const a = document.createElement("a");
  a.href = URL.createObjectURL(new Blob([text], { type }));
  a.download = name;
  a.textContent = name;
  return a;
}

function figureElement(fig) {
  const box = document.createElement("figure");
  box.dataset.figure = fig.name;
  const render = () => {
    const svg = draw(fig);
    const old = box.querySelector("svg");
    if (old) old.replaceWith(svg); else box.prepend(svg);
    return svg;
  };
  render();
  const caption = document.createElement("figcaption");
  for (const axis of ["X", "Y"]) {
    const label = document.createElement("label");
    const box2 = document.createElement("input");
    box2.type = "checkbox";
    box2.checked = fig[`log${axis}`];
    box2.addEventListener("change", () => { fig[`log${axis}`] = box2.checked; render(); });
    label.append(box2, ` log ${axis.toLowerCase()}`);
    caption.append(label, " ");
  }
  const save = document.createElement("button");
  save.type = "button";
  save.textContent = `download ${fig.name}.svg`;
  save.addEventListener("click", () => {
    const svg = box.querySelector("svg").cloneNode(true);
    svg.setAttribute("xmlns", "http://www.w3.org/2000/svg");
    download(`${fig.name}.svg`, svg.outerHTML, "image/svg+xml").click();
  });
  caption.append(save);
  box.append(caption);
  return box;
}

function show(outcome, sceneText, ms) {
  const done = outcome;
  $("status").textContent = `computed in ${ms < 10 ? ms.toFixed(1) : Math.round(ms)} ms`;
  const warnings = $("warnings");
  warnings.replaceChildren(...done.warnings.map((w) => {
    const li = document.createElement("li");
    li.textContent = `persson: warning: ${w}`;
    return li;
  }));
  const downloads = $("downloads");
  downloads.replaceChildren("Download: ",
    download("scene.json", sceneText, "application/json"), " ",
    download("report.json", JSON.stringify(done.report, null, 2) + "\n", "application/json"), " ",
    ...done.tables.filter((t) => t.rows.length || t.scalars.length).flatMap((t) => [download(`${t.name}.csv`, t.csv, "text/csv"), " "]));
  $("figures").replaceChildren(...figures(done.tables).map(figureElement));
  const pre = document.createElement("pre");
  pre.id = "text";
  pre.setAttribute("aria-label", "The report as persson run prints it");
  pre.tabIndex = 0;
  pre.textContent = done.text;
  $("tables").replaceChildren(pre);
}

async function runScene(bem) {
  clearErrors();
  const text = scene(bem);
  let result;
  try {
    result = await compute(text, await files());
  } catch (e) {
    if (e.message === "stopped") { $("status").textContent = "stopped"; return null; }
    throw e;
  }
  if (result.outcome.status === "error") {
    $("status").textContent = "not computed";
    showError(result.outcome.error);
    return result;
  }
  show(result.outcome, text, result.ms);
  return result;
}

form.addEventListener("submit", async (e) => {
  e.preventDefault();
  $("status").textContent = "computing…";
  await runScene(false);
});

$("bem_run").addEventListener("click", async () => {
  const grid = Number($("bem_grid").value);
  clearErrors();
  if (radio("kind") !== "height_map" && Number.isFinite(grid) && grid > 256) {
    const m = `outputs.bem.grid = ${grid}: at most 256 in the browser (the command line solves larger grids)`;
    showError(m);
    return;
  }
  $("bem_run").disabled = true;
  $("bem_stop").disabled = false;
  $("bem_progress").value = 0;
  $("bem_status").textContent = "starting…";
  $("status").textContent = "solving the BEM…";
  onProgress = (p) => {
    $("bem_progress").value = (p.step + Math.min(p.iteration, 50) / 50) / p.steps;
    $("bem_status").textContent = `load ${p.step + 1} of ${p.steps}, iteration ${p.iteration}, ε = ${p.residual.toExponential(1)}`;
  };
  try {
    const r = await runScene(true);
    if (r && r.outcome.status === "ok") $("bem_progress").value = 1;
    if (r) $("bem_status").textContent = r.outcome.status === "ok" ? `solved in ${(r.ms / 1000).toFixed(2)} s` : "";
  } finally {
    onProgress = null;
    $("bem_run").disabled = false;
    $("bem_stop").disabled = true;
  }
});

$("bem_stop").addEventListener("click", () => {
  stopWorker();
  $("bem_status").textContent = "stopped";
});

startWorker();
const t0 = performance.now();
ready.then(async () => {
  $("status").textContent = "computing…";
  const r = await runScene(false);
  if (r) document.body.dataset.firstResultMs = String(performance.now() - t0);
  document.body.dataset.ready = "true";
});
