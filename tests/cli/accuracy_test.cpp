// `luxgrid accuracy` end to end: the command runs the study (study/accuracy_study.h) and
// writes its table and plot; bad input is exit 2.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "calc/nearfield/illuminance.h"
#include "tests/cli/cli_support.h"

namespace {

namespace fs = std::filesystem;
using luxgrid::nearfield::Model;

const fs::path kLdtDir = fs::path(LUXGRID_SOURCE_DIR) / "tests/data/photometry/ldt";

TEST(AccuracyCommand, QuickRunWritesTableAndPlot) {
  const fs::path out = luxgrid::test::scratch("accuracy");
  const std::string cmd = std::string(LUXGRID_BINARY) + " accuracy --quick --out " + out.string() +
                          " --photometry " + kLdtDir.string() + " 2>&1";
  std::string output;
  FILE* pipe = popen(cmd.c_str(), "r");
  std::array<char, 4096> buf{};
  while (size_t n = fread(buf.data(), 1, buf.size(), pipe)) output.append(buf.data(), n);
  const int status = pclose(pipe);
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << output;
  EXPECT_TRUE(fs::exists(out / "accuracy.md"));
  ASSERT_TRUE(fs::exists(out / "accuracy.png"));
  EXPECT_GT(fs::file_size(out / "accuracy.png"), 1000u);
  std::ifstream md(out / "accuracy.md");
  std::stringstream text;
  text << md.rdbuf();
  EXPECT_NE(text.str().find("| " + luxgrid::nearfield::to_string(Model::paper_cubature()) + " |"),
            std::string::npos);
}

TEST(AccuracyCommand, MissingPhotometryIsBadInput) {
  const std::string cmd =
      std::string(LUXGRID_BINARY) + " accuracy --quick --photometry /nonexistent 2>&1";
  FILE* pipe = popen(cmd.c_str(), "r");
  std::array<char, 4096> buf{};
  std::string output;
  while (size_t n = fread(buf.data(), 1, buf.size(), pipe)) output.append(buf.data(), n);
  const int status = pclose(pipe);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 2) << output;
  EXPECT_NE(output.find("zumtobel_arcos3_isym1.ldt: photometry file of the study not found"),
            std::string::npos)
      << output;
}

}  // namespace
