#!/usr/bin/env python3
"""The report site in a real browser: generates a small site with `glossy sheets` + `glossy report` (or takes
one with --site), opens it from file:// in headless Chromium driven by Playwright, and checks that every
image of every page loads, that nothing is fetched from the network, that sorting a column orders the rows
as Python sorts the same values, that the filter hides rows, that the compare toggle swaps the image, and
that no page logs a console error. With --screenshots DIR it saves the pictures docs/report.md shows.

Exit status: 0 passed, 1 failed, 77 skipped (no Playwright or no Chromium: said on stdout)."""

import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile
import traceback
from pathlib import Path
from urllib.parse import unquote, urlparse

SKIP = 77
CHROMIUM_ARGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                 "--disable-background-networking", "--disable-component-update", "--disable-sync"]


def skip(why):
    print(f"Report.Browser: skipped: {why}")
    sys.exit(SKIP)


def find_chromium():
    for candidate in [os.environ.get("GLOSSY_CHROMIUM", ""), "/usr/bin/chromium", shutil.which("chromium") or "",
                      shutil.which("chromium-headless-shell") or "", "/usr/lib/chromium/chromium-headless-shell"]:
        if candidate and os.access(candidate, os.X_OK):
            return candidate
    return None


class Failures:
    def __init__(self):
        self.items = []

    def check(self, ok, what):
        if not ok:
            self.items.append(what)
            print(f"FAIL: {what}")
        return ok


def run(cmd, **kw):
    print("+", " ".join(str(c) for c in cmd), flush=True)
    r = subprocess.run([str(c) for c in cmd], capture_output=True, text=True, **kw)
    if r.returncode != 0:
        raise RuntimeError(f"{cmd[0]} {cmd[1]} exited {r.returncode}:\n{r.stdout}\n{r.stderr}")
    return r


def make_site(exe, source, shared, work):
    """Three tiny sheets — two supplement materials and one with no measured data and a fit missing — their
    plots (hand-made for one, `glossy plot` for another) and the site."""
    mats = work / "materials"
    mats.mkdir()
    for name in ["alum-bronze", "chrome"]:
        shutil.copy(source / "materials" / "library" / "merl" / f"{name}.toml", mats / f"{name}.toml")
    text = (source / "materials" / "library" / "merl" / "gold-paint.toml").read_text()
    text = text.replace('name = "gold-paint"', 'name = "no-data"').replace('measured = "gold-paint.binary"', 'measured = "no-data.binary"')
    # Its CT E2 fits left out (the published one and glossy's, which a sheet would show in its place): an
    # empty panel of the grid.
    blocks = re.split(r"(?m)^(?=\[\[fit\]\])", text)
    (mats / "no-data.toml").write_text("".join(b for b in blocks if 'model = "cook-torrance"\nmetric = "E2"\n' not in b))
    merl = shared / "merl"
    merl_args = ["--merl-dir", merl] if merl.is_dir() else []  # else the embedded NBRDF networks
    sheets = work / "sheets"
    run([exe, "sheets", mats, *merl_args, "--width", 32, "--height", 32, "--spp", 8, "--seed", 1, "-o", sheets])

    plots = work / "plots"
    hand = plots / "alum-bronze"
    hand.mkdir(parents=True)
    shutil.copy(sheets / "alum-bronze.png", hand / "theta_h.png")
    (hand / "theta_h.svg").write_text('<svg xmlns="http://www.w3.org/2000/svg" width="40" height="20"><rect width="40" height="20" fill="#0072b2"/></svg>\n')
    (hand / "theta_h.csv").write_text("theta_h,measured\n0,1\n")
    (hand / "plots.json").write_text(
        '{"material": "alum-bronze", "measured": "hand-made <test> plots", "channel": "luminance", "figures": ['
        '{"kind": "theta_h", "title": "Hand-made θh slice", "caption": "A caption with <b>markup</b> & more.", '
        '"svg": "theta_h.svg", "png": "theta_h.png", "csv": "theta_h.csv"},'
        '{"kind": "polar", "title": "SVG only", "caption": "", "svg": "theta_h.svg"}]}\n')
    run([exe, "plot", "--material", mats / "chrome.toml", *merl_args, "-o", plots / "chrome"])
    site = work / "site"
    run([exe, "report", sheets, plots, "-o", site])
    return site


