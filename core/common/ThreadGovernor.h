// How many OpenMP threads a model's steps run on: a fixed count, or the count that the run itself
// measures to be fastest, chosen again and again as the machine's load changes (BENCHMARKS.md,
// "Shared machines").
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

namespace pl {

// The process's choice, set once by a program's main. Fixed leaves OpenMP's thread count as it is
// (omp_set_num_threads, OMP_NUM_THREADS: the tests and `--threads N`); Adaptive lets each model's
// governor pick, between steps, among 1 … most threads. Either gives the same results bit for bit:
// every parallel loop writes per particle and sums serially (Parallel.h), whatever the team's size.
struct ThreadPolicy {
    bool adaptive = false;
    int most = 1; // the largest team an adaptive governor tries
};
void setThreadPolicy(ThreadPolicy policy);
ThreadPolicy threadPolicy();
// Adaptive over the threads OpenMP would use now, or Fixed where the user set OMP_NUM_THREADS.
ThreadPolicy adaptiveUnlessUserFixed();

// Steps taken at each team size (index: threads) since the last reset, over the whole process.
void resetThreadStepCounts();
std::vector<std::int64_t> threadStepCounts();

// The choice itself, without clocks or OpenMP, so a test can feed it step times. It runs the current
// team size for a window of wall time, then probes a neighbouring size for 1/32 of the window. A probe
// slower per step ends then, however few steps it took, so a team 100× slower costs no more than one
// 10 % slower. A probe faster by more than the noise margin goes on for as long as the window ran and
// wins if it stays faster. A window that confirms the choice doubles, up to 2 s: on a steady machine
// probing costs 1–3 % of the time. A load that comes is noticed within 16 ms (the window's steps slow
// down); one that goes, within a window.
class ThreadGovernor {
public:
    explicit ThreadGovernor(int most);

    int most() const { return ladder_.back(); }
    // The team size for the next step.
    int threadsForNextStep() const { return ladder_[probing_ ? probe_ : current_]; }
    // The wall time [s] of the step just taken at threadsForNextStep().
    void stepTook(double seconds);

private:
    struct Tally {
        std::int64_t steps = 0;
        double seconds = 0.0;
        double perStep() const { return seconds / static_cast<double>(steps); }
    };
    void startProbe();
    void endProbe(bool probeWon);

    std::vector<int> ladder_; // the team sizes tried, ascending
    std::size_t current_;     // index into ladder_
    std::size_t probe_ = 0;
    bool probing_ = false;
    bool probeDownNext_ = true; // probes alternate between the smaller and the larger neighbour
    double window_;             // [s] the current window's length
    double settledPerStep_ = 0; // [s] the last finished window's (or winning probe's) time per step
    Tally run_, trial_;
};

// One model's use of the policy, around each of its steps (ModelBase::step()): sets the team size the
// governor chose and times the step. Models that step on the GPU (hostThreads false) are left alone.
class StepThreads {
public:
    void beginStep(bool hostThreads);
    void endStep();

private:
    std::optional<ThreadGovernor> governor_; // made on the first adaptive step
    int threads_ = 0;                        // this step's team, 0 when not governed
    double started_ = 0.0;
};

} // namespace pl
