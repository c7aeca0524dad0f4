// The methods lab's worker: runs a page's jobs one by one in a thread, with a progress bar, Cancel and a
// status line. Each job returns what the GUI thread then does with its result (plot a point). A job
// that throws costs its point only: the error is shown and the next job runs.
#pragma once

#include <QWidget>
#include <atomic>
#include <functional>
#include <vector>

class QLabel;
class QProgressBar;
class QPushButton;
class QThread;

namespace pl::ui {

class LabRunner : public QWidget {
    Q_OBJECT
public:
    using Show = std::function<void()>;
    using Job = std::function<Show()>;

    explicit LabRunner(QWidget* parent = nullptr);
    ~LabRunner() override; // waits for the current job; its result is dropped

    // False (and nothing started) while another run is going.
    bool start(std::vector<Job> jobs, const QString& what);
    bool isRunning() const { return worker_ != nullptr; }
    // Jobs that run long may poll it to stop early.
    const std::atomic<bool>* stopFlag() const { return &stop_; }
    void setStatus(const QString& text);
    int failedJobs() const { return failed_; }

public slots:
    void cancel();

signals:
    void started();
    void finished();

private:
    void workerDone();

    QProgressBar* progress_ = nullptr;
    QPushButton* cancel_ = nullptr;
    QLabel* status_ = nullptr;
    QThread* worker_ = nullptr;
    std::atomic<bool> stop_{false};
    int done_ = 0, failed_ = 0;
    QString what_, lastFailure_;
};

} // namespace pl::ui
