"""The strength of the Drucker-Prager sand against its dummy floor: a layer on a
slope holds below the angle the model predicts and slides above it.

With no dilatancy (psi = 0) the plastic flow is coaxial and deviatoric, so in the
simple shear of a layer on a slope s_yy = 0 and Drucker-Prager's
sqrt(J2) = 3 alpha_phi |s_m| (plane-strain matching, alpha_phi = tan(phi) /
sqrt(9 + 12 tan^2 phi)) puts the largest shear stress, R = 3 alpha_phi |s_m|, on the
planes parallel to the slope: the layer holds while tan(theta) < 3 alpha_phi. For the
Chen2019 sand (phi = 37 deg) that is 29.6 deg, well below phi itself."""

import math
import os
import tempfile

import gransph_run

HERE = os.path.dirname(os.path.abspath(__file__))
PHI = math.radians(37.0)
ALPHA = math.tan(PHI) / math.sqrt(9.0 + 12.0 * math.tan(PHI) ** 2)
THRESHOLD = math.degrees(math.atan(3.0 * ALPHA))
check = gransph_run.Checks()


def acceleration(tmp, theta):
    """mean velocity down the slope at the end, and its mean rate of change"""
    out = gransph_run.run(os.path.join(HERE, "in.slope"), {"theta": theta}, cwd=tmp)
    words = gransph_run.result_line(out)
    t1, vx1, t2, vx2 = (float(words[i]) for i in (4, 6, 8, 10))
    return vx2, (vx2 - vx1) / (t2 - t1)


with tempfile.TemporaryDirectory() as tmp:
    below, above = THRESHOLD - 3.0, THRESHOLD + 3.5
    vx, a = acceleration(tmp, below)
    check(f"holds at {below:.1f} deg (threshold {THRESHOLD:.1f})", abs(vx) < 1e-3 and abs(a) < 0.02,
          f"v {vx:.2e} m/s, a {a:.2e} m/s^2")
    vx, a = acceleration(tmp, above)
    check(f"slides at {above:.1f} deg", a > 0.2, f"v {vx:.3f} m/s, a {a:.3f} m/s^2")
check.finish()
