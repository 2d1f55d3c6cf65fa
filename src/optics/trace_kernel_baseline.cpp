// The batch trace of batch_kernel.h compiled for the baseline instruction set (SSE2 on x86-64,
// 2 rays a register), the one every CPU runs when it has neither AVX2 nor AVX-512F. A file of
// its own, as its AVX2 and AVX-512F twins are, so that a build can give the three kernel
// instantiations options of their own (CMakeLists.txt: the sanitizer build's stack redzones).
#include "optics/batch_kernel.h"

namespace eyetrace::optics::kernel {

void trace_block_baseline(const BlockJob& job, Block& block) { trace_block<xsimd::batch<double>>(job, block); }

}  // namespace eyetrace::optics::kernel
