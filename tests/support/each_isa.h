// The instruction sets the batch trace can run on here (the baseline always, AVX2 and AVX-512
// where the CPU has them); the start-up choice is restored on leaving. For tests that compare the batch trace
// with the one-ray trace on every instruction set.
#pragma once
#include <vector>

#include "optics/sequential_trace.h"

namespace eyetrace::test {

struct EachIsa {
  optics::TraceBatchIsa start = optics::trace_batch_isa();
  std::vector<optics::TraceBatchIsa> isas;
  EachIsa() {
    for (optics::TraceBatchIsa isa :
         {optics::TraceBatchIsa::Baseline, optics::TraceBatchIsa::Avx2, optics::TraceBatchIsa::Avx512})
      if (optics::set_trace_batch_isa(isa)) isas.push_back(isa);
    optics::set_trace_batch_isa(start);
  }
  ~EachIsa() { optics::set_trace_batch_isa(start); }
};

}  // namespace eyetrace::test
