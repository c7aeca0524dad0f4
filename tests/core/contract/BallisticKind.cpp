// The ballistic test kind: its parameter table, state table, physics, series and registration.
#include "BallisticKind.h"

#include "common/MemoryBudget.h"
#include "common/Philox.h"
#include "common/StopRequest.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <ostream>

namespace pl::test {

namespace {
constexpr double kMaxPoints = 1e5;
// Spawned points start at rest; rows of this many fill a rectangle.
constexpr long long kSpawnedPerRectangle = 16;

// One sample of the series.
struct BallisticRow {
    double time, energy;
    long long count;
};

const SeriesTable<BallisticRow>& ballisticSeries() {
    static const SeriesTable<BallisticRow> table{
        {{"time", "T", "time"}, [](const BallisticRow& r) { return r.time; }},
        {{"energy", "L²/T²", "energy per unit mass"}, [](const BallisticRow& r) { return r.energy; }},
        {{"count", "", "points"}, [](const BallisticRow& r) { return static_cast<double>(r.count); }},
    };
    return table;
}
} // namespace

const std::vector<ParamField<BallisticParams>>& BallisticParams::fields() {
    using P = BallisticParams;
    static const std::vector<ParamField<P>> list = [] {
        const P d;
        std::vector<ParamField<P>> f;
        f.push_back(bindInteger(&P::count, makeSpec("count", "Points", "", "Box", "Points in the box.", 1,
                                                    kMaxPoints, 10, double(d.count))));
        f.push_back(bindReal(&P::boxWidth, makeSpec("box_width", "Box width", "L", "Box", "Width of the box.",
                                                    0.1, 100, 0.1, d.boxWidth)));
        f.push_back(bindReal(&P::boxHeight, makeSpec("box_height", "Box height", "L", "Box",
                                                     "Height of the box.", 0.1, 100, 0.1, d.boxHeight)));
        f.push_back(bindReal(&P::gravity, makeSpec("gravity", "Gravity", "L/T²", "Motion",
                                                   "Downward acceleration.", 0, 100, 0.1, d.gravity, true)));
        f.push_back(bindReal(&P::speed, makeSpec("speed", "Initial speed", "L/T", "Motion",
                                                 "Every point's speed at the start.", 0, 100, 0.1, d.speed)));
        f.push_back(bindReal(&P::toolSpeed,
                             makeSpec("tool_speed", "Drag speed limit", "L/T", "Motion",
                                      "Fastest a dragged body moves.", 1e-3, 100, 0.1, d.toolSpeed, true)));
        f.push_back(bindReal(&P::dt, makeSpec("dt", "Time step", "T", "Motion", "Integration step.", 1e-6,
                                              0.1, 1e-4, d.dt, true)));
        return f;
    }();
    return list;
}

MemoryNeed BallisticParams::memoryNeed() const {
    constexpr double kBytesPerPoint = 4 * sizeof(double); // x, y, vx, vy
    return {static_cast<double>(count) * kBytesPerPoint, "count", [](double fitting) {
                return "use {count} ≤ " + std::to_string(static_cast<long long>(fitting / kBytesPerPoint));
            }};
}

const std::vector<ParamSpec>& BallisticParams::describe() {
    static const std::vector<ParamSpec> list = specsOf(fields());
    return list;
}

const StateTable<BallisticModel, BallisticState>& BallisticModel::stateTable() {
    static const StateTable<BallisticModel, BallisticState> table = [] {
        StateTable<BallisticModel, BallisticState> t;
        t.scalar("spawned", &BallisticModel::spawned_);
        t.perParticle("x", &BallisticState::x)
            .perParticle("y", &BallisticState::y)
            .perParticle("vx", &BallisticState::vx)
            .perParticle("vy", &BallisticState::vy);
        return t;
    }();
    return table;
}

void BallisticModel::reset() {
    restartClock();
    restBodies();
    spawned_ = 0;
    const auto n = static_cast<std::size_t>(params_.count);
    state_ = BallisticState{};
    // A square lattice inside the box, each point moving in a random direction.
    const auto side = static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(n))));
    const Area a = toolArea();
    for (std::size_t i = 0; i < n; ++i) {
        const double fx = (static_cast<double>(i % side) + 0.5) / static_cast<double>(side);
        const double fy = (static_cast<double>(i / side) + 0.5) / static_cast<double>(side);
        const Philox4x32 w =
            randomWords(seed_, RngPurpose::InitialVelocity, static_cast<std::uint32_t>(i), 0);
        const double angle = 2.0 * std::numbers::pi * unitOpen(w[0], w[1]);
        state_.x.push_back(a.left + fx * (a.right - a.left));
        state_.y.push_back(a.bottom + fy * (a.top - a.bottom));
        state_.vx.push_back(params_.speed * std::cos(angle));
        state_.vy.push_back(params_.speed * std::sin(angle));
    }
    stateEdited();
}

