// `luxgrid info` end to end: the checking-tool warnings in text and in --json, the flux
// convention named, and a TILT file outside the file's folder refused with exit 2.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/cli/cli_support.h"

namespace {

namespace fs = std::filesystem;

struct Result {
  int code;
  std::string out;  // stdout and stderr (warnings go to stderr)
};

Result info(const std::string& args) {
  const auto r = luxgrid::test::luxgrid("info " + args);
  return {r.code, r.output};
}

// stdout alone: --json output must parse even when the file has warnings (they go to stderr).
Result info_stdout(const std::string& args) {
  const auto r =
      luxgrid::test::shell("(" + std::string(LUXGRID_BINARY) + " info " + args + " 2>/dev/null)");
  return {r.code, r.output};
}

const std::string kCorpus = std::string(LUXGRID_SOURCE_DIR) + "/tests/data/photometry/";
const std::string kPole =
    "the C planes disagree at gamma 0 (2200 to 2866 cd, 30.3 %); the pole is taken as their mean";

TEST(InfoCli, WarningsAndTheFluxConventionInText) {
  const Result r = info(kCorpus + "ldt/synthetic_isym3_c90c270.ldt");
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(
      r.out.find("luxgrid: warning: " + kCorpus + "ldt/synthetic_isym3_c90c270.ldt: " + kPole),
      std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("  photometry    absolute photometry (EULUMDAT lamp count -2 < 0; 1000 lm "
                       "is the luminaire flux)\n"),
            std::string::npos)
      << r.out;
}

TEST(InfoCli, WarningsAndTheFluxConventionInJson) {
  const Result r = info_stdout(kCorpus + "ldt/synthetic_isym3_c90c270.ldt --json");
  ASSERT_EQ(r.code, 0);
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j["warnings"].is_array());
  ASSERT_GE(j["warnings"].size(), 1u);
  EXPECT_EQ(j["warnings"][0], kCorpus + "ldt/synthetic_isym3_c90c270.ldt: " + kPole);
  EXPECT_EQ(j["flux_convention"],
            "absolute photometry (EULUMDAT lamp count -2 < 0; 1000 lm is the luminaire flux)");
  // A clean file has an empty array, not a missing key.
  const auto clean =
      nlohmann::json::parse(info_stdout(kCorpus + "ldt/zumtobel_mirel_isym4.ldt --json").out);
  EXPECT_EQ(clean["warnings"], nlohmann::json::array());
}

TEST(InfoCli, ATiltFileOutsideTheFilesFolderIsRefused) {
  const fs::path dir = luxgrid::test::scratch("tilt");
  fs::create_directories(dir / "sub");
  std::ofstream(dir / "lamp.tilt") << "1\n2\n0 90\n1 1\n";
  std::ofstream(dir / "sub/panel.ies") << "IESNA:LM-63-2002\n[TEST] x\nTILT=../lamp.tilt\n1 -1 1 2 "
                                          "1 1 2 0 0 0\n1 1 10\n0 90\n0\n10 0\n";
  const Result r = info((dir / "sub/panel.ies").string());
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.out, "luxgrid: error: " + (dir / "sub/panel.ies").string() +
                       ":3: TILT file '../lamp.tilt' lies outside the project folder; refused (a "
                       "TILT file must be in the folder of the project or below it)\n");
}

}  // namespace
