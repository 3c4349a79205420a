#!/usr/bin/env python3
"""`ekb serve` in a real browser (issue 41, SPEC §14): Debian's Chromium driven through
WebDriver (selenium and /usr/bin/chromedriver, nothing downloaded), on a copy of the seed file,
through the page's data-* hooks only. Run by scripts/test-serve.sh, which installs what it needs.

  python3 scripts/test-serve.py EKB-BINARY [AXE.min.js]

Each check prints `ok: …`; the first failure ends the run with exit 1. The server listens on
127.0.0.1 only and is stopped at the end, whatever happens."""
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
import urllib.error
import urllib.request

from selenium import webdriver
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.action_chains import ActionChains
from selenium.common.exceptions import StaleElementReferenceException
from selenium.webdriver.common.by import By
from selenium.webdriver.support.ui import WebDriverWait

EKB = os.path.abspath(sys.argv[1])
AXE = sys.argv[2] if len(sys.argv) > 2 else None
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SEED = os.path.join(ROOT, "data", "environmentKnowledgeBaseInput.dat")
MAP = os.path.join(ROOT, "tests", "fixtures", "map", "mapGenerationConfiguration.ini")
passed = 0


def ok(what):
    global passed
    passed += 1
    print(f"ok: {what}", flush=True)


def fail(what):
    print(f"test-serve: FAILED: {what}", file=sys.stderr, flush=True)
    raise SystemExit(1)


def check(condition, what):
    if not condition:
        fail(what)


