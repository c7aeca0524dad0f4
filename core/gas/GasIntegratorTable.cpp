// The integrator table's entries (docs/gas.md "Integrators") and the fusion of stages into passes.
#include "GasIntegratorTable.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace pl {

namespace {

GasStage kick(double fraction) {
    return {GasStageKind::Kick, fraction};
}
GasStage drift(double fraction) {
    return {GasStageKind::Drift, fraction};
}
GasStage forces() {
    return {GasStageKind::Forces, 0.0};
}

// See GasPass. Kicks wait for the next drift; a kick left at the end of the step goes into the last
// force pass, so the step ends with the true velocities. Adjacent kicks would add up; no entry has them.
std::vector<GasPass> fuse(const std::vector<GasStage>& stages) {
    std::vector<GasPass> passes;
    double pendingKick = 0.0;
    for (const GasStage& stage : stages) {
        const bool afterDrift = !passes.empty() && passes.back().kind == GasPass::Kind::Drift;
        switch (stage.kind) {
        case GasStageKind::Kick:
            if (afterDrift && pendingKick == 0.0)
                passes.back().kickAfter += stage.fraction;
            else
                pendingKick += stage.fraction;
            break;
        case GasStageKind::Drift:
            passes.push_back({GasPass::Kind::Drift, pendingKick, stage.fraction, 0.0, false});
            pendingKick = 0.0;
            break;
        case GasStageKind::Forces:
            passes.push_back({GasPass::Kind::Forces, 0.0, 0.0, 0.0, false});
            break;
        case GasStageKind::RungeKutta4:
            passes.push_back({GasPass::Kind::RungeKutta4, 0.0, 0.0, 0.0, false});
            break;
        }
    }
    if (pendingKick != 0.0) {
        if (passes.empty() || passes.back().kind != GasPass::Kind::Forces)
            throw std::logic_error("an integrator's final kick must follow a force evaluation");
        passes.back().kickAfter = pendingKick;
    }
    // Each step ends with forces at the new positions (the next step starts from them); that last
    // evaluation counts the contacts begun, the intermediate ones would count them twice.
    if (passes.empty() || passes.back().kind == GasPass::Kind::Drift)
        throw std::logic_error("an integrator must end with a force evaluation");
    passes.back().countContacts = true;
    return passes;
}

GasIntegratorInfo entry(GasIntegrator id, std::string name, std::string title, int order, bool symplectic,
                        double limit, std::string description, std::vector<GasStage> stages) {
    GasIntegratorInfo info{id,    std::move(name),        std::move(title),  order, symplectic,
                           limit, std::move(description), std::move(stages), {}};
    info.passes = fuse(info.stages);
    return info;
}

std::vector<GasIntegratorInfo> buildTable() {
    // Forest & Ruth (1990) / Yoshida (1990) 4th-order symplectic composition: θ = 1 / (2 − 2^{1/3}).
    const double t = 1.0 / (2.0 - std::cbrt(2.0));
    std::vector<GasIntegratorInfo> table;
    // Strang splitting kick–drift–kick.
    table.push_back(entry(GasIntegrator::VelocityVerlet, "velocity-verlet", "velocity Verlet", 2, true, 2.0,
                          "kick h/2, drift h, forces, kick h/2; symplectic, time-reversible",
                          {kick(0.5), drift(1.0), forces(), kick(0.5)}));
    // v_{n+1} = v_n + h a(x_n); x_{n+1} = x_n + h v_{n+1}.
    table.push_back(entry(GasIntegrator::SymplecticEuler, "symplectic-euler", "symplectic Euler", 1, true,
                          2.0, "kick h, drift h, forces; symplectic", {kick(1.0), drift(1.0), forces()}));
    // x_{n+1} = x_n + h v_n; v_{n+1} = v_n + h a(x_n): the kick after the drift still uses a(x_n), which
    // the stage list expresses because a kick uses the accelerations computed last. That kick is not
    // the exact flow of the potential at x_{n+1}, so this is no splitting: energy grows by (1 + ω²h²)
    // per step and no dt is stable.
    table.push_back(entry(GasIntegrator::ExplicitEuler, "explicit-euler", "explicit Euler", 1, false, 0.0,
                          "drift h with v_n, kick h with a(x_n), forces; gains energy every step",
                          {drift(1.0), kick(1.0), forces()}));
    // Classical RK4 on (x, v); walls reflect the final state. Limit: |R(iωh)| = 1 at ωh = 2√2.
    table.push_back(entry(GasIntegrator::RungeKutta4, "rk4", "RK4", 4, false, 2.0 * std::sqrt(2.0),
                          "classical Runge–Kutta on (x, v); slowly loses energy",
                          {{GasStageKind::RungeKutta4, 1.0}}));
    // Velocity form: kicks θ/2, (1−θ)/2, (1−θ)/2, θ/2 around drifts θ, 1−2θ, θ. Limit from the trace of
    // its amplification matrix on the oscillator.
    table.push_back(entry(GasIntegrator::ForestRuth, "forest-ruth", "Forest–Ruth", 4, true, 1.5734,
                          "three Verlet steps of θh, (1−2θ)h, θh; symplectic, time-reversible",
                          {kick(0.5 * t), drift(t), forces(), kick(0.5 * (1.0 - t)), drift(1.0 - 2.0 * t),
                           forces(), kick(0.5 * (1.0 - t)), drift(t), forces(), kick(0.5 * t)}));
    return table;
}

} // namespace

