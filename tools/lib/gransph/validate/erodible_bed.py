# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""A granular column released on a slope onto an erodible layer (examples/erodible_bed),
its runout against the layer's thickness: validation/erodible_bed/."""

import matplotlib.pyplot as plt

from .common import number_after, wall_time


# the column of Mangeney et al. (2010): 14 cm high, 20 cm long (the example's defaults)
BED_H0 = 0.14
BED_R0 = 0.2
GROWS = 0.05        # a runout more than 5% beyond (short of) the bare bed's grows (shrinks)


def channel_length(theta):
    """the channel beyond the column's foot, m: longer on steeper slopes, where the mass
    runs further (lone grains that skid on past its end leave and are counted)"""
    return round(0.6 + 0.03 * theta, 3)


def erodible_bed(args, report):
    """The column of examples/erodible_bed on slopes args.slopes (degrees) onto erodible
    layers of args.thickness h0 (whole rows of grains at each resolution), at
    args.per_height particles across h0: the front of the mobilised mass against the
    layer's thickness, set beside Mangeney et al. (2010)."""
    rows = {}
    for n in args.per_height:
        for ratio in args.thickness:
            rows[n, ratio] = round(ratio * n)
            if abs(rows[n, ratio] - ratio * n) > 0.02:
                report.append(f"Note: e/h0 = {ratio:g} is not a whole number of rows at h0/dx = {n}; "
                              f"the layer there is {rows[n, ratio]} rows (e/h0 = {rows[n, ratio] / n:.3f}).\n")
    report.append("A rectangular column of sand (Chen2019, Drucker-Prager), h0 = "
                  f"{BED_H0:g} m high and r0 = {BED_R0:g} m long against a back wall, released from "
                  "rest on a floor of dummy particles tilted by theta (gravity tilted), in plane "
                  "strain; downstream of its foot the floor is covered by an erodible layer e thick "
                  "of the same sand (a second material of the same parameters, so that it has a "
                  "colour of its own). Each run goes on until the front and x95 are at rest (or 3 s). "
                  "`runout` is the front of the mobilised mass beyond the column's foot: the "
                  "outermost grain where the grains that have moved (the column's, and the bed's "
                  "displaced by more than 1 cm) make a layer at least 0.1 h0 thick over strips "
                  "2 cm wide; `x95` the point behind which 95% of that mass lies; `skirt` the "
                  "fraction of it beyond the front (lone grains that skid on down the bed, some off "
                  "the channel's end: `off`); `bed moved` the bed's mass displaced by more than "
                  "1 cm, against the column's. `vs bare` is the runout against the bare bed's "
                  "(e = 0) on the same slope at the same resolution. Input: "
                  "examples/erodible_bed/in.erodible_bed.\n")
    report.append("The floor: " + ("rough, the pair style's default walls, whose dummies carry the "
                                   "grains' stress" if args.floor == "rough" else
                                   "the floor's dummies hold the grains as contacts do, at each "
                                   "grain's own slide friction (`wall/friction floor material "
                                   "wall/friction/hold stick`); the back wall rough") + ".\n")
    report.append("| theta (deg) | h0 / dx | e / h0 | runout / h0 | vs bare | x95 / h0 | skirt | "
                  "off | bed moved (kg/m) | / column | grains | particles | steps | t (s) | "
                  "wall time (s) |")
    report.append("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    results = {}
    for theta in args.slopes:
        for n in args.per_height:
            dx = BED_H0 / n
            for ratio in args.thickness:
                e = rows[n, ratio] * dx
                variables = {"theta": theta, "dx": f"{dx:.10g}", "e": f"{e:.10g}",
                             "h0": BED_H0, "r0": BED_R0, "length": channel_length(theta),
                             "tmax": args.tmax}
                if args.floor != "rough":
                    variables["floor"] = args.floor
                words, workdir = args.runner.run("erodible_bed", variables, args.ranks,
                                                 f"erodible_bed{args.suffix}_t{theta:g}_n{n}_e{rows[n, ratio]}")
                r = {k: number_after(words, k) for k in ("runout", "x95", "skirt", "bed_moved", "ratio",
                                                          "t", "steps", "grains", "particles", "off_end")}
                r["wall"] = wall_time(workdir)
                r["e"] = rows[n, ratio] / n
                results[theta, n, ratio] = r
                bare = results.get((theta, n, args.thickness[0]))
                versus = (f"{r['runout'] / bare['runout'] - 1:+.0%}"
                          if bare and args.thickness[0] == 0 and ratio != 0 else "")
                report.append(f"| {theta:g} | {n} | {r['e']:.3f} | {r['runout'] / BED_H0:.2f} | {versus} | "
                              f"{r['x95'] / BED_H0:.2f} | {r['skirt']:.3f} | {int(r['off_end'])} | "
                              f"{r['bed_moved']:.2f} | {r['ratio']:.3f} | {int(r['grains'])} | "
                              f"{int(r['particles'])} | {int(r['steps'])} | {r['t']:.2f} | {r['wall']:.0f} |")
                report.write(f"erodible_bed/erodible_bed{args.suffix}.md")
    plot(args, results)
    report.append(f"\n![runout against the layer's thickness](erodible_bed{args.suffix}.png)\n")
    findings(args, report, results)


def plot(args, results):
    """runout / h0 and the bed's mass moved against e / h0, a line per slope and
    resolution (the finest solid)"""
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    finest = max(args.per_height)
    for k, theta in enumerate(args.slopes):
        for n in args.per_height:
            rs = [results[theta, n, ratio] for ratio in args.thickness]
            style = dict(color=colours[k % len(colours)], ls="-" if n == finest else "--",
                         marker="o" if n == finest else "s", ms=4)
            label = f"{theta:g} deg, h0/dx = {n}"
            axes[0].plot([r["e"] for r in rs], [r["runout"] / BED_H0 for r in rs], label=label, **style)
            axes[1].plot([r["e"] for r in rs], [r["ratio"] for r in rs], label=label, **style)
    axes[0].set_xlabel("e / h0")
    axes[0].set_ylabel("runout / h0 (front of the mobilised mass)")
    axes[1].set_xlabel("e / h0")
    axes[1].set_ylabel("bed mass moved / column mass")
    axes[0].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(args.runner.out("erodible_bed", f"erodible_bed{args.suffix}.png"), dpi=120)
    plt.close(fig)


def findings(args, report, results):
    """how the runout moves with the layer's thickness on each slope, at each resolution,
    beside Mangeney et al. (2010)"""
    report.append("**Mangeney et al. (2010)** (JGR 115, F03040; glass beads released from behind a "
                  "gate onto a thin erodible layer of the same beads in an inclined channel): on "
                  "slopes above a critical angle of about 10 to 16 degrees the runout grows with "
                  "the erodible layer's thickness; below it the runout barely changes.\n")
    if args.thickness[0] != 0 or len(args.thickness) < 2:
        return
    report.append("**Here**, runout / h0 on each slope from the bare bed to the thickest layer, and "
                  "the thickest against the bare bed (grows / shrinks: more than "
                  f"{GROWS:.0%} beyond / short of it; a spacing is 1/{min(args.per_height)} to "
                  f"1/{max(args.per_height)} of h0):\n")
    for theta in args.slopes:
        parts = []
        for n in args.per_height:
            runouts = [results[theta, n, ratio]["runout"] / BED_H0 for ratio in args.thickness]
            change = runouts[-1] / runouts[0] - 1
            verdict = "grows" if change > GROWS else "shrinks" if change < -GROWS else "barely changes"
            parts.append(f"h0/dx = {n}: {', '.join(f'{r:.2f}' for r in runouts)} ({change:+.0%}, {verdict})")
        report.append(f"- theta = {theta:g} deg: " + "; ".join(parts))
    report.append("")
