"""Converts Neural BRDF Keras weight files (<name>.h5) to glossy's .nbrdf text format; run it through
scripts/nbrdf-from-h5, which provides numpy and h5py. See that script for the usage.

With --check MERL_DIR, rebuilds the whole MERL table from the network by the procedure of
shared/merl/SOURCES.md and compares it with MERL_DIR/<name>.binary.xz on every valid bin."""
import argparse
import hashlib
import io
import lzma
import pathlib
import sys
import time
import tomllib
import zipfile

import h5py
import numpy as np

SHAPES = [((6, 21), (21,)), ((21, 21), (21,)), ((21, 3), (3,))]  # Keras Dense: kernel (inputs, outputs), bias
ACTIVATIONS = ["relu", "relu", "linear"]
MERL_SCALE = np.array([1 / 1500, 1.15 / 1500, 1.66 / 1500])
NETWORKS = "asztr/Neural-BRDF data/"  # where the zips come from (../shared/nbrdf/SOURCES.md)
NBRDF_LICENCE = "Network weights: MIT licence, (c) 2022 asztr (github.com/asztr/Neural-BRDF)."
NBRDF_CITE = ('A. Sztrajman, G. Rainer, T. Ritschel, T. Weyrich, "Neural BRDF Representation and Importance Sampling", '
              'Computer Graphics Forum 40(6), 2021, 332-346, doi:10.1111/cgf.14335')

# The three databases: the zip and folder their networks come in, how a network's file name becomes the
# material's name, and how results from them are labelled. Names are unique over the three (the library's
# sheets are NAME.exr): RGL's "_rgb" (its RGB variant) is dropped, and Nielsen's cardboard, whose name RGL
# already has, is cardboard-nielsen2015.
DATABASES = {
    "merl": dict(
        zip="merl_nbrdf.zip", folder="merl_nbrdf", rename=lambda n: n,
        label="MERL (NBRDF reconstruction)", measurement="the MERL measurement",
        licence="Fitted to the MERL BRDF database, (c) MERL 2003, 2007, 2023, CC-BY-SA-4.0.",
        cite='W. Matusik, H. Pfister, M. Brand, L. McMillan, "A Data-Driven Reflectance Model", '
             'ACM Transactions on Graphics 22(3), 2003, 759-769'),
    "rgl-epfl": dict(
        zip="rgl-isotropic_nbrdf.zip", folder="rgl-isotropic_nbrdf", rename=lambda n: n.removesuffix("_rgb"),
        label="RGL-EPFL (NBRDF reconstruction)", measurement="the RGL-EPFL measurement (its RGB variant)",
        licence="Fitted to the RGL-EPFL isotropic BRDF database (rgl.epfl.ch/materials).",
        cite='J. Dupuy, W. Jakob, "An Adaptive Parameterization for Efficient Material Acquisition and Rendering", '
             'ACM Transactions on Graphics 37(6), 2018'),
    "nielsen2015": dict(
        zip="nielsen_nbrdf.zip", folder="nielsen_nbrdf",
        rename=lambda n: "cardboard-nielsen2015" if n == "cardboard" else n,
        label="Nielsen 2015 (NBRDF reconstruction)", measurement="the Nielsen et al. 2015 measurement",
        licence="Fitted to the BRDFs measured by Nielsen, Jensen and Ramamoorthi 2015.",
        cite='J. B. Nielsen, H. W. Jensen, R. Ramamoorthi, "On Optimal, Minimal BRDF Sampling for Reflectance '
             'Acquisition", ACM Transactions on Graphics 34(6), 2015'),
}


def read_layers(path, data):
    """The Dense layers' (kernel, bias) in order, found through the Keras attributes layer_names and weight_names."""
    layers = []
    with h5py.File(io.BytesIO(data), "r") as f:
        for layer in f.attrs["layer_names"]:
            group = f[layer.decode()]
            names = [n.decode() for n in group.attrs["weight_names"]]
            if not names:
                continue  # the final Lambda layer, exp(x) - 1, has no weights
            weights = {n.split("/")[-1].split(":")[0]: group[n][()] for n in names}
            layers.append((weights["kernel"], weights["bias"]))
    shapes = [(k.shape, b.shape) for k, b in layers]
    if shapes != SHAPES or any(a.dtype != np.float32 for layer in layers for a in layer):
        sys.exit(f"{path}: expected float32 Dense layers {SHAPES}, found {shapes}")
    return layers


