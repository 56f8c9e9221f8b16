"""Every docs page rendered in headless Chromium, as a reader sees it.

The site is built with mkdocs (as ``mkdocs build`` publishes it; without
mkdocs, each page is converted by python-markdown with the extensions of
mkdocs.yml and given the same KaTeX scripts), each page is opened in a
1280 × 900 window, and a probe script added to the page reports, once the
page has loaded and KaTeX has typeset it:

* **KaTeX rendered**: every equation that arithmatex marked holds a
  ``.katex`` element, none is a ``.katex-error``, every type page has
  equations, and no raw ``$$``, ``\\(``, ``\\[`` or TeX command is left in
  the text (code blocks aside);
* every display equation fits the column (no scroll bar), its number clear of it;
* **no image is scaled below its label size**: for each image, its displayed
  width over its natural width times its smallest text (the ``Label font px``
  text chunk that dyncli's plotting layer writes into a PNG, or the smallest
  ``font-size`` of an SVG) is at least 9 pt (12 CSS px).

Skipped only when no Chromium (or Chrome) is installed.  Debian:
``apt-get install -y chromium`` (``.ci/run`` does it when it can).
"""

from __future__ import annotations

import importlib.util
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import pytest

from tests.conftest import ROOT

BROWSERS = ("chromium", "chromium-browser", "google-chrome", "google-chrome-stable")
BROWSER = next((shutil.which(b) for b in BROWSERS if shutil.which(b)), None)

pytestmark = [pytest.mark.slow, pytest.mark.skipif(BROWSER is None, reason="no Chromium/Chrome installed")]

WINDOW = (1280, 900)
#: the smallest legible text, CSS pixels: 9 pt at 96 px per inch
MIN_TEXT_PX = 9 * 96 / 72

FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
         "--disable-component-update", "--disable-sync", "--no-first-run",
         "--allow-file-access-from-files", f"--window-size={WINDOW[0]},{WINDOW[1]}",
         "--virtual-time-budget=15000", "--dump-dom"]

PROBE = r"""<script>
window.addEventListener("load", function () { setTimeout(function () {
  var art = document.querySelector("article") || document.body;
  var plain = art.cloneNode(true);
  plain.querySelectorAll("pre, code, .katex, script, style").forEach(function (e) { e.remove(); });
  var out = {
    arithmatex: art.querySelectorAll(".arithmatex").length,
    untypeset: Array.from(art.querySelectorAll(".arithmatex")).filter(function (e) {
      return !e.querySelector(".katex"); }).map(function (e) { return e.textContent.slice(0, 80); }),
    katex: art.querySelectorAll(".katex").length,
    errors: Array.from(art.querySelectorAll(".katex-error")).map(function (e) { return e.title || e.textContent; }),
    text: plain.textContent,
    crowded: Array.from(art.querySelectorAll(".katex-display")).filter(function (d) {
      var tag = d.querySelector(".tag"), right = 0;
      d.querySelectorAll(".katex-html > .base").forEach(function (b) {
        right = Math.max(right, b.getBoundingClientRect().right); });
      return d.scrollWidth > d.clientWidth + 1 || (tag && right > tag.getBoundingClientRect().left - 8);
    }).map(function (d) { var a = d.querySelector("annotation"); return (a ? a.textContent : "").slice(0, 70); }),
    images: Array.from(art.querySelectorAll("img")).map(function (im) {
      return {src: im.currentSrc || im.src, shown: im.getBoundingClientRect().width,
              natural: im.naturalWidth, loaded: im.complete && im.naturalWidth > 0}; })
  };
  var pre = document.createElement("pre");
  pre.id = "dyncli-probe";
  pre.textContent = JSON.stringify(out);
  document.body.appendChild(pre);
}, 500); });
</script>"""

RAW_TEX = re.compile(r"\$\$|\\\(|\\\)|\\\[|\\\]|\\(?:frac|mathbf|boldsymbol|dot|ddot|tag|tfrac|sqrt)\b")


def _build_mkdocs(out: Path) -> None:
    env = dict(os.environ, NO_MKDOCS_2_WARNING="1", NO_COLOR="1")
    p = subprocess.run([sys.executable, "-m", "mkdocs", "build", "-q", "-f", str(ROOT / "mkdocs.yml"), "-d", str(out)],
                       cwd=ROOT, env=env, capture_output=True, text=True, timeout=300)
    assert p.returncode == 0, p.stderr


def _build_markdown(out: Path) -> None:
    """Without mkdocs: python-markdown with mkdocs.yml's extensions, the
    KaTeX assets and scripts of mkdocs.yml around each page."""
    markdown = pytest.importorskip("markdown", reason="neither mkdocs nor python-markdown is installed")
    pytest.importorskip("pymdownx", reason="neither mkdocs nor pymdown-extensions is installed")
    from tests.docs.test_math import _config

    cfg = _config()
    exts, conf = [], {}
    for e in cfg["markdown_extensions"]:
        name, opts = (next(iter(e.items())) if isinstance(e, dict) else (e, None))
        exts.append(name)
        if opts:
            conf[name] = opts
    docs = ROOT / "docs"
    shutil.copytree(docs / "assets", out / "assets")
    shutil.copytree(docs / "img", out / "img")
    for f in docs.glob("*.png"):
        shutil.copy(f, out / f.name)
    for page in sorted(docs.rglob("*.md")):
        rel = page.relative_to(docs)
        if rel.parts[0] in ("examples", "course-example"):
            continue
        target = out / (rel.with_suffix("") if rel.stem != "index" else rel.parent) / "index.html"
        target.parent.mkdir(parents=True, exist_ok=True)
        up = "../" * (len(target.relative_to(out).parts) - 1)
        body = markdown.markdown(page.read_text(encoding="utf-8"), extensions=exts, extension_configs=conf)
        body = re.sub(r'(src=")(?!https?:|/)', lambda m: m.group(1) + up + "/".join(rel.parts[:-1]) + "/"
                      if len(rel.parts) > 1 else m.group(1) + up, body)
        head = "".join(f'<link rel="stylesheet" href="{up}{c}">' for c in cfg["extra_css"])
        scripts = "".join(f'<script src="{up}{s}"></script>' for s in cfg["extra_javascript"])
        target.write_text(f"<!doctype html><html><head><meta charset='utf-8'>{head}</head>"
                          f"<body><article style='max-width:688px'>{body}</article>{scripts}</body></html>",
                          encoding="utf-8")


