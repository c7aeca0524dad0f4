// FileDialogs: the last folder per place in QSettings ("files/experiments", "files/exports"); a name saved
// without a suffix gets the one of the chosen filter.
#include "FileDialogs.h"

#include "ExperimentDocument.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QRegularExpression>
#include <QSettings>
#include <QStandardPaths>

namespace pl::ui::files {

namespace {

QString settingsKey(Place place) {
    return place == Place::Experiments ? QStringLiteral("files/experiments")
                                       : QStringLiteral("files/exports");
}

QString defaultFolder(Place place) {
    if (place == Place::Experiments) {
        const QString presets = ExperimentDocument::userPresetDirectory();
        QDir().mkpath(presets);
        if (QFileInfo(presets).isDir()) return presets;
    }
    // A fresh account may have no documents folder yet: its home folder instead, never the program's
    // working directory.
    const QString documents = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
    return !documents.isEmpty() && QFileInfo(documents).isDir() ? documents : QDir::homePath();
}

// The first suffix a name filter lists: "particlelab" for "Experiments (*.particlelab)".
QString filterSuffix(const QString& nameFilter) {
    static const QRegularExpression pattern(QStringLiteral("\\*\\.([^\\s)*;]+)"));
    return pattern.match(nameFilter).captured(1);
}

} // namespace

QString startFolder(Place place) {
    const QString last = QSettings().value(settingsKey(place)).toString();
    return !last.isEmpty() && QFileInfo(last).isDir() ? last : defaultFolder(place);
}

void rememberFolderOf(Place place, const QString& path, bool isFolder) {
    if (path.isEmpty()) return;
    const QFileInfo info(path);
    QSettings().setValue(settingsKey(place), isFolder ? info.absoluteFilePath() : info.absolutePath());
}

QString saveFileName(QWidget* parent, Place place, const QString& caption, const QString& suggestedName,
                     const QString& filter, QString* selectedFilter) {
    const QString start = QDir(startFolder(place)).filePath(QFileInfo(suggestedName).fileName());
    // A dialog of its own rather than getSaveFileName: its default suffix makes "my-gas" my-gas.particlelab
    // (a file the preset menu and a file manager recognise) and asks before that name is overwritten.
    QFileDialog dialog(parent, caption, QString(), filter);
    dialog.setAcceptMode(QFileDialog::AcceptSave);
    dialog.setFileMode(QFileDialog::AnyFile);
    dialog.selectFile(start);
    if (selectedFilter && !selectedFilter->isEmpty()) dialog.selectNameFilter(*selectedFilter);
    dialog.setDefaultSuffix(filterSuffix(dialog.selectedNameFilter()));
    QObject::connect(&dialog, &QFileDialog::filterSelected, &dialog,
                     [&dialog](const QString& chosen) { dialog.setDefaultSuffix(filterSuffix(chosen)); });
    if (dialog.exec() != QDialog::Accepted || dialog.selectedFiles().isEmpty()) return {};
    const QString path = dialog.selectedFiles().constFirst();
    if (selectedFilter) *selectedFilter = dialog.selectedNameFilter();
    rememberFolderOf(place, path);
    return path;
}

QString openFileName(QWidget* parent, Place place, const QString& caption, const QString& filter) {
    const QString path = QFileDialog::getOpenFileName(parent, caption, startFolder(place), filter);
    rememberFolderOf(place, path);
    return path;
}

QString existingFolder(QWidget* parent, Place place, const QString& caption) {
    const QString folder = QFileDialog::getExistingDirectory(parent, caption, startFolder(place));
    rememberFolderOf(place, folder, true);
    return folder;
}

} // namespace pl::ui::files
