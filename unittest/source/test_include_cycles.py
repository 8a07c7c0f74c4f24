# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""No include cycle among GRANSPH's sources: a module (x.h with its x.cpp) may not include,
directly or through others, a header whose module includes it back. Reads the #include
lines of src/GRANSPH; exits 1 naming each cycle.

    python3 test_include_cycles.py [SOURCE_DIR]
"""

import os
import re
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


def module_graph(src):
    """{module: set of modules whose headers it includes}, over the files in src."""
    files = [f for f in os.listdir(src) if f.endswith((".h", ".cpp"))]
    modules = {os.path.splitext(f)[0] for f in files}
    graph = {m: set() for m in modules}
    for f in files:
        with open(os.path.join(src, f), encoding="utf-8") as text:
            for header in INCLUDE.findall(text.read()):
                target = os.path.splitext(os.path.basename(header))[0]
                module = os.path.splitext(f)[0]
                if target in modules and target != module:
                    graph[module].add(target)
    return graph


def cycles(graph):
    """Each cycle once, as a list of modules from its smallest name."""
    found, state, path = set(), {}, []

    def visit(m):
        state[m] = "open"
        path.append(m)
        for n in sorted(graph[m]):
            if state.get(n) == "open":
                cycle = path[path.index(n):]
                start = cycle.index(min(cycle))
                found.add(tuple(cycle[start:] + cycle[:start]))
            elif n not in state:
                visit(n)
        path.pop()
        state[m] = "done"

    for m in sorted(graph):
        if m not in state:
            visit(m)
    return sorted(found)


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    src = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "..", "src", "GRANSPH")
    graph = module_graph(src)
    edges = sum(len(v) for v in graph.values())
    if edges == 0:
        print(f"no includes between modules found in {src}: nothing was checked")
        return 1
    found = cycles(graph)
    for cycle in found:
        print("include cycle: " + " -> ".join(cycle + (cycle[0],)))
    print(f"{len(graph)} modules, {edges} includes between them, {len(found)} cycles")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