def local_path(url):
    u = urlparse(url)
    return Path(unquote(u.path)) if u.scheme == "file" else None


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--exe", help="the glossy executable (to generate a site)")
    ap.add_argument("--source-dir", default=str(Path(__file__).resolve().parents[2]))
    ap.add_argument("--shared-dir", default=None, help="../shared beside the checkout")
    ap.add_argument("--work", default=None, help="a folder for the temporary files")
    ap.add_argument("--site", default=None, help="test this site instead of generating one")
    ap.add_argument("--screenshots", default=None, help="save screenshots into this folder")
    ap.add_argument("--keep", action="store_true", help="keep the temporary files")
    a = ap.parse_args()

    try:
        from playwright.sync_api import sync_playwright
    except ImportError:
        skip(f"Playwright is not installed for {sys.executable} (scripts/test-tools installs it)")
    chromium = find_chromium()
    if not chromium:
        skip("no Chromium binary (/usr/bin/chromium: scripts/test installs Debian's chromium)")

    source = Path(a.source_dir).resolve()
    shared = Path(a.shared_dir or os.environ.get("GLOSSY_SHARED_DIR") or source.parent / "shared").resolve()
    if a.work:
        Path(a.work).mkdir(parents=True, exist_ok=True)
    work = Path(tempfile.mkdtemp(prefix="report-browser-", dir=a.work))
    failures = Failures()
    try:
        if a.site:
            site = Path(a.site).resolve()
        else:
            if not a.exe:
                ap.error("--exe or --site is needed")
            site = make_site(Path(a.exe).resolve(), source, shared, work)
        check_site(site, work, chromium, failures, Path(a.screenshots).resolve() if a.screenshots else None,
                   generated=not a.site)
    except Exception:
        traceback.print_exc()
        failures.items.append("exception")
    finally:
        if failures.items or a.keep:
            print(f"Report.Browser: files kept in {work}")
        else:
            shutil.rmtree(work, ignore_errors=True)
    if failures.items:
        print(f"Report.Browser: {len(failures.items)} failure(s)")
        return 1
    print("Report.Browser: passed")
    return 0


def shown_and_loaded(page, src):
    """Whether the compare image comes to show `src`, loaded, within a few seconds."""
    try:
        page.wait_for_function("""(src) => { const i = document.querySelector('img.compare-image');
            return i.getAttribute('src') === src && i.complete && i.naturalWidth > 0; }""", arg=src, timeout=5000)
        return True
    except Exception:
        return False


