#!/usr/bin/python3
"""Tests of the pupil figure's MTF measurement (tools/pupil_figure.py) on images made here.

A letter-like test image (random dark blocks of several sizes on white) is the "pinhole"
image; the "eye" image is it blurred by a Gaussian of known width, applied here by its
analytic transfer function exp(-2 pi^2 s^2 f^2). The band transfer the figure measures must
equal the band average that follows from that transfer function and the image's own spectrum
(computed here), within 1 %; with white noise added to each half, the noise-subtracted
measurement must stay within 3 of its own sigmas of the truth, and its sigma must describe the
scatter over 30 noise draws. The optics' frequencies stop below the diffraction cut-off.

  tests/tools/pupil_figure_test.py        (CTest: pupil_figure_test)
"""
import math
import os
import sys
import unittest

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "tools"))
import pupil_figure as pf  # noqa: E402

N = 240  # pixels across pf.FOV_DEG, the preview quality


def chart(rng):
    img = np.ones((N, N))
    for size in (24, 16, 12, 8, 6, 4):
        for _ in range(40):
            y, x = rng.integers(0, N - size, 2)
            img[y:y + size, x:x + size // 2] = 0.05
    return img


def blur(img, sigma_px):
    f = np.fft.fftfreq(N)
    fx, fy = np.meshgrid(f, f)
    h = np.exp(-2 * math.pi ** 2 * sigma_px ** 2 * (fx ** 2 + fy ** 2))
    return np.real(np.fft.ifft2(np.fft.fft2(img) * h))


def rgb(y):
    return np.repeat(y[:, :, None], 3, axis=2)


def truth(img, sigma_px, band):
    """The band average sqrt(sum |H|^2 P / sum P) of the Gaussian's transfer over the windowed
    image's spectrum P, H at each bin's frequency (cycles/deg -> cycles/pixel)."""
    w = np.outer(np.hanning(N), np.hanning(N))
    p = np.abs(np.fft.fft2((img - img.mean()) * w)) ** 2
    f = np.fft.fftfreq(N, d=pf.FOV_DEG / N)
    fx, fy = np.meshgrid(f, f)
    fr = np.hypot(fx, fy)
    m = (fr >= band[0]) & (fr < band[1])
    h2 = np.exp(-4 * math.pi ** 2 * sigma_px ** 2 * (fr[m] * pf.FOV_DEG / N) ** 2)
    return math.sqrt((h2 * p[m]).sum() / p[m].sum())


class PupilFigureTest(unittest.TestCase):
    def test_noise_free_band_transfer_is_the_gaussians(self):
        img = chart(np.random.default_rng(1))
        ref = pf.spectra([rgb(img), rgb(img)])
        for sigma_px in (0.5, 1.0, 2.0):
            eye = pf.spectra([rgb(blur(img, sigma_px))] * 2)
            for band in pf.BANDS_CPD:
                t = pf.band_transfer(eye, ref, band)
                expected = truth(img, sigma_px, band)
                self.assertAlmostEqual(t.mtf, expected, delta=0.01 * expected + 1e-4, msg=f"{sigma_px} {band}")

    def test_noise_is_subtracted_and_its_sigma_is_honest(self):
        rng = np.random.default_rng(2)
        img = chart(rng)
        eye_clean = blur(img, 2.0)
        band = (27.5, 32.5)
        expected = truth(img, 2.0, band)
        values, sigmas, raws = [], [], []
        for _ in range(30):
            halves = lambda y: [rgb(y + rng.normal(0, 0.08, y.shape)) for _ in range(2)]
            eye, ref = pf.spectra(halves(eye_clean)), pf.spectra(halves(img))
            t = pf.band_transfer(eye, ref, band)
            raws.append(pf.band_transfer((eye[0], 0 * eye[1], eye[2]), (ref[0], 0 * ref[1], ref[2]), band).mtf)
            values.append(t.mtf)
            sigmas.append(t.sigma)
            self.assertLess(abs(t.mtf - expected), 3 * t.sigma + 0.01 * expected, msg=f"{t} vs {expected}")
        scatter, sigma = float(np.std(values)), float(np.mean(sigmas))
        print(f"\nband {band}: truth {expected:.4f}, mean {np.mean(values):.4f}, scatter {scatter:.5f}, sigma {sigma:.5f}")
        self.assertTrue(0.5 * scatter <= sigma <= 2.0 * scatter, f"sigma {sigma} against scatter {scatter}")
        # The subtraction matters at this noise: without it the mean over the draws is off by
        # more than 5 of its standard errors (so the checks above would catch its absence).
        self.assertGreater(abs(float(np.mean(raws)) - expected), 5 * scatter / math.sqrt(len(values)))

    def test_optics_frequencies_stop_below_the_cutoff(self):
        # D / lambda in cycles/deg for an entrance pupil 1.1 x the iris at 589.3 nm.
        cutoff = lambda mm: 1.1 * mm * 1e-3 / 589.3e-9 * math.pi / 180
        self.assertAlmostEqual(cutoff(1.0), 32.58, delta=0.01)
        self.assertEqual(pf.optics_freqs(1.0), [10.0, 20.0, 30.0])
        self.assertEqual(pf.optics_freqs(2.0), [10.0, 20.0, 30.0, 40.0])
        wave = {"mtf": [{"freq_cpd": 10.0, "tangential": 0.5, "sagittal": 0.7}]}
        self.assertAlmostEqual(pf.optics_mtf(wave, 10.0), 0.6)
        self.assertEqual(pf.optics_mtf(wave, 40.0), 0.0)


if __name__ == "__main__":
    unittest.main()
