# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""Several materials in one run (the integrator fixes' keyword material GROUP FILE
NAME), on the layered strip of in.layers:

- split: the lower layers given the fix's own material through the keyword run as the
  one-material run to the bit, for both models, plain, /kk on 2 threads and on 2 MPI
  ranks; a lower layer of another material does change the run (the check is not
  vacuous), and that run agrees across plain, /kk and 2 ranks to round-off;
- weak layer: a sand of phi = 37 deg over two layers of a sand of phi = 25 deg
  (Drucker-Prager under matching simple_shear; the phase change, mu_s = tan 25 deg) on a
  floor of the grains' own Coulomb friction holds at 23 degrees and slides at 27 along
  the weak layer, the upper sand riding on it (sheared less than the weak layer), where
  the strip without the weak layer holds;
- two densities: a light sand (1500 kg/m3) on a heavy one (2450) at rest loads the
  floor with sum rho_k g h_k within 2%, each sand at its own density within 1%.
Run with --only split|weak|densities for one part."""

import argparse
import os
import tempfile

import numpy as np

import gransph_run

HERE = os.path.dirname(os.path.abspath(__file__))
LAYERS = os.path.join(HERE, "in.layers")
SAND25 = os.path.join(HERE, "sand25.gransph")
LIGHT = os.path.join(HERE, "light.gransph")
KOKKOS = ["-k", "on", "t", "2", "-sf", "kk"]
MODELS = {"elastoplastic": "matching simple_shear", "phasechange": ""}


def layers(variables, cwd, args=(), ranks=1):
    """Run in.layers; its result line as a dict, and its final dump if it wrote one."""
    out = gransph_run.run(LAYERS, {"lower_matfile": SAND25, **variables}, ranks=ranks,
                          args=args, cwd=cwd)
    words = gransph_run.result_line(out)
    names = ["vx_lower", "vx_base", "vx_top", "rho_lower", "rho_upper", "stress", "weight"]
    result = dict(zip(names, map(float, words[3:])))
    if variables.get("dump"):
        result["dump"] = gransph_run.read_dump(os.path.join(cwd, "layers.dump"))
    return result


def identical(a, b):
    """Whether two dumps hold the same atoms with the same values, to the bit."""
    return all(np.array_equal(a[name], b[name]) for name in a)


def check_split(check, tmp):
    for model in MODELS:
        base = {"model": model, "theta": 35, "time": 0.03, "window": 0.01, "dump": 1}
        for label, args, ranks in (("plain", [], 1), ("kk", KOKKOS, 1), ("2 ranks", [], 2)):
            one = layers({**base, "lower_is": "fix"}, tmp, args, ranks)["dump"]
            split = layers({**base, "lower_is": "same"}, tmp, args, ranks)["dump"]
            moved = np.max(np.abs(one["vx"]))
            check(f"{model} {label}: one material in two groups = one group", identical(one, split)
                  and moved > 1e-3, f"identical {identical(one, split)}, max |vx| {moved:.3g}")
            if label == "kk":
                assert "sph/granular/kk" in gransph_run.LAST_OUTPUT, "the Kokkos pair style was not used"
        two = {label: layers({**base, "lower_is": "other"}, tmp, args, ranks)["dump"]
               for label, args, ranks in (("plain", [], 1), ("kk", KOKKOS, 1), ("2 ranks", [], 2))}
        changed = np.max(np.abs(two["plain"]["vx"] - one["vx"]))
        check(f"{model}: a lower layer of Sand25 changes the run", changed > 1e-6,
              f"max |vx - vx of one material| {changed:.3g}")
        for label in ("kk", "2 ranks"):    # by group: vy, sigma_xy, sigma_yz are round-off
            for group, diff in gransph_run.state_differences(two["plain"], two[label]).items():
                check(f"{model} two materials plain - {label} {group}", diff < 1e-10,
                      f"max difference / max value = {diff:.2e}")


def check_weak_layer(check, tmp):
    for model, options in MODELS.items():
        for theta, slides in ((23, False), (27, True)):
            r = layers({"model": model, "fix_options": options, "theta": theta, "contact": 1},
                       tmp)
            dx, layers_, lower = 0.02, 8, 2
            weak_shear = r["vx_base"] / (lower * dx)    # the floor at rest
            upper_shear = (r["vx_top"] - r["vx_base"]) / ((layers_ - lower - 1) * dx)
            detail = (f"vx lower {r['vx_lower']:.4f} base {r['vx_base']:.4f} top {r['vx_top']:.4f}"
                      f" m/s; shear rate weak {weak_shear:.3f}, upper {upper_shear:.3f} 1/s")
            if slides:
                check(f"{model} {theta} deg: slides along the weak layer, the upper sand riding",
                      r["vx_base"] > 0.04 and abs(upper_shear) < 0.25 * weak_shear, detail)
            else:
                check(f"{model} {theta} deg: holds", max(abs(r["vx_top"]), abs(r["vx_lower"])) < 0.01,
                      detail)
        # without the weak layer the same strip holds at 27 degrees: the weak layer slides
        r = layers({"model": model, "fix_options": options, "theta": 27, "contact": 1,
                    "lower_is": "fix"}, tmp)
        check(f"{model} 27 deg: holds without the weak layer", abs(r["vx_top"]) < 0.01,
              f"vx top {r['vx_top']:.4f} m/s")


def check_two_densities(check, tmp):
    for model in MODELS:
        r = layers({"model": model, "matfile": LIGHT, "material": "Light1500", "rho": 1500,
                    "lower_matfile": os.path.join(gransph_run.TOP, "potentials", "sand.gransph"),
                    "lower_material": "Chen2019", "rho_lower": 2450, "lower_layers": 3,
                    "time": 0.25, "window": 0.1}, tmp)
        ratio = r["stress"] / r["weight"]
        check(f"{model}: floor stress = sum rho_k g h_k", abs(ratio - 1.0) < 0.02,
              f"{r['stress']:.1f} Pa against {r['weight']:.1f} Pa ({ratio:.4f})")
        check(f"{model}: each sand at its own density",
              abs(r["rho_lower"] / 2450 - 1) < 0.01 and abs(r["rho_upper"] / 1500 - 1) < 0.01,
              f"lower {r['rho_lower']:.1f}, upper {r['rho_upper']:.1f} kg/m3")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--only", choices=["split", "weak", "densities"])
    only = parser.parse_args().only
    check = gransph_run.Checks()
    with tempfile.TemporaryDirectory() as tmp:
        if only in (None, "split"):
            check_split(check, tmp)
        if only in (None, "weak"):
            check_weak_layer(check, tmp)
        if only in (None, "densities"):
            check_two_densities(check, tmp)
    check.finish()


if __name__ == "__main__":
    main()
