// Line plots in SVG: linear or log axes, one or more series, the value
// under the pointer. No library: the page stays one HTML file, its scripts
// and the module.
const NS = "http://www.w3.org/2000/svg";
const W = 560, H = 360, M = { left: 72, right: 24, top: 28, bottom: 48 };
const COLOURS = ["#1f5fa8", "#c2410c", "#15803d", "#7e22ce", "#a16207", "#0e7490", "#be123c"];

function el(name, attrs = {}, text) {
  const e = document.createElementNS(NS, name);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
  if (text !== undefined) e.textContent = text;
  return e;
}

// A tick's label: powers of ten as `1e5`, other values short.
function tick(v, log) {
  if (log) {
    const e = Math.round(Math.log10(v));
    if (Math.abs(v / 10 ** e - 1) < 1e-9) return Math.abs(e) < 4 ? String(10 ** e >= 1 ? 10 ** e : Number((10 ** e).toPrecision(1))) : `1e${e}`;
  }
  return format(v);
}

export function format(v) {
  if (!Number.isFinite(v)) return "–";
  const a = Math.abs(v);
  const r = Number(v.toPrecision(4));
  return a !== 0 && (a < 1e-3 || a >= 1e5) ? r.toExponential().replace("e+", "e") : String(r);
}

// Axis scale over [lo, hi]: log10 or linear, with tick values.
function scale(lo, hi, log, from, to) {
  if (log) {
    const a = Math.log10(lo), b = Math.log10(hi);
    const span = b - a || 1;
    const map = (v) => from + ((Math.log10(v) - a) / span) * (to - from);
    const step = Math.max(1, Math.ceil((Math.ceil(b) - Math.floor(a)) / 8));
    const ticks = [];
    for (let e = Math.ceil(a); e <= Math.floor(b); e += step) ticks.push(10 ** e);
    if (ticks.length < 2) ticks.splice(0, ticks.length, lo, hi);
    return { map, ticks };
  }
  const span = hi - lo || Math.abs(hi) || 1;
  const map = (v) => from + ((v - lo) / span) * (to - from);
  const raw = span / 6, mag = 10 ** Math.floor(Math.log10(raw));
  const step = [1, 2, 5, 10].map((m) => m * mag).find((s) => s >= raw);
  const ticks = [];
  for (let t = Math.ceil(lo / step) * step; t <= hi + step * 1e-9; t += step) ticks.push(Number(t.toPrecision(12)));
  return { map, ticks };
}

function extent(values, log) {
  const v = values.filter((x) => Number.isFinite(x) && (!log || x > 0));
  if (!v.length) return null;
  let lo = Math.min(...v), hi = Math.max(...v);
  if (lo === hi) { lo = log ? lo / 2 : lo - 1; hi = log ? hi * 2 : hi + 1; }
  return [lo, hi];
}

// Whether log axes suit the values: all positive and over more than a decade.
export function suitsLog(values) {
  const v = values.filter(Number.isFinite);
  return v.length > 1 && v.every((x) => x > 0) && Math.max(...v) / Math.min(...v) > 20;
}

