"""glossy vs Mitsuba 3 on the same scene, the same BRDFs, in one invocation (issue 8; issue 21, deliverable 1).

Run through scripts/compare-mitsuba, which makes the venv and builds glossy; --only picks sections, e.g.
  scripts/compare-mitsuba --only efficiency --lighting sky --material ct --seeds 2     (about half a minute)
--glossy PATH measures another build's glossy_compare with this checkout's harness.

The scene (bench/mitsuba/scene.py), written once for both: a 128x64 UV sphere of radius 1 with vertex
normals as glTF (glossy; extras.glossy binds the material) and PLY (Mitsuba), camera at (0, 1, 4) looking at
the origin, 35 deg vertical FOV, 256^2. Both: path tracing, max depth 3 (path segments), power-heuristic MIS
between one emitter sample and one BSDF sample per vertex, the environment visible behind the sphere,
1-pixel box filter; Mitsuba 3.9.1 llvm_ad_rgb with the multijitter sampler, glossy with its own sampler.

 1. Efficiency (the main table): efficiency = 1 / (render time x pixel variance) at equal spp, per
    (lighting, material):
    - lightings: studio (../shared/envmaps/studio_small_09_1k.hdr, loaded by both), sky (glossy's procedural
      default sky written as one float EXR both load), constant (radiance 1: Mitsuba's `constant` emitter,
      glossy's Environment::constant through glossy_compare --env-constant);
    - materials: ct (blue-rubber's Cook-Torrance E1 fit; Mitsuba: cook_torrance.py), ct-metal (steel's
      Cook-Torrance E2 fit, m = 0.0125: a sharp metal lobe; cook_torrance.py, which samples the Beckmann lobe
      or the cosine in proportion to the lobes' albedos), microfacet (aluminium's
      Microfacet E2 fit, B = 2.2e5: a heavy-tailed lobe; microfacet.py), measured (the MERL-format
      blue-rubber table, an NBRDF reconstruction: glossy_compare --measured with glossy's tabulated sampler;
      Mitsuba: measured.py, the same nearest-bin lookup, sampled by the CT E1 fit's mixture). The plugins'
      values agree with `glossy eval` (bench/mitsuba/check_plugins.py).
    Each renderer renders SEEDS pairs of images at SPP, after warm-ups (glossy's thread pool; Mitsuba's JIT
    compile, timed by Dr.Jit's kernel history and reported apart), interleaved g m m g g m ... so that load
    from other processes falls on both alike. Render time only: glossy's is its render call (bench/
    compare_bench.cpp), Mitsuba's mi.render + dr.eval + dr.sync_thread (its Python tracing of the kernel
    included, as a user pays it). Per pair: variance = mean((a - b)^2) / 2 over the mask's pixels and the 3
    channels, time = the pair's mean, efficiency ratio = (t_M var_M) / (t_g var_g); the table gives medians
    over the pairs. The mask: pixels whose whole footprint sees the sphere, from rays through each pixel's
    four corners traced against the very mesh (Mitsuba's camera and ray_test; the mesh is convex, so four
    covered corners mean a covered pixel), shrunk by one more pixel all round (sphere_mask).
    Checks per cell: bias z = (glossy's mean - Mitsuba's) over the mask and all renders, over its standard
    error from the spread of the per-render means (a biased estimator or a wrongly scaled light shows as
    |z| >> 1); pixels = sum over the mask of (mean image_g - mean image_M)^2 over the sum of what their
    per-pixel noise explains (about 1 when the images agree; a mirrored or rotated map, which the mask
    mean can hide, drives it far above 1).
 2. Ray rates (on sphere.gltf: alum-bronze's CT E2 under the sky): glossy's path-tracing rays/s beside raw
    Embree's on the very rays of the same render, at 1 and 2 threads (bench/ray_replay.h); the same ratio
    for Mitsuba (its render's rate beside its own traversal, ray_intersect_preliminary and ray_test, of
    those rays); samples/s at 1 and 2 threads.
 3. Agreement (the same scene): converged images of both (each the mean of two half renders, cached in
    OUT/ref), relative RMSE between them over the sphere and the background, beside the noise floor the
    halves measure; the same for a grey Lambertian sphere (the environment orientation check).
 4. Highlight (bench/mitsuba/highlight.py): the light a sharp Cook-Torrance E2 lobe's highlight of a small
    bright source carries (a 512 x 256 map of 0.1 with a 2 x 2 or 1 x 1 texel source of radiance 2000, five
    places, three fits down to m = 0.0125) in glossy (`glossy render`) and Mitsuba, against an independent
    NumPy quadrature; each renderer's image minus its render of the background alone.

relative RMSE(img, ref) = sqrt(mean((img - ref)^2)) / sqrt(mean(ref^2)), over the pixels and the three
channels of the region named (all pixels unless stated). Results: OUT/results.json (the sections run).
"""

import argparse
import json
import math
import os
import statistics
import subprocess
import sys
import time
import tomllib
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

import scene as bench_scene  # noqa: E402

import drjit as dr  # noqa: E402
import mitsuba as mi  # noqa: E402

mi.set_variant("llvm_ad_rgb")
import cook_torrance  # noqa: E402  (these need the variant)
import highlight  # noqa: E402
import measured  # noqa: E402
import microfacet  # noqa: E402

for _plugin in (cook_torrance, microfacet, measured):
    _plugin.register()


def log(*args):
    print(*args, file=sys.stderr, flush=True)


