"""Summarise a callgrind profile of glossy by what the instructions do (scripts/profile-glossy runs it).

callgrind attributes the instructions of inlined code to the file the code comes from (fi=/fe= records)
inside the function it was inlined into, so with -O3 -g the header a cost comes from tells what it is:
cmj_sampler.h the sampler, cook_torrance.h the BRDF, latlong.h the environment lookup, and so on.
Calls into libm (atan2, acos, sincos, exp, ...) are charged, with everything below them, to the code that
called them. Prints the top self costs (file:function) and the cost by category, in % of instructions.

With --perf it reads instead the text of `perf report --stdio --sort=dso,srcfile,sym -t '|'` (a cpu-clock
sampling profile: time, not instructions, so cache misses count) and prints the same categories.
Usage: profile_summary.py CALLGRIND_OUT [TOP]    or    profile_summary.py --perf PERF_REPORT_TXT [TOP]
"""

import collections
import re
import sys

CATEGORIES = [  # (category, regex on the file the instructions come from, or on the object)
    ("Embree traversal (libembree3)", r"libembree3"),
    ("sampler (cmj_sampler.*)", r"cmj_sampler\.(h|cpp)"),
    ("environment: lookup, pdf, sampling (latlong.*, environment.cpp, distribution.*, libmvec)",
     r"latlong\.(h|cpp)|environment\.cpp|distribution\.(cpp|h)|lane_math\.cpp|libmvec"),
    ("BRDF eval / sample / pdf (materials/models)",
     r"materials/models/|\b(cook_torrance|brdf_sample|brdf|fresnel|half_vector|vgroove|warp|lambertian)\.h"),
    ("ray/hit set-up around Embree (embree_scene.cpp)", r"embree_scene\.cpp"),
    ("camera rays (camera_rays.h)", r"camera_rays\.h"),
    ("shading frame (frame.h)", r"frame\.h"),
    ("path tracer loop, MIS, film (path_tracer.cpp)", r"path_tracer\.cpp"),
    ("TBB", r"tbb"),
]
LIBM = re.compile(r"libm\.so|/math/|sysdeps/ieee754|fenv_private")


# A sampling profile has no call graph here (libm has no frame pointers): its libm time is charged by
# function to the callers that callgrind finds for it on this scene (the environment's trigonometry is
# libmvec's, not libm's; tan: the camera; exp, log1p, sincos: the BRDF's sampling and evaluation).
LIBM_CALLERS = [
    (r"\btan|_tan", "camera rays (camera_rays.h)"),
    (r"exp|log1p|sincos|sin|cos", "BRDF eval / sample / pdf (materials/models)"),
]


def categorise(where, function):
    if LIBM.search(where):
        for pattern, category in LIBM_CALLERS:
            if re.search(pattern, function):
                return category + " [libm]"
        return "libm, other"
    if re.search(r"\[kernel|ld-linux|dl-", where):
        return "other: kernel, dynamic loader (start-up)"
    for name, pattern in CATEGORIES:
        if re.search(pattern, where):
            return name
    # glm and the standard library are inlined everywhere: charge them to the function they sit in.
    if not re.search(r"/work/|\.cpp\b", where) or re.search(r"glm/|c\+\+/", where):
        if "Environment" in function or "Distribution" in function:
            return CATEGORIES[2][0]
        if "EmbreeScene" in function:
            return CATEGORIES[4][0]
        if re.search(r"CookTorrance|mixturePdf|sampleMixture|glossy::sample\(|glossy::eval\(|glossy::pdf\(", function):
            return CATEGORIES[3][0]
        if "render(" in function or "PathTracer" in function:
            return "glm / std vector math in the path tracer"
    return "other"


