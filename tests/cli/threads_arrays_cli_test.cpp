// `--threads N` / LUXGRID_THREADS and `--arrays npy` through the real binary.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "tests/cli/cli_support.h"

namespace {

namespace fs = std::filesystem;
using luxgrid::test::CommandResult;
using luxgrid::test::scratch;

// A reflecting room, so the reflected-light solve (a parallel loop over patches) runs too.
const char* kRoom = R"({
  "format": "luxgrid-project/1", "name": "threads test",
  "photometry": { "iso": { "builtin": "isotropic", "intensity_cd": 1000 } },
  "rooms": [ { "name": "r", "outline": [[0,0],[4,0],[4,3],[0,3]], "height": 3,
               "reflectance": { "floor": 0.2, "walls": 0.5, "ceiling": 0.7 } } ],
  "luminaires": [ { "photometry": "iso", "position": [1.5, 1.5, 2.9] } ],
  "surfaces": [ { "name": "floor", "workplane": { "room": "r", "height": 0.8, "border": 0.25 }, "spacing": 0.5 } ]
})";

fs::path example_project(const std::string& name) {
  const fs::path dir = scratch(name);
  luxgrid::test::write_file(dir / "p.json", kRoom);
  return dir;
}

TEST(Threads, ResultsDoNotDependOnTheThreadCount) {
  // Every parallel loop writes its own points or patches, so 1 and 2 threads must give the same
  // bytes; the option works before and after the subcommand, the variable without the option.
  const fs::path dir = example_project("threads_same");
  const std::string p = (dir / "p.json").string();
  ASSERT_EQ(luxgrid::test::luxgrid("--threads 1 calc " + p + " -o " + (dir / "one").string()).code,
            0);
  ASSERT_EQ(
      luxgrid::test::luxgrid("calc " + p + " -o " + (dir / "two").string() + " --threads 2").code,
      0);
  ASSERT_EQ(luxgrid::test::shell("LUXGRID_THREADS=2 " + std::string(LUXGRID_BINARY) + " calc " + p +
                                 " -o " + (dir / "env").string())
                .code,
            0);
  const std::string one = luxgrid::test::read_file(dir / "one" / "results.json");
  EXPECT_NE(one.find("\"E_indirect\""), std::string::npos);
  EXPECT_EQ(one, luxgrid::test::read_file(dir / "two" / "results.json"));
  EXPECT_EQ(one, luxgrid::test::read_file(dir / "env" / "results.json"));
  EXPECT_EQ(luxgrid::test::read_file(dir / "one" / "floor.png"),
            luxgrid::test::read_file(dir / "two" / "floor.png"));
}

TEST(Threads, BadCountsAreBadInput) {
  const fs::path dir = example_project("threads_bad");
  const std::string calc = " calc " + (dir / "p.json").string() + " -o " + (dir / "out").string();
  for (const char* n : {"0", "-1", "1025", "two"}) {
    const CommandResult r = luxgrid::test::luxgrid(std::string("--threads ") + n + calc);
    EXPECT_EQ(r.code, 2) << n << ": " << r.output;
  }
  for (const char* n : {"0", "abc", "4x", "100000"}) {
    const CommandResult r =
        luxgrid::test::shell(std::string("LUXGRID_THREADS=") + n + " " + LUXGRID_BINARY + calc);
    EXPECT_EQ(r.code, 2) << n << ": " << r.output;
    EXPECT_NE(r.output.find("LUXGRID_THREADS"), std::string::npos) << r.output;
  }
  EXPECT_FALSE(fs::exists(dir / "out")) << "refused before anything was written";
}

TEST(ArraysNpy, TheArrayHoldsTheCsvsPointsAndValues) {
  const fs::path dir = example_project("arrays_npy");
  const CommandResult r = luxgrid::test::luxgrid("calc " + (dir / "p.json").string() + " -o " +
                                                 (dir / "out").string() + " --arrays npy");
  ASSERT_EQ(r.code, 0) << r.output;
  const std::string npy = luxgrid::test::read_file(dir / "out" / "floor.npy");
  ASSERT_GT(npy.size(), 10u);
  ASSERT_EQ(npy.substr(0, 8), std::string("\x93NUMPY\x01\x00", 8));
  const std::size_t header =
      static_cast<unsigned char>(npy[8]) | (static_cast<unsigned char>(npy[9]) << 8);
  const std::string dict = npy.substr(10, header);
  // The CSV's rows are the array's rows: the same count, x y z and E, E_direct, E_indirect.
  std::istringstream csv(luxgrid::test::read_file(dir / "out" / "floor.csv"));
  std::string line;
  std::getline(csv, line);  // header
  std::vector<std::vector<double>> rows;
  while (std::getline(csv, line)) {
    std::vector<double> v;
    std::istringstream cells(line);
    std::string cell;
    // i,j,x,y,z,nx,ny,nz,active,E,E_direct,E_indirect,quantity (docs/project-format.md)
    for (int c = 0; c < 12 && std::getline(cells, cell, ','); ++c)
      v.push_back(c == 8 ? (cell == "true" ? 1.0 : 0.0) : std::stod(cell));
    ASSERT_EQ(v.size(), 12u) << line;
    ASSERT_EQ(v[8], 1.0) << "every point of the rectangular workplane is active: " << line;
    rows.push_back({v[2], v[3], v[4], v[9], v[10], v[11]});
  }
  ASSERT_EQ(rows.size(), 35u) << "7 x 5 points at 0.5 m on the 3.5 x 2.5 m inset workplane";
  EXPECT_NE(dict.find("'shape': (" + std::to_string(rows.size()) + ", 6)"), std::string::npos)
      << dict;
  ASSERT_EQ(npy.size(), 10 + header + rows.size() * 6 * 8);
  for (std::size_t k = 0; k < rows.size(); ++k) {
    for (int c = 0; c < 6; ++c) {
      std::uint64_t bits = 0;
      for (int b = 0; b < 8; ++b)
        bits |= std::uint64_t(static_cast<unsigned char>(npy[10 + header + (k * 6 + c) * 8 + b]))
                << (8 * b);
      const double v = std::bit_cast<double>(bits);
      // The CSV prints 6 significant digits: half a unit of the 6th digit, relative.
      EXPECT_NEAR(v, rows[k][c], 5e-6 * std::max(1.0, std::abs(rows[k][c]))) << k << "," << c;
    }
  }
}

}  // namespace
