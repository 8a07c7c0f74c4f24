# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""A steel ball dropped into a sand bed: validation/sphere_impact/."""

import math

import matplotlib.pyplot as plt

from .common import PHI_CHEN2019, number_after, wall_time


SPHERE_D = 0.0254
SPHERE_RHO_B = 7800.0
SPHERE_ALPHA = 0.02                     # the example's artificial viscosity (alpha)
UEHARA_EXPONENT = (1.0 / 3.0, 0.08)     # the exponent the issue asks for, and its tolerance
SPHERE_CONVERGED = 0.10                 # the two finest depths within this (relative)


def sphere_impact(args, report):
    """A steel ball dropped into the sand bed of examples/sphere_impact from several
    heights at several resolutions and artificial viscosities: its deepest penetration d
    against Uehara's law, the exponent of d against H = h + d, and its convergence in
    resolution and in the viscosity."""
    import numpy as np
    mu = math.tan(PHI_CHEN2019)
    report.append("A steel ball (D = 25.4 mm, 7800 kg/m^3) moved by fix rigid from the grains' "
                  "forces on its dummy particles, dropped from h above a bed of Chen2019's sand "
                  f"(Drucker-Prager, {args.width:g} D wide, {args.width / 2:g} D deep, open at the "
                  "top, geostatic start): `d` is "
                  "its bottom's deepest point below the bed's surface (`stop deepest`: the run "
                  "ends once the ball rests or turns upwards), H = h + d, and Uehara's "
                  "law d = (0.14 / mu) (rho_b / rho_g)^(1/2) D^(2/3) H^(1/3) with mu = tan(37 deg) "
                  "and rho_g = 2450 kg/m^3, the sand's. alpha is the linear coefficient of the "
                  "artificial viscosity between grains (`visc alpha 0`), `p_visc / p` the largest "
                  "viscous pressure in the bed during the run against its largest mean stress. "
                  "Input: examples/sphere_impact/in.sphere_impact.\n")
    report.append("| alpha | D / dx | h (m) | d (mm) | d / D | Uehara (mm) | d / Uehara | "
                  "p_visc / p | grains | steps | wall time (s) |")
    report.append("|---|---|---|---|---|---|---|---|---|---|---|")
    depths = {}
    for alpha in args.alphas:
        for per_d in args.per_diameter:
            for h in args.heights:
                words, workdir = args.runner.run("sphere_impact", {"h": h, "dx": SPHERE_D / per_d,
                                                       "alpha": alpha, "width": args.width,
                                                       "stop": "deepest"},
                                     args.ranks,
                                     f"sphere_impact_w{args.width:g}_a{alpha:g}_D{per_d}_h{h}")
                d, H, uehara, p_visc, p_max = (number_after(words, k) for k in
                                               ("d", "H", "uehara_d", "p_visc", "p_max"))
                depths[alpha, per_d, h] = (H, d)
                report.append(f"| {alpha:g} | {per_d} | {h} | {1e3 * d:.2f} | "
                              f"{d / SPHERE_D:.3f} | {1e3 * uehara:.2f} | {d / uehara:.2f} | "
                              f"{p_visc / p_max:.3f} | {int(number_after(words, 'grains'))} | "
                              f"{int(number_after(words, 'steps'))} | {wall_time(workdir):.0f} |")
                report.write(f"sphere_impact/sphere_impact{args.suffix}.md")
    report.append("\n**Exponent** of d against H (least squares on the logarithms, per viscosity "
                  f"and resolution; Uehara: 1/3, the issue's tolerance +-{UEHARA_EXPONENT[1]}):\n")
    fig, ax = plt.subplots(figsize=(6, 4))
    for alpha in args.alphas:
        for per_d in args.per_diameter:
            H, d = np.array([depths[alpha, per_d, h] for h in args.heights]).T
            exponent = np.polyfit(np.log(H), np.log(d), 1)[0]
            inside = abs(exponent - UEHARA_EXPONENT[0]) <= UEHARA_EXPONENT[1]
            report.append(f"- alpha = {alpha:g}, D / dx = {per_d}: {exponent:.3f} "
                          f"({'within' if inside else 'outside'} the tolerance)")
            ax.loglog(H, 1e3 * d, "o-", label=f"GRANSPH, alpha = {alpha:g}, D/dx = {per_d}")
    H = np.geomspace(min(args.heights), 1.2 * max(args.heights))
    ax.loglog(H, 1e3 * 0.14 / mu * math.sqrt(SPHERE_RHO_B / 2450.0) * SPHERE_D ** (2 / 3) *
              H ** (1 / 3), "k--", label="Uehara et al. (2003)")
    ax.set_xlabel("H = h + d (m)")
    ax.set_ylabel("d (mm)")
    ax.legend(fontsize=7)
    report.figure(fig, args.runner, "sphere_impact", f"sphere_impact{args.suffix}.png",
                  "d against H", before="\n")
    plt.close(fig)

    def changes(a, b):    # relative change of d from a to b at each height
        return [abs(depths[b + (h,)][1] / depths[a + (h,)][1] - 1) for h in args.heights]

    def listed(change):
        return ", ".join(f"{c:.1%}" for c in change)

    heights = ", ".join(f"{h}" for h in args.heights)
    if len(args.per_diameter) > 1:
        coarse, fine = args.per_diameter[-2:]
        for alpha in args.alphas:
            change = changes((alpha, coarse), (alpha, fine))
            verdict = "within" if max(change) <= SPHERE_CONVERGED else "not within"
            report.append(f"**Convergence in resolution** (alpha = {alpha:g}): between D / dx = "
                          f"{coarse} and {fine} the depth changes by " +
                          listed(change) + f" at h = {heights} m "
                          f"({verdict} the {SPHERE_CONVERGED:.0%} asked).\n")
    if len(args.alphas) > 1:
        report.append("**The viscosity's share**: how far the depth at each alpha lies from that at the "
                      f"smallest, alpha = {args.alphas[-1]:g} (h = {heights} m):\n")
        for per_d in args.per_diameter:
            for alpha in args.alphas[:-1]:
                change = changes((args.alphas[-1], per_d), (alpha, per_d))
                report.append(f"- D / dx = {per_d}, alpha = {alpha:g}: " + listed(change))
        report.append("")
