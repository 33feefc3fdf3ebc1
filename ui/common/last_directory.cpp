#include "ui/common/last_directory.h"

#include <QDir>
#include <QSettings>

namespace trimlab::ui {

namespace {

const QString kLastDirectory = QStringLiteral("paths/lastDirectory");

} // namespace

QString loadLastDirectory(const QSettings& settings)
{
    const QString directory = settings.value(kLastDirectory).toString();
    return !directory.isEmpty() && QDir(directory).exists() ? directory : QDir::homePath();
}

void saveLastDirectory(QSettings& settings, const QString& directory)
{
    settings.setValue(kLastDirectory, directory);
}

} // namespace trimlab::ui
