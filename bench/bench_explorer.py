#!/usr/bin/python3
"""bench_explorer.py: the explorer's speed in headless chromium, with the
page's own clock (performance.now() around request + redraw, recorded by
web/explorer.js in window.__fliplabTimings; docs/explorer.md).  Run by hand:

    FLIPLAB_LIBRARY=b/libfliplab.so FLIPLAB_BIN=b/fliplab PYTHONPATH=python \\
        /usr/bin/python3 bench/bench_explorer.py [--runs 5] [--moves 60]

Prints, for the rule --rule (default ES:hexagon), after the floor of any request
(the page's round trip of GET /api/names, an answer the server keeps ready):
  1. a drag of one site among 12 (convex 12-gon and 12 random sites): per move
     the time from the mousemove to the next animation frame after the redraw
     (the re-triangulation on the server, /api/tri, included), median and 95th
     percentile over --moves moves one at a time, with the median of its parts
     (wait: from the move to the animation frame sending the request; fetch: the
     request's round trip, of which server: the server's own time from its
     Server-Timing header; draw: the redraw); then the redraws per
     second while the mouse moves at every animation frame for 2 s, and the
     drop (mouseup to the flip graph's answer drawn); then the same drag by
     the browser's own input events (which chromium aligns with animation
     frames, as a real mouse's), median over --moves moves;
  2. the flip graph of 10 sites (convex 10-gon, 1430 triangulations, and 10
     random sites) from request to drawn, median of --runs (the server's graph
     cache emptied before each: computed every time);
  3. the LOT of 10^5 uniform points from the click to drawn, median of --runs,
     with the median of its parts (fetch, server, decode, draw on the canvases).
The browser and the server are the browser test's (python/tests/browser_explorer.py).
"""
import argparse
import math
import os
import statistics
import sys
import tempfile
import threading

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "python", "tests"))
import browser_explorer as bx   # noqa: E402  (exits 77 without chromium or selenium)
from fliplab import explorer    # noqa: E402

# One move at a time: dispatch the mousemove the page listens to and wait
# until its redraw is recorded; then one move per animation frame for 2 s,
# counting the redraws; then the drop, until the flip graph's answer is drawn.
DRAG_JS = """const [i, moves, done] = arguments;
const c = document.querySelectorAll('#sites .site')[i], r = $('sites').getBoundingClientRect();
const x = r.left + Number(c.getAttribute('cx')), y = r.top + Number(c.getAttribute('cy'));
const drags = () => __fliplabTimings.filter((t) => t.what === 'drag');
const until = (f) => new Promise((ok) => { const g = () => f() ? ok() : setTimeout(g, 1); g(); });
const move = (k) => window.dispatchEvent(new MouseEvent('mousemove',
  {clientX: x + 8 * Math.sin(k / 5), clientY: y + 8 * Math.cos(k / 7) - 8}));
__fliplabTimings.length = 0;
c.dispatchEvent(new MouseEvent('mousedown', {bubbles: true, clientX: x, clientY: y}));
(async () => {
  for (let k = 0; k < moves; k++) {
    move(k);
    await until(() => drags().length > k);
  }
  const one = drags();
  await new Promise((ok) => setTimeout(ok, 50));
  const n0 = drags().length, t0 = performance.now();
  let k = moves;
  await new Promise((ok) => { const f = () => {
    if (performance.now() - t0 > 2000) return ok();
    move(k++); requestAnimationFrame(f); }; f(); });
  const fps = 1000 * (drags().length - n0) / (performance.now() - t0);
  await until(() => !S.drag.busy);
  __fliplabTimings.length = 0;
  window.dispatchEvent(new MouseEvent('mouseup', {}));
  await until(() => __fliplabTimings.some((t) => t.what === 'graph'));
  const drop = __fliplabTimings.find((t) => t.what === 'graph').frame;
  done({frame: one.map((t) => t.frame), wait: one.map((t) => t.wait),
        fetch: one.map((t) => t.fetch),
        server: one.map((t) => t.server),
        draw: one.map((t) => t.draw), fps: fps, moves: k - moves, drop: drop});
})();"""


def convex(n):
    return [[round(math.cos(2 * math.pi * k / n), 6), round(math.sin(2 * math.pi * k / n), 6)]
            for k in range(n)]


def random_sites(n, seed):
    return np.round(np.random.default_rng(seed).random((n, 2)), 6).tolist()


def show(pg, sites, rule, srv=None):
    """The sites under the rule, drawn; the time of their request to drawn (ms).
    With srv, its /api/graph cache emptied first: the graph is computed."""
    if srv is not None:
        with srv.lock:
            srv.cache.clear()
    pg.d.execute_script("$('rule').value = arguments[1]; __fliplabTimings.length = 0;"
                        "setSites(arguments[0], true);", sites, rule)
    pg.settle()
    pg.until(lambda: pg.d.execute_script("return __fliplabTimings.length > 0;"), "drawn", 60)
    return pg.d.execute_script("return __fliplabTimings[__fliplabTimings.length - 1].frame;")


def census(pg):
    return pg.d.execute_script("""const g = S.graph;
        return g ? (g.too_large ? '> ' + g.more_than + ' (too many to draw: the LOT)'
                                : String(g.census.triangulations)) : S.pending + '?';""")


