// libFuzzer target: the case reader on arbitrary bytes (see fuzz_entry.h).
#include "fuzz_entry.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  gearbench::fuzz::read_case_bytes(data, size);
  return 0;
}
