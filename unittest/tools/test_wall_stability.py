#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""tools/research/wall-stability: the linear stability of a layer at rest on a dummy floor.

Checks the analysis that validation/README.md ("The rough floor's thinnest layer")
rests on, for a monolayer on a 20-degree slope, 8 columns, dx 0.02:
- at rest, the rates balance: under wall/stress ratio the grains carry the slope's
  stress ratio tan(theta), as the wall rule means them to;
- wall/stress paper is neutral, wall/stress ratio grows (the styles' known limit), and
  the adjoint and frozen designs together are neutral again.

The module is gransph.wall_stability (ctest runs this with tools/lib on PYTHONPATH, as the
launcher tools/research/wall-stability does):

  PYTHONPATH=tools/lib /usr/bin/python3 unittest/tools/test_wall_stability.py
"""
import argparse
import math
import unittest

from gransph import wall_stability

THETA = 20.0
NEUTRAL = 1.0      # 1/s: below this a mode does not grow within any run (5e-5 per step)
UNSTABLE = 100.0   # 1/s: 0.5% per step at cfl 0.2, e-folding in 200 steps


def analyse(wall_stress, design=()):
    args = argparse.Namespace(layers=1, columns=8, theta=THETA, dx=0.02,
                              wall_stress=wall_stress, material="Chen2019", design=design)
    return wall_stability.analyse(args)


class TestWallStability(unittest.TestCase):
    def test_ratio_wall_carries_the_slope(self):
        p, _, _ = analyse("ratio")
        self.assertAlmostEqual(p[1] / -p[0], math.tan(math.radians(THETA)), places=6)

    def test_paper_wall_is_neutral(self):
        _, lam, _ = analyse("paper")
        self.assertLess(lam.real, NEUTRAL)

    def test_ratio_wall_grows(self):
        _, lam, dt = analyse("ratio")
        self.assertGreater(lam.real, UNSTABLE, f"growth {lam.real} 1/s")
        self.assertGreater(lam.real * dt, 0.005)

    def test_adjoint_frozen_design_is_neutral(self):
        _, lam, _ = analyse("ratio", ("adjoint", "frozen"))
        self.assertLess(lam.real, NEUTRAL)


if __name__ == "__main__":
    unittest.main()
