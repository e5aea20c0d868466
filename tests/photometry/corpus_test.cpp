// Every file of the corpus (tests/data/photometry, copied from ../shared/photometry with its
// MANIFEST.md) is read, and what its MANIFEST row states is checked: version, photometric type,
// symmetry, counts, lamps, multiplier, luminous opening, and the integrated flux. For EULUMDAT
// files the integrated LOR and DFF are compared with what the file states.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <optional>
#include <set>
#include <string>

#include "photometry/derived_photometry.h"
#include "photometry/photometry.h"
#include "photometry/tabular_distribution.h"

namespace luxgrid::photometry {
namespace {

struct Row {
  const char* file;
  const char* version;
  char type;
  Symmetry symmetry;
  int counts_vertical, counts_horizontal;  // IES V x H; EULUMDAT Ng x stored planes
  int lamps;                               // lamps of (the first) set, as written
  int lamp_sets;
  std::optional<double> lamp_flux_lm;  // stated; nullopt for absolute photometry
  double multiplier;                   // IES: candela multiplier; LDT: flux1/1000
  double width_m, length_m, height_m;  // IES as written (signed, metres); LDT area L/W
  const char* opening;                 // MANIFEST's words
  double manifest_flux_lm;             // IES: exact integral of the bilinear interpolant
  double lor_integral, lor_stated, dff_integral, dff_stated;  // EULUMDAT (fractions)
};

// Generated from MANIFEST.md (the IES/EULUMDAT tables and the flux cross-check tables).
const Row kRows[] = {
    {"aec_italo_lm02_flasharea.ies", "LM-63-2002", 'C', Symmetry::none, 181, 73, 1, 1, std::nullopt,
     1.0, 0.23, 0.146, 0.0, "rectangle", 10579.9, -1, -1, -1, -1},
    {"asa_15m_r2_lm02_feet_h0_180.ies", "LM-63-2002", 'C', Symmetry::bilateral_c0_c180, 37, 73, 1,
     1, 13000.0, 1.0, 0.377952, 0.377952, 0.0, "rectangle", 9560.8, -1, -1, -1, -1},
    {"bega_50277_iesna91_abs.ies", "LM-63-1991", 'C', Symmetry::rotational, 73, 1, 1, 1,
     std::nullopt, 1.0, -1.3, 0.0, 0.0, "round (diameter =", 13773.2, -1, -1, -1, -1},
    {"bega_50899_lm95_h0_345.ies", "LM-63-1995", 'C', Symmetry::none, 19, 24, 1, 1, std::nullopt,
     1.0, -0.12, 0.0, 0.0, "round (diameter =", 1224.6, -1, -1, -1, -1},
    {"bega_6339_lm95_mult089.ies", "LM-63-1995", 'C', Symmetry::rotational, 73, 1, 1, 1, 890.0,
     0.89, -0.1, 0.0, 0.0, "round (diameter =", 231.8, -1, -1, -1, -1},
    {"bega_84659_lm95_h90_270.ies", "LM-63-1995", 'C', Symmetry::bilateral_c90_c270, 37, 37, 1, 1,
     std::nullopt, 1.0, 0.24, 0.27, 0.0, "rectangle", 9600.1, -1, -1, -1, -1},
    {"bega_8701_lm95_buried_flood.ies", "LM-63-1995", 'C', Symmetry::rotational, 61, 1, 1, 1, 650.0,
     0.65, -0.095, 0.0, 0.0, "round (diameter =", 431.2, -1, -1, -1, -1},
    {"deliver_indoor_full360_lm02.ies", "LM-63-2002", 'C', Symmetry::none, 37, 25, 1, 1,
     std::nullopt, 1.0043784, 0.21, 0.16, 0.0, "rectangle", 13348.4, -1, -1, -1, -1},
    {"els_dt106_lm02_mult1498.ies", "LM-63-2002", 'C', Symmetry::rotational, 181, 1, 1, 1,
     std::nullopt, 1.498, -0.092, -0.092, 0.0, "circle", 2437.8, -1, -1, -1, -1},
    {"erco_qrcbc35_lm86_spot.ies", "LM-63-1986", 'C', Symmetry::rotational, 19, 1, 1, 1, 600.0, 0.6,
     -0.035, 0.0, 0.0, "round (diameter =", 458.5, -1, -1, -1, -1},
    {"erco_stella_lm86_mult48.ies", "LM-63-1986", 'C', Symmetry::rotational, 19, 1, 1, 1, 4800.0,
     4.8, -0.17, 0.0, 0.0, "round (diameter =", 3061.9, -1, -1, -1, -1},
    {"erco_t26_lm86_quadrant.ies", "LM-63-1986", 'C', Symmetry::quadrant, 19, 7, 1, 1, 2580.0, 2.58,
     1.15, 0.045, 0.0, "rectangle", 1501.5, -1, -1, -1, -1},
    {"flood_typeb_lm02_144lamps.ies", "LM-63-2002", 'B', Symmetry::bilateral_c0_c180, 45, 23, 144,
     1, std::nullopt, 1.0, 0.195581016, 0.157481016, 0.0, "rectangle", 10698.3, -1, -1, -1, -1},
    {"flood_typeb_lm02_45x45.ies", "LM-63-2002", 'B', Symmetry::none, 45, 45, 1, 1, std::nullopt,
     1.0, 0.44, 0.18, 0.0, "rectangle", 30029.1, -1, -1, -1, -1},
    {"generated_iesna91_dense_horizon.ies", "LM-63-1991", 'C', Symmetry::rotational, 103, 1, 1, 1,
     596.57, 1.0, 0.0, 0.0, 0.0, "point", 591.3, -1, -1, -1, -1},
    {"generated_iesna91_split_header.ies", "LM-63-1991", 'C', Symmetry::rotational, 37, 1, 1, 1,
     13172.61, 1.0, 0.0, 0.0, 0.0, "point", 13148.3, -1, -1, -1, -1},
    {"halo_h7t_iesna91_feet.ies", "LM-63-1991", 'C', Symmetry::rotational, 36, 1, 1, 1, 900.0, 1.0,
     0.0, -0.09753600000000001, 0.0, "undefined sign combination (0, -1, 0) for LM-63-1991", 796.5,
     -1, -1, -1, -1},
    {"indoor_full360_lm02.ies", "LM-63-2002", 'C', Symmetry::none, 37, 9, 1, 1, std::nullopt, 1.0,
     -0.225, -0.225, 0.0, "circle", 9217.3, -1, -1, -1, -1},
    {"interlab_lm95_263x361_large.ies", "LM-63-1995", 'C', Symmetry::none, 263, 361, 1, 1,
     std::nullopt, 1.0, 0.145, 0.28, 0.0, "rectangle", 5608.2, -1, -1, -1, -1},
    {"interlight_ovni_lm02_nonascii.ies", "LM-63-2002", 'C', Symmetry::rotational, 361, 1, 1, 1,
     std::nullopt, 0.4597, -0.3, -0.3, 0.0, "circle", 5300.8, -1, -1, -1, -1},
    {"itl_downlight_rot_lm02_24lamps.ies", "LM-63-2002", 'C', Symmetry::rotational, 37, 1, 24, 1,
     std::nullopt, 1.0, -0.13811097600000002, -0.13811097600000002, 0.0, "circle", 531.8, -1, -1,
     -1, -1},
    {"itl_indoor_quadrant_lm02_120lamps.ies", "LM-63-2002", 'C', Symmetry::quadrant, 37, 5, 120, 1,
     std::nullopt, 1.0, 0.063498984, 0.61435488, 0.0, "rectangle", 753.6, -1, -1, -1, -1},
    {"kurtversen_par38_iesna91.ies", "LM-63-1991", 'C', Symmetry::rotational, 19, 1, 1, 1, 3500.0,
     1.0, -0.18288000000000001, 0.0, 0.0, "round (diameter =", 2988.9, -1, -1, -1, -1},
    {"ledalite_apex_iesna95tag_2lamps.ies", "LM-63-1995", 'C', Symmetry::quadrant, 73, 5, 2, 1,
     5800.0, 1.0, 0.25908000000000003, 1.231392, 0.0890016, "rectangle with luminous sides (box)",
     5296.7, -1, -1, -1, -1},
    {"lithonia_esg_iesna91_commas.ies", "LM-63-1991", 'C', Symmetry::quadrant, 37, 5, 1, 1, 68.0,
     1.0, 0.100584, 0.100584, 0.0, "rectangle", 33.1, -1, -1, -1, -1},
    {"maxwell_lm95_rel1000.ies", "LM-63-1995", 'C', Symmetry::none, 91, 73, 1, 1, 1000.0, 1.0, 0.0,
     0.0, 0.0, "point", 999.9, -1, -1, -1, -1},
    {"mdl_rimlight_iesna91_onevalueperline.ies", "LM-63-1991", 'C', Symmetry::rotational, 16, 1, 1,
     1, std::nullopt, 1.0, 0.0, 0.0, 0.0, "point", 18.8, -1, -1, -1, -1},
    {"mdl_test_iesna91_typeb.ies", "LM-63-1991", 'B', Symmetry::none, 2, 5, 1, 1, std::nullopt, 1.0,
     0.0, 0.0, 0.0, "point", 3.5, -1, -1, -1, -1},
    {"nvidia_example_lm19_feet.ies", "LM-63-2019", 'C', Symmetry::rotational, 10, 1, 1, 1,
     std::nullopt, 1.0, -0.06096000000000001, -0.06096000000000001, 0.0, "circle", 8749.7, -1, -1,
     -1, -1},
    {"opple_ltd0110301_lm02_vcyl.ies", "LM-63-2002", 'C', Symmetry::none, 181, 25, 1, 1,
     std::nullopt, 1.0, -0.034, -0.034, 0.1, "vertical cylinder", 150.1, -1, -1, -1, -1},
    {"opple_mtd0700312_lm02_h0_90.ies", "LM-63-2002", 'C', Symmetry::quadrant, 181, 2, 1, 1,
     std::nullopt, 1.0, -0.08, -0.08, 0.0, "circle", 12.6, -1, -1, -1, -1},
    {"rab_indoor_bilateral_lm02_nonascii.ies", "LM-63-2002", 'C', Symmetry::bilateral_c0_c180, 73,
     9, 1, 1, std::nullopt, 0.9687, -0.31751016000000004, -0.31751016000000004,
     0.035000184000000004, "vertical cylinder", 5820.2, -1, -1, -1, -1},
    {"rab_roadway_199x38_lm02.ies", "LM-63-2002", 'C', Symmetry::bilateral_c0_c180, 199, 38, 36, 1,
     std::nullopt, 0.809, 0.200406, 0.01905, 0.280925016, "rectangle with luminous sides (box)",
     828.3, -1, -1, -1, -1},
    {"rab_roadway_bilateral_lm02.ies", "LM-63-2002", 'C', Symmetry::bilateral_c0_c180, 73, 22, 4, 1,
     std::nullopt, 1.045644, -0.210312, -0.210312, 0.0, "circle", 5833.3, -1, -1, -1, -1},
    {"rab_roadway_quadrant_lm02.ies", "LM-63-2002", 'C', Symmetry::quadrant, 74, 12, 192, 1,
     std::nullopt, 1.032007, 0.448056, 0.448056, 0.07239, "rectangle with luminous sides (box)",
     9218.3, -1, -1, -1, -1},
    {"roadway_lm95_relative_361x73.ies", "LM-63-1995", 'C', Symmetry::none, 361, 73, 1, 1, 9155.7,
     1.0, 0.0, 0.0, 0.0, "point", 9155.5, -1, -1, -1, -1},
    {"synthetic_hcyl_along_width_lm95.ies", "LM-63-1995", 'C', Symmetry::rotational, 37, 1, 1, 1,
     std::nullopt, 1.0, 0.12, 0.0, -0.34, "undefined sign combination (1, 0, -1) for LM-63-1995",
     904.5, -1, -1, -1, -1},
    {"synthetic_rel_mult15_lm95.ies", "LM-63-1995", 'C', Symmetry::rotational, 37, 1, 1, 1, 500.0,
     1.5, -0.12, 0.0, 0.0, "round (diameter =", 1356.8, -1, -1, -1, -1},
    {"synthetic_tilt_include_lm02.ies", "LM-63-2002", 'C', Symmetry::rotational, 5, 1, 1, 1, 1000.0,
     1.0, 0.1, 0.1, 0.05, "rectangle with luminous sides (box)", 3226.8, -1, -1, -1, -1},
    {"acme_road_dc0_dg0_isym3.ldt", "EULUMDAT", 'C', Symmetry::bilateral_c90_c270, 25, 27, 1, 1,
     33200.0, 33.2, 0.0, 0.472, 0, "ldt", 0, 0.8414, 0.8442000000000001, 1.0, 1.0},
    {"erco_sample17_bom_abs.ldt", "EULUMDAT", 'C', Symmetry::rotational, 91, 1, -1, 1, std::nullopt,
     0.6119, 0.0, 0.076, 0, "ldt", 0, 1.0, 1.0, 1.0, 1.0},
    {"ledvance_flmax_asym_isym0.ldt", "EULUMDAT", 'C', Symmetry::none, 19, 8, 1, 1, 164000.0, 164.0,
     0.65, 0.4, 0, "ldt", 0, 0.9983, 0.998, 1.0, 1.0},
    {"philips_bdp100_two_lamp_sets.ldt", "EULUMDAT", 'C', Symmetry::bilateral_c90_c270, 44, 73, 1,
     2, 9408.0, 9.408, 0.0, 0.56, 0, "ldt", 0, 0.7756000000000001, 0.78, 0.991, 0.99},
    {"projector_isym2_dg0.ldt", "EULUMDAT", 'C', Symmetry::bilateral_c0_c180, 55, 37, 1, 1, 6500.0,
     6.5, 0.161, 0.195, 0, "ldt", 0, 0.7935, 0.7770999999999999, 1.0, 1.0},
    {"sample01_isym2.ldt", "EULUMDAT", 'C', Symmetry::bilateral_c0_c180, 37, 13, 1, 1, 2112.0,
     2.112, 0.038, 1.201, 0, "ldt", 0, 1.0025, 1.0, 1.0, 1.0},
    {"sample03_two_lamp_sets_isym4.ldt", "EULUMDAT", 'C', Symmetry::quadrant, 73, 37, 1, 2, 1983.0,
     1.983, 0.105, 1.208, 0, "ldt", 0, 1.0001, 1.0, 0.87, 0.87},
    {"sample06_spot_coarse.ldt", "EULUMDAT", 'C', Symmetry::none, 37, 24, 1, 1, 1014.0, 1.014, 0.0,
     0.075, 0, "ldt", 0, 1.0254, 1.001, 0.961, 0.96},
    {"sample14_circular_dff52.ldt", "EULUMDAT", 'C', Symmetry::none, 37, 24, 1, 1, 13729.0, 13.729,
     0.0, 0.662, 0, "ldt", 0, 1.0011, 1.0, 0.521, 0.521},
    {"sample18_mc360_large.ldt", "EULUMDAT", 'C', Symmetry::none, 181, 360, 1, 1, 2445.4,
     2.4454000000000002, 0.1, 0.1, 0, "ldt", 0, 1.0, 1.0, 1.0, 1.0},
    {"sample19_mc72_ng181.ldt", "EULUMDAT", 'C', Symmetry::none, 181, 72, 1, 1, 400.0, 0.4, 0.09,
     0.09, 0, "ldt", 0, 0.8863, 0.8863, 1.0, 1.0},
    {"sample20_isym4_dg0.ldt", "EULUMDAT", 'C', Symmetry::quadrant, 55, 19, 1, 1, 10002.0, 10.002,
     0.065, 1.75, 0, "ldt", 0, 1.0001, 1.0, 0.904, 0.9},
    {"synthetic_absolute_neg_lamps.ldt", "EULUMDAT", 'C', Symmetry::rotational, 37, 1, -2, 1,
     std::nullopt, 0.5, 0.0, 0.0, 0, "ldt", 0, 0.9045000000000001, 1.0, 1.0, 1.0},
    {"synthetic_dummy_mc1_isym0.ldt", "EULUMDAT", 'C', Symmetry::rotational, 37, 1, -1, 1,
     std::nullopt, 1.0, 0.0, 0.75, 0, "ldt", 0, 0.9045000000000001, 1.0, 1.0, 1.0},
    {"synthetic_isym3_c90c270.ldt", "EULUMDAT", 'C', Symmetry::bilateral_c90_c270, 37, 19, -2, 1,
     std::nullopt, 1.0, 0.0, 0.0, 0, "ldt", 0, 3.1408, 1.0, 1.0, 1.0},
    {"synthetic_multiple_lamp_sets.ldt", "EULUMDAT", 'C', Symmetry::rotational, 37, 1, 1, 3, 500.0,
     0.5, 0.0, 0.0, 0, "ldt", 0, 0.9045000000000001, 1.0, 1.0, 1.0},
    {"thorn_thor36_empty_fields.ldt", "EULUMDAT", 'C', Symmetry::bilateral_c90_c270, 91, 37, 1, 1,
     4611.0, 4.611, 0.4, 0.4, 0, "ldt", 0, 0.9987, 1.0, 1.0, 1.0},
    {"zumtobel_arcos3_isym1.ldt", "EULUMDAT", 'C', Symmetry::rotational, 73, 1, 1, 1, 758.0, 0.758,
     0.0, 0.11, 0, "ldt", 0, 1.0019, 1.0, 1.0, 1.0},
    {"zumtobel_crossign_isym3_nonascii.ldt", "EULUMDAT", 'C', Symmetry::bilateral_c90_c270, 181, 13,
     1, 1, 51.0, 0.051, 0.01, 0.232, 0, "ldt", 0, 0.9979, 0.998, 0.516, 0.516},
    {"zumtobel_floor_uplight_dg0.ldt", "EULUMDAT", 'C', Symmetry::none, 47, 24, 1, 1, 20000.0, 20.0,
     0.0, 0.45, 0, "ldt", 0, 0.7265999999999999, 0.7232999999999999, 0.022000000000000002, 0.017},
    {"zumtobel_intro_isym0.ldt", "EULUMDAT", 'C', Symmetry::none, 73, 24, 1, 1, 2800.0, 2.8, 0.085,
     0.001, 0, "ldt", 0, 0.9801000000000001, 0.98, 0.919, 0.919},
    {"zumtobel_linetik_isym3.ldt", "EULUMDAT", 'C', Symmetry::bilateral_c90_c270, 37, 13, 1, 1,
     7650.0, 7.65, 0.013, 1.0, 0, "ldt", 0, 1.0002, 1.0, 0.26, 0.26},
    {"zumtobel_mirel_isym4.ldt", "EULUMDAT", 'C', Symmetry::quadrant, 37, 7, 1, 1, 2630.0, 2.63,
     0.345, 0.345, 0, "ldt", 0, 1.0008, 1.0, 1.0, 1.0},
    {"zumtobel_panos_isym3.ldt", "EULUMDAT", 'C', Symmetry::bilateral_c90_c270, 73, 13, 1, 1,
     1012.0, 1.012, 0.127, 0.127, 0, "ldt", 0, 0.9995, 0.9990000000000001, 1.0, 1.0},
    {"zumtobel_perluce_isym0.ldt", "EULUMDAT", 'C', Symmetry::none, 37, 24, 1, 1, 5000.0, 5.0, 0.62,
     0.62, 0, "ldt", 0, 0.9231999999999999, 0.9229999999999999, 0.995, 0.995},
    {"zumtobel_perluce_isym4.ldt", "EULUMDAT", 'C', Symmetry::quadrant, 37, 7, 1, 1, 5490.0, 5.49,
     0.62, 0.62, 0, "ldt", 0, 1.0002, 1.0, 0.9179999999999999, 0.9179999999999999},
    {"zumtobel_slotlight_isym4.ldt", "EULUMDAT", 'C', Symmetry::quadrant, 37, 7, 1, 1, 2840.0, 2.84,
     0.072, 2.0, 0, "ldt", 0, -1, -1, -1, -1},
};

void PrintTo(const Row& r, std::ostream* os) { *os << r.file; }

std::string path_of(const Row& r) {
  const std::string f = r.file;
  const bool ies = f.size() > 4 && f.substr(f.size() - 4) == ".ies";
  return std::string(LUXGRID_SOURCE_DIR) + "/tests/data/photometry/" + (ies ? "ies/" : "ldt/") + f;
}

class Corpus : public ::testing::TestWithParam<Row> {};

TEST_P(Corpus, ReadsWhatTheManifestStates) {
  const Row& r = GetParam();
  const Photometry p = load_photometry_file(path_of(r));
  const bool ies = std::string(r.file).find(".ies") != std::string::npos;
  EXPECT_EQ(p.version, r.version);
  EXPECT_EQ(to_string(p.photometric_type), std::string(1, r.type));
  EXPECT_EQ(p.symmetry, r.symmetry) << to_string(p.symmetry);
  EXPECT_EQ(p.counts_vertical, r.counts_vertical);
  EXPECT_EQ(p.counts_horizontal, r.counts_horizontal);
  ASSERT_EQ(static_cast<int>(p.lamp_sets.size()), r.lamp_sets);
  EXPECT_EQ(p.lamp_sets.front().count, r.lamps);
  EXPECT_EQ(p.lamp_flux_lm.has_value(), r.lamp_flux_lm.has_value());
  if (r.lamp_flux_lm && p.lamp_flux_lm) {
    EXPECT_NEAR(*p.lamp_flux_lm, *r.lamp_flux_lm, 1e-9 * *r.lamp_flux_lm);
  }
  EXPECT_NEAR(p.candela_multiplier, r.multiplier, 1e-12 * r.multiplier);
  ASSERT_TRUE(p.distribution);
  ASSERT_TRUE(p.table);

  // Opening: the MANIFEST's words against LM-63's sign rules / EULUMDAT's width-0-is-circular.
  using Shape = LuminousOpening::Shape;
  const LuminousOpening& o = p.opening;
  const std::string words = r.opening;
  const double tol = 2e-5;  // MANIFEST prints sizes to 5 significant digits
  if (!ies) {
    if (r.length_m == 0 && r.width_m == 0) {
      EXPECT_EQ(o.shape, Shape::point);
    } else if (r.width_m == 0) {
      EXPECT_EQ(o.shape, Shape::disk);
      EXPECT_NEAR(o.length, r.length_m, tol);
      EXPECT_NEAR(o.width, r.length_m, tol);
    } else {
      EXPECT_EQ(o.shape, Shape::rectangle);
      EXPECT_NEAR(o.length, r.length_m, tol);
      EXPECT_NEAR(o.width, r.width_m, tol);
    }
  } else if (words == "point") {
    EXPECT_EQ(o.shape, Shape::point);
  } else if (words.rfind("rectangle", 0) == 0) {
    EXPECT_EQ(o.shape, Shape::rectangle);
    EXPECT_NEAR(o.length, r.length_m, tol);  // length along C0 (x)
    EXPECT_NEAR(o.width, r.width_m, tol);    // width along C90 (y)
    EXPECT_NEAR(o.height, r.height_m, tol);
  } else if (words.rfind("round", 0) == 0) {
    EXPECT_EQ(o.shape, Shape::disk);
    EXPECT_EQ(o.description, "round");
    EXPECT_NEAR(o.length, -r.width_m, tol);
    EXPECT_NEAR(o.width, -r.width_m, tol);
  } else if (words == "circle" || words == "vertical cylinder") {
    EXPECT_EQ(o.shape, Shape::disk);
    EXPECT_EQ(o.description, words);
    EXPECT_NEAR(o.length, -r.length_m, tol);
    EXPECT_NEAR(o.width, -r.width_m, tol);
    EXPECT_NEAR(o.height, r.height_m, tol);
  } else if (words.rfind("undefined", 0) == 0) {
    // No LM-63 table defines the combination: read anyway, and say what was assumed.
    EXPECT_NE(o.description.find("assumed"), std::string::npos) << o.description;
    bool warned = false;
    for (const auto& w : p.warnings)
      warned = warned || w.find("not defined by LM-63") != std::string::npos;
    EXPECT_TRUE(warned);
  } else {
    ADD_FAILURE() << "unhandled opening words: " << words;
  }

  const DerivedPhotometry d = derive(p);
  if (ies) {
    // MANIFEST's figure is the exact integral of the bilinear interpolant, printed to 0.1 lm.
    EXPECT_NEAR(d.flux_lm, r.manifest_flux_lm, 0.05 + 1e-4 * r.manifest_flux_lm) << r.file;
  } else if (r.lor_stated >= 0) {
    // Integrated LOR against MANIFEST's own integral (0.01 points) ...
    ASSERT_TRUE(d.lor || !p.lamp_flux_lm);
    const double lor = d.flux_lm / p.lamp_sets.front().flux_lm;
    EXPECT_NEAR(lor, r.lor_integral, 0.0001 + 1e-4) << r.file;
    EXPECT_NEAR(d.dff, r.dff_integral, 0.0005 + 1e-4) << r.file;
    ASSERT_TRUE(p.stated_lor && p.stated_dff);
    EXPECT_NEAR(*p.stated_lor, r.lor_stated, 0.0006);  // MANIFEST rounds to 0.01 / 0.1 points
    EXPECT_NEAR(*p.stated_dff, r.dff_stated, 0.0006);
  }
}

// The done-when criterion: for EULUMDAT files the integrated LOR and DFF agree with the values the
// file states within 1 % (relative). The exceptions, each explained in MANIFEST.md:
//  * sample06_spot_coarse: a narrow spot resampled on a 5 deg gamma grid; the exporter computed
//    its LOR (100.1 %) from finer data; bilinear gives 102.5 %, zonal 101.6 %.
//  * projector_isym2_dg0: 55 irregular gamma values with steep edges; bilinear and zonal agree
//    (79.35 %), the stated 77.71 % comes from another quadrature or an edit.
//  * zumtobel_floor_uplight_dg0: DFF 2.2 vs 1.7 %: the downward light is a sliver next to 90 deg
//    where the interpolation rule dominates (LOR agrees within 0.5 %).
//  * the four SYNTHETIC fixtures (absolute_neg_lamps, dummy_mc1_isym0, multiple_lamp_sets,
//    isym3_c90c270): tables made up by hand, inconsistent with their stated LOR by design.
TEST(CorpusEulumdat, IntegratedLorAndDffAgreeWithStatedWithinOnePercent) {
  const std::set<std::string> lor_exceptions = {
      "sample06_spot_coarse.ldt",         "projector_isym2_dg0.ldt",
      "synthetic_absolute_neg_lamps.ldt", "synthetic_dummy_mc1_isym0.ldt",
      "synthetic_multiple_lamp_sets.ldt", "synthetic_isym3_c90c270.ldt"};
  const std::set<std::string> dff_exceptions = {"zumtobel_floor_uplight_dg0.ldt"};
  int checked = 0;
  for (const Row& r : kRows) {
    const std::string f = r.file;
    if (f.find(".ldt") == std::string::npos) continue;
    const Photometry p = load_photometry_file(path_of(r));
    const DerivedPhotometry d = derive(p);
    const double lor = d.flux_lm / p.lamp_sets.front().flux_lm;
    ASSERT_TRUE(p.stated_lor && p.stated_dff);
    if (!lor_exceptions.count(f)) {
      EXPECT_NEAR(lor, *p.stated_lor, 0.01 * *p.stated_lor) << f;
      ++checked;
    }
    if (!dff_exceptions.count(f)) {
      EXPECT_NEAR(d.dff, *p.stated_dff, 0.01 * *p.stated_dff) << f;
    }
  }
  EXPECT_EQ(checked, 27 - 6);
}

// The flux table of every corpus file, bilinear against bicubic interpolation (printed, run with
// --gtest_filter=*FluxTable*). Checked: both integrals are positive, the downward part lies in
// [0, total], and the two interpolations, which meet at every table value, differ in flux by at
// most kInterpolationFluxShare: measured at most 2 % on all but four files, 4 to 6 % on the
// narrow spots (erco_qrcbc35, kurtversen_par38, erco_stella) and 16.7 % on a tiny synthetic
// table (mdl_test_iesna91_typeb), so 0.2 allows each and catches an integral gone wrong.
TEST(CorpusReport, FluxTableBilinearAndBicubicAgree) {
  constexpr double kInterpolationFluxShare = 0.2;
  for (const Row& r : kRows) {
    const Photometry p = load_photometry_file(path_of(r));
    const DerivedPhotometry d = derive(p);
    const DerivedPhotometry dc = derive([&] {
      Photometry q = p;
      q.table = p.table->with_interpolation(Interpolation::bicubic);
      q.distribution = q.table;
      return q;
    }());
    std::printf("| %s | %.1f | %.1f | %s | %.3f | %.1f |\n", r.file, d.flux_lm, dc.flux_lm,
                d.lor ? std::to_string(*d.lor).substr(0, 6).c_str() : "-", d.dff, d.max_cd);
    for (const DerivedPhotometry& x : {d, dc}) {
      EXPECT_GT(x.flux_lm, 0.0) << r.file;
      EXPECT_GE(x.downward_flux_lm, 0.0) << r.file;
      EXPECT_LE(x.downward_flux_lm, x.flux_lm * (1.0 + 1e-12)) << r.file;
    }
    EXPECT_NEAR(dc.flux_lm, d.flux_lm, kInterpolationFluxShare * d.flux_lm) << r.file;
  }
}

INSTANTIATE_TEST_SUITE_P(Manifest, Corpus, ::testing::ValuesIn(kRows),
                         [](const ::testing::TestParamInfo<Row>& info) {
                           std::string n = info.param.file;
                           for (char& c : n)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return n;
                         });

}  // namespace
}  // namespace luxgrid::photometry
