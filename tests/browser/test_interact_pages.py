"""
The stability-explorer worksheet in a real browser: a Jupyter server runs
on a copy of worksheets/, headless Chromium (Playwright, the Debian
chromium binary) opens the notebook, runs all cells, waits for the widgets
and the typeset equations, moves the diode-gain slider across the stability
boundary and checks that the page reacts (the verdict of the first
approximation changes). Screenshots are kept in tests/browser/artifacts/.

Run with ``make browser`` (installs chromium with apt-get if missing).
"""
import os
import shutil
import socket
import subprocess
import sys
import time
import urllib.request
from pathlib import Path

import pytest

pytest.importorskip("playwright.sync_api")

ROOT = Path(__file__).resolve().parents[2]
TOKEN = "sage-dynsym-browser-test"
TIMEOUT_MS = int(os.environ.get("BROWSER_TIMEOUT_MS", "300000"))


def _free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


@pytest.fixture(scope="module")
def server(tmp_path_factory, chromium):
    root = tmp_path_factory.mktemp("worksheets")
    for nb in (ROOT / "worksheets").glob("*.ipynb"):
        shutil.copy(nb, root)
    port = _free_port()
    log = open(root / "server.log", "w")
    proc = subprocess.Popen(
        [sys.executable, "-m", "notebook", "--no-browser", "--allow-root", "--ServerApp.ip=127.0.0.1",
         f"--ServerApp.port={port}", f"--IdentityProvider.token={TOKEN}",
         f"--ServerApp.root_dir={root}"],
        stdout=log, stderr=subprocess.STDOUT, cwd=root)
    url = f"http://127.0.0.1:{port}"
    for _ in range(120):
        try:
            urllib.request.urlopen(f"{url}/api/status?token={TOKEN}", timeout=2)
            break
        except OSError:
            if proc.poll() is not None:
                break
            time.sleep(1)
    else:
        proc.terminate()
        pytest.fail("the Jupyter server did not start")
    if proc.poll() is not None:
        pytest.fail("the Jupyter server exited: " + (root / "server.log").read_text()[-2000:])
    yield url
    proc.terminate()
    proc.wait(timeout=30)


def _run_all(page):
    page.get_by_role("menuitem", name="Run", exact=True).click()
    page.get_by_text("Run All Cells", exact=True).click()


def _verdict(page):
    loc = page.locator(".jp-OutputArea-output pre", has_text="first approximation:")
    loc.first.wait_for(timeout=TIMEOUT_MS)
    return loc.first.inner_text()


def _set_slider(page, label, value):
    slider = page.locator(".widget-slider", has=page.locator("label", has_text=label)).first
    readout = slider.locator(".widget-readout")
    readout.click()
    page.keyboard.press("Control+A")
    page.keyboard.type(str(value))
    page.keyboard.press("Enter")


def test_stability_explorer_renders_and_reacts(server, launch, artifacts):
    page = launch(viewport={"width": 1280, "height": 2400}).new_page()
    try:
        _explore(page, server, artifacts)
    finally:
        page.screenshot(path=str(artifacts / "last_state.png"), full_page=True)


def _explore(page, server, artifacts):
    page.goto(f"{server}/notebooks/10_stability_explorer.ipynb?token={TOKEN}")
    page.locator(".jp-Notebook").wait_for(timeout=TIMEOUT_MS)
    page.locator(".jp-Notebook-cell").first.wait_for(timeout=TIMEOUT_MS)
    time.sleep(3)         # let the kernel connect before running
    _run_all(page)
    # widgets rendered: the parameter sliders of the explorer
    page.locator(".widget-slider").nth(4).wait_for(timeout=TIMEOUT_MS)
    before = _verdict(page)
    assert "asymptotically stable" in before
    # equations typeset by MathJax, and the plots drawn
    page.locator("mjx-container").first.wait_for(timeout=TIMEOUT_MS)
    page.locator(".jp-OutputArea-output img").first.wait_for(timeout=TIMEOUT_MS)
    page.locator(".widget-slider").first.scroll_into_view_if_needed()
    page.screenshot(path=str(artifacts / "stability_explorer.png"), full_page=True)
    # across the boundary 1 - 3 R g s^2 = 0 (R = 2, s = 1): unstable
    _set_slider(page, "g", 0.5)
    page.wait_for_function(
        """() => [...document.querySelectorAll('.jp-OutputArea-output pre')]
                .some(e => e.innerText.includes('first approximation: unstable'))""",
        timeout=TIMEOUT_MS)
    page.locator(".jp-OutputArea-output img").first.wait_for(timeout=TIMEOUT_MS)
    time.sleep(2)
    page.screenshot(path=str(artifacts / "stability_explorer_unstable.png"), full_page=True)
    assert page.locator("mjx-container").count() > 0
