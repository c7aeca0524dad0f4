// Crash insurance: while time runs, the experiment and its full state are written every few seconds to
// the XDG state directory as a snapshot; a clean exit removes it. A snapshot left behind by a process
// that is gone (a crash, a kill, a power cut) is offered back on the next start.
#pragma once

#include <QObject>
#include <QString>
#include <QTimer>

class QWidget;

namespace pl::ui {

class ExperimentDocument;
class SimulationController;

class Autosave : public QObject {
    Q_OBJECT
public:
    static constexpr int kIntervalMs = 4000;
    // Larger experiments are not autosaved: writing them would stall the frame for seconds.
    static constexpr std::size_t kMaxParticles = 200000;

    Autosave(SimulationController* controller, ExperimentDocument* document, QWidget* dialogParent);

    // ~/.local/state/ParticleLab (or $XDG_STATE_HOME/ParticleLab).
    static QString directory();
    // This process's snapshot file.
    QString path() const;
    // Writes the snapshot now (when the state changed since the last one). Returns an error sentence or
    // empty.
    QString saveNow();
    // Asks whether to restore the newest snapshot left by a process that no longer runs; opens it when
    // the user agrees. Every such orphan is removed either way. Returns whether one was restored.
    bool offerRestore();
    // A clean exit: nothing to restore next time.
    void discard();

private:
    SimulationController* controller_;
    ExperimentDocument* document_;
    QWidget* parent_;
    QTimer timer_;
    long long savedStep_ = -1;
    const void* savedModel_ = nullptr;
};

} // namespace pl::ui
