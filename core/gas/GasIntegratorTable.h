// The gas's integrators, one table entry each: name, order, stability limit and the stage list that the
// CPU model (GasIntegrators.cpp) and the GPU model (gl/GasModelGL.cpp) both execute. Every list of
// integrator names (parameter choice, CLI, methods lab) is read from here.
#pragma once

#include "common/ParamSpec.h"

#include <string>
#include <vector>

namespace pl {

enum class GasIntegrator { VelocityVerlet, SymplecticEuler, ExplicitEuler, RungeKutta4, ForestRuth };

// One stage of a step; fraction is its length as a fraction of the step h.
enum class GasStageKind {
    Kick,   // v += fraction·h·a, with a the accelerations computed last (not re-evaluated)
    Drift,  // x += fraction·h·v, then walls and obstacles
    Forces, // a at the current positions
    // The whole classical Runge–Kutta step (GasModel::stepRungeKutta4). RK4 combines four slopes of
    // (x, v) taken from the start of the step; no sequence of kicks and drifts reproduces that, so it is
    // one stage of its own rather than a second description elsewhere. It evaluates kRungeKutta4Forces.
    RungeKutta4,
};
inline constexpr int kRungeKutta4Forces = 4;

struct GasStage {
    GasStageKind kind;
    double fraction = 0.0;
};

// The stages fused into the passes over the particles that the executors run: each kick joins the
// drift after it (kickBefore), a kick between a drift and the next force evaluation joins that drift
// (kickAfter), and the step's final kick, with no drift after it, joins the last force pass. Fractions
// of h as in GasStage.
struct GasPass {
    enum class Kind { Drift, Forces, RungeKutta4 };
    Kind kind;
    double kickBefore = 0.0, drift = 0.0, kickAfter = 0.0;
    bool countContacts = false; // only the step's last force evaluation counts contacts begun
};

// A pass's fraction of the step in time units [T]. An absent kick stays +0.0 whatever the sign of h
// (0.0 · h would be −0.0 when time runs backwards), so both executors pass exactly what they always did.
inline double stepFraction(double fraction, double h) {
    return fraction == 0.0 ? 0.0 : fraction * h;
}

struct GasIntegratorInfo {
    GasIntegrator id;
    std::string name;  // the preset and CLI spelling
    std::string title; // for prose ("velocity Verlet")
    int order;         // global order of accuracy
    bool symplectic;
    // Largest ω·dt for which the scheme is stable on x'' = −ω²x (docs/gas.md "Integrators"); 0: none.
    double stabilityLimit;
    std::string description; // one line for help texts and tooltips
    std::vector<GasStage> stages;
    std::vector<GasPass> passes; // the stages, fused (see GasPass)

    int forcesPerStep() const;       // force evaluations per step, counted from the stages
    bool onlyKicksAndDrifts() const; // a splitting the GPU model runs with its own dispatches
};

// In the parameter's choice order (velocity Verlet, the default, first).
const std::vector<GasIntegratorInfo>& gasIntegrators();
const GasIntegratorInfo& gasIntegrator(GasIntegrator id);
const GasIntegratorInfo& gasIntegrator(const std::string& name); // throws std::invalid_argument
std::vector<std::string> gasIntegratorNames();
// Ordered as the methods lab compares them: by order of accuracy, within one order the non-symplectic
// scheme first (the baseline the symplectic one improves on).
std::vector<std::string> gasIntegratorNamesByOrder();
// One line per integrator, "name: description (order, forces per step, stability limit)", for help.
std::string gasIntegratorHelp();

// The table's names as a choice table, for binding the integrator parameter to the enum (ParamSpec.h).
const ChoiceTable<GasIntegrator>& choiceTable(GasIntegrator);

GasIntegrator integratorFromName(const std::string& name); // throws std::invalid_argument
double stabilityLimit(GasIntegrator integrator);

} // namespace pl
