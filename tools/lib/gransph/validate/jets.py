# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""The jets of the paper's sections 5.3 and 5.4: the collision's drift speed, the wavy
jet's wavelength on a film."""

import os

import matplotlib.pyplot as plt

from .common import number_after
from .report import save_figure


def jet_collision(args, report):
    paper = {0.5: 0.14, 1.0: 0.0, 0.25: 3.96}
    rows, pts = [], []
    dx = 0.004 if args.paper else 0.008    # the example's default (the paper: 4 mm)
    R = 0.1    # the example's radius of the thick jet
    for k in [0.5, 1.0, 0.25]:
        variables = {"k": k, "dx": dx}
        words, _ = args.runner.run("jet_collision", variables, args.ranks, f"jets_k{k}")
        u0 = number_after(words, "u0")
        pts.append((k, u0))
        rows.append(f"| {k} | 2450 | {variables['dx']} | {u0:.2f} | {paper[k]:.2f} | "
                    f"{number_after(words, 'dissipation'):.3g} | {number_after(words, 'fraction'):.2f} |")
    words, _ = args.runner.run("jet_collision", {"k": 0.25, "rho": 1200, "dx": dx}, args.ranks, "jets_rho1200")
    rows.append(f"| 0.25 | 1200 | {dx} | {number_after(words, 'u0'):.2f} | - | "
                f"{number_after(words, 'dissipation'):.3g} | {number_after(words, 'fraction'):.2f} |")
    fig, ax = plt.subplots(figsize=(5, 4))
    ax.plot(*zip(*sorted(pts)), "o-", label="GRANSPH")
    ax.plot(*zip(*sorted(paper.items())), "ks", label="Chen et al. 2019")
    ax.set_xlabel("k (radius ratio)")
    ax.set_ylabel("u0 (m/s)")
    ax.legend()
    save_figure(fig, args.runner.out("paper", "u0_vs_k.png"))
    report.append("## 3. Head-on collisions of granular jets (section 5.3)\n")
    report.append("The dissipation is the loss of the jets' kinetic energy per unit time between "
                  "t1 and t2, and its fraction of the kinetic energy the two jets bring to the "
                  "impact per unit time.\n")
    report.append("| k | rho (kg/m3) | dx (m) | u0 (m/s) | paper u0 (m/s) | dissipation (W) | fraction |")
    report.append("|---|---|---|---|---|---|---|")
    report += rows
    report.append("\n![u0 vs k](paper/u0_vs_k.png)\n")
    report.append("Where we differ: k = 1 gives u0 = 0 by symmetry, as it must. For unequal jets "
                  "u0 is set by the energy the collision dissipates (Ellowitz 2015, "
                  "arXiv:1508.02254): jets of an ideal fluid meet in a stationary impact region "
                  "whose inclined ejecta carry the momentum excess, so the paper's small u0 for "
                  "k = 0.5 means little dissipation, and our larger u0 more (the dissipation "
                  "column), numerical dissipation included; the momentum balance with ejecta at "
                  "right angles, u0 = v0 (1 - k)/(1 + k) = 3.3 m/s for k = 0.5, is no bound. At "
                  f"dx = {dx * 1000:g} mm the thin jets are {0.5 * R / dx:.0f} (k = 0.5) and "
                  f"{0.25 * R / dx:.0f} (k = 0.25) particles across their radius. See "
                  "examples/jet_collision/README.md.\n")

def jet_film(args, report):
    dx = 0.002 if args.paper else 0.003
    cases = [(2.0e-3, f) for f in (80, 160, 240)] + [(a, 160) for a in (1.0e-3, 3.0e-3)]
    rows, by_f = [], []
    for a0, f0 in cases:
        words, workdir = args.runner.run("jet_film", {"A0": a0, "f0": f0, "dx": dx, "images": 4 if (a0, f0) == (2.0e-3, 160) else 0},
                             args.ranks, f"jet_film_A{a0}_f{f0}")
        wavelength = number_after(words, "wavelength")
        rows.append(f"| {1000 * a0:.1f} | {f0} | {wavelength:.4f} | {4.0 / f0:.4f} |")
        if a0 == 2.0e-3:
            by_f.append((f0, wavelength))
            if f0 == 160:
                snapshots = sorted(p for p in os.listdir(workdir) if p.endswith(".png"))
                for view in ("side", "top"):
                    name = [p for p in snapshots if f".{view}." in p][-1]
                    os.replace(os.path.join(workdir, name), args.runner.out("paper", f"film_{view}.png"))
    fig, ax = plt.subplots(figsize=(5, 4))
    ax.plot(*zip(*by_f), "o", label="GRANSPH, A0 = 2 mm")
    f = [60 + 2 * k for k in range(100)]
    ax.plot(f, [4.0 / x for x in f], "k-", label="v / f0")
    ax.set_xlabel("f0 (Hz)")
    ax.set_ylabel("wavelength (m)")
    ax.legend()
    save_figure(fig, args.runner.out("paper", "wavelength_vs_f0.png"))
    report.append("## 4. Wavy granular jet on a granular film (section 5.4)\n")
    report.append(f"Jet speed 4 m/s, dx = {dx} m. The wavelength is measured on the falling jet "
                  "(zero crossings of its centre line); the paper shows pictures, no numbers.\n")
    report.append("| A0 (mm) | f0 (Hz) | wavelength (m) | v/f0 (m) |")
    report.append("|---|---|---|---|")
    report += rows
    report.append("\n![wavelength](paper/wavelength_vs_f0.png) ![side](paper/film_side.png) ![top](paper/film_top.png)\n")
    report.append("Where we differ: the paper compares pictures of the wave on the film with the "
                  "experiment; we measure the wavelength on the jet, which follows v/f0, and do not "
                  "resolve wave crests on the film at this resolution. The nozzle size, height and "
                  "the film are our choices. See examples/jet_film/README.md.\n")


# The sphere impact (issue 23): Uehara et al. (2003), d = (0.14 / mu) (rho_b / rho_g)^(1/2)
