// Replays the fuzz corpus and every input that once crashed a fuzzer through the same entry
// points, in the ordinary (GCC, and under ASan/UBSan the asan preset) build: a regression
// of a fixed crash fails here without clang.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include "fuzz_entry.h"

namespace fs = std::filesystem;

namespace {

std::vector<fs::path> inputs(const char* folder) {
  std::vector<fs::path> out;
  for (const auto& e : fs::directory_iterator(fs::path(GEARBENCH_SOURCE_DIR) / "verification/fuzz" / folder))
    if (e.is_regular_file() && e.path().filename() != "README.md") out.push_back(e.path());
  return out;
}

std::vector<std::uint8_t> bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void replay(const char* folder) {
  const auto files = inputs(folder);
  for (const auto& f : files) {
    SCOPED_TRACE(f.string());
    const auto b = bytes(f);
    EXPECT_NO_THROW(gearbench::fuzz::read_case_bytes(b.data(), b.size()));
    EXPECT_NO_THROW(gearbench::fuzz::run_case_bytes(b.data(), b.size()));
  }
}

TEST(FuzzReplay, Corpus) { replay("corpus"); }
TEST(FuzzReplay, PastCrashes) { replay("regressions"); }

}  // namespace
