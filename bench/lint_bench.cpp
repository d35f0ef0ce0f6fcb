// hexc-bench-lint [--benchmark_* flags]: what each texture check (hexc/lint.h, docs/lint.md) costs, in milliseconds
// per megatexel, on a 1024 x 1024 8-bit normal map: decoding it from PNG, the normal map's slopes, the green check's
// curl, the tilt check's mean and the seam check's edge differences; and a whole slot as a compile checks it. It
// reports, it does not judge: the exit code is 0 whatever the numbers.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include "hexc/lint.h"
#include "textures/lint_measures.h"

namespace hexc::bench {
namespace {

constexpr int kSide = 1024;
constexpr double kMegatexels = kSide * kSide / 1e6;

// A bumpy normal map: smooth random slopes, 8-bit, green up. What it shows does not change what the checks cost.
const Texture& normalMap() {
    static const Texture t = [] {
        Texture n;
        n.width = n.height = kSide;
        n.rgba8.resize(size_t(kSide) * kSide * 4);
        std::mt19937 rng(1);
        std::uniform_real_distribution<double> phase(0, 6.283185307179586);
        const double a = phase(rng), b = phase(rng);
        for (int y = 0; y < kSide; ++y)
            for (int x = 0; x < kSide; ++x) {
                const double p = 0.5 * std::cos(6.283185307179586 * 5 * x / kSide + a),
                             q = 0.5 * std::sin(6.283185307179586 * 7 * y / kSide + b);
                const double n3[3] = {-p, q, 1}, len = std::sqrt(p * p + q * q + 1);
                uint8_t* texel = &n.rgba8[(size_t(y) * kSide + x) * 4];
                for (int c = 0; c < 3; ++c) texel[c] = uint8_t(std::lround((n3[c] / len * 0.5 + 0.5) * 255));
                texel[3] = 255;
            }
        return n;
    }();
    return t;
}

// Each benchmark's processor time per megatexel, in milliseconds, beside Google Benchmark's time per iteration: a rate
// (megatexels per second) inverted, in thousands.
void perMegatexel(benchmark::State& state) {
    state.counters["ms_per_Mtexel"] =
        benchmark::Counter(double(state.iterations()) * kMegatexels / 1e3, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void Decode(benchmark::State& state) {
    const std::string png = pngBytes(normalMap());
    for (auto _ : state) benchmark::DoNotOptimize(decodeTexture(png, false));
    perMegatexel(state);
}

void Slopes(benchmark::State& state) {
    for (auto _ : state) benchmark::DoNotOptimize(lint::slopes(normalMap(), false, 3));
    perMegatexel(state);
}

void Green(benchmark::State& state) {
    const lint::Slopes pq = lint::slopes(normalMap(), false, 3);
    TextureFigures f;
    for (auto _ : state) lint::curls(pq, kSide, kSide, f), benchmark::DoNotOptimize(f);
    perMegatexel(state);
}

void Tilt(benchmark::State& state) {
    const lint::Slopes pq = lint::slopes(normalMap(), false, 3);
    TextureFigures f;
    for (auto _ : state) lint::tilt(pq, f), benchmark::DoNotOptimize(f);
    perMegatexel(state);
}

void SeamNormal(benchmark::State& state) {
    for (auto _ : state) benchmark::DoNotOptimize(lint::seams(normalMap(), {0, 1}));
    perMegatexel(state);
}

void SeamColour(benchmark::State& state) {
    for (auto _ : state) benchmark::DoNotOptimize(lint::seams(normalMap(), {0, 1, 2}));
    perMegatexel(state);
}

void WholeNormalMap(benchmark::State& state) {
    for (auto _ : state) benchmark::DoNotOptimize(measureTexture(normalMap(), SlotKind::Normal, 0, false, 3));
    perMegatexel(state);
}

BENCHMARK(Decode)->Unit(benchmark::kMillisecond);
BENCHMARK(Slopes)->Unit(benchmark::kMillisecond);
BENCHMARK(Green)->Unit(benchmark::kMillisecond);
BENCHMARK(Tilt)->Unit(benchmark::kMillisecond);
BENCHMARK(SeamNormal)->Unit(benchmark::kMillisecond);
BENCHMARK(SeamColour)->Unit(benchmark::kMillisecond);
BENCHMARK(WholeNormalMap)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace hexc::bench

BENCHMARK_MAIN();
