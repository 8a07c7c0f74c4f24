# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""The column-collapse example runs in chunks until the pile is at rest: its result
does not depend on the chunk size. A coarse column for 200 steps (tmax falls
between steps 100 and 200) in chunks of 100 and of 200 steps gives the same
`result:` line and the same final state to 1e-12 of the largest value of each
column."""

import os
import tempfile

import gransph_run

EXAMPLE = os.path.join(gransph_run.TOP, "examples", "column_collapse", "in.column_collapse")
VARIABLES = {"dx": 0.04, "tmax": 0.015, "dump": 1}

check = gransph_run.Checks()
with tempfile.TemporaryDirectory() as tmp:
    results, states = [], []
    for chunk in (100, 200):
        out = gransph_run.run(EXAMPLE, {**VARIABLES, "chunk": chunk}, cwd=tmp)
        results.append(gransph_run.result_line(out))
        states.append(gransph_run.read_dump(os.path.join(tmp, "column_collapse.dump")))
        steps = results[-1][results[-1].index("steps") + 1]
        check(f"chunks of {chunk} steps end at step 200", steps == "200", " ".join(results[-1]))
    check("same result line", results[0] == results[1], " ".join(results[1]))
    diff = max(gransph_run.dump_differences(*states).values())
    check("same final state", diff < 1e-12,
          f"max difference / max value {diff:.1e} over {len(states[0]['id'])} grains")
check.finish()
