# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
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
hardest case, also on strips of other widths (--widths, default 4,16).
The material is Chen2019's sand (phi = 37 deg) or, with --material Sand25, the same sand
at phi = 25 deg (sand25.gransph; slide angles 22.3 deg plane-strain, 25.0 simple shear,
25.0 phase change).

Known limits, which the registered tests leave out (unittest/CMakeLists.txt). The layer
starts on a perfect lattice, so only round-off breaks its symmetry; --seed N displaces the
grains at random by up to 1e-4 dx along and across the slope first, which seeds every
mode a strip can hold. Seeded (--seed 1 --widths 4,8,16, 42 checks each):
- a monolayer held 1.5 degrees below its slide angle slips on strips of 8 and 16 columns
  (15 of the 16 such checks of the four configurations with the plane-strain matching or
  the phase change, both materials and spacings: up to 4 cm/s and 0.23 m/s^2 by 0.3 s;
  strips of 4 and 6 hold), through a stress wave 8 columns long that travels along the
  slope, in which the stretched grains' sigma_xx falls to zero (the cone's apex) and with
  it their shear strength. Without the seed the same run holds or slips by the last digit
  of theta (Chen2019, Drucker-Prager, 16 columns: slips at 28.1172 degrees, holds at
  28.11724501573419, the registered case). The cause is the floor, not the material: the
  default wall/stress ratio makes a layer at rest on a dummy floor linearly unstable, level
  or tilted, below yield too (a layer of phi = 60 degrees breaks up the same way, and
  holds only because it stays below yield), while wall/stress paper (whose monolayer
  slides at 18 degrees) is neutral: validation/README.md, "The rough floor's thinnest
  layer", and tools/research/wall-stability, which finds the growth from the equations alone and a
  design stable at rest (not yet sliding where the material does). Layers of 2 grow the
  same pattern but hold (32 columns); with a dilatancy angle of 5 degrees (a trial
  material, not kept) the seeded monolayer holds on 8 and 16 columns at both spacings
  (rising by 0.02 dx).
  With --pair "gradient corrected" 38 of the 40 monolayer hold checks of the five
  configurations below pass (25 with the default gradient); the other two creep at 2-3
  mm/s, accelerating at 0.02-0.03 m/s^2;
- under the simple-shear matching, and under the phase change, a layer of 8 particles held
  1.5 degrees below its slide angle slips (0.13 / 0.08 m/s under simple shear, 0.04 /
  0.02 m/s under the phase change, dx 0.02 / 0.01), with either gradient;
- under the phase-change model a monolayer of Chen2019 1.5 degrees above its slide angle
  slides at about the check's threshold, half of free sliding at mu_s (0.153 m/s^2; mu(I)
  rises with the shear rate): 0.141 on a strip of 4 (dx 0.02, failed), 0.14-0.15 on strips
  of 6 and 16 with the corrected gradient (failed); unseeded 0.55-0.58 on a strip of 16.
Floors with a friction of their own below the sand's (in.wall_friction, where the grains
stay below yield) hold seeded as well: delta 15 and 25 degrees, 1 and 4 layers, strips of
6 to 16, both models, five cases tried by hand (in.wall_friction has no seed option).
Seeded results: default gradient 38 / 40 / 36 / 38 / 38 of 42 checks passed for
Drucker-Prager, its simple-shear matching, the phase change, Sand25 Drucker-Prager and
Sand25 phase change; gradient corrected 41 / 40 / 37 / 42 / 39.

