// The interface every scene's model offers to the CLI and the UI: parameters, stepping, observables.
#pragma once

#include "Histogram.h"
#include "ParamSpec.h"
#include "Preset.h"
#include "SampledFields.h"
#include "SceneTools.h"
#include "SceneView.h"
#include "StateRecord.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace pl {

// Why a model stopped: what failed, when, and what to change.
struct ModelFailure {
    std::string what;
    std::int64_t step = 0;
    double time = 0.0;
    std::string hint;
    std::string message() const;
};

struct NamedHistogram {
    std::string name;    // e.g. "speed_a"
    std::string label;   // legend text, e.g. "species A"
    std::string axis;    // what is binned, with its unit, e.g. "speed [L/T]"
    std::string summary; // one line for a plot title, e.g. "kT = 0.501, KS distance 0.012"
    Histogram counts;    // measured
    std::function<double(double)> theoryDensity; // the density theory predicts (empty when none applies)
};

// A curve that is not a time series: e.g. the density error after each solver iteration of the last step.
struct NamedProfile {
    std::string name; // e.g. "density_error_mean"
    std::vector<double> x, y;
};

class Model {
public:
    virtual ~Model() = default;

    virtual std::string kind() const = 0; // "gas"
    virtual const std::vector<ParamSpec>& paramSpecs() const = 0;
    virtual ParamValues params() const = 0;
    // Validates every value first (ParamError, nothing applied). Values of specs marked appliesLive act
    // at once; the others wait for reset().
    virtual void setParams(const ParamValues& values) = 0;

    // Rebuilds the initial state from a validated preset; throws PresetError on cross-field problems.
    virtual void reset(const Preset& preset) = 0;
    // Rebuilds from the current parameters, seed and obstacles.
    virtual void reset() = 0;
    virtual Preset toPreset() const = 0;

    // Everything a snapshot keeps beyond toPreset(): particles, time, counters, and the caches whose order
    // decides the rounding of the next steps (core/common/Snapshot.h). restoreState() follows a
    // reset(toPreset()) of a model of the same kind, so that continuing is bit-identical on the CPU;
    // it throws PresetError naming the entry ("state.x") and leaves the model reset on failure.
    virtual StateRecord saveState() const = 0;
    virtual void restoreState(const StateRecord& state) = 0;

    // A step that a stop request may abandon half way (common/StopRequest.h): keepStepStart() before it
    // says whether the model keeps, as the step goes, what the step changes; undoStep() after an
    // abandoned one then puts the step's start back, touching only what the step reached. A model that
    // says false (the default) is kept whole by saveState() and put back by restoreState().
    virtual bool keepStepStart() { return false; }
    virtual void undoStep() {}

    // Advances by one step of timeDirection() × dt. Does nothing once failure() is set.
    virtual void step() = 0;
    virtual std::int64_t stepCount() const = 0;
    virtual double time() const = 0;
    virtual std::size_t particleCount() const = 0;
    virtual std::optional<ModelFailure> failure() const = 0;
    // Steps after which a run is complete (the DSMC write-up runs 500); 0: open-ended.
    virtual std::int64_t plannedSteps() const { return 0; }
    // Whether a negative time step runs the dynamics backwards (stochastic collisions cannot).
    virtual bool reversible() const { return true; }
    // The direction of time, +1 or −1: each step advances by timeDirection() × the dt parameter, so a
    // preset with a negative dt runs backwards at +1 (the CLI's reversal runs), and turning time round
    // changes no parameter, validates nothing and keeps the energy reference. Throws std::logic_error
    // for −1 when !reversible(), std::invalid_argument for anything but ±1.
    virtual void setTimeDirection(int direction) = 0;
    virtual int timeDirection() const = 0;
    // Checks the state now, as the model otherwise does on its own schedule (the gas: energy every 64
    // steps), and sets failure() when it has blown up; a caller runs it before it records a sample and at
    // the end of a run, so that no exploded row is kept and no run ends well with a runaway state.
    virtual void checkHealthNow() {}
    // A sentence when the current parameters make the method inaccurate though it still runs (DSMC: ν Δt
    // above Bird's guideline), naming what to change; empty otherwise.
    virtual std::string accuracyWarning() const { return {}; }
    // A sentence when the current parameters put every step beyond a known stability bound (the gas:
    // dt·ω above its integrator's limit), naming the parameters and values that fit; empty otherwise.
    // Such a run blows up within a few steps, and its first rows already are not physics: the CLI
    // refuses it before the first step unless the user insists (`run --allow-unstable`).
    virtual std::string stabilityRefusal() const { return {}; }

    // One row of observables per call, matching seriesColumns(); may close accumulation windows.
    virtual std::vector<std::string> seriesColumns() const = 0;
    virtual std::vector<double> sampleSeries() = 0;
    virtual std::vector<NamedHistogram> histograms() const = 0;
    virtual std::vector<NamedProfile> profiles() const { return {}; }

    // Particle dump: CSV with a header line.
    virtual void writeParticles(std::ostream& out) const = 0;

    // Where the model computes: "cpu", or the GPU backend's name ("gl").
    virtual std::string backend() const { return "cpu"; }
    // Returns once all issued work has completed (a GPU queues steps; timing must wait for them).
    virtual void finishPendingWork() const {}

    // What a viewport draws now.
    virtual SceneView sceneView() const = 0;
    // The same for a viewport whose GL context shares objects with the model's: a GPU model may leave
    // the particles in its buffers (SceneView::gpu) instead of copying them out.
    virtual SceneView sceneViewSharingGpu() const { return sceneView(); }
    // The mouse tools' entry points; nullptr when the scene has nothing to drag or spawn.
    virtual SceneTools* tools() { return nullptr; }
    // Fields sampled on a grid of cells (common/SampledFields.h); nullptr when the model has none.
    virtual const SampledFields* sampledFields() const { return nullptr; }
};

} // namespace pl
