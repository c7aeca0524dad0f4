// applyPlotFont: axes, tick labels, legends and text elements; lines thicken with the font so they stay
// visible on a projector.
#include "PlotStyle.h"

#include <qcustomplot.h>

namespace pl::ui {

void applyPlotFont(QCustomPlot* plot, const QFont& font) {
    QFont small = font;
    small.setPointSizeF(font.pointSizeF() * 0.9);
    for (QCPAxisRect* rect : plot->axisRects()) {
        for (QCPAxis* axis : rect->axes()) {
            axis->setLabelFont(font);
            axis->setTickLabelFont(small);
        }
        QCPLayoutInset* insets = rect->insetLayout();
        for (int i = 0; i < insets->elementCount(); ++i)
            if (auto* legend = qobject_cast<QCPLegend*>(insets->elementAt(i))) legend->setFont(small);
    }
    for (int i = 0; i < plot->plotLayout()->elementCount(); ++i) {
        QCPLayoutElement* element = plot->plotLayout()->elementAt(i);
        if (auto* text = qobject_cast<QCPTextElement*>(element)) text->setFont(font);
        if (auto* legend = qobject_cast<QCPLegend*>(element)) legend->setFont(small); // legends in rows
    }
    const double width = std::max(1.6, font.pointSizeF() / 6.0);
    for (int g = 0; g < plot->graphCount(); ++g) {
        QPen pen = plot->graph(g)->pen();
        pen.setWidthF(width);
        plot->graph(g)->setPen(pen);
    }
    plot->replot(QCustomPlot::rpQueuedReplot);
}

} // namespace pl::ui
