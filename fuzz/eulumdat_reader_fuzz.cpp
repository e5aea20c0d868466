// libFuzzer target: any bytes given to the EULUMDAT reader (chosen by FUZZ_FILE_NAME's extension
// when the content does not decide) either read or throw InputError, with the invariants of
// fuzz_invariants.h on whatever reads.
#include <cstdint>

#include "fuzz/fuzz_invariants.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return luxgrid::fuzz::read_and_check(data, size, FUZZ_FILE_NAME);
}
