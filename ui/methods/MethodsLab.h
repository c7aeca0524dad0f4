// The methods lab: experiments on the numerics rather than on one scene, one tab each, sharing one runner
// (a worker thread with progress and Cancel; the window never freezes):
//  - Time reversal: the Loschmidt echo (EchoPage).
//  - Accuracy vs cost: the gas's integrators (GasSweepPage), the fluid's dt × iterations (FluidPage),
//    DSMC's particles × ν dt (DsmcPage), each with Recommend.
//  - Stability: the gas's stability map (StabilityPage); the fluid's is on its page.
//  - MD vs DSMC: the cheapest model that will do (RelaxPage).
#pragma once

#include <QWidget>
#include <vector>

class QCustomPlot;
class QTabWidget;

namespace pl::ui {

class DsmcPage;
class EchoPage;
class FluidPage;
class GasSweepPage;
class LabRunner;
class RelaxPage;
class SimulationController;
class StabilityPage;

class MethodsLab : public QWidget {
    Q_OBJECT
public:
    explicit MethodsLab(QWidget* parent = nullptr, SimulationController* controller = nullptr);
    ~MethodsLab() override;

    void setEchoSteps(std::vector<long long> steps);
    void setSweepSteps(std::vector<int> steps);
    QCustomPlot* echoPlot() const;
    QCustomPlot* sweepPlot() const;
    GasSweepPage* gasSweepPage() const { return gasSweep_; }
    StabilityPage* stabilityPage() const { return stability_; }
    FluidPage* fluidPage() const { return fluid_; }
    DsmcPage* dsmcPage() const { return dsmc_; }
    RelaxPage* relaxPage() const { return relax_; }
    QTabWidget* tabs() const { return tabs_; }
    LabRunner* runner() const { return runner_; }
    bool isRunning() const;

public slots:
    void runEcho();
    void runSweep();
    void cancel();

signals:
    void finished();

private:
    LabRunner* runner_ = nullptr;
    QTabWidget* tabs_ = nullptr;
    EchoPage* echo_ = nullptr;
    GasSweepPage* gasSweep_ = nullptr;
    StabilityPage* stability_ = nullptr;
    FluidPage* fluid_ = nullptr;
    DsmcPage* dsmc_ = nullptr;
    RelaxPage* relax_ = nullptr;
};

} // namespace pl::ui
