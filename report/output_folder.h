#pragma once
// An output folder that appears whole or not at all, and never destroys what luxgrid did not
// write (docs/reliability.md, "Output folders").
//
// Files are written into a hidden staging folder beside the target (`.NAME.tmp-PID-SEQ`), and
// commit() swaps it into place. The target may be
//   - absent: it is created;
//   - an empty folder;
//   - a folder luxgrid wrote before: it holds the marker file `.luxgrid-output`, which lists every
//     top-level entry that run wrote, and nothing else lies in it.
// Anything else (a file, a folder of other files, a folder holding the project or one of its
// inputs, a dangling symbolic link) is refused with InputError naming the path, before any
// calculation and again, under a lock, at commit. A symbolic link to a folder is followed: the
// folder it points to is written, the link stays. If the run fails before commit(), the
// destructor removes the staging folder; staging folders left by processes that died (kill -9)
// are removed by the next run into the same target. Two runs into the same target do not
// interleave: commit() holds an exclusive lock on the parent folder while it checks and swaps.
#include <filesystem>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace luxgrid::report {

// The marker file that says "luxgrid wrote this folder" and lists what it wrote.
inline constexpr const char* kOutputMarker = ".luxgrid-output";

class OutputFolder {
 public:
  // `inputs`: files the run reads (the project, photometry, TILT files). None may lie inside
  // what gets replaced. Throws InputError when the target may not be written.
  explicit OutputFolder(std::filesystem::path target,
                        std::vector<std::filesystem::path> inputs = {});
  ~OutputFolder();
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;

  // Where to write files now (the staging folder).
  const std::filesystem::path& staging() const { return staging_; }
  std::filesystem::path file(const std::string& name) const { return staging_ / name; }
  // Files this run does not produce because its flags said so (report.html under --no-report):
  // commit() copies each one the previous output in the target holds into the new folder, so a
  // rerun never drops an output nobody asked it to drop. Only regular files the previous run's
  // marker lists are copied (never a link, never a file luxgrid did not write), under the lock.
  void keep_from_previous(std::vector<std::string> names) { keep_ = std::move(names); }
  // The files commit() carried over from the previous output (after commit).
  const std::vector<std::string>& kept() const { return kept_; }
  // Writes the marker and swaps the staged folder into place, replacing an older luxgrid output.
  // Throws InputError if the target changed into something that may not be replaced meanwhile,
  // CalculationError if the file system refuses.
  void commit();
  // The folder that is written (a symbolic link given as target resolved).
  const std::filesystem::path& target() const { return target_; }

 private:
  std::filesystem::path target_;
  std::filesystem::path staging_;
  std::vector<std::filesystem::path> inputs_;
  std::vector<std::string> keep_, kept_;
  bool committed_ = false;
};

// Writes `text` to `path` atomically (temporary file + rename).
void write_text_file(const std::filesystem::path& path, const std::string& text);

// The same for a file written piece by piece: `write` fills the stream.
void write_file_streamed(const std::filesystem::path& path,
                         const std::function<void(std::ostream&)>& write);

}  // namespace luxgrid::report
