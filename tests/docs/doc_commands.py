#!/usr/bin/env python3
"""Every shell block of README.md and docs/*.md runs, verbatim, on a fresh clone (CTest: Docs.Commands and,
by label, Docs.LongCommands and Docs.ClusterCommands; docs/testing.md).

A fenced block's info string says what it is: ```sh is a shell block this test runs; ```sh docs-long one too
long for the default suite (label docs-long); ```sh cluster one that needs a running Slurm (label cluster);
```sh suite the set-up and the test suite themselves (./scripts/test, ctest), whose run is the one this test
is part of, so never run here. ```console (a command with its output), ```text, ```python, ```toml, ```json
are not shell blocks: the Python ones run in tests/python/test_docs.py. A fence without an info string is an
error, so that no shell block is left out unnoticed. A block of one of those languages whose info string
names a file of the tree (```toml scenes/studies/example.toml) shows that file: it must be the file's text,
line for line, so that the shell blocks that run the file run what the page shows.

Each page runs in a fresh copy of the source tree (the files git tracks, plus new ones it does not ignore),
with the build tree as its build/ and the shared data beside it as ../shared, in one bash process, block
after block in the page's order, each from the top of the tree, under `set -eo pipefail`: a failing command
fails the test, naming the page's line. The environment is a new user's on Debian: the default PATH (for a
page other than the README with build/renderer first, the README's install step), a new HOME, no GLOSSY_*
variable. A block of the label runs after the page's default blocks before it, which may make its inputs.
Exit status 77 (a skip) when no page has a block the label runs, or, for cluster, when no Slurm answers.
"""
import argparse
import os
import re
import resource
import shutil
import subprocess
import sys
import time
from pathlib import Path

FENCE = re.compile(r"^(\s*)```(.*)$")
SHELL_TAGS = {"": "default", "docs-long": "docs-long", "cluster": "cluster", "suite": "suite"}
NOT_SHELL = {"console", "text", "python", "toml", "json"}
DEBIAN_PATH = "/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin"


class Block:
    def __init__(self, page, line, info, lines):
        self.page, self.line, self.info, self.lines = page, line, info, lines  # line: the first line inside


def blocks_of(page, text):
    """Every fenced block of a Markdown page: (info string, first line number, its lines)."""
    out, open_at, info, body = [], None, None, []
    for number, line in enumerate(text.splitlines(), 1):
        m = FENCE.match(line)
        if m and open_at is None:
            open_at, info, body, indent = number, m.group(2).strip(), [], len(m.group(1))
        elif m and open_at is not None and not m.group(2).strip():
            out.append(Block(page, open_at + 1, info, body))
            open_at = None
        elif open_at is not None:
            body.append(line[indent:] if line[:indent].isspace() else line)
    if open_at is not None:
        raise SystemExit(f"{page}:{open_at}: a fence is never closed")
    return out


def kind_of(block):
    """'default', 'docs-long', 'cluster', 'suite' for a shell block; None for any other."""
    words = block.info.split()
    if not words:
        raise ValueError(f"{block.page}:{block.line - 1}: a fence without an info string: say ```sh for a shell "
                         f"block, ```console for a command with its output, or the language")
    if words[0] in NOT_SHELL:
        return None
    if words[0] != "sh" or " ".join(words[1:]) not in SHELL_TAGS:
        raise ValueError(f"{block.page}:{block.line - 1}: unknown info string '{block.info}' "
                         f"(sh, sh docs-long, sh cluster, sh suite, {', '.join(sorted(NOT_SHELL))})")
    return SHELL_TAGS[" ".join(words[1:])]


