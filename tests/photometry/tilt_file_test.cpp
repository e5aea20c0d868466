// Where a TILT=<file> is looked for and what is refused before it is read (photometry/tilt_file.h):
// relative to the IES file's folder whatever the current directory, inside the allowed root
// after "..", and symbolic links, a regular file below kMaxTiltFileBytes. Each case builds its own
// folder, so the messages are exact.
#include "photometry/tilt_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "photometry/file_bytes.h"
#include "photometry/photometry.h"
#include "photometry/tilt.h"
#include "util/error.h"

namespace luxgrid::photometry {
namespace {

namespace fs = std::filesystem;

// A small valid LM-63-2002 file naming `tilt` on line 4.
std::string panel(const std::string& tilt) {
  return "IESNA:LM-63-2002\n[TEST] tilt\n[MANUFAC] luxgrid tests\nTILT=" + tilt +
         "\n1 1000 1 3 1 1 2 0 0 0\n1 1 10\n0 45 90\n0\n100 50 0\n";
}

void write(const fs::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
}

// A fresh folder of this process under testing::TempDir() (parallel runs never share it):
// <tmp>/lxtilt<pid>/<name>/ with sub/ inside it. Short, because one test writes its absolute path
// after TILT=, where at most 64 characters are allowed; each test passes its own `name`.
fs::path scratch(const std::string& name) {
  const fs::path dir =
      fs::path(::testing::TempDir()) / ("lxtilt" + std::to_string(::getpid())) / name;
  fs::remove_all(dir);
  fs::create_directories(dir / "sub");
  return dir;
}

std::string message_of(const fs::path& file, const LoadOptions& options, const fs::path& strip) {
  try {
    (void)load_photometry_file(file, options);
  } catch (const InputError& e) {
    std::string m = e.what();
    const std::string prefix = strip.string() + "/";
    for (std::size_t pos; (pos = m.find(prefix)) != std::string::npos;) m.erase(pos, prefix.size());
    return m;
  }
  return "accepted";
}

LoadOptions root(const fs::path& r) {
  LoadOptions o;
  o.allowed_root = r;
  return o;
}

// Restores the current directory when a test ends, even on failure.
struct CurrentDirectory {
  explicit CurrentDirectory(const fs::path& p) : saved(fs::current_path()) { fs::current_path(p); }
  ~CurrentDirectory() { fs::current_path(saved); }
  fs::path saved;
};

TEST(TiltFile, IsReadBesideTheIesFileNotFromTheCurrentDirectory) {
  const fs::path dir = scratch("beside");
  write(dir / "sub/panel.ies", panel("lamp.tilt"));
  write(dir / "sub/lamp.tilt", "1\n2\n0 90\n1 0.5\n");
  write(dir / "lamp.tilt", "1\n2\n0 90\n1 0.25\n");  // the current directory's: must not be used
  const CurrentDirectory cd(dir);
  const Photometry p = load_photometry_file("sub/panel.ies", root(dir / "sub"));
  ASSERT_TRUE(p.tilt);
  EXPECT_EQ(p.tilt->factor_at(90.0), 0.5);
  EXPECT_EQ(p.tilt->source, "sub/lamp.tilt");
}

TEST(TiltFile, AGigabyteTiltFileIsRefusedFromItsSizeBeforeItIsRead) {
  const fs::path dir = scratch("huge");
  write(dir / "panel.ies", panel("huge.tilt"));
  write(dir / "huge.tilt", "");
  fs::resize_file(dir / "huge.tilt", 1u << 30);  // sparse: no gigabyte on disk, nor in memory
  EXPECT_EQ(message_of(dir / "panel.ies", {}, dir),
            "panel.ies:4: TILT file 'huge.tilt': huge.tilt: file is 1073741824 bytes; TILT files "
            "are expected below 1048576 bytes");
}

TEST(TiltFile, AFifoIsNotARegularFile) {
  // A naive reader would block on a FIFO for ever.
  const fs::path dir = scratch("fifo");
  write(dir / "panel.ies", panel("pipe.tilt"));
  ASSERT_EQ(::mkfifo((dir / "pipe.tilt").c_str(), 0600), 0);
  EXPECT_EQ(
      message_of(dir / "panel.ies", {}, dir),
      "panel.ies:4: TILT file 'pipe.tilt': pipe.tilt: is a FIFO (named pipe), not a regular file");
}

TEST(TiltFile, OutsideTheRootIsRefusedAndAnEmptyRootAllowsIt) {
  const fs::path dir = scratch("outside");
  write(dir / "outside.tilt", "1\n2\n0 90\n1 0.5\n");
  write(dir / "sub/climbs.ies", panel("../outside.tilt"));
  write(dir / "sub/absolute.ies", panel((dir / "outside.tilt").string()));
  const std::string refused =
      " lies outside the project folder; refused (a TILT file must be in the folder of the "
      "project or below it)";
  EXPECT_EQ(message_of(dir / "sub/climbs.ies", root(dir / "sub"), dir),
            "sub/climbs.ies:4: TILT file '../outside.tilt'" + refused);
  EXPECT_EQ(message_of(dir / "sub/absolute.ies", root(dir / "sub"), dir),
            "sub/absolute.ies:4: TILT file 'outside.tilt'" + refused);  // the folder is stripped
  // The project folder above both: allowed; no root at all: allowed.
  EXPECT_EQ(load_photometry_file(dir / "sub/climbs.ies", root(dir)).tilt->factor_at(90.0), 0.5);
  EXPECT_EQ(load_photometry_file(dir / "sub/absolute.ies").tilt->factor_at(90.0), 0.5);
}

TEST(TiltFile, ASymbolicLinkCannotLeadOutOfTheRoot) {
  const fs::path dir = scratch("symlink");
  write(dir / "outside.tilt", "1\n2\n0 90\n1 0.5\n");
  fs::create_symlink(dir / "outside.tilt", dir / "sub/link.tilt");
  write(dir / "sub/panel.ies", panel("link.tilt"));
  EXPECT_EQ(message_of(dir / "sub/panel.ies", root(dir / "sub"), dir),
            "sub/panel.ies:4: TILT file 'link.tilt' lies outside the project folder; refused (a "
            "TILT file must be in the folder of the project or below it)");
}

TEST(TiltFile, LiesWithinComparesWholeComponents) {
  EXPECT_TRUE(lies_within("/data/project/a.tilt", "/data/project"));
  EXPECT_TRUE(lies_within("/data/project/a.tilt", "/data/project/"));
  EXPECT_TRUE(lies_within("/data/project/x/../a.tilt", "/data/project"));
  EXPECT_FALSE(lies_within("/data/project2/a.tilt", "/data/project"));
  EXPECT_FALSE(lies_within("/data/project/../a.tilt", "/data/project"));
  EXPECT_TRUE(lies_within("/anything", ""));
}

TEST(FileBytes, FilesThatReportSizeZeroAreStillReadWhole) {
  // /proc files are regular but report 0 bytes: the read goes by chunks, not by the size.
  const std::string status = read_bounded_file("/proc/self/status", "status", 1u << 20, "test");
  EXPECT_NE(status.find("Name:"), std::string::npos);
  EXPECT_THROW((void)read_bounded_file("/proc/self/status", "status", 8, "test"), InputError);
}

}  // namespace
}  // namespace luxgrid::photometry
