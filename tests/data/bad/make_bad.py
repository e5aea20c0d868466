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


# --- TILT files (ies/tilt_file.h): the helper TILT files end in .tilt, so bad_input_test (which
# reads *.ies and *.ldt with this folder as the allowed root) only meets them through an IES file.
def tilt(value):
    return ies(head=IES_HEAD.replace("TILT=NONE", "TILT=" + value)).encode()

def tilt_error(name, value, message):
    return f"{name}:4: TILT file '{value}': {message}"

helpers = {
    "bad_geometry.tilt": b"7\n2\n0 90\n1 1\n",
    "passwd_like.tilt": b"root:x:0:0:root:/root:/bin/bash\ndaemon:x:1:1:daemon:/usr/sbin:/usr/sbin/nologin\n",
    "binary.tilt": bytes(range(256)),
    "truncated.tilt": b"1\n3\n0 45 90\n1 0.9\n",
    "empty.tilt": b"",
}
OUTSIDE = "lies outside the project folder; refused (a TILT file must be in the folder of the project or below it)"
cases.update({
    "tilt_outside_absolute.ies": (tilt("/etc/passwd"),
                                  f"tilt_outside_absolute.ies:4: TILT file '/etc/passwd' {OUTSIDE}"),
    "tilt_outside_climbs.ies": (tilt("../photometry/lamp.tilt"),
                                f"tilt_outside_climbs.ies:4: TILT file '../photometry/lamp.tilt' {OUTSIDE}"),
    "tilt_directory.ies": (tilt("."), tilt_error("tilt_directory.ies", ".", ".: is a folder, not a file")),
    "tilt_bad_geometry_file.ies": (tilt("bad_geometry.tilt"), tilt_error(
        "tilt_bad_geometry_file.ies", "bad_geometry.tilt",
        "bad_geometry.tilt:1: expected the TILT lamp-to-luminaire geometry (1, 2 or 3) between 1 and 3, found '7'")),
    "tilt_passwd_file.ies": (tilt("passwd_like.tilt"), tilt_error(
        "tilt_passwd_file.ies", "passwd_like.tilt",
        "passwd_like.tilt:1: expected a number for the TILT lamp-to-luminaire geometry (1, 2 or 3), found a 31-character word")),
    "tilt_binary_file.ies": (tilt("binary.tilt"), tilt_error(
        "tilt_binary_file.ies", "binary.tilt", "binary.tilt: expected a text file (TILT data), found binary data")),
    "tilt_truncated_file.ies": (tilt("truncated.tilt"), tilt_error(
        "tilt_truncated_file.ies", "truncated.tilt", "truncated.tilt:4: expected TILT multiplying factor, found the end of the file")),
    "tilt_empty_file.ies": (tilt("empty.tilt"), tilt_error("tilt_empty_file.ies", "empty.tilt", "empty.tilt: file is empty")),
    "tilt_name_too_long.ies": (tilt("a" * 70 + ".tilt"),
                               "tilt_name_too_long.ies:4: expected NONE, INCLUDE or a file name of at most 64 printable ASCII characters after TILT=, found a 75-character name"),
    "tilt_factor_too_big.ies": (tilt("INCLUDE\n1\n2\n0 90\n1 1e6"),
                                "tilt_factor_too_big.ies:8: expected a TILT multiplying factor from 0 to 10, found 1e+06"),
    # 100 x 5e6 = 5e8 cd is within the limit, but tilted to where the TILT factor is 5 it is not.
    "tilt_product_over_limit.ies": (ies(head=IES_HEAD.replace("TILT=NONE", "TILT=INCLUDE\n1\n2\n0 90\n5 5")
                                        .replace("1 1000 1 5 3", "1 1000 5e6 5 3")).encode(),
                                    "tilt_product_over_limit.ies:13: expected the candela value at horizontal 0, vertical 0 to be at most 1e+09 cd after the multipliers, found 100 x 2.5e+07 = 2.5e+09 cd"),
})

# --- No leaks: a message quotes at most one short printable word of a file (limits.h).
cases.update({
    "passwd_as_value.ies": (ies(values=["100 90 root:x:0:0:root:/root:/bin/bash 40 10\n"] + VALUES[1:]).encode(),
                            "passwd_as_value.ies:9: expected a number for the candela value at horizontal 0, vertical 45, found a 31-character word"),
    "non_ascii_value.ies": (ies(values=["100 90 7\xe90 40 10\n"] + VALUES[1:]).encode("latin-1"),
                            "non_ascii_value.ies:9: expected a number for the candela value at horizontal 0, vertical 45, found a 3-byte word that is not printable ASCII"),
    "ldt_passwd_line.ldt": (ldt(mc="root:x:0:0:root:/root:/bin/bash").encode(),
                            "ldt_passwd_line.ldt:4: expected a number for the number of C planes Mc, found a 31-character word"),
    "ldt_words_line.ldt": (ldt(mc="twelve C planes").encode(),
                           "ldt_words_line.ldt:4: expected a number for the number of C planes Mc, found 3 words"),
})

