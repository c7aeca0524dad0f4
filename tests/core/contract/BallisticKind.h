// A model kind that lives in the test tree: free points in a box with elastic walls and uniform
// gravity, in reduced units (length L, time T, unit mass). It is built by docs/architecture.md's
// "Adding a model kind" alone — parameters, state, model, series, registration — and registered with
// registerModel(), so tst_model_contract checks the checklist itself: a kind made that way passes the
// whole catalog contract. The points do not feel the obstacles (the tools' contract needs none).
#pragma once

#include "catalog/ModelDescriptor.h"
#include "common/ModelBase.h"
#include "common/StateTable.h"

#include <string>
#include <vector>

namespace pl::test {

struct BallisticParams {
    long long count = 200;  // points, 1 … 100 000
    double boxWidth = 2.0;  // [L], centred on x = 0
    double boxHeight = 2.0; // [L], centred on y = 0
    double gravity = 1.0;   // downward acceleration [L/T²], 0 … 100
    double speed = 1.0;     // every point's initial speed, in a random direction [L/T]
    double toolSpeed = 0.5; // the dragged bodies' speed limit [L/T]
    double dt = 1e-3;       // [T]

    void validate() const {}
    // The points must fit in memory (common/MemoryBudget.h), as every kind's state must.
    MemoryNeed memoryNeed() const;
    static const std::vector<ParamField<BallisticParams>>& fields();
    static const std::vector<ParamSpec>& describe();
};

struct BallisticState {
    std::vector<double> x, y, vx, vy; // [L], [L/T]
    std::size_t size() const { return x.size(); }
};

class BallisticModel : public SceneModelBase<BallisticParams, BallisticState> {
public:
    BallisticModel() { reset(); }

    std::string kind() const override { return "ballistic"; }
    using ModelBase::reset;
    void reset() override;
    StateRecord saveState() const override;
    void restoreState(const StateRecord& record) override;
    std::vector<std::string> seriesColumns() const override;
    std::vector<double> sampleSeries() override;
    // The points' speeds (the speedHistogram dock), no theory: they keep the speeds they started with.
    std::vector<NamedHistogram> histograms() const override;
    void writeParticles(std::ostream& out) const override;
    SceneView sceneView() const override;

    double toolSpeed() const override { return params_.toolSpeed; }
    std::string spawnInRectangle(double x0, double y0, double x1, double y1) override;

    // Kinetic plus potential energy per unit mass, g y measured from the box's centre [L²/T²].
    double energy() const;

protected:
    // Velocity Verlet under constant gravity (exact for it, and reversible), then the walls' mirror.
    void advance(double h) override;
    Area areaOf(const BallisticParams& p) const override {
        return {-0.5 * p.boxWidth, -0.5 * p.boxHeight, 0.5 * p.boxWidth, 0.5 * p.boxHeight};
    }

private:
    static const StateTable<BallisticModel, BallisticState>& stateTable();
    long long spawned_ = 0; // rectangles filled by hand since the reset
};

// The kind's registration, for registerModel().
const ModelDescriptor& ballisticRegistration();

} // namespace pl::test
