#pragma once
// A photometric data set as luxgrid uses it: the full-sphere intensity distribution in absolute
// candela, the luminous opening in luminaire coordinates, and what the file said about itself.
//
// Readers (ies_reader.cpp, eulumdat_reader.cpp) fill this; they do not compute. Derived numbers
// (integrated flux, LOR, DFF, beam angles) live in derived_photometry.h.
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "photometry/intensity_distribution.h"

namespace luxgrid::photometry {

class TabularDistribution;  // tabular_distribution.h
struct TiltTable;           // tilt.h

// The luminous opening in the luminaire frame: it lies in the local z = 0 plane, centred on the
// origin, emitting towards -z. `length` runs along +x (C0), `width` along +y (C90), in metres.
struct LuminousOpening {
  enum class Shape { point, rectangle, disk };
  Shape shape = Shape::point;
  double length = 0.0;  // m, along x (C0-C180); the diameter along x for a disk
  double width = 0.0;   // m, along y (C90-C270)
  double height = 0.0;  // m, luminous sides (a box or cylinder); 0 for a flat opening
  // What the file described, in words ("circle", "vertical cylinder", "sphere", ...). A disk
  // whose length and width differ is an ellipse; a sphere is a disk with height = diameter.
  std::string description = "point";
};

// One EULUMDAT lamp set (IES files give one set: lamps x lumens per lamp).
struct LampSet {
  int count = 0;  // number of lamps; negative in EULUMDAT means absolute photometry
  std::string type;
  double flux_lm = 0.0;  // total flux of the set
  std::string colour;    // colour temperature / appearance as written
  std::string cri;       // colour rendering group / index as written
  double power_w = 0.0;
};

enum class PhotometricType { C, B, A };
enum class Symmetry { none, rotational, bilateral_c0_c180, bilateral_c90_c270, quadrant };
const char* to_string(PhotometricType t);
const char* to_string(Symmetry s);

struct Photometry {
  std::string source;  // file path as given, or "builtin:<name>"
  std::string format;  // e.g. "IES LM-63-2002", "EULUMDAT", "builtin"
  DistributionPtr distribution;
  LuminousOpening opening;
  std::map<std::string, std::string> keywords;  // manufacturer keywords ([MANUFAC], ...)

  // --- added by the complete readers (empty/defaults for builtins) ---
  std::string version;  // "LM-63-1986", "LM-63-1991", ..., "LM-63-2019", "EULUMDAT"
  PhotometricType photometric_type = PhotometricType::C;
  Symmetry symmetry = Symmetry::none;  // the symmetry the file stores (before expansion)
  // The same object as `distribution` when it came from a file, typed: gives angle-based lookup,
  // interpolation choice and the grid for integration.
  std::shared_ptr<const TabularDistribution> table;
  std::vector<LampSet> lamp_sets;
  // Stated lamp flux (all lamps of the first set, lm) for relative photometry; nullopt for
  // absolute photometry (IES lumens = -1 or 0, EULUMDAT lamp count < 0).
  std::optional<double> lamp_flux_lm;
  double candela_multiplier = 1.0;        // every factor applied to the stored numbers, combined
  std::optional<double> stated_lor;       // EULUMDAT line 23, as a fraction (0..1+)
  std::optional<double> stated_dff;       // EULUMDAT line 22, as a fraction
  std::shared_ptr<const TiltTable> tilt;  // IES TILT=INCLUDE / TILT=<file>; null for NONE
  int counts_vertical = 0;                // IES: vertical angles; EULUMDAT: Ng
  int counts_horizontal = 0;              // IES: horizontal angles; EULUMDAT: stored C planes
  // How the file states its flux, in words: "relative: 2 lamps x 1000 lm ..." or "absolute:
  // IES lumens per lamp = -1" (file_warnings.h; `luxgrid info` prints it).
  std::string flux_convention;
  std::vector<std::string> warnings;  // legal but suspicious input, each naming the file
};

struct LoadOptions {
  // Files a photometric file names (IES TILT=<file>) must lie in this folder or below it, after
  // resolving "..", "." and symbolic links (std::filesystem::weakly_canonical); empty = anywhere.
  // The project loader passes the project's folder; `luxgrid info FILE` the file's own folder.
  std::filesystem::path allowed_root;
  // How messages and warnings name the file: as the user wrote it (the project loader passes
  // the path as the project gives it, relative to the project's folder); empty: the path given
  // to load_photometry_file. The file is still found by that path.
  std::string name;
};

// Reads an IES LM-63 (.ies) or EULUMDAT (.ldt) file, chosen by content/extension.
// Throws InputError naming the file and line on anything it cannot read.
Photometry load_photometry_file(const std::filesystem::path& file, const LoadOptions& options = {});

// The same from bytes already in memory (`name` is used in messages, to pick the reader by
// extension when the content does not say, and its folder to find a TILT file). Used by the
// fuzzers and tests.
Photometry load_photometry_text(std::string_view bytes, const std::string& name,
                                const LoadOptions& options = {});

}  // namespace luxgrid::photometry
