// ReadablePlot: runs on QCustomPlot::afterLayout, when the axis rects have their sizes for this frame. A
// legend whose column count changes asks for one more layout; the count depends only on the plot's
// width, so that settles at once.
#include "ReadablePlot.h"

#include "FrameProfile.h"

#include <QFontMetricsF>
#include <QMouseEvent>
#include <QToolTip>
#include <algorithm>
#include <cmath>
#include <memory>
#include <qcustomplot.h>
#include <typeinfo>

namespace pl::ui {

namespace {
constexpr double kSmallestLabelScale = 0.75; // a label shrinks this far before it is shortened
constexpr double kScaleAllowance = 0.95;     // of the scale that would fit a label exactly
constexpr double kLegendRowStretch = 0.001;  // the legend row keeps its minimum height
constexpr double kMaxLegendShare = 0.3;      // of a panel's height (legend row and axis rect)
constexpr double kSmallestLegendScale = 0.65;
constexpr double kLegendScaleStep = 0.1;
constexpr double kTickRowsPerLabel = 2.2;    // a value tick every 2.2 text lines at most
constexpr double kTickColumnsPerLabel = 1.6; // and a time tick every 1.6 label widths
constexpr int kMostTicks = 6;
const QString kTypicalTickLabel = QStringLiteral("0.0000");

// Lays the entries out in this many columns (rows fill left to right) and returns the legend's size.
QSize arrange(QCPLegend* legend, int columns) {
    legend->setFillOrder(QCPLayoutGrid::foColumnsFirst, false);
    legend->setWrap(columns);
    legend->setFillOrder(QCPLayoutGrid::foColumnsFirst, true); // re-flows the entries
    return legend->minimumOuterSizeHint();
}

// The most columns that fit the width; returns the legend's height then.
int flow(QCPLegend* legend, int width) {
    int columns = std::max(1, legend->itemCount());
    while (columns > 1 && arrange(legend, columns).width() > width) --columns;
    return arrange(legend, columns).height();
}

// Flows the legend into the width and, where it would still take more than kMaxLegendShare of its
// panel's height, sets its text smaller (to kSmallestLegendScale). True when the legend changed.
bool fitLegend(QCPLegend* legend, int width, int panelHeight) {
    if (legend->property("pl_shownFont").value<QFont>() != legend->font())
        legend->setProperty("pl_baseFont", legend->font()); // a font set from outside (projector mode)
    const QFont base = legend->property("pl_baseFont").value<QFont>();
    const int wrapBefore = legend->wrap();
    const QFont fontBefore = legend->font();
    for (double scale = 1.0;; scale -= kLegendScaleStep) {
        QFont font = base;
        font.setPointSizeF(base.pointSizeF() * std::max(scale, kSmallestLegendScale));
        legend->setFont(font);
        if (flow(legend, width) <= kMaxLegendShare * panelHeight || scale <= kSmallestLegendScale) break;
    }
    legend->setProperty("pl_shownFont", legend->font());
    return legend->wrap() != wrapBefore || legend->font() != fontBefore;
}

// A vertical label longer than its axis runs past the rect into a title or the next panel.
void fitValueLabel(QCPAxisRect* rect) {
    QCPAxis* axis = rect->axis(QCPAxis::atLeft);
    // A text or font set from outside is the new full text or base font. Each on its own: a font set
    // from outside (projector mode) took the label shortened to fit the old font as the full text, and
    // "pairs per step" stayed "pairs per st…" however much room the axis had later.
    if (axis->property("pl_shownLabel").toString() != axis->label())
        axis->setProperty("pl_fullLabel", axis->label());
    if (axis->property("pl_shownFont").value<QFont>() != axis->labelFont())
        axis->setProperty("pl_labelFont", axis->labelFont());
    const QString full = axis->property("pl_fullLabel").toString();
    const QFont base = axis->property("pl_labelFont").value<QFont>();
    if (full.isEmpty()) return;
    const double room = rect->height();
    // A label too long for its axis even when set smaller goes on two lines, broken at the space nearest
    // its middle ("pairs per / step"), before it is shortened ("pairs per st…" on a 1024 px screen).
    QStringList lines{full};
    if (QFontMetricsF(base).horizontalAdvance(full) * kSmallestLabelScale > room) {
        qsizetype best = -1;
        for (qsizetype at = full.indexOf(' '); at > 0; at = full.indexOf(' ', at + 1))
            if (best < 0 || std::abs(at - full.size() / 2) < std::abs(best - full.size() / 2)) best = at;
        if (best > 0) lines = {full.left(best), full.mid(best + 1)};
    }
    double length = 0;
    for (const QString& line : lines) length = std::max(length, QFontMetricsF(base).horizontalAdvance(line));
    QFont font = base;
    // Text does not shrink exactly with its point size (hinting): a label scaled to the last pixel came
    // out a pixel too long and was shortened after all.
    if (length > room)
        font.setPointSizeF(base.pointSizeF() *
                           std::max(kSmallestLabelScale, kScaleAllowance * room / length));
    QStringList shownLines;
    for (const QString& line : lines)
        shownLines << QFontMetricsF(font).elidedText(line, Qt::ElideRight, room);
    const QString shown = shownLines.join('\n');
    axis->setLabelFont(font);
    axis->setLabel(shown);
    axis->setProperty("pl_shownLabel", shown);
    axis->setProperty("pl_shownFont", font);
}
// QCustomPlot's linear ticker with a floor of two ticks: its "nice" step for a count of 2 can exceed half
// the range, and a range around 0 (the v_x histogram's) then had the one tick 0. The step halves to the
// next clean value until two multiples of it lie in the range.
class AtLeastTwoTicks : public QCPAxisTicker {
protected:
    double getTickStep(const QCPRange& range) override {
        double step = QCPAxisTicker::getTickStep(range);
        const auto ticksIn = [&range](double s) {
            return std::floor(range.upper / s) - std::ceil(range.lower / s) + 1;
        };
        for (int halvings = 0; halvings < 8 && step > 0 && ticksIn(step) < 2; ++halvings)
            step = cleanMantissa(0.5 * step);
        return step;
    }
};

// A plain linear ticker becomes one with at least two ticks (log and time tickers stay as they are).
void keepTwoTicks(QCPAxis* axis) {
    if (typeid(*axis->ticker()) == typeid(QCPAxisTicker)) {
        const int count = axis->ticker()->tickCount();
        axis->setTicker(QSharedPointer<QCPAxisTicker>(new AtLeastTwoTicks));
        axis->ticker()->setTickCount(count);
    }
}

// Fewer ticks on a short or narrow axis, so its tick values never run into each other.
void fitTickCounts(QCPAxisRect* rect) {
    QCPAxis* y = rect->axis(QCPAxis::atLeft);
    QCPAxis* x = rect->axis(QCPAxis::atBottom);
    keepTwoTicks(y);
    keepTwoTicks(x);
    const QFontMetricsF yMetrics(y->tickLabelFont()), xMetrics(x->tickLabelFont());
    const int rows = static_cast<int>(rect->height() / (kTickRowsPerLabel * yMetrics.height()));
    const int columns = static_cast<int>(
        rect->width() / (kTickColumnsPerLabel * xMetrics.horizontalAdvance(kTypicalTickLabel)));
    y->ticker()->setTickCount(std::clamp(rows, 2, kMostTicks));
    x->ticker()->setTickCount(std::clamp(columns, 2, kMostTicks));
}

// A line wider than the plot breaks in two at the ", " or " (" nearest its middle (a summary such as
// "the whole domain: 52711 molecules (free stream, shock layer and wake together)").
QStringList wrapped(const QStringList& lines, const QFontMetricsF& metrics, double width) {
    QStringList out;
    for (const QString& line : lines) {
        qsizetype best = -1;
        if (metrics.horizontalAdvance(line) > width)
            for (const QString& separator : {QStringLiteral(", "), QStringLiteral(" (")})
                for (qsizetype at = line.indexOf(separator); at > 0; at = line.indexOf(separator, at + 1))
                    if (best < 0 || std::abs(at - line.size() / 2) < std::abs(best - line.size() / 2))
                        best = at;
        if (best < 0) {
            out << line;
            continue;
        }
        const qsizetype cut = line[best] == QLatin1Char(',') ? best + 1 : best;
        out << line.left(cut) << line.mid(cut).trimmed();
    }
    return out;
}

// A title (or a line of it) wider than the plot is wrapped, then set smaller, then shortened. Returns
// whether it now needs more height than the layout gave it (the layout must run again).
bool fitTitle(QCPTextElement* title, double width) {
    // A text or font set from outside is the new full text or base font; what this function set is not.
    if (title->property("pl_shownText").toString() != title->text())
        title->setProperty("pl_fullText", title->text());
    if (title->property("pl_shownFont").value<QFont>() != title->font())
        title->setProperty("pl_baseFont", title->font());
    const QFont base = title->property("pl_baseFont").value<QFont>();
    const QStringList lines =
        wrapped(title->property("pl_fullText").toString().split('\n'), QFontMetricsF(base), width);
    double widest = 0;
    for (const QString& line : lines) widest = std::max(widest, QFontMetricsF(base).horizontalAdvance(line));
    QFont font = base;
    if (widest > width) font.setPointSizeF(base.pointSizeF() * std::max(kSmallestLabelScale, width / widest));
    QStringList shown;
    for (const QString& line : lines) shown << QFontMetricsF(font).elidedText(line, Qt::ElideRight, width);
    title->setFont(font);
    title->setText(shown.join('\n'));
    title->setProperty("pl_shownText", title->text());
    title->setProperty("pl_shownFont", font);
    const int needed =
        static_cast<const QCPLayoutElement*>(title)->minimumOuterSizeHint().height(); // public there
    return !title->text().isEmpty() && needed > title->outerRect().height();
}
} // namespace

void placeLegendRow(QCustomPlot* plot, QCPLegend* legend, int row) {
    for (QCPAxisRect* rect : plot->axisRects())
        if (rect->insetLayout()->elements(false).contains(legend)) rect->insetLayout()->take(legend);
    QCPLayoutGrid* layout = plot->plotLayout();
    if (row < layout->rowCount() && layout->hasElement(row, 0)) layout->insertRow(row);
    layout->addElement(row, 0, legend);
    layout->setRowStretchFactor(row, kLegendRowStretch);
    legend->setLayer("legend");
    legend->setBorderPen(Qt::NoPen);
    legend->setBrush(Qt::NoBrush);
    legend->setRowSpacing(0);
    legend->setColumnSpacing(12);
    legend->setIconSize(20, 10); // short line samples leave the text more of the width
    legend->setVisible(true);
}

QString shortenedTextAt(QCustomPlot* plot, const QPointF& at) {
    for (QCPAxisRect* rect : plot->axisRects()) {
        QCPAxis* axis = rect->axis(QCPAxis::atLeft);
        const QString full = axis->property("pl_fullLabel").toString();
        // The value label runs up the strip left of the axis rect, beside it.
        if (at.x() < rect->left() && at.y() >= rect->top() && at.y() <= rect->bottom() &&
            full != QString(axis->label()).replace('\n', ' '))
            return full;
    }
    for (int i = 0; i < plot->plotLayout()->elementCount(); ++i)
        if (auto* title = qobject_cast<QCPTextElement*>(plot->plotLayout()->elementAt(i))) {
            const QString full = title->property("pl_fullText").toString();
            if (title->outerRect().contains(at.toPoint()) && title->text().contains(QChar(0x2026)) &&
                full != title->text())
                return full;
        }
    return {};
}

void setFittedTitle(QCPTextElement* title, const QString& text) {
    title->setText(text);
    fitTitle(title, title->parentPlot()->viewport().width());
}

void keepDataReadable(QCustomPlot* plot) {
    // The replot's wall time for the frame profile (--measure-fps), from before its layout to its end.
    const auto replotClock = std::make_shared<QElapsedTimer>();
    QObject::connect(plot, &QCustomPlot::beforeReplot, plot, [replotClock] { replotClock->start(); });
    QObject::connect(plot, &QCustomPlot::afterReplot, plot, [replotClock] {
        if (replotClock->isValid() && FrameProfile::instance().enabled())
            FrameProfile::instance().add(FramePart::Replot, replotClock->nsecsElapsed());
    });
    // A label or title shortened to fit says its whole text where the pointer rests on it.
    QObject::connect(plot, &QCustomPlot::mouseMove, plot, [plot](QMouseEvent* event) {
        const QString full = shortenedTextAt(plot, event->position());
        if (full.isEmpty())
            QToolTip::hideText();
        else
            QToolTip::showText(event->globalPosition().toPoint(), full, plot);
    });
    QObject::connect(plot, &QCustomPlot::afterLayout, plot, [plot] {
        bool again = false;
        QCPLayoutGrid* layout = plot->plotLayout();
        const int panels = std::max<int>(1, static_cast<int>(plot->axisRects().size()));
        for (int i = 0; i < layout->elementCount(); ++i)
            if (auto* legend = qobject_cast<QCPLegend*>(layout->elementAt(i)))
                again |= fitLegend(
                    legend, plot->viewport().width() - legend->margins().left() - legend->margins().right(),
                    plot->viewport().height() / panels);
        for (QCPAxisRect* rect : plot->axisRects()) {
            fitValueLabel(rect);
            fitTickCounts(rect);
        }
        for (int i = 0; i < layout->elementCount(); ++i)
            if (auto* title = qobject_cast<QCPTextElement*>(layout->elementAt(i)))
                again |= fitTitle(title, plot->viewport().width());
        if (again) plot->replot(QCustomPlot::rpQueuedReplot);
    });
}

} // namespace pl::ui
