"""browser_explorer.py: the explorer's page in a real headless browser
(Debian's chromium, chromium-driver and python3-selenium), ctest's
explorer_browser; exit 77 (skip) when one of them is missing.

It starts the server (fliplab.explorer) on a free loopback port, loads the
page and, by mouse events as a person would: places six sites by clicks,
picks -R_1 by a formula, checks the counts against fliplab.flipgraph on the
sites the page shows, hovers an interior edge (the decision shown is the
library's), clicks it (the page moves to the node the library's flip
reaches), steps and runs to a sink (one of the library's sinks), clicks a
node of the flip graph, drags a site onto another and types a bad formula
and a bad shape (a message, the page still works), exports SVG, CSV and the
command line (the command runs and gives the page's sinks), runs the LOT
panel (the figures are lot()'s; the triangles the canvases hold, read through
window.__fliplabLot, are the CLI's lot --out; its SVG export draws every
triangle), drags a site (while dragging
the triangles are lot()'s of the moved sites; the drop recomputes the flip
graph: its counts are flipgraph()'s and the current node is the dragged LOT),
and times site drags (frames per second of the redraw, printed and kept in
drag-fps.txt).  Screenshots of the main views go to
FLIPLAB_ARTEFACTS (default: the build's explorer-artefacts/).
"""
import os
import shlex
import subprocess
import sys
import tempfile
import threading
import time

try:
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service
    from selenium.webdriver.common.action_chains import ActionChains
    from selenium.webdriver.common.by import By
    from selenium.webdriver.support.ui import Select, WebDriverWait
except ImportError:
    print("explorer_browser: skipped: no python3-selenium (scripts/deps installs it)")
    sys.exit(77)
DRIVER = "/usr/bin/chromedriver"
if not os.path.exists(DRIVER):
    print("explorer_browser: skipped: no chromium-driver (scripts/deps installs it)")
    sys.exit(77)

import numpy as np   # noqa: E402

import fliplab       # noqa: E402
from fliplab import explorer   # noqa: E402

OUT = os.environ.get("FLIPLAB_ARTEFACTS") or os.path.join(
    os.environ.get("FLIPLAB_BUILD_DIR", tempfile.gettempdir()), "explorer-artefacts")
fliplab.define("bnegR = -R")


def browser(downloads):
    o = webdriver.ChromeOptions()
    for a in ("--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
              "--disable-component-update", "--disable-sync", "--no-first-run",
              "--user-data-dir=" + tempfile.mkdtemp(prefix="fliplab-chromium-"),
              "--window-size=1300,1500"):
        o.add_argument(a)
    o.add_experimental_option("prefs", {"download.default_directory": downloads,
                                        "download.prompt_for_download": False})
    return webdriver.Chrome(service=Service(DRIVER), options=o)


class Page:
    def __init__(self, d):
        self.d = d

    def el(self, id_):
        return self.d.find_element(By.ID, id_)

    def text(self, id_):
        return self.el(id_).text

    def until(self, cond, what, timeout=20):
        WebDriverWait(self.d, timeout).until(lambda _: cond(), message=what)

    def click_at(self, id_, x, y):
        """A click at (x, y) from the element's top left corner (selenium 4's
        offsets are from its centre)."""
        e = self.el(id_)
        w, h = e.size["width"], e.size["height"]
        ActionChains(self.d).move_to_element_with_offset(e, x - w / 2, y - h / 2).click().perform()

    def click_at_move(self, id_, x, y):
        """The mouse moved to (x, y) from the element's top left corner."""
        e = self.el(id_)
        w, h = e.size["width"], e.size["height"]
        ActionChains(self.d).move_to_element_with_offset(e, x - w / 2, y - h / 2).perform()

    def sites(self):
        """The sites the page holds, as it sends them to the server."""
        return self.d.execute_script("return S.sites;")

    def settle(self):
        self.until(lambda: self.d.execute_script("return !S.pending;"), "the page settles")

    def shot(self, name):
        os.makedirs(OUT, exist_ok=True)
        self.d.save_screenshot(os.path.join(OUT, name + ".png"))


