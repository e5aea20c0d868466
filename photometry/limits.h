#pragma once
// Every limit the photometry readers enforce, in one place, with its unit and its reason.
// A file beyond a limit is refused with an InputError naming the file and line (exit 2): these
// values bound memory for hostile input and keep every number luxgrid computes finite, so a
// distribution that was read always answers finite intensities and a finite flux.
#include <cstddef>

#include "util/limits.h"
#include "util/robust_math.h"

namespace luxgrid::photometry {

// Files larger than this are not photometry; refusing them (before reading) bounds memory. The
// largest real file seen (a 360 x 181 EULUMDAT) is 0.5 MB.
inline constexpr std::size_t kMaxPhotometryFileBytes = 32u << 20;

// Two angles in degrees closer than this are the same angle: files print at most 4 decimals.
inline constexpr double kSameAngleDeg = 1e-6;

// Header counts, checked before any table is allocated; real files stay far below (the largest
// in the corpus has 94,943 values).
inline constexpr long kMaxAngles = 100000;
inline constexpr long kMaxValues = 10000000;

// A TILT table has at most kMaxTiltPairs angle/factor pairs: LM-63 tables tabulate 0..90 or
// 0..180 deg in steps of a few degrees (the corpus's largest has 19 pairs), so 10,000 is
// generous. Written out with 30 bytes a pair that is 300 kB: a TILT file beyond 1 MiB is not a
// TILT file, and is refused from its size before a byte of it is read.
inline constexpr long kMaxTiltPairs = 10000;
inline constexpr std::size_t kMaxTiltFileBytes = 1u << 20;

// kMaxIntensity_cd, the brightest intensity accepted after every multiplier: util/limits.h.

// A TILT factor scales the lamp's output with its tilt; real tables stay within 0.5..1.1 (the
// lamp's output at tilt 0 is the reference). A factor above 10 is not a tilt correction.
inline constexpr double kMaxTiltFactor = 10.0;

// The flux of an isotropic source at the intensity limit, 4 pi x 1e9 cd: a stated lamp flux
// beyond it cannot belong to a luminaire within kMaxIntensity_cd (relative photometry scales
// intensities by it), so it is refused too.
inline constexpr double kMaxLampFluxLm = 4.0 * kPi * kMaxIntensity_cd;
// The dimmest lamps photometered (indicator LEDs) give about 0.01 lm. A rated flux below 1 mlm
// is a typo, and it would blow the LOR (integrated flux / lamp flux) up towards infinity.
inline constexpr double kMinLampFluxLm = 1e-3;

// The largest luminous openings in photometric files are luminous ceilings and LED walls of a few
// metres. An opening beyond 100 m is a unit error (a 600 mm panel written as 600 in a metre
// file) and would put the near-field quadrature far outside any room; it is refused.
inline constexpr double kMaxOpeningM = 100.0;

// Messages quote at most one word of a file, only when it is printable ASCII and this short: a
// number field holds at most ~12 characters ("-1.23456e+05"), and a short quote cannot carry a
// line of someone else's file (the first line of /etc/passwd, a key in /proc/self/environ) into
// a log. Longer or unprintable words are described ("a 47-character word"), never quoted.
inline constexpr std::size_t kMaxQuotedWordChars = 16;

// A TILT=<file> name is quoted in full (the user needs it to find the file), so it must be a
// printable ASCII name of at most this many characters; anything else is refused.
inline constexpr std::size_t kMaxTiltNameChars = 64;

}  // namespace luxgrid::photometry
