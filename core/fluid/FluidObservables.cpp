// What the fluid reports: density error (per step and per iteration), kinetic energy, neighbour counts,
// and the dam-break surge front in Martin & Moyce's units.
#include "FluidModel.h"
#include "FluidSeries.h"

#include "common/Parallel.h"

#include <algorithm>
#include <cmath>
#include <ostream>

namespace pl {

std::vector<double> FluidModel::densityConstraints(std::vector<int>* neighboursWithinH) const {
    const std::size_t count = state_.size();
    std::vector<double> c(count);
    if (neighboursWithinH) neighboursWithinH->assign(count, 0);
    if (count == 0) return c;
    fluid::Neighbours list;
    list.build(state_.x.data(), state_.y.data(), count, params_.h, params_.boxWidth, params_.boxHeight);
    const auto n = static_cast<long long>(count);
    const fluid::Kernels k = kernels_;
#pragma omp parallel for schedule(static) if (n >= kParallelMinParticles)
    for (long long i = 0; i < n; ++i) {
        double rho = k.selfWeight();
        int within = 0;
        for (std::uint32_t e = list.offsets()[i]; e < list.offsets()[i + 1]; ++e) {
            const std::uint32_t j = list.entries()[e];
            const double dx = state_.x[i] - state_.x[j], dy = state_.y[i] - state_.y[j];
            const double r2 = dx * dx + dy * dy;
            rho += k.w(r2);
            within += r2 < k.h2 ? 1 : 0;
        }
        c[i] = rho / restDensity_ - 1.0;
        if (neighboursWithinH) (*neighboursWithinH)[i] = within;
    }
    return c;
}

FluidObservables FluidModel::observe() const {
    pullState();
    FluidObservables o;
    o.step = stepCount();
    o.time = time();
    o.particles = state_.size();
    o.drained = drained_;
    const std::size_t n = state_.size();
    if (n == 0) return o;
    std::vector<int> neighbours;
    const std::vector<double> c = densityConstraints(&neighbours);
    double compression = 0, ratio = 0, within = 0;
    o.neighboursMin = neighbours[0];
    for (std::size_t i = 0; i < n; ++i) {
        compression += std::max(c[i], 0.0);
        o.densityErrorMax = std::max(o.densityErrorMax, c[i]);
        ratio += c[i] + 1.0;
        within += neighbours[i];
        o.neighboursMin = std::min<double>(o.neighboursMin, neighbours[i]);
        o.neighboursMax = std::max<double>(o.neighboursMax, neighbours[i]);
        const double v2 = state_.vx[i] * state_.vx[i] + state_.vy[i] * state_.vy[i];
        o.kinetic += 0.5 * v2;
        o.maxSpeed = std::max(o.maxSpeed, std::sqrt(v2));
    }
    const double count = static_cast<double>(n);
    o.densityErrorMean = compression / count;
    o.densityRatioMean = ratio / count;
    o.neighboursMean = within / count;

    // Dam break (docs/fluid.md#dam-break-front): a column of base a and height n² a; z is measured from the
    // column's back (the left wall in the preset) to the rightmost particle on the floor, plus half a spacing
    // so that Z(0) = 1 exactly; T = n t √(g/a).
    const double g = params_.gravityOn ? params_.gravityMagnitude() : 0.0;
    if (params_.hasFill() && g > 0) {
        const double a = params_.fillX1 - params_.fillX0;
        const double aspect = std::sqrt((params_.fillY1 - params_.fillY0) / a);
        const double floorLayer = params_.particleRadius + params_.spacing();
        double front = -INFINITY;
        for (std::size_t i = 0; i < n; ++i)
            if (state_.y[i] <= floorLayer) front = std::max(front, state_.x[i]);
        if (std::isfinite(front)) {
            o.frontZ = (front + 0.5 * params_.spacing() - params_.fillX0) / a;
            o.frontT = aspect * time() * std::sqrt(g / a);
        }
    }
    return o;
}

const SeriesTable<FluidObservables>& fluidSeriesTable() {
    using O = FluidObservables;
    static const SeriesTable<O> table{
        {{"step", "", "step"}, [](const O& o) { return static_cast<double>(o.step); }},
        {{"time", "s", "time"}, [](const O& o) { return o.time; }},
        {{"particles", "", "particles"}, [](const O& o) { return static_cast<double>(o.particles); }},
        {{"density_error_mean", "", "mean compression ρ/ρ₀ − 1"},
         [](const O& o) { return o.densityErrorMean; }},
        {{"density_error_max", "", "largest compression ρ/ρ₀ − 1"},
         [](const O& o) { return o.densityErrorMax; }},
        {{"density_ratio_mean", "", "mean ρ/ρ₀"}, [](const O& o) { return o.densityRatioMean; }},
        {{"kinetic", "L²/s²", "kinetic energy Σ ½ v²"}, [](const O& o) { return o.kinetic; }},
        {{"max_speed", "L/s", "largest speed"}, [](const O& o) { return o.maxSpeed; }},
        {{"neighbours_mean", "", "mean neighbours within h"}, [](const O& o) { return o.neighboursMean; }},
        {{"neighbours_min", "", "fewest neighbours within h"}, [](const O& o) { return o.neighboursMin; }},
        {{"neighbours_max", "", "most neighbours within h"}, [](const O& o) { return o.neighboursMax; }},
        {{"front_Z", "", "surge front Z = z / a"}, [](const O& o) { return o.frontZ; }},
        {{"front_T", "", "front time T = n t √(g/a)"}, [](const O& o) { return o.frontT; }},
        // The shallow-water (Ritter) front moves at dZ/dT = 2: the bound a real front stays below.
        {{"front_Z_shallow_water", "", "shallow-water bound 1 + 2T"},
         [](const O& o) { return std::isfinite(o.frontT) ? 1.0 + 2.0 * o.frontT : NAN; }},
        {{"drained", "", "removed by the drain"}, [](const O& o) { return static_cast<double>(o.drained); }},
    };
    return table;
}

std::vector<std::string> FluidModel::seriesColumns() const {
    return fluidSeriesTable().names();
}

std::vector<double> FluidModel::sampleSeries() {
    return fluidSeriesTable().sample(observe());
}

std::vector<double> FluidModel::iterationErrorMean() const {
    pullState();
    std::vector<double> errors = errorMean_;
    errors.push_back(observe().densityErrorMean);
    return errors;
}

std::vector<double> FluidModel::iterationErrorMax() const {
    pullState();
    std::vector<double> errors = errorMax_;
    errors.push_back(observe().densityErrorMax);
    return errors;
}

std::vector<NamedProfile> FluidModel::profiles() const {
    pullState();
    // Entry k: the error after k corrections of the last step; the last entry is the step's result.
    const FluidObservables now = observe();
    NamedProfile mean{"density_error_mean", {}, errorMean_}, max{"density_error_max", {}, errorMax_};
    mean.y.push_back(now.densityErrorMean);
    max.y.push_back(now.densityErrorMax);
    for (std::size_t k = 0; k < mean.y.size(); ++k) {
        mean.x.push_back(static_cast<double>(k));
        max.x.push_back(static_cast<double>(k));
    }
    return {mean, max};
}

void FluidModel::writeParticles(std::ostream& out) const {
    pullState();
    const std::vector<double> c = densityConstraints();
    out << "index,x,y,vx,vy,density_ratio\n";
    for (std::size_t i = 0; i < state_.size(); ++i)
        out << i << ',' << state_.x[i] << ',' << state_.y[i] << ',' << state_.vx[i] << ',' << state_.vy[i]
            << ',' << c[i] + 1.0 << '\n';
}

} // namespace pl
