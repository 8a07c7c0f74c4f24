# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""The flume impact in resolution: validation/flume/."""

import sys

import matplotlib.pyplot as plt

from ..measures import FLUME_WIDTH, FORCE_WINDOW, force_history, windowed_peak
from .common import number_after, wall_time


def flume_convergence(args, report):
    """The flume impact at several spacings and bed frictions, both models: the wall
    force's largest sample and its largest 20 ms mean with their times, the first impact
    and the impulse on the wall up to tend, with each run's size, steps and wall time."""
    tend = args.tend
    report.append("## Sand impact on a wall: convergence with resolution\n")
    report.append(f"examples/flume_impact to t = {tend} s ("
                  + ("the first surge; " if tend <= 1.0 else "") +
                  "the paper's peaks come at 0.65-0.70 s) at each spacing. The wall force is sampled every 100 steps; its "
                  "peak is given as the largest sample and as the largest mean over "
                  f"{1000 * FORCE_WINDOW:.0f} ms (a load cell's reading, which the sampling rate and "
                  "the particles' noise do not inflate), with the impulse the wall takes up to "
                  f"t = {tend} s. The paper: 192 N (phase change) / 212 N (Drucker-Prager) at "
                  "dx = 10 mm; Moriguchi et al. (2009) measured about 186 N.\n")
    fig, axes = plt.subplots(1, len(args.models), figsize=(6 * len(args.models), 4), squeeze=False)
    for model, ax in zip(args.models, axes[0]):
        report.append(f"### {model}\n")
        report.append("| delta (deg) | dx (m) | grains across | grains | steps | wall time (s) | "
                      "largest sample (N) | at t (s) | largest 20 ms mean (N) | at t (s) | "
                      "first impact (s) | impulse (N s) |")
        report.append("|---|---|---|---|---|---|---|---|---|---|---|---|")
        for delta, dx in ((delta, dx) for delta in args.deltas for dx in args.dx):
            variables = {"model": model, "dx": dx, "tend": tend, "delta": delta}
            if args.pair_options:
                variables["pair_options"] = args.pair_options
            if args.fix_options:
                variables["fix_options"] = args.fix_options
            words, workdir = args.runner.run("flume_impact", variables, args.ranks,
                                 f"flume_convergence{args.suffix}_{model}"
                                 + ("" if delta == "rough" else f"_delta{delta}") + f"_dx{dx}")
            t, f = force_history(workdir)
            mean_peak, mean_at, impulse = windowed_peak(t, f)
            if number_after(words, "first_impact") < 0 or impulse <= 0.0:
                sys.exit(f"[validate] flume, {model}, delta {delta}, dx {dx}: the sand never "
                         f"loaded the wall by t = {tend} s; no impact to report")
            report.append(f"| {delta} | {dx} | {FLUME_WIDTH / dx:.0f} | {int(number_after(words, 'grains'))} | "
                          f"{int(number_after(words, 'steps'))} | {wall_time(workdir):.0f} | "
                          f"{number_after(words, 'peak_force'):.0f} | {number_after(words, 'at'):.3f} | "
                          f"{mean_peak:.0f} | {mean_at:.3f} | {number_after(words, 'first_impact'):.3f} | "
                          f"{impulse:.1f} |")
            ax.plot(t, f, lw=0.8, label=f"dx = {dx} m" + ("" if len(args.deltas) == 1 else
                                                          f", delta = {delta}"))
            report.write(f"flume/flume_convergence{args.suffix}.md")
        report.append("")
        ax.axhline(186.0, color="k", ls=":", label="Moriguchi et al. 2009, peak")
        ax.set_title(model)
        ax.set_xlabel("t (s)")
        ax.set_ylabel("normal force on the wall (N)")
        ax.legend(fontsize=7)
    report.figure(fig, args.runner, "flume", f"flume_convergence{args.suffix}.png",
                  "force histories")