def shown_file_error(source, block):
    """Why a block that names the file it shows (```toml PATH) is not that file's text, or None."""
    words = block.info.split()
    if len(words) != 2 or words[0] not in NOT_SHELL:
        return None
    path = source / words[1]
    if not path.is_file():
        return f"{block.page}:{block.line - 1}: the block shows {words[1]}, which is not a file of the tree"
    text = path.read_text().splitlines()
    for i, (shown, real) in enumerate(zip(block.lines, text)):
        if shown != real:
            return f"{block.page}:{block.line + i}: the block differs from {words[1]}:{i + 1} ('{real}')"
    if len(block.lines) != len(text):
        return f"{block.page}:{block.line}: the block has {len(block.lines)} lines, {words[1]} {len(text)}"
    return None


def source_files(source):
    try:
        listed = subprocess.run(["git", "-C", str(source), "ls-files", "-z", "--cached", "--others", "--exclude-standard"],
                                check=True, capture_output=True).stdout
        return [p for p in listed.decode().split("\0") if p]
    except (OSError, subprocess.CalledProcessError):
        files = []
        for root, dirs, names in os.walk(source):
            rel = Path(root).relative_to(source)
            dirs[:] = [d for d in dirs if not (str(rel) == "." and (d.startswith("build") or d in {"out", ".git"}))]
            files += [str(rel / n) for n in names]
        return files


def fresh_clone(source, build, shared, into):
    """A copy of the source tree as a clone has it, build/ the build tree, ../shared the shared data."""
    if into.exists():
        shutil.rmtree(into)
    clone = into / "glossy"
    for rel in source_files(source):
        src, dst = source / rel, clone / rel
        if not (src.is_file() or src.is_symlink()) or rel.startswith("build/") or rel == "build":
            continue
        dst.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(src, dst, follow_symlinks=False)
    (clone / "build").symlink_to(build)
    if shared.is_dir():
        (into / "shared").symlink_to(shared.resolve())
    (into / "home").mkdir()
    (into / "tmp").mkdir()
    return clone


def page_script(blocks, timing):
    """The bash script of a page's blocks and, per script line, the page line it came from."""
    lines, origin = ["set -eo pipefail",
                     "trap 'echo \"doc-commands: line $LINENO failed (status $?)\" >&2' ERR",
                     f"exec 3>{shq(timing)}"], [None, None, None]
    for b in blocks:
        lines += [f"cd {shq('$CLONE')}".replace("'$CLONE'", '"$GLOSSY_DOC_CLONE"'),
                  f"echo \"{b.line} $(date +%s.%N)\" >&3"]
        origin += [None, None]
        for i, text in enumerate(b.lines):
            lines.append(text)
            origin.append(f"{b.page}:{b.line + i}")
    lines.append("echo \"end $(date +%s.%N)\" >&3")
    return "\n".join(lines) + "\n", origin


def shq(s):
    return "'" + str(s).replace("'", "'\\''") + "'"


def slurm_answers():
    try:
        return subprocess.run(["sinfo"], capture_output=True, timeout=30).returncode == 0
    except (OSError, subprocess.TimeoutExpired):
        return False


