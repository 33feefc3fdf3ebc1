#include "ui/common/last_directory.h"

#include <QDir>
#include <QFileInfo>
#include <QSettings>
#include <QStandardPaths>

namespace trimlab::ui {

namespace {

const QString kLastDirectory = QStringLiteral("paths/lastDirectory");

} // namespace

QString loadLastDirectory(const QSettings& settings)
{
    const QString directory = settings.value(kLastDirectory).toString();
    return !directory.isEmpty() && QDir(directory).exists() ? directory : QDir::homePath();
}

QString loadSaveDirectory(const QSettings& settings)
{
    return loadSaveDirectory(settings, [](const QString& folder) { return QFileInfo(folder).isWritable(); });
}

QString loadSaveDirectory(const QSettings& settings, const std::function<bool(const QString&)>& writable)
{
    const QString last = loadLastDirectory(settings);
    if (writable(last))
        return last;
    const QString pictures = QStandardPaths::writableLocation(QStandardPaths::PicturesLocation);
    if (!pictures.isEmpty() && QFileInfo(pictures).isDir() && writable(pictures))
        return pictures;
    return QDir::homePath();
}

void saveLastDirectory(QSettings& settings, const QString& directory)
{
    settings.setValue(kLastDirectory, directory);
}

} // namespace trimlab::ui
