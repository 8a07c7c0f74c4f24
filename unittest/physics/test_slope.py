"""Basal friction of layers of any thickness: a sand layer of 1, 2, 4 or 8 particles
on its dummy floor, at two resolutions, holds on a slope 1.5 degrees below the slide
angle its model declares and slides 1.5 degrees above it, without floating off or
sinking into the floor while it slides.

The declared slide angles (doc/fix_sph_elastoplastic.rst, doc/fix_sph_phasechange.rst):
with no dilatancy Drucker-Prager's flow is coaxial and deviatoric, so in the steady
simple shear of a layer on a slope the normal stresses are equal and the layer holds
while tan(theta) < 3 alpha_phi: atan(3 alpha_phi) = 29.6 deg for phi = 37 deg under the
plane-strain matching (the paper's), phi itself under the simple-shear matching. The
phase-change model slides above atan(mu_s).

Holding means not accelerating (|a| < 0.02 m/s^2, against the 0.3 m/s^2 of free sliding
1.5 degrees above the slide angle) at a speed left from loading the stress-free layer
below 0.01 m/s: a single particle layer creeps at a few mm/s after its loading, by more
the closer the slope is to the slide angle (0.2 mm/s at 15 degrees, 3.9 mm/s at 28.1 for
plane-strain Drucker-Prager at dx = 0.02), where two layers and more stop within 0.5 mm/s.

Every thickness on a strip 6 particles square, and the monolayer, a rough floor's
hardest case, also on strips of 4 and 16 particles (--widths 4,16).
The material is Chen2019's sand (phi = 37 deg) or, with --material Sand25, the same sand
at phi = 25 deg (sand25.gransph; slide angles 22.3 deg plane-strain, 25.0 simple shear,
25.0 phase change).

Known limits of the monolayer on a rough floor, which the registered tests leave out
(unittest/CMakeLists.txt): on a strip of 16, 1.5 degrees below its slide angle, a
monolayer of Sand25 slips for a while under either model (up to 4 cm/s by 0.6 s under
Drucker-Prager, slowing after) through a mode 8 particles long, in which grains stretched
along the slope reach the cone's apex and lose their stress; strips of 4 and 6 cannot hold
that mode, and at 18 degrees the strip of 16 holds (1.3 mm/s). Under the phase-change
model a monolayer of Chen2019 1.5 degrees above its slide angle slides at 0.14 m/s^2 on a
strip of 4 at dx = 0.02 (half of free sliding at mu_s is 0.15), and on a strip of 16 at
0.55-0.58 m/s^2, faster than free sliding at mu_s (0.31).

  test_slope.py [--material Chen2019|Sand25] [--widths 4,16] MODEL [fix keywords ...]
"""

import math
import os
import sys
import tempfile

import gransph_run

HERE = os.path.dirname(os.path.abspath(__file__))
# the materials of the test: name, file, friction angle phi, the phase-change model's mu_s
MATERIALS = {"Chen2019": ("sand.gransph", 37.0, 0.6419),
             "Sand25": (os.path.join(HERE, "sand25.gransph"), 25.0, 0.4663)}


def slide_angle(model, options, material):
    _, phi_deg, mu_s = MATERIALS[material]
    phi = math.radians(phi_deg)
    if model == "phasechange":
        return math.degrees(math.atan(mu_s))
    if "simple_shear" in options:
        return phi_deg
    alpha = math.tan(phi) / math.sqrt(9.0 + 12.0 * math.tan(phi) ** 2)
    return math.degrees(math.atan(3.0 * alpha))


def run(tmp, model, options, material, layers, columns, dx, theta):
    """velocity down the slope at the end, its mean rate of change, mean height"""
    out = gransph_run.run(os.path.join(HERE, "in.slope"),
                          {"theta": theta, "model": model, "layers": layers, "dx": dx,
                           "columns": columns, "material": material,
                           "materials": MATERIALS[material][0],
                           "fix_options": " ".join(options)}, cwd=tmp)
    words = gransph_run.result_line(out)
    t1, vx1, t2, vx2, z1, z2 = (float(words[i]) for i in (4, 6, 8, 10, 12, 14))
    return vx2, (vx2 - vx1) / (t2 - t1), z2


def main():
    args = sys.argv[1:]
    material, widths = "Chen2019", (4, 16)
    if "--material" in args:
        k = args.index("--material")
        material = args[k + 1]
        del args[k:k + 2]
    if "--widths" in args:
        k = args.index("--widths")
        widths = tuple(int(w) for w in args[k + 1].split(","))
        del args[k:k + 2]
    model, options = args[0], args[1:]
    threshold = slide_angle(model, options, material)
    below, above = threshold - 1.5, threshold + 1.5
    # sliding freely, a = g (sin - mu cos) at the slide angle's friction mu
    mu = math.tan(math.radians(threshold))
    a_free = 9.81 * (math.sin(math.radians(above)) - mu * math.cos(math.radians(above)))
    check = gransph_run.Checks()
    cases = [(layers, 6) for layers in (1, 2, 4, 8)] + [(1, w) for w in widths]
    with tempfile.TemporaryDirectory() as tmp:
        for dx in (0.02, 0.01):
            for layers, columns in cases:
                case = f"{material}, {layers} layer(s), {columns} columns, dx {dx}"
                geometry = (layers, columns, dx)
                vx, a, z_held = run(tmp, model, options, material, *geometry, below)
                check(f"{case}: holds at {below:.1f} deg (slide angle {threshold:.1f})",
                      abs(vx) < 0.01 and abs(a) < 0.02, f"v {vx:.2e} m/s, a {a:.2e} m/s^2")
                vx, a, z_sliding = run(tmp, model, options, material, *geometry, above)
                check(f"{case}: slides at {above:.1f} deg", a > 0.5 * a_free,
                      f"v {vx:.3f} m/s, a {a:.3f} m/s^2 (free sliding {a_free:.3f})")
                # the gravity's normal component differs by cos(above)/cos(below) - 1 = 2%:
                # the elastic layer's height differs by far less than 0.05 dx
                check(f"{case}: the sliding layer keeps its height",
                      abs(z_sliding - z_held) < 0.05 * dx,
                      f"mean height {z_sliding / dx:.3f} dx sliding, {z_held / dx:.3f} dx held")
    check.finish()


if __name__ == "__main__":
    main()
