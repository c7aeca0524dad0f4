// DsmcModel: parameters, reset and the NTC step.
#include "DsmcModel.h"

#include "common/Philox.h"
#include "common/StopRequest.h"

#include <cmath>
#include <sstream>

namespace pl {

namespace {

// Bird's guideline: the time step a small fraction of the mean collision time, here ν Δt ≤ 0.25. Above
// it collisions within a step are too many for the method to be accurate away from one uniform cell.
constexpr double kGuidelineNuDt = 0.25;
// Refused above this: each particle would be picked as a candidate more than 5 times a step, the cost of
// a step grows as N ν Δt / 2 candidates (1e8 for the dsmc-bkw preset at dt = 3.33) and no result is
// worth it.
constexpr double kRefusedNuDt = 10.0;

// The preset's (σ c_r)_max is predicted from the raw draws of the sampled particles: the built state
// matches each population's moments, which moves every relative speed by O(1/√N) (0.3 % at 1e5
// particles). A preset is refused before building only beyond this margin, and only from this many
// particles on; the refusal after building keeps the exact bound for the rest (a smaller state builds
// in milliseconds).
constexpr double kPredictionMargin = 0.05;
constexpr long long kPredictFromParticles = 100000;

// The dt and the F_N that bring ν Δt from nuDt down to the guideline.
std::string whatToChange(const DsmcParams& p, double nuDt) {
    const double factor = kGuidelineNuDt / nuDt;
    return "use {dt} ≤ " + formatNumber(p.dt * factor, 3) + " s (now " + formatNumber(p.dt, 3) +
           ") or {fn} ≤ " + formatNumber(p.fn * factor, 3) + " (now " + formatNumber(p.fn, 3) + ")";
}

} // namespace

DsmcModel::DsmcModel() {
    reset();
}

void DsmcModel::refuseParams(const DsmcParams& next) const {
    if (const std::string why = nuDtRefusal(next); !why.empty()) throw ParamError("dt", why);
}

void DsmcModel::paramsChanged(const DsmcParams& /*before*/) {
    collisions_ = CollisionModel::fromParams(params_);
}

void DsmcModel::checkBuiltState() const {
    // ν Δt needs the built state's (σ c_r)_max; a refused preset leaves the model as it was.
    if (const std::string why = nuDtRefusal(params_); !why.empty())
        throw PresetError("params.dt", withKeys(why));
}

void DsmcModel::refuseBeforeBuilding(const DsmcParams& next, std::uint64_t seed) const {
    const long long n = next.totalCount();
    if (n < kPredictFromParticles) return;
    const double predicted =
        next.sigmaCrMaxInit > 0
            ? next.sigmaCrMaxInit
            : sampledSigmaCrMax(CollisionModel::fromParams(next), seed, static_cast<std::uint32_t>(n),
                                [&](std::uint32_t i) { return drawnInitialVelocity(next, seed, i); });
    const double margin = next.sigmaCrMaxInit > 0 ? 1.0 : 1.0 + kPredictionMargin;
    if (const std::string why = nuDtRefusal(next, static_cast<double>(n), predicted / margin); !why.empty())
        throw PresetError("params.dt", withKeys(nuDtRefusal(next, static_cast<double>(n), predicted)));
}

double DsmcModel::nuDtBound(const DsmcParams& p) const {
    const double n = static_cast<double>(state_.size());
    return (n - 1.0) * p.fn * sigmaCrMax_ * p.dt / p.cellVolume;
}

std::string DsmcModel::nuDtRefusal(const DsmcParams& p) const {
    return nuDtRefusal(p, static_cast<double>(state_.size()), sigmaCrMax_);
}

std::string DsmcModel::nuDtRefusal(const DsmcParams& p, double n, double sigmaCrMax) {
    const double nuDt = (n - 1.0) * p.fn * sigmaCrMax * p.dt / p.cellVolume;
    if (std::isfinite(nuDt) && nuDt <= kRefusedNuDt) return {};
    return "ν Δt = " + formatNumber(nuDt, 3) + " collisions per particle and step (" +
           formatNumber(0.5 * n * nuDt, 3) + " candidate pairs a step) is more than the " +
           formatNumber(kRefusedNuDt, 3) + " a step can do in reasonable time; " + whatToChange(p, nuDt) +
           " to keep it below Bird's " + "guideline of " + formatNumber(kGuidelineNuDt, 2);
}

std::string DsmcModel::accuracyWarning() const {
    const double nuDt = nuDtBound(params_);
    if (!(nuDt > kGuidelineNuDt)) return {};
    return withKeys("ν Δt is up to " + formatNumber(nuDt, 3) +
                    " collisions per particle and step, above Bird's guideline of " +
                    formatNumber(kGuidelineNuDt, 2) +
                    " (Δt a small fraction of the mean collision time), so the result may depend on Δt; " +
                    whatToChange(params_, nuDt));
}

void DsmcModel::reset() {
    collisions_ = CollisionModel::fromParams(params_);
    restartClock();
    remainder_ = 0.0;
    candidates_ = collisionsThisStep_ = collisionsTotal_ = 0;
    buildInitialState();
    if (params_.sigmaCrMaxInit > 0)
        sigmaCrMax_ = params_.sigmaCrMaxInit;
    else
        estimateSigmaCrMax();
}

double DsmcModel::numberDensity() const {
    return static_cast<double>(state_.size()) * params_.fn / params_.cellVolume;
}

template <class Velocity>
double DsmcModel::sampledSigmaCrMax(const CollisionModel& collisions, std::uint64_t seed, std::uint32_t n,
                                    Velocity sampleVelocity) {
    double largest = 0.0;
    constexpr std::uint32_t kSamplePairs = 4096;
    for (std::uint32_t k = 0; k < kSamplePairs && n >= 2; ++k) {
        const Philox4x32 w = randomWords(seed, RngPurpose::Collision, 0xffffffffu, k);
        const std::uint32_t i = dsmc::randomIndex(w[0], n);
        std::uint32_t j = dsmc::randomIndex(w[1], n - 1);
        if (j >= i) ++j;
        largest =
            std::max(largest, collisions.sigmaCr(dsmc::relativeSpeed(sampleVelocity(i), sampleVelocity(j))));
    }
    return largest;
}

void DsmcModel::estimateSigmaCrMax() {
    // Bird's practice: start from a generous guess and let the running maximum correct it. The guess is
    // the largest σ c_r among a sample of pairs of the initial state, so the first steps neither
    // over-collide (a guess too low accepts every pair) nor waste candidates.
    sigmaCrMax_ = sampledSigmaCrMax(collisions_, seed_, static_cast<std::uint32_t>(state_.size()),
                                    [this](std::uint32_t i) { return state_.velocity(i); });
    if (!(sigmaCrMax_ > 0))
        sigmaCrMax_ = collisions_.meanSigmaCr(std::max(params_.temperature, 1.0), params_.mass());
}

void DsmcModel::advance(double /*h*/) { // h = dt: collisions run forwards only
    const auto n = static_cast<std::uint32_t>(state_.size());
    const double dt = params_.dt;
    // NTC candidates (docs/dsmc.md#ntc-candidate-pairs, Bird 1994 eq. 11.3): ½ N (N − 1) F_N (σ c_r)_max Δt /
    // V_c, the fractional part carried to the next step so the long-run rate has no rounding bias.
    const double wanted =
        0.5 * n * (n - 1.0) * params_.fn * sigmaCrMax_ * dt / params_.cellVolume + remainder_;
    // (σ c_r)_max only grows during a run, and with it the candidates: a run accepted at its start can
    // outgrow what a step can do.
    if (const std::string why = nuDtRefusal(params_); !std::isfinite(wanted) || !why.empty()) {
        fail("the candidate count " + formatNumber(wanted, 3) + " is not finite or too large", withKeys(why));
        return;
    }
    candidates_ = static_cast<long long>(wanted);
    remainder_ = wanted - static_cast<double>(candidates_);
    collisionsThisStep_ = 0;
    const double m = params_.mass();
    const auto stream = static_cast<std::uint32_t>(stepCount());
    constexpr long long kPollEvery = 1 << 16; // candidates between looks at a stop request: ~1 ms
    for (long long c = 0; c < candidates_; ++c) {
        if (c % kPollEvery == 0) leaveIfAbandoning(); // a step of 67 M molecules takes many seconds
        const Philox4x32 w =
            randomWords(seed_, RngPurpose::Collision, stream, 2 * static_cast<std::uint64_t>(c));
        // A random distinct pair.
        const std::uint32_t i = dsmc::randomIndex(w[0], n);
        std::uint32_t j = dsmc::randomIndex(w[1], n - 1);
        if (j >= i) ++j;
        dsmc::Velocity a = state_.velocity(i), b = state_.velocity(j);
        const double sigmaCr = collisions_.sigmaCr(dsmc::relativeSpeed(a, b));
        // Bird raises (σ c_r)_max as soon as a pair exceeds it; that pair is then accepted.
        if (sigmaCr > sigmaCrMax_) sigmaCrMax_ = sigmaCr;
        if (unitOpen32(w[2]) * sigmaCrMax_ >= sigmaCr) continue;
        const Philox4x32 angles =
            randomWords(seed_, RngPurpose::Collision, stream, 2 * static_cast<std::uint64_t>(c) + 1);
        if (params_.planar())
            dsmc::scatterInPlane(a, b, m, m, unitOpen(angles[0], angles[1]));
        else
            dsmc::scatterIsotropic(a, b, m, m, unitOpen(angles[0], angles[1]),
                                   unitOpen(angles[2], angles[3]));
        state_.setVelocity(i, a);
        state_.setVelocity(j, b);
        ++collisionsThisStep_;
    }
    collisionsTotal_ += collisionsThisStep_;
}

void DsmcModel::writeParticles(std::ostream& out) const {
    const auto precision = out.precision(17);
    out << "id,origin,vx,vy,vz\n";
    for (std::size_t i = 0; i < state_.size(); ++i)
        out << i << ',' << int(state_.origin[i]) << ',' << state_.vx[i] << ',' << state_.vy[i] << ','
            << state_.vz[i] << '\n';
    out.precision(precision);
}

SceneView DsmcModel::sceneView() const {
    // A 0D cell has no positions worth drawing: the particles are points in velocity space (v_x, v_y).
    SceneView view;
    const double half = params_.histogramSpeedMax;
    view.left = view.bottom = -half;
    view.right = view.top = half;
    view.xLabel = "v_x [m/s]";
    view.yLabel = "v_y [m/s]";
    view.colours = ColourMap::Category;
    view.colourLabel = "population";
    if (params_.initial == DsmcInitialState::TwoBeams) {
        std::ostringstream one, two;
        one << "beam 1 (" << params_.driftA << " m/s)";
        two << "beam 2 (" << params_.driftB << " m/s)";
        view.categories = {one.str(), two.str()};
    } else {
        view.categories = {params_.initial == DsmcInitialState::Bkw ? "BKW gas" : "Maxwellian gas"};
    }
    const std::size_t n = state_.size();
    view.x.resize(n);
    view.y.resize(n);
    view.radius.assign(n, 0.0f);
    view.value.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        view.x[i] = static_cast<float>(state_.vx[i]);
        view.y[i] = static_cast<float>(state_.vy[i]);
        view.value[i] = state_.origin[i];
    }
    return view;
}

} // namespace pl
