#!/usr/bin/env python3
"""Writes the hostile photometric files of this folder and, beside each, <file>.expected: the exact
message luxgrid must produce (the file's directory is stripped from the message; the tests do the
same). Re-run after changing a message on purpose: python3 make_bad.py"""
import os

HERE = os.path.dirname(os.path.abspath(__file__))

# A small valid LM-63-2002 file: 5 vertical x 3 horizontal (quadrant) = 15 values.
IES_HEAD = ("IESNA:LM-63-2002\n[TEST] hostile input\n[MANUFAC] luxgrid tests\nTILT=NONE\n"
            "1 1000 1 5 3 1 2 0.1 0.1 0\n1 1 10\n")
V = "0 22.5 45 67.5 90\n"
H = "0 45 90\n"
VALUES = ["100 90 70 40 10\n", "100 85 65 35 8\n", "100 80 60 30 5\n"]

def ies(head=IES_HEAD, v=V, h=H, values=VALUES):
    return head + v + h + "".join(values)

# A small valid EULUMDAT file: Isym 1, one plane, Ng = 5.
def ldt(isym="1", mc="4", ng="5", gammas=("0", "22.5", "45", "67.5", "90"),
        values=("100", "90", "70", "40", "10"), cs=("0", "90", "180", "270")):
    lines = ["luxgrid tests", "1", isym, mc, "90", ng, "22.5", "", "hostile", "", "", "",
             "100", "0", "50", "80", "0", "0", "0", "0", "0", "100", "90", "1", "0", "1",
             "1", "LED", "1000", "3000", "80", "10"] + ["0.5"] * 10 + list(cs) + list(gammas) + list(values)
    return "\n".join(lines) + "\n"

