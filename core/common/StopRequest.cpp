#include "StopRequest.h"

#include "Model.h"
#include "StateRecord.h"

#include <atomic>
#include <chrono>

namespace pl {

namespace {

std::atomic<bool> requested{false};
// Set only while an InterruptibleStepper keeps a state to return to.
std::atomic<bool> allowed{false};
static_assert(std::atomic<bool>::is_always_lock_free, "requestStop() runs in signal handlers");

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Allows abandoning for one step's duration.
class AllowAbandoning {
public:
    AllowAbandoning() { allowed.store(true, std::memory_order_relaxed); }
    ~AllowAbandoning() { allowed.store(false, std::memory_order_relaxed); }
    AllowAbandoning(const AllowAbandoning&) = delete;
    AllowAbandoning& operator=(const AllowAbandoning&) = delete;
};

} // namespace

void requestStop() noexcept {
    requested.store(true, std::memory_order_relaxed);
}

void withdrawStopRequest() noexcept {
    requested.store(false, std::memory_order_relaxed);
}

bool stopRequested() noexcept {
    return requested.load(std::memory_order_relaxed);
}

bool abandoningStep() noexcept {
    return allowed.load(std::memory_order_relaxed) && requested.load(std::memory_order_relaxed);
}

void leaveIfAbandoning() {
    if (abandoningStep()) throw StepAbandoned();
}

const char* StepAbandoned::what() const noexcept {
    return "the step was abandoned half way by a stop request";
}

InterruptibleStepper::InterruptibleStepper(Model& model, double setUpSeconds)
    : model_(model), lastSeconds_(setUpSeconds) {}

bool InterruptibleStepper::step() {
    const auto start = std::chrono::steady_clock::now();
    if (lastSeconds_ < kKeepAfterSeconds) {
        model_.step();
        lastSeconds_ = secondsSince(start);
        return true;
    }
    // A model that keeps its own step start copies what the step changes as it goes and undoes only
    // that; otherwise the whole state is copied, one pass over it, and put back through restoreState().
    const bool keepsItself = model_.keepStepStart();
    const StateRecord kept = keepsItself ? StateRecord{} : model_.saveState();
    try {
        AllowAbandoning allow;
        model_.step();
    } catch (const StepAbandoned&) {
        if (keepsItself)
            model_.undoStep();
        else
            model_.restoreState(kept);
        ++abandoned_;
        return false;
    }
    lastSeconds_ = secondsSince(start);
    return true;
}

} // namespace pl
