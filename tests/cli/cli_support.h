#pragma once
// Shared by the CLI tests: running the real binary, and a scratch folder of each test's own (its
// suite, name and the process id), so tests run in parallel and in any order without meeting.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace luxgrid::test {

struct CommandResult {
  int code;            // exit code, -1 if the process did not exit normally (a signal)
  std::string output;  // stdout + stderr
};

inline CommandResult shell(const std::string& cmd) {
  CommandResult r{-1, ""};
  FILE* pipe = popen((cmd + " 2>&1").c_str(), "r");
  if (!pipe) return r;
  std::array<char, 4096> buf{};
  while (size_t n = fread(buf.data(), 1, buf.size(), pipe)) r.output.append(buf.data(), n);
  const int status = pclose(pipe);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

inline CommandResult luxgrid(const std::string& args) {
  return shell(std::string(LUXGRID_BINARY) + " " + args);
}

// The binary with SOURCE_DATE_EPOCH set (the reproducible-builds convention; the report's date
// is then 2025-12-01 00:00 UTC), so that two runs can be compared byte for byte.
inline CommandResult luxgrid_at_fixed_date(const std::string& args) {
  return shell("SOURCE_DATE_EPOCH=1764547200 " + std::string(LUXGRID_BINARY) + " " + args);
}

// Folders handed out by scratch(), removed when the test program ends.
inline std::vector<std::filesystem::path>& scratch_folders() {
  static std::vector<std::filesystem::path> folders;
  static const bool registered = [] {
    std::atexit([] {
      std::error_code ec;
      for (const auto& f : scratch_folders()) std::filesystem::remove_all(f, ec);
    });
    return true;
  }();
  (void)registered;
  return folders;
}

// A new, empty folder `name` for the running test only.
inline std::filesystem::path scratch(const std::string& name) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string test = info ? std::string(info->test_suite_name()) + "." + info->name() : "none";
  for (char& c : test)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.') c = '_';
  const std::filesystem::path root = std::filesystem::path(::testing::TempDir()) /
                                     ("luxgrid_" + test + "_" + std::to_string(getpid()));
  static std::mutex mutex;
  {
    const std::lock_guard<std::mutex> lock(mutex);
    auto& folders = scratch_folders();
    if (std::find(folders.begin(), folders.end(), root) == folders.end()) folders.push_back(root);
  }
  const std::filesystem::path dir = root / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline void write_file(const std::filesystem::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
}

inline std::string read_file(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline std::string quote(const std::filesystem::path& p) { return "'" + p.string() + "'"; }

// Both files exist and hold the same bytes.
inline bool same_bytes(const std::filesystem::path& a, const std::filesystem::path& b) {
  return std::filesystem::exists(a) && std::filesystem::exists(b) && read_file(a) == read_file(b);
}

// The names in a folder (not recursing), sorted.
inline std::set<std::string> entries(const std::filesystem::path& folder) {
  std::set<std::string> out;
  for (const auto& e : std::filesystem::directory_iterator(folder))
    out.insert(e.path().filename().string());
  return out;
}

}  // namespace luxgrid::test
