/* explorer.js: the flip-graph explorer's page logic (docs/explorer.md).  It
** draws and asks: every decision, badness, flip, sink and count comes from the
** server (python3 -m fliplab.explorer, the library's verbs); the page only
** looks them up.  Plain JavaScript, SVG and a canvas for the large LOT, nothing
** fetched from elsewhere. */
"use strict";

const SVGNS = "http://www.w3.org/2000/svg";
const S = {
  names: null,          /* /api/names */
  sites: [],            /* [[x, y], ...] */
  view: null,           /* world -> screen: {x0, y0, k} */
  graph: null,          /* /api/graph's answer for sites + rule */
  node: 0,              /* the current triangulation, a node of graph */
  lotOnly: null,        /* /api/tri of the sites when the graph is too large */
  dragTri: null,        /* /api/tri during a drag: the LOT of the moved sites */
  lot: null,            /* /api/lot.bin's answer, unpacked: typed arrays */
  pending: false, again: false, drag: null, dragEnd: 0, lastLot: null,
};
const $ = (id) => document.getElementById(id);

/* Request-to-drawn times in ms, read by bench/bench_explorer.py: {what, dom, frame,
** ...parts}, dom when the drawing is done, frame at the next animation frame (the one
** painting it); parts: the phases (fetch, decode, draw) the caller timed. */
window.__fliplabTimings = [];
function timed(what, t0, parts) {
  const dom = performance.now() - t0;
  requestAnimationFrame(() => window.__fliplabTimings.push(
    Object.assign({what: what, dom: dom, frame: performance.now() - t0}, parts)));
}

function el(tag, attrs, parent) {
  const e = document.createElementNS(SVGNS, tag);
  for (const k in attrs) e.setAttribute(k, attrs[k]);
  if (parent) parent.appendChild(e);
  return e;
}

function say(text, ok) {
  $("message").textContent = text || "";
  $("message").className = ok ? "ok" : "";
}

/* The server's own time of the last answer in ms (its Server-Timing header), which
** the timings set beside the round trip. */
let serverMs = null;

async function api(path, body, binary) {
  const r = await fetch(path, body === undefined ? {} : {
    method: "POST", headers: {"Content-Type": "application/json"}, body: JSON.stringify(body)});
  const st = /dur=([0-9.]+)/.exec(r.headers.get("Server-Timing") || "");
  serverMs = st ? Number(st[1]) : null;
  if (binary && r.ok) return await r.arrayBuffer();
  let data;
  try { data = await r.json(); } catch (e) { throw new Error(path + ": HTTP " + r.status); }
  if (!r.ok) throw new Error(data.error || ("HTTP " + r.status));
  return data;
}

/* The server's binary message (pack_arrays in fliplab/explorer.py): a little-endian
** uint32 n, n bytes of JSON naming the arrays, then each array at an offset that is a
** multiple of 8, read here as typed arrays over the same buffer (no copy).  Typed
** arrays are in the machine's byte order: on a big-endian machine the page says so. */
const LITTLE = new Uint8Array(new Uint16Array([1]).buffer)[0] === 1;
const TYPED = {"<f8": Float64Array, "<i4": Int32Array};
function unpack(buf) {
  if (!LITTLE) throw new Error("this page reads the LOT as little-endian arrays");
  const n = new DataView(buf).getUint32(0, true), base = 4 + n;
  const m = JSON.parse(new TextDecoder().decode(new Uint8Array(buf, 4, n)));
  for (const a of m.arrays) {
    m[a.name] = new TYPED[a.dtype](buf, base + a.offset, a.shape.reduce((x, y) => x * y, 1));
  }
  return m;
}

function ruleBody(extra) {
  const b = Object.assign({rule: $("rule").value.trim()}, extra);
  const d = $("define").value.trim();
  if (d) b.define = d;
  return b;
}

/* ---- the world-to-screen map of the sites panel ---- */

