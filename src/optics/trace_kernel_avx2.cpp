// The batch trace of batch_kernel.h compiled for AVX2 (4 rays a register); CMakeLists.txt gives
// this file -mavx2 (and no -mfma: a fused multiply-add would round differently from the
// single-ray trace). sequential_trace.cpp calls it only on a CPU that has AVX2. Nothing else
// may be compiled here: every function this file instantiates has internal linkage
// (batch_kernel.h and the kernels it includes) or an AVX2 type in its signature, so none can replace a baseline twin.
#include "optics/batch_kernel.h"

namespace eyetrace::optics::kernel {

#if defined(__AVX2__)
bool avx2_compiled() { return true; }
void trace_block_avx2(const BlockJob& job, Block& block) { trace_block<xsimd::batch<double, xsimd::avx2>>(job, block); }
#else
bool avx2_compiled() { return false; }
void trace_block_avx2(const BlockJob& job, Block& block) { trace_block_baseline(job, block); }
#endif

}  // namespace eyetrace::optics::kernel
