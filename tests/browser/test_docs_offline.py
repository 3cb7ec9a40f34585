"""
The built documentation works offline and reads well.

Every HTML page and stylesheet of the build is read for a script,
stylesheet, font, image or frame loaded from another host (links a reader
clicks are fine), and every local script or stylesheet a page loads must
exist in the build. Then headless Chromium opens pages from the files with
every request to another host blocked and recorded. The method page must
show its formulas typeset by MathJax (no TeX source left, no TeX error,
none wider than the column), having asked for nothing outside. On the
pages written by hand and the largest reference pages, no code example may
be wider than its box (the examples wrap), nor any text stick out of the
column. Screenshots are kept in tests/browser/artifacts/.

The pages are the build of ``make docs`` (doc/_build/html), which
``make test`` runs just before; if that build is missing or older than a
file of doc/ (pages, configuration, stylesheet), it is built here.
"""
import functools
import os
import re
import subprocess
import sys
from html.parser import HTMLParser
from pathlib import Path
from urllib.parse import urlsplit

import pytest

pytest.importorskip("playwright.sync_api")

ROOT = Path(__file__).resolve().parents[2]
DOC = ROOT / "doc"

#: an address on another host: ``http(s)://``, ``ftp://``, ``ws(s)://`` or ``//host/``
EXTERNAL = re.compile(r"^\s*(?:(?:https?|ftp|wss?):)?//", re.IGNORECASE)
#: where a stylesheet loads something: ``url(...)`` and ``@import``
CSS_LOADS = re.compile(r"""url\(\s*['"]?([^'")\s]*)|@import\s+['"]([^'"]*)""", re.IGNORECASE)
#: the attributes by which each tag loads a resource (``<a href>`` is a link, not a load)
LOADING = {"script": ("src",), "link": ("href",), "img": ("src", "srcset"),
           "source": ("src", "srcset"), "iframe": ("src",), "frame": ("src",),
           "embed": ("src",), "object": ("data",), "audio": ("src",),
           "video": ("src", "poster"), "track": ("src",), "input": ("src",)}
#: ``<link rel=...>`` that only name a related page (the others load: stylesheet,
#: icon, preload, preconnect, ...)
NAVIGATION_RELS = {"canonical", "alternate", "author", "license", "help", "index", "search",
                   "next", "prev", "top", "up"}


def _sources():
    """The files the HTML is built from: the pages, the configuration, the CSS."""
    for path in DOC.rglob("*"):
        if path.is_file() and not {"_build", "api"} & set(path.relative_to(DOC).parts):
            yield path


@pytest.fixture(scope="module")
def html(tmp_path_factory):
    """The folder of the built HTML documentation."""
    built = DOC / "_build" / "html"
    index = built / "index.html"
    if index.exists() and all(p.stat().st_mtime <= index.stat().st_mtime for p in _sources()):
        return built
    out = tmp_path_factory.mktemp("docs") / "html"
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(ROOT), os.environ.get("PYTHONPATH", "")]))
    run = subprocess.run([sys.executable, "-m", "sphinx", "-W", "-q", "-b", "html", str(DOC), str(out)],
                         env=env, capture_output=True, text=True, timeout=1800)
    assert run.returncode == 0, "the documentation does not build:\n" + run.stderr[-4000:]
    return out


class _Loads(HTMLParser):
    """The addresses an HTML page loads: (tag, address) pairs, and the CSS in it."""

    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.loads, self.css, self._in_style = [], [], False

    def handle_starttag(self, tag, attrs):
        attrs = dict(attrs)
        rel = set((attrs.get("rel") or "").lower().split())
        if tag == "link" and rel and rel <= NAVIGATION_RELS:
            return
        for name in LOADING.get(tag, ()):
            value = (attrs.get(name) or "").strip()
            if name == "srcset":                  # "address width, address width, ..."
                addresses = [a.split()[0] for a in value.split(",") if a.strip()]
            else:
                addresses = [value] if value else []
            self.loads += [(tag, address) for address in addresses]
        if attrs.get("style"):
            self.css.append(attrs["style"])
        self._in_style = tag == "style"

    def handle_endtag(self, tag):
        self._in_style = False

    def handle_data(self, data):
        if self._in_style:
            self.css.append(data)