/* The map putting points (flat: x0, y0, x1, y1, ...) in a size x size square. */
function fit(xy, size) {
  let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
  for (let k = 0; k < xy.length; k += 2) {
    const x = xy[k], y = xy[k + 1];
    if (x < x0) x0 = x;
    if (x > x1) x1 = x;
    if (y < y0) y0 = y;
    if (y > y1) y1 = y;
  }
  if (!isFinite(x0)) { x0 = 0; y0 = 0; x1 = 1; y1 = 1; }
  const span = Math.max(x1 - x0, y1 - y0, 1e-9), pad = 0.08 * span;
  return {x0: x0 - pad, y0: y0 - pad, k: size / (span + 2 * pad), size: size};
}
const sx = (v, p) => (p[0] - v.x0) * v.k;
const sy = (v, p) => v.size - (p[1] - v.y0) * v.k;
const world = (v, X, Y) => [v.x0 + X / v.k, v.y0 + (v.size - Y) / v.k];

/* A badness's place on the colour scale: -1 (grey) for none (null, NaN, infinite). */
function bucket(b, lo, hi) {
  if (b === null || !isFinite(b)) return -1;
  return hi > lo ? Math.round((S.names.scale.length - 1) * (b - lo) / (hi - lo)) : 0;
}
const colour = (b, lo, hi) => { const i = bucket(b, lo, hi); return i < 0 ? "#dddddd"
                                                                   : S.names.scale[i]; };

/* The finite badness range [lo, hi] of a list or typed array. */
function range(bs) {
  let lo = Infinity, hi = -Infinity;
  for (const b of bs) {
    if (b !== null && isFinite(b)) { if (b < lo) lo = b; if (b > hi) hi = b; }
  }
  return [lo, hi];
}

/* ---- the triangulation: triangles shaded by badness, edges to hover and flip ---- */

function currentTriangles() {
  const g = S.graph, t = S.dragTri || (g && !g.too_large ? null : S.lotOnly);
  if (t) return t.triangles.map((v, i) => ({v: v, badness: t.badness ? t.badness[i] : null}));
  if (g) return g.nodes[S.node].map((k) => g.triangles[k]);
  return [];
}

/* The flips at the current node: diagonal "i-j" -> {flip, here: "AC"|"BD", to}. */
function flipsHere() {
  const out = new Map(), g = S.graph;
  if (!g || g.too_large || S.dragTri) return out;
  g.flips.forEach((f, k) => {
    if (f.ac !== S.node && f.bd !== S.node) return;
    const here = f.ac === S.node ? "AC" : "BD", q = f.quad;
    const d = here === "AC" ? [q[0], q[2]] : [q[1], q[3]];
    out.set(Math.min(...d) + "-" + Math.max(...d),
            {k: k, f: f, here: here, to: here === "AC" ? f.bd : f.ac});
  });
  return out;
}

/* The sites panel: the triangles and edges (drawTriangles), then the sites. */
function drawSites() {
  const svg = $("sites");
  svg.replaceChildren(el("g", {id: "tri-layer"}), el("g", {id: "edge-layer"}));
  drawTriangles();
  const v = S.view;
  S.sites.forEach((p, i) => {
    const c = el("circle", {cx: sx(v, p), cy: sy(v, p), r: 6, class: "site",
                            "data-index": i}, svg);
    const t = el("title", {}, c);
    t.textContent = "site " + (i + 1) + ": " + p[0] + ", " + p[1];
    c.addEventListener("mousedown", (e) => startDrag(e, i));
    c.addEventListener("contextmenu", (e) => { e.preventDefault(); deleteSite(i); });
    const n = el("text", {x: sx(v, p) + 7, y: sy(v, p) - 7, class: "label",
                          "data-label": i}, svg);
    n.textContent = i + 1;
  });
}

/* The triangles shaded by badness and their edges: all a drag redraws, with the
** moved site (moveSite); the sites' circles keep their listeners. */
function drawTriangles() {
  const v = S.view, tris = currentTriangles(), [lo, hi] = range(tris.map((t) => t.badness));
  const layer = $("tri-layer");
  layer.replaceChildren();
  for (const t of tris) {
    const pts = t.v.map((i) => sx(v, S.sites[i]) + "," + sy(v, S.sites[i])).join(" ");
    const p = el("polygon", {points: pts, class: "tri", fill: colour(t.badness, lo, hi)}, layer);
    p.addEventListener("mouseenter", () => showTriangle(t));
  }
  $("edge-layer").replaceChildren();
  drawEdges($("edge-layer"), tris);
}

function moveSite(i) {
  const v = S.view, p = S.sites[i], c = $("sites").querySelector('[data-index="' + i + '"]');
  const n = $("sites").querySelector('[data-label="' + i + '"]');
  if (!c || !n) return;
  c.setAttribute("cx", sx(v, p));
  c.setAttribute("cy", sy(v, p));
  c.firstChild.textContent = "site " + (i + 1) + ": " + p[0] + ", " + p[1];
  n.setAttribute("x", sx(v, p) + 7);
  n.setAttribute("y", sy(v, p) - 7);
}

