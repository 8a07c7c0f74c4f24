"""examples/sphere_impact runs: a steel ball of fix rigid dropped into the sand bed at a
coarse resolution (D / 6) enters the bed, is stopped by the grains (the run ends at its
deepest point, -var stop deepest) and prints its result line; the same run on 2 MPI ranks
gives the same state. A bad `stop` is refused with a message.

Arguments are passed to LAMMPS (e.g. -k on t 1 -sf kk): every run then takes them, and
the state of the first also equals the plain styles'."""

import os
import sys
import tempfile

import gransph_run

ARGS = sys.argv[1:]
EXAMPLE = os.path.join(gransph_run.TOP, "examples", "sphere_impact", "in.sphere_impact")
D = 0.0254
VARIABLES = {"dx": D / 6, "h": 0.1, "stop": "deepest", "dump": 1}

check = gransph_run.Checks()
states, results = {}, {}
with tempfile.TemporaryDirectory() as tmp:
    runs = [("1 rank", 1, ARGS), ("2 ranks", 2, ARGS)] + ([("plain", 1, [])] if ARGS else [])
    for label, ranks, args in runs:
        out = gransph_run.run(EXAMPLE, VARIABLES, ranks=ranks, args=args, cwd=tmp)
        results[label] = gransph_run.result_line(out)
        states[label] = gransph_run.read_dump(os.path.join(tmp, "sphere_impact.dump"))
    code, error = gransph_run.first_error(tmp, f"variable stop index sideways\n"
                                               f"include {EXAMPLE}\n", args=ARGS)

words = results["1 rank"]
d, v0, steps = (float(words[words.index(key) + 1]) for key in ("d", "v0", "steps"))
dx = D / 6
check("the ball entered the bed", 0.1 * dx < d < D, f"deepest {1e3 * d:.2f} mm, dx {1e3 * dx:.2f} mm")
check("the impact speed of a drop from 0.1 m", abs(v0 - (2 * 9.81 * (0.1 - 2 * dx)) ** 0.5) < 1e-3,
      f"{v0} m/s")
diffs = gransph_run.dump_differences(states["1 rank"], states["2 ranks"])
check("2 ranks = 1 rank (the dump's 10 digits)", max(diffs.values()) < 1e-8,
      f"largest relative difference {max(diffs.values()):.1e}")
step_2 = results["2 ranks"][results["2 ranks"].index("steps") + 1]
check("2 ranks stop at the same step", float(step_2) == steps, f"{step_2} and {steps:.0f}")
if ARGS:
    diffs = gransph_run.dump_differences(states["1 rank"], states["plain"])
    check(f"{' '.join(ARGS)} = plain (the dump's 10 digits)", max(diffs.values()) < 1e-8,
          f"largest relative difference {max(diffs.values()):.1e}")
check("a bad stop is refused", code != 0 and "stop is rest or deepest" in error, error)
check.finish()
