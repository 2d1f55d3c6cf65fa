#!/usr/bin/python3
"""docs/python_example.py, the worked example of docs/python.md, runs at a small size and
writes its PNG: four panels whose content this test checks from outside the script.

1. The script exits 0 and the PNG exists and is an image (read by OpenImageIO).
2. Its sweep's numbers: refraction falls with accommodation, by about the accommodation (the
   Navarro eye's accommodation model changes the lens power, not the refraction one for one, so
   the ratio is only checked to be within (0.5, 1.5)), and the 0 D eye is emmetropic within
   0.005 D (its published value, as tests/optics checks).
3. The two renders differ (two accommodations focus at different depths), and are not black.
"""
import os
import subprocess
import sys
import unittest

import numpy as np
import OpenImageIO as oiio

import support

sys.path.insert(0, os.path.join(support.SOURCE, "docs"))
import python_example  # noqa: E402  (the script, imported for its functions)

import eyetrace  # noqa: E402


class ExampleTest(unittest.TestCase):
    def test_script_writes_png(self):
        out = os.path.join(support.SCRATCH, "example.png")
        if os.path.exists(out):
            os.remove(out)
        script = os.path.join(support.SOURCE, "docs", "python_example.py")
        r = subprocess.run([sys.executable, script, "--out", out, "--spp", "1", "--resolution", "60x40"],
                           capture_output=True, text=True)
        self.assertEqual(r.returncode, 0, r.stderr)
        inp = oiio.ImageInput.open(out)
        self.assertIsNotNone(inp, oiio.geterror())
        self.assertGreater(inp.spec().width, 100)
        inp.close()

    def test_sweep_numbers(self):
        acc = np.array([0.0, 2.0, 4.0])
        refraction, spot = python_example.sweep(acc)
        self.assertAlmostEqual(refraction[0], 0.0, delta=0.005)
        slope = np.diff(refraction) / np.diff(acc)
        self.assertTrue(np.all(slope < -0.5) and np.all(slope > -1.5), slope)
        self.assertTrue(np.all(spot > 0))

    def test_two_accommodations_differ(self):
        images = []
        for acc in (0, 2):
            camera = f'Camera "navarro" "float pupildiameter" 4 "float accommodation" {acc} "float fov" 50'
            images.append(eyetrace.render(python_example.SCENE, camera=camera, spp=2, resolution=(60, 40), seed=1,
                                          quiet=True))
        self.assertGreater(float(images[0].mean()), 0.0)
        self.assertFalse(np.array_equal(images[0], images[1]))


if __name__ == "__main__":
    unittest.main()
