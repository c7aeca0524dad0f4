// Plot export: a PNG has exactly the pixels asked for, its DPI as metadata and scale; SVG is an SVG
// document, PDF starts with %PDF, CSV parses back to the plotted points; bad paths and formats give errors
// and leave no file behind. The file dialogs start in the folder used last, else the documents folder.
#include "FileDialogs.h"
#include "plots/ExportImageDialog.h"
#include "plots/PlotExport.h"

#include <QCheckBox>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QtTest>
#include <qcustomplot.h>

using namespace pl::ui;

class TestPlotExport : public QObject {
    Q_OBJECT
private:
    QCustomPlot plot_;
    QTemporaryDir dir_;

private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true); // settings in a test folder, never the user's
        QCoreApplication::setOrganizationName("ParticleLab");
        QCoreApplication::setApplicationName("tst_plotexport");
        plot_.setObjectName("testPlot");
        QCPGraph* graph = plot_.addGraph();
        graph->setName("sine, sampled");
        for (int i = 0; i <= 50; ++i) graph->addData(i * 0.1, std::sin(i * 0.1));
        auto* bars = new QCPBars(plot_.xAxis, plot_.yAxis);
        bars->setName("bars");
        bars->setData({1, 2, 3}, {0.5, 0.25, 0.125});
        plot_.rescaleAxes();
        plot_.resize(400, 300);
    }

    void pngHasTheChosenSizeAndResolution() {
        const QString path = dir_.filePath("plot.png");
        QVERIFY(savePlotImage(&plot_, path, {QSize(1200, 800), 150}).isEmpty());
        QImage image(path);
        QVERIFY(!image.isNull());
        QCOMPARE(image.size(), QSize(1200, 800)); // the pixels the dialog names, whatever the DPI
        QCOMPARE(qRound(image.dotsPerMeterX() * 0.0254), 150);
        QSet<QRgb> colours;
        for (int y = 0; y < image.height(); y += 8)
            for (int x = 0; x < image.width(); x += 8) colours.insert(image.pixel(x, y));
        QVERIFY(colours.size() > 3); // axes, curve and bars were drawn
    }

    // The DPI scales the drawing on the same pixels: at 192 DPI the tick labels take twice the margin.
    void aHigherDpiDrawsLargerOnTheSamePixels() {
        auto axisColumn = [this](int dpi) {
            const QString path = dir_.filePath(QString("dpi%1.png").arg(dpi));
            if (!savePlotImage(&plot_, path, {QSize(800, 600), dpi}).isEmpty()) return -1;
            const QImage image = QImage(path).convertToFormat(QImage::Format_RGB32);
            for (int x = 0; x < image.width(); ++x) { // the left axis: a dark line down most of the height
                int dark = 0;
                for (int y = 0; y < image.height(); ++y) dark += qGray(image.pixel(x, y)) < 100;
                if (dark > image.height() / 2) return x;
            }
            return -1;
        };
        const int at96 = axisColumn(96), at192 = axisColumn(192);
        QVERIFY2(at96 > 0 && at192 > 0, qPrintable(QString("%1 %2").arg(at96).arg(at192)));
        QVERIFY2(at192 > 1.6 * at96 && at192 < 2.4 * at96, qPrintable(QString("%1 %2").arg(at96).arg(at192)));
    }

    void svgIsAnSvgDocument() {
        const QString path = dir_.filePath("plot.svg");
        QVERIFY(savePlotImage(&plot_, path, {QSize(600, 400), 96}).isEmpty());
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QByteArray text = file.readAll();
        QVERIFY(text.contains("<svg"));
        QVERIFY(text.contains("</svg>"));
        QVERIFY(text.contains("<path") || text.contains("<polyline"));
    }

    void pdfIsAPdfDocument() {
        const QString path = dir_.filePath("plot.pdf");
        QVERIFY(savePlotImage(&plot_, path, {QSize(600, 400), 300}).isEmpty());
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QByteArray bytes = file.readAll();
        QVERIFY(bytes.startsWith("%PDF"));
        QVERIFY(bytes.size() > 1000);
    }

    void csvParsesBackToThePoints() {
        const QString path = dir_.filePath("plot.csv");
        QVERIFY(savePlotCsv(&plot_, path).isEmpty());
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly | QIODevice::Text));
        const QStringList lines = QString::fromUtf8(file.readAll()).split('\n', Qt::SkipEmptyParts);
        QCOMPARE(lines.first(), QString("series,x,y"));
        QCOMPARE(lines.size(), 1 + 51 + 3);
        // A name with a comma is quoted; numbers read back exactly (17 significant digits).
        QVERIFY(lines[1].startsWith("\"sine, sampled\","));
        const QStringList last = lines.last().split(',');
        QCOMPARE(last.size(), 3);
        QCOMPARE(last[0], QString("bars"));
        QCOMPARE(last[1].toDouble(), 3.0);
        QCOMPARE(last[2].toDouble(), 0.125);
        const QStringList sine = lines[11].split("\",").last().split(',');
        QCOMPARE(sine[1].toDouble(), std::sin(1.0));
    }

    void failuresAreReportedAndLeaveNoFile() {
        QVERIFY(!savePlotImage(&plot_, dir_.filePath("plot.bmp"), {}).isEmpty());
        QVERIFY(!QFile::exists(dir_.filePath("plot.bmp")));
        QVERIFY(!savePlotImage(&plot_, "/nonexistent/dir/plot.png", {}).isEmpty());
        QVERIFY(!savePlotCsv(&plot_, "/nonexistent/dir/plot.csv").isEmpty());
        QVERIFY(!savePlotImage(&plot_, dir_.filePath("tiny.png"), {QSize(4, 4), 96}).isEmpty());
        QVERIFY(!QFile::exists(dir_.filePath("tiny.png")));
    }

    // A fresh account: exports start in the documents folder (its home when it has none), never in the
    // program's working directory; experiments in the user's preset folder.
    void dialogsStartInTheDocumentsFolder() {
        QSettings().clear();
        const QString documents = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
        QCOMPARE(files::startFolder(files::Place::Exports),
                 QFileInfo(documents).isDir() ? documents : QDir::homePath());
        QVERIFY(files::startFolder(files::Place::Experiments).endsWith("presets"));
        QVERIFY(files::startFolder(files::Place::Exports) != QDir::currentPath());
    }

    // The folder chosen in one dialog is where the next one of its place opens, until it vanishes.
    void dialogsStartInTheFolderUsedLast() {
        QSettings().clear();
        QTemporaryDir chosen;
        const QString target = QDir(chosen.path()).filePath("exports");
        QVERIFY(QDir().mkpath(target));
        QString openedIn;
        QTimer driver; // answers the modal dialog as a user would: type a name in another folder, Save
        connect(&driver, &QTimer::timeout, this, [&] {
            auto* dialog = qobject_cast<QFileDialog*>(QApplication::activeModalWidget());
            if (!dialog) return;
            driver.stop();
            openedIn = dialog->directory().absolutePath();
            dialog->selectFile(QDir(target).filePath("plot.png"));
            QMetaObject::invokeMethod(dialog, "accept"); // Save, as a click would
        });
        const QString firstStart = files::startFolder(files::Place::Exports);
        driver.start(50);
        const QString path = files::saveFileName(nullptr, files::Place::Exports, "Save plot image",
                                                 "plot.png", "PNG image (*.png)");
        QCOMPARE(QFileInfo(path).absolutePath(), QFileInfo(target).absoluteFilePath());
        QCOMPARE(openedIn, QFileInfo(firstStart).absoluteFilePath());
        QCOMPARE(files::startFolder(files::Place::Exports), QFileInfo(target).absoluteFilePath());
        QVERIFY(files::startFolder(files::Place::Experiments) != files::startFolder(files::Place::Exports));

        driver.start(50); // the next export dialog opens where the last one saved
        QVERIFY(!files::saveFileName(nullptr, files::Place::Exports, "Export plot data", "plot.csv",
                                     "CSV table (*.csv)")
                     .isEmpty());
        QCOMPARE(openedIn, QFileInfo(target).absoluteFilePath());

        QVERIFY(QDir(target).removeRecursively()); // a folder that is gone: back to the default
        QVERIFY(files::startFolder(files::Place::Exports) != QFileInfo(target).absoluteFilePath());
    }

    // A name typed without a suffix gets the chosen filter's: my-gas.particlelab, fob-snap.plsnap (they
    // were saved as "my-gas" and "fob-snap", which the preset menu and a file manager pass over).
    void aBareNameGetsTheFiltersSuffix_data() {
        QTest::addColumn<QString>("typed");
        QTest::addColumn<QString>("filter");
        QTest::addColumn<QString>("expected");
        QTest::newRow("preset") << "my-gas"
                                << "Experiments (*.particlelab);;Presets (*.json)"
                                << "my-gas.particlelab";
        QTest::newRow("snapshot") << "fob-snap"
                                  << "Snapshots (*.plsnap *.json)"
                                  << "fob-snap.plsnap";
        QTest::newRow("own suffix kept") << "class.json"
                                         << "Snapshots (*.plsnap *.json)"
                                         << "class.json";
    }
    void aBareNameGetsTheFiltersSuffix() {
        QFETCH(QString, typed);
        QFETCH(QString, filter);
        QFETCH(QString, expected);
        QSettings().clear();
        files::rememberFolderOf(files::Place::Experiments, dir_.path(), true);
        QTimer driver; // types the name into the dialog's file name field and presses Return, as a user
        connect(&driver, &QTimer::timeout, this, [&] {
            auto* dialog = qobject_cast<QFileDialog*>(QApplication::activeModalWidget());
            if (!dialog || !QApplication::focusWidget()) return;
            driver.stop();
            QWidget* field = QApplication::focusWidget();
            QTest::keyClick(field, Qt::Key_A, Qt::ControlModifier);
            QTest::keyClicks(field, typed);
            QTest::keyClick(field, Qt::Key_Return);
        });
        driver.start(50);
        const QString path =
            files::saveFileName(nullptr, files::Place::Experiments, "Save preset", "untitled", filter);
        QCOMPARE(QFileInfo(path).fileName(), expected);
        QCOMPARE(QFileInfo(path).absolutePath(), QFileInfo(dir_.path()).absoluteFilePath());
    }

    // The image size keeps the plot's proportions: a width typed alone brings the height along (1200 ×
    // 251 from a 573 × 120 plot was a strip with its label cut); unlocked, each side is the user's.
    void imageSizeKeepsTheProportions() {
        ExportImageDialog dialog(QSize(600, 300), true);
        dialog.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dialog));
        auto boxes = dialog.findChildren<QSpinBox*>();
        QSpinBox* width = boxes.at(0);
        QSpinBox* height = boxes.at(1);
        QCOMPARE(width->value(), 600);
        QTest::mouseClick(width, Qt::LeftButton, {}, width->rect().center());
        QTest::keyClick(width, Qt::Key_A, Qt::ControlModifier);
        QTest::keyClicks(width, "1200");
        QTest::keyClick(width, Qt::Key_Tab);
        QCOMPARE(dialog.options().size, QSize(1200, 600));
        QTest::mouseClick(dialog.findChild<QCheckBox*>("keepProportions"), Qt::LeftButton);
        QTest::keyClick(height, Qt::Key_A, Qt::ControlModifier);
        QTest::keyClicks(height, "500");
        QTest::keyClick(height, Qt::Key_Tab);
        QCOMPARE(dialog.options().size, QSize(1200, 500));
    }
};

QTEST_MAIN(TestPlotExport)
#include "tst_plotexport.moc"
