// Asks for the size and resolution of an exported plot image; the size keeps the plot's proportions unless
// the user unlocks them.
#pragma once

#include "PlotExport.h"

#include <QDialog>

class QCheckBox;
class QSpinBox;

namespace pl::ui {

class ExportImageDialog : public QDialog {
    Q_OBJECT
public:
    ExportImageDialog(QSize initialSize, bool raster, QWidget* parent = nullptr);
    ImageExportOptions options() const;

private:
    void follow(QSpinBox* changed); // the other side, in proportion, while the lock is on

    QSpinBox* width_;
    QSpinBox* height_;
    QSpinBox* dpi_;
    QCheckBox* keepProportions_;
    double aspect_ = 1.0; // width / height while the lock is on
};

} // namespace pl::ui