function drawEdges(svg, tris) {
  const seen = new Map(), v = S.view, here = flipsHere();
  for (const t of tris) {
    for (let k = 0; k < 3; k++) {
      const a = Math.min(t.v[k], t.v[(k + 1) % 3]), b = Math.max(t.v[k], t.v[(k + 1) % 3]);
      seen.set(a + "-" + b, (seen.get(a + "-" + b) || 0) + 1);
    }
  }
  for (const [key, count] of seen) {
    const [a, b] = key.split("-").map(Number);
    const xy = {x1: sx(v, S.sites[a]), y1: sy(v, S.sites[a]),
                x2: sx(v, S.sites[b]), y2: sy(v, S.sites[b])};
    el("line", Object.assign({class: "edge"}, xy), svg);
    if (count < 2) continue;                      /* a hull edge */
    const fl = here.get(key);
    const hit = el("line", Object.assign({class: "edge-hit" + (fl ? " flippable" : ""),
                                          "data-edge": key}, xy), svg);
    hit.addEventListener("mouseenter", () => showEdge(key, fl));
    hit.addEventListener("click", () => { if (fl) goTo(fl.to); });
  }
}

function fmt(x) { return x === null || x === undefined ? "-" : Number(x).toPrecision(10); }

function showTriangle(t) {
  const v = t.v.map((i) => i + 1).join(" ");
  let text = "triangle (" + v + "): badness " +
    (t.badness === null ? "- (" + S.graph?.rule + " is not triangle-based)" : fmt(t.badness));
  const old = document.getElementById("homothet");
  if (old) old.remove();
  if (t.shape && t.shape.outline) {
    const pts = t.shape.outline.map((p) => sx(S.view, p) + "," + sy(S.view, p)).join(" ");
    el("polygon", {id: "homothet", class: "homothet", points: pts}, $("tri-layer"));
    text += "\ncircumscribing homothet of the shape (dashed)";
  } else if (t.shape) {
    text += "\ncircumscribing shape: the rounding shape of the shape's corner " + t.shape.corner +
      " (unbounded, not drawn)";
  }
  $("info").textContent = text;
}

function showEdge(key, fl) {
  const [a, b] = key.split("-").map((i) => Number(i) + 1);
  if (!fl) {
    $("info").textContent = "edge " + a + "-" + b +
      ": not flippable (its quadrilateral is not strictly convex)";
    return;
  }
  const f = fl.f, q = f.quad.map((i) => i + 1);
  const keep = f.decision === "either" ? "either diagonal (a tie)"
    : f.decision === fl.here ? "keep " + a + "-" + b : "flip " + a + "-" + b;
  $("info").textContent = "quadrilateral " + q.join(" ") + "\n" +
    "diagonal " + q[0] + "-" + q[2] + " (AC): " + fmt(f.ac_value) + "   diagonal " +
    q[1] + "-" + q[3] + " (BD): " + fmt(f.bd_value) + "\n" +
    "the rule prefers " + f.decision + ": " + keep;
  $("info").dataset.decision = f.decision === "either" ? "either"
    : f.decision === fl.here ? "keep" : "flip";
}

/* ---- the directed flip graph ---- */

