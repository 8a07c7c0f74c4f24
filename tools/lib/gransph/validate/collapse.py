# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""The column collapse's measures: Lube et al.'s laws, the deposit's snapshots, edge,
thickness profiles, skirt and tail, and the fronts' pictures (the paper's case and the
convergence study share them)."""

import math

import matplotlib.pyplot as plt

from .report import save_figure

EDGE_THRESHOLD = 0.025      # the example's deposit edge: thickness 2.5% of r0
EDGE_WINDOW = 0.1           # the example's window for the edge (in r0, fixed in the
                            # problem's units), also the profiles'


def lube(a):
    """Lube et al. (2004): (r_inf - r0)/r0 of an axisymmetric collapse."""
    return 1.24 * a if a < 1.7 else 1.6 * math.sqrt(a)


def lube_height(a):
    """Lube et al. (2004): h_inf/r0 of an axisymmetric collapse."""
    return a if a < 1.15 else 0.88 * a ** (1.0 / 6.0)


def deposit_picture(dump, png, title):
    """The deposit's cross-section, every grain at (r, z), coloured by the mobilised
    strength of compute sph/stress/atom (1 on the yield surface)."""
    with open(dump) as f:
        lines = f.read().splitlines()
    start = max(i for i, l in enumerate(lines) if l.startswith("ITEM: ATOMS"))
    names = lines[start].split()[2:]
    rows = [[float(w) for w in l.split()] for l in lines[start + 1:]]
    column = {n: [r[k] for r in rows] for k, n in enumerate(names)}
    radius = radii(column)
    fig, ax = plt.subplots(figsize=(7, 2.6))
    points = ax.scatter(radius, column["z"], c=column["c_stress[10]"], s=4, cmap="viridis",
                        vmin=0.0, vmax=1.0)
    fig.colorbar(points, ax=ax, label="mobilised strength")
    ax.set_xlabel("r (m)")
    ax.set_ylabel("z (m)")
    ax.set_title(f"deposit at rest, {title}")
    ax.set_aspect("equal")
    save_figure(fig, png)


def last_snapshot(dump):
    """The last snapshot of a dump custom file as {column: [values]}, keyed by atom id."""
    with open(dump) as f:
        lines = f.read().splitlines()
    start = max(i for i, l in enumerate(lines) if l.startswith("ITEM: ATOMS"))
    names = lines[start].split()[2:]
    rows = [[float(w) for w in l.split()] for l in lines[start + 1:]]
    return {n: [r[k] for r in rows] for k, n in enumerate(names)}


def radii(snapshot, plane=False):
    """Each grain's distance r from the column's axis, or in plane strain from the
    strip's middle plane x = 0."""
    if plane:
        return [abs(x) for x in snapshot["x"]]
    return [math.hypot(x, y) for x, y in zip(snapshot["x"], snapshot["y"])]


def thickness_profile(snapshot, dx, r0, plane=False, width=None):
    """Equivalent thickness (a grain's volume dx^3, or area dx^2 in plane strain, over the
    floor area of the annulus, or of the two strips) in annuli or strips `width` wide
    (default 2 dx): [((r - r0)/r0 at the middle, thickness in m)]."""
    width = width or 2.0 * dx
    counts = {}
    for r in radii(snapshot, plane):
        k = int(r / width)
        counts[k] = counts.get(k, 0) + 1

    def thickness(k):
        if plane:
            return counts.get(k, 0) * dx ** 2 / (2.0 * width)
        return counts.get(k, 0) * dx ** 3 / (math.pi * width ** 2 * (2 * k + 1))
    return [(((k + 0.5) * width - r0) / r0, thickness(k)) for k in range(max(counts) + 2)]


def edge_over(snapshot, dx, r0, width, plane=False):
    """The deposit edge by compute sph/runout's rule (the outermost grain where the deposit
    is at least EDGE_THRESHOLD r0 thick, plus half a spacing; as (r - r0)/r0), with the
    thickness over an annulus or strips `width` wide centred on each grain, where the
    compute centres it on bins a ninth of the width: the same edge over 0.1 r0 (the
    example's 0.610 at dx = 0.02), up to 0.02 r0 apart over 2 dx on a sparse tail.
    Returns the edge and the fraction of the grains beyond it."""
    import bisect
    r = sorted(radii(snapshot, plane))
    edge = 0.0
    for ri in r:
        inside = bisect.bisect_right(r, ri + 0.5 * width) - bisect.bisect_left(r, ri - 0.5 * width)
        r_in, r_out = max(ri - 0.5 * width, 0.0), ri + 0.5 * width
        area = 2.0 * (r_out - r_in) if plane else math.pi * (r_out ** 2 - r_in ** 2)
        if inside * dx ** (2 if plane else 3) / area >= EDGE_THRESHOLD * r0:
            edge = ri
    return (edge + 0.5 * dx - r0) / r0, sum(1 for ri in r if ri > edge) / len(r)


