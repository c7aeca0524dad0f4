// Asks for the size and resolution of an exported plot image.
#pragma once

#include "PlotExport.h"

#include <QDialog>

class QSpinBox;

namespace pl::ui {

class ExportImageDialog : public QDialog {
    Q_OBJECT
public:
    ExportImageDialog(QSize initialSize, bool raster, QWidget* parent = nullptr);
    ImageExportOptions options() const;

private:
    QSpinBox* width_;
    QSpinBox* height_;
    QSpinBox* dpi_;
};

} // namespace pl::ui
