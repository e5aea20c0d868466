#include "report/output_folder.h"

#include <fstream>
#include <unistd.h>

#include "util/error.h"

namespace luxgrid::report {

namespace fs = std::filesystem;

OutputFolder::OutputFolder(fs::path target) : target_(std::move(target)) {
  if (target_.filename().empty()) target_ = target_.parent_path();
  const fs::path parent = target_.parent_path().empty() ? fs::path(".") : target_.parent_path();
  std::error_code ec;
  fs::create_directories(parent, ec);
  staging_ = parent / ("." + target_.filename().string() + ".tmp-" + std::to_string(getpid()));
  fs::remove_all(staging_, ec);
  if (!fs::create_directory(staging_, ec)) {
    throw CalculationError(staging_.string() + ": cannot create the output folder: " + ec.message());
  }
}

OutputFolder::~OutputFolder() {
  if (!committed_) {
    std::error_code ec;
    fs::remove_all(staging_, ec);
  }
}

void OutputFolder::commit() {
  std::error_code ec;
  const fs::path old = staging_.string() + ".old";
  if (fs::exists(target_, ec)) {
    fs::rename(target_, old, ec);
    if (ec) throw CalculationError(target_.string() + ": cannot replace the output folder: " + ec.message());
  }
  fs::rename(staging_, target_, ec);
  if (ec) throw CalculationError(target_.string() + ": cannot create the output folder: " + ec.message());
  committed_ = true;
  fs::remove_all(old, ec);
}

void write_text_file(const fs::path& path, const std::string& text) {
  const fs::path tmp = path.string() + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary);
    out << text;
    if (!out) throw CalculationError(path.string() + ": cannot write the file");
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) throw CalculationError(path.string() + ": cannot write the file: " + ec.message());
}

}  // namespace luxgrid::report
