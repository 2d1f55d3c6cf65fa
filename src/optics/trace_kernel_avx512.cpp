// The batch trace of batch_kernel.h compiled for AVX-512F (8 rays a register); CMakeLists.txt
// gives this file -mavx512f, and the library's -ffp-contract=off keeps AVX-512's multiply-adds
// unfused (a fused one would round differently from the single-ray trace). sequential_trace.cpp
// calls it only on a CPU that has AVX-512F. Nothing else may be compiled here: every function
// this file instantiates has internal linkage (batch_kernel.h and the kernels it includes) or an
// AVX-512 type in its signature, so none can replace a baseline twin.
#include "optics/batch_kernel.h"

namespace eyetrace::optics::kernel {

#if defined(__AVX512F__)
bool avx512_compiled() { return true; }
void trace_block_avx512(const BlockJob& job, Block& block) {
  trace_block<xsimd::batch<double, xsimd::avx512f>>(job, block);
}
#else
bool avx512_compiled() { return false; }
void trace_block_avx512(const BlockJob& job, Block& block) { trace_block_baseline(job, block); }
#endif

}  // namespace eyetrace::optics::kernel
