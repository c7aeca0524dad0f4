// The methods lab without a window: run one page with its default settings and save its plot (PNG, SVG
// or PDF by suffix) and the plot's data (CSV). For `particlelab --lab PAGE --plot FILE`.
#pragma once

#include <QString>
#include <QStringList>

namespace pl::ui {

// Page names: echo, sweep, stability, fluid-map, fluid-cost, dsmc, relax.
QStringList labPageNames();
// Runs the page to the end and writes plotPath (and csvPath when not empty). Returns an error sentence, or
// empty on success.
QString runLabPage(const QString& page, const QString& plotPath, const QString& csvPath);

} // namespace pl::ui