# ------------------------------------------------------------------------------------------------ glossy
class Glossy:
    """The glossy_compare server: the scene loaded and the BVH built once; one command per line."""

    def __init__(self, exe, scene, env, size, max_depth, extra=()):
        """env: a map's path, or a number for a constant environment (--env-constant); extra: further options
        (e.g. --measured FILE)."""
        light = ["--env-constant", repr(float(env))] if isinstance(env, (int, float)) else ["--env", str(env)]
        command = [str(exe), "--scene", str(scene), *light, "--width", str(size), "--height", str(size),
                   "--max-depth", str(max_depth), *map(str, extra)]
        self.proc = subprocess.Popen(command, stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True, bufsize=1)
        ready = self.proc.stdout.readline().split(maxsplit=1)
        if not ready or ready[0] != "ready":
            raise RuntimeError(f"glossy_compare did not start ({' '.join(command)}); an older build may lack "
                               "--env-constant and --measured")
        self.binding = ready[1].strip() if len(ready) > 1 else ""

    def _ask(self, line):
        self.proc.stdin.write(line + "\n")
        self.proc.stdin.flush()
        answer = self.proc.stdout.readline().split()
        if not answer or answer[0] != "ok":
            raise RuntimeError(f"glossy_compare: {line!r} -> {' '.join(answer)}")
        return answer[1:]

    def render(self, spp, seed, threads, out=None):
        """Wall seconds of the render call; its CPU seconds (all threads) are left in last_cpu."""
        seconds, dropped, cpu = self._ask(f"render {spp} {seed} {threads} {out or '-'}")
        if int(dropped):
            log(f"glossy: {dropped} non-finite samples dropped")
        self.last_cpu = float(cpu)
        return float(seconds)

    def rays(self, spp, threads, runs):
        rays, samples, pt, raw, raw_packets = self._ask(f"rays {spp} {threads} {runs}")
        return int(rays), float(samples), float(pt), float(raw), float(raw_packets)

    def dump_rays(self, spp, path):
        """Every ray of one render at spp, written to path (bench/compare_bench.cpp: 8 float32 per ray)."""
        return int(self._ask(f"dumprays {spp} {path}")[0])

    def close(self):
        try:
            self.proc.stdin.write("quit\n")
            self.proc.stdin.close()
        except BrokenPipeError:
            pass
        self.proc.wait(timeout=30)


# ----------------------------------------------------------------------------------------------- Mitsuba
def mitsuba_scene(out, size, max_depth, bsdf, sampler, emitter=None):
    """emitter: a scene-dictionary emitter; default the sky EXR in out."""
    return mi.load_dict({
        "type": "scene",
        "integrator": {"type": "path", "max_depth": max_depth, "hide_emitters": False},
        "sensor": {
            "type": "perspective", "fov": bench_scene.YFOV_DEGREES, "fov_axis": "y",
            "to_world": mi.ScalarTransform4f().look_at(origin=list(bench_scene.EYE), target=list(bench_scene.TARGET),
                                                       up=list(bench_scene.UP)),
            "film": {"type": "hdrfilm", "width": size, "height": size, "rfilter": {"type": "box"},
                     "pixel_format": "rgb"},
            "sampler": {"type": sampler, "sample_count": 1},
        },
        "sky": emitter or {"type": "envmap", "filename": str(out / "sky.exr")},
        "sphere": {"type": "ply", "filename": str(out / "sphere.ply"), "bsdf": bsdf},
    })


mitsuba_last_cpu = 0.0


def mitsuba_render(scene, spp, seed):
    """Wall seconds and the image; the process's CPU seconds over the render are left in mitsuba_last_cpu."""
    global mitsuba_last_cpu
    cpu = time.process_time()
    start = time.perf_counter()
    image = mi.render(scene, spp=spp, seed=seed)
    dr.eval(image)
    dr.sync_thread()
    seconds = time.perf_counter() - start
    mitsuba_last_cpu = time.process_time() - cpu
    return seconds, np.array(image, dtype=np.float64)


def mitsuba_compile_seconds(scene, spp, seed):
    """Renders once with Dr.Jit's kernel history on: (wall seconds, seconds Dr.Jit spent generating and
    compiling (or loading from its disk cache) the kernels, kernels compiled, kernels loaded from the disk
    cache). For the warm-up render, whose compile is excluded from the timed renders and reported apart."""
    dr.kernel_history()  # clears it
    dr.set_flag(dr.JitFlag.KernelHistory, True)
    try:
        seconds, _ = mitsuba_render(scene, spp, seed)
    finally:
        dr.set_flag(dr.JitFlag.KernelHistory, False)
    kernels = [k for k in dr.kernel_history() if "codegen_time" in k]
    compile_ms = sum(k["codegen_time"] + k["backend_time"] for k in kernels if not k["cache_hit"])
    compiled = sum(1 for k in kernels if not k["cache_hit"] and not k["cache_disk"])
    from_disk = sum(1 for k in kernels if k["cache_disk"])
    return seconds, compile_ms / 1000.0, compiled, from_disk


class SppRounding:
    """Mitsuba's stratified samplers round a sample count up (multijitter: to a x ceil(n / a), a = floor
    sqrt n); largest_at_most(n) is the largest count <= n a sampler of this type renders as asked."""

    def __init__(self, sampler_type):
        level = mi.log_level()
        mi.set_log_level(mi.LogLevel.Error)
        self.sampler = mi.load_dict({"type": sampler_type, "sample_count": 1})
        mi.set_log_level(level)

    def largest_at_most(self, n):
        level = mi.log_level()
        mi.set_log_level(mi.LogLevel.Error)
        try:
            for k in range(max(1, n), 0, -1):
                self.sampler.set_sample_count(k)
                if self.sampler.sample_count() == k:
                    return k
            return 1
        finally:
            mi.set_log_level(level)


def mitsuba_raw_seconds(ply, ray_file, runs, thread_counts):
    """Mitsuba's own traversal of the rays glossy traced, on the same mesh: ray_intersect_preliminary for the
    path rays, ray_test for the shadow rays (what its path integrator calls), one wavefront each, after two
    warm-ups (JIT compile excluded). {threads: median seconds} for each thread count."""
    rec = np.fromfile(ray_file, dtype=np.float32).reshape(-1, 8)
    scene = mi.load_dict({"type": "scene", "sphere": {"type": "ply", "filename": str(ply)}})

    def rays(r):
        return mi.Ray3f(mi.Point3f(r[:, 0], r[:, 1], r[:, 2]), mi.Vector3f(r[:, 3], r[:, 4], r[:, 5]), r[:, 6], 0.0, [])

    path, shadow = rays(rec[rec[:, 7] == 0]), rays(rec[rec[:, 7] > 0])
    dr.eval(path, shadow)

    def run():
        dr.sync_thread()
        start = time.perf_counter()
        pi = scene.ray_intersect_preliminary(path)
        hit = scene.ray_test(shadow)
        dr.eval(pi.t, pi.prim_index, hit)
        dr.sync_thread()
        return time.perf_counter() - start

    seconds = {}
    for threads in thread_counts:
        dr.set_thread_count(threads)
        run()
        run()
        seconds[threads] = statistics.median(run() for _ in range(runs))
    return seconds


