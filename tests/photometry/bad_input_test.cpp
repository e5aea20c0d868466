// Hostile inputs (docs/reliability.md): every file under tests/data/bad/ must be rejected with
// exactly the message in <file>.expected (the folder is stripped from the message), never a
// crash, never a partial result. tests/data/bad/make_bad.py writes the files and messages.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "photometry/photometry.h"
#include "util/error.h"

namespace luxgrid::photometry {
namespace {

const std::filesystem::path kBadDir = std::filesystem::path(LUXGRID_SOURCE_DIR) / "tests/data/bad";

std::vector<std::string> bad_files() {
  std::vector<std::string> out;
  for (const auto& e : std::filesystem::directory_iterator(kBadDir)) {
    const std::string ext = e.path().extension().string();
    if (ext == ".ies" || ext == ".ldt") out.push_back(e.path().filename().string());
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::string replace_all(std::string s, const std::string& from, const std::string& to) {
  for (std::size_t pos = 0; (pos = s.find(from, pos)) != std::string::npos; pos += to.size())
    s.replace(pos, from.size(), to);
  return s;
}

class BadInput : public ::testing::TestWithParam<std::string> {};

TEST_P(BadInput, IsRejectedWithItsMessage) {
  const std::filesystem::path file = kBadDir / GetParam();
  std::ifstream ex(file.string() + ".expected");
  ASSERT_TRUE(ex) << "missing " << file << ".expected";
  std::string expected;
  std::getline(ex, expected);
  // As `luxgrid info` reads a file: TILT files may only come from the file's own folder.
  LoadOptions options;
  options.allowed_root = kBadDir;
  try {
    (void)load_photometry_file(file, options);
    ADD_FAILURE() << GetParam() << " was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(replace_all(e.what(), kBadDir.string() + "/", ""), expected);
  }
}

INSTANTIATE_TEST_SUITE_P(TestsDataBad, BadInput, ::testing::ValuesIn(bad_files()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string n = info.param;
                           for (char& c : n)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return n;
                         });

TEST(BadInputDir, HasTheHostileFiles) { EXPECT_EQ(bad_files().size(), 56u); }

TEST(BadInput, MissingFileNamesIt) {
  try {
    (void)load_photometry_file("/nonexistent/x.ies");
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "/nonexistent/x.ies: file not found");
  }
}

// Every prefix of a real file either reads or throws InputError (never crashes or hangs): a
// cheap, deterministic cousin of the fuzzers in fuzz/.
TEST(BadInput, EveryTruncationOfARealFileIsHandled) {
  for (const char* rel :
       {"ies/lithonia_esg_iesna91_commas.ies", "ldt/zumtobel_mirel_isym4.ldt",
        "ies/synthetic_tilt_include_lm02.ies", "ies/mdl_test_iesna91_typeb.ies"}) {
    const auto path = std::filesystem::path(LUXGRID_SOURCE_DIR) / "tests/data/photometry" / rel;
    std::ifstream in(path, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_FALSE(bytes.empty());
    for (std::size_t n = 0; n < bytes.size(); n += 7) {
      try {
        const Photometry p =
            load_photometry_text(std::string_view(bytes).substr(0, n), path.filename().string());
        EXPECT_TRUE(p.distribution);
      } catch (const InputError&) {
      }
    }
  }
}

}  // namespace
}  // namespace luxgrid::photometry