def check_counts(pg, rule):
    g = fliplab.flipgraph(np.array(pg.sites()), rule)
    pg.until(lambda: pg.text("count-triangulations") == str(len(g.nodes)), "triangulations")
    assert pg.text("count-sinks") == str(len(g.sinks)), (pg.text("count-sinks"), g)
    return g


def place_and_pick(pg):
    for x, y in ((60, 460), (460, 460), (460, 60), (60, 60), (235, 280), (300, 190)):
        pg.click_at("sites", x, y)
        pg.settle()
    assert len(pg.sites()) == 6
    pg.el("define").send_keys("negR = -R")
    rule = pg.el("rule")
    rule.clear()
    rule.send_keys("negR_1")
    pg.el("apply").click()
    pg.settle()
    return check_counts(pg, "bnegR_1")


def hover_and_flip(pg):
    """Hover each interior flippable edge; the shown decision is the rule's,
    and a click moves to the library's other triangulation."""
    hits = pg.d.execute_script("""return [...document.querySelectorAll('.edge-hit.flippable')]
        .filter((e) => { const r = e.getBoundingClientRect();
          return document.elementFromPoint(r.x + r.width / 2, r.y + r.height / 2) === e; });""")
    assert hits, "no flippable edge at T1 with its middle free"
    ActionChains(pg.d).move_to_element(hits[0]).perform()
    info = pg.text("info")
    assert "the rule prefers" in info, info
    key = hits[0].get_attribute("data-edge")
    fl = pg.d.execute_script("return flipsHere().get(arguments[0]);", key)
    q = np.array(pg.sites())[fl["f"]["quad"]]
    dec = ["AC", "BD", "either"][int(fliplab.decide(q[None], "bnegR_1")[0])]
    assert dec in info and fl["f"]["decision"] == dec
    hits[0].click()
    pg.until(lambda: pg.d.execute_script("return S.node;") == fl["to"], "the flip")


def step_and_run(pg, g):
    pg.el("to-node0").click()
    pg.el("step").click()
    pg.el("run").click()
    node = pg.d.execute_script("return S.node;")
    assert node in g.sinks.tolist(), (node, g.sinks)
    assert "sink" in pg.text("count-current")
    pg.shot("sink")
    n = pg.d.find_elements(By.CSS_SELECTOR, "#graph .node")
    assert len(n) == len(g.nodes)
    n[1].click()
    pg.until(lambda: pg.text("count-current").startswith("T2"), "node click")
    pg.shot("graph")


def bad_input(pg):
    """A drag onto another site, a bad formula, a bad shape: a message, no break."""
    s = pg.sites()
    v = pg.d.execute_script("return S.view;")
    def scr(p):
        return (p[0] - v["x0"]) * v["k"], v["size"] - (p[1] - v["y0"]) * v["k"]
    e = pg.d.find_elements(By.CSS_SELECTOR, "#sites .site")[0]
    x, y = scr(s[1])
    ActionChains(pg.d).click_and_hold(e).move_to_element_with_offset(
        pg.el("sites"), x - 260, y - 260).release().perform()
    pg.settle()
    pg.until(lambda: "equal" in pg.text("message") or "collinear" in pg.text("message")
             or pg.text("count-triangulations") != "-", "a drag onto a site")
    pg.d.execute_script("S.sites = arguments[0]; refresh();", s)     # back as they were
    pg.settle()
    for field, value, word in (("define", "negR = sin(", "syntax"),
                               ("rule", "ES:poly:0 0;1", "shape")):
        box = pg.el(field)
        box.clear()
        box.send_keys(value)
        pg.el("apply").click()
        pg.settle()
        pg.until(lambda: word in pg.text("message"), "message " + word)
        pg.shot("error-" + field)
        pg.el("define").clear()
    pg.el("rule").clear()
    pg.el("rule").send_keys("ES:hexagon")
    pg.el("apply").click()
    pg.settle()
    check_counts(pg, "ES:hexagon")
    at = pg.d.execute_script("""const r = $('sites').getBoundingClientRect();
        for (const t of document.querySelectorAll('#sites .tri')) {
          const p = t.getAttribute('points').split(' ').map((s) => s.split(',').map(Number));
          const x = (p[0][0] + p[1][0] + p[2][0]) / 3, y = (p[0][1] + p[1][1] + p[2][1]) / 3;
          if (document.elementFromPoint(r.x + x, r.y + y) === t) return [x, y];
        }
        return null;""")
    assert at, "no triangle with its centroid free"
    pg.click_at_move("sites", *at)
    pg.until(lambda: "circumscribing" in pg.text("info"), "the homothet")
    assert ("rounding shape" in pg.text("info")
            or pg.d.find_elements(By.ID, "homothet")), pg.text("info")
    pg.shot("homothet")


