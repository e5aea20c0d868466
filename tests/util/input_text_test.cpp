// util/degrees.h, util/printable.h, util/file_kind.h: the reductions and checks applied to a
// user's numbers, keys and paths before use. Each expected value is written out by hand.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include "util/degrees.h"
#include "util/file_kind.h"
#include "util/printable.h"

namespace luxgrid {
namespace {

TEST(ReduceDegrees, AnglesWithinOneTurnKeepTheirBits) {
  for (double deg : {0.0, -0.0, 30.0, -30.0, 0.1, 359.99999999999994, -359.99999999999994, 1e-300,
                     90.0 + 1e-13}) {
    const double r = reduce_degrees(deg);
    EXPECT_EQ(std::memcmp(&r, &deg, sizeof r), 0) << deg;
  }
}

TEST(ReduceDegrees, ExactMultiplesOfATurnGiveZero) {
  // 360 x 2^k is a double for every k up to 1014; 2^900 x 360 is about 3e273.
  for (int k : {0, 1, 10, 100, 900, 1014}) {
    const double deg = std::ldexp(360.0, k);
    EXPECT_EQ(reduce_degrees(deg), 0.0) << k;
    EXPECT_FALSE(std::signbit(reduce_degrees(deg))) << k;
    EXPECT_EQ(reduce_degrees(-deg), 0.0) << k;
    EXPECT_FALSE(std::signbit(reduce_degrees(-deg))) << k;
  }
}

TEST(ReduceDegrees, LargeAnglesKeepTheirPlaceInTheTurn) {
  EXPECT_EQ(reduce_degrees(450.0), 90.0);
  EXPECT_EQ(reduce_degrees(-450.0), -90.0);
  EXPECT_EQ(reduce_degrees(360.0 * 1000003.0 + 45.0), 45.0);
  // Remainders computed exactly in Python's integers (int(x) % 360): the double nearest 1e300
  // is a multiple of 360 (the rotation), that nearest 7e22 leaves 104.
  EXPECT_EQ(reduce_degrees(1e300), 0.0);
  EXPECT_EQ(reduce_degrees(7e22), 104.0);
  EXPECT_EQ(reduce_degrees(-7e22), -104.0);
}

TEST(PrintableText, ControlCharactersAreEscapedAndNothingElse) {
  EXPECT_EQ(printable_text(std::string("rot\0ation", 9)), "rot\\u0000ation");
  EXPECT_EQ(printable_text("a\x01"
                           "b\x1f"
                           "c\x7f"),
            "a\\u0001b\\u001Fc\\u007F");
  EXPECT_EQ(printable_text("tab\there\nnew"), "tab\\u0009here\\u000Anew");
  EXPECT_EQ(printable_text("caf\xc3\xa9 \"q\" \\ /x"), "caf\xc3\xa9 \"q\" \\ /x");
}

class FileKind : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("luxgrid-file-kind-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::filesystem::path dir_;
};

TEST_F(FileKind, NamesWhatThePathIsWithoutOpeningIt) {
  std::ofstream(dir_ / "plain.ies") << "x";
  EXPECT_EQ(not_a_regular_file(dir_ / "plain.ies"), "");
  EXPECT_EQ(not_a_regular_file(dir_ / "absent.ies"), "file not found");
  EXPECT_EQ(not_a_regular_file(dir_), "is a folder, not a file");
  // A FIFO with no writer: opening it would block this test for ever; stat does not.
  ASSERT_EQ(::mkfifo((dir_ / "pipe.ies").c_str(), 0600), 0);
  EXPECT_EQ(not_a_regular_file(dir_ / "pipe.ies"), "is a FIFO (named pipe), not a regular file");
  EXPECT_EQ(not_a_regular_file("/dev/null"), "is not a regular file (a device or a socket)");
}

}  // namespace
}  // namespace luxgrid
