#include "ui/common/mesh_file_filter.h"

#include "core/mesh/mesh_io.h"

#include <QObject>
#include <QStringList>

namespace trimlab::ui {

namespace {

constexpr const char* kGzipSuffix = ".gz";

QString pattern(const std::string& extension)
{
    return QStringLiteral("*.") + QString::fromStdString(extension);
}

} // namespace

QString meshFileDialogFilter()
{
    QStringList all;
    QStringList perFormat;
    for (const std::string& extension : supportedMeshExtensions()) {
        all << pattern(extension);
        if (extension.ends_with(kGzipSuffix))
            continue; // listed with its uncompressed format below
        const QString name = QString::fromStdString(extension).toUpper();
        perFormat << QStringLiteral("%1 (%2 %3)").arg(name, pattern(extension), pattern(extension + kGzipSuffix));
    }
    QStringList filters;
    filters << QObject::tr("Meshes (%1)").arg(all.join(QLatin1Char(' ')));
    filters << perFormat;
    filters << QObject::tr("All files (*)");
    return filters.join(QStringLiteral(";;"));
}

} // namespace trimlab::ui
