// A run computed elsewhere (a LAMMPS run read back), as a model the docks and the viewport can show: its
// last state, at the step and time the run reached, that never steps, takes no parameters and offers
// no tools, so nothing in the window can change what was imported.
#pragma once

#include "common/Model.h"

#include <memory>

namespace pl::ui {

class ImportedRunModel final : public Model {
public:
    // state: the run's last state (its time and step counter are ours, not the run's); step and time:
    // where the run ended.
    ImportedRunModel(std::unique_ptr<Model> state, std::int64_t step, double time);

    std::string kind() const override { return state_->kind(); }
    const std::vector<ParamSpec>& paramSpecs() const override { return state_->paramSpecs(); }
    ParamValues params() const override { return state_->params(); }
    void setParams(const ParamValues& values) override;
    void reset(const Preset&) override {} // read-only: the imported state stays
    void reset() override {}
    Preset toPreset() const override { return state_->toPreset(); }
    StateRecord saveState() const override { return state_->saveState(); }
    void restoreState(const StateRecord& state) override;

    void step() override {}
    std::int64_t stepCount() const override { return step_; }
    double time() const override { return time_; }
    std::size_t particleCount() const override { return state_->particleCount(); }
    std::optional<ModelFailure> failure() const override { return std::nullopt; }
    bool reversible() const override { return state_->reversible(); }
    void setTimeDirection(int direction) override { state_->setTimeDirection(direction); }
    int timeDirection() const override { return state_->timeDirection(); }

    std::vector<std::string> seriesColumns() const override { return state_->seriesColumns(); }
    std::vector<double> sampleSeries() override { return state_->sampleSeries(); }
    std::vector<NamedHistogram> histograms() const override { return state_->histograms(); }
    std::vector<NamedProfile> profiles() const override { return state_->profiles(); }
    void writeParticles(std::ostream& out) const override { state_->writeParticles(out); }
    SceneView sceneView() const override { return state_->sceneView(); }
    SceneTools* tools() override { return nullptr; }

private:
    std::unique_ptr<Model> state_;
    std::int64_t step_;
    double time_;
};

} // namespace pl::ui