class _Links(HTMLParser):
    """The ``<a href>`` of an HTML page."""

    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.links = []

    def handle_starttag(self, tag, attrs):
        if tag == "a" and dict(attrs).get("href"):
            self.links.append(dict(attrs)["href"])

    @classmethod
    def of(cls, path):
        parser = cls()
        parser.feed(path.read_text(encoding="utf-8"))
        return parser.links


def _css_loads(text):
    return [a or b for a, b in CSS_LOADS.findall(text)]


def _loads(text):
    parser = _Loads()
    parser.feed(text)
    return parser.loads + [("style", a) for css in parser.css for a in _css_loads(css)]


@functools.lru_cache(maxsize=None)
def _page_loads(path):
    return _loads(path.read_text(encoding="utf-8"))


def _pages(html):
    return sorted(html.rglob("*.html"))


def test_the_check_sees_every_kind_of_load():
    page = """<html><head>
    <link rel="stylesheet" href="//fonts.example.org/a.css">
    <link rel="preconnect" href="https://cdn.example.org">
    <link rel="canonical" href="https://docs.example.org/page.html">
    <script src="HTTPS://cdn.example.org/x.js"></script><script src="_static/local.js"></script>
    <style>@import "http://example.org/b.css"; p { background: url( 'https://example.org/c.png' ) }
    i { background: url(data:image/svg+xml;utf8,<svg xmlns="http://www.w3.org/2000/svg"/>) }</style>
    </head><body><a href="https://doi.org/10.1000/1">a paper</a>
    <img srcset="img/a.png 1x, https://example.org/d.png 2x">
    <div style="background: url(//example.org/e.png)"></div></body></html>"""
    external = sorted(a for _, a in _loads(page) if EXTERNAL.match(a))
    assert external == sorted(["//fonts.example.org/a.css", "https://cdn.example.org",
                               "HTTPS://cdn.example.org/x.js", "http://example.org/b.css",
                               "https://example.org/c.png", "https://example.org/d.png",
                               "//example.org/e.png"])


def test_the_reference_has_one_page_per_module(html):
    layers = sorted(html.glob("reference_*.html"))
    assert layers
    for layer in layers:
        links = {a for a in _Links.of(layer) if a.startswith("api/")}
        assert links, f"{layer.name} links to no module page"
        for link in links:
            assert (html / urlsplit(link).path).is_file(), f"{layer.name}: {link} not built"
    # no page near the size of the former single reference page (3.4 MB)
    assert max(p.stat().st_size for p in _pages(html)) < 1_000_000


def test_no_page_loads_anything_from_another_host(html):
    offenders = [f"{page.relative_to(html)}: <{tag}> {address}"
                 for page in _pages(html) for tag, address in _page_loads(page)
                 if EXTERNAL.match(address)]
    offenders += [f"{css.relative_to(html)}: {address}"
                  for css in sorted(html.rglob("*.css"))
                  for address in _css_loads(css.read_text(encoding="utf-8", errors="replace"))
                  if EXTERNAL.match(address)]
    assert not offenders, "loaded from another host:\n" + "\n".join(offenders)


def test_every_local_script_and_stylesheet_is_in_the_build(html):
    missing = []
    for page in _pages(html):
        for tag, address in _page_loads(page):
            if tag in ("script", "link") and not EXTERNAL.match(address):
                target = urlsplit(address).path
                if target and not (page.parent / target).is_file():
                    missing.append(f"{page.relative_to(html)}: {address}")
    assert not missing, "\n".join(missing)
    # MathJax itself is among them
    scripts = [a for tag, a in _page_loads(html / "method.html") if tag == "script"]
    assert any("mathjax" in a.lower() for a in scripts), scripts


def _block_other_hosts(context):
    """Abort every request that leaves this machine; return the list of those asked for."""
    asked = []

    def route(r):
        url = urlsplit(r.request.url)
        if url.scheme in ("file", "data", "blob") or url.hostname in ("localhost", "127.0.0.1", "::1"):
            r.continue_()
        else:
            asked.append(r.request.url)
            r.abort()

    context.route("**/*", route)
    return asked


