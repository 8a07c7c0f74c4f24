# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""examples/erodible_bed, reduced (h0/dx = 10): a column released on a 22 degree slope
onto an erodible layer of the same sand (a second material, e/h0 = 0.2) runs out and
sets bed grains moving; on a level floor it runs out less far and moves next to none
of the bed; the result line's numbers agree with each other (the mass of the bed moved
and its ratio to the column's, the counts). A few hundred steps with a dump: the grains
carry their materials (compute sph/material/atom: 1 the column, 2 the bed), and 2 MPI
ranks give the state of 1; with `under 0` and a bed of another material (Sand25 of
potentials/sand25.gransph) the example runs too.

Arguments are passed to LAMMPS (e.g. -k on t 1 -sf kk): every run then takes them, and
the state of the short run also equals the plain styles'."""

import os
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "physics"))
import gransph_run  # noqa: E402

ARGS = sys.argv[1:]
INPUT = os.path.join(gransph_run.TOP, "examples", "erodible_bed", "in.erodible_bed")
H0, DX = 0.14, 0.014
REDUCED = {"dx": DX, "e": 2 * DX, "length": 0.9, "tmax": 2.5}


def result(variables, cwd, ranks=1, args=ARGS):
    """the example's result line as a dict of its numbers"""
    return gransph_run.result_numbers(gransph_run.result_line(
        gransph_run.run(INPUT, variables, ranks=ranks, args=args, cwd=cwd)))


def main():
    check = gransph_run.Checks()
    with tempfile.TemporaryDirectory() as tmp:
        slope = result({**REDUCED, "theta": 22}, tmp)
        flat = result({**REDUCED, "theta": 0}, tmp)
        for label, r in (("22 deg", slope), ("level", flat)):
            grain = 2450 * DX ** 2
            check(f"{label}: the bed's mass moved = its grains' mass",
                  abs(r["bed_moved"] - r["moved_grains"] * grain) < 1e-3 * grain + 1e-9
                  and abs(r["ratio"] * r["column_mass"] - r["bed_moved"]) < 1e-3 * r["column_mass"],
                  f"bed_moved {r['bed_moved']:.3f} kg/m, {r['moved_grains']:.0f} grains, ratio {r['ratio']:.4f}")
            check(f"{label}: the front is ahead of the foot, x95 behind the outermost grain",
                  0 < r["runout"] <= r["outermost"] + 1e-9 and r["x95"] <= r["outermost"] + 1e-9,
                  f"runout {r['runout']:.3f} m, x95 {r['x95']:.3f} m, outermost {r['outermost']:.3f} m")
        check("22 deg: the flow sets bed grains moving (more than 2% of the column's mass)",
              slope["ratio"] > 0.02, f"{slope['bed_moved']:.2f} kg/m, ratio {slope['ratio']:.3f}")
        check("22 deg: the mass runs out beyond 1.5 h0", slope["runout"] > 1.5 * H0,
              f"runout {slope['runout'] / H0:.2f} h0")
        check("level: next to none of the bed moves (under 1% of the column's mass)",
              flat["ratio"] < 0.01, f"ratio {flat['ratio']:.4f}")
        check("level: it runs out less far than on the slope", flat["runout"] < 0.5 * slope["runout"],
              f"runout {flat['runout'] / H0:.2f} h0 against {slope['runout'] / H0:.2f} h0")
        check("each stopped at rest before tmax", slope["t"] < REDUCED["tmax"] and flat["t"] < REDUCED["tmax"],
              f"t {slope['t']:.3f} s and {flat['t']:.3f} s")

        # a short run's state: materials, ranks, and the styles of ARGS against the plain ones
        short = {**REDUCED, "theta": 22, "steps": 300, "dump": 1}
        states = {}
        runs = [("1 rank", 1, ARGS), ("2 ranks", 2, ARGS)] + ([("plain", 1, [])] if ARGS else [])
        kokkos = False
        for label, ranks, args in runs:
            result(short, tmp, ranks=ranks, args=args)
            states[label] = gransph_run.read_dump(os.path.join(tmp, "erodible_bed.dump"))
            kokkos = kokkos or (label == "1 rank" and "sph/granular/kk" in gransph_run.LAST_OUTPUT)
        one = states["1 rank"]
        material = one["c_material"].astype(int)
        column = int(np.sum(material == 1))
        check("the grains carry their materials (1 the column, 2 the bed)",
              set(material) == {1, 2} and np.all((one["type"] == 1) == (material == 1))
              and np.all((one["type"] == 3) == (material == 2)),
              f"{column} of material 1, {int(np.sum(material == 2))} of material 2")
        moved = float(np.max(np.abs(one["vx"])))
        diffs = gransph_run.dump_differences(one, states["2 ranks"])
        worst = max(diffs, key=diffs.get)
        check("2 ranks = 1 rank (the dump's 10 digits)", moved > 1e-3 and diffs[worst] < 1e-8,
              f"worst {worst} {diffs[worst]:.2e}, max |vx| {moved:.3g} m/s")
        if ARGS:
            check("the /kk styles ran", kokkos or "-sf" not in ARGS, " ".join(ARGS))
            diffs = gransph_run.dump_differences(one, states["plain"])
            worst = max(diffs, key=diffs.get)
            check(f"{' '.join(ARGS)} = plain (the dump's 10 digits)", diffs[worst] < 1e-8,
                  f"worst {worst} {diffs[worst]:.2e}")

        # the column on the floor behind the layer's end, and a bed of another material
        sand25 = os.path.join(gransph_run.TOP, "potentials", "sand25.gransph")
        r = result({**REDUCED, "under": 0, "bed_matfile": sand25, "bed_material": "Sand25",
                    "steps": 100, "dump": 1}, tmp)
        other = gransph_run.read_dump(os.path.join(tmp, "erodible_bed.dump"))
        check("under 0, a bed of Sand25: runs, its grains of material 2",
              np.all((other["type"] == 3) == (other["c_material"] == 2)) and r["steps"] == 100,
              f"{int(np.sum(other['c_material'] == 2))} grains of material 2")
    check.finish()


if __name__ == "__main__":
    main()
