// The thread policy and the governor that measures which team size steps fastest (ThreadGovernor.h).
#include "ThreadGovernor.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <omp.h>

namespace pl {

namespace {

// The first window [s] and the longest: a short run settles within milliseconds, a long one probes
// rarely. A probe takes kProbeShare of its window's time.
constexpr double kFirstWindowSeconds = 2e-3;
constexpr double kLongestWindowSeconds = 2.0;
constexpr double kProbeShare = 1.0 / 32.0;
// The fewest steps a window and a probe measure: one step may hold a rebuild of the neighbour list.
constexpr std::int64_t kFewestWindowSteps = 8;
constexpr std::int64_t kFewestProbeSteps = 3;
// A probe wins when it is faster per step by more than this fraction: on a quiet machine the same team
// differs by a few per cent from window to window (BENCHMARKS.md, "Shared machines").
constexpr double kNoiseMargin = 0.05;
// A window whose steps take kChangeFactor × the last window's per step, over at least
// kChangeNoticeSeconds, ends early: far beyond the spread of a quiet machine, and long enough to hold
// the rebuild steps of a neighbour list.
constexpr double kChangeFactor = 1.5;
constexpr double kChangeNoticeSeconds = 16e-3;
// Team sizes counted one by one; larger ones share the last counter.
constexpr int kLargestCounted = 256;

std::atomic<bool> policyAdaptive{false};
std::atomic<int> policyMost{1};
std::array<std::atomic<std::int64_t>, kLargestCounted + 1> stepsAtTeamSize{};

double nowSeconds() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

} // namespace

void setThreadPolicy(ThreadPolicy policy) {
    policyMost.store(std::max(1, policy.most), std::memory_order_relaxed);
    policyAdaptive.store(policy.adaptive, std::memory_order_relaxed);
}

ThreadPolicy threadPolicy() {
    return {policyAdaptive.load(std::memory_order_relaxed), policyMost.load(std::memory_order_relaxed)};
}

ThreadPolicy adaptiveUnlessUserFixed() {
    if (const char* fixed = std::getenv("OMP_NUM_THREADS"); fixed && *fixed)
        return {false, omp_get_max_threads()};
    return {true, omp_get_num_procs()};
}

void resetThreadStepCounts() {
    for (auto& count : stepsAtTeamSize) count.store(0, std::memory_order_relaxed);
}

std::vector<std::int64_t> threadStepCounts() {
    std::vector<std::int64_t> counts;
    for (const auto& count : stepsAtTeamSize) counts.push_back(count.load(std::memory_order_relaxed));
    while (!counts.empty() && counts.back() == 0) counts.pop_back();
    return counts;
}

ThreadGovernor::ThreadGovernor(int most) : window_(kFirstWindowSeconds) {
    most = std::max(1, most);
    // 1, half, all but one and all: on two cores {1, 2}; on eight {1, 4, 7, 8}.
    ladder_ = {1, std::max(1, most / 2), std::max(1, most - 1), most};
    std::sort(ladder_.begin(), ladder_.end());
    ladder_.erase(std::unique(ladder_.begin(), ladder_.end()), ladder_.end());
    // Start on one thread and climb: a probe up that wins costs nothing, while a first window on a team
    // that waits for a busy core costs milliseconds.
    current_ = 0;
}

void ThreadGovernor::stepTook(double seconds) {
    if (!probing_) {
        run_.steps += 1;
        run_.seconds += seconds;
        if (run_.steps < kFewestWindowSteps) return;
        // A window ends when it is full, or early when a team of several threads became much slower
        // than in its last window: another program took a core, and fewer threads may wait less. (On
        // one thread a slower machine is no reason to try more.)
        const bool changed = current_ > 0 && run_.seconds >= kChangeNoticeSeconds && settledPerStep_ > 0 &&
                             run_.perStep() > kChangeFactor * settledPerStep_;
        if (run_.seconds >= window_ || changed) startProbe();
        return;
    }
    trial_.steps += 1;
    trial_.seconds += seconds;
    if (trial_.seconds < window_ * kProbeShare) return;
    const bool faster = trial_.perStep() < run_.perStep() * (1.0 - kNoiseMargin);
    if (!faster) {
        // Slower: settled once it took its steps, or at once when already slower than the window (a
        // team that waits for a busy core costs no more than its share of time).
        if (trial_.steps >= kFewestProbeSteps || trial_.perStep() > run_.perStep()) endProbe(false);
        return;
    }
    // Faster so far: it wins once it stayed faster for as long as the window ran. A team whose steps
    // are quick but now and then wait milliseconds for a core the scheduler gave away is caught here,
    // at its first wait, before it is chosen.
    if (trial_.seconds >= run_.seconds && trial_.steps >= kFewestWindowSteps) endProbe(true);
}

void ThreadGovernor::startProbe() {
    const bool canGoDown = current_ > 0, canGoUp = current_ + 1 < ladder_.size();
    if (!canGoDown && !canGoUp) { // one core: nothing to compare
        window_ = kLongestWindowSeconds;
        run_ = {};
        return;
    }
    const bool down = canGoDown && (probeDownNext_ || !canGoUp);
    probe_ = down ? current_ - 1 : current_ + 1;
    probeDownNext_ = !down;
    probing_ = true;
    trial_ = {};
}

void ThreadGovernor::endProbe(bool probeWon) {
    if (probeWon) {
        current_ = probe_;
        settledPerStep_ = trial_.perStep();
    } else {
        // The next window is twice the one that ran (a window of few long steps runs past its length),
        // up to the longest, and at least 1/kProbeShare times this probe: where one step of the probe
        // took long, probes still cost no more than their share.
        window_ = std::max(std::min(2.0 * std::max(window_, run_.seconds), kLongestWindowSeconds),
                           trial_.seconds / kProbeShare);
        settledPerStep_ = run_.perStep();
    }
    probing_ = false;
    run_ = {};
    trial_ = {};
}

void StepThreads::beginStep(bool hostThreads) {
    threads_ = 0;
    const ThreadPolicy policy = threadPolicy();
    if (!hostThreads || !policy.adaptive) return;
    if (!governor_ || governor_->most() != policy.most) governor_.emplace(policy.most);
    threads_ = governor_->threadsForNextStep();
    omp_set_num_threads(threads_);
    started_ = nowSeconds();
}

void StepThreads::endStep() {
    if (threads_ == 0) return;
    governor_->stepTook(nowSeconds() - started_);
    stepsAtTeamSize[static_cast<std::size_t>(std::min(threads_, kLargestCounted))].fetch_add(
        1, std::memory_order_relaxed);
}

} // namespace pl