def check_site(site, work, chromium, f, screenshots, generated):
    from playwright.sync_api import sync_playwright

    index = site / "index.html"
    f.check(index.is_file(), f"{index} exists")
    problems = []  # console errors, page errors, failed or non-local requests, on any page

    with sync_playwright() as p:
        context = p.chromium.launch_persistent_context(
            str(work / "profile"), executable_path=chromium, headless=True, args=CHROMIUM_ARGS,
            viewport={"width": 1400, "height": 900}, offline=True)
        page = context.pages[0] if context.pages else context.new_page()
        page.on("console", lambda m: problems.append(f"console {m.type}: {m.text} ({page.url})") if m.type == "error" else None)
        page.on("pageerror", lambda e: problems.append(f"page error: {e} ({page.url})"))
        page.on("requestfailed", lambda r: problems.append(f"request failed: {r.url}: {r.failure}"))
        page.on("request", lambda r: problems.append(f"non-local request: {r.url}")
                if not r.url.startswith(("file:", "data:")) else None)

        def visit(path):
            page.goto(path.as_uri(), wait_until="load")
            images = page.evaluate("""() => Array.from(document.images).map(
                i => ({src: i.currentSrc || i.src, complete: i.complete, width: i.naturalWidth}))""")
            for im in images:
                f.check(im["complete"] and im["width"] > 0, f"{path.relative_to(site)}: image {im['src']} loads")
            links = page.evaluate("() => Array.from(document.querySelectorAll('a[href]')).map(a => a.href)")
            for href in links:
                target = local_path(href.split("#")[0])
                f.check(target is not None and target.exists(), f"{path.relative_to(site)}: link {href} leads to a file in the site")
            return images

        # The index: thumbnails, sorting, filtering.
        images = visit(index)
        rows = page.locator("#materials tbody.rows tr")
        n = rows.count()
        f.check(n >= 1, "the index has material rows")
        f.check(len(images) >= 1, "the index shows thumbnails")
        pages = [site / unquote(h) for h in page.eval_on_selector_all(
            "#materials tbody.rows td.name a", "els => els.map(a => a.getAttribute('href'))")]
        f.check(len(pages) == n, "every row links to its material's page")
        if screenshots:
            screenshots.mkdir(parents=True, exist_ok=True)
            page.screenshot(path=str(screenshots / "index.png"), full_page=True)

        def table_state(col):
            return page.evaluate("""(col) => Array.from(document.querySelectorAll('#materials tbody.rows tr')).map(
                r => ({name: r.dataset.name, value: r.cells[col].dataset.value, hidden: r.hidden}))""", col)

        def expected_order(state, numeric, ascending):
            present = [r for r in state if r["value"] not in (None, "")]
            missing = [r for r in state if r["value"] in (None, "")]
            key = (lambda r: float(r["value"])) if numeric else (lambda r: r["value"].lower())
            return [r["name"] for r in sorted(present, key=key, reverse=not ascending)] + [r["name"] for r in missing]

        def stable_sorted_desc(state, numeric):
            # Python's reverse=True keeps equal items in their order too, as the page's sort does.
            return expected_order(state, numeric, False)

        headers = page.locator("#materials th[data-col][data-type=number]")
        f.check(headers.count() >= 5, "the index has numeric sortable columns")
        # A model's rRMSE, then its E2: both orders, and the direction shown.
        for heading in ["rRMSE", "E2"]:
            th = page.locator(f"#materials th[data-type=number]:has(button:text-is('{heading}'))").first
            col = int(th.get_attribute("data-col"))
            before = table_state(col)
            values = [r["value"] for r in before]
            th.locator("button").click()
            after = table_state(col)
            f.check([r["name"] for r in after] == expected_order(before, True, True),
                     f"sorting by {heading} (column {col}) ascending: {[r['name'] for r in after]} from values {values}")
            f.check(th.get_attribute("aria-sort") == "ascending", f"{heading} header says ascending")
            th.locator("button").click()
            after = table_state(col)
            f.check([r["name"] for r in after] == stable_sorted_desc(before, True),
                    f"sorting by {heading} descending: {[r['name'] for r in after]} from values {values}")
            f.check(th.get_attribute("aria-sort") == "descending", f"{heading} header says descending")
        name_th = page.locator("#materials th[data-type=text][data-col='1']")
        name_th.locator("button").click()
        state = table_state(1)
        f.check([r["name"] for r in state] == sorted([r["name"] for r in state], key=str.lower), "sorting by material name")
        if generated:
            ordered = table_state(int(page.locator("#materials th[data-type=number]").first.get_attribute("data-col")))
            f.check(any(r["value"] == "" for r in ordered), "the generated site has a material without figures (sorted last)")

        # Filter: a name that matches one material hides the others; clearing shows them all again.
        names = [r["name"] for r in table_state(1)]
        target = names[-1]
        page.fill("#filter", target)
        state = table_state(1)
        shown = [r["name"] for r in state if not r["hidden"]]
        f.check(target in shown, f"filter '{target}' keeps it")
        expected_shown = [r["name"] for r in state if target.lower() in r["name"].lower() or
                          target.lower() in (page.locator(f"#materials tr[data-name='{r['name']}']").get_attribute("data-verdict") or "").lower()]
        f.check(shown == expected_shown, f"filter '{target}' shows {shown}, expected {expected_shown}")
        if n > 1:
            f.check(len(shown) < n, f"filter '{target}' hides rows")
            for r in state:
                if r["hidden"]:
                    f.check(not page.locator(f"#materials tr[data-name='{r['name']}']").is_visible(), f"the filtered-out row {r['name']} is not displayed")
        page.fill("#filter", "no material is called this")
        f.check(all(r["hidden"] for r in table_state(1)), "a filter matching nothing hides every row")
        page.fill("#filter", "")
        f.check(not any(r["hidden"] for r in table_state(1)), "clearing the filter shows every row")

        # Every material page: images, links, and the compare toggle where there is one.
        compared = 0
        shot = None
        for path in pages:
            visit(path)
            toggle = page.locator(".compare button.toggle")
            if toggle.count() == 0:
                continue
            img = page.locator(".compare img.compare-image")
            model_src = img.get_attribute("src")
            measured_src = img.get_attribute("data-measured-src")
            if screenshots and shot is None:  # the same model before and after the toggle
                f.check(shown_and_loaded(page, model_src), f"{path.parent.name}: the first model's panel loads")
                page.locator(".compare").screenshot(path=str(screenshots / "compare-model.png"))
            toggle.click()
            f.check(img.get_attribute("src") == measured_src and measured_src != model_src,
                    f"{path.parent.name}: the toggle shows the measured panel ({img.get_attribute('src')})")
            f.check("Measured" in page.locator(".compare .compare-label").inner_text(), f"{path.parent.name}: the label says Measured")
            f.check(shown_and_loaded(page, measured_src), f"{path.parent.name}: the measured panel loads")
            if screenshots and shot is None:
                page.locator(".compare").screenshot(path=str(screenshots / "compare-measured.png"))
            toggle.click()
            f.check(img.get_attribute("src") == model_src, f"{path.parent.name}: the toggle swaps back to the model")
            others = page.locator(".compare button.model:not([disabled])")
            # Every model's panel loads when chosen.
            for k in range(others.count()):
                others.nth(k).click()
                src = others.nth(k).get_attribute("data-src")
                f.check(shown_and_loaded(page, src), f"{path.parent.name}: the panel {src} loads when its button is pressed")
            others.first.click()
            if others.count() > 1:
                other = others.nth(others.count() - 1)
                other.click()
                f.check(img.get_attribute("src") == other.get_attribute("data-src"),
                        f"{path.parent.name}: a model button shows its panel")
                f.check(other.get_attribute("data-label") in page.locator(".compare .compare-label").inner_text(),
                        f"{path.parent.name}: the label names the model shown")
                img.hover()
                f.check(img.get_attribute("src") == measured_src, f"{path.parent.name}: pointing at the image shows the measured panel")
                page.mouse.move(0, 0)
                f.check(img.get_attribute("src") == other.get_attribute("data-src"), f"{path.parent.name}: and leaving it the model again")
            if screenshots and shot is None:
                page.evaluate("window.scrollTo(0, 0)")
                page.screenshot(path=str(screenshots / "material.png"))  # the first screen: header, sheet, compare
                shot = path
            compared += 1
        f.check(compared >= 1, "at least one material page has a compare toggle")
        if generated:
            nodata = site / "materials" / "no-data" / "index.html"
            if f.check(nodata.is_file(), "the material without measured data has a page"):
                visit(nodata)
                f.check(page.locator(".compare button.model[disabled]").count() >= 1, "no-data: its missing fit's button is disabled")
            visit(site / "materials" / "alum-bronze" / "index.html")
            f.check(page.locator(".plots figure").count() == 2, "alum-bronze: its two hand-made plots are shown")
            f.check("<b>" not in page.locator(".plots").inner_html().replace("&lt;b&gt;", ""), "plot captions are escaped")
            if generated:
                visit(site / "materials" / "chrome" / "index.html")
                f.check(page.locator(".plots figure").count() >= 1, "chrome: glossy plot's figures are shown")
        context.close()

    for problem in problems:
        f.check(False, problem)


if __name__ == "__main__":
    sys.exit(main())