def run_page(page, blocks, args, label):
    work = Path(args.work) / page.replace("/", "_").removesuffix(".md")
    shared = Path(os.environ.get("GLOSSY_SHARED_DIR") or args.shared_dir)
    clone = fresh_clone(Path(args.source_dir), Path(args.build_dir).resolve(), shared, work)
    script, origin = page_script(blocks, work / "timing")
    (work / "commands.sh").write_text(script)
    env = {"PATH": DEBIAN_PATH if page == "README.md" else f"{clone}/build/renderer:{DEBIAN_PATH}",
           "HOME": str(work / "home"), "TMPDIR": str(work / "tmp"), "LANG": "C.UTF-8", "TERM": "dumb",
           "USER": os.environ.get("USER", "root"), "GLOSSY_DOC_CLONE": str(clone)}
    for keep in ["ASAN_OPTIONS", "UBSAN_OPTIONS", "LSAN_OPTIONS", "LD_PRELOAD"]:
        if keep in os.environ:
            env[keep] = os.environ[keep]
    start, cpu_start = time.monotonic(), resource.getrusage(resource.RUSAGE_CHILDREN)
    with open(work / "log", "w") as log:
        done = subprocess.run(["bash", str(work / "commands.sh")], cwd=clone, env=env, stdout=log,
                              stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL)
    seconds, cpu_end = time.monotonic() - start, resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = cpu_end.ru_utime + cpu_end.ru_stime - cpu_start.ru_utime - cpu_start.ru_stime
    output = (work / "log").read_text(errors="replace")
    if label == "cluster":
        jobs = re.findall(r"^(?:array|merge) (\d+)$", output, flags=re.M)
        if jobs:
            subprocess.run(["scancel", *jobs], capture_output=True)
    times = []
    marks = [l.split() for l in (work / "timing").read_text().splitlines()] if (work / "timing").exists() else []
    for (line, t0), (_, t1) in zip(marks, marks[1:]):
        times.append(f"{page}:{line} {float(t1) - float(t0):.1f} s")
    if done.returncode == 0:
        print(f"ok   {page}: {len(blocks)} block(s) in {seconds:.1f} s, {cpu:.0f} CPU-s ({'; '.join(times)})")
        shutil.rmtree(work, ignore_errors=True)
        return True
    m = re.findall(r"doc-commands: line (\d+) failed \(status (\d+)\)", output)
    where = origin[int(m[-1][0]) - 1] if m and int(m[-1][0]) - 1 < len(origin) else None
    print(f"FAIL {page}: exit status {done.returncode}" + (f" at {where}" if where else "") + f" after {seconds:.1f} s")
    tail = output.splitlines()[-40:]
    print("  " + "\n  ".join(tail))
    print(f"  (the page's script and whole log: {work}/commands.sh, {work}/log)")
    return False


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--label", choices=["default", "docs-long", "cluster"], default="default")
    p.add_argument("--source-dir", required=True)
    p.add_argument("--build-dir", required=True)
    p.add_argument("--shared-dir", required=True)
    p.add_argument("--work", required=True)
    p.add_argument("--list", action="store_true", help="print the blocks each label runs, run nothing")
    p.add_argument("pages", nargs="*", help="pages relative to the source tree (default: README.md, docs/*.md)")
    args = p.parse_args()
    source = Path(args.source_dir)
    pages = args.pages or ["README.md"] + sorted(str(f.relative_to(source)) for f in (source / "docs").glob("*.md"))

    plan, errors = [], []
    for page in pages:
        try:
            blocks = [(b, kind_of(b)) for b in blocks_of(page, (source / page).read_text())]
        except ValueError as e:
            errors.append(str(e))
            continue
        errors += [e for e in (shown_file_error(source, b) for b, _ in blocks) if e]
        wanted = {"default"} | ({args.label} if args.label != "default" else set())
        run = [b for b, k in blocks if k in wanted]
        if args.list:
            for b, k in blocks:
                if k:
                    print(f"{page}:{b.line} {k}: {b.lines[0] if b.lines else ''}")
        # A labelled run covers the pages with a block of its label (after their default blocks).
        if run and (args.label == "default" or any(k == args.label for _, k in blocks)):
            plan.append((page, run))
    for e in errors:
        print(f"FAIL {e}")
    if errors or args.list:
        return 1 if errors else 0
    if not plan:
        print(f"Docs: skipped: no page has a block labelled {args.label}")
        return 77
    if args.label == "cluster" and not slurm_answers():
        print("Docs: skipped: no Slurm answers here (sinfo failed): the cluster blocks need a running Slurm")
        return 77
    start = time.monotonic()
    results = [run_page(page, blocks, args, args.label) for page, blocks in plan]
    print(f"{sum(results)} of {len(results)} pages ran every {args.label} block in {time.monotonic() - start:.0f} s")
    return 0 if all(results) else 1


if __name__ == "__main__":
    sys.exit(main())
