// ExportImageDialog: width and height in pixels (a PNG has exactly these), and the DPI.
#include "ExportImageDialog.h"

#include <QDialogButtonBox>
#include <QFormLayout>
#include <QSpinBox>

namespace pl::ui {

ExportImageDialog::ExportImageDialog(QSize initialSize, bool raster, QWidget* parent)
    : QDialog(parent), width_(new QSpinBox(this)), height_(new QSpinBox(this)), dpi_(new QSpinBox(this)) {
    setWindowTitle(tr("Image size"));
    auto* form = new QFormLayout(this);
    for (QSpinBox* box : {width_, height_}) {
        box->setRange(16, 10000);
        box->setSuffix(tr(" px"));
    }
    width_->setValue(std::max(16, initialSize.width()));
    height_->setValue(std::max(16, initialSize.height()));
    dpi_->setRange(24, 1200);
    dpi_->setValue(150);
    dpi_->setSuffix(tr(" DPI"));
    dpi_->setToolTip(
        raster ? tr("The PNG has exactly the pixels above; a higher DPI draws text and lines larger on them")
               : tr("Resolution recorded in the file"));
    form->addRow(tr("Width"), width_);
    form->addRow(tr("Height"), height_);
    form->addRow(tr("Resolution"), dpi_);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Save | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    form->addRow(buttons);
}

ImageExportOptions ExportImageDialog::options() const {
    return {QSize(width_->value(), height_->value()), dpi_->value()};
}

} // namespace pl::ui
