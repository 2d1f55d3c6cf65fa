"""The command line, input and output shared by the generators of the optics references in
tests/data/optics (tools/paraxial_reference.py, reference_trace.py, chromatic_reference.py):
--input (the shared eye-model reference) and --output ('-' = standard output), the input read with
its SHA-256 for the provenance, the facts of the run every independent reference records, and
writing the JSON. Not a command itself.
"""
import argparse
import datetime
import hashlib
import json
import os
import platform
import sys

DEFAULT_INPUT = "/work/shared/optics/eye-models.json"


def parse_args(doc):
    """--input and --output, with the generator's docstring as its --help."""
    ap = argparse.ArgumentParser(description=doc, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--input", default=DEFAULT_INPUT)
    ap.add_argument("--output", default="-", help="output file ('-' = standard output)")
    return ap.parse_args()


def read_input(path):
    """The input file's bytes (for its hash) and its parsed JSON."""
    raw = open(path, "rb").read()
    return raw, json.loads(raw)


def run_provenance(script, input_path, raw, numpy_version):
    """What, when and with which Python and numpy a computed reference was made, from which input
    (by hash): command, input_file, input_sha256, date_utc, python, numpy, in that order."""
    return {
        "command": (f"/usr/bin/python3 {script} " + " ".join(sys.argv[1:])).strip(),
        "input_file": input_path,
        "input_sha256": hashlib.sha256(raw).hexdigest(),
        "date_utc": datetime.datetime.now(datetime.timezone.utc).replace(microsecond=0).isoformat(),
        "python": platform.python_version(),
        "numpy": numpy_version,
    }


def write_output(text, output):
    """`text` to standard output ('-') or to the file, creating its folder."""
    if output == "-":
        sys.stdout.write(text)
    else:
        os.makedirs(os.path.dirname(os.path.abspath(output)), exist_ok=True)
        with open(output, "w") as f:
            f.write(text)