def drag(pg, sites, rule, moves):
    show(pg, sites, rule)
    n = census(pg)
    pg.d.set_script_timeout(600)
    r = pg.d.execute_async_script(DRAG_JS, len(sites) // 2, moves)
    t = sorted(r["frame"])
    r["median"], r["p95"] = statistics.median(t), t[min(len(t) - 1, math.ceil(0.95 * len(t)) - 1)]
    return n, r


def real_drag(pg, moves):
    """A drag by the browser's own input events (selenium's actions: chromium
    delivers them aligned to animation frames, as a mouse's): each redraw's
    parts, from the page's timings."""
    from selenium.webdriver.common.action_chains import ActionChains
    from selenium.webdriver.common.by import By
    e = pg.d.find_elements(By.CSS_SELECTOR, "#sites .site")[5]
    pg.d.execute_script("__fliplabTimings.length = 0;")
    chain = ActionChains(pg.d, duration=20).click_and_hold(e)
    for k in range(moves):
        chain.move_by_offset(2 if k % 2 else -2, 1)
    chain.release().perform()
    pg.settle()
    return pg.d.execute_script("return __fliplabTimings.filter((t) => t.what === 'drag');")


def round_trip(pg, runs=30):
    """The floor of any request: GET /api/names (a prepared answer) from the page, ms."""
    pg.d.set_script_timeout(60)
    t = pg.d.execute_async_script("""const done = arguments[0], t = [];
        (async () => { for (let k = 0; k < 30; k++) { const t0 = performance.now();
          await (await fetch('/api/names')).json(); t.push(performance.now() - t0); }
          done(t); })();""")
    return statistics.median(t)


def lot_click(pg, n):
    """The LOT's timing entry: frame (click to drawn), fetch, decode, draw, bytes."""
    pg.d.execute_script("$('lot-n').value = arguments[0]; __fliplabTimings.length = 0;"
                        "$('lot-go').click();", n)
    pg.until(lambda: pg.d.execute_script(
        "return __fliplabTimings.some((t) => t.what === 'lot');"), "the LOT", 120)
    return pg.d.execute_script("return __fliplabTimings.find((t) => t.what === 'lot');")


def row(what, count, n, ms, target):
    print("%-32s %-34s %4d %10.1f   %s" % (what, count, n, ms, target))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--runs", type=int, default=5)
    ap.add_argument("--moves", type=int, default=60)
    ap.add_argument("--rule", default="ES:hexagon")
    ap.add_argument("--only", choices=("drag", "graph", "lot"), help="one of the three parts")
    a = ap.parse_args()
    srv = explorer.Server(0, time_limit=60)
    threading.Thread(target=srv.serve_forever, daemon=True).start()
    d = bx.browser(tempfile.mkdtemp(prefix="fliplab-downloads-"))
    try:
        d.get("http://127.0.0.1:%d/" % srv.server_address[1])
        pg = bx.Page(d)
        pg.until(lambda: d.execute_script("return S.names !== null;"), "the names")
        print("# bench_explorer: rule %s, chromium headless; load %s"
              % (a.rule, os.getloadavg()[0]))
        print("%-32s %-34s %4s %10s   %s" % ("what", "triangulations", "n", "ms", "target"))
        row("round trip of GET /api/names", "", 30, round_trip(pg), "the floor of a request")
        for name, s in (("drag, convex 12-gon", convex(12)),
                        ("drag, 12 random sites", random_sites(12, 1))):
            if a.only not in (None, "drag"):
                break
            count, r = drag(pg, s, a.rule, a.moves)
            med, p95, n = r["median"], r["p95"], len(r["frame"])
            ok = "met" if p95 < 16 else "median met" if med < 16 else "not met"
            row(name + " (median)", count, n, med, "16 ms: %s" % ok)
            row(name + " (95th pct)", count, n, p95, "")
            row("  of which the wait to be sent", "", n, statistics.median(r["wait"]), "")
            row("  of which fetch (median)", "", n, statistics.median(r["fetch"]), "")
            row("    of which the server (median)", "", n, statistics.median(r["server"]), "")
            row("  of which draw (median)", "", n, statistics.median(r["draw"]), "")
            row("  redraws/s, a move every frame", "", r["moves"], r["fps"], "frames/s")
            row("  drop: the flip graph's answer", count, 1, r["drop"], "")
            t = real_drag(pg, a.moves)
            med = statistics.median(x["frame"] for x in t)
            row("  by input events (median)", count, len(t), med,
                "16 ms: %s" % ("met" if med < 16 else "not met"))
            row("    the same from the event's timestamp", "", len(t),
                statistics.median(x["frame"] + x["input"] for x in t), "")
            for part in ("input", "wait", "fetch", "draw"):
                row("    of which " + part, "", len(t), statistics.median(x[part] for x in t), "")
        for name, s in (("flip graph, convex 10-gon", convex(10)),
                        ("flip graph, 10 random sites", random_sites(10, 1))):
            if a.only not in (None, "graph"):
                break
            t = [show(pg, s, a.rule, srv) for _ in range(a.runs)]
            med = statistics.median(t)
            row(name, census(pg), a.runs, med, "1 s: %s" % ("met" if med < 1000 else "not met"))
        t = [lot_click(pg, 100000) for _ in range(a.runs if a.only in (None, "lot") else 0)]
        med = statistics.median(x["frame"] for x in t) if t else math.nan
        if t:
            row("LOT of 10^5 uniform points", "-", a.runs, med,
                "1 s: %s" % ("met" if med < 1000 else "not met"))
        for part in ("fetch", "server", "decode", "draw") if t else ():
            row("  of which " + part + " (median)", "", a.runs,
                statistics.median(x[part] for x in t), "")
        if t:
            print("# the LOT's message: %d bytes" % t[0]["bytes"])
        print("# load %s at the end" % os.getloadavg()[0])
    finally:
        d.quit()
        srv.shutdown()
    return 0


if __name__ == "__main__":
    sys.exit(main())