def mitsuba_render_chunked(scene, spp, seed, rounding, chunk=256):
    """A high-spp image as the mean of passes of at most chunk spp (keeps each kernel's wavefront moderate),
    each a count the sampler takes as it is; returns (image, spp rendered)."""
    total, done, k = None, 0, 0
    while done < spp:
        n = rounding.largest_at_most(min(chunk, spp - done))
        _, img = mitsuba_render(scene, n, seed * 1000 + k)
        total = img * n if total is None else total + img * n
        done += n
        k += 1
    return total / spp


# ------------------------------------------------------------------------------------------------ images
def read_exr(path):
    return np.array(mi.Bitmap(str(path)), dtype=np.float64)[..., :3]


def write_exr(path, image):
    mi.Bitmap(image.astype(np.float32)).write(str(path))


def rel_rmse(img, ref, mask=None):
    if mask is not None:
        img, ref = img[mask], ref[mask]
    return float(math.sqrt(np.mean((img - ref) ** 2)) / math.sqrt(np.mean(ref ** 2)))


def regions(size):
    """Pixels whose whole footprint sees the sphere, and those that see only the sky (edge pixels in
    neither), from the analytic pixel-centre rays and a margin of about a pixel."""
    eye = np.array(bench_scene.EYE)
    f = -eye / np.linalg.norm(eye)
    x = np.cross(f, bench_scene.UP)
    x /= np.linalg.norm(x)
    y = np.cross(x, f)
    t = math.tan(math.radians(bench_scene.YFOV_DEGREES / 2))
    j, i = np.meshgrid(np.arange(size), np.arange(size))
    sx, sy = (2 * (j + 0.5) / size - 1) * t, (1 - 2 * (i + 0.5) / size) * t
    d = f + sx[..., None] * x + sy[..., None] * y
    d /= np.linalg.norm(d, axis=2, keepdims=True)
    b = d @ eye
    meets = b * b - (eye @ eye - 1.0)          # > 0: the ray meets the unit sphere
    # Angular distance of a pixel from the silhouette, in pixels (silhouette half angle asin(1/|eye|)).
    half = math.asin(1.0 / np.linalg.norm(eye))
    angle = np.arccos(np.clip(-(d @ eye) / np.linalg.norm(eye), -1, 1))
    pixel = 2 * t / size
    return {"sphere": (meets > 0) & (angle < half - 1.5 * pixel), "background": angle > half + 1.5 * pixel}


def noise_of_mean(a, b):
    """RMSE of (a + b)/2 about its expectation, from two independent halves: sqrt(mean((a-b)^2)/4)."""
    return math.sqrt(np.mean((a - b) ** 2) / 4.0)


# ---------------------------------------------------------------------------------------------- efficiency
LIGHTINGS = {"studio": "studio HDR", "sky": "smooth sky", "constant": "constant 1"}
MATERIALS = {"ct": "Cook-Torrance E1, blue-rubber", "ct-metal": "Cook-Torrance E2, steel (m = 0.0125)",
             "microfacet": "Microfacet E2, aluminium",
             "measured": "MERL blue-rubber (NBRDF reconstruction)"}

# The sharp metal lobe: the published fit, the first of its kind in the file.
SHARP_METAL = ("materials/library/merl/steel.toml", "E2")


def fit_of(material_file, model, metric):
    fits = tomllib.loads(Path(material_file).read_text())["fit"]
    return next(f for f in fits if f["model"] == model and f["metric"] == metric)


def sphere_mask(out, size, max_depth, sampler):
    """Pixels whose whole footprint sees the sphere. The rays through a pixel's four corners (Mitsuba's
    camera, which glossy's matches) are traced against the very triangle mesh both render; the mesh is
    convex, so its image is a convex region, and a pixel whose four corners it covers is covered whole.
    The mask is then shrunk by one more pixel all round (3x3 erosion), a margin for any sub-pixel difference
    between the two renderers' cameras or film."""
    scene = mitsuba_scene(out, size, max_depth, {"type": "diffuse"}, sampler, {"type": "constant"})
    sensor = scene.sensors()[0]
    n = (size + 1) ** 2
    i, j = np.meshgrid(np.arange(size + 1), np.arange(size + 1), indexing="ij")  # corner row i, column j
    position = mi.Point2f((j.ravel() / size).astype(np.float32), (i.ravel() / size).astype(np.float32))
    ray, _ = sensor.sample_ray(dr.zeros(mi.Float, n), dr.full(mi.Float, 0.5, n), position,
                               dr.full(mi.Point2f, 0.5, n))
    hit = np.array(scene.ray_test(ray), dtype=bool).reshape(size + 1, size + 1)
    covered = hit[:-1, :-1] & hit[1:, :-1] & hit[:-1, 1:] & hit[1:, 1:]
    padded = np.pad(covered, 1, constant_values=False)
    mask = np.ones_like(covered)
    for di in range(3):
        for dj in range(3):
            mask &= padded[di:di + size, dj:dj + size]
    return mask


