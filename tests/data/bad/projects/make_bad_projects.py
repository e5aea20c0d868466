#!/usr/bin/env python3
"""Writes the hostile project files of this folder. Beside each, <file>.expected holds the exact
message `luxgrid calc` must print (after "luxgrid: error: ", this folder's path removed), with exit
code 2 and nothing written; tests/cli/hostile_corpus_test.cpp runs every one under a memory limit
and reports the peak. The .expected files are checked by eye and kept: this script writes one
only where it is missing ("TODO", which fails the test until a person fills it in).
Re-run after adding a case: python3 make_bad_projects.py"""
import json
import os

HERE = os.path.dirname(os.path.abspath(__file__))

def base():
    return {
        "format": "luxgrid-project/1", "name": "hostile",
        "photometry": {"iso": {"builtin": "isotropic", "intensity_cd": 1000}},
        "rooms": [{"name": "r", "outline": [[0, 0], [4, 0], [4, 4], [0, 4]], "height": 3}],
        "luminaires": [{"photometry": "iso", "position": [2, 2, 2.9]}],
        "surfaces": [{"name": "wp", "workplane": {"room": "r", "height": 0.8}, "spacing": 0.5}],
    }

def patch(compact=False, **changes):
    """base() with top-level keys replaced; a value None removes the key."""
    doc = base()
    for k, v in changes.items():
        if v is None:
            doc.pop(k, None)
        else:
            doc[k] = v
    return json.dumps(doc, separators=(",", ":")) if compact else json.dumps(doc, indent=1)

def with_settings(**s):
    return patch(settings=s)

def with_luminaire(**l):
    lum = {"photometry": "iso", "position": [2, 2, 2.9]}
    lum.update(l)
    return patch(luminaires=[{k: v for k, v in lum.items() if v is not None}])

def with_surfaces(*surfaces):
    return patch(surfaces=list(surfaces))

def wp(name, spacing=0.5):
    return {"name": name, "workplane": {"room": "r", "height": 0.8}, "spacing": spacing}

def replace_text(old, new):
    text = patch()
    assert old in text, old
    return text.replace(old, new, 1)

DEEP = 100000
A_IES = ("IESNA:LM-63-2002\n[TEST] hostile project input\nTILT={tilt}\n"
         "1 1000 1 3 1 1 2 0.1 0.1 0\n1 1 10\n0 45 90\n0\n100 70 0\n")

# name: (text, placeholder for a missing .expected file)
CASES = {}

def case(name, text, expected="TODO"):
    CASES[name] = (text, expected)

# --- the parse itself: syntax, depth, duplicates, numbers ---
case("empty.json", "")
case("truncated.json", patch()[:200])
case("not_an_object.json", "[1, 2, 3]\n")
case("binary.json", bytes(range(256)).decode("latin-1"))
case("utf16.json", patch())  # written as UTF-16 below
case("nan_literal.json", replace_text('"height": 3', '"height": NaN'))
case("deep_unknown_key.json", patch().replace('"format"', '"junk": ' + "{\"a\":" * DEEP + "1" + "}" * DEEP + ', "format"', 1))
case("deep_arrays.json", patch().replace('"format"', '"junk": ' + "[" * DEEP + "]" * DEEP + ', "format"', 1))
case("deep_known_key.json", replace_text('"outline": [', '"outline": [' + "[" * 2000 + "]" * 2000 + ", "))
case("duplicate_top_key.json", replace_text('"surfaces"', '"luminaires": [], "surfaces"'))
case("duplicate_nested_key.json", replace_text('"height": 3', '"height": 3, "height": 30'))
case("duplicate_photometry.json", replace_text('"iso": {', '"iso": {"builtin": "lambertian", "intensity_cd": 1}, "iso": {'))
case("number_overflow.json", replace_text('"height": 3', '"height": 1e400'))
case("negative_overflow.json", replace_text('"position": [\n    2', '"position": [\n    -1e400'))
case("huge_integer.json", replace_text('"height": 3', '"height": 123456789012345678901234567890'))

# --- limits ---
case("array_10000x10000.json", with_luminaire(position=None, array={"origin": [0.1, 0.1, 2.9], "count": [10000, 10000], "spacing": [0.0004, 0.0004]}))
case("array_one_axis_huge.json", with_luminaire(position=None, array={"origin": [0.1, 0.1, 2.9], "count": [1, 1000000000], "spacing": [0.1, 0.1]}))
case("array_count_fraction.json", with_luminaire(position=None, array={"origin": [0.1, 0.1, 2.9], "count": [2.5, 2], "spacing": [0.1, 0.1]}))
case("too_many_luminaires.json", patch(luminaires=[{"photometry": "iso", "array": {"origin": [0.01, 0.01, 2.9], "count": [100, 100], "spacing": [0.039, 0.039]}}] * 2
                                             + [{"photometry": "iso", "position": [2, 2, 2.9]}]))
case("bounces_billion.json", with_settings(bounces=1e9))
case("bounces_too_many.json", with_settings(bounces=100000))
case("bounces_fraction.json", with_settings(bounces=2.5))
case("spacing_tiny.json", with_surfaces(wp("wp", 1e-300)))
case("spacing_denormal.json", with_surfaces(wp("wp", 5e-324)))
case("grid_too_large.json", with_surfaces(wp("wp", 0.001)))
case("grids_too_large_in_total.json", with_surfaces(*[wp("wp%d" % k, 0.0025) for k in range(4)]))
case("pairs_too_many.json", patch(
    luminaires=[{"photometry": "iso", "array": {"origin": [0.02, 0.02, 2.9], "count": [100, 100], "spacing": [0.0396, 0.0396]}}],
    surfaces=[wp("wp", 0.0025)]))
