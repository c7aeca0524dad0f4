// ExportImageDialog: width and height in pixels (a PNG has exactly these), locked to the plot's proportions
// by default (a width of 1200 alone gave a 1200 × 251 strip with its axis label cut), and the DPI.
#include "ExportImageDialog.h"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QSpinBox>
#include <cmath>

namespace pl::ui {

ExportImageDialog::ExportImageDialog(QSize initialSize, bool raster, QWidget* parent)
    : QDialog(parent), width_(new QSpinBox(this)), height_(new QSpinBox(this)), dpi_(new QSpinBox(this)),
      keepProportions_(new QCheckBox(tr("Keep the plot's proportions"), this)) {
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
    keepProportions_->setObjectName("keepProportions");
    keepProportions_->setChecked(true);
    form->addRow(QString(), keepProportions_);
    aspect_ = double(width_->value()) / height_->value();
    connect(width_, &QSpinBox::valueChanged, this, [this] { follow(width_); });
    connect(height_, &QSpinBox::valueChanged, this, [this] { follow(height_); });
    connect(keepProportions_, &QCheckBox::toggled, this, [this](bool on) {
        if (on) aspect_ = double(width_->value()) / height_->value(); // the proportions as they are now
    });
    form->addRow(tr("Resolution"), dpi_);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Save | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    form->addRow(buttons);
}

void ExportImageDialog::follow(QSpinBox* changed) {
    if (!keepProportions_->isChecked()) return;
    QSpinBox* other = changed == width_ ? height_ : width_;
    const double value = changed == width_ ? width_->value() / aspect_ : height_->value() * aspect_;
    const QSignalBlocker block(other); // from the kept ratio, not back from a rounded other side
    other->setValue(static_cast<int>(std::lround(value)));
}

ImageExportOptions ExportImageDialog::options() const {
    return {QSize(width_->value(), height_->value()), dpi_->value()};
}

} // namespace pl::ui