def efficiency_cell(a, ctx, lighting, material):
    """One (lighting, material) cell: warm-ups, then 2 x seeds renders of each renderer at a.spp, interleaved
    g m m g g m ..., the images kept over the mask only. Returns the cell's record (efficiency_summary)."""
    root, out, mask = ctx["root"], ctx["out"], ctx["mask"]
    env = {"studio": ctx["studio"], "sky": out / "sky.exr", "constant": 1.0}[lighting]
    emitter = {"studio": {"type": "envmap", "filename": str(ctx["studio"])},
               "sky": {"type": "envmap", "filename": str(out / "sky.exr")},
               "constant": {"type": "constant", "radiance": {"type": "rgb", "value": 1.0}}}[lighting]
    ct_fit = fit_of(root / "materials/library/merl/blue-rubber.toml", "cook-torrance", "E1")
    if material == "ct":
        gltf, extra, bsdf = out / "eff-ct.gltf", (), cook_torrance.bsdf_dict(ct_fit)
    elif material == "ct-metal":
        gltf, extra = out / "eff-ct-metal.gltf", ()
        bsdf = cook_torrance.bsdf_dict(fit_of(root / SHARP_METAL[0], "cook-torrance", SHARP_METAL[1]))
    elif material == "microfacet":
        gltf, extra = out / "eff-microfacet.gltf", ()
        bsdf = microfacet.bsdf_dict(fit_of(root / "materials/library/merl/aluminium.toml", "microfacet", "E2"))
    else:  # glossy: its tabulated sampler; Mitsuba: the CT E1 fit's mixture as the proposal (measured.py)
        gltf, extra, bsdf = out / "eff-ct.gltf", ("--measured", ctx["merl"]), measured.bsdf_dict(ctx["merl"], ct_fit)
    if a.light_samples is not None:
        extra = (*extra, "--light-samples", a.light_samples)
    if a.fixed_light_samples:
        extra = (*extra, "--fixed-light-samples")
    glossy = Glossy(ctx["glossy"], gltf, env, a.size, a.max_depth, extra)
    mts = mitsuba_scene(out, a.size, a.max_depth, bsdf, a.sampler, emitter)

    # Warm-ups: glossy's thread pool and caches; Mitsuba's JIT compile (the first render), then one more so
    # that a kernel-cache miss on the seed would show here rather than in the timed runs.
    glossy.render(a.spp, 9999, a.threads)
    m_first, m_compile, m_compiled, m_from_disk = mitsuba_compile_seconds(mts, a.spp, 9999)
    m_second, _ = mitsuba_render(mts, a.spp, 9998)
    g_t, m_t, g_img, m_img, g_cpu, m_cpu = [], [], [], [], [], []
    tmp = out / "eff"
    tmp.mkdir(exist_ok=True)
    for i in range(2 * a.seeds):
        for who in (("g", "m") if i % 2 == 0 else ("m", "g")):
            if who == "g":  # the EXR is written after the render call, outside the time it reports
                path = tmp / f"glossy-{i}.exr"
                g_t.append(glossy.render(a.spp, a.seed + i, a.threads, path))
                g_cpu.append(glossy.last_cpu)
                g_img.append(read_exr(path)[mask])
            else:
                seconds, img = mitsuba_render(mts, a.spp, a.seed + i)
                m_t.append(seconds)
                m_cpu.append(mitsuba_last_cpu)
                m_img.append(img[mask])
    glossy.close()
    del mts
    cell = {"lighting": lighting, "material": material, "glossy_binding": glossy.binding,
            "mitsuba_bsdf": {k: v for k, v in bsdf.items()}, "spp": a.spp, "pairs": a.seeds,
            "glossy_seconds": g_t, "mitsuba_seconds": m_t, "glossy_cpu_seconds": g_cpu, "mitsuba_cpu_seconds": m_cpu,
            "mitsuba_first_render_seconds": m_first, "mitsuba_second_render_seconds": m_second,
            "mitsuba_compile_seconds": m_compile, "mitsuba_kernels_compiled": m_compiled,
            "mitsuba_kernels_from_disk_cache": m_from_disk,
            "load_average": os.getloadavg()}
    cell.update(efficiency_summary(g_t, g_img, m_t, m_img))
    return cell