void BallisticModel::advance(double h) {
    leaveIfAbandoning(); // a stop request ends the step before it changed anything (common/StopRequest.h)
    advanceObstacles(h);
    const double kick = -0.5 * params_.gravity * h; // half a step of gravity on v_y
    const Area a = toolArea();
    const auto mirror = [](double& x, double& v, double low, double high) {
        if (x < low) x = 2 * low - x, v = -v;
        if (x > high) x = 2 * high - x, v = -v;
    };
    for (std::size_t i = 0; i < state_.size(); ++i) {
        state_.vy[i] += kick;
        state_.x[i] += h * state_.vx[i];
        state_.y[i] += h * state_.vy[i];
        mirror(state_.x[i], state_.vx[i], a.left, a.right);
        mirror(state_.y[i], state_.vy[i], a.bottom, a.top);
        state_.vy[i] += kick;
    }
}

double BallisticModel::energy() const {
    double e = 0.0;
    for (std::size_t i = 0; i < state_.size(); ++i)
        e +=
            0.5 * (state_.vx[i] * state_.vx[i] + state_.vy[i] * state_.vy[i]) + params_.gravity * state_.y[i];
    return e;
}

StateRecord BallisticModel::saveState() const {
    StateRecord r;
    saveClock(r);
    stateTable().save(*this, state_, r);
    return r;
}

void BallisticModel::restoreState(const StateRecord& r) {
    const std::size_t n = stateTable().particlesIn(r);
    if (static_cast<double>(n) > kMaxPoints)
        throw PresetError("state.x", "the snapshot holds more than " + formatNumber(kMaxPoints) + " points");
    BallisticState s = stateTable().read(*this, r, n);
    restoreClock(r);
    stateTable().restore(*this, r);
    state_ = std::move(s);
    obstacleDrive_.clear();
    stateEdited();
}

std::vector<std::string> BallisticModel::seriesColumns() const {
    return ballisticSeries().names();
}

std::vector<double> BallisticModel::sampleSeries() {
    return ballisticSeries().sample({time(), energy(), static_cast<long long>(state_.size())});
}

std::vector<NamedHistogram> BallisticModel::histograms() const {
    constexpr std::size_t kBins = 20;
    double fastest = 0.0;
    std::vector<double> speeds(state_.size());
    for (std::size_t i = 0; i < state_.size(); ++i) {
        speeds[i] = std::hypot(state_.vx[i], state_.vy[i]);
        fastest = std::max(fastest, speeds[i]);
    }
    NamedHistogram h{
        "speed", "points", "speed [L/T]", "", Histogram(0.0, fastest > 0 ? 1.05 * fastest : 1.0, kBins), {}};
    for (const double s : speeds) h.counts.add(s);
    return {h};
}

