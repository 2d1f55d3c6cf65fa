#!/usr/bin/python3
"""Errors from Python (src/python/error_binding.cpp): each raises eyetrace.Error (an Exception)
whose message is exactly what the command line prints to stderr for the same input (run here as
a separate process, which exits 1), and the interpreter carries on:

1. scene text with mistakes (file:line:col, every error listed, then the count);
2. a bad eye parameter (naming it: the eye camera's range check);
3. a missing scene file; a missing prescription file;
4. a bad override (--resolution) and a bad Camera directive; a warning with strict=True (as
   --strict), and the next call without it renders;
5. a keyword value Python cannot spell as scene text (None, a quote in a string) is a TypeError
   or ValueError naming the parameter.
"""
import os
import unittest

import support
import eyetrace

BAD_SCENE = """Film "rgb" "integer xresolution" 16 "integer yresolution" 16
Camera "perspective" "float fvo" 40
WorldBegin
Shape "sphere" "float radius" -1
"""


def cli_error(*args):
    r = support.cli(*args, check=False)
    assert r.returncode == 1, (args, r.returncode, r.stderr)
    return r.stderr.rstrip("\n")


class ErrorTest(unittest.TestCase):
    def assert_same_error(self, expected, call, *args, **kwargs):
        with self.assertRaises(eyetrace.Error) as caught:
            call(*args, **kwargs)
        self.assertEqual(str(caught.exception), expected)
        self.assertTrue(caught.exception.diagnostics)
        return caught.exception

    def test_error_is_an_exception(self):
        self.assertTrue(issubclass(eyetrace.Error, Exception))

    def test_bad_scene_text(self):
        path = os.path.join(support.SCRATCH, "bad.pbrt")
        with open(path, "w") as f:
            f.write(BAD_SCENE)
        expected = cli_error("render", path, "-o", os.path.join(support.SCRATCH, "bad.exr"))
        self.assertIn("bad.pbrt:2:", expected)
        e = self.assert_same_error(expected, eyetrace.render, path, quiet=True)
        self.assertEqual(e.diagnostics[0]["line"], 2)
        # The same text given directly names "<text>" where the file had its path.
        with self.assertRaises(eyetrace.Error) as caught:
            eyetrace.render(text=BAD_SCENE, quiet=True)
        self.assertEqual(str(caught.exception), expected.replace(path, "<text>"))

    def test_bad_eye_parameter(self):
        expected = cli_error("optics", "--camera", 'Camera "navarro" "float pupildiameter" -1')
        self.assertIn("pupildiameter", expected)
        self.assert_same_error(expected, eyetrace.Eye, "navarro", pupildiameter=-1)
        expected = cli_error("optics", "--camera", 'Camera "navarro" "float acommodation" 2')
        self.assert_same_error(expected, eyetrace.Eye, "navarro", acommodation=2)

    def test_strict_makes_warnings_errors_for_that_call_only(self):
        path = os.path.join(support.SCRATCH, "warning.pbrt")
        with open(path, "w") as f:
            f.write('Integrator "path" "bool regularize" true\nWorldBegin\nShape "sphere"\n')
        out = os.path.join(support.SCRATCH, "warning.exr")
        expected = cli_error("render", path, "-o", out, "--resolution", "8x8", "--spp", "1", "--strict")
        self.assertIn("regularize", expected)
        self.assert_same_error(expected, eyetrace.render, path, resolution=(8, 8), spp=1, strict=True)
        self.assertEqual(eyetrace.render(path, resolution=(8, 8), spp=1, quiet=True).shape, (8, 8, 3))

    def test_python_types(self):
        with self.assertRaisesRegex(TypeError, "pupildiameter"):
            eyetrace.Eye("navarro", pupildiameter=None)
        with self.assertRaisesRegex(ValueError, "model"):
            eyetrace.Eye("eye", model='navarro"')

    def test_missing_files(self):
        missing = os.path.join(support.SCRATCH, "no-such-scene.pbrt")
        self.assert_same_error(cli_error("render", missing), eyetrace.render, missing)
        missing = os.path.join(support.SCRATCH, "no-such-eye.json")
        self.assert_same_error(cli_error("optics", "--prescription", missing), eyetrace.Eye.from_prescription,
                               missing)

    def test_bad_overrides(self):
        cornell = support.scene_path("cornell-box.pbrt")
        self.assert_same_error(cli_error("render", cornell, "--camera", 'Camera "navarro" "float fov" "wide"'),
                               eyetrace.render, cornell, camera='Camera "navarro" "float fov" "wide"', quiet=True)
        with self.assertRaises(eyetrace.Error) as caught:
            eyetrace.render(cornell, resolution="640by480", quiet=True)
        self.assertIn("--resolution", str(caught.exception))
        # The interpreter is still there and renders.
        self.assertEqual(eyetrace.render(cornell, spp=1, resolution=(4, 4), quiet=True).shape, (4, 4, 3))


if __name__ == "__main__":
    unittest.main()
