#!/usr/bin/python3
"""optiland_table.py EYETRACE [CSV]: the markdown table of docs/wavefront.md ("Against Optiland"):
eyetrace's RMS wavefront error, Strehl ratio at the chief ray and MTF beside Optiland's
(tests/data/optiland/eyes_mtf.csv, written by tools/oracles/optiland_eyes.py), with the differences.

eyetrace is run as `eyetrace optics --wave` with the camera's iris opened to 9 mm, so that the
analysis disc (--wave-pupil 3 or 5) is the paraxial entrance-pupil disc unclipped, as in Optiland
(the report traces the PSF with the real stop, which then clips nothing), on a 256 grid."""
import csv
import json
import subprocess
import sys

FREQS = [5, 10, 20, 30, 40, 60]


def eyetrace(binary, model, pupil):
    out = subprocess.run([binary, "optics", "--json", "--wave", "--camera",
                          f'Camera "{model}" "float pupildiameter" 9', "--wave-pupil", str(pupil),
                          "--wave-grid", "256", "--fields", "0,20", "--freqs", ",".join(map(str, FREQS))],
                         capture_output=True, text=True, check=True).stdout
    return {f["field_deg"]: f for f in json.loads(out)["wave"]}


def main(binary, path):
    rows = [r for r in csv.DictReader(line for line in open(path) if not line.startswith("#"))]
    cache = {}
    print("| eye | pupil mm | field ° | RMS waves eyetrace / Optiland | Strehl (chief ray) eyetrace / Optiland |"
          " MTF T/S at 10 cpd eyetrace | Optiland | 30 cpd eyetrace | Optiland | 60 cpd eyetrace | Optiland |"
          " largest MTF difference (6 frequencies, T and S) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        key = (r["model"], float(r["pupil_mm"]))
        if key not in cache:
            cache[key] = eyetrace(binary, *key)
        e = cache[key][float(r["field_deg"])]
        mtf = {m["freq_cpd"]: m for m in e["mtf"]}
        worst = max(max(abs(mtf[f]["tangential"] - float(r[f"mtf_t_{f}"])),
                        abs(mtf[f]["sagittal"] - float(r[f"mtf_s_{f}"]))) for f in FREQS)
        cells = [r["model"], f"{float(r['pupil_mm']):g}", f"{float(r['field_deg']):g}",
                 f"{e['rms_sampled_waves']:.4f} / {float(r['rms_waves']):.4f}",
                 f"{e['strehl_at_chief_ray']:.4f} / {float(r['strehl_at_chief_ray']):.4f}"]
        for f in (10, 30, 60):
            cells.append(f"{mtf[f]['tangential']:.3f} / {mtf[f]['sagittal']:.3f}")
            cells.append(f"{float(r[f'mtf_t_{f}']):.3f} / {float(r[f'mtf_s_{f}']):.3f}")
        cells.append(f"{worst:.4f}")
        print("| " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2] if len(sys.argv) > 2 else "tests/data/optiland/eyes_mtf.csv")
