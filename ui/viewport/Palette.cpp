// Palette stops: the thermal one as in the gas write-up's WGSL palette(); blue → red as in the fluid write-up
// (red = 255·s, blue = 255·(1 − s), no green); categories chosen to stay apart for colour-blind viewers.
#include "Palette.h"

#include <algorithm>
#include <cmath>

namespace pl::ui {

const QVector<QColor>& paletteStops(ColourMap map) {
    static const QVector<QColor> thermal = {
        QColor::fromRgbF(0.91f, 0.93f, 0.96f), QColor::fromRgbF(0.72f, 0.77f, 0.86f),
        QColor::fromRgbF(0.43f, 0.53f, 0.69f), QColor::fromRgbF(0.18f, 0.27f, 0.47f),
        QColor::fromRgbF(0.21f, 0.52f, 0.60f), QColor::fromRgbF(0.51f, 0.65f, 0.47f),
        QColor::fromRgbF(0.79f, 0.65f, 0.31f), QColor::fromRgbF(0.78f, 0.49f, 0.23f),
        QColor::fromRgbF(0.70f, 0.22f, 0.37f), QColor::fromRgbF(0.29f, 0.10f, 0.16f)};
    static const QVector<QColor> blueRed = {QColor(0, 0, 255), QColor(255, 0, 0)};
    static const QVector<QColor> categories = {QColor(86, 180, 233), QColor(230, 159, 0), QColor(0, 158, 115),
                                               QColor(204, 121, 167)};
    switch (map) {
    case ColourMap::Thermal:
        return thermal;
    case ColourMap::BlueRed:
        return blueRed;
    case ColourMap::Category:
        return categories;
    }
    return thermal;
}

bool isCategorical(ColourMap map) {
    return map == ColourMap::Category;
}

QColor paletteColour(ColourMap map, double value) {
    const QVector<QColor>& stops = paletteStops(map);
    const auto last = static_cast<int>(stops.size()) - 1;
    if (isCategorical(map)) return stops[std::clamp(static_cast<int>(value), 0, last)];
    const double x = std::clamp(std::isfinite(value) ? value : 0.0, 0.0, 1.0) * last;
    const int i0 = static_cast<int>(std::floor(x));
    const int i1 = std::min(i0 + 1, last);
    const float a = static_cast<float>(x - i0);
    const QColor& p = stops[i0];
    const QColor& q = stops[i1];
    return QColor::fromRgbF(p.redF() + a * (q.redF() - p.redF()), p.greenF() + a * (q.greenF() - p.greenF()),
                            p.blueF() + a * (q.blueF() - p.blueF()));
}

} // namespace pl::ui