cases = {
    # name: (bytes, expected message)
    "empty.ies": (b"", "empty.ies: file is empty"),
    "binary_junk.ldt": (bytes(range(256)) * 4, "binary_junk.ldt: expected a text file (IES or EULUMDAT), found binary data"),
    "no_tilt_line.ies": ("IESNA:LM-63-2002\n[TEST] x\n1 1000 1 5 3 1 2 0 0 0\n".encode(),
                         "no_tilt_line.ies:3: expected a TILT= line before the photometric data, found none in 3 lines"),
    "truncated_header.ies": ((IES_HEAD.split("\n1 1000")[0] + "\n1 1000\n").encode(),
                             "truncated_header.ies:5: expected candela multiplier, found the end of the file"),
    "truncated_values.ies": (ies(values=VALUES[:2] + ["100 80\n"]).encode(),
                             "truncated_values.ies:11: expected 15 candela values (5 vertical x 3 horizontal), found 12 (the file ends)"),
    "vertical_count_too_high.ies": (ies(head=IES_HEAD.replace("1 1000 1 5 3", "1 1000 1 6 3")).encode(),
                                    "vertical_count_too_high.ies:8: expected 6 vertical angles, found 5 (then 0, which does not increase)"),
    "too_many_values.ies": (ies(values=VALUES + ["7\n"]).encode(),
                            "too_many_values.ies:12: expected 15 candela values (5 vertical x 3 horizontal), found more: '7'"),
    "non_numeric_value.ies": (ies(values=["100 90 abc 40 10\n"] + VALUES[1:]).encode(),
                              "non_numeric_value.ies:9: expected a number for the candela value at horizontal 0, vertical 45, found 'abc'"),
    "nan_value.ies": (ies(values=VALUES[:1] + ["100 nan 65 35 8\n"] + VALUES[2:]).encode(),
                      "nan_value.ies:10: expected a number for the candela value at horizontal 45, vertical 22.5, found 'nan'"),
    "negative_value.ies": (ies(values=VALUES[:2] + ["100 80 60 -30 5\n"]).encode(),
                           "negative_value.ies:11: expected the candela value at horizontal 90, vertical 67.5 to be >= 0, found -30"),
    "non_monotonic_vertical.ies": (ies(v="0 45 22.5 67.5 90\n").encode(),
                                   "non_monotonic_vertical.ies:7: vertical angles must increase: 22.5 follows 45"),
    "no_symmetry.ies": (ies(h="0 60 120\n").encode(),
                        "no_symmetry.ies:8: horizontal angles 0..120 fit no symmetry (expected 0; 0..90; 0..180; 90..270; or 0 to more than 180, up to 360)"),
    "vertical_out_of_range.ies": (ies(v="0 22.5 45 67.5 190\n").encode(),
                                  "vertical_out_of_range.ies:7: expected vertical angles between 0 and 180, found 190"),
    "missing_tilt_file.ies": (ies(head=IES_HEAD.replace("TILT=NONE", "TILT=lamp_tilt.tlt")).encode(),
                              "missing_tilt_file.ies:4: TILT file 'lamp_tilt.tlt' not found (looked for lamp_tilt.tlt)"),
    "bad_tilt_geometry.ies": (ies(head=IES_HEAD.replace("TILT=NONE", "TILT=INCLUDE\n7\n2\n0 90\n1 1")).encode(),
                              "bad_tilt_geometry.ies:5: expected the TILT lamp-to-luminaire geometry (1, 2 or 3) between 1 and 3, found '7'"),
    "absurd_counts.ies": (ies(head=IES_HEAD.replace("1 1000 1 5 3", "1 1000 1 100000 100000")).encode(),
                          "absurd_counts.ies:5: expected at most 10000000 candela values, the header claims 100000 x 100000"),
    "billion_values.ies": (ies(head=IES_HEAD.replace("1 1000 1 5 3", "1 1000 1 1000000000 1")).encode(),
                           "billion_values.ies:5: expected the number of vertical angles between 1 and 100000, found '1000000000'"),
    "zero_multiplier.ies": (ies(head=IES_HEAD.replace("1 1000 1 5 3", "1 1000 0 5 3")).encode(),
                            "zero_multiplier.ies:5: expected a candela multiplier > 0, found 0"),
    "bad_photometric_type.ies": (ies(head=IES_HEAD.replace("1 1000 1 5 3 1 2", "1 1000 1 5 3 4 2")).encode(),
                                 "bad_photometric_type.ies:5: expected the photometric type (1 = C, 2 = B, 3 = A) between 1 and 3, found '4'"),
    "ldt_truncated.ldt": ("\n".join(ldt().split("\n")[:-3]) + "\n").encode(),
    "ldt_bad_isym.ldt": (ldt(isym="7").encode(),
                         "ldt_bad_isym.ldt:3: expected the symmetry indicator Isym to be a whole number from 0 to 4, found '7'"),
    "ldt_non_numeric_mc.ldt": (ldt(mc="twelve").encode(),
                               "ldt_non_numeric_mc.ldt:4: expected a number for the number of C planes Mc, found 'twelve'"),
    "ldt_gamma_decreasing.ldt": (ldt(gammas=("0", "22.5", "45", "40", "90")).encode(),
                                 "ldt_gamma_decreasing.ldt:50: gamma angles must increase: 40 follows 45"),
    "ldt_negative_intensity.ldt": (ldt(values=("100", "90", "-70", "40", "10")).encode(),
                                   "ldt_negative_intensity.ldt:54: expected the intensity at C0, gamma 45 to be >= 0, found -70"),
    "ldt_absurd_counts.ldt": (ldt(mc="100000", ng="100000").encode(),
                              "ldt_absurd_counts.ldt:6: expected at most 10000000 intensities, the header claims 100000 x 100000"),
    "ldt_isym4_odd_planes.ldt": (ldt(isym="4", mc="6", cs=("0", "60", "120", "180", "240", "300")).encode(),
                                 "ldt_isym4_odd_planes.ldt:4: expected a multiple of 4 C planes for Isym 4, found Mc = 6"),
    "ldt_isym2_wrong_range.ldt": (ldt(isym="2", mc="4", cs=("0", "80", "170", "270"),
                                      values=("1",) * 15).encode(),
                                  "ldt_isym2_wrong_range.ldt:43: expected the stored C planes to span 0..180 for Isym 2, found 0..170"),
    "ldt_zero_flux.ldt": (ldt().replace("\nLED\n1000\n", "\nLED\n0\n").encode(),
                          "ldt_zero_flux.ldt:29: expected a total lamp flux > 0 for lamp set 1, found 0"),
}
n_lines = len(ldt().split("\n")) - 1
cases["ldt_truncated.ldt"] = (cases["ldt_truncated.ldt"],
                              f"ldt_truncated.ldt:{n_lines - 2}: expected 5 intensities (1 C planes x 5 gamma), found 3 (the file ends)")

for name, (data, message) in cases.items():
    with open(os.path.join(HERE, name), "wb") as f:
        f.write(data)
    with open(os.path.join(HERE, name + ".expected"), "w") as f:
        f.write(message + "\n")
print(len(cases), "files")
