#pragma once
// SHA-256 [FIPS180-4] of a byte string, as 64 lower-case hex digits: results.json records the
// hash of the project file it was calculated from, so a result can be matched to its input.
// The digest is Nettle's (Debian's nettle-dev; docs/architecture.md, "Dependencies", says why
// Nettle rather than OpenSSL's libcrypto). Whoever calls it links PkgConfig::NETTLE.
#include <cstdint>
#include <string>
#include <string_view>

#include <nettle/sha2.h>

namespace luxgrid {

inline std::string sha256_hex(std::string_view bytes) {
  sha256_ctx ctx;
  sha256_init(&ctx);
  sha256_update(&ctx, bytes.size(), reinterpret_cast<const std::uint8_t*>(bytes.data()));
  std::uint8_t digest[SHA256_DIGEST_SIZE];
  sha256_digest(&ctx, SHA256_DIGEST_SIZE, digest);
  static constexpr char digits[] = "0123456789abcdef";
  std::string out;
  out.reserve(2 * SHA256_DIGEST_SIZE);
  for (std::uint8_t b : digest) {
    out.push_back(digits[b >> 4]);
    out.push_back(digits[b & 0xfu]);
  }
  return out;
}

}  // namespace luxgrid
