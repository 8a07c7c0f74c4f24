# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""tools/research/validate's command line: each study a subcommand, and the command lines
of before the subcommands (the mode flags --quick, --convergence, --cfl C ..., which the
reports of validation/ record) read as the same subcommand with the same options. Runs
nothing: only the parsed options are compared. (ctest runs it with tools/lib on
PYTHONPATH, as the launcher tools/research/validate does.)"""

import sys

from gransph.validate import cli

# (the older command line, the subcommand's)
PAIRS = [
    ("--quick --ranks 1", "report --quick --ranks 1"),
    ("", "report"),
    ("--paper --kokkos", "report --paper --kokkos"),
    ("--convergence --plane --aspect 0.5 --ppr 10 15 --models elastoplastic --ranks 1",
     "convergence --plane --aspect 0.5 --ppr 10 15 --models elastoplastic --ranks 1"),
    ("--convergence --aspect 0.5 --ppr 8 12 --pair-options x --var normals=1 --label s",
     "convergence --aspect 0.5 --ppr 8 12 --pair-options x --var normals=1 --label s"),
    ("--basal-friction --fix-options y --label cfl03", "basal-friction --fix-options y --label cfl03"),
    ("--flume-convergence --dx 0.05 --deltas 20 rough --tend 1.5 --resume",
     "flume-convergence --dx 0.05 --deltas 20 rough --tend 1.5 --resume"),
    ("--cfl 0.2 0.3 --cfl-parts wave --ranks 1", "cfl 0.2 0.3 --cfl-parts wave --ranks 1"),
    ("--ranks 1 --cfl 0.2 --cfl-parts flume --replicas 2", "cfl 0.2 --cfl-parts flume --replicas 2 --ranks 1"),
    ("--cfl --cfl-parts column", "cfl --cfl-parts column"),
    ("--sphere-impact --heights 0.05 0.1 --per-diameter 4 5 --width 3 --label w",
     "sphere-impact --heights 0.05 0.1 --per-diameter 4 5 --width 3 --label w"),
    # no older command line: the options in either order
    ("erodible-bed --ranks 1 --slopes 0 22 --per-height 5 10",
     "erodible-bed --slopes 0 22 --per-height 5 10 --ranks 1"),
]


def main():
    failed = 0
    for old, new in PAIRS:
        a, b = vars(cli.options(old.split())), vars(cli.options(new.split()))
        ok = a == b
        failed += not ok
        print(f"{'ok  ' if ok else 'FAIL'} `{old}` == `{new}`" +
              ("" if ok else f": {sorted(set(a.items()) ^ set(b.items()), key=str)}"))
    studies = {cli.options(new.split()).study for _, new in PAIRS}
    if studies != set(cli.STUDIES):
        print(f"FAIL: not every study checked: {sorted(set(cli.STUDIES) - studies)}")
        failed += 1
    args = cli.options("cfl 0.3 0.1".split())
    if not (args.cfl == [0.3, 0.1] and args.cfl_parts == ["wave", "column", "flume"] and not args.convergence):
        print(f"FAIL: cfl's options: {vars(args)}")
        failed += 1
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
