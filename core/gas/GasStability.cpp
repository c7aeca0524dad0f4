// Blow-up detection and the hints that explain it (stability limits from the integrator table).
#include "GasKernels.h"
#include "GasModel.h"

#include <cmath>
#include <sstream>
#include <utility>

namespace pl {

namespace {

std::string fixed(double v, int digits) {
    std::ostringstream out;
    out.setf(std::ios::fixed);
    out.precision(digits);
    out << v;
    return out.str();
}

// The decimals a hint shows at most: a dt·ω that agrees with a limit to these is said to be at it.
constexpr int kHintDecimals = 4;
// The share of a stability limit a hint at the limit recommends.
constexpr double kSafeShareOfLimit = 0.9;

// a and b with the fewest decimals (2 to kHintDecimals) that tell them apart, so a value just inside a
// limit never reads as the limit itself (RK4's 2.8279 against 2√2 = 2.8284); equal strings when they
// agree to kHintDecimals decimals.
std::pair<std::string, std::string> distinct(double a, double b) {
    int digits = 2;
    while (digits < kHintDecimals && fixed(a, digits) == fixed(b, digits)) ++digits;
    return {fixed(a, digits), fixed(b, digits)};
}

} // namespace

double GasModel::totalEnergy() {
    refreshEnergies();
    double kinetic = 0.0, potential = 0.0;
    const double mass[2] = {params_.a.mass, params_.b.mass};
    for (std::size_t i = 0; i < state_.size(); ++i) {
        const double m = mass[state_.species[i]];
        kinetic += 0.5 * m * (state_.vx[i] * state_.vx[i] + state_.vy[i] * state_.vy[i]);
        potential += state_.potential[i] + m * params_.appliedGravity() * (state_.y[i] - params_.bottom());
    }
    return kinetic + potential;
}

void GasModel::rebaseEnergy() {
    const double e = totalEnergy();
    energyBaseline_ = e;
    referenceEnergy_ = std::max(referenceEnergy_, e);
}

double GasModel::stiffestContactOmega() const {
    double omega = 0.0; // the smallest reduced mass present
    const bool hasA = params_.a.count > 0, hasB = params_.b.count > 0;
    if (hasA || !hasB)
        omega = std::max(omega, gas::contactOmega(params_.stiffness, params_.a.mass, params_.a.mass));
    if (hasB) omega = std::max(omega, gas::contactOmega(params_.stiffness, params_.b.mass, params_.b.mass));
    if (hasA && hasB)
        omega = std::max(omega, gas::contactOmega(params_.stiffness, params_.a.mass, params_.b.mass));
    return omega;
}

std::string GasModel::stabilityRefusal() const {
    const GasIntegratorInfo& scheme = gasIntegrator(integrator_);
    const double limit = scheme.stabilityLimit;
    // Explicit Euler has no stable dt at all: it is there to show its energy growing, slowly at small dt.
    if (!(limit > 0)) return {};
    const double wdt = stiffestContactOmega() * std::abs(params_.dt);
    const auto [shownWdt, shownLimit] = distinct(wdt, limit);
    if (!(wdt > limit) || shownWdt == shownLimit) return {}; // at the limit, as shown: the hint's case
    // ω ∝ √k, so dt·ω falls to the limit at dt × limit / (dt·ω) or at k × (limit / (dt·ω))².
    const double share = kSafeShareOfLimit * limit / wdt;
    return "dt·ω = " + shownWdt + " > " + shownLimit + ": " + scheme.name +
           " is unstable at these settings (a contact gains energy at every step); use dt ≤ " +
           formatNumber(share * std::abs(params_.dt), 3) + " or stiffness ≤ " +
           formatNumber(share * share * params_.stiffness, 3) + " (" +
           formatNumber(100 * kSafeShareOfLimit, 2) + " % of the limit)";
}

std::string GasModel::stabilityHint() const {
    const double omega = stiffestContactOmega();
    const double wdt = omega * std::abs(params_.dt);
    const GasIntegratorInfo& scheme = gasIntegrator(integrator_);
    const double limit = scheme.stabilityLimit;
    const std::string& name = scheme.name;
    if (integrator_ == GasIntegrator::ExplicitEuler)
        return "explicit Euler gains energy every step (factor 1 + ω²dt² = 1 + " +
               formatNumber(wdt * wdt, 3) + " per contact step) and is unstable at any dt: use " +
               gasIntegrator(GasIntegrator::VelocityVerlet).name;
    const auto [shownWdt, shownLimit] = distinct(wdt, limit); // compared unrounded, shown apart
    if (shownWdt == shownLimit) // on the limit, to the decimals shown: neither inside nor beyond it
        return "dt·ω = " + shownWdt + " is at the stability limit " + shownLimit + " of " + name +
               ", where a contact's oscillation is not damped and any stiffer contact (a deeper overlap) is "
               "unstable; use |dt| < " +
               formatNumber(kSafeShareOfLimit * limit / omega, 3) + " (" +
               formatNumber(100 * kSafeShareOfLimit, 2) + " % of the limit)";
    if (wdt > limit)
        return "dt·ω = " + shownWdt + " > " + shownLimit + ": " + name + " is unstable; use |dt| < " +
               formatNumber(limit / omega, 3) + " (about " + formatNumber(std::acos(-1.0) / wdt, 2) +
               " steps per contact now)";
    return "dt·ω = " + shownWdt + " is inside the stability limit " + shownLimit +
           "; look for deeply overlapping disks (spawning, random placement with large k) or a fast "
           "obstacle, "
           "or reduce dt";
}

void GasModel::checkHealth(bool energyCheck) {
    if (failed()) return;
    if (escaped_) {
        fail("a disk moved farther than the box in one step or became NaN", stabilityHint());
        return;
    }
    // A body the user drives does work on the gas, so energy is checked again once it rests (the energy
    // it gave then becomes the reference, advanceBodies).
    if (!energyCheck || bodiesMoving()) return;
    const double e = totalEnergy();
    if (!std::isfinite(e)) {
        fail("the total energy is not finite", stabilityHint());
        return;
    }
    const double bound =
        params_.blowupEnergyFactor * std::max(referenceEnergy_, std::abs(energyBaseline_)) +
        (params_.wallMode == GasWallMode::Thermal ? 4.0 * params_.wallKT * state_.size() : 0.0);
    if (e > bound && e > 0)
        fail("the total energy grew from " + formatNumber(referenceEnergy_, 6) + " to " + formatNumber(e, 6) +
                 " (more than " + formatNumber(params_.blowupEnergyFactor, 3) + "×)",
             stabilityHint());
}

} // namespace pl
