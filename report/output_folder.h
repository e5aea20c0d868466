#pragma once
// An output folder that appears whole or not at all: files are written into a hidden sibling
// folder, and commit() swaps it into place. If the run fails before commit(), the destructor
// removes the temporary folder and any earlier output stays as it was.
#include <filesystem>
#include <string>

namespace luxgrid::report {

class OutputFolder {
 public:
  explicit OutputFolder(std::filesystem::path target);
  ~OutputFolder();
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;

  // Where to write files now (the temporary folder).
  const std::filesystem::path& staging() const { return staging_; }
  std::filesystem::path file(const std::string& name) const { return staging_ / name; }
  // Moves the staged folder to the target, replacing an older one. Throws CalculationError.
  void commit();
  const std::filesystem::path& target() const { return target_; }

 private:
  std::filesystem::path target_;
  std::filesystem::path staging_;
  bool committed_ = false;
};

// Writes `text` to `path` atomically (temporary file + rename).
void write_text_file(const std::filesystem::path& path, const std::string& text);

}  // namespace luxgrid::report
