#!/usr/bin/env python3
"""scripts/compare-published-fits on a fixture database (CTest: Scripts.ComparePublishedFits).

tests/scripts/refit-fixture/ holds four parameter files: blue-rubber (the six published fits and glossy's real
fits of them), gold-paint (the six published fits and six perturbed ones marked as glossy's), chrome (published
only) and no-network (both kinds, but no network beside it). The test copies them with the library's networks
into a temporary folder, runs a copy of the script with --docs, and checks its CSV, summary and figure (and
the copy of docs/fitting.md) against `glossy error --json` run here directly and the statistics computed here;
then that bad input is refused with exit 2 and one line, before anything is written.
"""
import argparse
import csv
import json
import math
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import tomllib
import xml.etree.ElementTree as ET
from pathlib import Path

GRID = ["microfacet:E2", "smooth:E2", "ashikhmin-shirley:E1", "ashikhmin-shirley:E2", "cook-torrance:E1",
        "cook-torrance:E2"]
LABEL = {"microfacet:E2": "Microfacet E2", "smooth:E2": "Smooth E2", "ashikhmin-shirley:E1": "AS E1",
         "ashikhmin-shirley:E2": "AS E2", "cook-torrance:E1": "CT E1", "cook-torrance:E2": "CT E2"}
failures = []


def check(ok, what):
    if not ok:
        failures.append(what)
        print(f"FAIL {what}")


def direct_errors(exe, toml, network):
    out = subprocess.run([exe, "error", "--material", str(toml), "--measured", str(network), "--json"],
                         check=True, capture_output=True, text=True).stdout
    return {f["fit"]: f for f in json.loads(out)["fits"]}


def fits_of(toml):
    with open(toml, "rb") as f:
        return {f"{x['model']}:{x['metric']}" + (":glossy" if x.get("by") == "glossy" else ""): x
                for x in tomllib.load(f)["fit"]}