def number(x):
    """A float32 as TOML: 9 significant digits (round-trips to the same float32), always with float syntax."""
    if not np.isfinite(x):
        raise ValueError(f"non-finite weight {x}")
    s = "%.9g" % float(x)
    return s if any(c in s for c in ".e") else s + ".0"


def row(values):
    return ", ".join(number(v) for v in values)


def write_nbrdf(path, name, db, member, sha256, layers):
    q = lambda s: '"' + s.replace("\\", "\\\\").replace('"', '\\"') + '"'
    src = f"{NETWORKS}{db['zip']}: {member}"
    out = [
        f"# {name}: the Neural BRDF (Sztrajman et al. 2021) fitted to {db['measurement']}, converted by "
        f"scripts/nbrdf-from-h5 from {src}.",
        "# The network is a multilayer perceptron 6 -> 21 (ReLU) -> 21 (ReLU) -> 3, 675 float32 weights; each [[layer]]",
        "# computes y[o] = activation(biases[o] + sum over i of weights[o * inputs + i] * x[i]), in the order given.",
        "# Input: the half vector h = (sin θh, 0, cos θh) (φh = 0), then the difference vector",
        "# d = (sin θd cos φd, sin θd sin φd, cos θd), in Rusinkiewicz's half-difference angles (MERL's).",
        "# Output: linear RGB, each x becoming exp(x) - 1, in BRDF units (1/sr), MERL's channel scales already applied.",
        f'# A reconstruction of the measurement, not the measurement: label results "{db["label"]}".',
        "# Licence and citations: the licence and cite keys below. docs/measured.md documents this format.",
        'format = "glossy-nbrdf 1"',
        f"material = {q(name)}",
        f"label = {q(db['label'])}",
        f"source = {q(f'{src} (sha256 {sha256})')}",
        f"licence = {q(NBRDF_LICENCE + ' ' + db['licence'])}",
        "cite = [" + ", ".join(q(c) for c in (db["cite"], NBRDF_CITE)) + "]",
        'input = "half-difference"   # (sin θh, 0, cos θh, sin θd cos φd, sin θd sin φd, cos θd)',
        'output = "expm1"            # each output x becomes exp(x) − 1, in BRDF units (1/sr)',
    ]
    for (kernel, bias), activation in zip(layers, ACTIVATIONS):
        out += ["", "[[layer]]", f"inputs = {kernel.shape[0]}", f"outputs = {kernel.shape[1]}",
                f'activation = "{activation}"', f"biases = [{row(bias)}]", "weights = ["]
        out += [f"  {row(r)}," for r in kernel.T]  # one output's row per line
        out += ["]"]
    path.write_text("\n".join(out) + "\n", encoding="utf-8")


def check_round_trip(path, name, layers):
    """Re-reads the file and asserts every value gives back the .h5's float32 bit for bit."""
    with open(path, "rb") as f:
        doc = tomllib.load(f)
    assert doc["format"] == "glossy-nbrdf 1" and doc["material"] == name and len(doc["layer"]) == len(layers)
    for entry, (kernel, bias), activation in zip(doc["layer"], layers, ACTIVATIONS):
        assert (entry["inputs"], entry["outputs"], entry["activation"]) == (*kernel.shape, activation)
        for key, want in (("biases", bias), ("weights", kernel.T.ravel())):
            assert all(type(v) is float for v in entry[key]), f"{path}: {key} not all floats"
            got = np.array(entry[key], dtype=np.float32)
            assert got.shape == want.shape and np.array_equal(got.view(np.uint32), want.view(np.uint32)), \
                f"{path}: {key} do not round-trip"


def network(layers, x):
    """The forward pass in float64, x shaped (n, 6); returns (n, 3) BRDF values."""
    for kernel, bias in layers[:-1]:
        x = np.maximum(x @ kernel.astype(np.float64) + bias, 0.0)
    kernel, bias = layers[-1]
    return np.expm1(x @ kernel.astype(np.float64) + bias)


