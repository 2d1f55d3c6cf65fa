#!/usr/bin/python3
"""Image output without OpenImageIO in the process (src/render/exr_file.cpp,
src/render/image_library_loader.cpp), checked from outside through the eyetrace binary:

1. A gbuffer film's EXR, written by eyetrace's own OpenEXR writer, read back by OpenImageIO's
   Python binding has the channels eyetrace.render() returns: the same names and, channel by
   channel, the same values bit for bit (render_binding_test does RGB and spectral films).
2. The dynamic loader's own trace (LD_DEBUG=files, glibc) of a render to .exr of a scene with no
   image texture names no libOpenImageIO; the same render to .png does load it, through the
   module (so the check can tell); nor does a render of a scene with PNG textures.
3. With EYETRACE_IMAGE_MODULE_DIR pointing at an empty directory, a render to .png fails with a
   non-zero exit and an error naming the image and the module, and leaves an existing file of
   that name as it was; a render to .exr still works.
4. A copy of the binary in DIR/bin, started through PATH, loads the module from DIR/lib (the
   copy's ../lib), not from the build tree.
"""
import os
import shutil
import subprocess
import unittest

import numpy as np
import OpenImageIO as oiio

import support
import eyetrace

CORNELL = support.scene_path("cornell-box.pbrt")


def loaded_libraries(*args, env=None):
    """The shared objects the dynamic loader reports loading while eyetrace runs `args`."""
    r = support.cli(*args, env_extra={"LD_DEBUG": "files", **(env or {})})
    return [line.split("file=", 1)[1].split()[0] for line in r.stderr.splitlines() if "file=" in line]


class ImageOutputTest(unittest.TestCase):
    def test_gbuffer_exr_read_by_openimageio(self):
        with open(CORNELL) as f:
            text = f.read().replace('Film "rgb"', 'Film "gbuffer"')
        path = os.path.join(support.SCRATCH, "cornell-gbuffer.pbrt")
        with open(path, "w") as f:
            f.write(text)
        out = os.path.join(support.SCRATCH, "cornell-gbuffer.exr")
        support.cli("render", path, "-o", out, "--quiet", "--spp", "2", "--seed", "5", "--resolution", "20x16")
        written, names = support.read_exr(out)
        image, channels = eyetrace.render(text=text, spp=2, seed=5, resolution=(20, 16), quiet=True,
                                          channel_names=True)
        self.assertEqual(sorted(names), sorted(channels))
        self.assertEqual(len(names), 25)  # R, G, B and pbrt-v4's 22 gbuffer channels
        for c, name in enumerate(channels):
            self.assertTrue(np.array_equal(image[:, :, c], written[:, :, names.index(name)], equal_nan=True), name)
        # 32-bit float channels, RLE-compressed, as OpenImageIO wrote them before.
        spec = oiio.ImageInput.open(out).spec()
        self.assertEqual(spec.format, oiio.FLOAT)
        self.assertEqual(spec.get_string_attribute("compression"), "rle")
        self.assertEqual(spec.get_string_attribute("eyetrace:samples_per_pixel"), "2")

    def test_exr_render_maps_no_openimageio(self):
        args = ["render", CORNELL, "--quiet", "--spp", "1", "--resolution", "8x8"]
        exr = loaded_libraries(*args, "-o", os.path.join(support.SCRATCH, "nooiio.exr"))
        self.assertTrue(any("libembree3" in f for f in exr), exr)  # the trace is there
        self.assertFalse([f for f in exr if "OpenImageIO" in f])
        png = loaded_libraries(*args, "-o", os.path.join(support.SCRATCH, "withoiio.png"))
        self.assertTrue([f for f in png if "libOpenImageIO" in f], png)
        self.assertTrue([f for f in png if "libeyetrace_oiio" in f], png)

    def test_png_textured_render_maps_no_openimageio(self):
        """PNG textures are read by libpng and filtered by eyetrace's MIP map (src/render/mipmap.h)."""
        scene = support.scene_path("peripheral.pbrt")
        args = ["render", scene, "--quiet", "--spp", "1", "--resolution", "8x8"]
        exr = loaded_libraries(*args, "-o", os.path.join(support.SCRATCH, "textured.exr"))
        self.assertTrue(any("libembree3" in f for f in exr), exr)  # the trace is there
        self.assertFalse([f for f in exr if "OpenImageIO" in f or "libeyetrace_oiio" in f])

    def test_missing_module_is_a_clear_error(self):
        empty = os.path.join(support.SCRATCH, "no-module")
        os.makedirs(empty, exist_ok=True)
        png = os.path.join(support.SCRATCH, "kept.png")
        with open(png, "wb") as f:
            f.write(b"an earlier output")
        env = {"EYETRACE_IMAGE_MODULE_DIR": empty}
        args = ["render", CORNELL, "--quiet", "--spp", "1", "--resolution", "8x8"]
        r = support.cli(*args, "-o", png, check=False, env_extra=env)
        self.assertNotEqual(r.returncode, 0)
        self.assertIn(f'image "{png}"', r.stderr)
        self.assertIn(os.path.join(empty, "libeyetrace_oiio.so") + ": not found", r.stderr)
        self.assertNotIn("Segmentation", r.stderr)
        with open(png, "rb") as f:
            self.assertEqual(f.read(), b"an earlier output")
        exr = os.path.join(support.SCRATCH, "no-module.exr")
        support.cli(*args, "-o", exr, env_extra=env)
        self.assertEqual(support.read_exr(exr)[0].shape, (8, 8, 3))

    def test_module_found_beside_a_copied_binary(self):
        root = os.path.join(support.SCRATCH, "installed")
        shutil.rmtree(root, ignore_errors=True)
        os.makedirs(os.path.join(root, "bin"))
        os.makedirs(os.path.join(root, "lib"))
        shutil.copy2(support.EYETRACE, os.path.join(root, "bin"))
        module = os.path.join(os.path.dirname(os.path.dirname(support.EYETRACE)), "lib", "libeyetrace_oiio.so")
        shutil.copy2(module, os.path.join(root, "lib"))
        env = {k: v for k, v in os.environ.items() if k != "EYETRACE_IMAGE_MODULE_DIR"}
        env.update(PATH=os.path.join(root, "bin") + os.pathsep + env.get("PATH", ""), LD_DEBUG="files")
        out = os.path.join(support.SCRATCH, "installed.png")
        r = subprocess.run(["eyetrace", "render", CORNELL, "--quiet", "--spp", "1", "--resolution", "8x8", "-o", out],
                           capture_output=True, text=True, env=env, cwd=support.SCRATCH)
        self.assertEqual(r.returncode, 0, r.stderr[-2000:])
        loaded = [line.split("file=", 1)[1].split()[0] for line in r.stderr.splitlines() if "file=" in line]
        self.assertIn(os.path.join(os.path.realpath(root), "lib", "libeyetrace_oiio.so"), loaded)


if __name__ == "__main__":
    unittest.main()
