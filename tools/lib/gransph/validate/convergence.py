# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""The column collapse in resolution (axisymmetric or in plane strain): validation/convergence/."""

import os
import sys

import matplotlib.pyplot as plt

from .. import TOP
from .collapse import (EDGE_WINDOW, edge_over, front_profiles, last_snapshot,
                       lube, lube_height, profile_table, skirt_origin, tail_fractions,
                       tail_table)
from .common import number_after, wall_time

EXAMPLES = os.path.join(TOP, "examples")


CONVERGED_CHANGE = 0.03     # the two finest r_edge differ by at most this (relative)
SKIRT_MAX = 0.01            # volume fraction beyond r_edge at the two finest
LUBE_TOLERANCE = 0.15       # finest r_edge and h_inf against Lube et al.


def convergence(args, report):
    """The column collapse at several resolutions: the runout at the deposit edge
    (compute sph/runout, thickness 2.5% of r0), the radius of 95% of the grains, the
    outermost grain, the skirt beyond the edge and the height, with each run's size,
    steps and wall time, and the study's pass/fail criteria per case."""
    r0 = 0.2
    plane = args.plane
    report.append("## Column collapse: convergence with resolution\n")
    if plane:
        report.append("In plane strain (examples/column_collapse/in.column_collapse_plane): a strip "
                      "of half-width r0 and height a r0, r the distance from its middle plane, the "
                      f"thickness per unit length of floor over strips {EDGE_WINDOW:g} r0 wide on both sides. "
                      "Lube et al.'s axisymmetric runout serves only as a fixed scale here: there "
                      "is no criterion against experiment.\n")
    report.append("Runout (r - r0)/r0 at the deposit edge r_edge (the outermost grain where the "
                  "deposit is at least 2.5% of r0 = 5 mm thick, compute sph/runout over annuli "
                  f"{EDGE_WINDOW:g} r0 wide centred on each grain, a window fixed in the problem's "
                  "units, plus half a spacing; beside it, for comparison, the same edge over annuli "
                  "2 dx wide, a window that narrows as dx shrinks), of 95% of the grains (r95), of "
                  "the outermost grain "
                  "(plus half a spacing); the skirt is the fraction of the grains beyond r_edge, with "
                  "the share of its grains that started in the column's outermost ring (within one "
                  "spacing of r0) and their mean starting height. The runs end when the kinetic "
                  "energy is small and neither the edge nor the outermost grain moves faster than "
                  "0.5% of sqrt(g r0). "
                  "Lube et al. (2004): (r_inf - r0)/r0 = 1.24 a (a < 1.7), 1.6 a^(1/2); "
                  "h_inf/r0 = a (a < 1.15), 0.88 a^(1/6).\n")
    inp = os.path.join(EXAMPLES, "column_collapse", "in.column_collapse_plane") if plane else None
    fig, axes = plt.subplots(1, len(args.aspect), figsize=(5 * len(args.aspect), 4), squeeze=False)
    verdicts = []
    for a, ax in zip(args.aspect, axes[0]):
        for model, colour in zip(args.models, "br"):
            rows = []
            for ppr in args.ppr:
                dx = r0 / ppr
                variables = {"a": a, "model": model, "dx": f"{dx:.6g}", "dump": 1}
                if args.pair_options:
                    variables["pair_options"] = args.pair_options
                if args.fix_options:
                    variables["fix_options"] = args.fix_options
                if args.material:
                    variables["matfile"] = os.path.abspath(args.material[0])
                    variables["material"] = args.material[1]
                variables.update(args.input_vars)
                tag = f"convergence{args.suffix}_{model}_a{a}_ppr{ppr}"
                words, workdir = args.runner.run("column_collapse", variables, args.ranks, tag, inp)
                # the grains' starting places, to tell where the skirt came from
                _, startdir = args.runner.run("column_collapse", {**variables, "steps": 1}, args.ranks,
                                  tag + "_start", inp)
                final = last_snapshot(os.path.join(workdir, "column_collapse.dump"))
                edge = number_after(words, "(r_inf-r0)/r0")
                surface, height = skirt_origin(
                    final, last_snapshot(os.path.join(startdir, "column_collapse.dump")),
                    r0 * (1 + edge) - 0.5 * dx, dx, r0, plane)
                if number_after(words, "outermost") <= 0.0:
                    sys.exit(f"[validate] {tag}: the column did not spread; no runout to report")
                edge_2dx, skirt_2dx = edge_over(final, dx, r0, 2.0 * dx, plane)
                rows.append({"ppr": ppr, "dx": dx, "edge": number_after(words, "(r_inf-r0)/r0"),
                             "edge_2dx": edge_2dx, "skirt_2dx": skirt_2dx,
                             "r95": number_after(words, "r95"),
                             "outermost": number_after(words, "outermost"),
                             "skirt": number_after(words, "skirt"),
                             "height": number_after(words, "h_inf/r0"),
                             "t": number_after(words, "t"), "steps": int(number_after(words, "steps")),
                             "grains": int(number_after(words, "grains")),
                             "wall": wall_time(workdir), "final": final,
                             "skirt_surface": surface, "tail": tail_fractions(final, a, r0, plane),
                             "skirt_from": None if height is None else height / (a * r0)})
            verdicts.append(convergence_table(report, a, model, rows, plane))
            tail_table(report, a, rows)
            profile_table(report, rows, r0, plane)
            front = f"front{args.suffix}_a{a}_{model}.png"
            front_profiles(a, model, rows, args.runner.out("convergence", front), r0, plane)
            report.append(f"![front]({front})\n")
            report.write(f"convergence/convergence{args.suffix}.md")
            ppr = [r["ppr"] for r in rows]
            ax.plot(ppr, [r["edge"] for r in rows], colour + "o-", label=f"{model}: r_edge")
            ax.plot(ppr, [r["outermost"] for r in rows], colour + "^:", label=f"{model}: outermost")
        if not plane:
            ax.axhline(lube(a), color="k", label="Lube et al. 2004")
            ax.axhspan(lube(a) * (1 - LUBE_TOLERANCE), lube(a) * (1 + LUBE_TOLERANCE), color="0.9")
        ax.set_title(f"a = {a}" + (", plane strain" if plane else ""))
        ax.set_xlabel("particles per radius r0/dx")
        ax.set_ylabel("(r - r0)/r0")
        ax.legend(fontsize=7)
    report.figure(fig, args.runner, "convergence", f"convergence{args.suffix}.png", "convergence")
    report.append("| case | converged | verdict |")
    report.append("|---|---|---|")
    report += verdicts


