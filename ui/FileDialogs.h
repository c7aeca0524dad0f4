// The file dialogs of the window: each starts in the folder its kind of file was last read from or written
// to, so a series of exports lands in one place without browsing back each time.
#pragma once

#include <QString>

class QWidget;

namespace pl::ui::files {

// Experiments (presets, snapshots) start in the user's preset folder, where the New menu lists them;
// exports (images, data, clips, reports, LAMMPS decks) in the user's documents folder.
enum class Place { Experiments, Exports };

// The folder a dialog for this place opens in: the last one used while it still exists, else the default.
QString startFolder(Place place);
// Remembers the folder of a chosen file, or the chosen folder itself, for the next dialog of the place.
void rememberFolderOf(Place place, const QString& path, bool isFolder = false);

// QFileDialog's static dialogs, started in startFolder(place) and remembering what was chosen. A
// suggested name is a file name; it is placed in the start folder. An empty result means cancelled.
QString saveFileName(QWidget* parent, Place place, const QString& caption, const QString& suggestedName,
                     const QString& filter, QString* selectedFilter = nullptr);
QString openFileName(QWidget* parent, Place place, const QString& caption, const QString& filter);
QString existingFolder(QWidget* parent, Place place, const QString& caption);

} // namespace pl::ui::files
