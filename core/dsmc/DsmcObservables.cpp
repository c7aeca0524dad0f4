// Observables of the cell: temperatures about the mean velocity, kurtosis, normalised moments with the
// exact BKW curves, the KL divergence to Maxwell–Boltzmann, the NTC counters, and the histograms.
#include "DsmcModel.h"
#include "DsmcSeries.h"
#include "DsmcTheory.h"
#include "common/Statistics.h"

#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

namespace pl {

namespace {
const double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr int kKlBins = 40;
constexpr double kKlRangeSigmas = 5.0; // peculiar speeds up to 5 √(kT/m): all but ~1e-5 of them
} // namespace

DsmcObservables DsmcModel::observe() const {
    DsmcObservables o;
    o.step = stepCount();
    o.time = time();
    o.particles = state_.size();
    const std::size_t n = state_.size();
    if (n == 0) return o;
    const double inv = 1.0 / static_cast<double>(n);
    for (std::size_t i = 0; i < n; ++i) {
        o.ux += state_.vx[i];
        o.uy += state_.vy[i];
        o.uz += state_.vz[i];
    }
    o.ux *= inv;
    o.uy *= inv;
    o.uz *= inv;
    double sx = 0, sy = 0, sz = 0, x4 = 0, c4 = 0, c6 = 0, c8 = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const double dx = state_.vx[i] - o.ux, dy = state_.vy[i] - o.uy, dz = state_.vz[i] - o.uz;
        const double dx2 = dx * dx, c2 = dx2 + dy * dy + dz * dz;
        sx += dx2;
        sy += dy * dy;
        sz += dz * dz;
        x4 += dx2 * dx2;
        c4 += c2 * c2;
        c6 += c2 * c2 * c2;
        c8 += c2 * c2 * c2 * c2;
    }
    const double m = params_.mass();
    o.tx = m * sx * inv / kBoltzmann;
    o.ty = m * sy * inv / kBoltzmann;
    o.tz = m * sz * inv / kBoltzmann;
    const bool planar = params_.planar();
    o.t = planar ? 0.5 * (o.tx + o.ty) : (o.tx + o.ty + o.tz) / 3.0;
    o.tPerp = planar ? o.ty : 0.5 * (o.ty + o.tz);
    o.kurtosisVx = sx > 0 ? x4 * inv / ((sx * inv) * (sx * inv)) : kNaN;
    // Equilibrium moments at the sampled energy, kT/m = ⟨c²⟩/D: ⟨c^2k⟩_eq = (2k+1)!! (kT/m)^k in 3D and
    // k! (2 kT/m)^k in the plane (the speed² is then exponential).
    const double s2 = (sx + sy + sz) * inv / static_cast<double>(params_.velocityComponents);
    const double eq4 = planar ? 8.0 : 15.0, eq6 = planar ? 48.0 : 105.0, eq8 = planar ? 384.0 : 945.0;
    o.m4 = s2 > 0 ? c4 * inv / (eq4 * s2 * s2) : kNaN;
    o.m6 = s2 > 0 ? c6 * inv / (eq6 * s2 * s2 * s2) : kNaN;
    o.m8 = s2 > 0 ? c8 * inv / (eq8 * s2 * s2 * s2 * s2) : kNaN;
    if (!planar && params_.initial == DsmcInitialState::Bkw &&
        collisions_.kind == CollisionModel::Kind::Maxwell) {
        // Time in mean collision times: ν = n σ c_r, the same at every temperature for Maxwell molecules.
        const double K = dsmc::bkwK(numberDensity() * collisions_.prefactor * time());
        o.m4Bkw = dsmc::bkwMomentRatio(2, K);
        o.m6Bkw = dsmc::bkwMomentRatio(3, K);
        o.m8Bkw = dsmc::bkwMomentRatio(4, K);
    } else {
        o.m4Bkw = o.m6Bkw = o.m8Bkw = kNaN;
    }
    // KL divergence Σ p ln(p/q) of the binned peculiar speeds from Maxwell–Boltzmann at the same T.
    if (s2 > 0) {
        const double width = kKlRangeSigmas * std::sqrt(s2) / kKlBins;
        const double inverseWidth = 1.0 / width;
        std::vector<double> counts(kKlBins, 0.0);
        for (std::size_t i = 0; i < n; ++i) {
            const double dx = state_.vx[i] - o.ux, dy = state_.vy[i] - o.uy, dz = state_.vz[i] - o.uz;
            const auto b = static_cast<std::size_t>(std::sqrt(dx * dx + dy * dy + dz * dz) * inverseWidth);
            if (b < counts.size()) counts[b] += 1.0;
        }
        for (int b = 0; b < kKlBins; ++b) {
            if (counts[b] == 0) continue;
            const double p = counts[b] * inv;
            const auto cdf = [planar, s2](double c) {
                return planar ? rayleighCdf(c, s2, 1.0) : maxwellSpeedCdf(c, s2);
            };
            const double q = cdf((b + 1) * width) - cdf(b * width);
            o.klDivergence += p * std::log(p / std::max(q, 1e-300));
        }
    }
    o.collisionsPerParticle = 2.0 * static_cast<double>(collisionsTotal_) * inv;
    return o;
}

