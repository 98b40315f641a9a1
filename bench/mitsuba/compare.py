"""glossy vs Mitsuba 3 on the same scene, the same BRDF, in one invocation (issue 8, deliverables 1 and 2).

Run through scripts/compare-mitsuba, which makes the venv and builds glossy. Steps:

 1. The scene, written once for both (bench/mitsuba/scene.py): a 128x64 UV sphere of radius 1 with vertex
    normals as glTF (glossy) and PLY (Mitsuba), camera at (0, 1, 4) looking at the origin, 35 deg vertical
    FOV, 256^2; glossy's procedural sky written as one float EXR that both load; Cook-Torrance E2 of
    materials/alum-bronze.toml (glossy: extras.glossy binding; Mitsuba: bench/mitsuba/cook_torrance.py).
    Both: path tracing, max depth 3 (path segments), power-heuristic MIS between one emitter sample and one
    BSDF sample per vertex, the environment visible behind the sphere, 1-pixel box filter.
 2. Speed at equal spp: a warm-up each (Mitsuba's JIT compile is timed and reported apart), then RUNS
    renders each with different seeds, interleaved glossy / Mitsuba / Mitsuba / glossy ... so that load
    from other processes falls on both alike. Samples/s = W*H*spp / seconds; medians; their ratio.
    glossy's time is its render call (bench/compare_bench.cpp); Mitsuba's is mi.render + dr.eval +
    dr.sync_thread, so every kernel has run.
 3. Ray rates: glossy's path-tracing rays/s beside raw Embree's on the very rays of the same render, at
    1 and 2 threads (bench/ray_replay.h); and the same ratio for Mitsuba: its render's rate on that many rays
    beside its own traversal (ray_intersect_preliminary, ray_test) of those rays.
 4. Agreement: converged images of both (each the mean of two half renders, cached in OUT/ref), relative
    RMSE between them over the sphere and the background, beside the noise floor the halves measure;
    the same for a grey Lambertian sphere (the environment orientation check).
 5. Equal time: each renderer gets the same wall-time budget (spp from its measured rate), renders SEEDS
    images, and its relative RMSE against glossy's converged image is reported (median over seeds), beside
    the RMSE against its own converged image.

relative RMSE(img, ref) = sqrt(mean((img - ref)^2)) / sqrt(mean(ref^2)), over the pixels and the three
channels of the region named (all pixels unless stated).
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
import cook_torrance  # noqa: E402  (needs the variant)

cook_torrance.register()


def log(*args):
    print(*args, file=sys.stderr, flush=True)


# ------------------------------------------------------------------------------------------------ glossy
class Glossy:
    """The glossy_compare server: the scene loaded and the BVH built once; one command per line."""

    def __init__(self, exe, scene, env, size, max_depth):
        self.proc = subprocess.Popen(
            [str(exe), "--scene", str(scene), "--env", str(env), "--width", str(size), "--height", str(size),
             "--max-depth", str(max_depth)],
            stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True, bufsize=1)
        ready = self.proc.stdout.readline().split(maxsplit=1)
        if not ready or ready[0] != "ready":
            raise RuntimeError(f"glossy_compare did not start ({ready})")
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
def mitsuba_scene(out, size, max_depth, bsdf, sampler):
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
        "sky": {"type": "envmap", "filename": str(out / "sky.exr")},
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


# -------------------------------------------------------------------------------------------------- main
def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--root", type=Path, default=HERE.parent.parent, help="glossy checkout")
    p.add_argument("--build", type=Path, default=None, help="glossy build folder (default ROOT/build)")
    p.add_argument("--out", type=Path, default=None, help="work folder (default BUILD/compare)")
    p.add_argument("--size", type=int, default=256)
    p.add_argument("--spp", type=int, default=64, help="samples per pixel of the equal-spp runs")
    p.add_argument("--runs", type=int, default=5, help="timed runs of each renderer (median reported)")
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--max-depth", type=int, default=3)
    p.add_argument("--ref-spp", type=int, default=1024, help="spp of each converged image (two halves)")
    p.add_argument("--check-spp", type=int, default=256, help="spp of each diffuse-sphere check image")
    p.add_argument("--budget", type=float, default=2.0, help="seconds per equal-time render")
    p.add_argument("--seeds", type=int, default=3, help="equal-time renders of each renderer")
    p.add_argument("--ray-spp", type=int, default=16, help="spp of the recorded render of the ray-rate figures")
    p.add_argument("--sampler", default="multijitter", help="Mitsuba sampler plugin")
    p.add_argument("--material", default="materials/alum-bronze.toml")
    p.add_argument("--fit", default="cook-torrance:E2")
    p.add_argument("--fresh", action="store_true", help="re-render the cached converged images")
    p.add_argument("--json", type=Path, default=None, help="results file (default OUT/results.json)")
    p.add_argument("--scene-only", action="store_true", help="write the scene files and the sky, then stop")
    a = p.parse_args()
    root = a.root.resolve()
    build = (a.build or root / "build").resolve()
    out = (a.out or build / "compare").resolve()
    refdir = out / "ref"
    refdir.mkdir(parents=True, exist_ok=True)
    N = a.size * a.size
    wall = time.perf_counter()
    dr.set_thread_count(a.threads)

    # 1. The scene for both.
    material_file = (root / a.material).resolve()
    model, metric = a.fit.split(":")
    fit = next(f for f in tomllib.loads(material_file.read_text())["fit"]
               if f["model"] == model and f["metric"] == metric)
    if model != "cook-torrance":
        raise SystemExit("compare.py: the Mitsuba side implements cook-torrance fits only")
    triangles = bench_scene.write_scene(out, a.size, a.size, material_file, a.fit)
    subprocess.run([str(build / "bench/glossy_compare"), "--write-sky", str(out / "sky.exr")], check=True)
    log(f"scene: UV sphere {bench_scene.SEGMENTS}x{bench_scene.RINGS}, {triangles} triangles; sky {out / 'sky.exr'}")
    if a.scene_only:
        print(out)
        return

    glossy = Glossy(build / "bench/glossy_compare", out / "sphere.gltf", out / "sky.exr", a.size, a.max_depth)
    log(f"glossy: {glossy.binding}")
    mts = mitsuba_scene(out, a.size, a.max_depth, cook_torrance.bsdf_dict(fit), a.sampler)
    rounding = SppRounding(a.sampler)
    if rounding.largest_at_most(a.spp) != a.spp:
        raise SystemExit(f"compare.py: the {a.sampler} sampler does not render {a.spp} spp as asked")
    log(f"mitsuba {mi.__version__} (drjit {dr.__version__}), variant llvm_ad_rgb, sampler {a.sampler}, "
        f"{dr.thread_count()} threads")

    # 2. Equal spp. Warm-ups first: glossy's thread pool and caches, Mitsuba's JIT compile.
    glossy.render(a.spp, 999, a.threads)
    jit_first, _ = mitsuba_render(mts, a.spp, 999)
    mitsuba_render(mts, a.spp, 998)
    g_times, m_times, m_images, g_cpu, m_cpu = [], [], [], [], []
    for i in range(a.runs):
        order = ("g", "m") if i % 2 == 0 else ("m", "g")
        for who in order:
            if who == "g":  # the EXR is written after the render call, outside the time it reports
                g_times.append(glossy.render(a.spp, i, a.threads, out / f"equal-spp-glossy-{i}.exr"))
                g_cpu.append(glossy.last_cpu)
            else:
                seconds, img = mitsuba_render(mts, a.spp, i)
                m_times.append(seconds)
                m_cpu.append(mitsuba_last_cpu)
                m_images.append(img)
    g_med, m_med = statistics.median(g_times), statistics.median(m_times)
    speed = {
        "spp": a.spp, "threads": a.threads, "runs": a.runs,
        "glossy_seconds": g_times, "mitsuba_seconds": m_times,
        "glossy_samples_per_s": N * a.spp / g_med, "mitsuba_samples_per_s": N * a.spp / m_med,
        "ratio_glossy_over_mitsuba": m_med / g_med, "mitsuba_first_render_seconds": jit_first,
        "glossy_cpu_seconds": g_cpu, "mitsuba_cpu_seconds": m_cpu,
        "glossy_samples_per_cpu_s": N * a.spp / statistics.median(g_cpu),
        "mitsuba_samples_per_cpu_s": N * a.spp / statistics.median(m_cpu),
    }
    log(f"equal spp: glossy {g_med:.3f} s, mitsuba {m_med:.3f} s (median of {a.runs})")

    # 3. Ray rates, 1 and 2 threads (also glossy's thread scaling).
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

    # 4. Converged images (cached) and their agreement.
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

    def agreement(g, gh, m, mh):
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
    agree = {"cook_torrance": agreement(g_ref, g_halves, m_ref, m_halves)}
    speed["glossy_rmse_vs_glossy_ref"] = [rel_rmse(read_exr(out / f"equal-spp-glossy-{i}.exr"), g_ref)
                                          for i in range(a.runs)]
    speed["mitsuba_rmse_vs_glossy_ref"] = [rel_rmse(img, g_ref) for img in m_images]
    del m_images
    # The grey Lambertian sphere under the same sky: the environment orientation check.
    gd = Glossy(build / "bench/glossy_compare", out / "diffuse.gltf", out / "sky.exr", a.size, a.max_depth)
    md = mitsuba_scene(out, a.size, a.max_depth, {"type": "diffuse", "reflectance": {"type": "rgb", "value": 0.5}},
                       a.sampler)
    gd_ref, gd_halves = converged(f"glossy-diffuse-{a.size}-d{a.max_depth}", glossy_half(gd), a.check_spp)
    md_ref, md_halves = converged(f"mitsuba-{a.sampler}-diffuse-{a.size}-d{a.max_depth}", mitsuba_half(md), a.check_spp)
    gd.close()
    agree["diffuse"] = agreement(gd_ref, gd_halves, md_ref, md_halves)
    del md
    write_exr(out / "agreement.exr", np.concatenate([g_ref, m_ref, gd_ref, md_ref], axis=1))

    # 5. Equal time.
    g_rate, m_rate = speed["glossy_samples_per_s"], speed["mitsuba_samples_per_s"]
    g_spp = max(1, round(a.budget * g_rate / N))
    m_spp = rounding.largest_at_most(max(1, round(a.budget * m_rate / N)))
    mitsuba_render(mts, m_spp, 995)  # compile at this spp
    eq = {"budget_seconds": a.budget, "glossy_spp": g_spp, "mitsuba_spp": m_spp,
          "glossy": {"seconds": [], "rmse_vs_glossy_ref": [], "rmse_vs_own_ref": []},
          "mitsuba": {"seconds": [], "rmse_vs_glossy_ref": [], "rmse_vs_own_ref": []}}
    for s in range(a.seeds):
        path = out / f"equal-time-glossy-{s}.exr"
        seconds = glossy.render(g_spp, 2000 + s, a.threads, path)
        img = read_exr(path)
        eq["glossy"]["seconds"].append(seconds)
        eq["glossy"]["rmse_vs_glossy_ref"].append(rel_rmse(img, g_ref))
        eq["glossy"]["rmse_vs_own_ref"].append(rel_rmse(img, g_ref))
        seconds, img = mitsuba_render(mts, m_spp, 2000 + s)
        eq["mitsuba"]["seconds"].append(seconds)
        eq["mitsuba"]["rmse_vs_glossy_ref"].append(rel_rmse(img, g_ref))
        eq["mitsuba"]["rmse_vs_own_ref"].append(rel_rmse(img, m_ref))
        if s == 0:
            write_exr(out / "equal-time-mitsuba-0.exr", img)
    for who in ("glossy", "mitsuba"):
        # Monte Carlo error falls as 1/sqrt(time): the RMSE each would have had at exactly the budget.
        eq[who]["rmse_at_budget"] = [e * math.sqrt(t / a.budget) for e, t in
                                     zip(eq[who]["rmse_vs_glossy_ref"], eq[who]["seconds"])]
        for k in ("seconds", "rmse_vs_glossy_ref", "rmse_vs_own_ref", "rmse_at_budget"):
            eq[who][k + "_median"] = statistics.median(eq[who][k])
    glossy.close()

    results = {
        "mitsuba_version": mi.__version__, "drjit_version": dr.__version__, "variant": "llvm_ad_rgb",
        "mitsuba_sampler": a.sampler, "size": a.size, "max_depth": a.max_depth, "material": str(material_file),
        "fit": a.fit, "triangles": triangles, "speed": speed, "rays": rays, "scaling": scaling,
        "agreement": agree, "reference": {"spp": a.ref_spp, "check_spp": a.check_spp, "glossy_noise_rel": g_ref_noise / rms_ref,
                                          "mitsuba_noise_rel": m_ref_noise / rms_ref},
        "equal_time": eq, "wall_seconds": time.perf_counter() - wall,
        "load_average": os.getloadavg(),
    }
    (a.json or out / "results.json").write_text(json.dumps(results, indent=1) + "\n")
    print_table(results)


def print_table(r):
    s, eq = r["speed"], r["equal_time"]
    print(f"\nglossy vs Mitsuba {r['mitsuba_version']} ({r['variant']}, {r['mitsuba_sampler']} sampler): "
          f"{r['size']}x{r['size']} UV sphere ({r['triangles']} triangles), {r['fit']} of "
          f"{Path(r['material']).name}, max depth {r['max_depth']}, {s['threads']} threads\n")
    print(f"{'equal spp (' + str(s['spp']) + ' spp, median of ' + str(s['runs']) + ')':44} {'glossy':>12} {'Mitsuba':>12}")
    print(f"{'  seconds':44} {statistics.median(s['glossy_seconds']):12.3f} {statistics.median(s['mitsuba_seconds']):12.3f}")
    print(f"{'  samples/s':44} {s['glossy_samples_per_s']:12.4g} {s['mitsuba_samples_per_s']:12.4g}")
    print(f"{'  glossy / Mitsuba samples/s':44} {s['ratio_glossy_over_mitsuba']:12.3f}")
    print(f"{'  samples per CPU second (all threads)':44} {s['glossy_samples_per_cpu_s']:12.4g} "
          f"{s['mitsuba_samples_per_cpu_s']:12.4g}")
    print(f"{'  glossy / Mitsuba samples per CPU second':44} "
          f"{s['glossy_samples_per_cpu_s'] / s['mitsuba_samples_per_cpu_s']:12.3f}")
    print(f"{'  rel. RMSE vs glossy converged':44} {statistics.median(s['glossy_rmse_vs_glossy_ref']):12.4f} "
          f"{statistics.median(s['mitsuba_rmse_vs_glossy_ref']):12.4f}")
    print(f"{'  Mitsuba first render (JIT compile), s':44} {'':12} {s['mitsuba_first_render_seconds']:12.3f}")
    print(f"equal time ({eq['budget_seconds']:g} s budget, median of {len(eq['glossy']['seconds'])} seeds)")
    print(f"{'  spp':44} {eq['glossy_spp']:12d} {eq['mitsuba_spp']:12d}")
    print(f"{'  seconds':44} {eq['glossy']['seconds_median']:12.3f} {eq['mitsuba']['seconds_median']:12.3f}")
    print(f"{'  rel. RMSE vs glossy converged':44} {eq['glossy']['rmse_vs_glossy_ref_median']:12.4f} "
          f"{eq['mitsuba']['rmse_vs_glossy_ref_median']:12.4f}")
    print(f"{'  rel. RMSE vs own converged':44} {eq['glossy']['rmse_vs_own_ref_median']:12.4f} "
          f"{eq['mitsuba']['rmse_vs_own_ref_median']:12.4f}")
    print(f"{'  rel. RMSE scaled to the budget, sqrt(t/T)':44} {eq['glossy']['rmse_at_budget_median']:12.4f} "
          f"{eq['mitsuba']['rmse_at_budget_median']:12.4f}")
    print(f"{'  glossy / Mitsuba rel. RMSE at the budget':44} "
          f"{eq['glossy']['rmse_at_budget_median'] / eq['mitsuba']['rmse_at_budget_median']:12.3f}")
    sc = r["scaling"]
    print(f"threads ({sc['spp']} spp), samples/s")
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
        if "mitsuba_raw_seconds" in v:
            print(f"{'  ' + str(t) + ' thread(s)':44} {v['mitsuba_pt_rays_per_s']:12.4g} {v['mitsuba_raw_rays_per_s']:12.4g} "
                  f"{100 * v['mitsuba_pt_over_raw']:7.1f}%")
    print(f"agreement of the converged images (Cook-Torrance {r['reference']['spp']} spp each, grey diffuse "
          f"{r['reference']['check_spp']} spp each): rel. RMSE Mitsuba vs glossy [noise floor]")
    for name, g in r["agreement"].items():
        ratio = ", ".join(f"{x:.4f}" for x in g["mean_ratio_sphere"])
        cells = ", ".join(f"{region} {g[region]:.2e} [{g['noise_floor_' + region]:.2e}]"
                          for region in ("all", "sphere", "background"))
        print(f"  {name:14} {cells}")
        print(f"  {'':14} mean over the sphere, Mitsuba / glossy (R, G, B): {ratio}")
    ref = r["reference"]
    print(f"  noise of the converged Cook-Torrance images themselves (rel. RMSE about their expectation, from "
          f"their halves): glossy {ref['glossy_noise_rel']:.2e}, Mitsuba {ref['mitsuba_noise_rel']:.2e}")
    print(f"\nwall time {r['wall_seconds']:.0f} s, load average {', '.join(f'{x:.2f}' for x in r['load_average'])}")


if __name__ == "__main__":
    main()
