#!/usr/bin/python3
"""tools/scene-coverage on a small stand-in for a pbrt-v4-scenes checkout: five of the 98
scene paths with scenes whose outcome is known (clean, blocked by an unsupported material,
missing an included file, ignoring Attribute "medium", naming a material of a missing file, a cloud
medium, a nanovdb medium whose .nvdb file is missing), the other 91 absent. Checks each row's status and the counts,
then --update: a row kept for a scene no longer at hand, a new one for a scene added.

    scene_coverage_test.py EYETRACE WORKDIR
"""
import os
import shutil
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def main(eyetrace, work):
    shutil.rmtree(work, ignore_errors=True)
    scenes = {
        "smoke-plume/plume.pbrt": 'WorldBegin\nLightSource "point"\nShape "sphere"\n',
        "lte-orb/lte-orb-silver.pbrt": 'WorldBegin\nMaterial "plastic"\nShape "sphere"\n',
        "killeroos/killeroo-simple.pbrt": 'WorldBegin\nInclude "geometry/killeroo.pbrt"\n',
        "kroken/camera-1.pbrt": 'WorldBegin\nAttribute "medium" "float g" 0.5\n',
        "clouds/clouds.pbrt": 'WorldBegin\nMakeNamedMedium "c" "string type" "cloud"\nMediumInterface "c" ""\n'
                              'Material "interface"\nShape "sphere"\n',
        "bunny-cloud/bunny-cloud.pbrt": 'WorldBegin\nMakeNamedMedium "b" "string type" "nanovdb" '
                                        '"string filename" "bunny_cloud.nvdb"\n',
        # The named material would be defined in the missing materials.pbrt.
        "sportscar/sportscar-sky.pbrt": 'WorldBegin\nInclude "materials.pbrt"\nNamedMaterial "paint"\n'
                                        'Shape "sphere"\n',
    }
    for path, text in scenes.items():
        os.makedirs(os.path.join(work, os.path.dirname(path)), exist_ok=True)
        with open(os.path.join(work, path), "w") as f:
            f.write(text)
    out = os.path.join(work, "coverage.md")
    subprocess.run([os.path.join(ROOT, "tools", "scene-coverage"), "--scenes", work, "--eyetrace", eyetrace,
                    "--output", out], check=True, capture_output=True)
    text = open(out).read()
    expected_rows = [
        "| `smoke-plume/plume.pbrt` | renders | — | — | 0 |",
        '| `lte-orb/lte-orb-silver.pbrt` | blocked | material "plastic" | — | 0 |',
        "| `killeroos/killeroo-simple.pbrt` | missing data only | — | — | 1 |",
        '| `kroken/camera-1.pbrt` | renders, ignoring features | — | Attribute "medium" (ignored) | 0 |',
        "| `clouds/clouds.pbrt` | renders | — | — | 0 |",
        "| `bunny-cloud/bunny-cloud.pbrt` | missing data only | — | — | 1 |",
        "| `sportscar/sportscar-sky.pbrt` | missing data only | — | — | 1 |",
        "| `villa/villa-daylight.pbrt` | not checked (file not at hand) | — | — | 0 |",
        "| renders | 2 |", "| renders, ignoring features | 1 |", "| missing data only | 3 |", "| blocked | 1 |",
        "| not checked | 91 |",
        '| material "plastic" | 1: lte-orb-silver.pbrt |',
    ]
    if not rows_found(expected_rows, text):
        return 1
    # --update: the scenes at hand now are checked, the rows of those no longer at hand are kept
    # (with what blocks them), the rest stay "not checked".
    os.remove(os.path.join(work, "lte-orb/lte-orb-silver.pbrt"))
    os.makedirs(os.path.join(work, "villa"))
    with open(os.path.join(work, "villa/villa-daylight.pbrt"), "w") as f:
        f.write('WorldBegin\nShape "plymesh" "string filename" "a.ply"\n')
    updated = os.path.join(work, "updated.md")
    subprocess.run([os.path.join(ROOT, "tools", "scene-coverage"), "--scenes", work, "--eyetrace", eyetrace,
                    "--output", updated, "--update", out], check=True, capture_output=True)
    expected_rows = [r for r in expected_rows if "villa" not in r and "not checked" not in r and "missing data" not in r]
    expected_rows += ["| `villa/villa-daylight.pbrt` | missing data only | — | — | 1 |", "| missing data only | 4 |",
                      "| not checked | 90 |"]
    if not rows_found(expected_rows, open(updated).read()):
        return 1
    print("scene_coverage_test: ok")
    return 0


def rows_found(rows, text):
    missing = [r for r in rows if r not in text.splitlines()]
    if missing:
        print("scene_coverage_test: rows not found:\n" + "\n".join(missing) + "\n--- output:\n" + text)
    return not missing


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))
