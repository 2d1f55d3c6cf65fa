#!/usr/bin/python3
"""Tests of the sharpness metric of tools/figure_metrics.py against blur and noise made here.

The texture is synthetic: sparse dark 4x4-pixel cells on white (reflectances 0.08 and 0.75, as
the far wall's letters), periodic so that blurring it has no border. The blur is a Gaussian
made here with numpy, independent of the metric; a Gaussian attenuates every spatial frequency
(exp(-(sigma w)^2 / 2) < 1 for w != 0), so the gradient energy of the blurred texture must fall
strictly as sigma grows. The noise is white Gaussian of a stated standard deviation, with
known expected gradient energy: forward differences of independent pixels of variance v have
variance 2v, in x and in y, so 4v per pixel.

PREVIEW_NOISE is the noise of the preview panels of tools/figures: the standard deviation of a
panel's luminance noise (from the difference of its two half-sample renders, divided by 2) in
the far-wall centre, over the texture's contrast there (1st to 99th percentile of the pinhole
reference's luminance). Measured 2026-11-22 on the 480x320, 32 spp panels: 0.015 (thin lens),
0.038 (Navarro 0 D), 0.050 (4 D), 0.054 (8 D, the noisiest).

  tests/tools/figure_metrics_test.py        (CTest: figure_metrics_test)
"""
import os
import sys
import unittest

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "tools"))
import figure_metrics as fm  # noqa: E402

DARK, BRIGHT = 0.08, 0.75
PREVIEW_NOISE = 0.054  # x (BRIGHT - DARK); see the header
BLURS = [0.0, 0.5, 1.0, 2.0, 4.0, 8.0]  # Gaussian sigma, pixels


