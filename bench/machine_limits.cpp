// The machine's own limits that the CPU speed goals run into (BENCHMARKS.md, "Limits"): copy bandwidth
// at the working-set sizes of the goals, the cost of an OpenMP region and of a barrier, and the throughput
// of the double-precision square root and division (two lanes, SSE2, as the kernels use them; four with
// AVX where the CPU has it). Built and run by bench/machine_limits.sh; figures are medians of repeats.
#include <immintrin.h>
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <vector>

namespace {

// Wall time, or with cpuTime the process's CPU time: a one-thread figure in CPU time does not count the
// time slices other processes took, so it stays meaningful on a loaded machine.
bool cpuTime = false;

double now() {
    if (cpuTime) {
        timespec t{};
        clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
        return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
    }
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

template <class F> double medianSeconds(int repeats, F&& f) {
    std::vector<double> t;
    for (int r = 0; r < repeats; ++r) {
        const double start = now();
        f();
        t.push_back(now() - start);
    }
    std::sort(t.begin(), t.end());
    return t[t.size() / 2];
}

// Read + write bytes per second of a copy of `bytes`, split over `threads`.
double copyBandwidth(std::size_t bytes, int threads) {
    const std::size_t n = bytes / sizeof(double);
    std::vector<double> a(n, 1.0), b(n, 0.0);
    const int passes = static_cast<int>(std::max<std::size_t>(1, (std::size_t{1} << 28) / bytes));
    const double s = medianSeconds(5, [&] {
        for (int p = 0; p < passes; ++p) {
#pragma omp parallel for schedule(static) num_threads(threads)
            for (std::size_t i = 0; i < n; ++i) b[i] = a[i] + static_cast<double>(p);
        }
    });
    return 2.0 * static_cast<double>(bytes) * passes / s;
}

// Microseconds per empty parallel region and per barrier inside one region.
void regionCosts(int threads, double& region, double& barrier) {
    constexpr int kTimes = 5000;
    region = medianSeconds(5,
                           [&] {
                               for (int k = 0; k < kTimes; ++k) {
#pragma omp parallel num_threads(threads)
                                   { asm volatile("" ::: "memory"); }
                               }
                           }) /
             kTimes * 1e6;
    barrier = medianSeconds(5,
                            [&] {
#pragma omp parallel num_threads(threads)
                                for (int k = 0; k < kTimes; ++k) {
#pragma omp barrier
                                }
                            }) /
              kTimes * 1e6;
}

// Nanoseconds per instruction of independent square roots, then of independent divisions (8 chains).
void dividerSse2(double& sqrtNs, double& divNs) {
    constexpr int kTimes = 500000;
    __m128d v[8];
    for (int c = 0; c < 8; ++c) v[c] = _mm_set1_pd(1.5 + c);
    const __m128d one = _mm_set1_pd(1.0000001);
    sqrtNs = medianSeconds(5,
                           [&] {
                               for (int k = 0; k < kTimes; ++k)
                                   for (int c = 0; c < 8; ++c) {
                                       v[c] = _mm_sqrt_pd(v[c]);
                                       asm volatile("" : "+x"(v[c]));
                                   }
                           }) /
             (8.0 * kTimes) * 1e9;
    divNs = medianSeconds(5,
                          [&] {
                              for (int k = 0; k < kTimes; ++k)
                                  for (int c = 0; c < 8; ++c) {
                                      v[c] = _mm_div_pd(v[c], one);
                                      asm volatile("" : "+x"(v[c]));
                                  }
                          }) /
            (8.0 * kTimes) * 1e9;
}

// No lambdas here: a lambda does not inherit the function's target.
__attribute__((target("avx"))) double avxChains(bool divide) {
    constexpr int kTimes = 500000;
    __m256d v[8];
    for (int c = 0; c < 8; ++c) v[c] = _mm256_set1_pd(1.5 + c);
    const __m256d one = _mm256_set1_pd(1.0000001);
    const double start = now();
    for (int k = 0; k < kTimes; ++k)
        for (int c = 0; c < 8; ++c) {
            v[c] = divide ? _mm256_div_pd(v[c], one) : _mm256_sqrt_pd(v[c]);
            asm volatile("" : "+x"(v[c]));
        }
    return (now() - start) / (8.0 * kTimes) * 1e9;
}

void dividerAvx(double& sqrtNs, double& divNs) {
    std::vector<double> s, d;
    for (int r = 0; r < 5; ++r) s.push_back(avxChains(false)), d.push_back(avxChains(true));
    std::sort(s.begin(), s.end());
    std::sort(d.begin(), d.end());
    sqrtNs = s[2];
    divNs = d[2];
}

} // namespace

int main() {
    std::printf("one-thread figures in CPU time, two-thread figures in wall time (load-sensitive)\n");
    // Working sets: a 4096-disk gas's hot arrays (~0.4 MB, in L2), the fluid tank's (~1 MB), a 262 144-disk
    // gas's (~40 MB: beyond the 32 MB L3), and memory far beyond any cache.
    for (std::size_t bytes : {std::size_t{256} << 10, std::size_t{1} << 20, std::size_t{8} << 20,
                              std::size_t{40} << 20, std::size_t{256} << 20})
        for (int threads : {1, 2}) {
            cpuTime = threads == 1;
            std::printf("copy %zu KiB, %d thread(s): %.3g B/s (read + write)\n", bytes >> 10, threads,
                        copyBandwidth(bytes, threads));
        }
    for (int threads : {1, 2}) {
        cpuTime = false;
        double region = 0, barrier = 0;
        regionCosts(threads, region, barrier);
        std::printf("empty parallel region, %d thread(s): %.2f us; barrier inside a region: %.2f us\n",
                    threads, region, barrier);
    }
    cpuTime = true;
    double s = 0, d = 0;
    dividerSse2(s, d);
    std::printf("SSE2 (2 doubles): sqrtpd %.2f ns, divpd %.2f ns per instruction (independent)\n", s, d);
    if (__builtin_cpu_supports("avx")) {
        dividerAvx(s, d);
        std::printf("AVX (4 doubles): vsqrtpd %.2f ns, vdivpd %.2f ns per instruction (independent)\n", s, d);
    }
}