--stick puts the layer on a floor of Coulomb friction at the slide angle the model
declares, holding its grains as contacts do (pair_style sph/granular wall/friction floor
material wall/friction/hold stick; the floor's dummies get their normal, +z). Seeded, it
holds and slides as declared where the rough floor does not: Chen2019 Drucker-Prager,
Sand25 Drucker-Prager and Sand25 phase change 42 of 42 checks; Chen2019 phase change and
simple-shear matching 40 of 42, the two failures the held layer of 8 above (its own
yield, not the floor's); sliding monolayers at 0.290-0.296 m/s^2 against the free
sliding's 0.295 (Chen2019 Drucker-Prager).

--push V starts the layer sliding down the slope at V m/s (held: it must stop; at dx 0.01
the runs end at 0.16 s, so a push above about 2 cm/s has not stopped by then). With
--stick --push 0.02 (Chen2019, Drucker-Prager, seeded, --widths 16) 29 of 30 checks pass:
the layer of 8 at dx 0.01 held 1.5 degrees below keeps creeping (1.4 cm/s, +0.08 m/s^2),
where on the rough floor it stops (0.1 mm/s): a known limit of the contact floor, not
registered. The layers of 1 and 4 (--layers 1,4) pass pushed, seeded, on strips of 4 to 16:
Chen2019 Drucker-Prager, Chen2019 phase change and Sand25 phase change 30 of 30 each
(ctest Physics:slope:stick_push and Physics:slope:stick_push_sand25_phasechange).

  test_slope.py [--material Chen2019|Sand25] [--widths 4,8,16] [--layers 1,2,4,8]
                [--seed N] [--stick] [--push V] [--pair "pair keywords"]
                MODEL [fix keywords ...]

--layers: the thicknesses on the strip of 6 (default 1,2,4,8).
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


def run(tmp, model, options, material, layers, columns, dx, theta, seed, pair_options, push):
    """velocity down the slope at the end, its mean rate of change, mean height"""
    out = gransph_run.run(os.path.join(HERE, "in.slope"),
                          {"theta": theta, "model": model, "layers": layers, "dx": dx,
                           "columns": columns, "material": material,
                           "materials": MATERIALS[material][0], "seed": seed, "push": push,
                           "fix_options": " ".join(options),
                           "pair_options": pair_options,
                           "wall_normals": int("wall/friction" in pair_options)}, cwd=tmp)
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
    seed, pair_options = 0, ""
    if "--seed" in args:
        k = args.index("--seed")
        seed = int(args[k + 1])
        del args[k:k + 2]
    if "--pair" in args:
        k = args.index("--pair")
        pair_options = args[k + 1]
        del args[k:k + 2]
    stick = "--stick" in args
    if stick:
        args.remove("--stick")
    push = 0.0
    if "--push" in args:
        k = args.index("--push")
        push = float(args[k + 1])
        del args[k:k + 2]
    thicknesses = (1, 2, 4, 8)
    if "--layers" in args:
        k = args.index("--layers")
        thicknesses = tuple(int(n) for n in args[k + 1].split(","))
        del args[k:k + 2]
    model, options = args[0], args[1:]
    threshold = slide_angle(model, options, material)
    if stick:    # a Coulomb floor at the model's slide angle, holding grains as contacts do
        pair_options += " wall/friction floor material wall/friction/hold stick"
    below, above = threshold - 1.5, threshold + 1.5
    # sliding freely, a = g (sin - mu cos) at the slide angle's friction mu
    mu = math.tan(math.radians(threshold))
    a_free = 9.81 * (math.sin(math.radians(above)) - mu * math.cos(math.radians(above)))
    check = gransph_run.Checks()
    cases = [(layers, 6) for layers in thicknesses] + [(1, w) for w in widths]
    with tempfile.TemporaryDirectory() as tmp:
        for dx in (0.02, 0.01):
            for layers, columns in cases:
                case = f"{material}, {layers} layer(s), {columns} columns, dx {dx}"
                geometry = (layers, columns, dx)
                vx, a, z_held = run(tmp, model, options, material, *geometry, below, seed,
                                    pair_options, push)
                check(f"{case}: holds at {below:.1f} deg (slide angle {threshold:.1f})",
                      abs(vx) < 0.01 and abs(a) < 0.02, f"v {vx:.2e} m/s, a {a:.2e} m/s^2")
                vx, a, z_sliding = run(tmp, model, options, material, *geometry, above, seed,
                                       pair_options, push)
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