function drawGraph() {
  const svg = $("graph"), g = S.graph;
  svg.replaceChildren();
  if (!g || g.too_large) return;
  const W = 520, P = 16, at = (u) => [P + (W - 2 * P) * g.layout[u][0],
                                       P + (W - 2 * P) * (1 - g.layout[u][1])];
  const defs = el("defs", {}, svg);
  const r = g.nodes.length > 500 ? 2.5 : g.nodes.length > 60 ? 4 : 7;
  const m = el("marker", {id: "arrow", viewBox: "0 0 10 10", refX: 10 + 10 * r / 8, refY: 5,
                          markerUnits: "userSpaceOnUse", markerWidth: 8, markerHeight: 8,
                          orient: "auto"}, defs);
  el("path", {d: "M0,0 L10,5 L0,10 z", fill: "#555"}, m);
  for (const f of g.flips) {
    const [from, to] = f.decision === "AC" ? [f.bd, f.ac] : [f.ac, f.bd];
    const [x1, y1] = at(from), [x2, y2] = at(to);
    const attrs = {x1: x1, y1: y1, x2: x2, y2: y2, class: "arc" +
                   (f.decision === "either" ? " tie" : "")};
    if (f.decision !== "either" && g.nodes.length <= 500) attrs["marker-end"] = "url(#arrow)";
    el("line", attrs, svg);
  }
  const sinks = new Set(g.sinks);
  g.nodes.forEach((_, u) => {
    const [x, y] = at(u);
    const c = el("circle", {cx: x, cy: y, r: r, "data-node": u, class: "node" +
      (sinks.has(u) ? " sink" : "") + (u === S.node ? " current" : "")}, svg);
    el("title", {}, c).textContent = "T" + (u + 1) + (sinks.has(u) ? " (sink)" : "");
    c.addEventListener("click", () => goTo(u));
    const tag = (u === g.dt ? "DT " : "") + (u === g.got ? "GOT" : "");
    if (tag) el("text", {x: x + r + 2, y: y - r, class: "label"}, svg).textContent = tag;
  });
}

function drawCounts() {
  const g = S.graph, c = g && !g.too_large ? g.census : null;
  const put = (id, v) => { $(id).textContent = v === null || v === undefined ? "-" : v; };
  put("count-triangulations", g ? (c ? c.triangulations : "> " + g.more_than) : null);
  put("count-flips", c && c.flips);
  put("count-sinks", c && c.sinks);
  put("count-ties", c && c.ties);
  put("count-type", c && c.type);
  put("count-sinkdt", c ? (c.sink_dt === null ? "-" : c.sink_dt ? "yes" : "no") : null);
  put("count-got", c && fmt(c.got_total));
  put("count-gap", c && fmt(c.worst_gap));
  put("count-current", c ? "T" + (S.node + 1) + (g.sinks.includes(S.node) ? " (sink)" : "")
                         : S.lotOnly ? "the LOT" : null);
  put("count-rule", g && g.rule);
}

function redraw() {
  $("graph").classList.toggle("stale", S.dragTri !== null);
  drawSites(); drawGraph(); drawCounts();
}

function goTo(u) { S.node = u; $("info").textContent = "T" + (u + 1); redraw(); }

/* ---- asking the server: the graph of the sites under the rule ---- */

async function refresh() {
  if (S.pending) { S.again = true; return; }
  S.pending = true;
  try {
    do {
      S.again = false;
      await refreshOnce();
    } while (S.again);
  } finally { S.pending = false; }
}

async function refreshOnce() {
  const sites = S.sites.map((p) => p.slice());
  if (sites.length < 3) {
    S.graph = null; S.lotOnly = null; redraw();
    say(sites.length ? "place at least 3 sites" : "click to place sites (3 to 12)", true);
    return;
  }
  const t0 = performance.now();
  const old = currentTriangles().map((t) => t.v);
  try {
    const g = await api("/api/graph", ruleBody({sites: sites}));
    S.graph = g; S.lotOnly = null; S.node = 0;
    if (g.too_large) {
      S.lotOnly = await api("/api/tri", ruleBody({sites: sites}));
      say(g.message, false);
    } else {
      keepNode(old);
      say(g.census.triangulations + " triangulations under " + g.rule, true);
    }
  } catch (e) {
    S.graph = null; S.lotOnly = null;
    say(e.message, false);
  }
  if (!S.drag) S.dragTri = null;
  redraw();
  timed("graph", t0);
}

/* A triangulation as a string, whatever the order of its triangles and their vertices
** (the graph's triangles are in the enumeration's order, a LOT's anticlockwise). */
const triKey = (tris) => tris.map((v) => v.slice().sort((a, b) => a - b) + "").sort().join(";");

/* After an edit, stay on the triangulation with the same triangles if there is one
** (after a drag: the LOT drawn while dragging). */
function keepNode(old) {
  if (!old.length) return;
  const want = triKey(old), g = S.graph;
  for (let u = 0; u < g.nodes.length; u++) {
    if (triKey(g.nodes[u].map((t) => g.triangles[t].v)) === want) {
      S.node = u; return;
    }
  }
}

/* ---- the flip algorithm: the first flip out of the current node, in the library's order */

