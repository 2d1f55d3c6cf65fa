#!/usr/bin/python3
"""Tests of the chromatic figure's fringe measurement (tools/chromatic_figure.py) on images made here.

Each field's white letter is a block "H" drawn on the preview quality's pixel grid; the two TCA
buckets hold it shifted by known angles and blurred along the radial direction by kernels made
here, one a symmetric box and one a one-sided flare (the shape of the 6 mm, 30 deg blue image).
A centroid is linear, so the measured fringe must be the shift difference plus the difference of
the kernels' own centroids, computed here from the kernels. Then white noise: the sigma the
measurement pools from two halves must match the scatter of the fringe over many noise draws.
Student's t thresholds are checked against printed tables (two-sided 1% and 0.1% at 12 degrees of
freedom: 3.055 and 4.318; 0.27% at infinitely many: 3.000).

  tests/tools/chromatic_figure_test.py        (CTest: chromatic_figure_test)
"""
import os
import sys
import unittest

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "tools"))
import chromatic_figure as cf  # noqa: E402

QUALITY = "preview"


def grid():
    g = cf.geometry(QUALITY)
    return cf.pixel_angles(QUALITY, (g.height, g.width - g.first_column))


def letters(ax, ay, shift_deg):
    """A block H (two strokes and a bar) of side LETTER_DEG at every field, moved by shift_deg."""
    img = np.zeros(ax.shape)
    half = cf.LETTER_DEG / 2
    for f in cf.FIELDS_DEG:
        x, y = ax - f - shift_deg, ay
        inside = (np.abs(x) < half) & (np.abs(y) < half)
        strokes = np.abs(x) > half / 2
        bar = np.abs(y) < half / 5
        img[inside & (strokes | bar)] = 1.0
    return img


def blur_x(img, kernel):
    """Convolves every row with kernel (centred on its middle element)."""
    return np.apply_along_axis(lambda r: np.convolve(r, kernel, mode="same"), 1, img)


def kernel_centroid_px(kernel):
    offsets = np.arange(len(kernel)) - len(kernel) // 2
    return float((offsets * kernel).sum() / kernel.sum())


def channels(short, long_):
    """A channel dict as read from a render: the two TCA buckets and B, R (here the same images)."""
    return {cf.bucket_channel(cf.TCA_NM[0]): short, cf.bucket_channel(cf.TCA_NM[1]): long_, "B": short, "R": long_}


class FringeMeasurement(unittest.TestCase):
    def test_shift_and_asymmetric_blur(self):
        ax, ay = grid()
        pitch_arcmin = 60 * (ax[0, 1] - ax[0, 0])
        box = np.ones(9)
        flare = np.concatenate([np.exp(-np.arange(40)[::-1] / 12.0), np.zeros(39)])  # towards -x only
        # Whole pixels: a letter drawn on the pixel grid moves by the shift exactly.
        s_short, s_long = -3, 1
        short = blur_x(letters(ax, ay, s_short * pitch_arcmin / 60), flare)
        long_ = blur_x(letters(ax, ay, s_long * pitch_arcmin / 60), box)
        expected = pitch_arcmin * (s_short - s_long + kernel_centroid_px(flare) - kernel_centroid_px(box))
        for f, (fringe, _, edge) in cf.fringes(channels(short, long_), ax, ay).items():
            with self.subTest(field=f):
                self.assertAlmostEqual(fringe, expected, delta=0.02 * pitch_arcmin)
                self.assertLess(edge, cf.MAX_EDGE_LIGHT)

    def test_sigma_from_halves_matches_scatter(self):
        ax, ay = grid()
        clean = letters(ax, ay, 0.0)
        noise_sd = 0.5  # per pixel and half, of a letter of value 1 (noisier than the renders)
        rng = np.random.default_rng(3)
        tca = {f: (0.0, 0.0) for f in cf.FIELDS_DEG}
        values, sigmas = [], []
        for _ in range(25):
            halves = [channels(*(clean + rng.normal(0, noise_sd, clean.shape) * (clean > 0) for _ in range(2)))
                      for _ in range(2)]
            fr = cf.measure(halves, ax, ay, tca)
            values += [f.measured for f in fr]
            sigmas.append(fr[0].sigma)
        scatter, sigma = float(np.std(values)), float(np.sqrt(np.mean(np.square(sigmas))))
        self.assertLess(abs(np.mean(values)), 4 * scatter / np.sqrt(len(values)))  # no bias
        self.assertGreater(sigma / scatter, 0.8)
        self.assertLess(sigma / scatter, 1.25)


class StudentT(unittest.TestCase):
    def test_thresholds_match_tables(self):
        self.assertAlmostEqual(cf.t_threshold(12, 0.01), 3.055, delta=0.002)
        self.assertAlmostEqual(cf.t_threshold(12, 0.001), 4.318, delta=0.002)
        self.assertAlmostEqual(cf.t_threshold(100000, 0.0027), 3.000, delta=0.005)


if __name__ == "__main__":
    unittest.main()
