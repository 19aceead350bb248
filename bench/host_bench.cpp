// host_bench.cpp: what this machine gives a second thread, independently of
// shadertwin's code, so that a thread-scaling figure can be read against it
// (docs/performance.md). Google Benchmark's Threads(n) runs n copies side by
// side; compare items_per_second at threads:1 and threads:2 (real time).
// - BM_HostFma: 16 independent FMA chains per thread, no memory traffic.
// - BM_HostReadModifyWrite/<KiB>: per thread, a buffer scaled in place, as
//   blending reads and writes a framebuffer; 4 MiB stays in the shared L3,
//   64 MiB goes to memory.
#include <benchmark/benchmark.h>

#include <vector>

namespace {

void BM_HostFma(benchmark::State& state) {
    float acc[16];
    for (int k = 0; k < 16; ++k) acc[k] = float(k);
    const float a = 1.0001f, b = 0.9999f;
    for (auto _ : state) {
        for (int i = 0; i < 4096; ++i)
            for (float& x : acc) x = x * a + b;
        benchmark::DoNotOptimize(acc);
    }
    state.SetItemsProcessed(int64_t(state.iterations()) * 4096 * 16);
}
BENCHMARK(BM_HostFma)->Threads(1)->Threads(2)->UseRealTime();

void BM_HostReadModifyWrite(benchmark::State& state) {
    std::vector<float> buffer(size_t(state.range(0)) * 256, 1.0f);
    for (auto _ : state) {
        for (float& x : buffer) x = x * 0.5f + 0.5f;
        benchmark::ClobberMemory();
    }
    state.SetBytesProcessed(int64_t(state.iterations()) * int64_t(buffer.size() * sizeof(float)));
}
BENCHMARK(BM_HostReadModifyWrite)->Arg(4 << 10)->Arg(64 << 10)->Threads(1)->Threads(2)->UseRealTime();

}  // namespace
