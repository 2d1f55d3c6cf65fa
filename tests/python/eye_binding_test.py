#!/usr/bin/python3
"""eyetrace.Eye (src/python/eye_binding.cpp) against numbers from outside it:

1. The report dict equals `eyetrace optics --json` of the same eye, run as a separate process,
   key for key (keyword parameters, a Camera directive, a prescription file; with --wave).
2. The relaxed Navarro eye's power is the published 60.416 D (Escudero-Sanz & Navarro 1999, the
   value tests/optics checks) within 0.001 D, and its refraction 0 within 0.005 D; accommodating
   A dioptres makes it myopic (refraction falls as A rises).
3. spot(): on axis the RMS of the returned points about their mean equals rms_radius_um within
   1 % (the points are x, y offsets, the radius is over 3-D distances on the curved retina, which
   off axis is oblique, so there the points' RMS is only smaller), the count equals `rays`, and
   the radius is the report's spot RMS at that field (which rounds it to 1e-6 um).
4. wavefront(): the least-squares refraction equals -4 sqrt(3) c(2,0) / r^2 (ANSI Z80.28's
   conversion, computed here from the returned coefficients) within 1e-9 D, and the astigmatic
   terms give J0 = -2 sqrt(6) c(2,2) / r^2, J45 = -2 sqrt(6) c(2,-2) / r^2.
5. psf() and mtf(): for a 1 mm pupil (nearly diffraction-limited), the sagittal cut-off is
   D / lambda in cycles per degree (computed here) within 1e-9, and the MTF is within 0.05 of
   the diffraction-limited (2 / pi)(acos v - v sqrt(1 - v^2)); the PSF's peak is the Strehl
   ratio (its stated unit) within 5 %.
"""
import json
import math
import os
import pathlib
import unittest

import numpy as np

import support
import eyetrace


def cli_report(*args):
    return json.loads(support.cli("optics", "--json", *args).stdout)


class EyeTest(unittest.TestCase):
    def test_report_equals_command_line(self):
        eye = eyetrace.Eye("navarro", pupildiameter=4, accommodation=2)
        directive = 'Camera "navarro" "float pupildiameter" 4 "float accommodation" 2'
        expected = cli_report("--camera", directive)
        self.assertEqual(eye.report(), expected)
        self.assertEqual(eyetrace.Eye.from_camera(directive).report(), expected)
        self.assertAlmostEqual(eye.report()["refraction_diopters"], expected["refraction_diopters"], places=12)
        wave = cli_report("--camera", directive, "--wave", "--fields", "0,10")
        self.assertEqual(eye.report(fields=[0, 10], wave=True), wave)

    def test_generic_eye_camera_with_model(self):
        directive = 'Camera "eye" "string model" "legrand" "float accommodation" 1'
        self.assertEqual(eyetrace.Eye("eye", model="legrand", accommodation=1).report(fields=[0]),
                         cli_report("--camera", directive, "--fields", "0"))

    def test_report_of_prescription_file(self):
        path = os.path.join(support.SOURCE, "data", "eyes", "navarro.json")
        self.assertEqual(eyetrace.Eye.from_prescription(path).report(fields=[0]),
                         cli_report("--prescription", path, "--fields", "0"))
        self.assertEqual(eyetrace.Eye.from_prescription(pathlib.Path(path)).report(fields=[0]),
                         cli_report("--prescription", path, "--fields", "0"))

    def test_navarro_published_constants(self):
        r = eyetrace.Eye("navarro").report(fields=[0])
        self.assertAlmostEqual(r["power_diopters"], 60.416, delta=0.001)
        self.assertAlmostEqual(r["refraction_diopters"], 0.0, delta=0.005)
        refraction = [eyetrace.Eye("navarro", accommodation=a).report(fields=[0])["refraction_diopters"]
                      for a in (0, 1, 2, 4)]
        self.assertTrue(all(b < a for a, b in zip(refraction, refraction[1:])), refraction)

    def test_spot_points(self):
        eye = eyetrace.Eye("navarro", pupildiameter=4)
        for field in (0.0, 20.0):
            s = eye.spot(field=field)
            pts = s["points_um"]
            self.assertEqual(pts.shape, (s["rays"], 2))
            rms = math.sqrt(np.mean(np.sum((pts - pts.mean(axis=0)) ** 2, axis=1)))
            if field == 0.0:  # off axis the curved retina is oblique: the 3-D radius is larger
                self.assertAlmostEqual(rms, s["rms_radius_um"], delta=0.01 * s["rms_radius_um"])
            else:
                self.assertLess(rms, s["rms_radius_um"])
            spot = eye.report(fields=[field])["spot"][0]
            self.assertAlmostEqual(s["rms_radius_um"], spot["rms_radius_um"], delta=1e-6)  # the report rounds to 1e-6

    def test_wavefront_refraction_from_coefficients(self):
        eye = eyetrace.Eye("navarro", pupildiameter=6, accommodation=1)
        w = eye.wavefront(field=10)
        c, r = w["zernike_osa_um"], w["pupil_radius_mm"]
        self.assertEqual(len(c), 28)  # order 6: (6 + 1)(6 + 2) / 2 terms
        ls = w["refraction"]["least_squares"]
        self.assertAlmostEqual(ls["M_diopters"], -4 * math.sqrt(3) * c[4] / r ** 2, delta=1e-9)
        self.assertAlmostEqual(ls["J0_diopters"], -2 * math.sqrt(6) * c[5] / r ** 2, delta=1e-9)
        self.assertAlmostEqual(ls["J45_diopters"], -2 * math.sqrt(6) * c[3] / r ** 2, delta=1e-9)
        self.assertEqual(w["pupil_points"].shape, (len(w["opd_waves"]), 2))

    def test_psf_and_mtf_near_diffraction_limit(self):
        eye = eyetrace.Eye("navarro", pupildiameter=1, wavelength=555)
        p = eye.psf()
        self.assertEqual(p["intensity"].ndim, 2)
        self.assertAlmostEqual(p["intensity"].max(), p["strehl"], delta=0.05 * p["strehl"])
        freqs = [5, 10, 15, 20, 25]
        m = eye.mtf(freqs)
        diameter_mm = 2 * p["pupil_radius_mm"]
        cutoff = diameter_mm * 1e-3 / (p["wavelength_nm"] * 1e-9) * math.pi / 180
        self.assertAlmostEqual(m["sagittal_cutoff_cpd"], cutoff, delta=1e-9 * cutoff)
        for f, t, s in zip(freqs, m["tangential"], m["sagittal"]):
            v = f / cutoff
            limit = 2 / math.pi * (math.acos(v) - v * math.sqrt(1 - v * v))
            self.assertAlmostEqual(s, limit, delta=0.05, msg=f"{f} cpd")
            self.assertAlmostEqual(t, limit, delta=0.05, msg=f"{f} cpd")


if __name__ == "__main__":
    unittest.main()
