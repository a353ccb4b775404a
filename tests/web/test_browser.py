"""`sass serve` in a real browser: Debian's headless Chromium, driven by selenium.

The page draws the terminal on a canvas, so the test reads what the app sent:
Chromium's performance log carries every WebSocket frame the page received;
their text, with the escape sequences taken out, is what the screen shows.
"""

from __future__ import annotations

import base64
import json
import re
import shutil
import time
from pathlib import Path

import pytest
from _serve import start_serve

CHROMIUM = shutil.which("chromium")
CHROMEDRIVER = shutil.which("chromedriver")
webdriver = pytest.importorskip("selenium.webdriver")
if not (CHROMIUM and CHROMEDRIVER):
    pytest.skip("Debian's chromium and chromium-driver are not installed", allow_module_level=True)

from selenium.webdriver.chrome.options import Options  # noqa: E402
from selenium.webdriver.chrome.service import Service  # noqa: E402
from selenium.webdriver.common.by import By  # noqa: E402

ESCAPES = re.compile(
    r"\x1b\[[0-9;?<>=]*[ -/]*[@-~]|\x1b\][^\x07\x1b]*(?:\x07|\x1b\\)|\x1b[()][0-9A-B]"
)
READY = "Press left-mouse to select items."


class Screen:
    """The text the page has received over its WebSocket."""

    def __init__(self, driver) -> None:
        self.driver = driver
        self.text = ""
        self.requested: list[str] = []  # every URL the page asked for

    def read(self) -> str:
        for entry in self.driver.get_log("performance"):
            message = json.loads(entry["message"])["message"]
            if message.get("method") == "Network.requestWillBeSent":
                self.requested.append(message["params"]["request"]["url"])
            if message.get("method") != "Network.webSocketFrameReceived":
                continue
            response = message["params"]["response"]
            data = response.get("payloadData", "")
            if response.get("opcode") == 2:
                data = base64.b64decode(data).decode("utf-8", "replace")
            self.text += ESCAPES.sub("", data)
        return self.text

    def since(self, mark: int) -> str:
        return self.read()[mark:]

    def wait_for(self, needle: str, mark: int = 0, timeout: float = 30.0) -> None:
        end = time.monotonic() + timeout
        while time.monotonic() < end:
            if needle in self.since(mark):
                return
            time.sleep(0.1)
        raise AssertionError(f"{needle!r} never reached the page; last text:\n{self.text[-2000:]}")


@pytest.fixture
def served(tmp_path: Path, default_people_db: Path):
    """The URL `sass serve` prints (with its token): the only one that opens."""
    server = start_serve(
        tmp_path, "--host", "localhost", "--db", str(default_people_db), "--workdir", "work"
    )
    try:
        yield server.url
    finally:
        server.stop()


@pytest.fixture
def browser(tmp_path: Path):
    options = Options()
    options.binary_location = CHROMIUM
    for flag in (
        "--headless=new",
        "--no-sandbox",
        "--disable-gpu",
        "--disable-quic",
        "--no-first-run",
        "--disable-background-networking",
        "--disable-component-update",
        "--disable-sync",
        "--window-size=1280,900",
        f"--user-data-dir={tmp_path / 'chromium'}",
    ):
        options.add_argument(flag)
    options.set_capability("goog:loggingPrefs", {"performance": "ALL", "browser": "ALL"})
    driver = webdriver.Chrome(service=Service(CHROMEDRIVER), options=options)
    try:
        yield driver
    finally:
        driver.quit()


@pytest.mark.slow
def test_the_spreadsheet_runs_in_a_browser_and_takes_keys(served: str, browser) -> None:
    browser.get(served)
    start = browser.find_elements(By.ID, "start")
    if start and start[0].is_displayed():
        start[0].click()
    screen = Screen(browser)
    screen.wait_for(READY)
    assert "Neck ul" not in screen.read()  # Girth first: no joint-limit rows yet
    mark = len(screen.read())
    # xterm.js takes keys through its hidden text area.
    keyboard = browser.find_element(By.CSS_SELECTOR, "#terminal textarea")
    # `j` switches to Joint Limits: its rows and the degree unit reach the page.
    keyboard.send_keys("j")
    screen.wait_for("Neck ul", mark)
    screen.wait_for("deg", mark)


@pytest.mark.slow
def test_the_page_runs_under_its_policy_on_its_own_font(served: str, browser) -> None:
    """The served page breaks no rule of its Content-Security-Policy (the
    console says every violation), asks no other server for anything (it
    loaded Roboto Mono from fonts.googleapis.com on every session) and draws
    the terminal in the Roboto Mono the package ships."""
    browser.get(served)
    screen = Screen(browser)
    screen.wait_for(READY)
    # the browser's own pages (its new tab) are not the page's
    requested = [url for url in screen.requested if not url.startswith("chrome")]
    origin = served.split("?", 1)[0].rstrip("/")
    assert requested and all(
        url.startswith(origin) or url.startswith("data:") for url in requested
    ), requested
    assert any(url.endswith("RobotoMono-VariableFont_wght.ttf") for url in requested)
    assert browser.execute_script("return document.fonts.check('16px \"Roboto Mono\"')")
    console = [entry["message"] for entry in browser.get_log("browser")]
    assert not [line for line in console if "Content Security Policy" in line], console
