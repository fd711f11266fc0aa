// libFuzzer target: `gearbench run`'s dispatch on arbitrary bytes (see fuzz_entry.h).
#include "fuzz_entry.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  gearbench::fuzz::run_case_bytes(data, size);
  return 0;
}
