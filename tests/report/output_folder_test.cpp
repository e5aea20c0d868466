// The output folder never destroys what luxgrid did not write (report/output_folder.h): every
// refusal leaves the user's files byte for byte as they were; what luxgrid wrote is replaced whole.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "report/output_folder.h"
#include "util/error.h"

namespace luxgrid::report {
namespace {

namespace fs = std::filesystem;

// A folder of this test's own (test name and pid), removed when the test ends.
class OutputFolderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::path(::testing::TempDir()) /
           ("luxgrid_output_folder_" + std::string(info->name()) + "_" + std::to_string(getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

void write(const fs::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
}
std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}
std::vector<std::string> entries(const fs::path& folder) {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(folder)) out.push_back(e.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}
std::string refusal(const fs::path& target, std::vector<fs::path> inputs = {}) {
  try {
    OutputFolder f(target, std::move(inputs));
    f.commit();
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

void write_run(const fs::path& target, const std::string& content) {
  OutputFolder f(target);
  write_text_file(f.file("results.json"), content);
  f.commit();
}

TEST_F(OutputFolderTest, NewFolderAppearsWithItsMarkerAndNothingBeside) {
  write_run(dir_ / "out", "{}");
  EXPECT_EQ(entries(dir_), std::vector<std::string>{"out"});
  EXPECT_EQ(entries(dir_ / "out"), (std::vector<std::string>{kOutputMarker, "results.json"}));
  const std::string marker = read(dir_ / "out" / kOutputMarker);
  EXPECT_NE(marker.find("\nresults.json\n"), std::string::npos) << marker;
}

TEST_F(OutputFolderTest, EarlierOutputIsReplacedWhole) {
  const fs::path out = dir_ / "out";
  {
    OutputFolder f(out);
    write_text_file(f.file("old.csv"), "old");
    write_text_file(f.file("results.json"), "1");
    f.commit();
  }
  write_run(out, "2");
  EXPECT_EQ(entries(out), (std::vector<std::string>{kOutputMarker, "results.json"}));
  EXPECT_EQ(read(out / "results.json"), "2");
  EXPECT_EQ(entries(dir_), std::vector<std::string>{"out"});
}

TEST_F(OutputFolderTest, EmptyFolderIsAccepted) {
  fs::create_directory(dir_ / "out");
  write_run(dir_ / "out", "{}");
  EXPECT_EQ(read(dir_ / "out" / "results.json"), "{}");
}

TEST_F(OutputFolderTest, ExistingFileIsRefusedAndKept) {
  const fs::path file = dir_ / "thesis.docx";
  write(file, "years of work");
  EXPECT_EQ(refusal(file),
            file.string() +
                ": exists and is not a folder; luxgrid writes only into a new folder, "
                "an empty one, or one it wrote before (choose another -o)");
  EXPECT_EQ(read(file), "years of work");
  EXPECT_EQ(entries(dir_), std::vector<std::string>{"thesis.docx"});
}

TEST_F(OutputFolderTest, ForeignFolderIsRefusedAndKept) {
  const fs::path photos = dir_ / "photos";
  fs::create_directory(photos);
  write(photos / "a.jpg", "jpeg");
  EXPECT_EQ(refusal(photos),
            photos.string() +
                ": is a folder that luxgrid did not write (it has no .luxgrid-output "
                "file) and it is not empty; choose a new or empty folder (-o)");
  EXPECT_EQ(entries(photos), std::vector<std::string>{"a.jpg"});
  EXPECT_EQ(entries(dir_), std::vector<std::string>{"photos"});
}

TEST_F(OutputFolderTest, OutputWithAUserFileAddedIsRefusedAndKept) {
  const fs::path out = dir_ / "out";
  write_run(out, "1");
  write(out / "notes.txt", "mine");
  EXPECT_EQ(refusal(out),
            out.string() +
                ": holds \"notes.txt\", which luxgrid did not write; it is left as it "
                "is (move it away or choose another -o)");
  EXPECT_EQ(read(out / "notes.txt"), "mine");
  EXPECT_EQ(read(out / "results.json"), "1");
}

TEST_F(OutputFolderTest, ForgedMarkerWithoutTheListProtectsNothingItDoesNotList) {
  const fs::path out = dir_ / "out";
  fs::create_directory(out);
  write(out / kOutputMarker, "");
  write(out / "data.csv", "mine");
  EXPECT_NE(refusal(out).find("holds \"data.csv\", which luxgrid did not write"),
            std::string::npos);
  EXPECT_EQ(read(out / "data.csv"), "mine");
}

TEST_F(OutputFolderTest, FolderHoldingAnInputIsRefused) {
  const fs::path out = dir_ / "out";
  write_run(out, "1");
  // The user saved the project inside an earlier output folder (not in the marker's list, and
  // named as an input: the input rule speaks first).
  write(out / "p.json", "{}");
  EXPECT_EQ(refusal(out, {out / "p.json"}),
            out.string() + ": the output folder would replace " + (out / "p.json").string() +
                ", an input of this run; choose another output folder (-o)");
  EXPECT_EQ(read(out / "p.json"), "{}");
  // The project file itself as the output folder.
  write(dir_ / "p.json", "{ }");
  EXPECT_NE(refusal(dir_ / "p.json", {dir_ / "p.json"}).find("an input of this run"),
            std::string::npos);
  EXPECT_EQ(read(dir_ / "p.json"), "{ }");
  // The project's own folder.
  EXPECT_NE(refusal(dir_, {dir_ / "p.json"}).find("an input of this run"), std::string::npos);
}

TEST_F(OutputFolderTest, SymlinkIsFollowedNotReplaced) {
  const fs::path real = dir_ / "real";
  fs::create_directory(real);
  fs::create_directory_symlink(real, dir_ / "link");
  write_run(dir_ / "link", "via link");
  EXPECT_TRUE(fs::is_symlink(dir_ / "link"));
  EXPECT_EQ(read(real / "results.json"), "via link");
  write_run(dir_ / "link", "again");
  EXPECT_TRUE(fs::is_symlink(dir_ / "link"));
  EXPECT_EQ(read(real / "results.json"), "again");
  // A link to nothing is refused; the link stays.
  fs::create_directory_symlink(dir_ / "missing", dir_ / "dangling");
  EXPECT_EQ(refusal(dir_ / "dangling"),
            (dir_ / "dangling").string() + ": is a symbolic link to nothing; give a folder (-o)");
  EXPECT_TRUE(fs::is_symlink(dir_ / "dangling"));
}

TEST_F(OutputFolderTest, FailedRunLeavesTheEarlierOutputAndNoStaging) {
  const fs::path out = dir_ / "out";
  write_run(out, "good");
  {
    OutputFolder f(out);
    write_text_file(f.file("results.json"), "half");
    // destroyed without commit: the calculation failed
  }
  EXPECT_EQ(read(out / "results.json"), "good");
  EXPECT_EQ(entries(dir_), std::vector<std::string>{"out"});
}

TEST_F(OutputFolderTest, StagingOfDeadProcessesIsRemovedOthersKept) {
  // A pid that certainly ran and is gone: a child that exited and was reaped.
  const pid_t child = fork();
  if (child == 0) _exit(0);
  waitpid(child, nullptr, 0);
  const std::string dead = std::to_string(child);
  auto staging = [&](const std::string& name, bool marker) {
    fs::create_directory(dir_ / name);
    write(dir_ / name / "results.json", "half");
    if (marker) write(dir_ / name / kOutputMarker, "# luxgrid staging folder, being written\n");
  };
  staging(".out.tmp-" + dead + "-0", true);                       // killed mid-run
  staging(".out.tmp-" + dead + "-3.old", true);                   // killed mid-replace
  staging(".out.tmp-" + std::to_string(getppid()) + "-0", true);  // a live process's
  staging(".out.tmp-" + dead + "-0-mine", true);                  // not our pattern
  staging(".out.tmp-" + dead + "-1", false);                      // no marker: not ours
  fs::create_directory(dir_ / (".out.tmp-" + dead + "-2"));       // killed before its marker
  write_run(dir_ / "out", "{}");
  std::vector<std::string> kept{".out.tmp-" + dead + "-0-mine", ".out.tmp-" + dead + "-1",
                                ".out.tmp-" + std::to_string(getppid()) + "-0", "out"};
  std::sort(kept.begin(), kept.end());
  EXPECT_EQ(entries(dir_), kept);
}

TEST_F(OutputFolderTest, ConcurrentRunsDoNotInterleave) {
  // Eight writers of eight files each into one target: the result is one writer's set, whole.
  const fs::path out = dir_ / "out";
  constexpr int kWriters = 8, kFiles = 8;
  std::vector<std::thread> threads;
  std::atomic<int> refused{0};
  for (int w = 0; w < kWriters; ++w) {
    threads.emplace_back([&, w] {
      try {
        OutputFolder f(out);
        for (int k = 0; k < kFiles; ++k)
          write_text_file(f.file("f" + std::to_string(k)), std::to_string(w));
        f.commit();
      } catch (const InputError&) {
        ++refused;
      }
    });
  }
  for (auto& t : threads) t.join();
  EXPECT_EQ(refused.load(), 0);
  const std::string first = read(out / "f0");
  for (int k = 0; k < kFiles; ++k) EXPECT_EQ(read(out / ("f" + std::to_string(k))), first) << k;
  EXPECT_EQ(entries(out).size(), static_cast<size_t>(kFiles + 1));
  EXPECT_EQ(entries(dir_), std::vector<std::string>{"out"});
}

}  // namespace
}  // namespace luxgrid::report
