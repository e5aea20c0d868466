#pragma once
// What every photometry fuzzer asserts: bytes either read or throw InputError, and a file that
// reads gives finite, non-negative intensities (also tilted to its largest TILT factor), a finite
// flux, downward flux and LOR. The limits of photometry/limits.h are what make this hold;
// anything else (crash, another exception, NaN, infinity) is a bug and aborts.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "photometry/derived_photometry.h"
#include "photometry/photometry.h"
#include "photometry/tilt.h"
#include "util/error.h"

namespace luxgrid::fuzz {

inline void require(bool ok) {
  if (!ok) std::abort();
}

inline int read_and_check(const std::uint8_t* data, std::size_t size, const char* name) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  // No TILT=<file> may be read during fuzzing (results must not depend on the disk): every
  // path lies outside this root.
  photometry::LoadOptions options;
  options.allowed_root = "/nonexistent/luxgrid-fuzz-root";
  try {
    const auto p = photometry::load_photometry_text(bytes, name, options);
    const double tilt =
        p.tilt ? *std::max_element(p.tilt->factor.begin(), p.tilt->factor.end()) : 1.0;
    for (double z : {-1.0, -0.5, 0.0, 0.5, 1.0}) {
      const double v = p.distribution->intensity(glm::normalize(Vec3(0.3, 0.4, z)));
      require(std::isfinite(v) && v >= 0 && std::isfinite(v * tilt));
    }
    const auto d = photometry::derive(p);
    require(std::isfinite(d.flux_lm) && d.flux_lm >= 0);
    require(std::isfinite(d.downward_flux_lm) && std::isfinite(d.max_cd));
    require(!d.lor || std::isfinite(*d.lor));
  } catch (const InputError&) {
  }
  return 0;
}

}  // namespace luxgrid::fuzz