# --- Numbers that stay numbers: intensities, multipliers and their products within the limits.
cases.update({
    "intensity_over_limit.ies": (ies(values=["100 90 2e9 40 10\n"] + VALUES[1:]).encode(),
                                 "intensity_over_limit.ies:9: expected the candela value at horizontal 0, vertical 45 to be at most 1e+09 cd after the multipliers, found 2e+09 x 1 = 2e+09 cd"),
    "multiplier_product_over_limit.ies": (ies(head=IES_HEAD.replace("1 1000 1 5 3", "1 1000 2e7 5 3")).encode(),
                                          "multiplier_product_over_limit.ies:9: expected the candela value at horizontal 0, vertical 0 to be at most 1e+09 cd after the multipliers, found 100 x 2e+07 = 2e+09 cd"),
    "multiplier_overflow.ies": (ies(head=IES_HEAD.replace("1 1000 1 5 3", "1 1000 1e300 5 3").replace("\n1 1 10\n", "\n1e10 1 10\n")).encode(),
                                "multiplier_overflow.ies:6: expected the candela multiplier x ballast factor to be at most 1e+09, found inf"),
    "lamp_flux_over_limit.ies": (ies(head=IES_HEAD.replace("1 1000 1 5 3", "2 1e300 1 5 3")).encode(),
                                 "lamp_flux_over_limit.ies:5: expected the lamp flux (2 x 1e+300 lm) to be from 0.001 to 1.26e+10 lm (4 pi x the intensity limit of 1e+09 cd), found 2e+300 lm"),
    "lamp_flux_tiny.ies": (ies(head=IES_HEAD.replace("1 1000 1 5 3", "1 1e-300 1 5 3")).encode(),
                           "lamp_flux_tiny.ies:5: expected the lamp flux (1 x 1e-300 lm) to be from 0.001 to 1.26e+10 lm (4 pi x the intensity limit of 1e+09 cd), found 1e-300 lm"),
    "single_vertical_type_c.ies": (ies(head=IES_HEAD.replace("1 1000 1 5 3", "1 1000 1 1 3"), v="0\n", values=["100\n"] * 3).encode(),
                                   "single_vertical_type_c.ies:5: expected at least 2 vertical angles for a type C file, found 1 (one angle describes no distribution)"),
    "single_vertical_type_b.ies": (ies(head=IES_HEAD.replace("1 1000 1 5 3 1 2", "1 1000 1 1 3 2 2"), v="0\n", values=["100\n"] * 3).encode(),
                                   "single_vertical_type_b.ies:5: expected at least 2 vertical angles for a type B file, found 1 (one angle describes no distribution)"),
    "single_horizontal_type_a.ies": (ies(head=IES_HEAD.replace("1 1000 1 5 3 1 2", "1 1000 1 5 1 3 2"), h="0\n", values=VALUES[:1]).encode(),
                                     "single_horizontal_type_a.ies:5: expected at least 2 horizontal angles for a type A file, found 1 (types A and B have no rotational symmetry)"),
    "opening_in_mm.ies": (ies(head=IES_HEAD.replace("0.1 0.1 0\n", "600 600 0\n")).encode(),
                          "opening_in_mm.ies:5: expected the luminous opening width to be at most 100 m, found 600 m"),
    "ldt_opening_too_large.ldt": (ldt().replace("\n100\n0\n50\n80\n0\n", "\n100\n0\n50\n2e6\n0\n").encode(),
                                  "ldt_opening_too_large.ldt:16: expected the luminous area length to be at most 100 m, found 2000 m"),
    "ldt_intensity_over_limit.ldt": (ldt(values=("100", "90", "2e9", "40", "10")).encode(),
                                     "ldt_intensity_over_limit.ldt:54: expected the intensity at C0, gamma 45 to be at most 1e+09 cd after the multipliers, found 2e+09 x 1 = 2e+09 cd"),
    "ldt_flux_over_limit.ldt": (ldt().replace("\nLED\n1000\n", "\nLED\n1e300\n").encode(),
                                "ldt_flux_over_limit.ldt:29: expected the total lamp flux of set 1 to be from 0.001 to 1.26e+10 lm (4 pi x the intensity limit of 1e+09 cd), found 1e+300 lm"),
    "ldt_conversion_over_limit.ldt": (ldt().replace("\n100\n90\n1\n0\n1\n", "\n100\n90\n1e12\n0\n1\n").encode(),
                                      "ldt_conversion_over_limit.ldt:24: expected the lamp flux / 1000 x the conversion factor to be at most 1e+09, found 1e+12"),
})

for name, data in helpers.items():
    with open(os.path.join(HERE, name), "wb") as f:
        f.write(data)

for name, (data, message) in cases.items():
    with open(os.path.join(HERE, name), "wb") as f:
        f.write(data)
    with open(os.path.join(HERE, name + ".expected"), "w") as f:
        f.write(message + "\n")
print(len(cases), "files")
