#pragma once
// What the fuzzers do with one input, shared by the libFuzzer targets (clang, the `fuzz`
// preset) and the replay test that runs the corpus and every past crash in the unit tier.
// Bad input must end in InputError (exit 2) or ConvergenceError (exit 3); any other
// exception, a crash, a sanitizer report or a NaN in a result is a bug.
#include <cstddef>
#include <cstdint>

namespace gearbench::fuzz {

/// Bytes → JSON → the gear-pair case sections (gear_pair, materials, operating, lubricant).
void read_case_bytes(const std::uint8_t* data, std::size_t size);
/// Bytes → JSON → `gearbench run`'s dispatch (every kind), result checked for NaN/Inf.
void run_case_bytes(const std::uint8_t* data, std::size_t size);

}  // namespace gearbench::fuzz
