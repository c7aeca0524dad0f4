// What the tunnel shows and reports: the free stream's mean free path and collision time, the accuracy
// guidelines, the series, the speed histogram, the particles' CSV and the viewport's scene (particles
// by speed, or a sampled field as a colour map).
#include "TunnelSeries.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <utility>

namespace pl {

namespace {
const double kNaN = std::numeric_limits<double>::quiet_NaN();
// Bird's guidelines (1994 §11.1): cells below about λ/2, Δt below about a quarter of the mean
// collision time, and enough molecules per cell for the NTC pairs to be representative.
constexpr double kCellOverMeanFreePath = 0.5;
constexpr double kStepOverCollisionTime = 0.25;
constexpr double kMinParticlesPerCell = 5.0;
constexpr std::size_t kHistogramBins = 60;

BodyForce sum(const std::vector<BodyForce>& forces) {
    BodyForce total;
    for (const BodyForce& f : forces) total.drag += f.drag, total.lift += f.lift;
    return total;
}

// The field each view shows (TunnelSampler's names).
const char* fieldOf(TunnelView view) {
    switch (view) {
    case TunnelView::Density:
        return "n";
    case TunnelView::Speed:
        return "speed";
    case TunnelView::Temperature:
        return "T";
    case TunnelView::Mach:
        return "mach";
    case TunnelView::Particles:
        break;
    }
    return "";
}
} // namespace

CollisionModel TunnelModel::collisionModelOf(const TunnelParams& p) {
    return CollisionModel::fromCrossSection(p.crossSection, p.diameter, p.vhsDiameter, p.vhsTref, p.vhsOmega,
                                            p.maxwellSigmaCr, p.mass());
}

double TunnelModel::collisionTimeOf(const TunnelParams& p) {
    return 1.0 / (p.streamDensity * collisionModelOf(p).meanSigmaCr(p.streamTemperature, p.mass()));
}

double TunnelModel::meanFreePathOf(const TunnelParams& p) {
    const double n = p.streamDensity, T = p.streamTemperature;
    if (p.crossSection == DsmcCrossSection::HardSphere) // Bird 1994 eq. 4.52
        return 1.0 / (std::numbers::sqrt2 * std::numbers::pi * p.diameter * p.diameter * n);
    if (p.crossSection == DsmcCrossSection::Vhs) // Bird 1994 eq. 4.65
        return 1.0 / (std::numbers::sqrt2 * std::numbers::pi * p.vhsDiameter * p.vhsDiameter * n *
                      std::pow(p.vhsTref / T, p.vhsOmega - 0.5));
    // Otherwise the mean speed times the mean collision time (Bird 1994 eq. 4.51).
    const double meanSpeed = std::sqrt(8.0 * kBoltzmann * T / (std::numbers::pi * p.mass()));
    return meanSpeed * collisionTimeOf(p);
}

double TunnelModel::freeStreamMeanFreePath() const {
    return meanFreePathOf(params_);
}

double TunnelModel::knudsenNumber() const {
    double length = params_.boxHeight;
    if (!obstacles_.empty()) {
        const Obstacle& o = obstacles_.front();
        length = o.shape == Obstacle::Shape::Disc ? 2.0 * o.radius : 2.0 * o.halfHeight;
    }
    return freeStreamMeanFreePath() / length;
}

std::string TunnelModel::accuracyWarning() const {
    std::vector<std::string> issues;
    const double lambda = freeStreamMeanFreePath();
    const double cell = std::max(params_.cellWidth(), params_.cellHeight());
    if (cell > kCellOverMeanFreePath * lambda) {
        const double wanted = kCellOverMeanFreePath * lambda;
        issues.push_back("cells are " + formatNumber(cell / lambda, 2) +
                         " free-stream mean free paths wide (λ = " + formatNumber(lambda, 3) +
                         " m), above λ/2: use {cells_x} ≥ " +
                         formatNumber(std::ceil(params_.boxWidth / wanted), 6) + " and {cells_y} ≥ " +
                         formatNumber(std::ceil(params_.boxHeight / wanted), 6));
    }
    const double tau = freeStreamCollisionTime();
    if (params_.dt > kStepOverCollisionTime * tau)
        issues.push_back("Δt is " + formatNumber(params_.dt / tau, 2) +
                         " mean collision times of the free stream: use {dt} ≤ " +
                         formatNumber(kStepOverCollisionTime * tau, 3) + " s");
    const double perCell = params_.streamDensity * params_.cellWidth() * params_.cellHeight() / params_.fn;
    if (perCell < kMinParticlesPerCell)
        issues.push_back("a free-stream cell holds " + formatNumber(perCell, 2) +
                         " molecules on average: use {fn} ≤ " +
                         formatNumber(params_.fn * perCell / kMinParticlesPerCell, 3));
    std::string text;
    for (const std::string& issue : issues) text += (text.empty() ? "" : "; ") + issue;
    return withKeys(text);
}

TunnelObservables TunnelModel::observe() const {
    pullSamples();
    TunnelObservables o;
    o.particles = particleCount(); // a GPU backend answers without a download
    o.collisions = collisionsThisStep_;
    const BodyForce last = sum(sampler_.lastForces()), average = sum(sampler_.averageForces());
    o.drag = last.drag;
    o.lift = last.lift;
    o.dragAverage = average.drag;
    o.liftAverage = average.lift;
    const double rate = 2.0 * static_cast<double>(collisionsThisStep_) /
                        (static_cast<double>(o.particles) * params_.dt); // per molecule and second
    o.meanFreeTime = rate > 0 ? 1.0 / rate : kNaN;
    o.sampledSteps = sampler_.sampledSteps();
    return o;
}

const SeriesTable<TunnelSeriesRow>& tunnelSeriesTable() {
    using R = TunnelSeriesRow;
    static const SeriesTable<R> table{
        {{"step", "", "step"}, [](const R& r) { return static_cast<double>(r.step); }},
        {{"time", "s", "time"}, [](const R& r) { return r.time; }},
        {{"particles", "", "simulated molecules"},
         [](const R& r) { return static_cast<double>(r.observed.particles); }},
        {{"collisions", "", "collisions in the last step"},
         [](const R& r) { return static_cast<double>(r.observed.collisions); }},
        {{"drag", "N/m", "drag per unit depth"}, [](const R& r) { return r.observed.drag; }},
        {{"lift", "N/m", "lift per unit depth"}, [](const R& r) { return r.observed.lift; }},
        {{"drag_avg", "N/m", "drag averaged over the fields window"},
         [](const R& r) { return r.observed.dragAverage; }},
        {{"lift_avg", "N/m", "lift averaged over the fields window"},
         [](const R& r) { return r.observed.liftAverage; }},
        {{"sampled_steps", "", "steps in the fields window"},
         [](const R& r) { return static_cast<double>(r.observed.sampledSteps); }},
    };
    return table;
}

std::vector<std::string> TunnelModel::seriesColumns() const {
    return tunnelSeriesTable().names();
}

std::vector<double> TunnelModel::sampleSeries() {
    TunnelSeriesRow row{stepCount(), time(), observe()};
    // The force columns are the mean since the previous sample, so no step's force is lost between rows.
    const BodyForce interval = sum(sampler_.takeIntervalForces());
    row.observed.drag = interval.drag;
    row.observed.lift = interval.lift;
    return tunnelSeriesTable().sample(row);
}

namespace {
// The speed at the top of the colour scale: twice the fastest motion the scene imposes (stream, walls,
// piston), and at least three most-probable thermal speeds.
double colourMaxOf(const TunnelParams& p) {
    const double thermal = std::sqrt(2.0 * kBoltzmann * p.streamTemperature / p.mass());
    const double imposed = std::max({std::abs(p.streamSpeed), std::abs(p.bottomWallSpeed),
                                     std::abs(p.topWallSpeed), p.pistonOn ? p.pistonSpeed : 0.0});
    return std::max(2.0 * imposed, 3.0 * thermal);
}
} // namespace

namespace {
// The colour scale of a field: from the 1st to the 99th percentile of its sampled cells. Early in a
// window a cell holding one molecule can read a Mach number of 10⁸; min–max would give the whole field
// one colour. Cells beyond the range take the end colours.
std::pair<double, double> colourRange(const std::vector<double>& values) {
    std::vector<double> finite;
    finite.reserve(values.size());
    for (double v : values)
        if (std::isfinite(v)) finite.push_back(v);
    if (finite.empty()) return {0.0, 1.0};
    const auto at = [&](double q) {
        const auto k = static_cast<std::ptrdiff_t>(q * static_cast<double>(finite.size() - 1));
        std::nth_element(finite.begin(), finite.begin() + k, finite.end());
        return finite[static_cast<std::size_t>(k)];
    };
    const double lo = at(0.01), hi = at(0.99);
    return {lo, hi > lo ? hi : lo + 1.0};
}
} // namespace

std::vector<NamedHistogram> TunnelModel::histograms() const {
    pullState();
    NamedHistogram speed;
    speed.name = "speed";
    speed.label = "all molecules";
    speed.axis = "speed [m/s]";
    std::ostringstream summary;
    summary << "the whole domain: " << state_.size() << " molecules";
    if (!obstacles_.empty()) summary << " (free stream, shock layer and wake together)";
    speed.summary = summary.str();
    speed.counts = Histogram(0.0, 1.5 * colourMaxOf(params_), kHistogramBins);
    for (std::size_t i = 0; i < state_.size(); ++i)
        speed.counts.add(std::sqrt(state_.vx[i] * state_.vx[i] + state_.vy[i] * state_.vy[i] +
                                   state_.vz[i] * state_.vz[i]));
    // The reference is the free stream's: the speed of v ~ N(U e_x, σ² I₃), σ² = kT/m, is a noncentral
    // χ with three degrees of freedom, f(c) = c / (U σ √(2π)) [e^(−(c−U)²/2σ²) − e^(−(c+U)²/2σ²)], and
    // Maxwell's √(2/π) c² / σ³ e^(−c²/2σ²) at U = 0. Where the domain holds only free stream the two
    // agree; the shock layer and the wake show as the difference.
    const double sigma = std::sqrt(kBoltzmann * params_.streamTemperature / params_.mass());
    const double drift = std::abs(params_.streamSpeed);
    speed.theoryDensity = [sigma, drift](double c) {
        if (c <= 0.0) return 0.0;
        const double twoVariance = 2.0 * sigma * sigma;
        if (drift < 1e-9 * sigma)
            return std::sqrt(2.0 / std::numbers::pi) * c * c / (sigma * sigma * sigma) *
                   std::exp(-c * c / twoVariance);
        return c / (drift * sigma * std::sqrt(2.0 * std::numbers::pi)) *
               (std::exp(-(c - drift) * (c - drift) / twoVariance) -
                std::exp(-(c + drift) * (c + drift) / twoVariance));
    };
    return {speed};
}

void TunnelModel::writeParticles(std::ostream& out) const {
    pullState();
    const auto precision = out.precision(17);
    out << "id,x,y,vx,vy,vz\n";
    for (std::size_t i = 0; i < state_.size(); ++i)
        out << i << ',' << state_.x[i] << ',' << state_.y[i] << ',' << state_.vx[i] << ',' << state_.vy[i]
            << ',' << state_.vz[i] << '\n';
    out.precision(precision);
}

SceneView TunnelModel::sceneFrame() const {
    pullSamples(); // a field view shows the sums of every step so far
    SceneView view;
    view.left = 0.0;
    view.bottom = 0.0;
    view.right = params_.boxWidth;
    view.top = params_.boxHeight;
    view.colours = ColourMap::Thermal;
    view.colourLabel = "speed [m/s]";
    view.colourMax = colourMaxOf(params_);
    view.obstacles = obstacles_;
    if (params_.pistonOn) view.pistonX = pistonX_;
    if (params_.view != TunnelView::Particles) {
        const FieldGrid grid = sampler_.field(fieldOf(params_.view));
        SceneFieldImage image;
        image.nx = grid.nx;
        image.ny = grid.ny;
        image.left = grid.left;
        image.bottom = grid.bottom;
        image.right = grid.right;
        image.top = grid.top;
        image.label = grid.choice.label + (grid.choice.unit.empty() ? "" : " [" + grid.choice.unit + "]");
        const auto [lo, hi] = colourRange(grid.values);
        image.minimum = lo;
        image.maximum = hi;
        image.sampledSteps = sampler_.sampledSteps();
        image.window = sampler_.window();
        const double span = hi > lo ? hi - lo : 1.0;
        image.value.resize(grid.values.size());
        for (std::size_t c = 0; c < grid.values.size(); ++c)
            image.value[c] = std::isfinite(grid.values[c])
                                 ? static_cast<float>(std::clamp((grid.values[c] - lo) / span, 0.0, 1.0))
                                 : std::numeric_limits<float>::quiet_NaN();
        view.field = std::move(image);
        view.drawParticles = false;
        // An empty box would look broken: the window opens sample_start steps after a reset or an edit.
        if (sampler_.sampledSteps() == 0)
            view.hint = "Not sampled yet: the fields appear after the start-up steps";
    }
    return view;
}

SceneView TunnelModel::sceneView() const {
    SceneView view = sceneFrame();
    if (!view.drawParticles) return view;
    pullState();
    const std::size_t n = state_.size();
    view.x.resize(n);
    view.y.resize(n);
    view.radius.assign(n, 0.0f);
    view.value.resize(n);
    const double inverseMax = 1.0 / view.colourMax;
    for (std::size_t i = 0; i < n; ++i) {
        view.x[i] = static_cast<float>(state_.x[i]);
        view.y[i] = static_cast<float>(state_.y[i]);
        view.value[i] =
            static_cast<float>(std::sqrt(state_.vx[i] * state_.vx[i] + state_.vy[i] * state_.vy[i] +
                                         state_.vz[i] * state_.vz[i]) *
                               inverseMax);
    }
    return view;
}

} // namespace pl