def convergence_table(report, a, model, rows, plane=False):
    """One case's table and its verdict line (in plane strain without Lube et al.'s
    axisymmetric criteria)."""
    report.append(f"### a = {a}, {model}\n")
    report.append("| r0/dx | dx (m) | grains | steps | wall time (s) | t at rest (s) | r_edge | "
                  "change | r_edge over 2 dx | change | skirt beyond it | r95 | outermost | "
                  "skirt | skirt from the surface | started at z/h0 | h_inf/r0 |")
    report.append("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    changes = [None] + [abs(b["edge"] - c["edge"]) for c, b in zip(rows, rows[1:])]
    changes_2dx = [None] + [abs(b["edge_2dx"] - c["edge_2dx"]) for c, b in zip(rows, rows[1:])]
    for r, change, change_2dx in zip(rows, changes, changes_2dx):
        origin = ("| - | - |" if r["skirt_surface"] is None else
                  f"| {100 * r['skirt_surface']:.0f}% | {r['skirt_from']:.2f} |")
        report.append(f"| {r['ppr']} | {r['dx']:.5f} | {r['grains']} | {r['steps']} | {r['wall']:.0f} | "
                      f"{r['t']:.3f} | {r['edge']:.3f} | {'' if change is None else f'{change:.3f}'} | "
                      f"{r['edge_2dx']:.3f} | {'' if change_2dx is None else f'{change_2dx:.3f}'} | "
                      f"{100 * r['skirt_2dx']:.2f}% | "
                      f"{r['r95']:.3f} | {r['outermost']:.3f} | {100 * r['skirt']:.2f}% "
                      f"{origin} {r['height']:.3f} |")
    finest, second = rows[-1], rows[-2]
    steps = [c for c in changes if c is not None]
    checks = {
        "changes shrink": all(b <= c for c, b in zip(steps, steps[1:])),
        f"two finest within {100 * CONVERGED_CHANGE:.0f}%":
            abs(finest["edge"] - second["edge"]) <= CONVERGED_CHANGE * abs(finest["edge"]),
        f"skirt <= {100 * SKIRT_MAX:.0f}% at the two finest":
            finest["skirt"] <= SKIRT_MAX and second["skirt"] <= SKIRT_MAX,
        "outermost within 2 dx of r_edge":    # both in units of r0 = ppr dx
            finest["outermost"] - finest["edge"] <= 2.0 / finest["ppr"] + 1e-9,
    }
    if not plane:
        checks[f"r_edge within {100 * LUBE_TOLERANCE:.0f}% of Lube"] = \
            abs(finest["edge"] - lube(a)) <= LUBE_TOLERANCE * lube(a)
        checks[f"h_inf within {100 * LUBE_TOLERANCE:.0f}% of Lube"] = \
            abs(finest["height"] - lube_height(a)) <= LUBE_TOLERANCE * lube_height(a)
    failed = [name for name, ok in checks.items() if not ok]
    against = "" if plane else (
        f"Finest against Lube et al.: r_edge {finest['edge']:.3f} vs {lube(a):.3f} "
        f"({100 * (finest['edge'] - lube(a)) / lube(a):+.1f}%), h_inf/r0 "
        f"{finest['height']:.3f} vs {lube_height(a):.3f} "
        f"({100 * (finest['height'] - lube_height(a)) / lube_height(a):+.1f}%). ")
    report.append("\n" + against
                  + ("All criteria met." if not failed else "Not met: " + "; ".join(failed) + ".")
                  + "\n")
    return f"| a = {a}, {model} | {'yes' if not failed else 'no'} | " + \
        ("all criteria met" if not failed else "not met: " + "; ".join(failed)) + " |"