def texture(n=256, cell=4, dark_fraction=0.2, seed=7):
    rng = np.random.default_rng(seed)
    cells = rng.random((n // cell, n // cell)) < dark_fraction
    return np.where(np.kron(cells, np.ones((cell, cell))) > 0, DARK, BRIGHT)


def gaussian_blur(img, sigma):
    """Separable Gaussian blur with periodic boundaries (the texture is periodic)."""
    if sigma == 0:
        return img.copy()
    r = int(np.ceil(4 * sigma))
    x = np.arange(-r, r + 1)
    k = np.exp(-0.5 * (x / sigma) ** 2)
    k /= k.sum()
    out = sum(w * np.roll(img, s, axis=0) for s, w in zip(x, k))
    return sum(w * np.roll(out, s, axis=1) for s, w in zip(x, k))


def interior(shape):
    """Pixels with both forward differences (gradient_energy leaves the last row/column 0)."""
    m = np.zeros(shape, bool)
    m[:-1, :-1] = True
    return m


class SharpnessMetric(unittest.TestCase):
    def setUp(self):
        self.sharp = texture()
        self.mask = interior(self.sharp.shape)
        self.blurred = [gaussian_blur(self.sharp, s) for s in BLURS]

    def test_blur_ranks_below_sharp_monotonically(self):
        s = [fm.sharpness(b, self.sharp, self.mask) for b in self.blurred]
        self.assertAlmostEqual(s[0], 1.0, places=12)
        for (b0, v0), (b1, v1) in zip(zip(BLURS, s), zip(BLURS[1:], s[1:])):
            self.assertLess(v1, v0, f"blur sigma {b1} px: sharpness {v1:.4g} not below {v0:.4g} at {b0} px")

    def test_preview_noise_does_not_flip_the_ranking(self):
        """20 noise realisations per image at the preview panels' noise level: the ranking by blur
        must survive every one of them."""
        sd = PREVIEW_NOISE * (BRIGHT - DARK)
        rng = np.random.default_rng(11)
        for trial in range(20):
            s = [fm.sharpness(b + rng.normal(0, sd, b.shape), self.sharp, self.mask) for b in self.blurred]
            for b1, v0, v1 in zip(BLURS[1:], s, s[1:]):
                self.assertLess(v1, v0, f"trial {trial}: noise {sd:.4f} flips blur {b1} px ({v1:.4g} vs {v0:.4g})")

    def test_noise_floor_is_the_expected_noise_energy(self):
        """Halves of per-pixel noise sd h: their mean has noise variance h^2/2, so expected
        gradient energy 4 h^2 / 2 = 2 h^2 per pixel, whatever the signal underneath."""
        h = 0.1
        rng = np.random.default_rng(3)
        for b in (self.blurred[0], self.blurred[3], np.full_like(self.sharp, 0.5)):
            panel = fm.PanelEnergy(b + rng.normal(0, h, b.shape), b + rng.normal(0, h, b.shape))
            estimate = panel.noise[self.mask].mean()
            # The mean of 65025 pixels' squared differences: relative sd below 1%; 4% is > 4 sd.
            self.assertAlmostEqual(estimate / (2 * h * h), 1.0, delta=0.04)
            # Take the floor away and the clean image's own gradient energy is left.
            clean = fm.gradient_energy(b)[self.mask].mean()
            self.assertAlmostEqual(panel.mean[self.mask].mean() - estimate, clean, delta=0.04 * 2 * h * h)

    def test_sigma_matches_the_scatter_over_seeds(self):
        """pool_sigma, from one pair of halves per panel, against the standard deviation of
        value - floor over 200 independent renders of the same panel (here: noise draws)."""
        h = PREVIEW_NOISE * (BRIGHT - DARK) * np.sqrt(2)  # halves: twice the panel's noise variance
        rng = np.random.default_rng(5)
        b = self.blurred[-1]  # near the floor, where the claim needs sigma
        e_ref = fm.gradient_energy(self.sharp)

        def one_panel():
            return fm.region_sharpness(fm.PanelEnergy(b + rng.normal(0, h, b.shape), b + rng.normal(0, h, b.shape)),
                                       e_ref, self.mask)
        signal = [s.value - s.floor for s in (one_panel() for _ in range(200))]
        pooled = fm.pool_sigma([one_panel() for _ in range(7)])  # the 7 panels of Figure 4
        estimate, truth = np.mean([s.sigma for s in pooled]), np.std(signal, ddof=1)
        # 7 gaps give a scatter estimate good to about +-30% (chi-square, 7 dof, 95%); pool_sigma
        # is conservative by up to sqrt(2) by design: accept 0.6x to 2.5x.
        self.assertGreater(estimate, 0.6 * truth, f"sigma {estimate:.3g}, scatter {truth:.3g}")
        self.assertLess(estimate, 2.5 * truth, f"sigma {estimate:.3g}, scatter {truth:.3g}")


class ClaimOfFigure4(unittest.TestCase):
    """falls_to_floor on the series the brief quotes and on series that must fail."""
    floors = [0.05, 0.07, 0.08, 0.08, 0.08, 0.08, 0.08]
    sigmas = [0.005] * 7

    def test_falling_to_the_floor_and_staying_holds(self):
        holds, reached = fm.falls_to_floor([0.60, 0.22, 0.12, 0.09, 0.08, 0.08, 0.09], self.floors, self.sigmas)
        self.assertTrue(holds)
        self.assertEqual(reached, 3)  # 0.09 - 0.08 <= 3 x 0.005

    def test_strictly_falling_above_the_floor_holds(self):
        self.assertEqual(fm.falls_to_floor([0.6, 0.5, 0.4, 0.35, 0.3, 0.25, 0.2], self.floors, self.sigmas),
                         (True, None))

    def test_a_raw_rise_from_a_rising_floor_holds(self):
        """The paper-quality run: the raw value rises from 4 to 6 D because the floor rises, while
        value - floor keeps falling (0.0014, 0.0004, -0.0001)."""
        values = [0.3721, 0.0574, 0.0215, 0.0107, 0.0074, 0.0076, 0.0087]
        floors = [0.0032, 0.0045, 0.0049, 0.0054, 0.0060, 0.0072, 0.0088]
        self.assertEqual(fm.falls_to_floor(values, floors, [0.0002] * 5 + [0.0003, 0.0004]), (True, 5))

    def test_a_rise_before_the_floor_fails(self):
        holds, _ = fm.falls_to_floor([0.60, 0.22, 0.25, 0.09, 0.08, 0.08, 0.08], self.floors, self.sigmas)
        self.assertFalse(holds)

    def test_leaving_the_floor_again_fails(self):
        holds, reached = fm.falls_to_floor([0.60, 0.22, 0.12, 0.08, 0.08, 0.08, 0.12], self.floors, self.sigmas)
        self.assertFalse(holds)
        self.assertEqual(reached, 3)


if __name__ == "__main__":
    unittest.main()
