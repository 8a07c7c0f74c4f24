# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""GRANSPH from Python: the README's sand column collapsing on a floor of dummy particles,
run through the LAMMPS Python module, with the grains' stress, the force of the grains on
the floor and the deposit's edge read into numpy by the module's own extract functions
(no dump, no log parsing), plotted with matplotlib and saved for a check.

    tools/python examples/python/column_stress.py [--steps 8000] [--chunk 200] [--out DIR]

tools/python puts the LAMMPS module, liblammps.so, the plugin and potentials/ on their
paths. Writes into DIR (default: the current folder) column_stress.png, the LAMMPS log
log.column_stress and column_stress.npz (what was extracted), and prints a result line.
"""

import argparse
import os

import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
from lammps import lammps, LMP_STYLE_ATOM, LMP_STYLE_GLOBAL, LMP_TYPE_ARRAY, LMP_TYPE_VECTOR

# The README's minimal input (a column of radius 0.2 m and height 0.1 m, dx 0.02 m), with
# the force of the grains on the floor (compute sph/wallforce, normal into the floor).
# The thermo line prints what the script reads, so that a run's log can be checked against
# it (unittest/physics/test_python_example.py): the floor's force, the deposit's edge and
# the sums and extremes of the integrator's per-atom array f_sph over the grains.
INPUT = """
plugin load     gransphplugin.so
units           si
atom_style      atomic
boundary        f f f
comm_modify     vel yes
region          box block -0.4 0.4 -0.4 0.4 -0.08 0.14 units box
create_box      2 box
lattice         sc 0.02 origin 0.5 0.5 0.5
region          column cylinder z 0 0 0.2 0 0.1 units box
region          floor cylinder z 0 0 0.4 -0.06 0 units box
create_atoms    1 region column
create_atoms    2 region floor
group           sand type 1
group           floor type 2
mass            * $(2450*0.02^3)
pair_style      sph/granular 0.024
pair_coeff      * *
neighbor        0.004 bin
neigh_modify    exclude type 2 2
fix             gravity sand gravity 9.81 vector 0 0 -1
fix             sph sand sph/elastoplastic sand.gransph Chen2019 walls floor
compute         floor floor sph/wallforce 0 0 -1
compute         deposit sand sph/runout 0 0 0.2 0.02
compute         sums sand reduce sum f_sph[1] f_sph[2] f_sph[3] f_sph[4] f_sph[5] f_sph[6] f_sph[7] f_sph[8]
compute         lows sand reduce min f_sph[2] f_sph[3] f_sph[4]
thermo_style    custom step time c_floor[1] c_floor[2] c_floor[3] c_floor[4] c_deposit[1] c_deposit[6] &
                c_sums[1] c_sums[2] c_sums[3] c_sums[4] c_sums[5] c_sums[6] c_sums[7] c_sums[8] &
                c_lows[1] c_lows[2] c_lows[3]
thermo_modify   format float %.17g
"""


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--steps", type=int, default=8000, help="steps in all (default 8000)")
    parser.add_argument("--chunk", type=int, default=200,
                        help="steps between two readings of the floor force (default 200)")
    parser.add_argument("--out", default=".", help="folder for the png, log and npz")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)

    lmp = lammps(cmdargs=["-log", os.path.join(args.out, "log.column_stress"), "-screen", "none"])
    lmp.commands_string(INPUT)
    lmp.command(f"thermo {args.chunk}")

    steps, times, floor, deposit = [], [], [], []
    for _ in range(args.steps // args.chunk):
        lmp.command(f"run {args.chunk}")
        steps.append(lmp.extract_global("ntimestep"))
        times.append(lmp.get_thermo("time"))
        # global vectors of the computes: (Fx, Fy, Fz, F_W) and the deposit's six values;
        # copied, since the numpy arrays view LAMMPS' memory, which the next run changes
        floor.append(lmp.numpy.extract_compute("floor", LMP_STYLE_GLOBAL, LMP_TYPE_VECTOR).copy())
        deposit.append(lmp.numpy.extract_compute("deposit", LMP_STYLE_GLOBAL, LMP_TYPE_VECTOR).copy())

    # per-atom: the integrator's array f_sph (density, stress xx yy zz xy xz yz with tension
    # positive, regime) for every local atom; its rows for the floor's dummies are not the
    # grains', so keep those of type 1
    sand = lmp.numpy.extract_atom("type") == 1
    state = lmp.numpy.extract_fix("sph", LMP_STYLE_ATOM, LMP_TYPE_ARRAY)[sand].copy()
    x = lmp.numpy.extract_atom("x")[sand].copy()
    weight = sand.sum() * 2450 * 0.02**3 * 9.81
    lmp.close()

    floor, deposit = np.array(floor), np.array(deposit)
    np.savez(os.path.join(args.out, "column_stress.npz"), step=np.array(steps), time=np.array(times),
             floor=floor, deposit=deposit, state=state, x=x, weight=weight)

    # the grains' mean stress p = -(sxx + syy + szz)/3 in a radial section, and the floor's
    # force against the sand's weight as the column collapses
    pressure = -state[:, 1:4].sum(axis=1) / 3
    r = np.hypot(x[:, 0], x[:, 1])
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 3.6), gridspec_kw={"width_ratios": (1.4, 1)})
    order = np.argsort(pressure)
    dots = left.scatter(r[order], x[order, 2], c=pressure[order] / 1e3, s=12, cmap="viridis")
    fig.colorbar(dots, ax=left, label="mean stress p (kPa)", shrink=0.6)
    left.set(xlabel="r (m)", ylabel="z (m)", title=f"grains at t = {times[-1]:.3f} s")
    left.set_aspect("equal")
    right.plot(times, floor[:, 3] / weight, ".-", label="floor force $F_W$ / weight")
    right.plot(times, deposit[:, 0] / 0.2, ".-", label="deposit edge / $r_0$")
    right.set(xlabel="t (s)", title="compute sph/wallforce, sph/runout")
    right.legend()
    fig.tight_layout()
    png = os.path.join(args.out, "column_stress.png")
    fig.savefig(png, dpi=100)

    print(f"result: steps {steps[-1]} t {times[-1]:.4f} s grains {len(state)} "
          f"floor_force {floor[-1, 3]:.2f} N weight {weight:.2f} N edge {deposit[-1, 0]:.3f} m "
          f"p_max {pressure.max():.1f} Pa png {png}")


if __name__ == "__main__":
    main()