def efficiency_summary(g_t, g_img, m_t, m_img):
    """Per seed pair k (renders 2k, 2k+1 of each): variance = mean((a - b)^2) / 2 over the mask's pixels and
    the 3 channels, time = the pair's mean render seconds, efficiency = 1 / (time x variance); the ratio
    glossy / Mitsuba per pair, and its median. Bias: the renderers' means over the mask (all their renders),
    their difference over its standard error (z), the error from the spread of the per-render means."""
    def pairs(times, imgs):
        var = [float(np.mean((imgs[2 * k] - imgs[2 * k + 1]) ** 2) / 2) for k in range(len(imgs) // 2)]
        sec = [(times[2 * k] + times[2 * k + 1]) / 2 for k in range(len(imgs) // 2)]
        return var, sec

    g_var, g_sec = pairs(g_t, g_img)
    m_var, m_sec = pairs(m_t, m_img)
    ratios = [(ms * mv) / (gs * gv) for gs, gv, ms, mv in zip(g_sec, g_var, m_sec, m_var)]
    r = {"glossy_variance": g_var, "mitsuba_variance": m_var, "efficiency_ratios": ratios,
         "efficiency_ratio": statistics.median(ratios),
         "glossy_seconds_median": statistics.median(g_t), "mitsuba_seconds_median": statistics.median(m_t),
         "glossy_noise": math.sqrt(statistics.median(g_var)), "mitsuba_noise": math.sqrt(statistics.median(m_var)),
         "mask_pixels": int(g_img[0].shape[0])}
    # Bias: per-render means over the mask, for the channel average and per channel.
    g_means = np.array([img.mean(axis=0) for img in g_img])   # [renders, 3]
    m_means = np.array([img.mean(axis=0) for img in m_img])
    for name, g, m in (("", g_means.mean(axis=1), m_means.mean(axis=1)), ("_rgb", g_means, m_means)):
        se = np.sqrt(g.var(axis=0, ddof=1) / len(g) + m.var(axis=0, ddof=1) / len(m))
        diff = g.mean(axis=0) - m.mean(axis=0)
        r["bias_z" + name] = (diff / se).tolist()
        r["mean_ratio_mitsuba_over_glossy" + name] = (m.mean(axis=0) / g.mean(axis=0)).tolist()
    # The same standard error from the pixels' variance (assumes independent pixels): a check of the above.
    def pixel_se2(imgs):
        c = [img.mean(axis=1) for img in imgs]
        v = statistics.mean(float(np.mean((c[2 * k] - c[2 * k + 1]) ** 2) / 2) for k in range(len(c) // 2))
        return v / len(c[0]) / len(c)
    r["bias_z_pixel_se"] = float((g_means.mean() - m_means.mean()) / math.sqrt(pixel_se2(g_img) + pixel_se2(m_img)))
    # Pixel by pixel: the squared difference of the two mean images over what their noise alone would give
    # (from each pixel's spread over the renders). About 1 when the images agree; a structural difference
    # the mask mean can hide (a mirrored or rotated map, a shifted camera) drives it well above 1.
    g_stack, m_stack = np.stack(g_img), np.stack(m_img)
    expected = g_stack.var(axis=0, ddof=1) / len(g_stack) + m_stack.var(axis=0, ddof=1) / len(m_stack)
    r["pixel_agreement"] = float(np.sum((g_stack.mean(axis=0) - m_stack.mean(axis=0)) ** 2) / np.sum(expected))
    return r


# -------------------------------------------------------------------------------------------------- main
SECTIONS = ("efficiency", "rays", "agreement", "highlight")


def csv_of(choices):
    def parse(text):
        items = [t.strip() for t in text.split(",") if t.strip()]
        bad = [t for t in items if t not in choices]
        if bad or not items:
            raise argparse.ArgumentTypeError(f"choose from {', '.join(choices)} (comma-separated), not {text!r}")
        return items
    return parse


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--root", type=Path, default=HERE.parent.parent, help="glossy checkout")
    p.add_argument("--build", type=Path, default=None, help="glossy build folder (default ROOT/build)")
    p.add_argument("--glossy", type=Path, default=None,
                   help="glossy_compare to measure (default BUILD/bench/glossy_compare): another build's, to judge it")
    p.add_argument("--out", type=Path, default=None, help="work folder (default BUILD/compare)")
    p.add_argument("--only", type=csv_of(SECTIONS), default=list(SECTIONS),
                   help=f"sections to run, comma-separated: {', '.join(SECTIONS)} (default all)")
    p.add_argument("--lighting", type=csv_of(tuple(LIGHTINGS)), default=list(LIGHTINGS),
                   help="efficiency: lightings, comma-separated: studio, sky, constant (default all)")
    p.add_argument("--material", type=csv_of(tuple(MATERIALS)), default=list(MATERIALS),
                   help="efficiency: materials, comma-separated: ct, ct-metal, microfacet, measured (default all)")
    p.add_argument("--seeds", type=int, default=4, help="efficiency: seed pairs per renderer and cell (median reported)")
    p.add_argument("--seed", type=int, default=100, help="efficiency: first seed (render i has seed SEED + i)")
    p.add_argument("--spp", type=int, default=64, help="efficiency: samples per pixel of every render")
    p.add_argument("--light-samples", type=int, default=None,
                   help="efficiency: glossy's light samples at the first vertex, at most (default: glossy's own default)")
    p.add_argument("--fixed-light-samples", action="store_true",
                   help="efficiency: glossy takes --light-samples at every first vertex, whatever the BRDF")
    p.add_argument("--studio", type=Path, default=None,
                   help="efficiency: the studio map (default ROOT/../shared/envmaps/studio_small_09_1k.hdr)")
    p.add_argument("--merl", type=Path, default=None,
                   help="efficiency: the measured table (default ROOT/../shared/merl/blue-rubber.binary.xz)")
    p.add_argument("--size", type=int, default=256)
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--max-depth", type=int, default=3)
    p.add_argument("--sampler", default="multijitter", help="Mitsuba sampler plugin")
    p.add_argument("--runs", type=int, default=5, help="rays: timed runs of each measurement (median reported)")
    p.add_argument("--ray-spp", type=int, default=16, help="rays: spp of the recorded render")
    p.add_argument("--ref-spp", type=int, default=1024, help="agreement: spp of each converged image (two halves)")
    p.add_argument("--check-spp", type=int, default=256, help="agreement: spp of each diffuse-sphere check image")
    p.add_argument("--sphere-material", default="materials/library/merl/alum-bronze.toml",
                   help="the material of sphere.gltf: the rays and agreement sections' and bench/compare-builds'")
    p.add_argument("--sphere-fit", default="cook-torrance:E2")
    p.add_argument("--fresh", action="store_true", help="agreement: re-render the cached converged images")
    p.add_argument("--highlight-spp", type=int, default=256, help="highlight: spp of every render of both renderers")
    p.add_argument("--highlight-seeds", type=int, default=2, help="highlight: renders per renderer and case (seeds 1 ...)")
    p.add_argument("--json", type=Path, default=None, help="results file (default OUT/results.json)")
    p.add_argument("--scene-only", action="store_true", help="write the scene files and the sky, then stop")
    a = p.parse_args()
    root = a.root.resolve()
    build = (a.build or root / "build").resolve()
    exe = (a.glossy or build / "bench/glossy_compare").resolve()
    out = (a.out or build / "compare").resolve()
    refdir = out / "ref"
    refdir.mkdir(parents=True, exist_ok=True)
    wall = time.perf_counter()
    load_start = os.getloadavg()
    dr.set_thread_count(a.threads)

    # The scene files: sphere.gltf (--sphere-material) for the rays and agreement sections and
    # bench/compare-builds, eff-*.gltf for the efficiency table, the PLY, the sky.
    material_file = (root / a.sphere_material).resolve()
    model, metric = a.sphere_fit.split(":")
    fit = fit_of(material_file, model, metric)
    if model != "cook-torrance":
        raise SystemExit("compare.py: the rays and agreement sections take cook-torrance fits only")
    triangles = bench_scene.write_scene(out, a.size, a.size, material_file, a.sphere_fit)
    bench_scene.write_sphere_gltf(out / "eff-ct.gltf", root / "materials/library/merl/blue-rubber.toml", "cook-torrance:E1", a.size, a.size)
    bench_scene.write_sphere_gltf(out / "eff-ct-metal.gltf", root / SHARP_METAL[0], f"cook-torrance:{SHARP_METAL[1]}",
                                  a.size, a.size)
    bench_scene.write_sphere_gltf(out / "eff-microfacet.gltf", root / "materials/library/merl/aluminium.toml", "microfacet:E2",
                                  a.size, a.size)
    subprocess.run([str(exe), "--write-sky", str(out / "sky.exr")], check=True)
    log(f"scene: UV sphere {bench_scene.SEGMENTS}x{bench_scene.RINGS}, {triangles} triangles; sky {out / 'sky.exr'}")
    if a.scene_only:
        print(out)
        return
    rounding = SppRounding(a.sampler)
    log(f"glossy: {exe}; mitsuba {mi.__version__} (drjit {dr.__version__}), variant llvm_ad_rgb, sampler {a.sampler}, "
        f"{dr.thread_count()} threads; load average {load_start[0]:.2f}")
    results = {"mitsuba_version": mi.__version__, "drjit_version": dr.__version__, "variant": "llvm_ad_rgb",
               "mitsuba_sampler": a.sampler, "size": a.size, "max_depth": a.max_depth, "threads": a.threads,
               "glossy_compare": str(exe), "triangles": triangles, "sections": a.only}

    # 1. Efficiency.
    if "efficiency" in a.only:
        if rounding.largest_at_most(a.spp) != a.spp:
            raise SystemExit(f"compare.py: the {a.sampler} sampler does not render {a.spp} spp as asked")
        if a.seeds < 2:
            raise SystemExit("compare.py: --seeds must be at least 2 (the bias check needs a spread)")
        ctx = {"root": root, "out": out, "glossy": exe, "mask": sphere_mask(out, a.size, a.max_depth, a.sampler),
               "studio": (a.studio or root.parent / "shared/envmaps/studio_small_09_1k.hdr").resolve(),
               "merl": (a.merl or root.parent / "shared/merl/blue-rubber.binary.xz").resolve()}
        log(f"efficiency: mask of {int(ctx['mask'].sum())} pixels; {a.seeds} seed pairs at {a.spp} spp per cell")
        cells = []
        for lighting in a.lighting:
            for material in a.material:
                start = time.perf_counter()
                cells.append(efficiency_cell(a, ctx, lighting, material))
                c = cells[-1]
                log(f"  {lighting:8} {material:10} glossy {c['glossy_seconds_median']:.3f} s noise {c['glossy_noise']:.5f}, "
                    f"Mitsuba {c['mitsuba_seconds_median']:.3f} s noise {c['mitsuba_noise']:.5f}: efficiency ratio "
                    f"{c['efficiency_ratio']:.3f}, bias z {c['bias_z']:+.1f} (pixel SE {c['bias_z_pixel_se']:+.1f}), pixels "
                    f"{c['pixel_agreement']:.2f} "
                    f"[{time.perf_counter() - start:.0f} s]")
        results["efficiency"] = {"spp": a.spp, "pairs": a.seeds, "seed": a.seed, "studio": str(ctx["studio"]),
                                 "merl": str(ctx["merl"]), "mask_pixels": int(ctx["mask"].sum()), "cells": cells}

    if "rays" in a.only or "agreement" in a.only:
        glossy = Glossy(exe, out / "sphere.gltf", out / "sky.exr", a.size, a.max_depth)
        log(f"glossy: {glossy.binding}")
        mts = mitsuba_scene(out, a.size, a.max_depth, cook_torrance.bsdf_dict(fit), a.sampler)
        results.update({"material": str(material_file), "fit": a.sphere_fit})
        if "rays" in a.only:
            results.update(ray_rates(a, glossy, mts, out))
        if "agreement" in a.only:
            results.update(agreement(a, glossy, mts, out, refdir, rounding, exe, model, metric, material_file))
        glossy.close()

    if "highlight" in a.only:
        results["highlight"] = highlight_cases(a, root, build, out, rounding)

    results["wall_seconds"] = time.perf_counter() - wall
    results["load_average_start"] = load_start
    results["load_average"] = os.getloadavg()
    (a.json or out / "results.json").write_text(json.dumps(results, indent=1) + "\n")
    if "efficiency" in results:
        print_efficiency(results)
    if "rays" in results:
        print_rays(results)
    if "agreement" in results:
        print_agreement(results)
    if "highlight" in results:
        print_highlight(results)
    print(f"\nwall time {results['wall_seconds']:.0f} s; load average at the start {load_start[0]:.2f}, at the end "
          f"{', '.join(f'{x:.2f}' for x in results['load_average'])} (1, 5, 15 min; this benchmark's own is about "
          f"{a.threads})")


def ray_rates(a, glossy, mts, out):
    """glossy's path-tracing ray rate beside raw Embree's on the same rays, at 1 and 2 threads; the same ratio
    for Mitsuba; samples/s at 1 and 2 threads (thread scaling)."""
    N = a.size * a.size
    rays = {}
    for threads in (1, 2):
        n_rays, samples, pt, raw, raw_packets = glossy.rays(a.ray_spp, threads, a.runs)
        rays[threads] = {"rays": n_rays, "samples": samples, "pt_seconds": pt, "raw_seconds": raw,
                         "raw_packet_seconds": raw_packets,
                         "samples_per_s": samples / pt, "pt_rays_per_s": n_rays / pt,
                         "raw_rays_per_s": n_rays / raw, "pt_over_raw": raw / pt,
                         "raw_packet_rays_per_s": n_rays / raw_packets, "pt_over_raw_packets": raw_packets / pt,
                         "rays_per_sample": n_rays / samples}
        log(f"rays, {threads} thread(s): PT {n_rays / pt:.3g}/s, raw Embree {n_rays / raw:.3g}/s one at a time, "
            f"{n_rays / raw_packets:.3g}/s in glossy's packets")
    dr.set_thread_count(1)
    mitsuba_render(mts, a.ray_spp, 997)  # compile at this spp
    m1 = statistics.median(mitsuba_render(mts, a.ray_spp, 990 + k)[0] for k in range(3))
    dr.set_thread_count(a.threads)
    mitsuba_render(mts, a.ray_spp, 996)
    m2 = statistics.median(mitsuba_render(mts, a.ray_spp, 980 + k)[0] for k in range(3))
    scaling = {"glossy_1": rays[1]["samples_per_s"], "glossy_2": rays[2]["samples_per_s"],
               "mitsuba_1": N * a.ray_spp / m1, "mitsuba_2": N * a.ray_spp / m2, "spp": a.ray_spp}
    # The same ratio for Mitsuba: its render's ray rate beside its own traversal of glossy's rays. Its ray
    # count is taken as glossy's (same scene and algorithm); it traces a shadow ray for every emitter sample,
    # also those glossy skips (below the surface, zero BRDF), so that count is a lower bound and the ratio too.
    ray_file = out / f"rays-{a.ray_spp}spp.bin"
    n_dumped = glossy.dump_rays(a.ray_spp, ray_file)
    m_raws = mitsuba_raw_seconds(out / "sphere.ply", ray_file, a.runs, (1, 2))
    for threads, m_pt in ((1, m1), (2, m2)):
        m_raw = m_raws[threads]
        rays[threads].update({"mitsuba_pt_seconds": m_pt, "mitsuba_raw_seconds": m_raw,
                              "mitsuba_raw_rays_per_s": n_dumped / m_raw, "mitsuba_pt_rays_per_s": n_dumped / m_pt,
                              "mitsuba_pt_over_raw": m_raw / m_pt})
        log(f"rays, {threads} thread(s): Mitsuba PT >= {n_dumped / m_pt:.3g}/s, its own traversal {n_dumped / m_raw:.3g}/s")
    dr.set_thread_count(a.threads)
    ray_file.unlink()
    return {"rays": rays, "scaling": scaling}


def agreement(a, glossy, mts, out, refdir, rounding, exe, model, metric, material_file):
    """Converged images of both (each the mean of two half renders, cached in OUT/ref) and their agreement,
    for sphere.gltf's material and for a grey Lambertian sphere (the environment orientation check)."""
    def converged(name, render_half, spp):
        """(mean of two half renders, the halves), rendered once and cached in OUT/ref."""
        halves = [refdir / f"{name}-{spp}spp-{h}.exr" for h in "ab"]
        if a.fresh or not all(h.exists() for h in halves):
            start = time.perf_counter()
            for k, h in enumerate(halves):
                render_half(h, spp // 2, 1000 + k)
            log(f"{name}: rendered {spp} spp in {time.perf_counter() - start:.0f} s")
        imgs = [read_exr(h) for h in halves]
        return (imgs[0] + imgs[1]) / 2, imgs

    def glossy_half(g):
        return lambda path, spp, seed: g.render(spp, seed, a.threads, path)

    def mitsuba_half(scene):
        return lambda path, spp, seed: write_exr(path, mitsuba_render_chunked(scene, spp, seed, rounding))

    tag = f"{a.size}-d{a.max_depth}-{model}-{metric}-{material_file.stem}"
    g_ref, g_halves = converged(f"glossy-{tag}", glossy_half(glossy), a.ref_spp)
    m_ref, m_halves = converged(f"mitsuba-{a.sampler}-{tag}", mitsuba_half(mts), a.ref_spp)
    reg = {"all": np.ones((a.size, a.size), bool), **regions(a.size)}

    def agree(g, gh, m, mh):
        """Rel. RMSE of Mitsuba's converged image against glossy's per region, beside the noise floor:
        the rel. RMSE two unbiased images with these noise levels would show, sqrt(n_g^2 + n_m^2)."""
        r = {}
        for name, mask in reg.items():
            floor = math.sqrt(noise_of_mean(gh[0][mask], gh[1][mask]) ** 2 + noise_of_mean(mh[0][mask], mh[1][mask]) ** 2)
            r[name] = rel_rmse(m, g, mask)
            r[f"noise_floor_{name}"] = floor / math.sqrt(np.mean(g[mask] ** 2))
            r[f"mean_ratio_{name}"] = (m[mask].mean(axis=0) / g[mask].mean(axis=0)).tolist()
        return r

    rms_ref = math.sqrt(np.mean(g_ref ** 2))
    g_ref_noise, m_ref_noise = noise_of_mean(*g_halves), noise_of_mean(*m_halves)
    result = {"cook_torrance": agree(g_ref, g_halves, m_ref, m_halves)}
    gd = Glossy(exe, out / "diffuse.gltf", out / "sky.exr", a.size, a.max_depth)
    md = mitsuba_scene(out, a.size, a.max_depth, {"type": "diffuse", "reflectance": {"type": "rgb", "value": 0.5}},
                       a.sampler)
    gd_ref, gd_halves = converged(f"glossy-diffuse-{a.size}-d{a.max_depth}", glossy_half(gd), a.check_spp)
    md_ref, md_halves = converged(f"mitsuba-{a.sampler}-diffuse-{a.size}-d{a.max_depth}", mitsuba_half(md), a.check_spp)
    gd.close()
    result["diffuse"] = agree(gd_ref, gd_halves, md_ref, md_halves)
    write_exr(out / "agreement.exr", np.concatenate([g_ref, m_ref, gd_ref, md_ref], axis=1))
    return {"agreement": result,
            "reference": {"spp": a.ref_spp, "check_spp": a.check_spp, "glossy_noise_rel": g_ref_noise / rms_ref,
                          "mitsuba_noise_rel": m_ref_noise / rms_ref}}


def highlight_cases(a, root, build, out, rounding):
    """Section 4: the light of a sharp lobe's highlight of a small bright source (bench/mitsuba/highlight.py),
    glossy (its render command, defaults but for the scene's size and depth) and Mitsuba against the
    quadrature, each renderer's excess the mean over its seeds, z from their spread."""
    if rounding.largest_at_most(a.highlight_spp) != a.highlight_spp:
        raise SystemExit(f"compare.py: the {a.sampler} sampler does not render {a.highlight_spp} spp as asked")
    work = out / "highlight"
    work.mkdir(parents=True, exist_ok=True)
    exe = build / "renderer/glossy"
    background = work / "background.exr"
    write_exr(background, np.full((highlight.HEIGHT, highlight.WIDTH, 3), highlight.BACKGROUND))

    def glossy_image(env, material, fit, seed):
        path = work / "glossy.exr"
        subprocess.run([str(exe), "render", "--scene", str(out / "sphere.gltf"), "--env", str(env), "--material",
                        str(root / material), "--fit", fit, "--width", str(a.size), "--height", str(a.size),
                        "--max-depth", str(a.max_depth), "--spp", str(a.highlight_spp), "--seed", str(seed),
                        "--threads", str(a.threads), "-o", str(path)], check=True, capture_output=True)
        return read_exr(path)

    def mitsuba_image(env, bsdf, seed):
        scene = mitsuba_scene(out, a.size, a.max_depth, bsdf, a.sampler, {"type": "envmap", "filename": str(env)})
        return mitsuba_render_chunked(scene, a.highlight_spp, seed, rounding)

    cases = []
    for label, material, fit_id in highlight.MATERIALS:
        model, metric = fit_id.split(":")
        fit = fit_of(root / material, model, metric)
        bsdf = cook_torrance.bsdf_dict(fit)
        seeds = range(1, a.highlight_seeds + 1)
        g_background = [glossy_image(background, material, fit_id, s) for s in seeds]
        m_background = [mitsuba_image(background, bsdf, s) for s in seeds]
        for column, row, size in highlight.PLACES:
            env = work / f"source-{column}-{row}-{size}.exr"
            write_exr(env, highlight.source_map(column, row, size))
            expected, window = highlight.quadrature(fit, column, row, size, a.size)
            g = [highlight.light(glossy_image(env, material, fit_id, s) - b, window) for s, b in zip(seeds, g_background)]
            m = [highlight.light(mitsuba_image(env, bsdf, s) - b, window) for s, b in zip(seeds, m_background)]
            q = highlight.light(expected, window)
            se = math.sqrt(statistics.variance(g) / len(g) + statistics.variance(m) / len(m))
            cases.append({"material": label, "column": column, "row": row, "size": size, "quadrature": q,
                          "glossy": statistics.mean(g), "mitsuba": statistics.mean(m), "glossy_seeds": g,
                          "mitsuba_seeds": m, "z": (statistics.mean(g) - statistics.mean(m)) / se if se > 0 else 0.0})
            c = cases[-1]
            log(f"  highlight {label:15} source {column},{row} ({size}x{size}): quadrature {q:.2f}, glossy "
                f"{c['glossy']:.2f}, Mitsuba {c['mitsuba']:.2f}, z {c['z']:+.1f}")
    return {"spp": a.highlight_spp, "seeds": a.highlight_seeds, "map": [highlight.WIDTH, highlight.HEIGHT],
            "background": highlight.BACKGROUND, "radiance": highlight.RADIANCE, "cases": cases}


def print_highlight(r):
    h = r["highlight"]
    print(f"\nHighlight of a small source (map {h['map'][0]}x{h['map'][1]}, background {h['background']}, source "
          f"radiance {h['radiance']:g}; {h['seeds']} renders of {h['spp']} spp per renderer; light = excess "
          f"luminance summed over the highlight's window)\n")
    print("| material | source texel (size) | quadrature | glossy | Mitsuba 3 | glossy / quadrature | "
          "Mitsuba / quadrature | glossy / Mitsuba | z |")
    print("|---|---|---|---|---|---|---|---|---|")
    for c in h["cases"]:
        q = c["quadrature"]
        print(f"| {c['material']} | {c['column']},{c['row']} ({c['size']}x{c['size']}) | {q:.2f} | {c['glossy']:.2f} | "
              f"{c['mitsuba']:.2f} | {c['glossy'] / q:.3f} | {c['mitsuba'] / q:.3f} | {c['glossy'] / c['mitsuba']:.3f} | "
              f"{c['z']:+.1f} |")


def print_efficiency(r):
    e = r["efficiency"]
    print(f"\n## Efficiency, glossy vs Mitsuba {r['mitsuba_version']} ({r['variant']}, {r['mitsuba_sampler']} sampler)\n")
    print(f"Efficiency = 1 / (render seconds x variance); variance = mean((a - b)^2) / 2 over the sphere's "
          f"{e['mask_pixels']} fully covered pixels and the 3 channels, for two renders a, b of different seeds; "
          f"noise = sqrt(variance). {r['size']}x{r['size']}, {e['spp']} spp, max depth {r['max_depth']}, "
          f"{r['threads']} threads. Medians over {e['pairs']} seed pairs per renderer and cell; the efficiency ratio "
          f"> 1 when glossy is the more efficient (in brackets: its least and greatest over the pairs). Bias z: "
          f"(glossy's mean - Mitsuba's) over the mask and all renders, over its standard error. Pixels: the squared "
          f"difference of the two mean images over what their noise explains (about 1 when they agree). "
          f"**!** marks |z| > 4 or pixels > 1.5. Mitsuba 1st s: its first (warm-up) render, not in its times, and the "
          f"seconds Dr.Jit spent compiling kernels in it (none when its disk cache, ~/.drjit, has them).\n")
    print("| lighting | material | glossy s | glossy noise | Mitsuba s | Mitsuba noise | efficiency glossy / Mitsuba "
          "| bias z | pixels | Mitsuba 1st s |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for c in e["cells"]:
        ratios = c["efficiency_ratios"]
        z_flag = " **!**" if abs(c["bias_z"]) > 4 else ""
        p_flag = " **!**" if c["pixel_agreement"] > 1.5 else ""
        compiled = f" ({c['mitsuba_compile_seconds']:.2f} compile)" if c["mitsuba_kernels_compiled"] else ""
        print(f"| {LIGHTINGS[c['lighting']]} | {MATERIALS[c['material']]} | {c['glossy_seconds_median']:.3f} | "
              f"{c['glossy_noise']:.5f} | {c['mitsuba_seconds_median']:.3f} | {c['mitsuba_noise']:.5f} | "
              f"**{c['efficiency_ratio']:.3f}** ({min(ratios):.3g}-{max(ratios):.3g}) | {c['bias_z']:+.1f}{z_flag} | "
              f"{c['pixel_agreement']:.2f}{p_flag} | "
              f"{c['mitsuba_first_render_seconds']:.2f}{compiled} |")


def print_rays(r):
    sc = r["scaling"]
    print(f"\nsphere.gltf: {Path(r['material']).name} {r['fit']} under the smooth sky")
    print(f"threads ({sc['spp']} spp), samples/s {'glossy':>22} {'Mitsuba':>12}")
    print(f"{'  1 thread':44} {sc['glossy_1']:12.4g} {sc['mitsuba_1']:12.4g}")
    print(f"{'  2 threads':44} {sc['glossy_2']:12.4g} {sc['mitsuba_2']:12.4g}")
    print(f"{'  scaling 1 -> 2':44} {sc['glossy_2'] / sc['glossy_1']:12.2f} {sc['mitsuba_2'] / sc['mitsuba_1']:12.2f}")
    print(f"glossy rays ({sc['spp']} spp render, {r['rays'][1]['rays_per_sample']:.2f} rays/sample): "
          f"{'PT rays/s':>12} {'raw 1-ray':>12} {'PT/raw':>8} {'raw packets':>12} {'PT/raw':>8}")
    for t, v in r["rays"].items():
        print(f"{'  ' + str(t) + ' thread(s)':44} {v['pt_rays_per_s']:12.4g} {v['raw_rays_per_s']:12.4g} "
              f"{100 * v['pt_over_raw']:7.1f}% {v['raw_packet_rays_per_s']:12.4g} {100 * v['pt_over_raw_packets']:7.1f}%")
    print(f"Mitsuba on the same rays (its ray count taken as glossy's: a lower bound): "
          f"{'PT rays/s':>12} {'own raw':>12} {'PT/raw':>8}")
    for t, v in r["rays"].items():
        print(f"{'  ' + str(t) + ' thread(s)':44} {v['mitsuba_pt_rays_per_s']:12.4g} {v['mitsuba_raw_rays_per_s']:12.4g} "
              f"{100 * v['mitsuba_pt_over_raw']:7.1f}%")


def print_agreement(r):
    print(f"\nagreement of the converged images ({Path(r['material']).name} {r['fit']} {r['reference']['spp']} spp "
          f"each, grey diffuse {r['reference']['check_spp']} spp each): rel. RMSE Mitsuba vs glossy [noise floor]")
    for name, g in r["agreement"].items():
        ratio = ", ".join(f"{x:.4f}" for x in g["mean_ratio_sphere"])
        cells = ", ".join(f"{region} {g[region]:.2e} [{g['noise_floor_' + region]:.2e}]"
                          for region in ("all", "sphere", "background"))
        print(f"  {name:14} {cells}")
        print(f"  {'':14} mean over the sphere, Mitsuba / glossy (R, G, B): {ratio}")
    ref = r["reference"]
    print(f"  noise of the converged images themselves (rel. RMSE about their expectation, from their halves): "
          f"glossy {ref['glossy_noise_rel']:.2e}, Mitsuba {ref['mitsuba_noise_rel']:.2e}")


if __name__ == "__main__":
    main()
