#include "report/output_folder.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>
#include <algorithm>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <set>

#include "util/error.h"
#include "util/paths.h"

namespace luxgrid::report {

namespace fs = std::filesystem;

namespace {

constexpr const char* kMarkerHeader =
    "# luxgrid output folder: luxgrid replaces this folder only while it holds nothing but the "
    "entries below.";
constexpr const char* kStagingHeader = "# luxgrid staging folder, being written";

// The folder's parent and name, for a target given as "out", "out/", "./out" or "/abs/out".
fs::path normalised(const fs::path& target) {
  fs::path p = fs::absolute(target).lexically_normal();
  if (p.filename().empty()) p = p.parent_path();  // a trailing separator
  return p;
}

std::set<std::string> marker_entries(const fs::path& marker) {
  std::set<std::string> out;
  std::ifstream in(marker);
  std::string line;
  std::getline(in, line);
  if (line != kMarkerHeader) return out;  // a staging marker or something else: lists nothing
  while (std::getline(in, line)) {
    if (!line.empty()) out.insert(line);
  }
  return out;
}

void write_marker(const fs::path& folder, const std::string& header) {
  std::vector<std::string> names;
  if (header == kMarkerHeader) {
    for (const auto& e : fs::directory_iterator(folder)) {
      const std::string n = e.path().filename().string();
      if (n != kOutputMarker) names.push_back(n);
    }
    std::sort(names.begin(), names.end());
  }
  std::ofstream out(folder / kOutputMarker, std::ios::binary | std::ios::trunc);
  out << header << "\n";
  for (const auto& n : names) out << n << "\n";
  if (!out) throw CalculationError((folder / kOutputMarker).string() + ": cannot write the file");
}

// Throws InputError unless `target` may be replaced by a new output folder.
void check_replaceable(const fs::path& target, const std::vector<fs::path>& inputs) {
  std::error_code ec;
  for (const auto& input : inputs) {
    if (lies_within(input, target)) {
      throw InputError(SourceLocation{target.string()},
                       "the output folder would replace " + input.string() +
                           ", an input of this run; choose another output folder (-o)");
    }
  }
  const auto status = fs::symlink_status(target, ec);
  if (!fs::exists(status)) return;
  if (!fs::is_directory(status)) {
    throw InputError(target.string() +
                     ": exists and is not a folder; luxgrid writes only into a new folder, an "
                     "empty one, or one it wrote before (choose another -o)");
  }
  const fs::path marker = target / kOutputMarker;
  const bool has_marker = fs::is_regular_file(fs::symlink_status(marker, ec));
  const std::set<std::string> listed =
      has_marker ? marker_entries(marker) : std::set<std::string>{};
  for (const auto& e : fs::directory_iterator(target, ec)) {
    const std::string name = e.path().filename().string();
    if (name == kOutputMarker) continue;
    if (!has_marker) {
      throw InputError(SourceLocation{target.string()},
                       std::string("is a folder that luxgrid did not write (it has no ") +
                           kOutputMarker +
                           " file) and it is not empty; choose a new or empty folder (-o)");
    }
    if (!listed.count(name)) {
      throw InputError(SourceLocation{target.string()},
                       "holds \"" + name +
                           "\", which luxgrid did not write; it is left as it is (move it away or "
                           "choose another -o)");
    }
  }
  if (ec)
    throw InputError(SourceLocation{target.string()}, "cannot read the folder: " + ec.message());
}

// Staging folders `.NAME.tmp-PID-SEQ` (and `.old` ones) of processes that no longer run: a run
// killed before it could clean up. Only folders with luxgrid's marker inside, or empty ones, are
// removed.
void remove_stale_staging(const fs::path& parent, const std::string& name) {
  const std::string prefix = "." + name + ".tmp-";
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(parent, ec)) {
    const std::string n = e.path().filename().string();
    if (n.rfind(prefix, 0) != 0) continue;
    // PID-SEQ, then ".old" for a folder moved aside during a replace.
    std::string rest = n.substr(prefix.size());
    if (rest.size() > 4 && rest.compare(rest.size() - 4, 4, ".old") == 0)
      rest.resize(rest.size() - 4);
    const size_t dash = rest.find('-');
    const std::string pid_text = rest.substr(0, dash),
                      seq = dash == std::string::npos ? "" : rest.substr(dash + 1);
    auto all_digits = [](const std::string& t) {
      return !t.empty() && t.size() <= 9 &&
             std::all_of(t.begin(), t.end(), [](unsigned char c) { return std::isdigit(c); });
    };
    if (!all_digits(pid_text) || !all_digits(seq)) continue;
    const pid_t pid = static_cast<pid_t>(std::stol(pid_text));
    if (pid == getpid()) continue;
    if (kill(pid, 0) == 0 || errno != ESRCH) continue;  // alive (or not ours to judge)
    std::error_code sub;
    if (!fs::is_directory(fs::symlink_status(e.path(), sub))) continue;
    // Ours if it holds the marker, or is still empty (killed between creating it and writing
    // the marker): removing an empty folder destroys nothing.
    const bool marked = fs::is_regular_file(fs::symlink_status(e.path() / kOutputMarker, sub));
    if (!marked && !fs::is_empty(e.path(), sub)) continue;
    fs::remove_all(e.path(), sub);
  }
}

// An exclusive advisory lock on a folder, held while it lives.
class FolderLock {
 public:
  explicit FolderLock(const fs::path& folder) {
    fd_ = open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd_ >= 0 && flock(fd_, LOCK_EX) != 0) {
      close(fd_);
      fd_ = -1;
    }
    if (fd_ < 0) {
      throw CalculationError(folder.string() + ": cannot lock the folder: " + std::strerror(errno));
    }
  }
  ~FolderLock() { close(fd_); }
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;

