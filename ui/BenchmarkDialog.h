// "Benchmark this machine": the gas and the fluid at growing N on each backend this machine has,
// one point at a time (the window stays live between points), plotted as particle-steps per second
// against N on log–log axes and exportable like every plot.
#pragma once

#include "gl/MachineBenchmark.h"

#include <QDialog>
#include <vector>

class QCustomPlot;
class QLabel;
class QProgressBar;
class QPushButton;

namespace pl::ui {

class BenchmarkDialog : public QDialog {
    Q_OBJECT
public:
    struct Job {
        std::string scene;
        gl::Backend backend;
        std::size_t particles;
    };

    explicit BenchmarkDialog(QWidget* parent = nullptr);
    // The sweep to run (tests use a small one); the default covers 10³ … 2.6·10⁵ particles.
    void setJobs(std::vector<Job> jobs);
    void setSettings(const gl::BenchSettings& settings) { settings_ = settings; }
    const std::vector<gl::BenchPoint>& results() const { return results_; }
    QCustomPlot* plot() const { return plot_; }
    bool isRunning() const { return running_; }

public slots:
    void start();
    void stop();

signals:
    void finished();

private:
    void runNext();
    void addPoint(const gl::BenchPoint& point);
    int graphFor(const std::string& scene, const std::string& backend);

    std::vector<Job> jobs_;
    std::size_t next_ = 0;
    std::vector<gl::BenchPoint> results_;
    std::vector<std::string> tooSlow_; // "scene/backend" that passed the time limit: larger N skipped
    gl::BenchSettings settings_;
    bool running_ = false;
    QCustomPlot* plot_;
    QProgressBar* progress_;
    QLabel* status_;
    QPushButton* startButton_;
    QPushButton* stopButton_;
};

} // namespace pl::ui