function nextFlip() {
  const g = S.graph;
  if (!g || g.too_large) return -1;
  for (const f of g.flips) {
    if (f.decision === "AC" && f.bd === S.node) return f.ac;
    if (f.decision === "BD" && f.ac === S.node) return f.bd;
  }
  return -1;
}

function step() {
  const to = nextFlip();
  if (to < 0) { say(S.graph ? "T" + (S.node + 1) + " is a sink: no flip improves it" : "", true); return false; }
  goTo(to);
  return true;
}

function runToSink() {
  let n = 0;
  while (n <= (S.graph ? S.graph.nodes.length : 0) && nextFlip() >= 0) { S.node = nextFlip(); n++; }
  redraw();
  say(S.graph && !S.graph.too_large ? n + " flips to the sink T" + (S.node + 1) : "", true);
}

/* ---- editing the sites ---- */

function setSites(pts, refit) {
  S.sites = pts.map((p) => [Number(p[0]), Number(p[1])]);
  if (refit || !S.view) S.view = fit(S.sites.flat(), 520);
  refresh();
}

function addSite(e) {
  if (e.target.tagName !== "svg" && !e.target.classList.contains("tri")) return;
  if (e.shiftKey || Date.now() - S.dragEnd < 400) return;   /* the click ending a drag */
  const lim = S.names.limits;
  if (S.sites.length >= lim.sites_max) { say("at most " + lim.sites_max + " sites"); return; }
  const r = $("sites").getBoundingClientRect();
  const p = world(S.view, e.clientX - r.left, e.clientY - r.top);
  S.sites.push([Number(p[0].toPrecision(6)), Number(p[1].toPrecision(6))]);
  refresh();
}

function deleteSite(i) { S.sites.splice(i, 1); refresh(); }

/* A drag: each mousemove moves the site at once and asks at once (not at the next
** animation frame: the answer is drawn when it comes, and painted by the next frame
** after it) for the rule's LOT of the moved sites only (/api/tri: one small request,
** no flip graph), at most one request in flight (moves while it flies are coalesced
** into the next); the drop (mouseup) asks for the flip graph and the census once. */
function startDrag(e, i) {
  e.preventDefault();
  e.stopPropagation();
  if (e.shiftKey) { deleteSite(i); return; }
  S.drag = {i: i, moved: false, busy: false, dirty: false, t0: null, input: 0, raw: null};
}

function moveDrag(e) {
  const d = S.drag;
  if (!d) return;
  const r = $("sites").getBoundingClientRect();
  if (e.type === "pointerrawupdate") d.raw = [e.clientX, e.clientY];
  else if (d.raw && d.raw[0] === e.clientX && d.raw[1] === e.clientY) return;  /* its twin */
  const p = world(S.view, e.clientX - r.left, e.clientY - r.top);
  S.sites[d.i] = [Number(p[0].toPrecision(6)), Number(p[1].toPrecision(6))];
  d.moved = true;
  if (d.t0 === null) {                            /* the oldest move not yet drawn */
    d.t0 = performance.now();
    d.input = d.t0 - e.timeStamp;                 /* from the input event's own time */
  }
  moveSite(d.i);
  if (d.busy) d.dirty = true;
  else retriangulate(d);
}

async function retriangulate(d) {
  const t0 = d.t0, input = d.input, sites = S.sites.map((p) => p.slice());
  const tq = performance.now();
  d.busy = true; d.dirty = false; d.t0 = null;
  let tri = null, t1 = tq;
  try {
    tri = await api("/api/tri", ruleBody({sites: sites}));
    t1 = performance.now();
  } catch (e) {
    if (S.drag === d) say(e.message, false);
  }
  d.busy = false;
  if (S.drag !== d) return;                     /* dropped meanwhile: the graph redraws */
  if (tri) {
    S.dragTri = tri;
    say("LOT(" + tri.rule + ") of the moved sites, " + tri.status +
        "; the flip graph when the site is dropped", true);
    $("graph").classList.add("stale");
    drawTriangles();
    timed("drag", t0, {input: input, wait: tq - t0, fetch: t1 - tq, server: serverMs,
                       draw: performance.now() - t1});
  }
  if (d.dirty) retriangulate(d);
}

function endDrag() {
  const d = S.drag;
  S.drag = null;
  if (d && d.moved) {
    S.dragEnd = Date.now();
    drawSites();
    refresh();
  }
}