// Draw `fig` = {title, xLabel, yLabel, series: [{name, x, y}], logX, logY}.
export function draw(fig) {
  const svg = el("svg", { viewBox: `0 0 ${W} ${H}`, width: W, height: H, role: "img", "aria-label": fig.title, class: "plot" });
  svg.append(el("title", {}, fig.title));
  svg.append(el("rect", { x: 0, y: 0, width: W, height: H, fill: "white" }));
  const xs = fig.series.flatMap((s) => s.x), ys = fig.series.flatMap((s) => s.y);
  const xe = extent(xs, fig.logX), ye = extent(ys, fig.logY);
  if (!xe || !ye) {
    svg.append(el("text", { x: W / 2, y: H / 2, "text-anchor": "middle" }, "no finite values to draw"));
    return svg;
  }
  const sx = scale(xe[0], xe[1], fig.logX, M.left, W - M.right);
  const sy = scale(ye[0], ye[1], fig.logY, H - M.bottom, M.top);
  const axes = el("g", { class: "axes", "font-size": 11, fill: "#222" });
  axes.append(el("rect", { x: M.left, y: M.top, width: W - M.left - M.right, height: H - M.top - M.bottom, fill: "none", stroke: "#444" }));
  for (const t of sx.ticks) {
    const x = sx.map(t);
    axes.append(el("line", { x1: x, x2: x, y1: H - M.bottom, y2: H - M.bottom + 5, stroke: "#444" }));
    axes.append(el("text", { x, y: H - M.bottom + 17, "text-anchor": "middle" }, tick(t, fig.logX)));
  }
  for (const t of sy.ticks) {
    const y = sy.map(t);
    axes.append(el("line", { x1: M.left - 5, x2: M.left, y1: y, y2: y, stroke: "#444" }));
    axes.append(el("text", { x: M.left - 8, y: y + 4, "text-anchor": "end" }, tick(t, fig.logY)));
  }
  axes.append(el("text", { x: (M.left + W - M.right) / 2, y: H - 10, "text-anchor": "middle" }, fig.xLabel));
  axes.append(el("text", { x: 14, y: (M.top + H - M.bottom) / 2, "text-anchor": "middle", transform: `rotate(-90 14 ${(M.top + H - M.bottom) / 2})` }, fig.yLabel));
  const short = fig.title.length > 78 ? fig.title.slice(0, 77) + "…" : fig.title;
  axes.append(el("text", { x: M.left, y: 18, "font-size": 12 }, short));
  svg.append(axes);
  const points = [];
  fig.series.forEach((s, k) => {
    const colour = COLOURS[k % COLOURS.length];
    const pts = s.x.map((x, i) => [x, s.y[i]])
      .filter(([x, y]) => Number.isFinite(x) && Number.isFinite(y) && (!fig.logX || x > 0) && (!fig.logY || y > 0));
    const d = pts.map(([x, y], i) => `${i ? "L" : "M"}${sx.map(x).toFixed(2)},${sy.map(y).toFixed(2)}`).join("");
    svg.append(el("path", { d, fill: "none", stroke: colour, "stroke-width": 1.8, class: "series" }));
    for (const [x, y] of pts) {
      const cx = sx.map(x), cy = sy.map(y);
      if (pts.length <= 30) svg.append(el("circle", { cx, cy, r: 2.5, fill: colour }));
      points.push({ cx, cy, x, y, name: s.name });
    }
    if (fig.series.length > 1) {
      const ly = M.top + 14 + 15 * k;
      svg.append(el("line", { x1: W - M.right - 150, x2: W - M.right - 130, y1: ly - 4, y2: ly - 4, stroke: colour, "stroke-width": 2 }));
      svg.append(el("text", { x: W - M.right - 125, y: ly, "font-size": 11 }, s.name.length > 22 ? s.name.slice(0, 21) + "…" : s.name));
    }
  });
  // The value under the pointer.
  const tip = el("g", { visibility: "hidden", "pointer-events": "none" });
  const dot = el("circle", { r: 4, fill: "none", stroke: "#000" });
  const box = el("rect", { fill: "#fffbe6", stroke: "#888", rx: 3 });
  const label = el("text", { "font-size": 11 });
  tip.append(dot, box, label);
  svg.append(tip);
  svg.addEventListener("pointermove", (e) => {
    const r = svg.getBoundingClientRect();
    const px = ((e.clientX - r.left) / r.width) * W, py = ((e.clientY - r.top) / r.height) * H;
    let best = null, bd = Infinity;
    for (const p of points) {
      const d = (p.cx - px) ** 2 + (p.cy - py) ** 2;
      if (d < bd) { bd = d; best = p; }
    }
    if (!best || bd > 40 ** 2) { tip.setAttribute("visibility", "hidden"); return; }
    dot.setAttribute("cx", best.cx); dot.setAttribute("cy", best.cy);
    label.textContent = `${fig.series.length > 1 ? best.name + ": " : ""}${fig.xLabel} = ${format(best.x)}, ${fig.yLabel} = ${format(best.y)}`;
    const tx = Math.min(best.cx + 8, W - 8 - 7 * label.textContent.length), ty = Math.max(best.cy - 10, 16);
    label.setAttribute("x", tx); label.setAttribute("y", ty);
    box.setAttribute("x", tx - 4); box.setAttribute("y", ty - 12);
    box.setAttribute("width", 6.2 * label.textContent.length + 8); box.setAttribute("height", 16);
    tip.setAttribute("visibility", "visible");
  });
  svg.addEventListener("pointerleave", () => tip.setAttribute("visibility", "hidden"));
  return svg;
}
