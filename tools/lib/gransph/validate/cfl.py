# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""The CFL constant of the integrators' timestep: validation/cfl/."""

import math
import os
import re
import sys

import matplotlib.pyplot as plt

from .. import TOP
from ..measures import FORCE_WINDOW, force_history, windowed_peak
from .collapse import last_snapshot
from .common import number_after, wall_time


WAVE_DIR = os.path.join(TOP, "unittest", "physics")
WAVE_REFERENCE_CFL = 0.025   # the wave's reference run
WAVE_TIMES = (2.0e-3, 2.0e-2)   # s: about one and ten periods of the standing wave
WAVE_LONG = 0.5              # s: how long a run must stay finite and not grow (250 periods)
WAVE_BISECTION = 0.0125      # the resolution in C of the wave's limit of stability
WAVE_AMPLITUDE = 0.01        # m/s: in.elastic_wave's A, passed explicitly
WAVE_DX = 0.01               # m: in.elastic_wave's dx (h = 1.2 dx), passed explicitly
EDGE_TOLERANCE = 0.01        # the column's r_edge and h_inf against the smallest C (relative)
FLUME_SPREAD = 12.0          # N: the Drucker-Prager largest 20 ms means of
                             # validation/flume/flume_convergence.md, 92 to 104 N over dx 0.03 to 0.0167 m
FLUME_IMPACT_SPREAD = 0.015  # s: its first impacts, 0.599 to 0.614 s


def derived_input(runner, source, tag, replacements):
    """A copy of the input `source` in the run folder of `tag` with each (old, new) of
    `replacements` made, old standing exactly once in it: the input as it is, with a
    keyword or an ending that its variables do not offer. Returns the copy's path."""
    with open(source) as f:
        text = f.read()
    for old, new in replacements:
        if text.count(old) != 1:
            sys.exit(f"[validate] {source}: '{old.strip()}' stands {text.count(old)} times, "
                     "not once: update tools/research/validate with the input")
        text = text.replace(old, new)
    path = os.path.join(runner.workdir(tag), "in." + tag)
    with open(path, "w") as f:
        f.write(text)
    return path


def failure(workdir):
    """Why a run of args.runner.run(..., may_fail=True) stopped, shortened to its message and step."""
    with open(os.path.join(workdir, "failed")) as f:
        reason = f.read().strip()
    step = re.search(r"at step (\d+)", reason)
    if "non-finite" in reason:
        return "non-finite state" + (f" at step {step.group(1)}" if step else "")
    return reason[:80]


def dump_snapshots(path):
    """Every snapshot of a dump custom file written with `time yes`, as
    [(time, {column: array})]."""
    import numpy as np
    with open(path) as f:
        lines = f.read().splitlines()
    snapshots, time = [], None
    for i, line in enumerate(lines):
        if line == "ITEM: TIME":
            time = float(lines[i + 1])
        elif line.startswith("ITEM: NUMBER OF ATOMS"):
            count = int(lines[i + 1])
        elif line.startswith("ITEM: ATOMS"):
            rows = np.array([[float(w) for w in l.split()] for l in lines[i + 1:i + 1 + count]])
            snapshots.append((time, dict(zip(line.split()[2:], rows.T))))
    return snapshots


def at_time(snapshots, t):
    """The snapshots' columns at time t, by Lagrange interpolation through the four
    snapshots nearest in time (the reference's steps are a fortieth of the wave's period
    over 2 pi: its error is far below the errors measured against it)."""
    times = [s[0] for s in snapshots]
    if not min(times) <= t <= max(times):
        sys.exit(f"[validate] wave: t = {t} is outside the reference's window "
                 f"{min(times)} to {max(times)}")
    near = sorted(range(len(times)), key=lambda k: abs(times[k] - t))[:4]
    result = {}
    for j in near:
        weight = math.prod((t - times[m]) / (times[j] - times[m]) for m in near if m != j)
        for name, column in snapshots[j][1].items():
            result[name] = result.get(name, 0.0) + weight * column
    return result


