#!/usr/bin/python3
"""eyetrace.render() (src/python/render_binding.cpp) against the command line:

1. A render of a scene file equals, pixel for pixel and bit for bit, the EXR `eyetrace render`
   writes for the same scene, overrides and seed (read back by OpenImageIO's Python binding):
   the Cornell box through a pinhole, and through the Navarro eye with a --camera override.
2. The same scene given as text renders the same pixels; a spectral film returns every channel
   with the EXR's channel names.
3. The GIL is released while it renders: a Python thread that counts 2 ms sleeps keeps counting
   during a render (with the GIL held it could not run at all).
4. Ctrl-C: a SIGINT sent during a long render raises KeyboardInterrupt within seconds, and the
   interpreter renders again afterwards.
"""
import os
import pathlib
import signal
import threading
import time
import unittest

import numpy as np

import support
import eyetrace

CORNELL = support.scene_path("cornell-box.pbrt")
EYE = 'Camera "navarro" "float pupildiameter" 4 "float accommodation" 1 "float fov" 40'


def cli_render(scene, name, *args):
    out = os.path.join(support.SCRATCH, name + ".exr")
    support.cli("render", scene, "-o", out, "--quiet", *args)
    return support.read_exr(out)


class RenderTest(unittest.TestCase):
    def test_equals_command_line_exr(self):
        expected, names = cli_render(CORNELL, "cornell", "--spp", "4", "--seed", "7", "--resolution", "40x30")
        image = eyetrace.render(CORNELL, spp=4, seed=7, resolution=(40, 30), quiet=True)
        self.assertEqual(image.dtype, np.float32)
        self.assertEqual(image.shape, (30, 40, 3))
        self.assertEqual(names, ["R", "G", "B"])
        self.assertTrue(np.array_equal(image, expected))
        self.assertGreater(float(image.mean()), 0.0)

    def test_camera_override_equals_command_line(self):
        expected, _ = cli_render(CORNELL, "cornell-eye", "--spp", "2", "--seed", "3", "--resolution", "32x32",
                                 "--camera", EYE, "--threads", "2")
        image = eyetrace.render(CORNELL, camera=EYE, spp=2, seed=3, resolution="32x32", threads=1, quiet=True)
        self.assertTrue(np.array_equal(image, expected))

    def test_scene_text_and_spectral_film(self):
        with open(CORNELL) as f:
            text = f.read()
        from_file = eyetrace.render(CORNELL, spp=2, seed=1, resolution=(24, 24), quiet=True)
        from_text = eyetrace.render(text=text, spp=2, seed=1, resolution=(24, 24), quiet=True)
        self.assertTrue(np.array_equal(from_file, from_text))
        # A pathlib.Path is a path as a str is (os.PathLike).
        from_path = eyetrace.render(pathlib.Path(CORNELL), spp=2, seed=1, resolution=(24, 24), quiet=True)
        self.assertTrue(np.array_equal(from_file, from_path))

        spectral = text.replace('Film "rgb"', 'Film "spectral" "integer nbuckets" 6')
        path = os.path.join(support.SCRATCH, "cornell-spectral.pbrt")
        with open(path, "w") as f:
            f.write(spectral)
        expected, names = cli_render(path, "cornell-spectral", "--spp", "2", "--seed", "1", "--resolution", "24x24")
        image, channels = eyetrace.render(text=spectral, spp=2, seed=1, resolution=(24, 24), quiet=True,
                                          channel_names=True)
        self.assertEqual(channels, names)
        self.assertEqual(image.shape, (24, 24, len(names)))
        self.assertGreater(len(names), 3)
        self.assertTrue(np.array_equal(image, expected))

    def test_gil_released_while_rendering(self):
        count, running = [0], [True]

        def counter():
            while running[0]:
                time.sleep(0.002)
                count[0] += 1

        thread = threading.Thread(target=counter)
        thread.start()
        start = time.monotonic()
        before = count[0]
        eyetrace.render(CORNELL, spp=64, resolution=(96, 96), threads=1, quiet=True)
        seconds = time.monotonic() - start
        during = count[0] - before
        running[0] = False
        thread.join()
        self.assertGreater(seconds, 0.3, "the render must last long enough to tell")
        # 2 ms sleeps: up to 500 a second; a tenth of that allows for a loaded machine.
        self.assertGreater(during, 50 * seconds, f"{during} counts in {seconds:.2f} s")

    def test_keyboard_interrupt(self):
        timer = threading.Timer(0.5, lambda: os.kill(os.getpid(), signal.SIGINT))
        timer.start()
        start = time.monotonic()
        with self.assertRaises(KeyboardInterrupt):
            eyetrace.render(CORNELL, spp=4096, resolution=(256, 256), threads=1, quiet=True)
        self.assertLess(time.monotonic() - start, 20.0)
        timer.join()
        image = eyetrace.render(CORNELL, spp=1, resolution=(8, 8), quiet=True)
        self.assertEqual(image.shape, (8, 8, 3))


if __name__ == "__main__":
    unittest.main()
