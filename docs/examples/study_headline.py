"""A study's headline from Python (docs/python.md, "A study's results"): the within-material E2 - E1 and
each model's mean r*, recomputed from the rows. Usage: python3 docs/examples/study_headline.py [OUT]
(OUT: a study's output folder; default out/study-merl100, the 100-material example's)."""
import sys

import glossy
import numpy as np

study = glossy.read_study(sys.argv[1] if len(sys.argv) > 1 else "out/study-merl100")
rows = study.rows

# Does E2 predict image error (r*) better than E1? Within a material, across its fits (Löw et al.'s question).
within = next(d for d in study.results["e2MinusE1"] if d["image"] == "rrmse")["withinMaterialSpearman"]
interval = f"[{within['lo']:.3f}, {within['hi']:.3f}]" if within["lo"] is not None else f"({within['reason']})"
print(f"E2 - E1, within a material: {within['estimate']:.3f} {interval}")

# Each model's mean r*: a material's r* is the mean over its sheets, then the mean over materials.
for model in study.results["models"]:
    mine = rows["label"] == model["label"]
    per_material = [np.nanmean(rows["rrmse"][mine & (rows["material"] == m)]) for m in np.unique(rows["material"][mine])]
    print(f"{model['label']:14s} mean rank {model['meanRank']:.2f}, mean r* {np.mean(per_material):.4f}")
