// The integrator table's entries (docs/gas.md "Integrators") and the fusion of stages into passes.
#include "MdIntegratorTable.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace pl {

namespace {

MdStage kick(double fraction) {
    return {MdStageKind::Kick, fraction};
}
MdStage drift(double fraction) {
    return {MdStageKind::Drift, fraction};
}
MdStage forces() {
    return {MdStageKind::Forces, 0.0};
}

// See MdPass. Kicks wait for the next drift; a kick left at the end of the step goes into the last
// force pass, so the step ends with the true velocities. Adjacent kicks would add up; no entry has them.
std::vector<MdPass> fuse(const std::vector<MdStage>& stages) {
    std::vector<MdPass> passes;
    double pendingKick = 0.0;
    for (const MdStage& stage : stages) {
        const bool afterDrift = !passes.empty() && passes.back().kind == MdPass::Kind::Drift;
        switch (stage.kind) {
        case MdStageKind::Kick:
            if (afterDrift && pendingKick == 0.0)
                passes.back().kickAfter += stage.fraction;
            else
                pendingKick += stage.fraction;
            break;
        case MdStageKind::Drift:
            passes.push_back({MdPass::Kind::Drift, pendingKick, stage.fraction, 0.0, false});
            pendingKick = 0.0;
            break;
        case MdStageKind::Forces:
            passes.push_back({MdPass::Kind::Forces, 0.0, 0.0, 0.0, false});
            break;
        case MdStageKind::RungeKutta4:
            passes.push_back({MdPass::Kind::RungeKutta4, 0.0, 0.0, 0.0, false});
            break;
        }
    }
    if (pendingKick != 0.0) {
        if (passes.empty() || passes.back().kind != MdPass::Kind::Forces)
            throw std::logic_error("an integrator's final kick must follow a force evaluation");
        passes.back().kickAfter = pendingKick;
    }
    // Each step ends with forces at the new positions (the next step starts from them); that last
    // evaluation counts the contacts begun, the intermediate ones would count them twice.
    if (passes.empty() || passes.back().kind == MdPass::Kind::Drift)
        throw std::logic_error("an integrator must end with a force evaluation");
    passes.back().countContacts = true;
    return passes;
}

MdIntegratorInfo entry(MdIntegrator id, std::string name, std::string title, int order, bool symplectic,
                       double limit, std::string description, std::vector<MdStage> stages) {
    MdIntegratorInfo info{id,    std::move(name),        std::move(title),  order, symplectic,
                          limit, std::move(description), std::move(stages), {}};
    info.passes = fuse(info.stages);
    return info;
}

std::vector<MdIntegratorInfo> buildTable() {
    // Forest & Ruth (1990) / Yoshida (1990) 4th-order symplectic composition: θ = 1 / (2 − 2^{1/3}).
    const double t = 1.0 / (2.0 - std::cbrt(2.0));
    std::vector<MdIntegratorInfo> table;
    // Strang splitting kick–drift–kick.
    table.push_back(entry(MdIntegrator::VelocityVerlet, "velocity-verlet", "velocity Verlet", 2, true, 2.0,
                          "kick h/2, drift h, forces, kick h/2; symplectic, time-reversible",
                          {kick(0.5), drift(1.0), forces(), kick(0.5)}));
    // v_{n+1} = v_n + h a(x_n); x_{n+1} = x_n + h v_{n+1}.
    table.push_back(entry(MdIntegrator::SymplecticEuler, "symplectic-euler", "symplectic Euler", 1, true, 2.0,
                          "kick h, drift h, forces; symplectic", {kick(1.0), drift(1.0), forces()}));
    // x_{n+1} = x_n + h v_n; v_{n+1} = v_n + h a(x_n): the kick after the drift still uses a(x_n), which
    // the stage list expresses because a kick uses the accelerations computed last. That kick is not
    // the exact flow of the potential at x_{n+1}, so this is no splitting: energy grows by (1 + ω²h²)
    // per step and no dt is stable.
    table.push_back(entry(MdIntegrator::ExplicitEuler, "explicit-euler", "explicit Euler", 1, false, 0.0,
                          "drift h with v_n, kick h with a(x_n), forces; gains energy every step",
                          {drift(1.0), kick(1.0), forces()}));
    // Classical RK4 on (x, v); walls reflect the final state. Limit: |R(iωh)| = 1 at ωh = 2√2.
    table.push_back(entry(MdIntegrator::RungeKutta4, "rk4", "RK4", 4, false, 2.0 * std::sqrt(2.0),
                          "classical Runge–Kutta on (x, v); slowly loses energy",
                          {{MdStageKind::RungeKutta4, 1.0}}));
    // Velocity form: kicks θ/2, (1−θ)/2, (1−θ)/2, θ/2 around drifts θ, 1−2θ, θ. Limit from the trace of
    // its amplification matrix on the oscillator.
    table.push_back(entry(MdIntegrator::ForestRuth, "forest-ruth", "Forest–Ruth", 4, true, 1.5734,
                          "three Verlet steps of θh, (1−2θ)h, θh; symplectic, time-reversible",
                          {kick(0.5 * t), drift(t), forces(), kick(0.5 * (1.0 - t)), drift(1.0 - 2.0 * t),
                           forces(), kick(0.5 * (1.0 - t)), drift(t), forces(), kick(0.5 * t)}));
    return table;
}

} // namespace