def table(layers):
    """The MERL table (3, 90, 90, 180) the SOURCES.md way: lower bin edges, mean over phi_d and phi_d + 180 deg,
    clamped at 0, divided by the channel scales, rounded to float32."""
    td = np.radians(np.arange(90.0))[:, None]
    out = np.empty((3, 90, 90, 180))
    for i in range(90):
        th = np.radians((i / 90) ** 2 * 90)
        f = 0.0
        for pd in (np.radians(np.arange(180.0)), np.radians(np.arange(180.0) + 180)):
            x = np.stack(np.broadcast_arrays(np.sin(th), 0.0, np.cos(th), np.sin(td) * np.cos(pd),
                                             np.sin(td) * np.sin(pd), np.cos(td)), axis=-1)
            f = f + 0.5 * network(layers, x.reshape(-1, 6))
        out[:, i] = (np.maximum(f, 0.0) / MERL_SCALE).T.reshape(3, 90, 180)
    return out.astype(np.float32)


def check_table(merl_path, layers):
    """Compares the rebuilt table with the stored one on every valid bin; returns False if any differs by > 1 ulp."""
    start = time.perf_counter()
    raw = lzma.decompress(merl_path.read_bytes())
    assert list(np.frombuffer(raw, "<i4", 3)) == [90, 90, 180] and len(raw) == 12 + 3 * 1458000 * 8
    stored = np.frombuffer(raw, "<f8", offset=12).reshape(3, 90, 90, 180)
    ours = table(layers)
    valid = stored >= 0
    s, o = stored[valid].astype(np.float32), ours[valid]
    assert np.array_equal(s.astype(np.float64), stored[valid]), "stored values are not float32 values"
    ulps = np.abs(s.view(np.int32).astype(np.int64) - o.view(np.int32))  # both >= 0: ulp distance
    rel = np.abs(o.astype(np.float64) - s) / np.maximum(s, np.finfo(np.float32).tiny)
    print(f"  check {merl_path.name}: {valid.sum()} valid values ({valid[0].sum()} bins x 3 channels), "
          f"{(ulps > 0).sum()} differ, {(ulps > 1).sum()} by > 1 ulp, max ulps {ulps.max()}, "
          f"max relative difference {rel.max():.3g}  ({time.perf_counter() - start:.1f} s)")
    return ulps.max() <= 1


def main():
    parser = argparse.ArgumentParser(description="Neural BRDF .h5 weights -> .nbrdf text files")
    parser.add_argument("--database", required=True, choices=sorted(DATABASES))
    parser.add_argument("zip", type=pathlib.Path, help="the database's zip of networks (../shared/nbrdf/)")
    parser.add_argument("names", nargs="*", help="only these networks (their names in the zip, without .h5)")
    parser.add_argument("-o", "--out-dir", required=True, type=pathlib.Path)
    parser.add_argument("--check", metavar="MERL_DIR", type=pathlib.Path,
                        help="compare the network's table with MERL_DIR/<name>.binary.xz where there is one")
    args = parser.parse_args()
    db = DATABASES[args.database]
    if args.zip.name != db["zip"]:
        sys.exit(f"{args.zip}: the {args.database} networks come in {db['zip']}")
    args.out_dir.mkdir(parents=True, exist_ok=True)
    ok = True
    with zipfile.ZipFile(args.zip) as z:
        members = sorted(m for m in z.namelist() if m.startswith(db["folder"] + "/") and m.endswith(".h5"))
        if args.names:
            members = [m for m in members if pathlib.PurePosixPath(m).stem in args.names]
            if len(members) != len(set(args.names)):
                sys.exit(f"{args.zip}: not every name given is a network there")
        for member in members:
            data = z.read(member)
            name = db["rename"](pathlib.PurePosixPath(member).stem)
            layers = read_layers(member, data)
            out = args.out_dir / f"{name}.nbrdf"
            write_nbrdf(out, name, db, member, hashlib.sha256(data).hexdigest(), layers)
            check_round_trip(out, name, layers)
            print(f"{out}: {sum(a.size for layer in layers for a in layer)} weights, round-trip exact")
            if args.check and (args.check / f"{name}.binary.xz").exists():
                ok &= check_table(args.check / f"{name}.binary.xz", layers)
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