function parseCsv(text) {
  const out = [];
  text.split(/\r?\n/).forEach((line, k) => {
    const s = line.trim();
    if (!s || /^x\s*,\s*y$/i.test(s)) return;
    const f = s.split(/[,\s]+/);
    const x = Number(f[0]), y = Number(f[1]);
    if (f.length !== 2 || !isFinite(x) || !isFinite(y) || f[0] === "" || f[1] === "")
      throw new Error("line " + (k + 1) + ": expected x,y");
    out.push([x, y]);
  });
  const lim = S.names.limits;
  if (out.length < lim.sites_min || out.length > lim.sites_max)
    throw new Error(out.length + " sites: the flip graph takes " + lim.sites_min + " to " +
                    lim.sites_max + " (the LOT panel takes more)");
  return out;
}

function useText(text) {
  try { setSites(parseCsv(text), true); } catch (e) { say(e.message); }
}

/* ---- the LOT panel: typed arrays from /api/lot.bin, drawn on canvases ---- */

/* Screen coordinates (flat x, y) of flat world points in a size x size square. */
function screenXY(pts, size) {
  const v = fit(pts, size), out = new Float32Array(pts.length);
  for (let k = 0; k < pts.length; k += 2) {
    out[k] = (pts[k] - v.x0) * v.k;
    out[k + 1] = v.size - (pts[k + 1] - v.y0) * v.k;
  }
  return out;
}

/* A CSS colour as [r, g, b] (the canvas normalises what it is given to #rrggbb). */
function rgb(css) {
  const g = document.createElement("canvas").getContext("2d");
  g.fillStyle = css;
  return [1, 3, 5].map((i) => parseInt(g.fillStyle.substr(i, 2), 16));
}

/* Triangle k filled with colour c (RGBA packed as the machine's uint32) on a w x h
** image: each pixel whose centre lies in it (rows by the half-open rule on y, both
** ends of a row included, so triangles tiling a region cover every centre in it).
** O(rows + pixels) of the triangle. */
function fillTriangle(px, w, h, xy, tris, k, c) {
  const a = 2 * tris[3 * k], b = 2 * tris[3 * k + 1], d = 2 * tris[3 * k + 2];
  const ya = xy[a + 1], yb = xy[b + 1], yd = xy[d + 1];
  const y0 = Math.max(0, Math.ceil(Math.min(ya, yb, yd) - 0.5));
  const y1 = Math.min(h - 1, Math.floor(Math.max(ya, yb, yd) - 0.5));
  for (let y = y0; y <= y1; y++) {
    const yc = y + 0.5;
    let xl = Infinity, xr = -Infinity;
    for (let j = 0; j < 3; j++) {
      const p = j === 0 ? a : j === 1 ? b : d, q = j === 0 ? b : j === 1 ? d : a;
      const yp = xy[p + 1], yq = xy[q + 1];
      if ((yp <= yc && yc < yq) || (yq <= yc && yc < yp)) {
        const x = xy[p] + (yc - yp) * (xy[q] - xy[p]) / (yq - yp);
        if (x < xl) xl = x;
        if (x > xr) xr = x;
      }
    }
    const x1 = Math.min(w - 1, Math.floor(xr - 0.5));
    for (let x = Math.max(0, Math.ceil(xl - 0.5)); x <= x1; x++) px[y * w + x] = c;
  }
}

/* The segment a-b blended over the image at weight t, a pixel per step along its
** longer axis.  O(its length in pixels). */
function blendLine(rgba, w, h, xa, ya, xb, yb, c, t) {
  const n = Math.max(1, Math.ceil(Math.max(Math.abs(xb - xa), Math.abs(yb - ya))));
  const dx = (xb - xa) / n, dy = (yb - ya) / n;
  for (let i = 0; i <= n; i++) {
    const x = Math.floor(xa + dx * i), y = Math.floor(ya + dy * i);
    if (x < 0 || y < 0 || x >= w || y >= h) continue;
    const o = 4 * (y * w + x);
    rgba[o] += t * (c[0] - rgba[o]);
    rgba[o + 1] += t * (c[1] - rgba[o + 1]);
    rgba[o + 2] += t * (c[2] - rgba[o + 2]);
  }
}