const SeriesTable<DsmcSeriesRow>& dsmcSeriesTable() {
    using R = DsmcSeriesRow;
    static const SeriesTable<R> table{
        {{"step", "", "step"}, [](const R& r) { return static_cast<double>(r.observed.step); }},
        {{"time", "s", "time"}, [](const R& r) { return r.observed.time; }},
        {{"particles", "", "simulators"},
         [](const R& r) { return static_cast<double>(r.observed.particles); }},
        {{"Tx", "K", "T_x"}, [](const R& r) { return r.observed.tx; }},
        {{"Ty", "K", "T_y"}, [](const R& r) { return r.observed.ty; }},
        {{"Tz", "K", "T_z"}, [](const R& r) { return r.observed.tz; }},
        {{"T", "K", "temperature"}, [](const R& r) { return r.observed.t; }},
        {{"T_perp", "K", "T_⊥"}, [](const R& r) { return r.observed.tPerp; }},
        {{"anisotropy", "K", "T_x − T_⊥"}, [](const R& r) { return r.observed.tx - r.observed.tPerp; }},
        {{"ux", "m/s", "mean velocity x"}, [](const R& r) { return r.observed.ux; }},
        {{"uy", "m/s", "mean velocity y"}, [](const R& r) { return r.observed.uy; }},
        {{"uz", "m/s", "mean velocity z"}, [](const R& r) { return r.observed.uz; }},
        {{"kurtosis_vx", "", "kurtosis of v_x (3 for a Maxwellian)"},
         [](const R& r) { return r.observed.kurtosisVx; }},
        {{"ng", "", "candidate pairs ng"}, [](const R& r) { return static_cast<double>(r.candidates); }},
        {{"nc", "", "collisions nc"}, [](const R& r) { return static_cast<double>(r.collisions); }},
        {{"sigma_cr_max", "m³/s", "(σ c_r)_max"}, [](const R& r) { return r.sigmaCrMax; }},
        {{"M4", "", "M4 / M4(eq)"}, [](const R& r) { return r.observed.m4; }},
        {{"M6", "", "M6 / M6(eq)"}, [](const R& r) { return r.observed.m6; }},
        {{"M8", "", "M8 / M8(eq)"}, [](const R& r) { return r.observed.m8; }},
        {{"M4_bkw", "", "M4 exact (BKW)"}, [](const R& r) { return r.observed.m4Bkw; }},
        {{"M6_bkw", "", "M6 exact (BKW)"}, [](const R& r) { return r.observed.m6Bkw; }},
        {{"M8_bkw", "", "M8 exact (BKW)"}, [](const R& r) { return r.observed.m8Bkw; }},
        {{"kl_divergence", "nats", "KL divergence to Maxwell–Boltzmann"},
         [](const R& r) { return r.observed.klDivergence; }},
        {{"collisions_per_particle", "", "collisions per simulator"},
         [](const R& r) { return r.observed.collisionsPerParticle; }},
    };
    return table;
}

std::vector<std::string> DsmcModel::seriesColumns() const {
    return dsmcSeriesTable().names();
}

std::vector<double> DsmcModel::sampleSeries() {
    return dsmcSeriesTable().sample({observe(), candidates_, collisionsThisStep_, sigmaCrMax_});
}

std::vector<NamedHistogram> DsmcModel::histograms() const {
    const DsmcObservables o = observe();
    const double sigma2 = kBoltzmann * o.t / params_.mass();
    const double drift = std::sqrt(o.ux * o.ux + o.uy * o.uy + o.uz * o.uz);
    const double vmax = params_.histogramSpeedMax;
    const auto bins = static_cast<std::size_t>(params_.histogramBins);
    std::ostringstream summary;
    summary.precision(4);
    summary << "T = " << o.t << " K, u_x = " << o.ux << " m/s, " << o.collisionsPerParticle
            << " collisions each";

    NamedHistogram speed;
    speed.name = "speed";
    speed.label = "all particles";
    speed.axis = "speed [m/s]";
    speed.summary = summary.str();
    speed.counts = Histogram(0.0, vmax, bins);
    NamedHistogram vx;
    vx.name = "vx";
    vx.label = "all particles";
    vx.axis = "v_x [m/s]";
    vx.summary = speed.summary;
    vx.counts = Histogram(-vmax, vmax, 2 * bins);
    for (std::size_t i = 0; i < state_.size(); ++i) {
        speed.counts.add(std::sqrt(state_.vx[i] * state_.vx[i] + state_.vy[i] * state_.vy[i] +
                                   state_.vz[i] * state_.vz[i]));
        vx.counts.add(state_.vx[i]);
    }
    // The overlay is the Maxwellian the cell relaxes to: same T, same mean velocity.
    if (params_.planar()) // in the plane: (v/σ²) exp(−(v − u)²/2σ²) e^(−vu/σ²) I₀(vu/σ²), overflow-free
        speed.theoryDensity = [sigma2, drift](double v) {
            const double z = v * drift / sigma2;
            // e^(−z) I₀(z) → 1/√(2πz) for large z (Abramowitz & Stegun 9.7.1), where I₀ overflows
            const double scaledI0 = z < 500 ? std::exp(-z) * std::cyl_bessel_i(0.0, z)
                                            : 1.0 / std::sqrt(2 * std::numbers::pi * z);
            return v / sigma2 * std::exp(-(v - drift) * (v - drift) / (2 * sigma2)) * scaledI0;
        };
    else
        speed.theoryDensity = [sigma2, drift](double v) { return maxwellSpeedPdf(v, sigma2, drift); };
    const double ux = o.ux;
    vx.theoryDensity = [sigma2, ux](double v) {
        return std::exp(-(v - ux) * (v - ux) / (2 * sigma2)) / std::sqrt(2 * std::numbers::pi * sigma2);
    };
    return {speed, vx};
}

} // namespace pl