// The report's row: with elastic walls and no friction the energy stays what it was; velocity Verlet is
// exact under constant gravity between the walls, and a wall's mirror mid-step errs by O(h²) at most.
std::vector<TheoryRow> ballisticTheoryRows(const Model& /*model*/, const TimeSeries& series) {
    constexpr double kConserved = 1e-3; // relative
    const SeriesColumns columns(series);
    const double start = columns.first("energy"), end = columns.last("energy");
    if (!std::isfinite(start) || !std::isfinite(end) || start == 0) return {};
    const double drift = (end - start) / std::abs(start);
    const bool conserved = std::abs(drift) <= kConserved;
    return {
        {"Energy at the end against its start", theoryNumber(end), "L²/T²",
         "at the start " + theoryNumber(start) + "; drift " + theoryPercent(drift) + ": " +
             (conserved ? "conserved, as elastic walls keep it" : "not conserved: the time step is too long"),
         conserved}};
}

void BallisticModel::writeParticles(std::ostream& out) const {
    const auto precision = out.precision(17);
    out << "id,x,y,vx,vy\n";
    for (std::size_t i = 0; i < state_.size(); ++i)
        out << i << ',' << state_.x[i] << ',' << state_.y[i] << ',' << state_.vx[i] << ',' << state_.vy[i]
            << '\n';
    out.precision(precision);
}

SceneView BallisticModel::sceneView() const {
    SceneView view;
    const Area a = toolArea();
    view.left = a.left, view.bottom = a.bottom, view.right = a.right, view.top = a.top;
    view.obstacles = obstacles_;
    for (std::size_t i = 0; i < state_.size(); ++i) {
        view.x.push_back(static_cast<float>(state_.x[i]));
        view.y.push_back(static_cast<float>(state_.y[i]));
        view.radius.push_back(0.0f); // a point of a few pixels
        view.value.push_back(static_cast<float>(std::hypot(state_.vx[i], state_.vy[i])));
    }
    view.colourLabel = "speed";
    view.colourMax = std::max(params_.speed, 1e-9);
    return view;
}

std::string BallisticModel::spawnInRectangle(double x0, double y0, double x1, double y1) {
    clampIntoArea(x0, y0);
    clampIntoArea(x1, y1);
    if (static_cast<double>(state_.size() + kSpawnedPerRectangle) > kMaxPoints)
        return "added no points: the box holds " + formatNumber(kMaxPoints) + " at most";
    for (long long k = 0; k < kSpawnedPerRectangle; ++k) {
        const double f = (static_cast<double>(k) + 0.5) / static_cast<double>(kSpawnedPerRectangle);
        state_.x.push_back(x0 + f * (x1 - x0));
        state_.y.push_back(y0 + f * (y1 - y0));
        state_.vx.push_back(0.0);
        state_.vy.push_back(0.0);
    }
    ++spawned_;
    stateEdited();
    return "added " + std::to_string(kSpawnedPerRectangle) + " points at rest";
}

const ModelDescriptor& ballisticRegistration() {
    static const ModelDescriptor descriptor{
        .kind = "ballistic",
        .title = "Ballistic points (test kind)",
        .units = {"reduced (L, T)", "length L, time T, unit mass; energies per unit mass in L²/T²", "T"},
        .specs = &BallisticParams::describe(),
        .create = []() -> std::unique_ptr<Model> { return std::make_unique<BallisticModel>(); },
        .particleCount =
            [](const Preset& preset) {
                const BallisticParams p =
                    withValues(BallisticParams{}, BallisticParams::fields(), preset.params);
                return static_cast<std::size_t>(p.count);
            },
        .series = ballisticSeries().columns(),
        .plots = {{"ballisticEnergyPlot",
                   "Energy",
                   {"energy [L²/T²]", {{"energy", "kinetic + potential", plot_colours::kBlue}}},
                   {}}},
        .distributions = {"speedHistogram"},
        .watchableRate = 1.0,
        .present = {},        // nothing of its own: present mode builds the board from what the kind offers
        .contractPreset = {}, // no built-in presets: the contract starts from the defaults
        .stateArrays = {.x = "x", .y = "y"},
        .theoryRows = ballisticTheoryRows,
    };
    return descriptor;
}

} // namespace pl::test