int MdIntegratorInfo::forcesPerStep() const {
    int count = 0;
    for (const MdStage& s : stages) {
        if (s.kind == MdStageKind::Forces) count += 1;
        if (s.kind == MdStageKind::RungeKutta4) count += kRungeKutta4Forces;
    }
    return count;
}

bool MdIntegratorInfo::onlyKicksAndDrifts() const {
    return std::none_of(stages.begin(), stages.end(),
                        [](const MdStage& s) { return s.kind == MdStageKind::RungeKutta4; });
}

const std::vector<MdIntegratorInfo>& mdIntegrators() {
    static const std::vector<MdIntegratorInfo> table = buildTable();
    return table;
}

const MdIntegratorInfo& mdIntegrator(MdIntegrator id) {
    for (const auto& info : mdIntegrators())
        if (info.id == id) return info;
    throw std::logic_error("integrator missing from the table");
}

const MdIntegratorInfo& mdIntegrator(const std::string& name) {
    for (const auto& info : mdIntegrators())
        if (info.name == name) return info;
    throw std::invalid_argument("unknown integrator '" + name + "'");
}

std::vector<std::string> mdIntegratorNames() {
    std::vector<std::string> names;
    for (const auto& info : mdIntegrators()) names.push_back(info.name);
    return names;
}

std::vector<std::string> mdIntegratorNamesByOrder() {
    std::vector<const MdIntegratorInfo*> sorted;
    for (const auto& info : mdIntegrators()) sorted.push_back(&info);
    std::stable_sort(sorted.begin(), sorted.end(), [](const MdIntegratorInfo* a, const MdIntegratorInfo* b) {
        return a->order != b->order ? a->order < b->order : (!a->symplectic && b->symplectic);
    });
    std::vector<std::string> names;
    for (const auto* info : sorted) names.push_back(info->name);
    return names;
}

std::string mdIntegratorHelp() {
    std::string help;
    for (const auto& info : mdIntegrators()) {
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

const ChoiceTable<MdIntegrator>& choiceTable(MdIntegrator) {
    static const ChoiceTable<MdIntegrator> table = [] {
        ChoiceTable<MdIntegrator> t;
        for (const auto& info : mdIntegrators()) t.emplace_back(info.id, info.name);
        return t;
    }();
    return table;
}

MdIntegrator integratorFromName(const std::string& name) {
    return mdIntegrator(name).id;
}

double stabilityLimit(MdIntegrator integrator) {
    return mdIntegrator(integrator).stabilityLimit;
}

} // namespace pl
