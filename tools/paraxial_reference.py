#!/usr/bin/python3
"""Copies the paraxial constants tests/optics/eye_models_test.cpp checks out of the shared
eye-model reference (eye-models.json) into tests/data/optics/paraxial_reference.json, with its
provenance. Nothing is computed here: every number is copied as it stands in the input file.

  /usr/bin/python3 tools/paraxial_reference.py [--input /work/shared/optics/eye-models.json]
                                               [--output tests/data/optics/paraxial_reference.json]

Each entry names the eyetrace preset (model, variant, accommodation in dioptres) that stands for
one model key of eye-models.json. See tests/data/optics/README.md.
"""
import datetime
import hashlib
import json

import reference_io

# eyetrace preset -> eye-models.json model key. Gullstrand's accommodated exact eye is the end
# state of Atchison & Smith's continuous version, A = 10.87013 D.
PRESETS = [
    ("gullstrand", "", 0.0, "gullstrand_exact_relaxed"),
    ("gullstrand", "", 10.87013, "gullstrand_exact_accommodated"),
    ("legrand", "", 0.0, "le_grand"),
    ("legrand", "", 7.0525, "le_grand_accommodated"),
    ("kooijman", "", 0.0, "kooijman"),
    ("navarro", "", 0.0, "navarro"),
    ("navarro", "wu2011", 0.0, "navarro_wu2011_table1"),
    ("escudero-sanz", "", 0.0, "escudero_sanz_1999"),
    ("arizona", "", 0.0, "arizona"),
]

# The paraxial_computed keys the test reads (eye-models.json names them so).
COMPUTED_KEYS = ["power_D", "refraction_D", "F", "Fp", "H", "Hp", "N", "Np", "entrance_pupil_z",
                 "entrance_pupil_mag", "exit_pupil_z", "exit_pupil_mag"]


def main():
    args = reference_io.parse_args(__doc__)
    raw, src = reference_io.read_input(args.input)
    models = src["models"]

    presets = []
    for model, variant, accommodation, key in PRESETS:
        m = models[key]
        computed = m["paraxial_computed"]
        entry = {
            "model": model,
            "variant": variant,
            "accommodation_D": accommodation,
            "source_model_key": key,
            "source": m["source"],
            "status": m["status"],
            "axial_length_mm": m["retina"]["distance_from_cornea_mm"],
            "paraxial_computed": {k: computed[k] for k in COMPUTED_KEYS},
        }
        if "paraxial_published" in m:
            entry["paraxial_published"] = m["paraxial_published"]
        presets.append(entry)

    out = {
        "provenance": {
            "what": "paraxial constants of the schematic eyes, computed and published, copied unchanged "
                    "from the shared eye-model reference",
            "input_file": args.input,
            "input_sha256": hashlib.sha256(raw).hexdigest(),
            "input_sections": "models.<key>.paraxial_computed, models.<key>.paraxial_published, "
                              "models.<key>.retina.distance_from_cornea_mm (eye-models.md sections 1, 3-7, 9); "
                              "navarro_accommodation (eye-models.md table 5c)",
            "method_computed": "paraxial_computed: an independent paraxial (2x2 ray-transfer matrix) calculation "
                               "of each tabulated prescription, rounded to 4 decimals (eye-models.md, header)",
            "method_published": "paraxial_published: values from the literature, each with its source key: "
                                "AS = Atchison & Smith, Optics of the Human Eye (2000), schematic-eye appendix; "
                                "SCH = Schwiegerling, lecture notes 'Eye Models' (Gullstrand-Le Grand eye); "
                                "MB = duijnhouwer/magic_beam GullstrandVar.m (eye-models.md 'Source keys')",
            "script": "tools/paraxial_reference.py",
            "command": "/usr/bin/python3 tools/paraxial_reference.py --output tests/data/optics/paraxial_reference.json",
            "date": datetime.date.today().isoformat(),
            "conventions": src["conventions"],
        },
        "presets": presets,
        # Table 5c of eye-models.md: paraxial power and accommodation produced by Navarro's
        # parameter D with the axial length held fixed (computed, no published table found).
        "navarro_accommodation": {
            "source": src["navarro_accommodation"]["source"],
            "retina": src["navarro_accommodation"]["retina"],
            "power_D_axial_length_fixed": src["navarro_accommodation"]["power_D_axial_length_fixed"],
            "paraxial_accommodation_D_axial_length_fixed":
                src["navarro_accommodation"]["paraxial_accommodation_D_axial_length_fixed"],
        },
    }
    reference_io.write_output(json.dumps(out, indent=1) + "\n", args.output)


if __name__ == "__main__":
    main()
