// The status bar's word when this machine cannot run the scene at its watchable pace: how far below it
// the run is and why (the work of a step), and the lighter experiment that would keep the pace (fewer
// particles, from the kind's registration) as a button. Nothing changes until the teacher presses it.
#pragma once

#include "common/ParamSpec.h"

#include <QElapsedTimer>
#include <QWidget>

class QLabel;
class QPushButton;

namespace pl::ui {

class SimulationController;

class PaceAdvice : public QWidget {
    Q_OBJECT
public:
    // Judged over this much wall time of running at the automatic pace [s].
    static constexpr double kJudgedSeconds = 3.0;
    // Below this share of the watchable rate the pace is said to be short.
    static constexpr double kShortShare = 0.5;
    // The lighter experiment aims at this share of the work that would just keep the pace, leaving room
    // for the viewport and the plots.
    static constexpr double kMargin = 0.8;

    explicit PaceAdvice(SimulationController* controller, QWidget* parent = nullptr);
    // The values the button applies (empty while nothing is advised).
    const ParamValues& advised() const { return advised_; }

private:
    void restart(); // a new experiment, parameters or pace: judge afresh, say nothing yet
    void judge();   // after each frame
    void apply();   // the button: the lighter values, then Reset

    SimulationController* controller_;
    QLabel* text_;
    QPushButton* use_;
    QElapsedTimer clock_;
    double startTime_ = 0.0;  // model time when the clock started
    long long startStep_ = 0; // step count when the clock started
    ParamValues advised_;
};

} // namespace pl::ui
