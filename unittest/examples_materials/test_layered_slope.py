# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""examples/layered_slope, reduced (a strip of 10 columns at dx = 0.02 m: 8 rows of the
sand of phi = 37 deg over 2 rows of the weak sand of phi = 25 deg over 2 rows of the
sand again, to 0.4 s): it holds at 23 degrees and slides at 27 along the weak layer,
the sand below holding and the sand above riding on it as a block (sheared far less
than the weak layer); without the weak layer it holds at 27 degrees. Drucker-Prager
matched in simple shear (the example's default), and with --phasechange the phase
change as well.

Arguments after the options are passed to LAMMPS (e.g. -k on t 1 -sf kk)."""

import argparse
import os
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "physics"))
import gransph_run  # noqa: E402

INPUT = os.path.join(gransph_run.TOP, "examples", "layered_slope", "in.layered_slope")
REDUCED = {"dx": 0.02, "upper": 8, "weak": 2, "below": 2, "columns": 10, "time": 0.4, "window": 0.1}


def result(variables, cwd, args):
    """the example's result line: the verdict and its numbers"""
    words = gransph_run.result_line(gransph_run.run(INPUT, {**REDUCED, **variables}, args=args,
                                                    cwd=cwd))
    return {"verdict": words[3], **gransph_run.result_numbers(words)}


def detail(r):
    return (f"{r['verdict']}: vx below {r['vx_below']:.4f}, weak {r['vx_weak']:.4f}, base "
            f"{r['vx_base']:.4f}, top {r['vx_top']:.4f} m/s; shear weak {r['shear_weak']:.3f}, "
            f"upper {r['shear_upper']:.3f} 1/s")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--phasechange", action="store_true", help="the phase change too")
    opts, args = parser.parse_known_args()
    models = ["elastoplastic"] + (["phasechange"] if opts.phasechange else [])
    check = gransph_run.Checks()
    with tempfile.TemporaryDirectory() as tmp:
        for model in models:
            held = result({"theta": 23, "model": model}, tmp, args)
            check(f"{model} 23 deg: holds", held["verdict"] == "holds" and abs(held["vx_top"]) < 0.01,
                  detail(held))
            slid = result({"theta": 27, "model": model}, tmp, args)
            check(f"{model} 27 deg: slides along the weak layer",
                  slid["verdict"] == "slides" and slid["vx_base"] > 0.04, detail(slid))
            check(f"{model} 27 deg: the sand below holds, the sand above rides as a block",
                  abs(slid["vx_below"]) < 0.1 * slid["vx_base"]
                  and abs(slid["shear_upper"]) < 0.25 * slid["shear_weak"], detail(slid))
            one = result({"theta": 27, "model": model, "weak_material": "none"}, tmp, args)
            check(f"{model} 27 deg: holds without the weak layer", abs(one["vx_top"]) < 0.01, detail(one))
    check.finish()


if __name__ == "__main__":
    main()
