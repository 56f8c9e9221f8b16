"""Equations in the docs render as math on the built site, offline:

* ``pymdownx.arithmatex`` (generic) is on, and KaTeX with its auto-render
  extension is served from the site itself (``docs/assets/katex``; no
  ``http`` URL among the scripts and styles);
* every equation of the docs (``$...$``, ``$$...$$``) compiles with the
  vendored KaTeX (run with node when it is installed).
"""

from __future__ import annotations

import html
import json
import re
import shutil
import subprocess

import pytest
import yaml

from tests.conftest import ROOT

DOCS = ROOT / "docs"


class _Loader(yaml.SafeLoader):
    pass


_Loader.add_multi_constructor("tag:yaml.org,2002:python/", lambda loader, suffix, node: None)


def _config() -> dict:
    return yaml.load((ROOT / "mkdocs.yml").read_text(encoding="utf-8"), Loader=_Loader)


def test_katex_served_from_the_site():
    cfg = _config()
    exts = {next(iter(e)) if isinstance(e, dict) else e: e for e in cfg["markdown_extensions"]}
    assert exts["pymdownx.arithmatex"]["pymdownx.arithmatex"]["generic"] is True
    assets = cfg["extra_javascript"] + cfg["extra_css"]
    assert not [a for a in assets if "://" in a], "math must not need the network"
    for a in assets:
        assert (DOCS / a).is_file(), a
    css = (DOCS / "assets/katex/katex.min.css").read_text(encoding="utf-8")
    fonts = set(re.findall(r"url\(fonts/([\w-]+\.woff2)\)", css))
    assert fonts and all((DOCS / "assets/katex/fonts" / f).is_file() for f in fonts)
    assert (DOCS / "assets/katex/LICENSE").is_file()


def _equations() -> list[tuple[str, str, bool]]:
    import markdown

    md = markdown.Markdown(extensions=["tables", "pymdownx.superfences", "pymdownx.arithmatex"],
                           extension_configs={"pymdownx.arithmatex": {"generic": True}})
    out = []
    for f in sorted(DOCS.rglob("*.md")):
        page = md.reset().convert(f.read_text(encoding="utf-8"))
        for m in re.finditer(r'class="arithmatex">(.*?)</(?:div|span)>', page, re.S):
            tex = html.unescape(m.group(1)).strip()
            out.append((str(f.relative_to(ROOT)), tex[2:-2], tex.startswith("\\[")))
    return out


def test_docs_have_equations():
    pages = {p for p, _, _ in _equations()}
    assert "docs/types/vibration.md" in pages


_NODE = r"""
const katex = require(process.argv[1]);
const eqs = JSON.parse(require('fs').readFileSync(0, 'utf8'));
const bad = [];
for (const [page, tex, display] of eqs) {
  try { katex.renderToString(tex, {displayMode: display, throwOnError: true}); }
  catch (e) { bad.push(page + ': ' + e.message); }
}
console.log(JSON.stringify(bad));
"""


@pytest.mark.skipif(shutil.which("node") is None, reason="node is not installed")
def test_every_equation_compiles_with_the_vendored_katex():
    eqs = _equations()
    p = subprocess.run(["node", "-e", _NODE, str(DOCS / "assets/katex/katex.min.js")], input=json.dumps(eqs),
                       capture_output=True, text=True, timeout=60)
    assert p.returncode == 0, p.stderr
    assert json.loads(p.stdout) == []


def _type_pages() -> list:
    return sorted(p for p in (DOCS / "types").glob("*.md") if p.name != "index.md")


def _html(page) -> str:
    import markdown

    md = markdown.Markdown(extensions=["tables", "pymdownx.superfences", "pymdownx.arithmatex"],
                           extension_configs={"pymdownx.arithmatex": {"generic": True}})
    return md.convert(page.read_text(encoding="utf-8"))


def test_every_type_page_states_its_equations_in_math_markup():
    """No equation left as a monospace block (an indented code block: its
    overdots sit beside the letter and its equation numbers drift); every
    type page has math, display equations number with \\tag, and overdots
    are \\dot / \\ddot, not combining characters, inside math."""
    bad = []
    for page in _type_pages():
        html_ = _html(page)
        name = page.name
        plain_code = re.findall(r"<pre><code>(.*?)</code></pre>", html_, re.S)   # indented blocks: no language
        bad += [f"{name}: monospace equation block: {html.unescape(c).strip()[:70]!r}" for c in plain_code if "=" in c]
        maths = [html.unescape(m) for m in re.findall(r'class="arithmatex">(.*?)</(?:div|span)>', html_, re.S)]
        rest = re.sub(r'<(div|span) class="arithmatex">.*?</\1>|<pre>.*?</pre>|<code>.*?</code>', "", html_, flags=re.S)
        bad += [f"{name}: '$$' not taken as math (a display equation needs blank lines around it, "
                f"and 4 spaces of indent in a list item)"] if "$$" in rest else []
        if not maths:
            bad.append(f"{name}: no equation in math markup")
        bad += [f"{name}: combining overdot inside math: {m[:60]!r}" for m in maths if re.search("[\u0307\u0308]", m)]
        for m in maths:
            for tag in re.findall(r"\\tag\{([^}]*)\}", m):
                one = r"\d+\.\d+[a-z]?(?:,[a-z])*"       # 17.30b, 17.30c,d (as the notes write them)
                if not re.fullmatch(rf"{one}(?:(?:, |--){one})*", tag):
                    bad.append(f"{name}: \\tag{{{tag}}} is not an equation number of the notes")
    assert not bad, "\n".join(bad)


def test_display_equations_have_their_own_lines():
    """``$$`` on lines of their own (a forge's Markdown view shows them as
    math blocks, and a plain view keeps them apart from the text)."""
    bad = []
    for page in _type_pages():
        for n, line in enumerate(page.read_text(encoding="utf-8").splitlines(), 1):
            if "$$" in line and line.strip() != "$$":
                bad.append(f"{page.name}:{n}: {line.strip()[:70]}")
    assert not bad, "\n".join(bad)
