# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""What the studies and the GPU check take from a flume run's wall force: its history,
its largest mean over a load cell's window and its integral."""

import os

FLUME_WIDTH = 0.25           # examples/flume_impact: the flume's width (m)
FORCE_WINDOW = 0.02          # s: the wall force averaged over this, as a load cell reads it


def force_history(workdir):
    """The wall's normal force of a flume run, as (times, forces) arrays."""
    import numpy as np
    return np.loadtxt(os.path.join(workdir, "flume_impact.force"), unpack=True)


def windowed_peak(t, f):
    """The largest mean of the force over FORCE_WINDOW and the middle of that window: a
    peak that does not grow with the sampling rate or the particles' noise, as the raw
    largest sample can."""
    import numpy as np
    keep = np.concatenate(([True], np.diff(t) > 0))    # the print repeats a run's first step
    t, f = t[keep], f[keep]
    # the trapezoidal integral up to each sample: a window's is the difference of two
    running = np.concatenate(([0.0], np.cumsum(0.5 * (f[1:] + f[:-1]) * np.diff(t))))
    start = np.nonzero(t + FORCE_WINDOW <= t[-1])[0]
    end = np.searchsorted(t, t[start] + FORCE_WINDOW, side="right") - 1
    start, end = start[end > start], end[end > start]    # a window with one sample has no mean
    means = (running[end] - running[start]) / (t[end] - t[start])
    if len(means) == 0 or means.max() <= 0.0:
        return 0.0, 0.0, integral(t, f)
    k = int(np.argmax(means))
    return float(means[k]), float(t[start[k]] + 0.5 * FORCE_WINDOW), integral(t, f)


def integral(t, f):
    """The trapezoidal integral of samples f(t)."""
    return float(sum(0.5 * (f[1:] + f[:-1]) * (t[1:] - t[:-1])))

