# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""A study's report: Markdown lines, written under the output folder with the run time so
far (a study writes it after each part, complete at the end), and its figures (laid out,
saved at one resolution, shown in the report)."""

import datetime
import os


class Report(list):
    """the lines of one report; write() puts them, and the minutes since `started`, into
    the file `name` under `root`"""

    def __init__(self, root, started, lines=()):
        super().__init__(lines)
        self.root = root
        self.started = started

    def write(self, name="report.md"):
        minutes = (datetime.datetime.now() - self.started).total_seconds() / 60
        path = os.path.join(self.root, name)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "w") as f:
            f.write("\n".join(list(self) + [f"\nRun time so far: {minutes:.1f} min."]) + "\n")
        print(f"[validate] wrote {path} ({minutes:.1f} min)", flush=True)

    def figure(self, fig, runner, folder, name, alt, before=""):
        """save fig as `name` in the study's folder of the runner's output (save_figure)
        and show it in the report, which is written into that folder: a line
        `before![alt](name)`"""
        save_figure(fig, runner.out(folder, name))
        self.append(f"{before}![{alt}]({name})\n")


def save_figure(fig, path):
    """a study's figure, laid out, written to path at the reports' resolution"""
    fig.tight_layout()
    fig.savefig(path, dpi=120)


def machine(args):
    """how the runs ran, for a report's first lines"""
    return (f"the /kk styles on {args.ranks} OpenMP thread(s)" if args.kokkos
            else f"{args.ranks} MPI rank(s)")