 private:
  int fd_ = -1;
};

// Exchanges two paths atomically (Linux renameat2 RENAME_EXCHANGE); false where the file system
// does not support it.
bool exchange(const fs::path& a, const fs::path& b) {
#ifdef RENAME_EXCHANGE
  return renameat2(AT_FDCWD, a.c_str(), AT_FDCWD, b.c_str(), RENAME_EXCHANGE) == 0;
#else
  (void)a;
  (void)b;
  return false;
#endif
}

}  // namespace

OutputFolder::OutputFolder(fs::path target, std::vector<fs::path> inputs)
    : target_(normalised(target)), inputs_(std::move(inputs)) {
  std::error_code ec;
  const auto link = fs::symlink_status(target_, ec);
  if (fs::is_symlink(link)) {
    // Followed, never replaced: the folder it points to is the target.
    if (!fs::exists(fs::status(target_, ec))) {
      throw InputError(SourceLocation{target_.string()},
                       "is a symbolic link to nothing; give a folder (-o)");
    }
    target_ = fs::canonical(target_, ec);
    if (ec)
      throw InputError(SourceLocation{target_.string()},
                       "cannot resolve the symbolic link: " + ec.message());
  }
  if (target_.filename().empty() || target_ == target_.root_path()) {
    throw InputError(SourceLocation{target_.string()},
                     "cannot be an output folder (choose a new folder, -o)");
  }
  check_replaceable(target_, inputs_);
  const fs::path parent = target_.parent_path();
  fs::create_directories(parent, ec);
  if (ec)
    throw InputError(SourceLocation{parent.string()}, "cannot create the folder: " + ec.message());
  remove_stale_staging(parent, target_.filename().string());
  // PID-SEQ: unique per process and per folder object, so two in one process do not collide.
  static std::atomic<unsigned> sequence{0};
  staging_ = parent / ("." + target_.filename().string() + ".tmp-" + std::to_string(getpid()) +
                       "-" + std::to_string(sequence++));
  fs::remove_all(staging_, ec);
  if (!fs::create_directory(staging_, ec)) {
    throw CalculationError(staging_.string() +
                           ": cannot create the output folder: " + ec.message());
  }
  write_marker(staging_, kStagingHeader);
}

OutputFolder::~OutputFolder() {
  if (!committed_) {
    std::error_code ec;
    fs::remove_all(staging_, ec);
  }
}

void OutputFolder::commit() {
  std::error_code ec;
  {
    const FolderLock lock(target_.parent_path());
    // The target may have changed during the calculation (another run, the user): check again.
    check_replaceable(target_, inputs_);
    // What the previous run wrote and this one was told not to: carried over, before the marker
    // is written, so the new marker lists them as luxgrid's.
    const std::set<std::string> listed = marker_entries(target_ / kOutputMarker);
    for (const auto& name : keep_) {
      const fs::path from = target_ / name, to = staging_ / name;
      if (name.find('/') != std::string::npos || !listed.count(name) ||
          fs::exists(fs::symlink_status(to, ec)))
        continue;
      if (!fs::is_regular_file(fs::symlink_status(from, ec))) continue;
      fs::copy_file(from, to, ec);
      if (ec)
        throw CalculationError(from.string() +
                               ": cannot keep the file of the previous run: " + ec.message());
      kept_.push_back(name);
    }
    write_marker(staging_, kMarkerHeader);
    if (fs::exists(fs::symlink_status(target_, ec))) {
      if (exchange(staging_, target_)) {
        committed_ = true;
      } else {
        // No atomic exchange here: move the old folder aside, the new one in, then drop the old.
        const fs::path old = staging_.string() + ".old";
        fs::rename(target_, old, ec);
        if (ec)
          throw CalculationError(target_.string() +
                                 ": cannot replace the output folder: " + ec.message());
        fs::rename(staging_, target_, ec);
        if (ec)
          throw CalculationError(target_.string() +
                                 ": cannot create the output folder: " + ec.message());
        committed_ = true;
        fs::remove_all(old, ec);
        return;
      }
    } else {
      fs::rename(staging_, target_, ec);
      if (ec)
        throw CalculationError(target_.string() +
                               ": cannot create the output folder: " + ec.message());
      committed_ = true;
      return;
    }
  }
  // After an exchange the staging path holds the previous output.
  fs::remove_all(staging_, ec);
}

void write_text_file(const fs::path& path, const std::string& text) {
  write_file_streamed(path, [&](std::ostream& out) { out << text; });
}

void write_file_streamed(const fs::path& path, const std::function<void(std::ostream&)>& write) {
  const fs::path tmp = path.string() + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary);
    write(out);
    out.flush();
    if (!out) throw CalculationError(path.string() + ": cannot write the file");
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) throw CalculationError(path.string() + ": cannot write the file: " + ec.message());
}

}  // namespace luxgrid::report
