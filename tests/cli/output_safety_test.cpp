// `-o` never destroys a user's files, through the real binary (docs/reliability.md): an existing
// file, a folder of other files, the project file and the project's folder are refused with exit
// 2 and left byte for byte; a symbolic link is followed; a run killed with SIGKILL leaves a staging
// folder that the next run removes; two runs into one folder leave one run's output, whole;
// `luxgrid view` writes over no file it did not write.
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <set>
#include <thread>

#include <nlohmann/json.hpp>

#include "tests/cli/cli_support.h"

namespace {

namespace fs = std::filesystem;
using luxgrid::test::entries;
using luxgrid::test::luxgrid;
using luxgrid::test::quote;
using luxgrid::test::read_file;
using luxgrid::test::scratch;
using luxgrid::test::write_file;

// A black 4 x 4 m room, one isotropic source; `spacing` sets the cost.
std::string project(const std::string& name, double spacing = 1.0,
                    const std::string& quality = "standard") {
  return R"({
  "format": "luxgrid-project/1", "name": ")" +
         name + R"(",
  "settings": { "quality": ")" +
         quality + R"(" },
  "photometry": { "panel": { "builtin": "lambertian", "intensity_cd": 1000 } },
  "rooms": [ { "name": "r", "outline": [[0,0],[4,0],[4,4],[0,4]], "height": 3,
               "reflectance": { "floor": 0.2, "walls": 0.5, "ceiling": 0.7 } } ],
  "luminaires": [ { "photometry": "panel", "position": [2, 2, 2.9],
                    "emitter": { "shape": "rectangle", "size": [1.2, 0.6] } } ],
  "surfaces": [ { "name": ")" +
         name + R"(", "workplane": { "room": "r", "height": 0.8, "border": 0 },
                  "spacing": )" +
         std::to_string(spacing) + R"( } ]
})";
}

TEST(OutputSafety, ExistingFileIsRefusedAndKept) {
  const fs::path dir = scratch("file");
  write_file(dir / "p.json", project("floor"));
  write_file(dir / "report.pdf", "the client's signed copy");
  const auto r = luxgrid("calc " + quote(dir / "p.json") + " -o " + quote(dir / "report.pdf"));
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.output, "luxgrid: error: " + (dir / "report.pdf").string() +
                          ": exists and is not a folder; luxgrid writes only into a new folder, an "
                          "empty one, or one it wrote before (choose another -o)\n");
  EXPECT_EQ(read_file(dir / "report.pdf"), "the client's signed copy");
  EXPECT_EQ(entries(dir), (std::set<std::string>{"p.json", "report.pdf"}));
}

// `luxgrid view -o FILE` writes over FILE only when an earlier `luxgrid view` wrote it: a page of
// the user's and a glb another tool wrote are refused with exit 2 and kept byte for byte.
TEST(OutputSafety, ViewOverwritesOnlyItsOwnFile) {
  const fs::path dir = scratch("view");
  write_file(dir / "p.json", project("floor"));
  const std::string p = quote(dir / "p.json");
  for (const std::string name : {"page.html", "model.glb"}) {
    const std::string theirs = name == "page.html" ? "<html>the client's page</html>"
                                                   : std::string("glTF\x02\0\0\0another tool");
    write_file(dir / name, theirs);
    const auto r = luxgrid("view " + p + " -o " + quote(dir / name));
    EXPECT_EQ(r.code, 2) << name;
    EXPECT_EQ(r.output, "luxgrid: error: " + (dir / name).string() +
                            ": exists and was not written by luxgrid view: not overwritten "
                            "(choose another file with -o, or remove it)\n");
    EXPECT_EQ(read_file(dir / name), theirs) << name;
    // Its own file it writes again.
    const fs::path own = dir / ("own_" + name);
    EXPECT_EQ(luxgrid("view " + p + " -o " + quote(own)).code, 0) << name;
    const std::string first = read_file(own);
    EXPECT_EQ(luxgrid("view " + p + " -o " + quote(own)).code, 0) << name;
    EXPECT_EQ(read_file(own), first) << name;
  }
}