def skirt_origin(final, start, r_edge, dx, r0, plane=False):
    """Where the skirt's grains (beyond r_edge, a centre distance read from the result
    line's three decimals, hence the tenth of a spacing) started: the fraction that started
    in the column's outermost ring (within one spacing of r0) and their mean starting
    height."""
    up = "y" if plane else "z"
    begin = {int(i): (r, z) for i, r, z in zip(start["id"], radii(start, plane), start[up])}
    skirt = [begin[int(i)] for i, r in zip(final["id"], radii(final, plane))
             if r > r_edge + 0.1 * dx and int(i) in begin]
    if not skirt:
        return None, None
    surface = sum(1 for r, _ in skirt if r > r0 - dx)
    return surface / len(skirt), sum(z for _, z in skirt) / len(skirt)


TAIL_RADII = (0.6, 0.8, 0.9, 1.0)   # fractions of Lube's runout the tail is counted beyond


def tail_fractions(snapshot, a, r0, plane=False):
    """The fraction of the grains beyond (r - r0)/r0 = f * Lube's runout for each f of
    TAIL_RADII: fixed places, so a tail of the model converges where a discretisation's
    skirt would grow as dx shrinks."""
    x = [(r - r0) / r0 for r in radii(snapshot, plane)]
    return [sum(1 for v in x if v > f * lube(a)) / len(x) for f in TAIL_RADII]


def tail_table(report, a, rows):
    report.append(f"The tail: grains beyond fixed radii, (r - r0)/r0 = f x {lube(a):.3f} (Lube)\n")
    report.append("| r0/dx | " + " | ".join(f"f = {f}" for f in TAIL_RADII) + " |")
    report.append("|---|" + "---|" * len(TAIL_RADII))
    for r in rows:
        report.append(f"| {r['ppr']} | " + " | ".join(f"{100 * t:.2f}%" for t in r["tail"]) + " |")
    report.append("")


def profile_table(report, rows, r0, plane):
    """The thickness profiles near the front in numbers, over annuli or strips
    EDGE_WINDOW r0 wide: fixed places, where a converging deposit's thickness
    settles. The front: from the last place where the finest deposit is still four
    times the edge's threshold thick to the last where any deposit is."""
    width = EDGE_WINDOW * r0
    profiles = [dict(thickness_profile(r["final"], r["dx"], r0, plane, width)) for r in rows]
    places = sorted(set().union(*profiles))
    start = max((x for x in places if profiles[-1].get(x, 0.0) >= 4 * EDGE_THRESHOLD * r0),
                default=places[0])
    end = max(x for x in places if any(p.get(x, 0.0) > 0.0 for p in profiles))
    places = [x for x in places if start <= x <= end]
    report.append(f"The front's thickness (mm) over {'strips' if plane else 'annuli'} "
                  f"{EDGE_WINDOW:g} r0 wide, centred at (r - r0)/r0 =\n")
    report.append("| r0/dx | " + " | ".join(f"{x:.2f}" for x in places) + " |")
    report.append("|---|" + "---|" * len(places))
    for r, thickness in zip(rows, profiles):
        report.append(f"| {r['ppr']} | " + " | ".join(f"{1e3 * thickness.get(x, 0.0):.1f}"
                                                     for x in places) + " |")
    report.append("")


def front_profiles(a, model, rows, png, r0, plane=False):
    """The deposits' thickness profiles near the front, one line per resolution, with the
    edge's threshold: a skirt that converges in physical units is the model's, one that
    scales with dx is the discretisation's. The profile is taken over the edge's window,
    EDGE_WINDOW r0 wide."""
    fig, ax = plt.subplots(figsize=(6, 3.5))
    width = EDGE_WINDOW * r0
    for r in rows:
        profile = [(x, h) for x, h in thickness_profile(r["final"], r["dx"], r0, plane, width)
                   if x > 0.0]
        ax.plot(*zip(*[(x, 1e3 * h) for x, h in profile]), ".-", label=f"{r['ppr']} per r0")
    ax.axhline(1e3 * EDGE_THRESHOLD * r0, color="k", ls=":", label="edge threshold")
    ax.set_ylim(0, 1e3 * 0.2 * r0)
    ax.set_xlabel("(r - r0)/r0")
    ax.set_ylabel("thickness (mm)")
    ax.set_title(f"deposit front, a = {a}, {model}" + (", plane strain" if plane else "") +
                 f", {'strips' if plane else 'annuli'} {EDGE_WINDOW:g} r0 wide", fontsize=9)
    ax.legend(fontsize=7)
    save_figure(fig, png)
