// nbscope_bench: the benchmark that shows tracing costs nothing when off (bench_trace_off.cpp).
#pragma once

namespace nbscope {

// Registers BM_TraceOff/{nbs,nbs_plain}/<layout>/<N>.
void register_trace_off_benchmarks();
// True when the hook-free control finds exactly nbs's pairs on every test layout (else says so on stderr).
bool trace_off_control_agrees();

}  // namespace nbscope
