// Plot export: PNG decodes at the chosen size and DPI, SVG is an SVG document, PDF starts with %PDF,
// CSV parses back to the plotted points; bad paths and formats give errors and leave no file behind.
#include "plots/PlotExport.h"

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
        QVERIFY(savePlotImage(&plot_, path, {QSize(600, 400), 192}).isEmpty());
        QImage image(path);
        QVERIFY(!image.isNull());
        QCOMPARE(image.size(), QSize(1200, 800)); // 192 DPI = twice the 96-DPI logical size
        QCOMPARE(qRound(image.dotsPerMeterX() * 0.0254), 192);
        QSet<QRgb> colours;
        for (int y = 0; y < image.height(); y += 8)
            for (int x = 0; x < image.width(); x += 8) colours.insert(image.pixel(x, y));
        QVERIFY(colours.size() > 3); // axes, curve and bars were drawn
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
};

QTEST_MAIN(TestPlotExport)
#include "tst_plotexport.moc"