def parse(path):
    names = {"fl": {}, "fn": {}, "ob": {}}
    self_cost = collections.Counter()       # (file, function) -> Ir
    calls_into_libm = collections.Counter()  # (caller file, caller function) -> inclusive Ir of libm calls
    total = 0
    fl = fi = fn = ob = cob = cfn = ""
    pending_call = False

    def name(kind, text):
        m = re.match(r"\((\d+)\)\s*(.*)", text)
        if not m:
            return text
        if m.group(2):
            names[kind][m.group(1)] = m.group(2)
        return names[kind].get(m.group(1), m.group(2))

    with open(path) as f:
        for line in f:
            line = line.rstrip("\n")
            if not line:
                continue
            c = line[0]
            if c.isdigit() or c in "+-*":
                parts = line.split()
                cost = int(parts[1]) if len(parts) > 1 else 0
                if pending_call:
                    pending_call = False
                    where = fi or fl
                    if LIBM.search(cob or "") and not LIBM.search(where + " " + ob):
                        calls_into_libm[(where, fn)] += cost
                    continue
                where = fi or fl
                self_cost[(where + " [" + ob + "]", fn)] += cost
                total += cost
                continue
            key, _, value = line.partition("=")
            if key == "fl":
                fl, fi = name("fl", value), ""
            elif key in ("fi", "fe"):
                fi = name("fl", value)
            elif key == "fn":
                fn, fi = name("fn", value), ""
            elif key == "ob":
                ob = name("ob", value)
            elif key == "cob":
                cob = name("ob", value)
            elif key == "cfn":
                cfn = name("fn", value)
            elif key == "cfi" or key == "cfl":
                name("fl", value)
            elif key == "calls":
                pending_call = True
                if not cob:
                    cob = ob
            if key not in ("calls", "cob", "cfn", "cfi", "cfl"):
                cob = ""
    return total, self_cost, calls_into_libm, cfn


def main_perf(path, top):
    rows = []
    for line in open(path):
        parts = [p.strip() for p in line.split("|")]
        if len(parts) < 4 or not parts[0].endswith("%"):
            continue
        share = float(parts[0].rstrip("%"))
        dso, srcfile, sym = parts[1], parts[2], re.sub(r"^\[[.k]\]\s*", "", parts[3])
        rows.append((share, dso, srcfile, sym))
    total = sum(r[0] for r in rows)
    print(f"{total:.1f}% of the samples attributed\n")
    print(f"top {top} (source file of the sampled instruction : function it is inlined into)")
    for share, dso, srcfile, sym in sorted(rows, reverse=True)[:top]:
        print(f"  {share:6.2f}%  {srcfile or dso} : {sym[:110]}")
    by_category, libm = collections.Counter(), collections.Counter()
    for share, dso, srcfile, sym in rows:
        category = categorise(f"{srcfile} {dso}", sym)
        if category.endswith(" [libm]"):
            category = category[: -len(" [libm]")]
            libm[category] += share
        by_category[category] += share
    print("\nby category (libm time charged by function to its callers, as callgrind finds them)")
    for k, v in by_category.most_common():
        extra = f"   (of which libm {libm[k]:.1f}%)" if libm[k] else ""
        print(f"  {v:6.2f}%  {k}{extra}")


def main():
    if sys.argv[1] == "--perf":
        return main_perf(sys.argv[2], int(sys.argv[3]) if len(sys.argv) > 3 else 25)
    path = sys.argv[1]
    top = int(sys.argv[2]) if len(sys.argv) > 2 else 25
    total, self_cost, libm_calls, _ = parse(path)
    print(f"{total:,} instructions in the profiled region\n")
    print(f"top {top} self costs (file of the instructions : function they are inlined into)")
    for (where, fn), cost in self_cost.most_common(top):
        file, _, obj = where.partition(" [")
        print(f"  {100.0 * cost / total:6.2f}%  {file if file != '???' else obj.rstrip(']')} : {fn[:110]}")

    by_category = collections.Counter()
    libm_total = 0
    for (where, fn), cost in self_cost.items():
        if LIBM.search(where):
            libm_total += cost
            continue
        by_category[categorise(where, fn)] += cost
    charged = 0
    for (where, fn), cost in libm_calls.items():
        by_category[categorise(where, fn) + " (incl. its libm calls)"] += cost
        charged += cost
    if libm_total > charged:
        by_category["libm, caller not resolved"] += libm_total - charged
    print("\nby category (libm calls charged to their callers)")
    merged = collections.Counter()
    for k, v in by_category.items():
        merged[k.replace(" (incl. its libm calls)", "")] += v
    libm_share = collections.Counter()
    for k, v in by_category.items():
        if k.endswith(" (incl. its libm calls)"):
            libm_share[k.replace(" (incl. its libm calls)", "")] += v
    for k, v in merged.most_common():
        if v < 1e-4 * total:
            continue
        extra = f"   (of which libm {100.0 * libm_share[k] / total:.1f}%)" if libm_share[k] else ""
        print(f"  {100.0 * v / total:6.2f}%  {k}{extra}")


if __name__ == "__main__":
    main()
