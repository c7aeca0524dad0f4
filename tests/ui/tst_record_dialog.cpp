// The Record dialog and the app's recording, driven as a user drives them: keys into the spin boxes and
// choosers, clicks on the buttons. The defaults (720p, 30 frames/s, the watchable pace), the pace
// following the frame rate until the steps are set by hand, a size the format refuses, the choices
// remembered; then Record in the window (dialog, file, the indicator, Stop) and Cancel in the progress
// dialog of frames still queued at Stop, each clip read back with ffprobe.
#include "ExperimentDocument.h"
#include "MainWindow.h"
#include "SimulationController.h"
#include "UiTestSupport.h"
#include "record/AppRecorder.h"
#include "record/RecordDialog.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFileDialog>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QLineEdit>
#include <QProcess>
#include <QProgressDialog>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QtTest>

using namespace pl;

namespace {

// Picks the combo box's item `index` with the keyboard (Home, then Down), as a user does without the popup.
void choose(QComboBox* combo, int index) {
    combo->setFocus();
    QTest::keyClick(combo, Qt::Key_Home);
    for (int i = 0; i < index; ++i) QTest::keyClick(combo, Qt::Key_Down);
}

// Selects the spin box's text and types a new value, then leaves it with Tab.
void type(QSpinBox* spin, int value) {
    spin->setFocus();
    QTest::keyClick(spin, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(spin, QString::number(value));
    QTest::keyClick(spin, Qt::Key_Tab);
}

QPushButton* recordButton(QDialog& dialog) {
    return dialog.findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok);
}

long long probedFrames(const QString& path) {
    QProcess ffprobe;
    ffprobe.start("ffprobe", {"-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
                              "stream=nb_read_frames", "-of", "json", path});
    if (!ffprobe.waitForFinished(60000)) return -1;
    const QJsonObject stream =
        QJsonDocument::fromJson(ffprobe.readAllStandardOutput())["streams"].toArray().at(0).toObject();
    return stream["nb_read_frames"].toString("-1").toLongLong();
}

} // namespace

class TestRecordDialog : public QObject {
    Q_OBJECT
    ui::SimulationController controller_;

    // The steps of one frame at the watchable pace of the loaded gas, at fps frames per second.
    int watchable(int fps) const {
        const double dt = std::get<double>(controller_.model()->params().at("dt"));
        return ui::watchableStepsPerFrame(controller_.watchableRate(), dt, fps);
    }

private slots:
    void initTestCase() {
        test::useCleanTestSettings();
        controller_.setBackend(gl::Backend::Cpu);
        QVERIFY(controller_.load(loadPreset("gas-classroom")).isEmpty());
    }
    void init() { QSettings().clear(); }

    void watchableStepsKeepTheSceneAtItsPace() {
        QCOMPARE(ui::watchableStepsPerFrame(2.5, 0.005, 30), 17); // 2.5 T/s ÷ (0.005 T × 30 frames/s)
        QCOMPARE(ui::watchableStepsPerFrame(2.5, 0.005, 60), 8);
        QCOMPARE(ui::watchableStepsPerFrame(1e-4, 2e-7, 30), 17);
        QCOMPARE(ui::watchableStepsPerFrame(1.0, 10.0, 30), 1); // never fewer than one
        QCOMPARE(ui::watchableStepsPerFrame(0.0, 0.005, 30), ui::kAppStepsPerClipFrame); // no pace known
        QCOMPARE(ui::clipPathFor("/tmp/a", ClipFormat::Gif), QString("/tmp/a.gif"));
        QCOMPARE(ui::clipPathFor("/tmp/a.webm", ClipFormat::Mp4),
                 QString("/tmp/a.webm")); // the file decides
        QCOMPARE(ui::clipPathFor("/tmp/a.v1", ClipFormat::Mp4), QString("/tmp/a.v1.mp4"));
    }