TEST(OutputSafety, ForeignFolderIsRefusedAndKept) {
  const fs::path dir = scratch("foreign");
  write_file(dir / "p.json", project("floor"));
  fs::create_directory(dir / "home");
  write_file(dir / "home" / "notes.txt", "mine");
  const auto r = luxgrid("calc " + quote(dir / "p.json") + " -o " + quote(dir / "home"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find(": is a folder that luxgrid did not write"), std::string::npos)
      << r.output;
  EXPECT_EQ(entries(dir / "home"), std::set<std::string>{"notes.txt"});
  EXPECT_EQ(entries(dir), (std::set<std::string>{"home", "p.json"}));
}

TEST(OutputSafety, TheProjectFileAndItsFolderAreRefused) {
  const fs::path dir = scratch("self");
  const std::string text = project("floor");
  write_file(dir / "p.json", text);
  const auto r = luxgrid("calc " + quote(dir / "p.json") + " -o " + quote(dir / "p.json"));
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.output, "luxgrid: error: " + (dir / "p.json").string() +
                          ": the output folder would replace " + (dir / "p.json").string() +
                          ", an input of this run; choose another output folder (-o)\n");
  EXPECT_EQ(read_file(dir / "p.json"), text);
  const auto folder = luxgrid("calc " + quote(dir / "p.json") + " -o " + quote(dir));
  EXPECT_EQ(folder.code, 2);
  EXPECT_NE(folder.output.find("an input of this run"), std::string::npos) << folder.output;
  EXPECT_EQ(read_file(dir / "p.json"), text);
  EXPECT_EQ(entries(dir), std::set<std::string>{"p.json"});
}

TEST(OutputSafety, SymlinkIsFollowedNotReplaced) {
  const fs::path dir = scratch("symlink");
  write_file(dir / "p.json", project("floor"));
  fs::create_directory(dir / "elsewhere");
  fs::create_directory_symlink(dir / "elsewhere", dir / "out");
  for (int run = 0; run < 2; ++run) {
    const auto r = luxgrid("calc " + quote(dir / "p.json") + " -o " + quote(dir / "out"));
    ASSERT_EQ(r.code, 0) << r.output;
    EXPECT_TRUE(fs::is_symlink(dir / "out"));
    EXPECT_TRUE(fs::exists(dir / "elsewhere" / "results.json"));
  }
}

TEST(OutputSafety, KilledRunLeavesStagingThatTheNextRunRemoves) {
  const fs::path dir = scratch("kill");
  // Long enough to be killed mid-run: 0.02 m grid, reference quality (several seconds).
  write_file(dir / "slow.json", project("floor", 0.02, "reference"));
  write_file(dir / "p.json", project("floor"));
  const pid_t child = fork();
  if (child == 0) {
    const std::string out = (dir / "out").string(), proj = (dir / "slow.json").string();
    execl(LUXGRID_BINARY, LUXGRID_BINARY, "calc", proj.c_str(), "-o", out.c_str(),
          static_cast<char*>(nullptr));
    _exit(127);
  }
  // Wait for the staging folder (it appears once the project is loaded), then SIGKILL.
  auto staging_present = [&] {
    for (const auto& e : fs::directory_iterator(dir))
      if (e.path().filename().string().rfind(".out.tmp-", 0) == 0) return true;
    return false;
  };
  const auto t0 = std::chrono::steady_clock::now();
  while (!staging_present() && std::chrono::steady_clock::now() - t0 < std::chrono::seconds(30))
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  ASSERT_TRUE(staging_present());
  kill(child, SIGKILL);
  int status = 0;
  waitpid(child, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the run finished before it could be killed";
  EXPECT_TRUE(staging_present());
  EXPECT_FALSE(fs::exists(dir / "out"));
  const auto r = luxgrid("calc " + quote(dir / "p.json") + " -o " + quote(dir / "out"));
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_EQ(entries(dir), (std::set<std::string>{"out", "p.json", "slow.json"}));
}

TEST(OutputSafety, TwoConcurrentRunsLeaveOneWholeOutput) {
  const fs::path dir = scratch("concurrent");
  // Two projects with different surface names: the folder must hold one project's files only.
  write_file(dir / "a.json", project("alpha", 0.1));
  write_file(dir / "b.json", project("beta", 0.1));
  const std::string out = quote(dir / "out");
  luxgrid::test::CommandResult ra, rb;
  std::thread ta(
      [&] { ra = luxgrid("calc " + quote(dir / "a.json") + " -o " + out + " --no-report"); });
  std::thread tb(
      [&] { rb = luxgrid("calc " + quote(dir / "b.json") + " -o " + out + " --no-report"); });
  ta.join();
  tb.join();
  EXPECT_EQ(ra.code, 0) << ra.output;
  EXPECT_EQ(rb.code, 0) << rb.output;
  const auto j = nlohmann::json::parse(read_file(dir / "out" / "results.json"));
  const std::string name = j["surfaces"][0]["name"];
  ASSERT_TRUE(name == "alpha" || name == "beta") << name;
  EXPECT_EQ(entries(dir / "out"),
            (std::set<std::string>{".luxgrid-output", "results.json", "timing.json", "scene.glb",
                                   name + ".csv", name + ".png"}));
  EXPECT_EQ(entries(dir), (std::set<std::string>{"a.json", "b.json", "out"}));
}

}  // namespace
