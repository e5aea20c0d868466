// libFuzzer target: any bytes given to the EULUMDAT reader either read or throw InputError; a read
// distribution answers finite, non-negative intensities. Anything else (crash, other exception,
// NaN) is a bug.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "photometry/derived_photometry.h"
#include "photometry/photometry.h"
#include "util/error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  try {
    const auto p = luxgrid::photometry::load_photometry_text(bytes, FUZZ_FILE_NAME);
    for (double z : {-1.0, -0.5, 0.0, 0.5, 1.0}) {
      const double v = p.distribution->intensity(glm::normalize(luxgrid::Vec3(0.3, 0.4, z)));
      if (!std::isfinite(v) || v < 0) std::abort();
    }
    const auto d = luxgrid::photometry::derive(p);
    if (!std::isfinite(d.flux_lm) || d.flux_lm < 0) std::abort();
  } catch (const luxgrid::InputError&) {
  }
  return 0;
}