def test_method_page_shows_typeset_math_offline(html, launch, artifacts):
    context = launch()
    asked = _block_other_hosts(context)
    page = context.new_page()
    errors = []
    page.on("console", lambda m: errors.append(m.text) if m.type == "error" else None)
    page.on("pageerror", lambda e: errors.append(str(e)))
    page.goto((html / "method.html").as_uri())
    # MathJax has typeset the page when its start-up promise resolves; the
    # page's load event waited for the scripts, so MathJax is there or never will be
    started = page.evaluate("() => Boolean(window.MathJax && MathJax.startup)")
    assert started, "MathJax did not load; requests to other hosts: " + ", ".join(asked)
    page.evaluate("() => MathJax.startup.promise")
    formulas = page.locator(".math").count()
    assert formulas > 100                      # the method page is mostly formulas
    untypeset = page.evaluate(
        "() => [...document.querySelectorAll('.math')]"
        ".filter(e => !e.querySelector('mjx-container')).map(e => e.textContent.slice(0, 80))")
    assert not untypeset, untypeset[:5]
    assert page.locator("mjx-merror").count() == 0, "TeX errors on the page"
    # at a laptop's width every displayed formula fits the column (none to scroll)
    wide = page.evaluate(
        "() => [...document.querySelectorAll('mjx-container[display=\"true\"]')]"
        ".filter(e => e.scrollWidth > e.clientWidth + 1)"
        ".map(e => e.closest('.math').textContent.trim().slice(0, 80))")
    assert not wide, f"formulas wider than the column: {wide}"
    text = page.evaluate("() => document.body.innerText")
    for tex in ("\\(", "\\[", "$$", "\\frac", "\\partial"):
        assert tex not in text, f"TeX source {tex!r} visible"
    # the Lagrange equations (5) and what follows them
    page.evaluate("() => document.getElementById('eq-lagrange').scrollIntoView()")
    page.screenshot(path=str(artifacts / "docs_method_offline.png"))
    assert not asked, "requests to other hosts: " + ", ".join(asked)
    assert not errors, errors


#: the text that sticks out of the column of a page (the theme would clip it),
#: unless it is in a box that scrolls (as tables and displayed formulas are)
STICKING_OUT = """() => {
    const column = document.querySelector('article') || document.body;
    const right = column.getBoundingClientRect().right + 1;
    const inScrollBox = e => {
        for (let a = e.parentElement; a && a !== column; a = a.parentElement) {
            if (['auto', 'scroll'].includes(getComputedStyle(a).overflowX)) return true;
        }
        return false;
    };
    const walker = document.createTreeWalker(column, NodeFilter.SHOW_TEXT);
    const range = document.createRange(), out = [];
    for (let t = walker.nextNode(); t; t = walker.nextNode()) {
        if (!t.textContent.trim()) continue;
        range.selectNodeContents(t);
        if (range.getBoundingClientRect().right > right && !inScrollBox(t)) {
            out.push(t.textContent.trim().slice(0, 80));
        }
    }
    return out;
}"""


def test_no_code_example_or_text_is_cut(html, launch, artifacts):
    # every page written by hand, and the reference pages with the most code
    # (the CSS that wraps code is the same on all pages)
    modules = sorted((html / "api").glob("*.html"), key=lambda p: p.stat().st_size)
    pages = sorted(html.glob("*.html")) + modules[-5:]
    # the layout of code does not depend on scripts: without them the pages load fast
    context = launch(java_script_enabled=False)
    asked = _block_other_hosts(context)
    page = context.new_page()
    too_wide, sticking_out = [], []
    for path in pages:
        page.goto(path.as_uri())
        too_wide += [f"{path.relative_to(html)}: {line}" for line in page.evaluate(
            "() => [...document.querySelectorAll('pre')]"
            ".filter(e => e.scrollWidth > e.clientWidth + 1)"
            ".map(e => e.textContent.split('\\n').reduce((a, b) => a.length >= b.length ? a : b))")]
        sticking_out += [f"{path.relative_to(html)}: {what}" for what in page.evaluate(STICKING_OUT)]
    assert not too_wide, f"{len(too_wide)} code blocks cut:\n" + "\n".join(too_wide[:20])
    assert not sticking_out, "wider than the text:\n" + "\n".join(sticking_out[:20])
    assert not asked, "requests to other hosts: " + ", ".join(asked)
    # what a reader sees: the largest reference page, its examples wrapped,
    # its formulas typeset offline too
    context = launch()
    asked = _block_other_hosts(context)
    page = context.new_page()
    page.goto(modules[-1].as_uri())
    page.evaluate("() => MathJax.startup.promise")
    page.screenshot(path=str(artifacts / "docs_reference_code.png"))
    assert page.evaluate("() => [...document.querySelectorAll('.math')]"
                         ".every(e => e.querySelector('mjx-container'))")
    assert not asked, "requests to other hosts: " + ", ".join(asked)
