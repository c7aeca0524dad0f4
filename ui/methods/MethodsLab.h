// The methods lab dock: experiments on the numerics rather than on one scene, each run point by point in
// a worker thread (progress bar, Cancel; the window never freezes) and plotted as it comes.
//  - Time reversal: the Loschmidt echo in double, float and bit-reversible integers (md/TimeReversal).
//  - Accuracy against cost: the five integrators on a harmonic pair, error against force evaluations
//    per unit time, measured orders in the legend (md/MethodSweep).
#pragma once

#include <QWidget>
#include <atomic>
#include <functional>
#include <vector>

class QCustomPlot;
class QLabel;
class QProgressBar;
class QPushButton;
class QThread;

namespace pl::ui {

class MethodsLab : public QWidget {
    Q_OBJECT
public:
    explicit MethodsLab(QWidget* parent = nullptr);
    ~MethodsLab() override;

    void setEchoSteps(std::vector<long long> steps) { echoSteps_ = std::move(steps); }
    void setSweepSteps(std::vector<int> steps) { sweepSteps_ = std::move(steps); }
    QCustomPlot* echoPlot() const { return echoPlot_; }
    QCustomPlot* sweepPlot() const { return sweepPlot_; }
    bool isRunning() const { return worker_ != nullptr; }

public slots:
    void runEcho();
    void runSweep();
    void cancel();

signals:
    void finished();

private:
    // Runs jobs one by one in a worker thread; each returns a function that the GUI thread then calls
    // (to plot the point). progress_ counts them; Cancel stops between jobs.
    using Job = std::function<std::function<void()>()>;
    void start(std::vector<Job> jobs, const QString& what);
    void workerDone();

    QWidget* makePage(QCustomPlot*& plot, const QString& xLabel, const QString& yLabel, QPushButton*& run,
                      QLabel*& note);

    std::vector<long long> echoSteps_{10, 30, 100, 300, 1000, 3000};
    std::vector<int> sweepSteps_{16, 32, 64, 128, 256};
    QCustomPlot* echoPlot_ = nullptr;
    QCustomPlot* sweepPlot_ = nullptr;
    QPushButton* echoRun_ = nullptr;
    QPushButton* sweepRun_ = nullptr;
    QLabel* echoNote_ = nullptr;
    QLabel* sweepNote_ = nullptr;
    QProgressBar* progress_ = nullptr;
    QPushButton* cancel_ = nullptr;
    QLabel* status_ = nullptr;
    QThread* worker_ = nullptr;
    std::atomic<bool> stop_{false};
    int done_ = 0;
};

} // namespace pl::ui