work = tempfile.mkdtemp(prefix="ekb-serve-test.")
kb = os.path.join(work, "environmentKnowledgeBaseInput.dat")
shutil.copy(SEED, kb)
original = open(kb, "rb").read()
server = subprocess.Popen(
    [EKB, "--isolated", "serve", kb, "--port", "0", "--map-config", MAP],
    stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
)
driver = None
try:
    address = server.stdout.readline().strip()
    check(address.startswith("http://127.0.0.1:") and "?token=" in address, f"first line: {address!r}")
    base, token = address.split("/?token=")
    port = base.rsplit(":", 1)[1]
    ok(f"ekb serve prints its address with a token: {base}/?token=…")

    # Refusals, over plain HTTP.
    def status(path, headers=None, data=None):
        request = urllib.request.Request(base + path, data=data, headers=headers or {},
                                         method="POST" if data is not None else "GET")
        try:
            with urllib.request.urlopen(request, timeout=10) as answer:
                return answer.status
        except urllib.error.HTTPError as error:
            return error.code

    check(status("/") == 403, "a request without the token is refused")
    check(status(f"/?token={token}", {"Host": f"evil.example:{port}"}) in (403, 421),
          "a request with another Host is refused")
    check(status(f"/?token={token}x") == 403, "a wrong token is refused")
    body = json.dumps({"text": ""}).encode()
    cookie = {"Cookie": f"ekb_token={token}"}
    check(status(f"/api/check?token={token}", {"Origin": "http://evil.example", "Content-Type": "application/json"}, body) == 403,
          "a change from another Origin is refused")
    ok("bad Host, missing or wrong token and a foreign Origin are refused")

    options = webdriver.ChromeOptions()
    options.binary_location = "/usr/bin/chromium"
    for flag in ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                 "--disable-background-networking", "--disable-component-update", "--disable-sync",
                 f"--user-data-dir={work}/chromium", "--window-size=1400,1000"]:
        options.add_argument(flag)
    driver = webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=options)
    driver.set_script_timeout(30)
    wait = WebDriverWait(driver, 15)
    driver.get(address)
    state = lambda: driver.find_element(By.TAG_NAME, "body").get_attribute("data-state")
    wait.until(lambda d: state() == "clean")
    wait.until(lambda d: d.find_elements(By.CSS_SELECTOR, '[data-location="4"] [data-rule="key-case"][data-severity="error"]'))
    first = driver.find_element(By.CSS_SELECTOR, "#summary li a").text
    check(first.startswith("error key-case"), f"the summary starts with {first!r}, not the key-case error")
    ok("the page loads clean and shows the key-case error at location 4, first in the summary")
    if os.environ.get("EKB_SERVE_SCREENSHOT"):
        driver.save_screenshot(os.environ["EKB_SERVE_SCREENSHOT"])

    # The fix button of key-case fixes it.
    driver.find_element(By.CSS_SELECTOR, '[data-location="4"] [data-fix="key-case"]').click()
    wait.until(lambda d: not d.find_elements(By.CSS_SELECTOR, '[data-rule="key-case"]'))
    check(state() == "dirty", f"after a fix the page is dirty, not {state()}")
    ok("one click on its fix button fixes the key-case error")

    # Typing what the robot would misread shows its finding at the field.
    field = driver.find_element(By.CSS_SELECTOR, '[data-key="postGestureMessageKinyarwanda"][data-id="4"]')
    written = field.get_attribute("value")
    field.clear()
    field.send_keys('"Quoted')
    wait.until(lambda d: d.find_elements(By.CSS_SELECTOR, '[data-location="4"] [data-rule="compat-leading-symbol"][data-severity="error"]'))
    field.clear()
    field.send_keys(written)
    wait.until(lambda d: not d.find_elements(By.CSS_SELECTOR, '[data-rule="compat-leading-symbol"]'))
    ok("typing a leading quote shows compat-leading-symbol at its field, and undoing it clears it")

    # Typing a translation: one untranslated-message finding fewer at location 4, and how
    # long after the last key the page shows it.
    untranslated = '[data-location="4"] [data-rule="untranslated-message"]'
    count = len(driver.find_elements(By.CSS_SELECTOR, untranslated))
    check(count >= 1, "location 4 has untranslated messages")
    field = driver.find_element(By.CSS_SELECTOR, '[data-key="preGestureMessageIsiZulu"][data-id="4"]')
    field.clear()
    field.send_keys("Le yiRoomb")
    wait.until(lambda d: len(d.find_elements(By.CSS_SELECTOR, untranslated)) == count)
    elapsed = driver.execute_async_script("""
        const [field, selector, count, done] = arguments;
        field.value += 'a';
        const start = performance.now();
        field.dispatchEvent(new Event('input', {bubbles: true}));
        (function poll() {
            document.querySelectorAll(selector).length < count
                ? requestAnimationFrame(() => done(performance.now() - start))
                : setTimeout(poll, 2);
        })();
    """, field, untranslated, count)
    check(elapsed <= 300, f"the findings came {elapsed:.0f} ms after the last key, over 300 ms")
    ok(f"a translation typed clears its finding, painted {elapsed:.0f} ms after the last key")

    # Dragging a pose moves it: its x field follows.
    x = driver.find_element(By.CSS_SELECTOR, '[data-key][data-id="3"][data-part="x"]')
    before_x = float(x.get_attribute("value"))
    # The map is drawn again after each check: the handle is found anew if it was redrawn.
    for attempt in range(10):
        try:
            handle = driver.find_element(By.CSS_SELECTOR, '[data-pose-handle="3"]')
            ActionChains(driver).click_and_hold(handle).move_by_offset(40, 0).release().perform()
            break
        except StaleElementReferenceException:
            time.sleep(0.3)
    wait.until(lambda d: float(x.get_attribute("value")) != before_x)
    check(float(x.get_attribute("value")) > before_x, "dragging right increases x")
    ok(f"dragging location 3's pose moves it: x {before_x} → {x.get_attribute('value')}")

    # Save: the file on disk is the original with exactly those three lines changed.
    driver.find_element(By.CSS_SELECTOR, '[data-action="save"]').click()
    wait.until(lambda d: state() == "saved")
    after = open(kb, "rb").read().split(b"\n")
    before = original.split(b"\n")
    changed = [i + 1 for i, (a, b) in enumerate(zip(before, after)) if a != b]
    check(len(after) == len(before), "the save kept every line")
    check(changed == [20, 32, 34], f"the save changed lines {changed}, not 20, 32 and 34")
    check(after[31] == b"preGestureMessageIsiZulu      4 Le yiRoomba", f"line 32: {after[31]!r}")
    check(after[19].startswith(b"robotLocation                 3 ") and after[19] != before[19], f"line 20: {after[19]!r}")
    ok("the save is lossless: only lines 20 (the pose dragged), 32 (the translation) and 34 (the key) changed")

    # A colleague's ekb set meanwhile is kept, and the page notices it.
    subprocess.run([EKB, "--isolated", "-q", "set", "2", "robotLocationDescription", "The other Pepper", kb], check=True)
    field = driver.find_element(By.CSS_SELECTOR, '[data-key="postGestureMessageIsiZulu"][data-id="5"]')
    field.clear()
    field.send_keys("Sizobonana")
    wait.until(lambda d: state() == "dirty")
    driver.find_element(By.CSS_SELECTOR, '[data-action="save"]').click()
    wait.until(lambda d: state() == "saved")
    text = open(kb).read()
    check("robotLocationDescription      2 The other Pepper" in text, "the colleague's edit was lost")
    check("postGestureMessageIsiZulu     5 Sizobonana" in text, "the page's edit was not saved")
    ok("a concurrent ekb set is merged with the page's edit")

    # The same value changed on both sides is a conflict, shown, not overwritten.
    subprocess.run([EKB, "--isolated", "-q", "set", "5", "postGestureMessageKinyarwanda", "Theirs", kb], check=True)
    field = driver.find_element(By.CSS_SELECTOR, '[data-key="postGestureMessageKinyarwanda"][data-id="5"]')
    field.clear()
    field.send_keys("Mine")
    driver.find_element(By.CSS_SELECTOR, '[data-action="save"]').click()
    wait.until(lambda d: state() == "conflict")
    rows = driver.find_elements(By.CSS_SELECTOR, '[data-conflict] [data-key="postGestureMessageKinyarwanda"][data-id="5"]')
    check(rows, "the conflict shows the value")
    check("Theirs" in open(kb).read(), "the conflict overwrote the file")
    driver.find_element(By.CSS_SELECTOR, '[data-conflict] [data-choose="mine"]').click()
    driver.find_element(By.CSS_SELECTOR, '[data-action="save"]').click()
    wait.until(lambda d: state() == "saved")
    check("postGestureMessageKinyarwanda 5 Mine" in open(kb).read(), "choosing mine did not save it")
    ok("the same value changed on both sides is shown in [data-conflict]; choosing mine saves it")

    if AXE:
        driver.execute_script(open(AXE).read())
        result = driver.execute_async_script(
            "const done = arguments[arguments.length - 1];"
            "axe.run(document, {resultTypes: ['violations']}).then(r => done(r.violations.map(v => [v.id, v.impact, v.nodes.length, v.nodes.slice(0, 2).map(n => n.html.slice(0, 120))])));")
        grave = [v for v in result if v[1] in ("critical", "serious")]
        check(not grave, f"axe-core: {grave}")
        ok(f"axe-core: no critical or serious violation ({len(result)} minor)")
finally:
    if driver is not None:
        driver.quit()
    server.terminate()
    try:
        server.wait(timeout=10)
    except subprocess.TimeoutExpired:
        server.kill()
    shutil.rmtree(work, ignore_errors=True)
print(f"test-serve: {passed} passed", flush=True)