/* The triangles on a canvas: filled by badness, one packed colour per bucket of the
** scale, then every edge blended over once (weight t): an interior edge is a-b in one
** anticlockwise triangle and b-a in the other, so each triangle draws its edges with
** a < b, and the hull (anticlockwise too) the hull edges its triangle left out.  All is
** rasterised into one ImageData here: chromium's vector paths take seconds for 2 * 10^5
** triangles on its software rasteriser (minutes in one path).  O(triangles + pixels). */
function drawCanvas(cv, xy, tris, badness, hull) {
  const w = cv.width, h = cv.height, m = tris.length / 3, g = cv.getContext("2d");
  const img = g.createImageData(w, h), px = new Uint32Array(img.data.buffer);
  const pack = (c) => new Uint32Array(new Uint8ClampedArray([c[0], c[1], c[2], 255]).buffer)[0];
  px.fill(pack([255, 255, 255]));
  if (badness) {
    const [lo, hi] = range(badness), grey = pack(rgb("#dddddd"));
    const fills = S.names.scale.map((c) => pack(rgb(c)));
    for (let k = 0; k < m; k++) {
      const i = bucket(badness[k], lo, hi);
      fillTriangle(px, w, h, xy, tris, k, i < 0 ? grey : fills[i]);
    }
  }
  /* Edges fade as triangles shrink below 16 pixels (about the picture's area over m), so
  ** that the shading of 10^5 points still shows through them. */
  const edge = rgb("#1f4e79"), t = 0.65 * Math.min(1, 0.8 * w * h / m / 16);
  const line = (a, b) => blendLine(img.data, w, h, xy[2 * a], xy[2 * a + 1], xy[2 * b],
                                    xy[2 * b + 1], edge, t);
  for (let k = 0; k < m; k++) {
    for (let j = 0; j < 3; j++) {
      const a = tris[3 * k + j], b = tris[3 * k + (j + 1) % 3];
      if (a < b) line(a, b);
    }
  }
  hull.forEach((a, i) => { const b = hull[(i + 1) % hull.length]; if (a > b) line(a, b); });
  g.putImageData(img, 0, 0);
}

/* The same picture as SVG, made only when exported: the LOT and DT side by side. */
function lotSvg() {
  const L = S.lot, xy = screenXY(L.points, 420), svg = el("svg", {width: 860, height: 420,
    viewBox: "0 0 860 420"});
  const [lo, hi] = L.badness ? range(L.badness) : [0, 0];
  [[L.triangles, L.badness, 0], [L.dt, null, 440]].forEach(([tris, bad, dx]) => {
    const g = el("g", {transform: "translate(" + dx + ",0)"}, svg), d = [];
    for (let k = 0; k < tris.length / 3; k++) {
      const p = [0, 1, 2].map((j) => xy[2 * tris[3 * k + j]].toFixed(1) + "," +
                                   xy[2 * tris[3 * k + j] + 1].toFixed(1));
      if (bad) el("polygon", {class: "tri", fill: colour(bad[k], lo, hi), points: p.join(" ")}, g);
      d.push("M" + p.join("L") + "Z");
    }
    el("path", {d: d.join(""), fill: "none", stroke: "#1f4e79", "stroke-width": 0.4}, g);
  });
  return svg;
}

async function lot(body) {
  say("computing the LOT...", true);
  const t0 = performance.now();
  try {
    const buf = await api("/api/lot.bin", ruleBody(body), true);
    const t1 = performance.now(), server = serverMs, r = unpack(buf), t2 = performance.now();
    S.lot = r; S.lastLot = body;
    const xy = screenXY(r.points, 420);
    drawCanvas($("lot-canvas"), xy, r.triangles, r.badness || null, r.hull);
    drawCanvas($("dt-canvas"), xy, r.dt, null, r.hull);
    const t3 = performance.now(), c = r.compare, n = r.points.length / 2;
    $("lot-figures").textContent = "LOT(" + r.rule + ") left, DT right: " + n +
      " points, " + r.triangles.length / 3 + " triangles, " + r.flips + " flips, " + r.status +
      "; compare DT: " + c.edges_common + " of " + c.edges_b + " edges and " +
      c.triangles_common + " of " + c.triangles_b + " triangles shared (" +
      (100 * c.triangles_common / Math.max(1, c.triangles_b)).toFixed(2) + "% of triangles)";
    say("", true);
    timed("lot", t0, {fetch: t1 - t0, server: server, decode: t2 - t1, draw: t3 - t2,
                      bytes: buf.byteLength});
  } catch (e) { say(e.message); }
}