def table_rows(summary):
    rows = {}
    for line in summary.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if line.startswith("| ") and cells[0] in LABEL.values():
            rows[cells[0]] = cells
    return rows


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--exe", required=True)
    p.add_argument("--source-dir", required=True)
    a = p.parse_args()
    source = Path(a.source_dir)
    with tempfile.TemporaryDirectory() as tmp:
        db, out, root = Path(tmp) / "db", Path(tmp) / "out", Path(tmp) / "root"
        # The script in a tree of its own, so that --docs writes into this copy of docs/fitting.md.
        script = root / "scripts/compare-published-fits"
        script.parent.mkdir(parents=True)
        (root / "docs").mkdir()
        shutil.copy(source / "scripts/compare-published-fits", script)
        shutil.copy(source / "docs/fitting.md", root / "docs/fitting.md")
        shutil.copytree(source / "tests/scripts/refit-fixture", db)
        for name in ["blue-rubber", "gold-paint", "chrome"]:
            shutil.copy(source / f"materials/library/merl/{name}.nbrdf", db)
        env = dict(os.environ, GLOSSY=a.exe)
        run = subprocess.run([sys.executable, str(script), str(db), "--out-dir", str(out), "-j", "2", "--docs"],
                             capture_output=True, text=True, env=env)
        check(run.returncode == 0, f"the script exits 0 (got {run.returncode}: {run.stderr.strip()})")
        if run.returncode != 0:
            return 1

        # The CSV against glossy error run here.
        rows = list(csv.DictReader(open(out / "refit.csv")))
        by_key = {(r["material"], r["fit"]): r for r in rows}
        direct = {name: direct_errors(a.exe, db / f"{name}.toml", db / f"{name}.nbrdf")
                  for name in ["blue-rubber", "gold-paint"]}
        ratios = {fit: {} for fit in GRID}
        for name, e in direct.items():
            for fit in GRID:
                metric = fit.split(":")[1]
                pub, own = e[fit][metric], e[fit + ":glossy"][metric]
                ratios[fit][name] = own / pub
                r = by_key.get((name, fit))
                check(r is not None and r["status"] == "compared", f"{name} {fit}: a compared row")
                if r is None:
                    continue
                check(math.isclose(float(r["published_E"]), pub, rel_tol=1e-5), f"{name} {fit}: published E {pub}")
                check(math.isclose(float(r["glossy_E"]), own, rel_tol=1e-5), f"{name} {fit}: glossy's E {own}")
                check(math.isclose(float(r["ratio"]), own / pub, rel_tol=1e-5), f"{name} {fit}: ratio")
                check(r["glossy_lower"] == str(int(own < pub)), f"{name} {fit}: glossy_lower")
        fits = {name: fits_of(db / f"{name}.toml") for name in direct}
        for name in direct:
            r = by_key[(name, "cook-torrance:E2")]
            check(float(r["glossy_m"]) == float(f'{fits[name]["cook-torrance:E2:glossy"]["m"]:.6g}'), f"{name} CT E2: glossy's m")
            check(float(r["published_kd_b"]) == float(f'{fits[name]["cook-torrance:E2"]["kd"][2]:.6g}'),
                  f"{name} CT E2: the published kd's blue")
        # Missing comparisons are rows, never dropped: chrome has no glossy fit, no-network no network.
        for fit in GRID:
            check(by_key.get(("chrome", fit), {}).get("status") == "no glossy fit", f"chrome {fit}: 'no glossy fit'")
        check(by_key.get(("no-network", "cook-torrance:E2"), {}).get("status") == "no network",
              "no-network CT E2: 'no network'")
        check(len(rows) == 6 + 6 + 6 + 1, f"19 rows (got {len(rows)})")

        # The summary's table against the statistics computed here.
        summary = (out / "refit.md").read_text()
        table = table_rows(summary)
        for fit in GRID:
            cells = table.get(LABEL[fit])
            check(cells is not None, f"a summary row for {LABEL[fit]}")
            if cells is None:
                continue
            rs = ratios[fit]
            worst = max(rs, key=rs.get)
            lower = sum(r < 1 for r in rs.values())
            check(cells[1] == "2", f"{LABEL[fit]}: N 2 (got {cells[1]})")
            check(cells[2] == f"{statistics.median(rs.values()):.3f}", f"{LABEL[fit]}: median {cells[2]}")
            check(cells[3] == f"{rs[worst]:.3f} ({worst})", f"{LABEL[fit]}: worst {cells[3]}")
            check(cells[5].startswith(f"{lower} of 2 "), f"{LABEL[fit]}: {lower} of 2 lower (got {cells[5]})")
        # Wilson's interval for 2 of 2 is [0.342, 1] (z = 1.96), for 0 of 2 [0, 0.658], for 1 of 2 [0.095, 0.905].
        wilson = {0: "0.0 %–66 %", 1: "9.5 %–91 %", 2: "34 %–100 %"}
        for fit in GRID:
            cells = table.get(LABEL[fit])
            if cells:
                lower = sum(r < 1 for r in ratios[fit].values())
                check(wilson[lower] in cells[5], f"{LABEL[fit]}: Wilson interval {wilson[lower]} (got {cells[5]})")
        # The parameters' agreement: the median over materials of |g − p| / max(g, p), kd by its RGB mean.
        for fit, key, column in [("cook-torrance:E2", "m", 6), ("ashikhmin-shirley:E1", "n", 6), ("smooth:E2", "kd", 7)]:
            rel = []
            for name in direct:
                g, p = fits[name][fit + ":glossy"][key], fits[name][fit][key]
                g, p = (sum(g) / 3, sum(p) / 3) if isinstance(g, list) else (g, p)
                rel.append(abs(g - p) / max(g, p))
            x = 100 * statistics.median(rel)
            want = f"{x:.0f} %" if x >= 10 else f"{x:.1f} %"
            got = table[LABEL[fit]][column]
            check(got.endswith(want), f"{LABEL[fit]}: {key}'s median relative difference {want} (got {got})")
        check("chrome (all six)" in summary, "the summary lists chrome as missing glossy's fits")
        check("no-network (cook-torrance:E2)" in summary, "the summary lists no-network as missing its network")

        # The figure: one marker per compared row, each titled with its material.
        svg = ET.parse(out / "refit.svg").getroot()
        titles = [t.text for t in svg.iter("{http://www.w3.org/2000/svg}title") if t.text and "published" in t.text]
        check(len(titles) == 12, f"12 markers in the figure (got {len(titles)})")

        # --docs: the summary between the page's markers, the figure beside it.
        page = (root / "docs/fitting.md").read_text()
        begin, end = "<!-- refit summary: written by scripts/compare-published-fits --docs -->\n", "<!-- end of refit summary -->"
        check(begin + summary + end in page, "--docs puts the summary between docs/fitting.md's markers")
        check((root / "docs/images/refit/refit.svg").read_bytes() == (out / "refit.svg").read_bytes(),
              "--docs puts the figure into docs/images/refit/")

        # Bad input: exit 2, one line naming the folder, file or option, and nothing written.
        (db / "bad.toml").write_text("name = \n")
        bad_out = Path(tmp) / "bad-out"
        for argv, names in [([str(db), "--out-dir", str(bad_out)], "bad.toml"),
                            ([str(Path(tmp) / "absent")], "absent"),
                            ([str(db), "-j", "0"], "-j 0"),
                            ([str(db), "--out-dir", str(bad_out), "--docs"], "fitting.md")]:
            if argv[-1] == "--docs":
                (db / "bad.toml").unlink()
                (root / "docs/fitting.md").write_text("# no markers\n")
            r = subprocess.run([sys.executable, str(script), *argv], capture_output=True, text=True, env=env)
            lines = r.stderr.strip().splitlines()
            check(r.returncode == 2 and len(lines) == 1 and names in lines[0],
                  f"{argv}: exit 2 and one line naming {names} (got {r.returncode}: {r.stderr.strip()})")
        check(not (bad_out / "refit.csv").exists(), "nothing written for bad input")
    print("ok" if not failures else f"{len(failures)} check(s) failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
