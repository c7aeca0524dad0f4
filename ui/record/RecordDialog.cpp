// RecordDialog: a form over AppClipOptions. The size chooser's presets fill the two spin boxes, which
// only a custom size unlocks; a size the format refuses (ClipFormat's rule, shared with the CLI) says so
// under the form and disables Record. The steps per frame follow the frame rate at the watchable pace
// until the user sets them, and the line beside them says what they mean in simulated time.
#include "RecordDialog.h"

#include <qcustomplot.h> // before SeriesPlot.h, which names QCPAxis

#include "SimulationController.h"
#include "plots/SeriesPlotSpecs.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QVBoxLayout>
#include <cmath>

namespace pl::ui {

namespace {

struct SizePreset {
    QSize size;
    const char* name; // after the size, in brackets
};
// The common 16:9 sizes and a square one for slides with a plot beside nothing.
const SizePreset kSizePresets[] = {{{640, 360}, "360p"},
                                   {{854, 480}, "480p"},
                                   {{1280, 720}, "720p"},
                                   {{1920, 1080}, "1080p"},
                                   {{1080, 1080}, ""}};
const ClipFormat kFormats[] = {ClipFormat::Mp4, ClipFormat::WebM, ClipFormat::Gif};

QString sizeText(QSize size) {
    return QStringLiteral("%1x%2").arg(size.width()).arg(size.height());
}

} // namespace

QString clipSuffix(ClipFormat format) {
    switch (format) {
    case ClipFormat::Mp4:
        return QStringLiteral("mp4");
    case ClipFormat::WebM:
        return QStringLiteral("webm");
    case ClipFormat::Gif:
        return QStringLiteral("gif");
    }
    return {};
}

QString clipPathFor(const QString& chosen, ClipFormat format) {
    if (chosen.isEmpty() || clipFormatOf(chosen.toStdString())) return chosen;
    return chosen + QLatin1Char('.') + clipSuffix(format);
}

RecordDialog::RecordDialog(SimulationController* controller, QWidget* parent)
    : QDialog(parent), controller_(controller) {
    setObjectName("recordDialog");
    setWindowTitle(tr("Record clip"));
    if (const Model* model = controller->model()) kind_ = QString::fromStdString(model->kind());

    formatChooser_ = new QComboBox(this);
    formatChooser_->setObjectName("formatChooser");
    formatChooser_->addItem(tr("MP4 (H.264): plays everywhere"), clipSuffix(ClipFormat::Mp4));
    formatChooser_->addItem(tr("WebM (VP9): smaller, for the web"), clipSuffix(ClipFormat::WebM));
    formatChooser_->addItem(tr("GIF: loops, for slides and chat"), clipSuffix(ClipFormat::Gif));
    formatChooser_->setToolTip(tr("The file's suffix decides in the end: a name ending in .webm is WebM"));

    contentChooser_ = new QComboBox(this);
    contentChooser_->setObjectName("contentChooser");
    contentChooser_->addItem(tr("The scene alone"), QString());
    for (const SeriesPlotSpec& spec : seriesPlotSpecs())
        if (spec.kinds.contains(kind_))
            contentChooser_->addItem(tr("The scene beside %1").arg(spec.title), spec.objectName);

    sizeChooser_ = new QComboBox(this);
    sizeChooser_->setObjectName("sizeChooser");
    for (const SizePreset& preset : kSizePresets)
        sizeChooser_->addItem(*preset.name
                                  ? QStringLiteral("%1 × %2 (%3)")
                                        .arg(preset.size.width())
                                        .arg(preset.size.height())
                                        .arg(QLatin1String(preset.name))
                                  : tr("%1 × %2 (square)").arg(preset.size.width()).arg(preset.size.height()),
                              preset.size);
    sizeChooser_->addItem(tr("Custom size"), QSize());
    widthSpin_ = new QSpinBox(this);
    widthSpin_->setObjectName("widthSpin");
    widthSpin_->setRange(kMinClipSide, kMaxClipWidth);
    widthSpin_->setSuffix(tr(" px"));
    heightSpin_ = new QSpinBox(this);
    heightSpin_->setObjectName("heightSpin");
    heightSpin_->setRange(kMinClipSide, kMaxClipHeight);
    heightSpin_->setSuffix(tr(" px"));
    auto* sizeRow = new QHBoxLayout;
    sizeRow->addWidget(sizeChooser_, 1);
    sizeRow->addWidget(widthSpin_);
    sizeRow->addWidget(new QLabel(QStringLiteral("×"), this));
    sizeRow->addWidget(heightSpin_);

    fpsSpin_ = new QSpinBox(this);
    fpsSpin_->setObjectName("fpsSpin");
    fpsSpin_->setRange(1, kMaxClipFps);
    fpsSpin_->setSuffix(tr(" frames/s"));

    stepsSpin_ = new QSpinBox(this);
    stepsSpin_->setObjectName("stepsSpin");
    stepsSpin_->setRange(1, kMaxStepsPerClipFrame);
    stepsSpin_->setToolTip(tr("Every frame is the state after this many steps, so the clip shows simulated "
                              "time evenly however long each step took"));
    watchableButton_ = new QPushButton(tr("Watchable pace"), this);
    watchableButton_->setObjectName("watchablePaceButton");
    watchableButton_->setToolTip(
        tr("The steps per frame that play the scene at the pace it is best watched at"));
    auto* stepsRow = new QHBoxLayout;
    stepsRow->addWidget(stepsSpin_, 1);
    stepsRow->addWidget(watchableButton_);
    paceLabel_ = new QLabel(this);
    paceLabel_->setObjectName("paceLabel");
    paceLabel_->setWordWrap(true);

    captionsCheck_ = new QCheckBox(tr("Title at the start and the time in the corner"), this);
    captionsCheck_->setObjectName("captionsCheck");

    refusalLabel_ = new QLabel(this);
    refusalLabel_->setObjectName("refusalLabel");
    refusalLabel_->setWordWrap(true);
    refusalLabel_->setStyleSheet(QStringLiteral("color: #c0392b;"));
    refusalLabel_->hide();

    buttons_ = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons_->button(QDialogButtonBox::Ok)->setText(tr("Record…"));
    connect(buttons_, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons_, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto* form = new QFormLayout;
    form->addRow(tr("Format:"), formatChooser_);
    form->addRow(tr("Shows:"), contentChooser_);
    form->addRow(tr("Size:"), sizeRow);
    form->addRow(tr("Frame rate:"), fpsSpin_);
    form->addRow(tr("Steps per frame:"), stepsRow);
    form->addRow(QString(), paceLabel_);
    form->addRow(QString(), captionsCheck_);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(refusalLabel_);
    layout->addWidget(buttons_);

    readSettings();
    connect(sizeChooser_, &QComboBox::currentIndexChanged, this, &RecordDialog::updateSize);
    connect(widthSpin_, &QSpinBox::valueChanged, this, &RecordDialog::check);
    connect(heightSpin_, &QSpinBox::valueChanged, this, &RecordDialog::check);
    connect(formatChooser_, &QComboBox::currentIndexChanged, this, &RecordDialog::check);
    connect(fpsSpin_, &QSpinBox::valueChanged, this, [this] {
        if (followsPace_) stepsSpin_->setValue(watchableStepsPerFrame(*controller_, fpsSpin_->value()));
        updatePace();
    });
    connect(stepsSpin_, &QSpinBox::valueChanged, this, [this] {
        // The user's own number, unless it is what the pace gives at this frame rate.
        followsPace_ = stepsSpin_->value() == watchableStepsPerFrame(*controller_, fpsSpin_->value());
        updatePace();
    });
    connect(watchableButton_, &QPushButton::clicked, this,
            [this] { stepsSpin_->setValue(watchableStepsPerFrame(*controller_, fpsSpin_->value())); });
    updateSize();
    updatePace();
}

void RecordDialog::readSettings() {
    QSettings settings;
    const int format = formatChooser_->findData(settings.value("record/format", clipSuffix(ClipFormat::Mp4)));
    formatChooser_->setCurrentIndex(std::max(0, format));
    const int content = contentChooser_->findData(settings.value("record/plot/" + kind_, QString()));
    contentChooser_->setCurrentIndex(std::max(0, content));
    int width = kAppClipSize.width(), height = kAppClipSize.height();
    parseClipSize(settings.value("record/size", sizeText(kAppClipSize)).toString().toStdString(), width,
                  height);
    const QSize size(std::clamp(width, kMinClipSide, kMaxClipWidth),
                     std::clamp(height, kMinClipSide, kMaxClipHeight));
    const int preset = sizeChooser_->findData(size);
    sizeChooser_->setCurrentIndex(preset >= 0 ? preset : sizeChooser_->count() - 1);
    widthSpin_->setValue(size.width());
    heightSpin_->setValue(size.height());
    fpsSpin_->setValue(std::clamp(settings.value("record/fps", kAppClipFps).toInt(), 1, kMaxClipFps));
    const QVariant steps = settings.value("record/stepsPerFrame/" + kind_);
    followsPace_ = !steps.isValid();
    stepsSpin_->setValue(followsPace_ ? watchableStepsPerFrame(*controller_, fpsSpin_->value())
                                      : steps.toInt());
    captionsCheck_->setChecked(settings.value("record/captions", true).toBool());
}

void RecordDialog::remember() const {
    QSettings settings;
    settings.setValue("record/format", clipSuffix(format()));
    settings.setValue("record/plot/" + kind_, contentChooser_->currentData());
    settings.setValue("record/size", sizeText(options().size));
    settings.setValue("record/fps", fpsSpin_->value());
    if (followsPace_)
        settings.remove("record/stepsPerFrame/" + kind_);
    else
        settings.setValue("record/stepsPerFrame/" + kind_, stepsSpin_->value());
    settings.setValue("record/captions", captionsCheck_->isChecked());
}

void RecordDialog::updateSize() {
    const QSize preset = sizeChooser_->currentData().toSize();
    const bool custom = !preset.isValid();
    widthSpin_->setEnabled(custom);
    heightSpin_->setEnabled(custom);
    if (!custom) {
        widthSpin_->setValue(preset.width());
        heightSpin_->setValue(preset.height());
    }
    check();
}

void RecordDialog::updatePace() {
    const double perFrame = stepsSpin_->value() * stepTime(*controller_);
    const QString unit = controller_->timeUnit();
    paceLabel_->setText(tr("%1 %2 of simulated time per frame, %3 %2 per second of clip")
                            .arg(QString::number(perFrame, 'g', 3), unit,
                                 QString::number(perFrame * fpsSpin_->value(), 'g', 3)));
    watchableButton_->setEnabled(!followsPace_);
}

void RecordDialog::check() {
    const QSize size(widthSpin_->value(), heightSpin_->value());
    const std::string refusal = clipSizeRefusal(format(), size.width(), size.height());
    // The spin boxes keep the size within the sides every format takes, so what is left to refuse is an
    // odd side; any other refusal shows in the CLI's (English) words.
    const bool odd = size.width() % 2 != 0 || size.height() % 2 != 0;
    refusalLabel_->setText(
        odd ? tr("%1 cannot store an odd side (its colours are kept at half resolution): use an even width "
                 "and height.")
                  .arg(QString::fromStdString(clipFormatName(format())))
            : QString::fromStdString(refusal));
    refusalLabel_->setVisible(!refusal.empty());
    buttons_->button(QDialogButtonBox::Ok)->setEnabled(refusal.empty());
}

ClipFormat RecordDialog::format() const {
    return kFormats[std::max(0, formatChooser_->currentIndex())];
}

AppClipOptions RecordDialog::options() const {
    AppClipOptions o;
    o.size = QSize(widthSpin_->value(), heightSpin_->value());
    o.fps = fpsSpin_->value();
    o.stepsPerFrame = stepsSpin_->value();
    o.captions = captionsCheck_->isChecked();
    o.plot = contentChooser_->currentData().toString();
    return o;
}

void RecordDialog::accept() {
    remember();
    QDialog::accept();
}

} // namespace pl::ui