def wave_ending(window):
    """The commands that replace in.elastic_wave's fixed-step run: with the CFL step the
    run goes to the step nearest each of WAVE_TIMES, writes wave<k>.dump there, and goes
    on to WAVE_LONG, whether it stays finite (wave_end.dump); for the reference (window > 0) through
    t +- window of each with a snapshot every step."""
    def until(t):
        return [f"fix stop all halt 1 v_tnear >= {t!r} error continue", "run 1000000000",
                "unfix stop"]
    columns = "id x vx f_sph[1] f_sph[2]"
    lines = ["variable tnear equal time+0.5*dt", "thermo_style custom step time dt", "thermo 1000"]
    for k, t in enumerate(WAVE_TIMES):
        if window:
            lines += until(t - window) + [f"dump ref all custom 1 wave{k}.dump {columns}",
                                          "dump_modify ref sort id format float %.17g time yes"]
            lines += until(t + window) + ["undump ref"]
        else:
            lines += until(t) + [f"write_dump all custom wave{k}.dump {columns} modify sort id "
                                 "format float %.17g time yes"]
    if not window:
        lines += until(WAVE_LONG) + ["write_dump all custom wave_end.dump id vx modify sort id"]
    return "\n".join(lines + ['print "result: t $(time:%.10g) steps $(step)"']) + "\n"


def elastic_material():
    """rho0, E and nu of the material Elastic of unittest/physics/elastic.gransph."""
    with open(os.path.join(WAVE_DIR, "elastic.gransph")) as f:
        words = next(l.split() for l in f if l.startswith("Elastic"))
    return float(words[1]), float(words[2]), float(words[3])


def cfl_keywords(args, cfl):
    """the integrator keywords of one C of the study (and the variant's, --fix-options)"""
    return f"cfl {cfl} cfl/sound {args.cfl_sound} {args.fix_options}".strip()


def cfl_tag(args, what, cfl):
    """the run folder's name of one C of the study"""
    return f"cfl_{what}_C{cfl}" + ("_ref" if args.cfl_sound == "reference" else "") + args.suffix


def wave_run(args, cfl, window):
    """in.elastic_wave with `cfl C` instead of `cfl none`, to WAVE_TIMES and WAVE_LONG
    (wave_ending): returns the result line's words (None if it stopped) and the run's
    folder."""
    tag = cfl_tag(args, "wave", cfl)
    source = os.path.join(WAVE_DIR, "in.elastic_wave")
    with open(source) as f:
        ending = f.read().partition("\nrun ")
    inp = derived_input(args.runner, source, tag, [("cfl none", cfl_keywords(args, "${cfl}")),
                                      ("\nrun " + ending[2], "\n" + wave_ending(window))])
    return args.runner.run("elastic_wave", {"cfl": cfl, "A": WAVE_AMPLITUDE, "dx": WAVE_DX,
                                "material": os.path.join(WAVE_DIR, "elastic.gransph")},
               1, tag, input_file=inp, may_fail=True)


