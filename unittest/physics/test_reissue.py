# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""Re-issuing a GRANSPH style starts from its defaults: examples/column_collapse with
pair_style sph/granular (and the integrator fix) issued first with other options and then
as the example issues it runs bit for bit as the example alone, with both models, plain
and /kk. The other options must change the run: the same input with the first line only
is checked to differ, so that the comparison can fail."""

import os
import re
import tempfile

import numpy as np

import gransph_run

EXAMPLE = os.path.join(gransph_run.TOP, "examples", "column_collapse", "in.column_collapse")
PAIR_OTHER = ("pair_style      sph/granular ${h} visc 1 1 visc/sound paper visc/walls yes "
              "gradient corrected wall/gradient normal wall/stress paper precision mixed prune 0 "
              "wall/friction floor 20 wall/friction/hold stick\n")
FIX_OTHER = {
    "elastoplastic": "fix             sph sand sph/elastoplastic ${matfile} ${material} walls floor "
                     "cfl 0.1 cfl/sound local predictor extrapolated matching simple_shear "
                     "plastic paper rho 2000\n",
    "phasechange": "fix             sph sand sph/phasechange ${matfile} ${material} walls floor "
                   "cfl 0.1 cfl/sound local predictor extrapolated rho 2000\n",
}
KOKKOS = ["-k", "on", "t", "2", "-sf", "kk"]
# normals: the floor's dummies carry their wall normal, which wall/friction needs
VARIABLES = {"steps": 200, "dump": 1, "dx": 0.025, "normals": 1}


def with_line_before(text, pattern, line):
    """text with `line` inserted before the first line that matches pattern."""
    match = re.search(pattern, text, re.M)
    assert match, f"no line matches {pattern}"
    return text[:match.start()] + line + text[match.start():]


def run(tmp, name, text, model, args):
    """Run input text as `name`; its thermo lines and final dump."""
    path = os.path.join(tmp, name)
    with open(path, "w") as f:
        f.write(text)
    out = gransph_run.run(path, {**VARIABLES, "model": model}, args=args, cwd=tmp)
    thermo = [l for l in out.splitlines() if re.match(r"\s+\d+\s+[-\d.e+]+\s", l)]
    assert thermo, "no thermo lines"
    return thermo, gransph_run.read_dump(os.path.join(tmp, "column_collapse.dump"))


def same(a, b):
    return a[0] == b[0] and all(np.array_equal(a[1][k], b[1][k]) for k in a[1])


def main():
    check = gransph_run.Checks()
    with open(EXAMPLE) as f:
        example = f.read()
    pair_line = r"^pair_style\s+sph/granular"
    fix_line = r"^fix\s+sph\s"
    with tempfile.TemporaryDirectory() as tmp:
        for model in ("elastoplastic", "phasechange"):
            for label, args in (("plain", []), ("kk", KOKKOS)):
                alone = run(tmp, "in.alone", example, model, args)
                reissued = with_line_before(with_line_before(example, pair_line, PAIR_OTHER),
                                            fix_line, FIX_OTHER[model])
                # the other options alone (the example's own lines taken out) change the run
                other = re.sub(pair_line + r".*\n", PAIR_OTHER, example, count=1, flags=re.M)
                other = re.sub(fix_line + r".*\n", FIX_OTHER[model], other, count=1, flags=re.M)
                again = run(tmp, "in.reissued", reissued, model, args)
                compared = f"{len(alone[0])} thermo lines and {len(alone[1]['id'])} grains compared bit for bit"
                check(f"{model} {label}: pair_style and fix issued twice = once", same(alone, again),
                      compared if same(alone, again) else compared + ": they differ")
                differ = run(tmp, "in.other", other, model, args)
                check(f"{model} {label}: the first lines alone change the run", not same(alone, differ),
                      "so that the comparison above can fail")
    check.finish()


if __name__ == "__main__":
    main()