def exports(pg, downloads, g):
    pg.el("export-cmd").click()
    pg.until(lambda: "flipgraph" in pg.text("command"), "the command")
    cmd = [x for x in pg.text("command").splitlines() if x.startswith("fliplab ")][0]
    pg.el("export-csv").click()
    pg.el("export-svg").click()
    pg.el("export-graph").click()
    files = [os.path.join(downloads, f) for f in ("sites.csv", "triangulation.svg",
                                                  "flipgraph.svg")]
    pg.until(lambda: all(os.path.exists(f) for f in files), "downloads")
    assert open(files[1]).read().count("<polygon") >= 4
    assert "<circle" in open(files[2]).read()
    out = subprocess.run([os.environ["FLIPLAB_BIN"]] + shlex.split(cmd)[1:], cwd=downloads,
                         capture_output=True, text=True, check=True).stdout
    sinks = [ln for ln in out.splitlines() if ln.startswith("sinks: ")]
    assert sinks == ["sinks: %d" % len(g.sinks)], (out, g)


def lot_panel(pg, downloads):
    n = pg.el("lot-n")
    n.clear()
    n.send_keys("20000")
    pg.el("lot-go").click()
    pg.until(lambda: "compare DT" in pg.text("lot-figures"), "the LOT", timeout=60)
    p = fliplab.samplers.points(20000, "uniform", 1)
    t, d = fliplab.lot(p, "ES:hexagon"), fliplab.lot(p, "DT")
    c = t.compare(d)
    assert ("%d of %d triangles" % (c["triangles_common"], c["triangles_b"])
            in pg.text("lot-figures"))
    held = pg.d.execute_script("return window.__fliplabLot();")
    assert held["points"] == p.ravel().tolist()
    for key, rule in (("triangles", "ES:hexagon"), ("dt", "DT")):
        out = os.path.join(tempfile.mkdtemp(prefix="fliplab-lot-"), "t.csv")
        subprocess.run([os.environ["FLIPLAB_BIN"], "lot", "--random", "20000", "--sampler",
                        "uniform", "--seed", "1", "--rule", rule, "--out", out],
                       capture_output=True, check=True)
        cli = np.genfromtxt(out, delimiter=",", skip_header=1, usecols=(0, 1, 2), dtype=np.int64)
        assert held[key] == cli.ravel().tolist(), key
    pg.el("export-lot").click()                  # the SVG, made from the held arrays
    svg = os.path.join(downloads, "lot.svg")
    pg.until(lambda: os.path.exists(svg) and open(svg).read().endswith("</svg>\n"), "lot.svg")
    assert open(svg).read().count("Z") == len(t.triangles) + len(d.triangles)  # path closes
    pg.shot("lot")


DRAG_JS = """const [i, done] = arguments;
const c = document.querySelectorAll('#sites .site')[i], r = $('sites').getBoundingClientRect();
const x = r.left + Number(c.getAttribute('cx')), y = r.top + Number(c.getAttribute('cy'));
const until = (f) => new Promise((ok) => { const g = () => f() ? ok() : setTimeout(g, 5); g(); });
__fliplabTimings.length = 0;
c.dispatchEvent(new MouseEvent('mousedown', {bubbles: true, clientX: x, clientY: y}));
window.dispatchEvent(new MouseEvent('mousemove', {clientX: x + 23, clientY: y - 17}));
until(() => __fliplabTimings.some((t) => t.what === 'drag') && !S.drag.busy).then(() =>
  done({sites: S.sites, tri: S.dragTri.triangles, stale: $('graph').classList.contains('stale')}));
"""


