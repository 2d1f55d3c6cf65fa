// FFTW3 behind one lock for planning (see fft.h).
#include "optics/fft.h"

#include <fftw3.h>

#include <algorithm>
#include <mutex>

#include <fmt/format.h>

#include "optics/optics_error.h"

namespace eyetrace::optics {

namespace {

std::mutex& planner_mutex() {
  static std::mutex m;
  return m;
}

}  // namespace

FftBuffer::FftBuffer(size_t count) {
  // std::complex<double> has fftw_complex's layout (both are two doubles, real then imaginary).
  data = reinterpret_cast<std::complex<double>*>(fftw_alloc_complex(count));
  if (data == nullptr) throw OpticsError(fmt::format("fft: cannot allocate {} complex samples", count));
  std::fill_n(data, count, std::complex<double>(0.0));
}

FftBuffer::~FftBuffer() { fftw_free(data); }

namespace {

void run(fftw_plan plan, int n) {
  if (plan == nullptr) throw OpticsError(fmt::format("fft: FFTW could not plan a {} x {} transform", n, n));
  fftw_execute(plan);
  std::lock_guard<std::mutex> lock(planner_mutex());
  fftw_destroy_plan(plan);
}

}  // namespace

void fft2_in_place(std::complex<double>* data, int n, int nonzero_rows) {
  auto* d = reinterpret_cast<fftw_complex*>(data);
  if (nonzero_rows <= 0 || nonzero_rows >= n) {
    fftw_plan plan = nullptr;
    {
      std::lock_guard<std::mutex> lock(planner_mutex());
      plan = fftw_plan_dft_2d(n, n, d, d, FFTW_FORWARD, FFTW_ESTIMATE);
    }
    run(plan, n);
    return;
  }
  fftw_plan columns = nullptr, rows = nullptr;
  {
    std::lock_guard<std::mutex> lock(planner_mutex());
    // The block is square (the pupil fills the first nonzero_rows rows and columns): first the
    // columns that hold it (stride n), then every row (contiguous).
    columns = fftw_plan_many_dft(1, &n, nonzero_rows, d, nullptr, n, 1, d, nullptr, n, 1, FFTW_FORWARD, FFTW_ESTIMATE);
    rows = fftw_plan_many_dft(1, &n, n, d, nullptr, 1, n, d, nullptr, 1, n, FFTW_FORWARD, FFTW_ESTIMATE);
  }
  run(columns, n);
  run(rows, n);
}

}  // namespace eyetrace::optics