/* What the LOT panel holds, for the tests: plain arrays of its typed arrays. */
window.__fliplabLot = () => S.lot && {points: Array.from(S.lot.points),
  triangles: Array.from(S.lot.triangles), dt: Array.from(S.lot.dt), rule: S.lot.rule};

/* ---- export ---- */

function download(name, type, text) {
  const a = document.createElement("a");
  a.href = URL.createObjectURL(new Blob([text], {type: type}));
  a.download = name;
  document.body.appendChild(a);
  a.click();
  a.remove();
}

function svgText(id) {
  const s = typeof id === "string" ? $(id).cloneNode(true) : id;
  s.setAttribute("xmlns", SVGNS);
  return '<?xml version="1.0" encoding="UTF-8"?>\n' + s.outerHTML + "\n";
}

async function exportCommand() {
  try {
    const r = await api("/api/export", ruleBody(S.lastLot && S.lastLot.random &&
      S.sites.length < 3 ? S.lastLot : {sites: S.sites}));
    $("command").textContent = (r.csv ? "# sites.csv:\n" + r.csv : "") + r.commands.join("\n");
    return r;
  } catch (e) { say(e.message); return null; }
}

/* ---- start ---- */

function fillNames(n) {
  const opts = ["DT"].concat(n.shapes);
  for (const j of n.joints) for (const m of n.measures) opts.push(m.name + "_" + j);
  $("rule-names").replaceChildren(...opts.map((o) => {
    const e = document.createElement("option"); e.value = o; return e;
  }));
  const add = (sel, list) => list.forEach((k) => {
    const o = document.createElement("option"); o.value = o.textContent = k; sel.appendChild(o);
  });
  add($("sampler"), n.site_samplers.concat(n.point_samplers));
  add($("lot-sampler"), n.point_samplers);
  add($("preset"), Object.keys(n.presets));
}

function wire() {
  const svg = $("sites");
  svg.addEventListener("click", addSite);
  window.addEventListener("mousemove", moveDrag);
  /* a move as it comes, not at the next frame as mousemove (a secure context's:
  ** 127.0.0.1 is one) */
  if ("onpointerrawupdate" in window) window.addEventListener("pointerrawupdate", moveDrag);
  window.addEventListener("mouseup", endDrag);
  $("apply").onclick = refresh;
  $("rule").addEventListener("change", refresh);
  $("define").addEventListener("change", refresh);
  $("step").onclick = step;
  $("run").onclick = runToSink;
  $("to-node0").onclick = () => goTo(0);
  $("clear").onclick = () => setSites([], true);
  $("preset").onchange = () => {
    const p = S.names.presets[$("preset").value];
    if (!p) return;
    $("rule").value = p.rule; $("define").value = p.define || "";
    setSites(p.sites, true);
  };
  $("sample").onclick = async () => {
    try {
      const r = await api("/api/sample", {kind: $("sampler").value,
        n: Number($("sample-n").value), seed: Number($("sample-seed").value)});
      setSites(r.sites, true);
    } catch (e) { say(e.message); }
  };
  $("paste-open").onclick = () => { $("paste-box").hidden = !$("paste-box").hidden; };
  $("paste-go").onclick = () => useText($("paste-text").value);
  $("csv-file").onchange = async () => {
    const f = $("csv-file").files[0];
    if (f) useText(await f.text());
  };
  $("lot-go").onclick = () => lot({random: {n: Number($("lot-n").value),
    sampler: $("lot-sampler").value, seed: Number($("lot-seed").value)}});
  $("lot-sites").onclick = () => lot({sites: S.sites});
  $("export-svg").onclick = () => download("triangulation.svg", "image/svg+xml", svgText("sites"));
  $("export-graph").onclick = () => download("flipgraph.svg", "image/svg+xml", svgText("graph"));
  $("export-lot").onclick = () => {
    if (S.lot) download("lot.svg", "image/svg+xml", svgText(lotSvg()));
    else say("no LOT yet: compute one in the LOT panel");
  };
  $("export-csv").onclick = async () => {
    const r = await exportCommand();
    if (r && r.csv) download("sites.csv", "text/csv", r.csv);
  };
  $("export-cmd").onclick = exportCommand;
}

async function start() {
  try {
    S.names = await api("/api/names");
  } catch (e) { say("the explorer's server does not answer: " + e.message); return; }
  fillNames(S.names);
  wire();
  setSites([], true);
}

start();
