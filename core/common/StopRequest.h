// A stop asked for from outside the computation (the CLI's SIGINT / SIGTERM), and how one step of
// minutes still ends within a second: the step's long loops poll for it and abandon the step, and the
// stepper that allowed that puts the state of the step's start back (docs/architecture.md, "Stopping a
// step half way"). Nothing here changes a result: a step that is not abandoned is the same bit for bit.
#pragma once

#include <exception>

namespace pl {

class Model;

// Async-signal-safe: a lock-free atomic store.
void requestStop() noexcept;
void withdrawStopRequest() noexcept;
bool stopRequested() noexcept;

// Whether the step now running is to be abandoned: a stop was requested while an InterruptibleStepper
// allows it. Cheap enough for every cell or chunk of a loop, also inside an OpenMP region, where the
// loop skips its remaining iterations (an exception may not leave the region).
bool abandoningStep() noexcept;
// Outside parallel regions, between a step's phases: throws StepAbandoned when abandoningStep().
void leaveIfAbandoning();

struct StepAbandoned : std::exception {
    const char* what() const noexcept override;
};

// Steps a model so that a stop request ends even a long step within a second. Before a step that may
// take long (the previous one, or the set-up, took at least kKeepAfterSeconds) it has the step's start
// kept (Model::keepStepStart(): by the model, as the step goes, or else a copy of the whole state) and
// allows the step to be abandoned; a request half way then puts the start back, so the run ends at the
// last whole step exactly as if the request had come between steps. Short steps keep nothing (no copy,
// no cost) and always finish: they end within kKeepAfterSeconds.
class InterruptibleStepper {
public:
    static constexpr double kKeepAfterSeconds = 0.1;

    InterruptibleStepper(Model& model, double setUpSeconds);
    // Takes one step; false when a stop request abandoned it and the model is back at its start.
    bool step();
    // The steps abandoned so far (0 or 1 in a run that ends at the first request).
    int abandoned() const { return abandoned_; }

private:
    Model& model_;
    double lastSeconds_;
    int abandoned_ = 0;
};

} // namespace pl
