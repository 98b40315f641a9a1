#!/usr/bin/env python3
"""The product's folders form layers (CTest: Layers.Includes).

README.md's layout table states the order once: its rows go from the base up, and a folder's code includes
only headers of its own folder and of the folders before it (rows above; within a row, names to the left).
This test reads that order from the table and walks every `#include` of every C++ source under materials/
and renderer/. It fails on
  - an include of a folder placed after the includer's (an edge against the order; any folder cycle has one),
  - a glossy header included by a bare name, or from outside materials/ and renderer/ (such an edge could
    not be checked),
  - a folder holding sources that the table does not place, or a folder the table names that does not exist,
and prints the folder cycles it finds, with the includes that make each edge.
"""
import argparse
import re
import sys
from collections import defaultdict
from pathlib import Path

PRODUCT = ("materials", "renderer")
SOURCE_SUFFIXES = {".h", ".hpp", ".cpp", ".cc", ".inl"}
INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^>"]+)[>"]')


def layer_order(readme):
    """The product folders in the layout table's order: `renderer/scene/`, `camera/` in one cell is
    renderer/scene then renderer/camera (a bare name is a folder of the last full path's top folder)."""
    lines = readme.read_text(encoding="utf-8").splitlines()
    if "## Layout" not in lines:
        return []
    start = lines.index("## Layout")
    order = []
    for line in lines[start + 1:]:
        if line.startswith("## "):
            break
        if not line.startswith("| `"):
            continue
        top = None
        for name in re.findall(r"`([^`]+)`", line.split("|")[1]):
            if not name.endswith("/"):
                continue
            parts = name.rstrip("/").split("/")
            if parts[0] in PRODUCT:
                top = parts[0]
                order.append("/".join(parts))
            elif top is not None:
                order.append(top + "/" + "/".join(parts))
    return order


def includes(root):
    """(source folder, included folder, where) for every include of a glossy header; and the problems found
    on the way (bare or outside includes)."""
    edges, problems = [], []
    for top in PRODUCT:
        for path in sorted((root / top).rglob("*")):
            if path.suffix not in SOURCE_SUFFIXES or not path.is_file():
                continue
            source = path.relative_to(root)
            for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
                m = INCLUDE.match(line)
                if not m:
                    continue
                quote, name = m.groups()
                where = f"{source}:{number}: {name}"
                if "/" not in name:
                    if quote == '"':
                        problems.append(f"{where}: a glossy header by a bare name (include it by its path from the top)")
                    continue
                target = Path(name)
                if target.parts[0] in PRODUCT:
                    edges.append((str(source.parent), str(target.parent), where))
                elif quote == '"':
                    problems.append(f"{where}: product code includes a header outside {' and '.join(PRODUCT)}")
    return edges, problems


def cycles(edges):
    """The strongly connected components of more than one folder (Tarjan), each sorted."""
    graph = defaultdict(set)
    for a, b, _ in edges:
        if a != b:
            graph[a].add(b)
    index, low, stack, on_stack, found = {}, {}, [], set(), []

    def visit(v):
        index[v] = low[v] = len(index)
        stack.append(v)
        on_stack.add(v)
        for w in sorted(graph[v]):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                found.append(sorted(component))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return found


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--source-dir", type=Path, required=True, help="the tree whose sources are checked")
    p.add_argument("--readme", type=Path, help="the README.md whose layout table gives the order (default: the tree's)")
    a = p.parse_args()
    root = a.source_dir.resolve()
    order = layer_order(a.readme or root / "README.md")
    failures = []
    if len(order) < 2:
        failures.append("README.md: no layout table placing the folders of materials/ and renderer/ (## Layout)")
    rank = {folder: i for i, folder in enumerate(order)}
    for folder in sorted({f for f in order if order.count(f) > 1}):
        failures.append(f"README.md's layout table places {folder}/ more than once")
    for folder in order:
        if not (root / folder).is_dir():
            failures.append(f"README.md's layout table places {folder}/, which does not exist")
    source_folders = {str(path.parent.relative_to(root)) for top in PRODUCT for path in (root / top).rglob("*")
                      if path.suffix in SOURCE_SUFFIXES and path.is_file()}
    for folder in sorted(source_folders - rank.keys()):
        failures.append(f"{folder}/ holds sources, but README.md's layout table does not place it")

    edges, problems = includes(root)
    failures += problems
    by_edge = defaultdict(list)
    for a_folder, b_folder, where in edges:
        if a_folder != b_folder:
            by_edge[a_folder, b_folder].append(where)
    for (a_folder, b_folder), wheres in sorted(by_edge.items()):
        # A folder missing from the table is reported above; an include of a missing header, by the compiler.
        if a_folder in rank and b_folder in rank and rank[b_folder] > rank[a_folder]:
            failures.append(f"{a_folder} -> {b_folder} goes up the layers (README.md places {b_folder}/ after "
                            f"{a_folder}/): " + "; ".join(wheres))

    for component in cycles(edges):
        print("folder cycle: " + " <-> ".join(component))
        for a_folder in component:
            for b_folder in component:
                if (a_folder, b_folder) in by_edge:
                    print(f"  {a_folder} -> {b_folder}: " + "; ".join(by_edge[a_folder, b_folder]))
    print(f"{len(source_folders)} folders, {len(by_edge)} folder edges from {len(edges)} includes; layer order: "
          + " < ".join(order))
    for f in failures:
        print("FAIL " + f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
