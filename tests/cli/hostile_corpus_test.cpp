// The hostile corpus through the real binary (docs/reliability.md): every file under
// tests/data/bad/ (photometric files through `luxgrid info`, projects under projects/ through
// `luxgrid calc`) is refused with exit 2 and exactly the message in <file>.expected, which names
// the file; nothing is written; each run stays within a hard address-space limit, and the peak
// resident memory over the corpus is printed and bounded.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <functional>
#include <set>
#include <string>
#include <vector>

#include "tests/cli/cli_support.h"

namespace {

namespace fs = std::filesystem;
using luxgrid::test::read_file;
using luxgrid::test::scratch;

const fs::path kBad = fs::path(LUXGRID_SOURCE_DIR) / "tests/data/bad";

// Each run may map at most this much (a hard limit: exceeding it is a failed allocation, which
// must still end in a clear message, not a crash); the corpus's peak must stay well below it.
constexpr rlim_t kAddressSpaceLimit = rlim_t{2} << 30;  // 2 GiB: TBB and CGAL map ~0.3 GiB at start
// The largest refused project builds the grids it accepted before the total grid limit refuses
// the next (project/project_limits.h: three of 2.56 million points, ~640 MiB).
constexpr long kPeakResidentLimit_kiB = 1024 * 1024;
// Each run gets this much CPU time; a refusal takes milliseconds.
constexpr rlim_t kCpuLimit_s = 60;

struct Outcome {
  int code = -1;
  std::string output;
  long peak_kib = 0;
};

// Starts the binary with `args` under the limits above; stdout and stderr go to `log`.
pid_t start_limited(const std::vector<std::string>& args, const fs::path& log) {
  const pid_t child = fork();
  if (child == 0) {
    const rlimit as{kAddressSpaceLimit, kAddressSpaceLimit}, cpu{kCpuLimit_s, kCpuLimit_s};
    setrlimit(RLIMIT_AS, &as);
    setrlimit(RLIMIT_CPU, &cpu);
    const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    dup2(fd, 1);
    dup2(fd, 2);
    std::vector<char*> argv{const_cast<char*>(LUXGRID_BINARY)};
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execv(LUXGRID_BINARY, argv.data());
    _exit(127);
  }
  return child;
}

Outcome finish(pid_t child, const fs::path& log) {
  Outcome r;
  int status = 0;
  rusage usage{};
  wait4(child, &status, 0, &usage);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.output = read_file(log);
  r.peak_kib = usage.ru_maxrss;
  return r;
}

Outcome run_limited(const std::vector<std::string>& args, const fs::path& log) {
  return finish(start_limited(args, log), log);
}

// Runs one command per file, a few at a time (each run is mostly start-up), in file order.
std::vector<Outcome> run_all(
    const std::vector<fs::path>& inputs, const fs::path& tmp,
    const std::function<std::vector<std::string>(const fs::path&, const fs::path&)>& args) {
  constexpr size_t kParallel = 4;
  std::vector<Outcome> out(inputs.size());
  for (size_t first = 0; first < inputs.size(); first += kParallel) {
    std::vector<pid_t> children;
    const size_t last = std::min(inputs.size(), first + kParallel);
    for (size_t k = first; k < last; ++k) {
      const fs::path work = tmp / std::to_string(k);
      fs::create_directories(work);
      children.push_back(start_limited(args(inputs[k], work), work / "log"));
    }
    for (size_t k = first; k < last; ++k)
      out[k] = finish(children[k - first], tmp / std::to_string(k) / "log");
  }
  return out;
}

std::string without(std::string s, const std::string& what) {
  for (size_t pos = 0; (pos = s.find(what, pos)) != std::string::npos;) s.erase(pos, what.size());
  return s;
}

std::vector<fs::path> files(const fs::path& dir, const std::set<std::string>& extensions) {
  std::vector<fs::path> out;
  for (const auto& e : fs::directory_iterator(dir)) {
    if (e.is_regular_file() && extensions.count(e.path().extension().string()))
      out.push_back(e.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

struct Peak {
  long kib = 0;
  std::string file;
  void add(const Outcome& r, const fs::path& f) {
    if (r.peak_kib > kib) kib = r.peak_kib, file = f.filename().string();
  }
};

void expect_refused(const Outcome& r, const fs::path& file, const std::string& folder_prefix) {
  const std::string expected = read_file(file.string() + ".expected");
  ASSERT_FALSE(expected.empty()) << "missing " << file << ".expected";
  EXPECT_EQ(r.code, 2) << file.filename() << ": " << r.output;
  EXPECT_EQ(without(r.output, folder_prefix), "luxgrid: error: " + expected) << file.filename();
  EXPECT_NE(r.output.find(file.filename().string()), std::string::npos)
      << file.filename() << ": the message does not name the file: " << r.output;
}

TEST(HostileCorpus, ProjectsAreRefusedInBoundedMemory) {
  const fs::path dir = kBad / "projects";
  const fs::path tmp = scratch("projects");
  const auto before = luxgrid::test::entries(dir);
  Peak peak;
  const auto projects = files(dir, {".json"});
  const auto runs = run_all(projects, tmp, [](const fs::path& p, const fs::path& work) {
    return std::vector<std::string>{"calc", p.string(), "-o", (work / "out").string()};
  });
  for (size_t k = 0; k < projects.size(); ++k) {
    expect_refused(runs[k], projects[k], dir.string() + "/");
    EXPECT_FALSE(fs::exists(tmp / std::to_string(k) / "out"))
        << projects[k].filename() << " wrote an output folder";
    peak.add(runs[k], projects[k]);
  }
  EXPECT_EQ(luxgrid::test::entries(dir), before) << "a refused project wrote beside itself";
  std::printf("hostile projects: %zu refused with exit 2; peak resident memory %.1f MiB (%s)\n",
              projects.size(), peak.kib / 1024.0, peak.file.c_str());
  EXPECT_GE(projects.size(), 60u);
  EXPECT_LT(peak.kib, kPeakResidentLimit_kiB);
}

TEST(HostileCorpus, PhotometricFilesAreRefusedInBoundedMemory) {
  const fs::path tmp = scratch("photometry");
  Peak peak;
  const auto bad = files(kBad, {".ies", ".ldt"});
  const auto runs = run_all(bad, tmp, [](const fs::path& f, const fs::path&) {
    return std::vector<std::string>{"info", f.string()};
  });
  for (size_t k = 0; k < bad.size(); ++k) {
    expect_refused(runs[k], bad[k], kBad.string() + "/");
    peak.add(runs[k], bad[k]);
  }
  std::printf(
      "hostile photometric files: %zu refused with exit 2; peak resident memory %.1f MiB (%s)\n",
      bad.size(), peak.kib / 1024.0, peak.file.c_str());
  EXPECT_LT(peak.kib, kPeakResidentLimit_kiB);
}

// Files too large to keep in the repository, made here as sparse files: refused by their size
// before a byte is read.
TEST(HostileCorpus, HugeFilesAreRefusedBeforeReading) {
  const fs::path dir = scratch("huge");
  // What the process costs before it reads anything: a project that does not exist.
  const long start_kib = run_limited({"calc", (dir / "none.json").string()}, dir / "log").peak_kib;
  // Reading either file would cost at least its size (200 MiB, 1 GiB); refusing costs nothing.
  constexpr long kReadingMargin_kiB = 32 * 1024;
  const fs::path project = dir / "huge.json";
  {
    const int fd = open(project.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ASSERT_EQ(ftruncate(fd, off_t{200} << 20), 0);  // 200 MiB of NUL bytes, none on disk
    close(fd);
  }
  const Outcome r =
      run_limited({"calc", project.string(), "-o", (dir / "out").string()}, dir / "log");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("huge.json"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("limit"), std::string::npos) << r.output;
  EXPECT_LT(r.peak_kib, start_kib + kReadingMargin_kiB) << "read the file before checking its size";

  const fs::path tilt = dir / "big.tilt";
  {
    const int fd = open(tilt.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ASSERT_EQ(ftruncate(fd, off_t{1} << 30), 0);  // 1 GiB
    close(fd);
  }
  luxgrid::test::write_file(dir / "lamp.ies",
                            "IESNA:LM-63-2002\n[TEST] big tilt\nTILT=big.tilt\n"
                            "1 1000 1 3 1 1 2 0.1 0.1 0\n1 1 10\n0 45 90\n0\n100 70 10\n");
  const Outcome t = run_limited({"info", (dir / "lamp.ies").string()}, dir / "log");
  EXPECT_EQ(t.code, 2) << t.output;
  EXPECT_NE(t.output.find("lamp.ies:3"), std::string::npos) << t.output;
  EXPECT_NE(t.output.find("big.tilt"), std::string::npos) << t.output;
  EXPECT_LT(t.peak_kib, start_kib + kReadingMargin_kiB)
      << "read the TILT file before checking its size";
}

}  // namespace
