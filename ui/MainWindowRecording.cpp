// MainWindow's recording and report: Simulation → Record clip (the Record dialog, then the file; a checked
// tool-bar button while it records, with the clip's length in the status bar; the last frames' encoding
// with a progress dialog) and File → Export report….
#include "MainWindow.h"

#include "ExperimentDocument.h"
#include "FileDialogs.h"
#include "SimulationController.h"
#include "record/AppRecorder.h"
#include "record/RecordDialog.h"
#include "report/LabReport.h"

#include <QLabel>
#include <QMenu>
#include <QMessageBox>
#include <QProgressDialog>
#include <QStatusBar>
#include <QToolBar>
#include <algorithm>

namespace pl::ui {

void MainWindow::createReportAction(QMenu* file) {
    QAction* report = file->addAction(tr("Expor&t report…"));
    report->setObjectName("exportReportAction");
    report->setStatusTip(tr("Write a lab report of the experiment: parameters, run, scene, plots, readouts"));
    connect(report, &QAction::triggered, this, [this] {
        const QString path =
            files::saveFileName(this, files::Place::Exports, tr("Export report"), document_->title() + ".pdf",
                                tr("PDF (*.pdf);;Web page (*.html)"));
        if (path.isEmpty()) return;
        const QString error =
            exportLabReport(*controller_, document_->title(), document_->description(), path);
        if (!error.isEmpty()) QMessageBox::critical(this, tr("Cannot write the report"), error);
    });
}

void MainWindow::createRecordAction(QMenu* sim, QToolBar* bar) {
    recorder_ = new AppRecorder(controller_, this);
    recordAction_ = sim->addAction(tr("Record clip…"));
    recordAction_->setObjectName("recordAction");
    recordAction_->setCheckable(true);
    recordAction_->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_R));
    recordAction_->setIcon(style()->standardIcon(QStyle::SP_DialogNoButton));
    recordAction_->setToolTip(tr("Record a clip in simulated time (MP4, WebM or GIF); press again to stop"));
    bar->addAction(recordAction_);
    recordingLabel_ = new QLabel(this);
    recordingLabel_->setObjectName("recordingLabel");
    recordingLabel_->setStyleSheet(QStringLiteral("color: #c0392b; font-weight: bold;"));
    recordingLabel_->hide();
    statusBar()->addPermanentWidget(recordingLabel_);
    connect(recordAction_, &QAction::triggered, this, [this](bool on) {
        if (!on) {
            recorder_->stop();
            return;
        }
        recordAction_->setChecked(false); // until the clip starts
        RecordDialog dialog(controller_, this);
        if (dialog.exec() != QDialog::Accepted) return;
        // The format chosen in the dialog comes first: a name typed without a suffix gets its suffix.
        QStringList filters =
            tr("MP4 video (*.mp4);;WebM video (*.webm);;GIF (*.gif)").split(QStringLiteral(";;"));
        const QString suffix = QStringLiteral("*.") + clipSuffix(dialog.format());
        std::stable_partition(filters.begin(), filters.end(),
                              [&suffix](const QString& filter) { return filter.contains(suffix); });
        const QString chosen = files::saveFileName(this, files::Place::Exports, tr("Record clip"),
                                                   document_->title() + "." + clipSuffix(dialog.format()),
                                                   filters.join(QStringLiteral(";;")));
        const QString path = clipPathFor(chosen, dialog.format());
        const QString error =
            path.isEmpty() ? QString() : recorder_->start(path, document_->title(), dialog.options());
        if (!error.isEmpty()) QMessageBox::critical(this, tr("Cannot record"), error);
        recordAction_->setChecked(recorder_->isRecording());
    });
    connect(recorder_, &AppRecorder::recordingChanged, this, [this](bool on) {
        recordAction_->setChecked(on);
        recordAction_->setEnabled(!recorder_->isDraining());
        recordAction_->setText(on ? tr("Stop recording") : tr("Record clip…"));
        recordingLabel_->setVisible(on);
        recordingLabel_->setText(tr("● REC %1 s").arg(0.0, 0, 'f', 1));
    });
    connect(recorder_, &AppRecorder::progressed, this,
            [this](double seconds) { recordingLabel_->setText(tr("● REC %1 s").arg(seconds, 0, 'f', 1)); });
    // Frames still queued at Stop: their encoding shows its progress and can be cancelled (the clip then
    // ends with the frames encoded, still a playable file).
    connect(recorder_, &AppRecorder::draining, this, [this](long long left, long long all) {
        auto* progress = findChild<QProgressDialog*>("recordDrainProgress");
        if (!progress) {
            progress = new QProgressDialog(tr("Encoding the last frames of the clip…"), tr("Cancel"), 0,
                                           static_cast<int>(all), this);
            progress->setObjectName("recordDrainProgress");
            progress->setWindowTitle(tr("Record clip"));
            progress->setMinimumDuration(0);
            progress->setAutoClose(false);
            progress->setAutoReset(false);
            connect(progress, &QProgressDialog::canceled, recorder_, &AppRecorder::cancelDraining);
            progress->show();
        }
        progress->setValue(static_cast<int>(all - left));
    });
    connect(recorder_, &AppRecorder::finished, this, [this](const QString& sentence) {
        if (auto* progress = findChild<QProgressDialog*>("recordDrainProgress")) {
            progress->disconnect(recorder_); // closing it is no cancel
            progress->setObjectName(QString());
            progress->deleteLater();
        }
        recordAction_->setEnabled(true);
        statusBar()->showMessage(sentence, 10000);
    });
}

} // namespace pl::ui