    void defaultsAre720pAt30FramesAndTheWatchablePace() {
        ui::RecordDialog dialog(&controller_);
        dialog.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dialog));
        const ui::AppClipOptions o = dialog.options();
        QCOMPARE(o.size, QSize(1280, 720));
        QCOMPARE(o.fps, 30);
        QCOMPARE(o.stepsPerFrame, watchable(30));
        QVERIFY(o.captions);
        QVERIFY(o.plot.isEmpty());
        QCOMPARE(dialog.format(), ClipFormat::Mp4);
        QVERIFY(!dialog.findChild<QSpinBox*>("widthSpin")->isEnabled()); // a preset's size
        const QString pace = dialog.findChild<QLabel*>("paceLabel")->text();
        QVERIFY2(pace.contains(" T of simulated time per frame"), qPrintable(pace));
        QVERIFY(!dialog.findChild<QPushButton*>("watchablePaceButton")->isEnabled());
        // Every plot of the gas is offered beside the scene.
        QVERIFY(dialog.findChild<QComboBox*>("contentChooser")->findData("energyPlot") > 0);
    }

    void theStepsFollowTheFrameRateUntilSetByHand() {
        ui::RecordDialog dialog(&controller_);
        dialog.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dialog));
        auto* fps = dialog.findChild<QSpinBox*>("fpsSpin");
        auto* steps = dialog.findChild<QSpinBox*>("stepsSpin");
        auto* pace = dialog.findChild<QPushButton*>("watchablePaceButton");
        type(fps, 60);
        QCOMPARE(steps->value(), watchable(60));
        type(steps, 3);
        QVERIFY(pace->isEnabled());
        type(fps, 25);
        QCOMPARE(steps->value(), 3); // the user's number stays
        const QString label = dialog.findChild<QLabel*>("paceLabel")->text();
        const double dt = std::get<double>(controller_.model()->params().at("dt"));
        QVERIFY2(label.startsWith(QString::number(3 * dt, 'g', 3) + " T"), qPrintable(label));
        QTest::mouseClick(pace, Qt::LeftButton);
        QCOMPARE(steps->value(), watchable(25));
        QVERIFY(!pace->isEnabled());
    }

    void anOddSizeIsRefusedWhereTheFormatCannotStoreIt() {
        ui::RecordDialog dialog(&controller_);
        dialog.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dialog));
        auto* sizes = dialog.findChild<QComboBox*>("sizeChooser");
        choose(sizes, sizes->count() - 1); // Custom size
        auto* width = dialog.findChild<QSpinBox*>("widthSpin");
        QVERIFY(width->isEnabled());
        type(width, 1281);
        auto* refusal = dialog.findChild<QLabel*>("refusalLabel");
        QVERIFY(refusal->isVisible());
        QVERIFY2(refusal->text().contains("odd side"), qPrintable(refusal->text()));
        QVERIFY(!recordButton(dialog)->isEnabled());
        choose(dialog.findChild<QComboBox*>("formatChooser"), 2); // GIF keeps every pixel's colour
        QCOMPARE(dialog.format(), ClipFormat::Gif);
        QVERIFY(!refusal->isVisible());
        QVERIFY(recordButton(dialog)->isEnabled());
        QCOMPARE(dialog.options().size, QSize(1281, dialog.findChild<QSpinBox*>("heightSpin")->value()));
    }

    void choicesAreRememberedForTheNextClip() {
        {
            ui::RecordDialog dialog(&controller_);
            dialog.show();
            QVERIFY(QTest::qWaitForWindowExposed(&dialog));
            choose(dialog.findChild<QComboBox*>("formatChooser"), 1); // WebM
            auto* content = dialog.findChild<QComboBox*>("contentChooser");
            choose(content, content->findData("energyPlot"));
            choose(dialog.findChild<QComboBox*>("sizeChooser"), 3); // 1080p
            type(dialog.findChild<QSpinBox*>("fpsSpin"), 24);
            type(dialog.findChild<QSpinBox*>("stepsSpin"), 5);
            QTest::mouseClick(dialog.findChild<QCheckBox*>("captionsCheck"), Qt::LeftButton);
            QTest::mouseClick(recordButton(dialog), Qt::LeftButton);
            QCOMPARE(dialog.result(), int(QDialog::Accepted));
        }
        ui::RecordDialog again(&controller_);
        QCOMPARE(again.format(), ClipFormat::WebM);
        const ui::AppClipOptions o = again.options();
        QCOMPARE(o.plot, QString("energyPlot"));
        QCOMPARE(o.size, QSize(1920, 1080));
        QCOMPARE(o.fps, 24);
        QCOMPARE(o.stepsPerFrame, 5);
        QVERIFY(!o.captions);
    }

    // Record in the window: the dialog, then the file (named without a suffix: the dialog's format is
    // added), the indicator counting the clip's length, Stop, and the clip on disk with every frame taken.
    void recordActionOpensTheDialogThenTheFileAndRecords() {
        QTemporaryDir dir;
        ui::MainWindow window;
        QVERIFY(window.openPreset("gas-classroom"));
        QVERIFY(test::showActive(window));
        QStringList seen;
        QTimer driver;
        bool busy = false; // a tick during the keys and clicks of the last one waits
        connect(&driver, &QTimer::timeout, this, [&] {
            if (busy) return;
            busy = true;
            QWidget* modal = QApplication::activeModalWidget();
            if (auto* dialog = qobject_cast<ui::RecordDialog*>(modal)) {
                seen << "dialog";
                choose(dialog->findChild<QComboBox*>("formatChooser"), 1); // WebM
                choose(dialog->findChild<QComboBox*>("sizeChooser"), 0);   // 640 × 360
                type(dialog->findChild<QSpinBox*>("stepsSpin"), 4);
                QTest::mouseClick(recordButton(*dialog), Qt::LeftButton);
            } else if (auto* files = qobject_cast<QFileDialog*>(modal)) {
                auto* name = files->findChild<QLineEdit*>("fileNameEdit");
                if (name->text() != dir.filePath("lesson")) { // typed once; the completer's popup may linger
                    seen << "file";
                    name->selectAll();
                    QTest::keyClicks(name, dir.filePath("lesson"));
                }
                QMetaObject::invokeMethod(files, "accept"); // Save, as the button would
            }
            busy = false;
        });
        driver.start(50);
        QAction* record = window.findChild<QAction*>("recordAction");
        record->trigger();
        driver.stop();
        QCOMPARE(seen, QStringList({"dialog", "file"}));
        ui::AppRecorder* recorder = window.recorder();
        QVERIFY(recorder->isRecording());
        QVERIFY(record->isChecked());
        auto* indicator = window.findChild<QLabel*>("recordingLabel");
        QVERIFY(indicator->isVisible());
        window.controller()->setStepsPerFrame(2);
        for (int frame = 0; frame < 60; ++frame) window.controller()->advanceFrame(); // 120 steps: 31 frames
        QCOMPARE(recorder->frames(), 31LL);
        QCOMPARE(indicator->text(), QString("● REC %1 s").arg(31.0 / 30, 0, 'f', 1));
        QSignalSpy finished(recorder, &ui::AppRecorder::finished);
        record->trigger(); // Stop
        QVERIFY(finished.count() == 1 || finished.wait(30000));
        QVERIFY(!indicator->isVisible());
        QVERIFY(!record->isChecked());
        QVERIFY(record->isEnabled());
        const QString clip = dir.filePath("lesson.webm");
        QVERIFY2(window.statusBar()->currentMessage().contains(clip),
                 qPrintable(window.statusBar()->currentMessage()));
        QCOMPARE(probedFrames(clip), 31LL);
        window.document()->setModified(false);
    }

    // Frames still queued at Stop (4K VP9 encodes far slower than the scene takes them): a progress
    // dialog counts them down; its Cancel ends the clip with the frames encoded, and the file plays them.
    void cancelInTheProgressDialogKeepsAPlayableClip() {
        QTemporaryDir dir;
        ui::MainWindow window;
        QVERIFY(window.openPreset("gas-classroom"));
        QVERIFY(test::showActive(window));
        ui::AppRecorder* recorder = window.recorder();
        ui::AppClipOptions options;
        options.size = QSize(3840, 2160);
        options.stepsPerFrame = 1;
        const QString clip = dir.filePath("long.webm");
        QVERIFY(recorder->start(clip, "gas-classroom", options).isEmpty());
        window.controller()->setStepsPerFrame(1);
        for (int frame = 0; frame < 60; ++frame) window.controller()->advanceFrame();
        QAction* record = window.findChild<QAction*>("recordAction");
        QVERIFY(record->isChecked());
        QSignalSpy finished(recorder, &ui::AppRecorder::finished);
        record->trigger(); // Stop
        auto* progress = window.findChild<QProgressDialog*>("recordDrainProgress");
        QVERIFY(progress);
        QVERIFY(QTest::qWaitForWindowExposed(progress));
        QVERIFY(progress->maximum() > 10);
        QVERIFY(!record->isEnabled()); // no new clip while this one is finished
        auto* cancel = progress->findChild<QPushButton*>();
        QVERIFY(cancel);
        QTest::mouseClick(cancel, Qt::LeftButton);
        QVERIFY(finished.count() == 1 || finished.wait(60000));
        QVERIFY2(window.statusBar()->currentMessage().startsWith("Encoding cancelled"),
                 qPrintable(window.statusBar()->currentMessage()));
        QVERIFY(record->isEnabled());
        const long long encoded = recorder->framesInLastClip();
        QVERIFY2(encoded > 0 && encoded < 61, qPrintable(QString::number(encoded)));
        QCOMPARE(probedFrames(clip), encoded);
        QTRY_VERIFY(!window.findChild<QProgressDialog*>("recordDrainProgress"));
        window.document()->setModified(false);
    }
};

QTEST_MAIN(TestRecordDialog)
#include "tst_record_dialog.moc"
