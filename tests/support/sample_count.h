// How many random samples a statistical test draws. The optimised build draws the number the test
// asks for; the sanitizer build (EYETRACE_SANITIZED_TESTS, CI's second pass) draws a tenth. Under
// ASan at -O1, with the tests at -O0, a sample costs about ten times as much, and that pass is there
// to find memory errors and undefined behaviour, which every sample path taken already exposes;
// the statistical power is the optimised build's job. A test that scales its count this way must
// derive its tolerance from the count it drew (a standard error, a chi-square p-value), so that its
// assertion keeps its stated confidence in both builds.
#pragma once

namespace eyetrace::test {

#ifdef EYETRACE_SANITIZED_TESTS
inline constexpr int kSampleDivisor = 10;
#else
inline constexpr int kSampleDivisor = 1;
#endif

// `n` samples in the optimised build, n / 10 (at least 1) under the sanitizers.
constexpr int sample_count(int n) { return n / kSampleDivisor > 0 ? n / kSampleDivisor : 1; }

}  // namespace eyetrace::test