case("surface_name_long.json", with_surfaces(wp("w" * 5000)))
case("emitter_nanometre.json", with_luminaire(emitter={"shape": "rectangle", "size": [1e-9, 1e-9]}))
case("emitter_gigametre.json", with_luminaire(emitter={"shape": "rectangle", "size": [1e9, 1e9]}))
case("emitter_disk_tiny.json", with_luminaire(emitter={"shape": "disk", "diameter": 1e-12}))
case("position_far_away.json", with_luminaire(position=[1e300, 2, 2.9]))
case("outline_far_away.json", replace_text('[\n     4,\n     0\n    ]', '[\n     4e200,\n     0\n    ]'))
case("height_absurd.json", replace_text('"height": 3', '"height": 1e250'))
case("many_rooms.json", patch(compact=True, rooms=[{"name": "r%d" % k if k else "r", "outline": [[10 * k, 0], [10 * k + 4, 0], [10 * k + 4, 4], [10 * k, 4]], "height": 3} for k in range(2000)]))
case("many_obstacles.json", patch(compact=True, rooms=[{"name": "r", "outline": [[0, 0], [4, 0], [4, 4], [0, 4]], "height": 3,
                                          "obstacles": [{"box": {"min": [0.001 * k, 0, 0], "max": [0.001 * k + 0.0005, 1, 1]}} for k in range(3000)]}]))

# --- numbers that stay numbers ---
case("intensity_near_max.json", patch(photometry={"iso": {"builtin": "isotropic", "intensity_cd": 1.7e308}}))
case("intensity_absurd.json", patch(photometry={"iso": {"builtin": "isotropic", "intensity_cd": 1e15}}))
case("flux_absurd.json", patch(photometry={"iso": {"file": "lamp.ies", "flux_lm": 1e300}}))
case("multiplier_overflow.json", patch(photometry={"iso": {"file": "lamp.ies", "multiplier": 1e307}}))
case("multiplier_tiny.json", patch(photometry={"iso": {"file": "lamp.ies", "multiplier": 1e-320}}))
case("maintenance_tiny.json", with_settings(maintenance_factor=1e-310))

# --- overwrites: two surfaces, one file ---
case("names_slash_underscore.json", with_surfaces(wp("a/b"), wp("a_b")))
case("names_direct_suffix.json", with_surfaces(wp("x"), wp("x_direct")))
case("names_case.json", with_surfaces(wp("Desk"), wp("desk")))
case("names_room_surfaces.json", with_surfaces({"name": "w", "room_surfaces": {"room": "r"}, "spacing": "auto"}, wp("w floor")))
case("names_hidden.json", with_surfaces(wp(".luxgrid-output")))
case("names_empty.json", with_surfaces(wp("")))
case("names_control.json", with_surfaces(wp("a\u0000b")))

# --- paths ---
case("path_absolute.json", patch(photometry={"iso": "/etc/passwd"}))
case("path_climbs.json", patch(photometry={"iso": "../../../../../../../../etc/passwd"}))
case("path_proc.json", patch(photometry={"iso": "/proc/self/environ"}))
case("path_folder.json", patch(photometry={"iso": "."}))
case("path_device.json", patch(photometry={"iso": "/dev/zero"}))
case("tilt_absolute.json", patch(photometry={"iso": "tilt_absolute.ies"}))
case("tilt_climbs.json", patch(photometry={"iso": "tilt_climbs.ies"}))
case("tilt_proc.json", patch(photometry={"iso": "tilt_proc.ies"}))
case("path_nul.json", patch(photometry={"iso": "lamp.ies\u0000.txt"}))

# --- wrong kinds ---
case("format_missing.json", patch(format=None))
case("format_number.json", patch(format=1))
case("luminaires_object.json", patch(luminaires={"a": 1}))
case("surfaces_empty.json", patch(surfaces=[]))

AUX = {
    "lamp.ies": A_IES.format(tilt="NONE"),
    "tilt_absolute.ies": A_IES.format(tilt="/etc/passwd"),
    "tilt_climbs.ies": A_IES.format(tilt="../../../../../../../../etc/hostname"),
    "tilt_proc.ies": A_IES.format(tilt="/proc/self/environ"),
}

def main():
    for name, text in AUX.items():
        with open(os.path.join(HERE, name), "w", encoding="utf-8", newline="\n") as f:
            f.write(text)
    for name, (text, expected) in CASES.items():
        with open(os.path.join(HERE, name), "wb") as f:
            if name == "binary.json":
                f.write(bytes(range(256)))
            elif name == "utf16.json":
                f.write(text.encode("utf-16"))  # with its byte-order mark
            else:
                f.write(text.encode("utf-8"))
        expected_file = os.path.join(HERE, name + ".expected")
        if not os.path.exists(expected_file):
            with open(expected_file, "w", encoding="utf-8") as f:
                f.write(expected + "\n")
    print(f"{len(CASES)} hostile projects written")

if __name__ == "__main__":
    main()
