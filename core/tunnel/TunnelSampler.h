// What the wind tunnel measures: cell sums of the particles over a window of steps (number, momentum,
// energy per component), turned into n, u, T, T_x, T_y and Mach on demand; and the momentum the gas
// gives each body, summed into drag and lift per unit depth. Bird (1994) §1.4, §12.2;
// docs/wind-tunnel.md#sampling.
#pragma once

#include "TunnelState.h"
#include "common/SampledFields.h"
#include "common/StateRecord.h"

#include <array>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace pl {

// The grid and gas the sums are turned into fields with.
struct SamplingGrid {
    int nx = 0, ny = 0;
    double left = 0, bottom = 0, right = 1, top = 1; // [m]
    double fn = 1;                                   // real molecules per particle (per m of depth)
    double mass = 1;                                 // [kg]
    double gamma = 5.0 / 3.0; // ratio of specific heats for the Mach number (monatomic)
    // Per cell, the fraction of its area outside every body (cut cells hold less gas); empty: all 1.
    // The model updates it when a body is added, removed, placed or moves.
    std::vector<double> openFraction;
};

// Force on one body per unit depth [N/m]: x is the drag (along the free stream), y the lift.
struct BodyForce {
    double drag = 0, lift = 0;
};

class TunnelSampler {
public:
    void configure(const SamplingGrid& grid);
    // New open fractions (a body moved); keeps the sums.
    void setOpenFraction(std::vector<double> fraction) { grid_.openFraction = std::move(fraction); }
    const SamplingGrid& grid() const { return grid_; }
    // Empties the window (fields and surface sums); the next addState() starts it again.
    void restart();
    // A moving window for flows that change: the fields and the mean forces cover only the most recent
    // steps, between half and all of `steps` (two halves; the older is dropped when the newer is full).
    // 0: every step since the window opened (a steady flow). Empties the window.
    void setWindow(std::int64_t steps);
    std::int64_t window() const { return window_; }

    // Adds the state after one step to the cell sums (each particle in the cell of state.cell[i]).
    void addState(const TunnelState& state);
    // One cell's sums over the window.
    struct CellSums {
        double count = 0;              // particle-steps
        double mx = 0, my = 0, mz = 0; // Σ v
        double ex = 0, ey = 0, ez = 0; // Σ v²
    };
    // Sums gathered elsewhere over `steps` steps (the GL backend sums the cells on the GPU), one per
    // cell, added as that many addState() calls would add them.
    void addCellSums(const std::vector<CellSums>& sums, std::int64_t steps);
    // A particle of momentum change (dpx, dpy) [kg m/s] at the surface of body b this step: the gas
    // feels dp, the body −dp. Called by the model's surface reflection, with the real-molecule weight
    // applied by the sampler (× fn).
    void addSurfaceImpulse(std::size_t body, double dpx, double dpy);
    // Closes one step of surface sums of duration dt [s]. The model calls it every step; the window's
    // force average counts the step only once the window is open (addState() was called since
    // restart()), the interval and the latest force always. The model calls addState() only from
    // sampleStart steps after a reset or an edit on.
    void endStep(std::size_t bodies, double dt);

    // Steps the fields average over now (both halves of a moving window).
    std::int64_t sampledSteps() const { return steps_ + previousSteps_; }
    // The force on each body averaged over the window [N/m]; and over the last step alone. One entry per
    // body of the last endStep(); zero forces while the window has no step.
    std::vector<BodyForce> averageForces() const;
    std::vector<BodyForce> lastForces() const;
    // The force on each body averaged over the steps since the previous call (the series' interval);
    // the interval sums restart. Counts every endStep(), inside or outside the fields window. With no step
    // since the previous call (a row of the same state, as the first row of a resumed run) it repeats
    // that call's forces; zero forces before any.
    std::vector<BodyForce> takeIntervalForces();

    // The window's sums, the surface sums and the series' interval as a snapshot keeps them, so that a
    // resumed run's fields, forces and rows continue as those of the run that never stopped
    // (TunnelSamplerState.cpp).
    void save(StateRecord& record) const;
    // Reads what save() wrote, on this sampler's grid (the per-body sums have one entry per body of the
    // last step). Throws PresetError naming the field that does not fit, and then leaves the sampler as it
    // was.
    void restore(const StateRecord& record);
    // Whether the record holds a sampler's state (snapshots of earlier builds do not).
    static bool savedIn(const StateRecord& record);

    // SampledFields' pieces (TunnelModel forwards them). Field names: "n", "ux", "uy", "speed", "T",
    // "Tx", "Ty", "mach". A cell without samples, or with no open area, gives NaN for every field.
    std::vector<FieldChoice> fieldChoices() const;
    FieldGrid field(const std::string& name) const;
    std::vector<FieldValue> probe(double x, double y) const;
    void writeFieldsCsv(std::ostream& out) const;

private:
    // A cell's fields in the order of fieldChoices().
    using CellFieldValues = std::array<double, 8>;
    CellFieldValues cellFields(std::size_t cell) const;
    // The newer half of a moving window is full: it becomes the older one.
    void rotateWindow();

    SamplingGrid grid_;
    std::vector<CellSums> cells_;
    std::int64_t steps_ = 0;
    std::vector<double> impulseX_, impulseY_;   // this step, per body [kg m/s] (× fn applied)
    std::vector<double> sumForceX_, sumForceY_; // Σ over the window's steps of the force [N/m]
    std::vector<BodyForce> last_;
    std::int64_t forceSteps_ = 0;
    std::vector<double> intervalForceX_, intervalForceY_;
    std::int64_t intervalSteps_ = 0;
    std::vector<BodyForce> previousInterval_; // what the last takeIntervalForces() gave
    // A moving window's older half (empty, 0 steps, for a window over the whole run).
    std::int64_t window_ = 0;
    std::vector<CellSums> previous_;
    std::int64_t previousSteps_ = 0;
    std::vector<double> previousForceX_, previousForceY_;
    std::int64_t previousForceSteps_ = 0;
};

} // namespace pl
