// The FFTs of the wave-optics analysis (psf.h, encircled_energy.h), through FFTW3.
#pragma once

#include <complex>

namespace eyetrace::optics {

// In-place forward 2-D DFT (sign -1, unnormalised) of an n x n row-major array. FFTW's planner is
// not thread-safe (execution is): plans are made and destroyed under one lock, with FFTW_ESTIMATE
// (no timing runs, so planning is cheap and the result does not depend on the machine's load).
// `data` should come from fft_buffer (FFTW's alignment).
// nonzero_rows < n: only the first nonzero_rows rows and columns hold non-zero values (a
// zero-padded pupil), so only those columns are transformed (the others stay zero) before the n
// rows.
void fft2_in_place(std::complex<double>* data, int n, int nonzero_rows = 0);

struct FftBuffer {
  explicit FftBuffer(size_t count);
  ~FftBuffer();
  FftBuffer(const FftBuffer&) = delete;
  FftBuffer& operator=(const FftBuffer&) = delete;
  std::complex<double>* data = nullptr;
};

}  // namespace eyetrace::optics
