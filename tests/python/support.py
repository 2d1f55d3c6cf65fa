"""What the tests of the Python module share: the eyetrace binary and scratch directory they
are given (tests/python/X_test.py EYETRACE_BINARY SCRATCH_DIR), the command line run as an
independent process, and an EXR read through OpenImageIO's own Python binding."""
import os
import subprocess
import sys

import numpy as np
import OpenImageIO as oiio

EYETRACE = os.path.abspath(sys.argv[1]) if len(sys.argv) > 1 else "build/bin/eyetrace"
SCRATCH = os.path.abspath(sys.argv[2]) if len(sys.argv) > 2 else "build/tests/python/scratch"
SOURCE = os.environ.get("EYETRACE_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
os.makedirs(SCRATCH, exist_ok=True)
del sys.argv[1:]  # unittest reads the rest of the command line


def cli(*args, check=True, env_extra=None):
    """Runs the eyetrace binary (with `env_extra` added to the environment); returns the completed
    process (stdout and stderr as text)."""
    env = {**os.environ, **env_extra} if env_extra else None
    r = subprocess.run([EYETRACE, *args], capture_output=True, text=True, env=env)
    if check and r.returncode != 0:
        raise AssertionError(f"eyetrace {' '.join(args)} exited {r.returncode}:\n{r.stderr}")
    return r


def read_exr(path):
    """(H x W x C float32 array, channel names) of an EXR, read by OpenImageIO."""
    inp = oiio.ImageInput.open(path)
    if inp is None:
        raise AssertionError(f"cannot open {path}: {oiio.geterror()}")
    spec = inp.spec()
    pixels = inp.read_image(0, 0, 0, spec.nchannels, oiio.FLOAT)
    inp.close()
    return np.asarray(pixels, dtype=np.float32).reshape(spec.height, spec.width, spec.nchannels), list(
        spec.channelnames)


def scene_path(name):
    return os.path.join(SOURCE, "scenes", name)