def cfl_wave(args, report):
    """The standing elastic wave of unittest/physics/in.elastic_wave with the CFL step:
    errors of vx and the stress against a run at WAVE_REFERENCE_CFL, at about one and ten
    periods, as fractions of the wave's amplitudes, and whether the run stays finite to
    WAVE_LONG; the limit of stability bisected between the list's C."""
    import numpy as np
    rho0, E, nu = elastic_material()
    c = math.sqrt(E / rho0)                       # the CFL step's sound speed (eq. 19)
    c_p = math.sqrt(E * (1 - nu) / ((1 + nu) * (1 - 2 * nu)) / rho0)   # the wave's
    stress_amplitude = rho0 * c_p * WAVE_AMPLITUDE
    step = lambda cfl: cfl * 1.2 * WAVE_DX / c    # noqa: E731 (|a| is far below h/dt^2 here)
    window = 0.6 * step(max(args.cfl)) + 4 * step(WAVE_REFERENCE_CFL)
    words, refdir = wave_run(args, WAVE_REFERENCE_CFL, window)
    if words is None:
        sys.exit(f"[validate] the wave's reference run at C = {WAVE_REFERENCE_CFL} stopped: "
                 f"{failure(refdir)}")
    reference = [dump_snapshots(os.path.join(refdir, f"wave{k}.dump")) for k in range(len(WAVE_TIMES))]
    reference_steps = int(number_after(words, "steps"))
    report.append("## 1. Elastic standing wave\n")
    report.append("unittest/physics/in.elastic_wave (a periodic bar of 20 x 3 x 3 grains, dx = "
                  f"{WAVE_DX} m, material Elastic of elastic.gransph, v_x = A sin(2 pi x / L) with "
                  f"A = {WAVE_AMPLITUDE} m/s at t = 0; test_time_order.py runs it at fixed dt) with "
                  "the integrator's `cfl C` instead of `cfl none` (a copy of the input in the run's "
                  "folder; the input itself is unchanged), run to the step nearest "
                  f"t = {WAVE_TIMES[0] * 1e3:g} ms (about one period) and {WAVE_TIMES[1] * 1e3:g} ms "
                  f"(ten), then on to {WAVE_LONG:g} s ({WAVE_LONG / WAVE_TIMES[0]:.0f} periods), "
                  "whether it stays finite. The reference is the same run at "
                  f"C = {WAVE_REFERENCE_CFL}, interpolated to each run's times. The errors are the "
                  "largest over the grains of |vx - vx_ref| over A and of |sigma_xx - sigma_xx_ref| "
                  f"over the wave's stress amplitude rho0 c_p A = {stress_amplitude:.0f} Pa "
                  f"(c_p = {c_p:.1f} m/s, the P-wave speed of the bar); at t = 2 ms the wave's stress "
                  "is near a zero, so an error relative to its value there would mean little; at "
                  "20 ms the error is mostly the phase lag a second-order scheme accumulates. The "
                  f"step is C h / sqrt(E/rho) = C x {step(1.0):.3e} s here (the acceleration term of "
                  "eq. 19 is far larger). An unstable run stops with the integrator's error on a "
                  "non-finite state, recorded with its step and time; a run that ends with "
                  f"max abs(vx) above A at {WAVE_LONG:g} s has grown (the wave itself decays under "
                  "the artificial viscosity, and nothing feeds it): unstable too; the CFL step, "
                  "which shrinks as the grains speed up, can keep such a run finite. The order is log(error ratio) / log(C ratio) between neighbouring "
                  "C: 2 for a second-order scheme.\n")
    report.append(f"| C | dt (s) | steps to {WAVE_LONG:g} s | stable to {WAVE_LONG:g} s | "
                  f"max abs(vx) / A at {WAVE_LONG:g} s | "
                  + " | ".join(f"{q} error at {t * 1e3:g} ms | order" for t in WAVE_TIMES
                               for q in ("vx", "stress")) + " |")
    report.append("|---|---|---|---|---|" + "---|---|" * 2 * len(WAVE_TIMES))

    def one(cfl):
        """A run at C: its row of the table and its record."""
        words, workdir = wave_run(args, cfl, 0.0)
        errors = []
        for k, _ in enumerate(WAVE_TIMES):
            path = os.path.join(workdir, f"wave{k}.dump")
            if not os.path.exists(path):
                break
            (t, state), = dump_snapshots(path)
            ref = at_time(reference[k], t)
            errors += [np.max(np.abs(state["vx"] - ref["vx"])) / WAVE_AMPLITUDE,
                       np.max(np.abs(state["f_sph[2]"] - ref["f_sph[2]"])) / stress_amplitude]
        r = {"cfl": cfl, "errors": errors, "wall": wall_time(workdir), "stable": words is not None and
             all(math.isfinite(e) for e in errors) and len(errors) == 2 * len(WAVE_TIMES)}
        if words is None:
            why = failure(workdir)
            at = re.search(r"step (\d+)", why)
            r["why"] = why + (f" (t = {int(at.group(1)) * step(cfl):.3f} s)" if at else "")
        else:
            vmax = max(abs(v) for v in last_snapshot(os.path.join(workdir, "wave_end.dump"))["vx"])
            r.update(steps=int(number_after(words, "steps")), vmax=vmax / WAVE_AMPLITUDE,
                     why=f"grew to max abs(vx) = {vmax / WAVE_AMPLITUDE:.2g} A")
            r["stable"] &= vmax <= WAVE_AMPLITUDE    # the wave gains no energy from anywhere
        return r

    rows = []
    for cfl in args.cfl:
        rows.append(one(cfl))
        r = rows[-1]
        cells = []
        before = rows[-2] if len(rows) > 1 else None
        for j, e in enumerate(r["errors"]):
            order = (math.log(e / before["errors"][j]) / math.log(r["cfl"] / before["cfl"])
                     if before and len(before["errors"]) > j and e > 0 and before["errors"][j] > 0
                     else None)
            cells.append(f"{e:.2e} | {'' if order is None else f'{order:.2f}'}")
        cells += ["- | -"] * (2 * len(WAVE_TIMES) - len(cells))
        report.append(f"| {cfl} | {step(cfl):.3e} | {r.get('steps', '-')} | "
                      f"{'yes' if r['stable'] else 'no: ' + r['why']} | "
                      + (f"{r['vmax']:.2e} | " if "vmax" in r else "- | ") + " | ".join(cells) + " |")
    longest = max(r["wall"] for r in rows + [{"wall": wall_time(refdir)}])
    report.append(f"\nThe reference (C = {WAVE_REFERENCE_CFL}) took {reference_steps} steps to "
                  f"{WAVE_TIMES[-1] * 1e3:g} ms; all runs are 180 grains on 1 rank, the longest "
                  f"{longest:.0f} s.\n")
    # the limit between the largest C that stayed finite and the smallest that did not
    stable = [r["cfl"] for r in rows if r["stable"]]
    unstable = [r["cfl"] for r in rows if not r["stable"] and (not stable or r["cfl"] > max(stable))]
    limit = None
    if stable and unstable:
        lo, hi = max(stable), min(unstable)
        tried = []
        while hi - lo > WAVE_BISECTION + 1e-9:
            mid = round(0.5 * (lo + hi), 4)
            r = one(mid)
            tried.append(f"C = {mid}: " + ("stable" if r["stable"] else r["why"]))
            lo, hi = (mid, hi) if r["stable"] else (lo, mid)
        limit = (lo, hi)
        report.append(f"The limit, bisected to {WAVE_BISECTION}: the wave stays stable to "
                      f"{WAVE_LONG:g} s up to C = {lo} and not from C = {hi} ("
                      + "; ".join(tried) + ").\n")
    if any(r["errors"] for r in rows):
        fig, ax = plt.subplots(figsize=(5, 4))
        for j, label in enumerate(f"{q}, t = {t * 1e3:g} ms" for t in WAVE_TIMES for q in ("vx", "stress")):
            have = [r for r in rows if len(r["errors"]) > j]
            ax.loglog([r["cfl"] for r in have], [r["errors"][j] for r in have], "o-", label=label)
        first = rows[0]
        ax.loglog([r["cfl"] for r in rows], [first["errors"][0] * (r["cfl"] / first["cfl"]) ** 2
                                             for r in rows], "k:", label="C^2")
        for r in rows:
            if not r["stable"]:
                ax.axvline(r["cfl"], color="r", ls="--", lw=0.8)
        ax.set_xlabel("C")
        ax.set_ylabel("error / amplitude")
        ax.set_title(f"elastic wave (dashed: unstable within {WAVE_LONG:g} s)", fontsize=9)
        ax.legend(fontsize=7)
        report.figure(fig, args.runner, "cfl", args.cfl_report + "_wave.png", "wave errors")
    return rows, limit


