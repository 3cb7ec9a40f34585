"""What the browser tests share: the Chromium they drive (Debian's binary,
``make browser`` installs it) and the folder where they keep screenshots."""
import os
import shutil
from pathlib import Path

import pytest

ARTIFACTS = Path(__file__).resolve().parent / "artifacts"
#: a headless browser that makes no request of its own (updates, sync, ...)
CHROMIUM_FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                  "--disable-background-networking", "--disable-component-update",
                  "--disable-sync"]


@pytest.fixture(scope="session")
def chromium():
    """The path of the Chromium binary (``$CHROMIUM``, else ``chromium`` on the PATH)."""
    path = os.environ.get("CHROMIUM", shutil.which("chromium") or "/usr/bin/chromium")
    if not os.path.exists(path):
        pytest.fail(f"no chromium at {path} (make browser installs it)")
    return path


@pytest.fixture(scope="session")
def artifacts():
    """The folder of the screenshots the tests keep (not in git)."""
    ARTIFACTS.mkdir(exist_ok=True)
    return ARTIFACTS


@pytest.fixture
def launch(chromium, tmp_path):
    """``launch(**options)``: a fresh browser context of Chromium, closed after the test."""
    from playwright.sync_api import sync_playwright

    with sync_playwright() as p:
        contexts = []

        def start(**options):
            options.setdefault("viewport", {"width": 1280, "height": 1000})
            context = p.chromium.launch_persistent_context(
                str(tmp_path / f"chromium-profile-{len(contexts)}"), executable_path=chromium,
                headless=True, args=CHROMIUM_FLAGS, **options)
            contexts.append(context)
            return context

        yield start
        for context in contexts:
            context.close()