@pytest.fixture(scope="module")
def site(tmp_path_factory) -> Path:
    out = tmp_path_factory.mktemp("site")
    if importlib.util.find_spec("mkdocs") is None:
        _build_markdown(out)
    else:
        _build_mkdocs(out)
    return out


def _pages(site: Path) -> list[Path]:
    return sorted(p for p in site.rglob("*.html") if "assets" not in p.relative_to(site).parts and p.name != "404.html")


def _probe(page: Path) -> dict:
    html = page.read_text(encoding="utf-8")
    page.write_text(html.replace("</body>", PROBE + "</body>", 1) if "dyncli-probe" not in html else html,
                    encoding="utf-8")
    with tempfile.TemporaryDirectory(prefix="dyncli-chromium-") as profile:
        p = subprocess.run([BROWSER, *FLAGS, f"--user-data-dir={profile}", page.as_uri()],
                           capture_output=True, text=True, timeout=120)
    m = re.search(r'<pre id="dyncli-probe">(.*?)</pre>', p.stdout, re.S)
    assert m, f"{page}: the probe did not report (Chromium exit {p.returncode}): {p.stderr[-500:]}"
    import html as html_mod

    return json.loads(html_mod.unescape(m.group(1)))


@pytest.fixture
def rendered(site) -> dict[str, dict]:
    pages = _pages(site)
    with ThreadPoolExecutor(max_workers=2) as pool:
        reports = list(pool.map(_probe, pages))
    return {str(p.relative_to(site)): r for p, r in zip(pages, reports)}


def label_px(image: Path) -> float | None:
    """The smallest text of a figure in pixels at its natural size: a PNG's
    ``Label font px`` text chunk (dyncli.render.plot writes it), an SVG's
    smallest ``font-size`` (in its own units, = px at its natural width)."""
    if image.suffix == ".svg":
        sizes = [float(s) for s in re.findall(r'font-size[=:]\s*"?([\d.]+)', image.read_text(encoding="utf-8"))]
        return min(sizes) if sizes else None
    from PIL import Image

    from dyncli.render.plot import LABEL_PX_KEY

    with Image.open(image) as im:
        v = getattr(im, "text", {}).get(LABEL_PX_KEY)
    return float(v) if v else None


def _katex_problems(rendered: dict) -> list[str]:
    bad = []
    for page, r in sorted(rendered.items()):
        if r["untypeset"]:
            bad.append(f"{page}: not typeset: {r['untypeset'][:3]}")
        if r["errors"]:
            bad.append(f"{page}: KaTeX errors: {r['errors'][:3]}")
        if r["arithmatex"] and r["katex"] < r["arithmatex"]:
            bad.append(f"{page}: {r['arithmatex']} equations but {r['katex']} .katex elements")
        raw = sorted({m.group(0) for m in RAW_TEX.finditer(r["text"])})
        if raw:
            bad.append(f"{page}: raw TeX left in the text: {raw}")
        if r["crowded"]:     # a scroll bar, or the equation number over the equation: split it over lines
            bad.append(f"{page}: display equations wider than the column: {r['crowded']}")
    types = [p for p in rendered if p.startswith("types/") and p != "types/index.html"]
    bad += [f"{p}: a type page without typeset equations" for p in types if rendered[p]["katex"] == 0]
    return bad


def _image_problems(rendered: dict) -> tuple[int, list[str]]:
    seen, bad = 0, []
    for page, r in sorted(rendered.items()):
        for im in r["images"]:
            if not im["src"].startswith("file:"):
                continue
            path = Path(im["src"][len("file://"):].split("?")[0].split("#")[0])
            px = label_px(path) if im["loaded"] else None
            if not im["loaded"]:
                bad.append(f"{page}: image {path.name} did not load")
            elif px is None:
                bad.append(f"{page}: {path.name} does not record its smallest text "
                           "(regenerate it with docs/gen_plots.py or the benchmark that draws it)")
            elif px * im["shown"] / im["natural"] < MIN_TEXT_PX - 0.01:
                bad.append(f"{page}: {path.name} shown at {im['shown']:.0f} of {im['natural']} px: its "
                           f"{px:.1f} px text is {px * im['shown'] / im['natural']:.1f} px (< 12 px = 9 pt)")
            seen += 1
    return seen, bad


def test_every_docs_page_in_chromium(rendered):
    """One test for all the checks, so that the pages are rendered once
    even when pytest-xdist spreads tests over workers."""
    assert len(rendered) >= 30 and "types/vibration/index.html" in rendered
    assert sum(1 for p in rendered if p.startswith("types/")) >= 20
    seen, image_bad = _image_problems(rendered)
    assert seen >= 5
    bad = _katex_problems(rendered) + image_bad
    assert not bad, "\n".join(bad)
