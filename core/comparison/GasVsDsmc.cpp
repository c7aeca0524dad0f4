// The two relaxations of the methods lab's MD-vs-DSMC comparison, each through its model's own code.
#include "GasVsDsmc.h"

#include "common/Philox.h"
#include "common/Statistics.h"
#include "common/sweep/CellOutcome.h"
#include "dsmc/DsmcModel.h"
#include "gas/GasModel.h"

#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>

namespace pl::methods {

namespace {

// The DSMC cell behind both starts: O2 beams at ±100 m/s, hard-sphere collisions in the plane.
constexpr double kBeamSpeed = 100.0; // [m/s]
constexpr double kFn = 1e10, kCellVolume = 1e-8;

ParamValues dsmcParams(const TwoBeamSetup& setup) {
    if (setup.particles < 4) throw std::invalid_argument("the comparison needs at least 4 particles");
    DsmcParams defaults;
    const double temperature = setup.beamKT * defaults.mass() * kBeamSpeed * kBeamSpeed / kBoltzmann;
    return {{"velocity_components", 2.0},
            {"initial", "two-beams"},
            {"count_a", static_cast<double>(setup.particles / 2)},
            {"count_b", static_cast<double>(setup.particles - setup.particles / 2)},
            {"drift_a", -kBeamSpeed},
            {"drift_b", kBeamSpeed},
            {"temperature", temperature},
            {"cross_section", "hard-sphere"},
            {"fn", kFn},
            {"cell_volume", kCellVolume},
            {"run_steps", 0.0},
            {"histogram_speed_max", 3.0 * kBeamSpeed}};
}

std::unique_ptr<DsmcModel> twoBeamCell(const TwoBeamSetup& setup) {
    auto model = std::make_unique<DsmcModel>();
    Preset preset;
    preset.model = "dsmc";
    preset.seed = setup.seed;
    preset.params = dsmcParams(setup);
    model->reset(preset);
    return model;
}

} // namespace

std::vector<std::pair<double, double>> twoBeamVelocities(const TwoBeamSetup& setup) {
    const auto cell = twoBeamCell(setup);
    const DsmcState& s = cell->state();
    std::vector<std::pair<double, double>> v(s.size());
    for (std::size_t i = 0; i < s.size(); ++i) v[i] = {s.vx[i] / kBeamSpeed, s.vy[i] / kBeamSpeed};
    return v;
}

RelaxationRun relaxWithDsmc(const TwoBeamSetup& setup,
                            const std::function<void(const RelaxationSample&)>& onSample,
                            const std::atomic<bool>* stop) {
    auto cell = twoBeamCell(setup);
    // ν = n σ ⟨c_r⟩ per particle; two beams at ±u have ⟨c_r⟩ ≈ u (half the pairs at 2u, half near 0).
    const double n = static_cast<double>(setup.particles) * kFn / kCellVolume;
    const double nu = n * cell->collisionModel().sigmaCr(kBeamSpeed);
    ParamValues dt{{"dt", setup.dsmcCollisionsPerStep / nu}};
    cell->setParams(dt);
    RelaxationRun run;
    run.method = "dsmc";
    const auto emit = [&](const DsmcObservables& o) {
        RelaxationSample sample{o.collisionsPerParticle, o.kurtosisVx, run.seconds};
        run.curve.push_back(sample);
        if (onSample) onSample(sample);
    };
    emit(cell->observe());
    while (run.curve.back().collisionsPerParticle < setup.collisionsPerParticle && !(stop && *stop)) {
        run.seconds += secondsOf([&] { cell->step(); });
        ++run.steps;
        if (cell->failure()) throw std::runtime_error("DSMC: " + cell->failure()->message());
        emit(cell->observe());
    }
    run.particleSteps = run.steps * setup.particles;
    for (double vx : cell->state().vx) run.finalVx.push_back(vx / kBeamSpeed);
    return run;
}

RelaxationRun relaxWithMd(const TwoBeamSetup& setup,
                          const std::function<void(const RelaxationSample&)>& onSample,
                          const std::atomic<bool>* stop) {
    const auto velocities = twoBeamVelocities(setup);
    const auto count = static_cast<double>(velocities.size());
    // A unit box at the requested area fraction N π d²/4 = φ.
    const double diameter = std::sqrt(4.0 * setup.areaFraction / (count * std::numbers::pi));
    // The fastest head-on pair (2u plus 4σ of both beams' spread) reaches depth c_r/ω; ω = √(2k/m), m = 1.
    const double fastest = 2.0 + 4.0 * std::sqrt(2.0 * setup.beamKT);
    const double omega = fastest / (setup.depthOverDiameter * diameter);
    const double stiffness = 0.5 * omega * omega;
    GasModel model;
    model.setParams({{"count_a", count},
                     {"mass_a", 1.0},
                     {"diameter_a", diameter},
                     {"stiffness", stiffness},
                     {"dt", setup.omegaDt / omega},
                     {"integrator", gasIntegrator(GasIntegrator::VelocityVerlet).name},
                     {"box_width", 1.0},
                     {"box_height", 1.0},
                     {"max_particles", count}});
    // Uniform positions without overlaps (rejection), from the seed.
    std::vector<GasParticle> particles;
    const double room = 0.5 - 0.5 * diameter;
    std::uint64_t draw = 0;
    for (const auto& [vx, vy] : velocities) {
        for (;;) {
            if (draw > 1000 * velocities.size())
                throw std::invalid_argument("the disks do not fit at this area fraction");
            const auto [u1, u2] =
                uniformPair(randomWords(setup.seed, RngPurpose::InitialPosition, 0, draw++));
            const double x = (2 * u1 - 1) * room, y = (2 * u2 - 1) * room;
            bool free = true;
            for (const auto& p : particles)
                if ((p.x - x) * (p.x - x) + (p.y - y) * (p.y - y) < diameter * diameter) {
                    free = false;
                    break;
                }
            if (!free) continue;
            particles.push_back({x, y, vx, vy, 0});
            break;
        }
    }
    model.placeParticles(particles);
    model.observe(); // opens the contact window
    RelaxationRun run;
    run.method = "md";
    double collisions = 0;
    const auto sample = [&] {
        std::vector<double> vx(model.state().vx.begin(), model.state().vx.end());
        RelaxationSample s{collisions, kurtosis(vx), run.seconds};
        run.curve.push_back(s);
        if (onSample) onSample(s);
    };
    sample();
    // Samples about every 1/20 of a collision time: from the mean free path 1/(√2 n d) at speed ~1.
    const double freeTime = 1.0 / (std::sqrt(2.0) * count * diameter);
    const auto chunk = std::max<long long>(1, std::llround(0.05 * freeTime * omega / setup.omegaDt));
    while (collisions < setup.collisionsPerParticle && !(stop && *stop)) {
        run.seconds += secondsOf([&] {
            for (long long s = 0; s < chunk; ++s) model.step();
        });
        run.steps += chunk;
        if (model.failure()) throw std::runtime_error("MD: " + model.failure()->message());
        const GasObservables o = model.observe(); // its rate counts contacts since the last observe()
        collisions += 2.0 * o.collisionRate * chunk * model.parameters().dt / count; // two disks each
        sample();
    }
    run.particleSteps = run.steps * static_cast<long long>(count);
    run.finalVx.assign(model.state().vx.begin(), model.state().vx.end());
    return run;
}

GasVsDsmcResult compareRelaxations(RelaxationRun md, RelaxationRun dsmc) {
    GasVsDsmcResult r;
    std::vector<double> a = md.finalVx, b = dsmc.finalVx;
    r.ksDistance = ksTwoSampleDistance(a, b);
    r.ksPValue =
        ksTwoSamplePValue(r.ksDistance, static_cast<double>(a.size()), static_cast<double>(b.size()));
    r.costRatio = dsmc.seconds > 0 ? md.seconds / dsmc.seconds : std::nan("");
    r.md = std::move(md);
    r.dsmc = std::move(dsmc);
    return r;
}

} // namespace pl::methods