def drag_and_drop(pg, rule):
    """A site dragged: the triangles drawn meanwhile are lot()'s of the moved sites
    (the flip graph greyed); the drop recomputes the flip graph (flipgraph()'s
    counts) and stays on the dragged LOT."""
    r = pg.d.execute_async_script(DRAG_JS, 2)
    t = fliplab.lot(np.array(r["sites"]), rule)
    assert r["tri"] == t.triangles.tolist() and r["stale"], r
    pg.d.execute_script("window.dispatchEvent(new MouseEvent('mouseup', {}));")
    pg.settle()
    g = check_counts(pg, rule)
    assert g.points.tolist() == r["sites"]
    now = pg.d.execute_script("""const g = S.graph;
        return g.nodes[S.node].map((k) => g.triangles[k].v.slice().sort((a, b) => a - b));""")
    assert sorted(now) == sorted(sorted(x) for x in t.triangles.tolist()), (now, t.triangles)
    assert not pg.d.execute_script("return $('graph').classList.contains('stale');")


def drag_fps(pg):
    """Redraws of the triangulation while a site is dragged, per second."""
    e = pg.d.find_elements(By.CSS_SELECTOR, "#sites .site")[4]
    pg.d.execute_script("__fliplabTimings.length = 0;")
    t0 = time.perf_counter()
    moves = 30
    chain = ActionChains(pg.d, duration=5).click_and_hold(e)
    for k in range(moves):
        chain.move_by_offset(1 if k % 2 else -1, 1)
    chain.release().perform()
    pg.settle()
    dt = time.perf_counter() - t0
    drags = pg.d.execute_script("return __fliplabTimings.filter((t) => t.what === 'drag')"
                                ".map((t) => t.frame).sort((a, b) => a - b);")
    ms = pg.d.execute_script("""const t = performance.now();
        for (let k = 0; k < 50; k++) drawSites();
        return (performance.now() - t) / 50;""")
    rt = pg.d.execute_async_script("""const done = arguments[0], t = performance.now();
        (async () => { for (let k = 0; k < 10; k++) await refreshOnce();
                       done((performance.now() - t) / 10); })();""")
    line = ("explorer_browser: drag of %d moves in %.2f s, %d redrawn (median %.1f ms from the "
            "move to the frame); one redraw of %d sites %.2f ms (%.0f frames/s); one round "
            "trip to the server (graph and redraw) %.1f ms"
            % (moves, dt, len(drags), drags[len(drags) // 2] if drags else float("nan"),
               len(pg.sites()), ms, 1000 / max(ms, 1e-3), rt))
    print(line)
    with open(os.path.join(OUT, "drag-fps.txt"), "w") as f:   # beside the screenshots
        f.write(line + "\n")


def main():
    srv = explorer.Server(0, time_limit=30)
    threading.Thread(target=srv.serve_forever, daemon=True).start()
    downloads = tempfile.mkdtemp(prefix="fliplab-downloads-")
    d = browser(downloads)
    try:
        d.get("http://127.0.0.1:%d/" % srv.server_address[1])
        pg = Page(d)
        pg.until(lambda: d.execute_script("return S.names !== null;"), "the names")
        g = place_and_pick(pg)
        pg.shot("placed")
        hover_and_flip(pg)
        step_and_run(pg, g)
        exports(pg, downloads, g)
        bad_input(pg)
        lot_panel(pg, downloads)
        drag_and_drop(pg, "ES:hexagon")
        drag_fps(pg)
        errors = [x for x in d.get_log("browser") if x["level"] == "SEVERE"
                  and "status of 4" not in x["message"]]
        assert errors == [], errors
    finally:
        d.quit()
        srv.shutdown()
    print("explorer_browser: ok; screenshots in %s" % OUT)
    return 0


if __name__ == "__main__":
    sys.exit(main())
