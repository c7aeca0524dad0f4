// Scene builders and measurements for the MD tests.
#include "GasTestScenes.h"

#include <cmath>
#include <unordered_map>

namespace pl::test {

GasModel makeGas(const ParamValues& values, std::uint64_t seed, std::vector<Obstacle> obstacles) {
    Preset preset;
    preset.model = "gas";
    preset.seed = seed;
    preset.params = values;
    preset.obstacles = std::move(obstacles);
    GasModel model;
    model.reset(preset);
    return model;
}

std::pair<double, double> totalMomentum(const GasModel& model) {
    const auto& s = model.state();
    const auto& p = model.parameters();
    double px = 0, py = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        const double m = s.species[i] == 0 ? p.a.mass : p.b.mass;
        px += m * s.vx[i];
        py += m * s.vy[i];
    }
    return {px, py};
}

double rmsDistance(const GasState& a, const GasState& b) {
    // Large gases are kept in spatial order, so particles are matched by id, not by index.
    std::unordered_map<std::uint32_t, std::size_t> indexOf;
    for (std::size_t i = 0; i < b.size(); ++i) indexOf[b.id[i]] = i;
    double sum = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const std::size_t j = indexOf.at(a.id[i]);
        sum += std::pow(a.x[i] - b.x[j], 2) + std::pow(a.y[i] - b.y[j], 2);
    }
    return std::sqrt(sum / static_cast<double>(a.size()));
}

} // namespace pl::test