def cfl_column(args, report):
    """The column collapse (a = 0.5, one resolution) with `cfl C` through the input's
    fix_options, each model: the deposit against the smallest C."""
    r0, a = 0.2, 0.5
    ppr = args.ppr[0]
    dx = r0 / ppr
    report.append(f"## 2. Column collapse, a = {a}, {ppr} particles per radius\n")
    report.append(f"examples/column_collapse/in.column_collapse, r0 = {r0} m, dx = {dx:.6g} m, "
                  "`-var fix_options \"cfl C\"`, run to rest as in the convergence study "
                  "(validation/convergence/convergence.md: the same columns): the deposit edge r_edge = "
                  "(r_inf - r0)/r0, h_inf/r0, r95, the skirt beyond the edge, with the changes "
                  f"against C = {args.cfl[0]}. The run ends at rest, checked every 1000 steps, so "
                  "steps and t at rest move in steps of 1000.\n")
    results = {}
    for model in args.models:
        report.append(f"### {model}\n")
        report.append("| C | grains | steps | wall time (s) | t at rest (s) | r_edge | change | "
                      "h_inf/r0 | change | r95 | change | outermost | skirt | off the floor |")
        report.append("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
        rows = results[model] = []
        for cfl in args.cfl:
            variables = {"a": a, "model": model, "dx": f"{dx:.6g}", "fix_options": cfl_keywords(args, cfl)}
            words, workdir = args.runner.run("column_collapse", variables, args.ranks,
                                 cfl_tag(args, f"collapse_{model}_ppr{ppr}", cfl), may_fail=True)
            if words is None:
                rows.append({"cfl": cfl, "stable": False, "why": failure(workdir)})
                report.append(f"| {cfl} | - | - | {wall_time(workdir):.0f} | unstable: {rows[-1]['why']} |"
                              + " - |" * 9)
                continue
            r = {"cfl": cfl, "stable": True, "wall": wall_time(workdir),
                 **{k: number_after(words, key) for k, key in
                    (("edge", "(r_inf-r0)/r0"), ("height", "h_inf/r0"), ("r95", "r95"),
                     ("outermost", "outermost"), ("skirt", "skirt"), ("t", "t"),
                     ("steps", "steps"), ("grains", "grains"), ("off", "off_floor"))}}
            rows.append(r)
            ref = next(x for x in rows if x["stable"])
            change = lambda key: f"{100 * (r[key] - ref[key]) / ref[key]:+.1f}%"   # noqa: E731
            report.append(f"| {cfl} | {int(r['grains'])} | {int(r['steps'])} | {r['wall']:.0f} | "
                          f"{r['t']:.3f} | {r['edge']:.3f} | {change('edge')} | {r['height']:.3f} | "
                          f"{change('height')} | {r['r95']:.3f} | {change('r95')} | "
                          f"{r['outermost']:.3f} | {100 * r['skirt']:.2f}% | {int(r['off'])} |")
            report.write("cfl/" + args.cfl_report + ".md")
        report.append("")
    return results


def cfl_flume(args, report):
    """The flume impact at one spacing, Drucker-Prager, to 1 s, with `cfl C`: the first
    impact and the largest 20 ms mean force against the smallest C; with --replicas, each C
    again with the grains displaced at random by --perturb of a spacing, to set the change
    with C beside the change that so small a perturbation alone makes."""
    tend, dx, model = args.tend, args.dx[0], "elastoplastic"
    report.append(f"## 3. Flume impact, dx = {dx} m, {model}, to t = {tend} s\n")
    report.append("examples/flume_impact/in.flume_impact, `-var fix_options \"cfl C\"`, "
                  "as in validation/flume/flume_convergence.md: the wall force's largest "
                  f"sample (every 100 steps), its largest {1000 * FORCE_WINDOW:.0f} ms mean, the "
                  f"first impact (force > 5 N), the impulse to t = {tend:g} s, with the changes against "
                  f"C = {args.cfl[0]}. For scale, flume_convergence.md's Drucker-Prager 20 ms "
                  f"means spread over {FLUME_SPREAD:.0f} N (92 to 104 N) and its first impacts over "
                  f"{FLUME_IMPACT_SPREAD:.3f} s across dx = 0.03 to 0.0167 m.\n")
    if args.replicas > 1:
        report.append(f"Each C is run {args.replicas} times: replica 0 as the input stands, replica k "
                      f"with every grain displaced at random by up to {args.perturb:g} of a spacing "
                      f"along each axis (`-var perturb {args.perturb:g} -var seed k`): the spread of "
                      "the replicas is how far so small a perturbation alone moves a result of "
                      "this flow.\n")
    report.append("| C | replica | grains | steps | wall time (s) | largest sample (N) | at t (s) | "
                  "largest 20 ms mean (N) | change (N) | at t (s) | first impact (s) | change (s) | "
                  "impulse (N s) |")
    report.append("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    rows = []
    fig, ax = plt.subplots(figsize=(7, 4))
    for cfl in args.cfl:
        runs = []
        for k in range(args.replicas):
            variables = {"model": model, "dx": dx, "tend": tend, "fix_options": cfl_keywords(args, cfl)}
            if k:
                variables.update(perturb=args.perturb, seed=k)
            words, workdir = args.runner.run("flume_impact", variables, args.ranks,
                                 cfl_tag(args, "flume", cfl) + (f"_replica{k}" if k else ""),
                                 may_fail=True)
            if words is None:
                runs.append({"cfl": cfl, "stable": False, "why": failure(workdir)})
                report.append(f"| {cfl} | {k} | - | - | {wall_time(workdir):.0f} | unstable: "
                              f"{runs[-1]['why']} |" + " - |" * 7)
                continue
            t, f = force_history(workdir)
            mean_peak, mean_at, impulse = windowed_peak(t, f)
            r = {"cfl": cfl, "stable": True, "mean": mean_peak, "sample": number_after(words, "peak_force"),
                 "first": number_after(words, "first_impact"), "impulse": impulse,
                 "steps": int(number_after(words, "steps")), "wall": wall_time(workdir)}
            runs.append(r)
            ref = next((x for x in rows + runs if x["stable"]), r)
            report.append(f"| {cfl} | {k} | {int(number_after(words, 'grains'))} | {r['steps']} | "
                          f"{r['wall']:.0f} | {r['sample']:.0f} | {number_after(words, 'at'):.3f} | "
                          f"{mean_peak:.0f} | {mean_peak - ref['mean']:+.0f} | {mean_at:.3f} | "
                          f"{r['first']:.3f} | {r['first'] - ref['first']:+.3f} | {impulse:.1f} |")
            if k == 0:
                ax.plot(t, f, lw=0.7, label=f"C = {cfl}")
            report.write("cfl/" + args.cfl_report + ".md")
        rows.append(dict(runs[0], replicas=[r for r in runs if r["stable"]]))
    if args.replicas > 1:
        report.append("\nThe replicas of each C: the smallest and largest of each measure, and the "
                      "spread (largest - smallest).\n")
        report.append("| C | stable replicas | largest 20 ms mean (N) | spread (N) | largest sample (N) | "
                      "spread (N) | first impact (s) | spread (s) | impulse (N s) | spread (N s) |")
        report.append("|---|---|---|---|---|---|---|---|---|---|")
        for r in rows:
            cells = []
            for key, form in (("mean", ".0f"), ("sample", ".0f"), ("first", ".3f"), ("impulse", ".1f")):
                values = [x[key] for x in r["replicas"]]
                cells += ([f"{min(values):{form}} to {max(values):{form}}",
                           f"{max(values) - min(values):{form}}"] if values else ["-", "-"])
            report.append(f"| {r['cfl']} | {len(r['replicas'])} of {args.replicas} | " + " | ".join(cells) + " |")
    ax.set_xlabel("t (s)")
    ax.set_ylabel("normal force on the wall (N)")
    ax.set_title(f"flume impact, dx = {dx} m, {model}", fontsize=9)
    ax.legend(fontsize=7)
    report.figure(fig, args.runner, "cfl", args.cfl_report + "_flume.png", "force histories",
                  before="\n")
    return rows


def replica_mean(row, key):
    """the mean of a measure over a flume row's replicas (the row's own without replicas)"""
    values = [x[key] for x in row.get("replicas", [])] or [row[key]]
    return sum(values) / len(values)


def cfl_study(args, report):
    """The parts of the CFL study (args.cfl_parts), then a summary per C: stable or not,
    and within the tolerances of the smallest C or not."""
    summary, limit = {}, None
    if "wave" in args.cfl_parts:
        summary["wave"], limit = cfl_wave(args, report)
        report.write("cfl/" + args.cfl_report + ".md")
    if "column" in args.cfl_parts:
        summary.update(cfl_column(args, report))
    if "flume" in args.cfl_parts:
        summary["flume"] = cfl_flume(args, report)
    report.append("## Summary\n")
    report.append(f"Against the smallest C ({args.cfl[0]}) of each part; the wave against its "
                  f"reference (C = {WAVE_REFERENCE_CFL}), its errors as a multiple of those at "
                  "C = 0.2. Tolerances: r_edge and h_inf/r0 within "
                  f"{100 * EDGE_TOLERANCE:.0f}%, the flume's 20 ms mean within {FLUME_SPREAD:.0f} N "
                  f"and its first impact within {FLUME_IMPACT_SPREAD:.3f} s (the spreads of "
                  "flume_convergence.md).\n")
    names = {"wave": "elastic wave", "flume": "flume"}
    report.append("| C | steps against C = 0.2, each part | " + " | ".join(names.get(p, f"column, {p}") for p in summary)
                  + " | within the tolerances |")
    report.append("|---|---|" + "---|" * (len(summary) + 1))
    default = {part: next((r for r in rows if r["cfl"] == 0.2 and r["stable"]), None)
               for part, rows in summary.items()}
    passed = {}
    for k, cfl in enumerate(args.cfl):
        cells, ok = [], True
        for part, rows in summary.items():
            r, ref = rows[k], next((x for x in rows if x["stable"]), None)
            if not r["stable"]:
                cells.append(f"unstable ({r['why']})")
                ok = False
            elif part == "wave":
                cells.append("stable" + (f", errors x{max(r['errors']) / max(default[part]['errors']):.2f} "
                                         "of C = 0.2's" if default[part] else ""))
            elif part == "flume":    # with replicas, their means
                df, dt = (replica_mean(r, key) - replica_mean(ref, key) for key in ("mean", "first"))
                ok &= abs(df) <= FLUME_SPREAD and abs(dt) <= FLUME_IMPACT_SPREAD
                cells.append(f"20 ms mean {df:+.0f} N, first impact {dt:+.3f} s" +
                             (f" (means of {len(r['replicas'])} replicas; theirs "
                              f"{min(x['mean'] for x in r['replicas']):.0f} to "
                              f"{max(x['mean'] for x in r['replicas']):.0f} N)" if len(r["replicas"]) > 1 else ""))
            else:
                de, dh = (r[key] / ref[key] - 1 for key in ("edge", "height"))
                ok &= abs(de) <= EDGE_TOLERANCE and abs(dh) <= EDGE_TOLERANCE
                cells.append(f"r_edge {100 * de:+.1f}%, h {100 * dh:+.1f}%")
        steps = [f"{r['steps'] / default[p]['steps']:.2f}" if r["stable"] and default[p] else "-"
                 for p, r in ((p, rows[k]) for p, rows in summary.items())]
        report.append(f"| {cfl} | {' / '.join(steps)} | "
                      + " | ".join(cells) + f" | {'yes' if ok else 'no'} |")
        passed[cfl] = ok
    report.append("")
    cfl_conclusion(args, report, summary, passed, limit, default)


def cfl_conclusion(args, report, summary, passed, limit, default):
    """The study's answer in numbers, and what a change of the default would need."""
    report.append("## Conclusion\n")
    largest = None
    for cfl in args.cfl:    # the largest C up to which every C of the list passes
        if not passed[cfl]:
            break
        largest = cfl
    if limit:
        report.append(f"- The elastic wave is stable to {WAVE_LONG:g} s ({WAVE_LONG / WAVE_TIMES[0]:.0f} "
                      f"periods) up to C = {limit[0]} and not from C = {limit[1]}; its errors grow as "
                      "C^2 below that (the orders above).")
    if largest is None:
        report.append(f"- Already the smallest C of the list, {args.cfl[0]}, fails a part.")
    else:
        report.append(f"- Every part is stable and within the tolerances up to C = {largest}"
                      + ("." if largest == args.cfl[-1] else
                         f"; C = {args.cfl[args.cfl.index(largest) + 1]} is not (the summary's row)."))
    flume = {r["cfl"]: r for r in summary.get("flume", []) if r["stable"]}
    if largest and largest in flume and default.get("flume"):
        ratio = flume[largest]["steps"] / default["flume"]["steps"]
        report.append(f"- At C = {largest} the flume takes {ratio:.2f} of the steps and "
                      f"{flume[largest]['wall'] / default['flume']['wall']:.2f} of the wall time of "
                      f"C = 0.2; the paper's flume at dx = 10 mm to 3 s, 152,800 steps at C = 0.2 "
                      "(flume_convergence_paper_dx_3s.md), would take about "
                      f"{152800 * ratio:,.0f}.")
    report.append("\nThe integrators' defaults are given in doc/fix_sph_elastoplastic.rst "
                  "(Default) and validation/README.md (\"The CFL constant\") says which study "
                  "chose them. A new default C divides the steps of every run whose step the "
                  "sound speed bounds by C / C_before and moves its results within the changes "
                  "above; it takes the default in the source and the two doc pages, the example "
                  "logs regenerated, the test suite on both stacks (whose physics tests run at the "
                  "default), and a word in validation/README.md on the reports made before it.\n")
