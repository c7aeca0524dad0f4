// The methods lab's worker thread: runs queued jobs with progress and Cancel, results back on the GUI.
#include "LabRunner.h"

#include <QCoreApplication>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QThread>
#include <QVBoxLayout>

namespace pl::ui {

LabRunner::LabRunner(QWidget* parent) : QWidget(parent) {
    progress_ = new QProgressBar(this);
    progress_->setValue(0);
    cancel_ = new QPushButton(tr("Cancel"), this);
    cancel_->setEnabled(false);
    connect(cancel_, &QPushButton::clicked, this, &LabRunner::cancel);
    status_ = new QLabel(this);
    status_->setWordWrap(true);
    status_->setObjectName("labStatus");
    auto* bar = new QHBoxLayout;
    bar->addWidget(progress_, 1);
    bar->addWidget(cancel_);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addLayout(bar);
    layout->addWidget(status_);
}

LabRunner::~LabRunner() {
    stop_ = true;
    if (!worker_) return;
    worker_->wait();
    delete worker_;
}

void LabRunner::setStatus(const QString& text) {
    status_->setText(text);
}

bool LabRunner::start(std::vector<Job> jobs, const QString& what) {
    if (worker_) return false;
    stop_ = false;
    done_ = failed_ = 0;
    lastFailure_.clear();
    what_ = what;
    progress_->setRange(0, static_cast<int>(jobs.size()));
    progress_->setValue(0);
    cancel_->setEnabled(true);
    setStatus(tr("%1: running…").arg(what));
    worker_ = QThread::create([this, jobs = std::move(jobs)] {
        for (const Job& job : jobs) {
            if (stop_) return;
            Show show;
            // The cores isolate their cells; this catches what escapes a whole job (a reference run
            // that failed, no memory), so one bad point never ends the run or the program.
            try {
                show = job();
            } catch (const std::exception& e) {
                show = [this, message = QString::fromStdString(e.what())] {
                    ++failed_;
                    lastFailure_ = message;
                    setStatus(tr("A point failed: %1").arg(message));
                };
            } catch (...) {
                show = [this] {
                    ++failed_;
                    lastFailure_ = tr("an unknown error");
                    setStatus(tr("A point failed with an unknown error."));
                };
            }
            QMetaObject::invokeMethod(this, [this, show] {
                if (show) show();
                progress_->setValue(++done_);
            });
        }
    });
    connect(worker_, &QThread::finished, this, &LabRunner::workerDone);
    worker_->start();
    emit started();
    return true;
}

void LabRunner::cancel() {
    if (!worker_) return;
    stop_ = true;
    setStatus(tr("Cancelling after the current point…"));
}

void LabRunner::workerDone() {
    // Points still queued behind this signal are shown first: the queue is in order.
    QCoreApplication::sendPostedEvents(this);
    worker_->deleteLater();
    worker_ = nullptr;
    cancel_->setEnabled(false);
    if (stop_)
        setStatus(tr("%1: cancelled after %2 of %3 points.").arg(what_).arg(done_).arg(progress_->maximum()));
    else if (failed_ > 0)
        setStatus(tr("%1: done; %2 of %3 points failed, the last with: %4")
                      .arg(what_)
                      .arg(failed_)
                      .arg(done_)
                      .arg(lastFailure_));
    emit finished();
}

} // namespace pl::ui
