// How many random samples a statistical or stress test draws. The optimised build draws the
// number the test asks for; the sanitizer build (EYETRACE_SANITIZED_TESTS, CI's second pass) draws
// a tenth. Under ASan at -O1, with the tests at -O0, a sample costs about ten times as much, and
// that pass is there to find memory errors and undefined behaviour on the code paths the samples
// take: a tenth still takes each common path thousands of times (rare ones, such as grazing
// angles, fewer times). The statistical power, and the millions of rays of the stress tests, are
// the optimised build's job. A statistical test that scales its count this way must derive its
// tolerance from the count it drew (a standard error, a chi-square p-value), so that its assertion
// keeps its stated confidence in both builds; a stress test must check each sample on its own.
#pragma once

namespace eyetrace::test {

#ifdef EYETRACE_SANITIZED_TESTS
inline constexpr int kSampleDivisor = 10;
#else
inline constexpr int kSampleDivisor = 1;
#endif

// `n` samples in the optimised build, n / 10 (at least 1) under the sanitizers.
constexpr int sample_count(int n) { return n / kSampleDivisor > 0 ? n / kSampleDivisor : 1; }

// Panels per side with which a chi-square test integrates the claimed density over each cell
// (chi2::expected_per_cell, 5 x 5 Gauss-Legendre points per panel): 12 in the optimised build, 6
// with the sanitizers' tenth of the samples, a quarter of the density evaluations. Where the
// density is smooth both are exact far below the counts' noise; where it is not (a kink; the
// layered BxDFs' pdf, itself a random estimate, whose noise is averaged over a quarter of the
// points) the expected counts' error grows a few times, while the error Pearson's statistic
// tolerates grows with 1 / sqrt(count), about 3 times for a tenth of the samples. Measured on
// BsdfProperties' 30 chi-square tests with 20000 samples and 6 panels: all pass, the smallest
// p-value 0.034 (the smallest of 30 uniform p-values is below that two times in three).
inline constexpr int kChi2Panels = kSampleDivisor == 1 ? 12 : 6;

}  // namespace eyetrace::test