int GasIntegratorInfo::forcesPerStep() const {
    int count = 0;
    for (const GasStage& s : stages) {
        if (s.kind == GasStageKind::Forces) count += 1;
        if (s.kind == GasStageKind::RungeKutta4) count += kRungeKutta4Forces;
    }
    return count;
}

bool GasIntegratorInfo::onlyKicksAndDrifts() const {
    return std::none_of(stages.begin(), stages.end(),
                        [](const GasStage& s) { return s.kind == GasStageKind::RungeKutta4; });
}

const std::vector<GasIntegratorInfo>& gasIntegrators() {
    static const std::vector<GasIntegratorInfo> table = buildTable();
    return table;
}

const GasIntegratorInfo& gasIntegrator(GasIntegrator id) {
    for (const auto& info : gasIntegrators())
        if (info.id == id) return info;
    throw std::logic_error("integrator missing from the table");
}

const GasIntegratorInfo& gasIntegrator(const std::string& name) {
    for (const auto& info : gasIntegrators())
        if (info.name == name) return info;
    throw std::invalid_argument("unknown integrator '" + name + "'");
}

std::vector<std::string> gasIntegratorNames() {
    std::vector<std::string> names;
    for (const auto& info : gasIntegrators()) names.push_back(info.name);
    return names;
}

std::vector<std::string> gasIntegratorNamesByOrder() {
    std::vector<const GasIntegratorInfo*> sorted;
    for (const auto& info : gasIntegrators()) sorted.push_back(&info);
    std::stable_sort(
        sorted.begin(), sorted.end(), [](const GasIntegratorInfo* a, const GasIntegratorInfo* b) {
            return a->order != b->order ? a->order < b->order : (!a->symplectic && b->symplectic);
        });
    std::vector<std::string> names;
    for (const auto* info : sorted) names.push_back(info->name);
    return names;
}

std::string gasIntegratorHelp() {
    std::string help;
    for (const auto& info : gasIntegrators()) {
        std::ostringstream line;
        line << info.name << ": " << info.description << " (order " << info.order << ", "
             << info.forcesPerStep()
             << (info.forcesPerStep() == 1 ? " force evaluation" : " force evaluations") << " per step, ";
        if (info.stabilityLimit > 0)
            line << "stable for ω dt < " << std::setprecision(4) << info.stabilityLimit << ")";
        else
            line << "no stable dt)";
        help += (help.empty() ? "" : "\n") + line.str();
    }
    return help;
}

const ChoiceTable<GasIntegrator>& choiceTable(GasIntegrator) {
    static const ChoiceTable<GasIntegrator> table = [] {
        ChoiceTable<GasIntegrator> t;
        for (const auto& info : gasIntegrators()) t.emplace_back(info.id, info.name);
        return t;
    }();
    return table;
}

GasIntegrator integratorFromName(const std::string& name) {
    return gasIntegrator(name).id;
}

double stabilityLimit(GasIntegrator integrator) {
    return gasIntegrator(integrator).stabilityLimit;
}

} // namespace pl
